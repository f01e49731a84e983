// steerseg segment: one segmentation run, offscreen; the mask to a file, the report to stdout.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/segment_clicks.hpp"
#include "cli/segmentation_options.hpp"
#include "core/mask_overlap.hpp"
#include "files/file_write.hpp"
#include "gpu/gpu_info.hpp"
#include "model/export_format.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "scan/scan_reader.hpp"
#include "session/segment_report.hpp"
#include "session/session.hpp"

#include <cstdio>
#include <optional>
#include <span>
#include <stdexcept>

namespace steerseg::cli {

int runSegment(std::span<const std::string> words) {
    std::vector<std::string> valueOptions = segmentationValueOptions();
    valueOptions.insert(valueOptions.end(), {"input", "output", "report", "format", "reference",
                                             "reference-label", "click", "box", "config"});
    const Args args(words, valueOptions, segmentationFlagOptions());
    if (!args.values("click").empty() || args.value("box")) {
        if (!args.positional().empty()) {
            throw UsageError("unexpected argument '" + args.positional().front() + "'");
        }
        return runSegmentClicks(args);
    }
    if (args.value("config")) {
        throw UsageError(
            "--config goes with --click or --box (the kiosk's settings for the prompts)");
    }
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string output = args.required("output");
    SegmentationRequest request = parseSegmentation(args);
    model::ExportFormat format{};
    try {
        format = model::exportFormatFor(output, args.value("format"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }

    // The scan first, then the reference: a bad file is reported before the GPU is brought up.
    scan::LoadedScan scan = scan::readScan(input);
    completeWithScan(request, scan.volume);
    const auto referenceFile = args.value("reference");
    int referenceLabel = -1;
    std::optional<Volume> referenceLabels;
    if (referenceFile) {
        const std::string& file = *referenceFile;
        if (const auto label = args.value("reference-label")) {
            referenceLabel = static_cast<int>(parseNumber(*label, "--reference-label"));
        }
        referenceLabels = scan::readScan(file).volume;
        if (referenceLabels->dims() != scan.volume.dims()) {
            throw UsageError("--reference " + file + " is not on the scan's grid (" +
                             dimsText(referenceLabels->dims()) + " voxels, the scan " +
                             dimsText(scan.volume.dims()) + ")");
        }
    } else if (args.value("reference-label")) {
        throw UsageError("--reference-label goes with --reference");
    }
    auto context = platform::createOffscreenContext();
    session::Session session(std::move(scan), request.options);
    applySegmentation(session, request);
    const session::RunOutcome run = session.run(request.mode);

    const std::vector<std::uint8_t> mask = session.mask();
    if (session::surfaceVanished(mask)) {
        std::fprintf(stderr,
                     "steerseg: note: the surface vanished after %d iterations: nothing is inside "
                     "(a larger seed, a wider eps or a smaller alpha)\n",
                     session.stats().iterations);
    }
    // Surfaces come from the level set's zero crossing (Session::exportAs), not the mask.
    const exports::ExportSummary written = session.exportAs(output, format);
    if (!written.note.empty()) {
        std::fprintf(stderr, "steerseg: note: %s\n", written.note.c_str());
    }
    std::optional<session::ReferenceOverlap> reference;
    if (referenceLabels) {
        reference = session::ReferenceOverlap{*referenceFile, referenceLabel,
                                              maskOverlap(mask, *referenceLabels, referenceLabel)};
    }
    const std::string text = session::segmentReport(
        session, run, mask,
        {input, output, gpu::queryGpuInfo().renderer, request.params, reference});
    if (const auto report = args.value("report")) {
        writeReport(*report, text);
    }
    std::printf("%s\n", text.c_str());
    return 0;
}

} // namespace steerseg::cli
