// steerseg measure: one structure's measurements (core/mask_measurements, docs/measurements.md)
// from a mask on the scan's grid. GL-free: it needs no GPU, only the two files.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "core/mask_inside.hpp"
#include "core/mask_measurements.hpp"
#include "core/volume.hpp"
#include "exports/label_description.hpp"
#include "scan/scan_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
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

// The label values a label map holds (0 left out); stops past `most`, so that a scan given as a
// mask does not gather millions.
std::set<long long> labelValues(const Volume& mask, std::size_t most) {
    std::set<long long> values;
    for (std::size_t n = 0; n < mask.geometry().voxelCount() && values.size() <= most; ++n) {
        const double v = mask.realAt(n);
        if (v != 0.0) {
            values.insert(std::llround(v));
        }
    }
    return values;
}

std::string namedText(const std::vector<exports::DescribedLabel>& names) {
    std::string text;
    for (const exports::DescribedLabel& l : names) {
        text += (text.empty() ? "" : ", ") + std::to_string(l.value) + " " + l.name;
    }
    return text.empty() ? "none" : text;
}

// With a label description beside the label map (ITK-SNAP's, as the exports write it), a label
// it does not name means the map and its names no longer belong together: refused before
// anything is measured, so a figure is never reported under the wrong structure's name.
// Returns the measured label's name ("" without a description or without --label).
std::string checkDescribedLabels(const std::string& path, const Volume& mask,
                                 std::optional<long long> label) {
    const std::filesystem::path sidecar = exports::labelDescriptionPathFor(path);
    std::error_code ec;
    if (!std::filesystem::exists(sidecar, ec)) {
        return {};
    }
    std::vector<exports::DescribedLabel> names;
    try {
        names = exports::readLabelDescription(sidecar);
    } catch (const std::runtime_error& e) {
        throw UsageError(std::string(e.what()) + " (the names of " + path + "'s labels)");
    }
    const auto nameOf = [&](long long value) -> const exports::DescribedLabel* {
        const auto it =
            std::find_if(names.begin(), names.end(),
                         [&](const exports::DescribedLabel& l) { return l.value == value; });
        return it == names.end() ? nullptr : &*it;
    };
    constexpr std::size_t kMostLabels = 256;
    for (const long long value : labelValues(mask, kMostLabels)) {
        if (nameOf(value) == nullptr) {
            throw UsageError("--mask " + path + " holds label " + std::to_string(value) +
                             ", which " + sidecar.filename().string() +
                             " beside it does not name (it names " + namedText(names) + ")");
        }
    }
    if (!label) {
        return {};
    }
    const exports::DescribedLabel* named = nameOf(*label);
    if (named == nullptr) {
        throw UsageError("--label " + std::to_string(*label) + ": " + sidecar.filename().string() +
                         " does not name it (it names " + namedText(names) + ")");
    }
    return named->name;
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

void printTable(const MaskMeasurements& m, const std::string& structure) {
    const char* axes = "ijk";
    if (!structure.empty()) {
        std::printf("structure             %s\n", structure.c_str());
    }
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
    const std::string name = checkDescribedLabels(maskPath, mask.volume, label);
    const std::vector<std::uint8_t> inside = selectVoxels(maskPath, mask.volume, label);
    if (std::find(inside.begin(), inside.end(), std::uint8_t{1}) == inside.end()) {
        throw UsageError("--mask " + maskPath + ": no voxel is inside (all zero)");
    }
    const MaskMeasurements m = measureMask(scan.volume, inside);

    if (!args.flag("json")) {
        printTable(m, name);
        return 0;
    }
    nlohmann::ordered_json j;
    j["input"] = input;
    j["mask"] = maskPath;
    j["label"] = label ? nlohmann::ordered_json(*label) : nlohmann::ordered_json(nullptr);
    j["name"] = name.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(name);
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
