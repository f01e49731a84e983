// steerseg export: a mask already made (by `segment` or another tool) written again on the scan's
// grid, as a mask or as a surface mesh. GL-free: it needs no GPU, only the two files.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/dicom_options.hpp"
#include "core/mask_inside.hpp"
#include "core/volume.hpp"
#include "exports/export_writer.hpp"
#include "model/file_name.hpp"
#include "scan/scan_reader.hpp"
#include "workflow/audit_log.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

namespace steerseg::cli {

namespace {

// The format from --format or the output's extension (model::exportFormatFor); a wrong choice is
// a usage error.
model::ExportFormat chooseFormat(const Args& args, const std::string& output) {
    try {
        return model::exportFormatFor(output, args.value("format"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

// --segment-name, --segment-color r,g,b (0..1) and --segment-label (1..255): what 3D Slicer
// shows for a .seg.nrrd.
exports::SegmentInfo segmentFrom(const Args& args) {
    exports::SegmentInfo segment;
    if (const auto name = args.value("segment-name")) {
        if (name->empty() || name->find_first_of("|\r\n") != std::string::npos) {
            throw UsageError("--segment-name: give a name without '|' or line breaks");
        }
        segment.name = *name;
    }
    if (const auto color = args.value("segment-color")) {
        double r = -1.0, g = -1.0, b = -1.0;
        char end = '\0';
        if (std::sscanf(color->c_str(), "%lf,%lf,%lf%c", &r, &g, &b, &end) != 3 ||
            !(r >= 0.0 && r <= 1.0 && g >= 0.0 && g <= 1.0 && b >= 0.0 && b <= 1.0)) {
            throw UsageError("--segment-color: expected r,g,b each within 0..1 (got '" + *color +
                             "')");
        }
        segment.color = {r, g, b};
    }
    if (const auto label = args.value("segment-label")) {
        int value = 0;
        char end = '\0';
        if (std::sscanf(label->c_str(), "%d%c", &value, &end) != 1 || value < 1 || value > 255) {
            throw UsageError("--segment-label: expected a whole number within 1..255 (got '" +
                             *label + "')");
        }
        segment.label = value;
    }
    return segment;
}

// The mask as 0/1 on the scan's grid. It must be on that grid: the same dimensions and, within
// what a file header's float precision leaves, the same placement in the patient.
std::vector<std::uint8_t> readMaskFor(const std::string& path, const Geometry& scan) {
    const scan::LoadedScan mask = scan::readScan(path);
    const Geometry& g = mask.volume.geometry();
    if (g.dims != scan.dims) {
        throw scan::ScanError(path, "the mask is " + dimsText(g.dims) + " voxels but the scan is " +
                                        dimsText(scan.dims));
    }
    const double far = glm::length(scan.indexToWorld(glm::dvec3(scan.dims - 1)) -
                                   g.indexToWorld(glm::dvec3(g.dims - 1)));
    const double near = glm::length(scan.origin - g.origin);
    const double tolerance = 0.01 * std::min({scan.spacing.x, scan.spacing.y, scan.spacing.z});
    if (std::max(near, far) > tolerance) {
        throw scan::ScanError(path, "the mask is not on the scan's grid (its corner voxels lie " +
                                        std::to_string(std::max(near, far)) +
                                        " mm from the scan's)");
    }
    try {
        return maskInside(mask.volume);
    } catch (const std::invalid_argument& e) {
        throw scan::ScanError(path, e.what());
    }
}

// --send PEER (docs/dicom-network.md): the written SEG goes into the persistent outbox for a
// configured peer and is sent at once; what the peer did not take waits there for the next
// `steerseg send --outbox`. Checked before anything is written.
struct SendTarget {
    std::string peer;
    config::KioskConfig config;
};

std::optional<SendTarget> sendTargetFor(const Args& args, model::ExportFormat format) {
    const auto peer = args.value("send");
    if (!peer) {
        if (args.value("config")) {
            throw UsageError("--config goes with --send");
        }
        return std::nullopt;
    }
    if (format != model::ExportFormat::DicomSeg) {
        throw UsageError("--send: only a DICOM SEG (.dcm) goes to a DICOM peer");
    }
    SendTarget target{*peer, nodeConfig(args)};
    requireSendPeer(target.config.dicom, target.peer);
    return target;
}

// The SEG and its measurement report go together: both queued, then one attempt each.
void sendExported(const SendTarget& target, const std::string& output,
                  const std::vector<std::filesystem::path>& companions,
                  nlohmann::ordered_json& report) {
    const config::DicomConfig& dicom = target.config.dicom;
    workflow::AuditLog audit(target.config.audit.path);
    net::Outbox outbox = configuredOutbox(dicom, audit);
    const std::string id = outbox.enqueue(output, target.peer);
    std::vector<std::string> companionIds;
    for (const std::filesystem::path& companion : companions) {
        companionIds.push_back(outbox.enqueue(companion, target.peer));
    }
    const net::SendOptions options = kiosk::sendOptions(dicom);
    std::optional<net::SendOutcome> outcome;
    std::optional<std::string> companionProblem;
    std::size_t companionsDelivered = 0;
    outbox.deliverDue([&](const std::string& name) { return sendPeer(dicom, name); }, options,
                      [&](const net::OutboxEntry& e, const net::SendOutcome& o) {
                          if (e.id == id) {
                              outcome = o;
                          } else if (std::find(companionIds.begin(), companionIds.end(), e.id) !=
                                     companionIds.end()) {
                              companionsDelivered += o.accepted ? 1 : 0;
                              if (!o.accepted && !companionProblem) {
                                  companionProblem = o.problem;
                              }
                          }
                      });
    report["sent_to"] = target.peer;
    report["outbox_id"] = id;
    if (!companionIds.empty()) {
        report["measurement_report_outbox_id"] = companionIds.front();
    }
    const bool all = outcome && outcome->accepted && companionsDelivered == companionIds.size();
    report["delivered"] = all;
    if (!all) {
        report["waiting_because"] = outcome && !outcome->accepted ? outcome->problem
                                    : companionProblem            ? *companionProblem
                                                                  : "not due yet";
    }
}

} // namespace

int runExport(std::span<const std::string> words) {
    const Args args(words,
                    {"input", "mask", "output", "format", "segment-name", "segment-color",
                     "segment-label", "send", "config"},
                    {});
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string maskPath = args.required("mask");
    const std::string output = args.required("output");
    const model::ExportFormat format = chooseFormat(args, output);
    const exports::SegmentInfo segment = segmentFrom(args);
    const std::optional<SendTarget> sendTo = sendTargetFor(args, format);

    const scan::LoadedScan scan = scan::readScan(input);
    const Geometry& geometry = scan.volume.geometry();
    const std::vector<std::uint8_t> mask = readMaskFor(maskPath, geometry);
    const auto insideVoxels = std::count(mask.begin(), mask.end(), std::uint8_t{1});
    const double voxelVolume = geometry.spacing.x * geometry.spacing.y * geometry.spacing.z;

    nlohmann::ordered_json report;
    report["input"] = input;
    report["mask"] = maskPath;
    report["output"] = output;
    report["format"] = model::exportFormatName(format);
    report["mask_volume_mm3"] = static_cast<double>(insideVoxels) * voxelVolume;
    const exports::ExportSummary written = exports::writeExport(
        output, format, {geometry, mask, {}, segment, scan.dicom.get(), &scan.volume});
    if (model::isSurfaceFormat(format)) {
        report["triangles"] = written.triangles;
        report["vertices"] = written.vertices;
        report["surface_volume_mm3"] = written.surfaceVolumeMm3;
    }
    if (!written.note.empty()) {
        report["note"] = written.note;
    }
    report["world"] = format == model::ExportFormat::Tiff ? "none (voxel order)" : "LPS";
    if (!written.companions.empty()) {
        report["measurement_report"] = written.companions.front().string();
    }
    if (sendTo) {
        sendExported(*sendTo, output, written.companions, report);
    }
    std::printf("%s\n", report.dump(2).c_str());
    return 0;
}

} // namespace steerseg::cli
