#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace steerseg {

// Position of voxel (i, j, k) in an i-fastest array of `dims` voxels (the storage order of every
// volume, mask and level set here).
inline std::size_t linearIndex(const glm::ivec3& dims, int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims.x) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(dims.y) * static_cast<std::size_t>(k));
}

// Stored voxel type. Scans keep their native type on the GPU and in memory (a 512^3 CT stays
// 256 MiB of int16, not 512 MiB of float); real units come from Volume::rescale.
enum class VoxelType : std::uint8_t { UInt8, Int16, UInt16, Float32 };

std::size_t voxelBytes(VoxelType type);
const char* voxelTypeName(VoxelType type); // "uint8", "int16", "uint16", "float32"
// "WxHxD", as every message about a grid's size says it.
std::string dimsText(const glm::ivec3& dims);

// Where voxels sit in the world. World coordinates are LPS millimetres (DICOM/ITK convention);
// readers of RAS formats (NIfTI, MGZ) convert. Voxel index (i, j, k) is the file's own storage
// order, i fastest.
//   world = origin + direction * (spacing * index)
// direction's columns are the unit vectors of the i, j and k axes in world space.
struct Geometry {
    glm::ivec3 dims{0};
    glm::dvec3 spacing{1.0};
    glm::dvec3 origin{0.0};
    glm::dmat3 direction{1.0};

    [[nodiscard]] std::size_t voxelCount() const;
    [[nodiscard]] glm::dvec3 indexToWorld(const glm::dvec3& index) const;
    [[nodiscard]] glm::dvec3 worldToIndex(const glm::dvec3& world) const;
    // Row-major 3x3, as ITK and `steerseg info` print it.
    [[nodiscard]] std::array<double, 9> directionRowMajor() const;
};

// stored value -> real units (HU for CT): real = slope * stored + intercept.
struct Rescale {
    double slope = 1.0;
    double intercept = 0.0;
    [[nodiscard]] double apply(double stored) const { return slope * stored + intercept; }
};

// Why `rescale` cannot take stored values in [storedMin, storedMax] to finite real values within
// float32's range (the solver and renderer hold real values as float), e.g. "slope is nan" or
// "slope 1e+38 and intercept 0 take stored 32767 to 3.3e+42, beyond float32's range"; empty
// when it can. Readers check a file's rescale against its stored min and max.
std::string rescaleProblem(const Rescale& rescale, double storedMin, double storedMax);

struct IntensityStats {
    double min = 0.0; // real units
    double max = 0.0;
    double mean = 0.0;
    std::vector<std::uint64_t> histogram; // bins evenly over [min, max]
};

// A scan in memory: voxels in their native type, geometry, and the rescale to real units.
class Volume {
  public:
    Volume() = default;
    // Zero-filled voxels. Throws std::invalid_argument for non-positive dims.
    Volume(VoxelType type, const Geometry& geometry);

    [[nodiscard]] VoxelType type() const { return type_; }
    [[nodiscard]] const Geometry& geometry() const { return geometry_; }
    Geometry& geometry() { return geometry_; }
    [[nodiscard]] glm::ivec3 dims() const { return geometry_.dims; }
    [[nodiscard]] const Rescale& rescale() const { return rescale_; }
    void setRescale(const Rescale& r) { rescale_ = r; }

    [[nodiscard]] std::span<const std::byte> bytes() const { return data_; }
    std::span<std::byte> bytes() { return data_; }
    template <typename T> std::span<T> voxels() {
        return {reinterpret_cast<T*>(data_.data()), geometry_.voxelCount()};
    }
    template <typename T> std::span<const T> voxels() const {
        return {reinterpret_cast<const T*>(data_.data()), geometry_.voxelCount()};
    }

    [[nodiscard]] std::size_t linearIndex(int i, int j, int k) const {
        return steerseg::linearIndex(geometry_.dims, i, j, k);
    }
    // Stored value at a voxel as double (no rescale).
    [[nodiscard]] double storedAt(std::size_t linear) const;
    // Real-unit value at a voxel.
    [[nodiscard]] double valueAt(int i, int j, int k) const { return realAt(linearIndex(i, j, k)); }
    [[nodiscard]] double realAt(std::size_t linear) const {
        return rescale_.apply(storedAt(linear));
    }

    // Smallest and largest stored value (no rescale); {0, 0} for an empty volume.
    [[nodiscard]] std::pair<double, double> storedRange() const;

    // Min/max/mean in real units and a histogram; computed on demand and cached.
    [[nodiscard]] const IntensityStats& stats() const;
    // Drops the cache after voxels were written through bytes()/voxels().
    void invalidateStats() { stats_.reset(); }

    // Real-unit copy as float (the solver's and reference's view of the scan).
    [[nodiscard]] std::vector<float> realValues() const;
    // Real units of voxels first .. first + out.size() - 1 (linear index), for readers that
    // go through a large scan a slab of slices at a time.
    void realValues(std::size_t first, std::span<float> out) const;

  private:
    VoxelType type_ = VoxelType::UInt8;
    Geometry geometry_;
    Rescale rescale_;
    std::vector<std::byte> data_;
    mutable std::shared_ptr<const IntensityStats> stats_;
};

inline constexpr int kHistogramBins = 256;

} // namespace steerseg
