// DICOM series / file -> Volume: header scan and series choice (series), slice geometry
// (geometry), pixel decoding (pixels). docs/dicom.md describes the rules.
#include "scan/dicom/geometry.hpp"
#include "scan/dicom/pixels.hpp"
#include "scan/dicom/series.hpp"
#include "scan/load_checks.hpp"
#include "scan/readers.hpp"

#include <cmath>
#include <new>
#include <optional>

namespace steerseg::scan {

namespace {

double positiveOr(std::optional<double> value, double fallback) {
    return value && std::isfinite(*value) && *value > 0.0 ? *value : fallback;
}

// Where each frame of each file goes: slices[file][frame] = k.
struct Layout {
    Geometry geometry;
    std::vector<std::vector<std::size_t>> slices;
};

// A multi-frame file without per-frame positions (legacy multi-frame: NM, US, XA, old MR cine):
// frames stacked in file order from the file's position and orientation (origin 0 and identity
// if absent), SpacingBetweenSlices, else SliceThickness, else 1 mm, which is what GDCM reports
// for these files too except where its Frame Increment Pointer names Frame Time: time points
// are stacked 1 mm apart, not at a spacing in milliseconds.
Layout stackFramesInFileOrder(const std::filesystem::path& where, const DicomHeader& h) {
    Layout out;
    Geometry& g = out.geometry;
    g.dims = {h.columns, h.rows, h.frames};
    const glm::dvec2 ps = h.pixelSpacing.value_or(glm::dvec2(1.0));
    const double k = h.framesAreTimePoints
                         ? 1.0
                         : positiveOr(h.spacingBetweenSlices, positiveOr(h.sliceThickness, 1.0));
    g.spacing = {ps.x, ps.y, k};
    g.origin = h.planes.front().position.value_or(glm::dvec3(0.0));
    if (h.orientation) {
        const glm::dvec3 row = glm::normalize(h.orientation->first);
        const glm::dvec3 col = glm::normalize(h.orientation->second);
        g.direction = glm::dmat3(row, col, glm::normalize(glm::cross(row, col)));
    }
    checkGeometry(where, g);
    out.slices.emplace_back(static_cast<std::size_t>(h.frames));
    for (std::size_t f = 0; f < out.slices[0].size(); ++f) {
        out.slices[0][f] = f;
    }
    return out;
}

// Single-frame files of one series, or an enhanced multi-frame file: slices sorted along the
// normal from their ImagePositionPatient.
Layout stackByPosition(const std::filesystem::path& where, const std::vector<DicomHeader>& files) {
    const DicomHeader& first = files.front();
    SliceStackInput in;
    in.size = {first.columns, first.rows};
    in.pixelSpacing = first.pixelSpacing.value_or(glm::dvec2(1.0));
    in.singleSliceSpacing =
        positiveOr(first.spacingBetweenSlices, positiveOr(first.sliceThickness, 1.0));
    if (first.orientation) {
        in.rowDirection = first.orientation->first;
        in.columnDirection = first.orientation->second;
    }
    std::vector<std::pair<std::size_t, std::size_t>> source; // (file, frame) per input slice
    for (std::size_t i = 0; i < files.size(); ++i) {
        const DicomHeader& h = files[i];
        if (glm::length(h.pixelSpacing.value_or(glm::dvec2(1.0)) - in.pixelSpacing) > 1e-4) {
            throw ScanError(h.file, "pixel spacing differs from the series' other slices");
        }
        for (std::size_t f = 0; f < h.planes.size(); ++f) {
            const auto& pos = h.planes[f].position;
            std::string name =
                h.frames > 1 ? "frame " + std::to_string(f + 1) : h.file.filename().string();
            if (!pos || !first.orientation) {
                if (files.size() == 1 && h.planes.size() == 1) {
                    in.positions.push_back(pos.value_or(glm::dvec3(0.0)));
                    in.names.push_back(std::move(name));
                    source.emplace_back(i, f);
                    continue;
                }
                throw ScanError(h.file, name + " has no ImagePositionPatient or "
                                               "ImageOrientationPatient, so the slice order and "
                                               "spacing are unknown");
            }
            in.positions.push_back(*pos);
            in.names.push_back(std::move(name));
            source.emplace_back(i, f);
        }
    }
    const SliceStack stack = stackSlices(where, in);
    Layout out;
    out.geometry = stack.geometry;
    out.slices.resize(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        out.slices[i].resize(files[i].planes.size());
    }
    for (std::size_t k = 0; k < stack.order.size(); ++k) {
        const auto [file, frame] = source[stack.order[k]];
        out.slices[file][frame] = k;
    }
    return out;
}

// The instance, frame and position behind each slice k, and the series' shared attributes.
DicomSource describeSource(const std::vector<DicomHeader>& files, const Layout& layout) {
    const DicomHeader& first = files.front();
    DicomSource src;
    src.studyInstanceUid = first.studyUid;
    src.seriesInstanceUid = first.seriesUid;
    src.frameOfReferenceUid = first.frameOfReferenceUid;
    src.modality = first.modality;
    src.sliceThickness = first.sliceThickness;
    src.inherited = first.inherited;
    for (const auto& a : first.inherited) {
        if (a.group == 0x0010 && a.element == 0x0020) {
            src.patientId = a.value;
        }
    }
    src.slices.resize(static_cast<std::size_t>(layout.geometry.dims.z));
    for (std::size_t i = 0; i < files.size(); ++i) {
        const DicomHeader& h = files[i];
        if (h.lossyCompression == "01" && !src.lossyCompressed) {
            src.lossyCompressed = true;
            src.lossyRatio = h.lossyRatio;
            src.lossyMethod = h.lossyMethod;
        }
        for (std::size_t f = 0; f < layout.slices[i].size(); ++f) {
            DicomSourceSlice& s = src.slices.at(layout.slices[i][f]);
            s.sopClassUid = h.sopClassUid.empty() ? h.mediaStorageSopClassUid : h.sopClassUid;
            s.sopInstanceUid =
                h.sopInstanceUid.empty() ? h.mediaStorageSopInstanceUid : h.sopInstanceUid;
            s.frameNumber = h.frames > 1 ? static_cast<int>(f) + 1 : 0;
            // Frames stacked in file order repeat the file's position: only their own counts.
            if (h.frames == 1 || h.framesFromGroups) {
                s.position = h.planes[f].position;
            }
        }
    }
    return src;
}

Volume assemble(const std::filesystem::path& where, const std::vector<DicomHeader>& files,
                const ReadLimits& limits, DicomSource* source) {
    std::size_t slices = 0;
    for (const auto& h : files) {
        slices += h.planes.size();
    }
    checkDims(where,
              {files.front().columns, files.front().rows,
               static_cast<int>(std::min<std::size_t>(slices, 1U << 30))},
              limits);

    const Layout layout =
        files.size() == 1 && files.front().frames > 1 && !files.front().framesFromGroups
            ? stackFramesInFileOrder(where, files.front())
            : stackByPosition(where, files);

    if (source != nullptr) {
        *source = describeSource(files, layout);
    }
    PixelPlan plan = planPixels(files);
    for (int attempt = 0;; ++attempt) {
        try {
            Volume volume(plan.type, layout.geometry);
            volume.setRescale(plan.shared);
            for (std::size_t i = 0; i < files.size(); ++i) {
                const DicomPixels pixels(files[i]);
                pixels.copyFrames(layout.slices[i], files[i].planes, plan, volume);
            }
            checkFinite(where, volume);
            if (!plan.realUnits) {
                checkRescale(where, volume, kDicomRescaleFields);
            }
            return volume;
        } catch (const PixelPlanMismatch&) {
            if (attempt > 0) {
                throw ScanError(where, "decoded pixel values do not fit float32");
            }
            plan = PixelPlan{}; // float32 in real units
        }
    }
}

} // namespace

Volume readDicom(const std::filesystem::path& path, const ReadLimits& limits, DicomSource* source) {
    quietGdcm();
    try {
        std::vector<DicomHeader> series;
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) {
            series = selectSeries(path, scanDicomFolder(path, limits));
        } else {
            DicomHeader h = readDicomHeader(path, limits);
            if (!h.isImage()) {
                throw ScanError(path,
                                "not an image: " + describeNonImage(h) + " has no pixel data");
            }
            series.push_back(std::move(h));
        }
        return assemble(path, series, limits, source);
    } catch (const ScanError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw ScanError(path, "out of memory while reading the DICOM data");
    } catch (const std::exception& e) {
        throw ScanError(path, std::string("DICOM reading failed: ") + e.what());
    }
}

} // namespace steerseg::scan
