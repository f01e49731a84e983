// steerseg measure: one structure's measurements (core/mask_measurements, docs/measurements.md)
// from a mask on the scan's grid. GL-free: it needs no GPU, only the two files.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "core/mask_inside.hpp"
#include "core/mask_measurements.hpp"
#include "core/volume.hpp"
#include "scan/scan_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::cli {

namespace {

// A mask that is not on the scan's grid would measure another place of the patient: refused as
// a mask that does not fit the scan, like a seed outside it. Same dimensions and, within what
// a header's float precision leaves, the same corners in the patient (export's rule).
void requireScanGrid(const std::string& path, const Geometry& mask, const Geometry& scan) {
    if (mask.dims != scan.dims) {
        throw UsageError("--mask " + path + ": the mask is " + dimsText(mask.dims) +
                         " voxels but the scan is " + dimsText(scan.dims));
    }
    const double far = glm::length(scan.indexToWorld(glm::dvec3(scan.dims - 1)) -
                                   mask.indexToWorld(glm::dvec3(mask.dims - 1)));
    const double near = glm::length(scan.origin - mask.origin);
    const double tolerance = 0.01 * std::min({scan.spacing.x, scan.spacing.y, scan.spacing.z});
    if (std::max(near, far) > tolerance) {
        throw UsageError("--mask " + path + ": the mask is not on the scan's grid (its corner " +
                         "voxels lie " + std::to_string(std::max(near, far)) +
                         " mm from the scan's)");
    }
}

// 0/1: the voxels equal to `label`, or with none given the mask file's inside (non-zero).
std::vector<std::uint8_t> selectVoxels(const std::string& path, const Volume& mask,
                                       std::optional<long long> label) {
    if (!label) {
        try {
            return maskInside(mask);
        } catch (const std::invalid_argument& e) {
            throw scan::ScanError(path, e.what());
        }
    }
    std::vector<std::uint8_t> picked(mask.geometry().voxelCount());
    const auto wanted = static_cast<double>(*label);
    for (std::size_t n = 0; n < picked.size(); ++n) {
        picked[n] = mask.realAt(n) == wanted ? 1 : 0;
    }
    if (std::find(picked.begin(), picked.end(), std::uint8_t{1}) == picked.end()) {
        throw UsageError("--label " + std::to_string(*label) + ": no voxel of " + path +
                         " has that label");
    }
    return picked;
}

nlohmann::ordered_json lineJson(const MeasuredLine& line) {
    const auto point = [](const glm::dvec3& p) { return std::vector<double>{p.x, p.y, p.z}; };
    return {{"length_mm", line.lengthMm},
            {"from", {{"index", point(line.index[0])}, {"lps_mm", point(line.world[0])}}},
            {"to", {{"index", point(line.index[1])}, {"lps_mm", point(line.world[1])}}}};
}

std::string indexText(const glm::dvec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f)", p.x, p.y, p.z);
    return text;
}

void printTable(const MaskMeasurements& m) {
    const char* axes = "ijk";
    std::printf("voxels                %llu\n", static_cast<unsigned long long>(m.voxels));
    std::printf("volume                %.3f ml\n", m.volumeMl);
    std::printf("surface area          %.1f mm^2\n", m.surfaceAreaMm2);
    std::printf("axial slice           %c = %d\n", axes[m.axial.sliceAxis], m.axial.slice);
    for (const auto& [name, line] : {std::pair{"longest axial", &m.axial.longest},
                                     std::pair{"perpendicular", &m.axial.perpendicular},
                                     std::pair{"longest 3D", &m.longest3d}}) {
        std::printf("%-21s %.1f mm  %s -> %s\n", name, line->lengthMm,
                    indexText(line->index[0]).c_str(), indexText(line->index[1]).c_str());
    }
    std::printf("intensity mean        %.2f\n", m.intensity.mean);
    std::printf("intensity sd          %.2f\n", m.intensity.sd);
    std::printf("intensity min, max    %.2f, %.2f\n", m.intensity.min, m.intensity.max);
}

} // namespace

int runMeasure(std::span<const std::string> words) {
    const Args args(words, {"input", "mask", "label"}, {"json"});
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string maskPath = args.required("mask");
    const std::optional<long long> label = args.integer("label");

    const scan::LoadedScan scan = scan::readScan(input);
    const scan::LoadedScan mask = scan::readScan(maskPath);
    requireScanGrid(maskPath, mask.volume.geometry(), scan.volume.geometry());
    const std::vector<std::uint8_t> inside = selectVoxels(maskPath, mask.volume, label);
    if (std::find(inside.begin(), inside.end(), std::uint8_t{1}) == inside.end()) {
        throw UsageError("--mask " + maskPath + ": no voxel is inside (all zero)");
    }
    const MaskMeasurements m = measureMask(scan.volume, inside);

    if (!args.flag("json")) {
        printTable(m);
        return 0;
    }
    nlohmann::ordered_json j;
    j["input"] = input;
    j["mask"] = maskPath;
    j["label"] = label ? nlohmann::ordered_json(*label) : nlohmann::ordered_json(nullptr);
    j["voxels"] = m.voxels;
    j["volume_ml"] = m.volumeMl;
    j["surface_area_mm2"] = m.surfaceAreaMm2;
    j["axial"] = {{"slice_axis", std::string(1, "ijk"[m.axial.sliceAxis])},
                  {"slice", m.axial.slice},
                  {"longest", lineJson(m.axial.longest)},
                  {"perpendicular", lineJson(m.axial.perpendicular)}};
    j["longest_3d"] = lineJson(m.longest3d);
    j["intensity"] = {{"mean", m.intensity.mean},
                      {"sd", m.intensity.sd},
                      {"min", m.intensity.min},
                      {"max", m.intensity.max}};
    j["world"] = "LPS";
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
}

} // namespace steerseg::cli
