#include "scan/load_checks.hpp"

#include "scan/byte_source.hpp"

#include <cmath>
#include <sstream>

namespace steerseg::scan {

void checkDims(const std::filesystem::path& path, const glm::ivec3& dims,
               const ReadLimits& limits) {
    for (int a = 0; a < 3; ++a) {
        if (dims[a] <= 0) {
            throw ScanError(path, "dimensions " + dimsText(dims) + " are not all positive");
        }
        if (dims[a] > limits.maxDimension) {
            throw ScanError(path, "dimensions " + dimsText(dims) + " exceed the limit of " +
                                      std::to_string(limits.maxDimension) + " voxels per axis");
        }
    }
    const auto count = static_cast<std::uint64_t>(dims.x) * static_cast<std::uint64_t>(dims.y) *
                       static_cast<std::uint64_t>(dims.z);
    if (count > limits.maxVoxels) {
        throw ScanError(path, "dimensions " + dimsText(dims) + " (" + std::to_string(count) +
                                  " voxels) exceed the limit of " +
                                  std::to_string(limits.maxVoxels) + " voxels");
    }
}

void checkGeometry(const std::filesystem::path& path, const Geometry& g, double tolerance) {
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(g.spacing[a]) || g.spacing[a] <= 0.0) {
            throw ScanError(path, "voxel spacing " + std::to_string(g.spacing.x) + " x " +
                                      std::to_string(g.spacing.y) + " x " +
                                      std::to_string(g.spacing.z) + " is not positive and finite");
        }
        if (!std::isfinite(g.origin[a])) {
            throw ScanError(path, "origin is not finite");
        }
    }
    for (int c = 0; c < 3; ++c) {
        const double len = glm::length(g.direction[c]);
        if (!std::isfinite(len) || std::abs(len - 1.0) > tolerance) {
            throw ScanError(path, "direction cosines are not unit vectors");
        }
        for (int d = c + 1; d < 3; ++d) {
            if (std::abs(glm::dot(g.direction[c], g.direction[d])) > tolerance) {
                throw ScanError(path, "direction cosines are not orthogonal (sheared grid)");
            }
        }
    }
}

void checkFinite(const std::filesystem::path& path, const Volume& volume) {
    if (volume.type() != VoxelType::Float32) {
        return;
    }
    const auto v = volume.voxels<float>();
    std::size_t bad = 0;
    std::size_t first = 0;
    for (std::size_t n = 0; n < v.size(); ++n) {
        if (!std::isfinite(v[n])) {
            if (bad == 0) {
                first = n;
            }
            ++bad;
        }
    }
    if (bad > 0) {
        const auto& d = volume.dims();
        const std::size_t i = first % static_cast<std::size_t>(d.x);
        const std::size_t j =
            (first / static_cast<std::size_t>(d.x)) % static_cast<std::size_t>(d.y);
        const std::size_t k =
            first / (static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y));
        throw ScanError(path, std::to_string(bad) + " voxels are NaN or infinite (first at " +
                                  std::to_string(i) + "," + std::to_string(j) + "," +
                                  std::to_string(k) + ")");
    }
}

void checkRescale(const std::filesystem::path& path, const Rescale& rescale, double storedMin,
                  double storedMax, const std::string& fields) {
    const std::string problem = rescaleProblem(rescale, storedMin, storedMax);
    if (!problem.empty()) {
        throw ScanError(path, "rescale (" + fields + ") refused: " + problem);
    }
}

void checkRescale(const std::filesystem::path& path, const Volume& volume,
                  const std::string& fields) {
    const auto [lo, hi] = volume.storedRange();
    checkRescale(path, volume.rescale(), lo, hi, fields);
}

void checkDataLimit(const std::filesystem::path& path, std::uint64_t bytes,
                    const ReadLimits& limits, const std::string& what) {
    if (bytes > limits.maxDataBytes) {
        throw ScanError(path, what + ", more than the limit of " + sizeText(limits.maxDataBytes) +
                                  " of scan data");
    }
}

void checkDataFits(const std::filesystem::path& path, std::uint64_t bytes, const ByteSource& source,
                   const ReadLimits& limits, const std::string& what) {
    checkDataLimit(path, bytes, limits, what);
    if (source.remaining()) {
        return;
    }
    const auto compressed = source.compressedRemaining();
    if (!compressed) {
        return;
    }
    const double most = static_cast<double>(*compressed) * limits.maxCompressionRatio +
                        static_cast<double>(GzipSource::kPendingBytes);
    if (static_cast<double>(bytes) > most) {
        std::ostringstream ratio;
        ratio << limits.maxCompressionRatio;
        throw ScanError(path, what + " but " + sizeText(*compressed) +
                                  " of compressed data expand to at most " +
                                  sizeText(static_cast<std::uint64_t>(most)) +
                                  " (compression ratio limit " + ratio.str() + ":1)");
    }
}

void checkAvailable(const std::filesystem::path& path, std::uint64_t needed,
                    std::uint64_t available, const char* what) {
    if (needed > available) {
        throw ScanError(path, std::string(what) + " needs " + std::to_string(needed) +
                                  " bytes but the file holds only " + std::to_string(available));
    }
}

} // namespace steerseg::scan
