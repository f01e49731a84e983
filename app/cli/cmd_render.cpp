// steerseg render: one view of a scan (and its segmentation) to an image file, offscreen.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/segmentation_options.hpp"
#include "exports/image_file.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "render/render_names.hpp"
#include "render/renderer.hpp"
#include "render/slice_frame.hpp"
#include "scan/scan_reader.hpp"
#include "session/session.hpp"

#include <cstdio>
#include <optional>
#include <stdexcept>

namespace steerseg::cli {

namespace {

std::vector<std::string> valueOptions() {
    std::vector<std::string> names = {"input", "output", "view",   "slice",   "clip",
                                      "roi",   "size",   "preset", "window",  "camera",
                                      "orbit", "zoom",   "pan",    "surface", "mask"};
    const std::vector<std::string> segmentation = segmentationValueOptions();
    names.insert(names.end(), segmentation.begin(), segmentation.end());
    return names;
}

std::vector<std::string> flagOptions() {
    std::vector<std::string> names = {"speed-view", "no-labels"};
    const std::vector<std::string> segmentation = segmentationFlagOptions();
    names.insert(names.end(), segmentation.begin(), segmentation.end());
    return names;
}

template <typename F> auto usage(F&& parse) -> decltype(parse()) {
    try {
        return parse();
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

render::ClipPlane parseClip(const std::string& text) {
    const std::vector<double> v = parseNumberList(text, 4, "--clip");
    const glm::dvec3 n(v[0], v[1], v[2]);
    if (glm::length(n) < 1e-12) {
        throw UsageError("--clip: the normal nx,ny,nz must not be zero");
    }
    return {true, n, v[3]};
}

// Display options that need no scan; checked before the scan is read (which may take seconds).
void parseDisplayOptions(const Args& args, render::ViewParams& p) {
    if (auto preset = args.value("preset")) {
        (void)usage([&] { return render::parseTfPreset(*preset); });
    }
    if (auto window = args.value("window")) {
        const std::vector<double> v = parseNumberList(*window, 2, "--window");
        if (!(v[1] > 0.0)) {
            throw UsageError("--window: width must be positive");
        }
    }
    if (auto zoom = args.number("zoom")) {
        if (!(*zoom > 0.0) || *zoom > 1000.0) {
            throw UsageError("--zoom: expected a factor in (0, 1000]");
        }
        p.zoom = *zoom;
    }
    if (auto pan = args.value("pan")) {
        const std::vector<double> v = parseNumberList(*pan, 2, "--pan");
        p.pan = {v[0], v[1]};
    }
    if (auto orbit = args.value("orbit")) {
        (void)parseNumberList(*orbit, 2, "--orbit");
    }
    if (auto camera = args.value("camera")) {
        (void)usage([&] { return render::parseCameraPreset(*camera); });
    }
    if (auto roi = args.value("roi")) {
        p.roi = usage([&] { return render::parseRoiMode(*roi); });
    }
    if (auto surface = args.value("surface")) {
        p.surface = usage([&] { return render::parseSurfaceMode(*surface); });
    }
    if (auto clip = args.value("clip")) {
        p.clip = parseClip(*clip);
    }
    p.labels = !args.flag("no-labels");
}

// Presets and window from the scan's intensities, then the options that override them.
void applyIntensityOptions(const Args& args, const Volume& volume, render::ViewParams& p) {
    if (auto preset = args.value("preset")) {
        const render::TfPreset which = render::parseTfPreset(*preset);
        p.transfer = render::transferPreset(which, volume.stats());
        p.window = render::windowPreset(which, volume.stats());
    }
    if (auto window = args.value("window")) {
        const std::vector<double> v = parseNumberList(*window, 2, "--window");
        p.window = {v[0], v[1]};
    }
}

void applyCamera(const Args& args, const Geometry& g, render::ViewParams& p) {
    if (auto camera = args.value("camera")) {
        const render::CameraPreset which = render::parseCameraPreset(*camera);
        p.camera =
            render::Camera::preset(which, render::volumeCentre(g), render::volumeExtentMm(g));
    }
    if (auto orbit = args.value("orbit")) {
        const std::vector<double> v = parseNumberList(*orbit, 2, "--orbit");
        p.camera.orbit(v[0], v[1]);
    }
}

// Options checked before the scan is read (reading the scan may take seconds).
void parseSliceOptions(const Args& args, render::ViewParams& p) {
    if (auto slice = args.integer("slice")) {
        if (p.kind == render::ViewKind::Volume3d) {
            throw UsageError("--slice applies to axial, coronal and sagittal views");
        }
        if (*slice < 0 || *slice > 65535) {
            throw UsageError("--slice must be a voxel index >= 0");
        }
        p.slice = static_cast<int>(*slice);
    }
}

// The view shows the speed in force: with a segmentation, its own (T and eps from --probe, or
// classify's, which reads neither); without one, the threshold speed of --T and --eps.
void parseSpeedOptions(const Args& args, bool segment, render::ViewParams& p) {
    const auto target = args.number("T");
    const auto eps = args.number("eps");
    if (args.flag("speed-view")) {
        if (!segment && (!target || !eps || !(*eps > 0.0))) {
            throw UsageError("--speed-view needs --T and a positive --eps, or a segmentation "
                             "whose speed it shows");
        }
        p.content = render::SliceContent::Speed;
        if (target && eps) {
            p.speed = {*target, *eps};
        }
    }
}

void checkSliceRange(const Geometry& g, render::ViewParams& p) {
    if (p.slice >= 0) {
        const int axis = render::sliceAxisFor(g, p.kind);
        if (p.slice >= g.dims[axis]) {
            throw UsageError("--slice " + std::to_string(p.slice) + " is outside 0.." +
                             std::to_string(g.dims[axis] - 1) + " (index axis " +
                             std::to_string(axis) + ")");
        }
    }
}

} // namespace

int runRender(std::span<const std::string> words) {
    const Args args(words, valueOptions(), flagOptions());
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string output = args.required("output");
    render::ViewParams p;
    p.kind = usage([&] { return render::parseViewKind(args.value("view").value_or("3d")); });
    const auto [w, h] = parseSize(args.value("size").value_or("512x512"), "--size", 1, 8192);
    p.size = {w, h};
    const bool segment = wantsSegmentation(args);
    if (args.value("mask") && segment) {
        throw UsageError("--mask and the segmentation options exclude each other");
    }
    std::optional<SegmentationRequest> request;
    if (segment) {
        request = parseSegmentation(args);
    }

    parseDisplayOptions(args, p);
    parseSliceOptions(args, p);
    parseSpeedOptions(args, segment, p);

    // The scan first: a bad file is reported before the GPU is brought up.
    scan::LoadedScan scan = scan::readScan(input);
    const Geometry g = scan.volume.geometry();
    checkSliceRange(g, p);
    if (request) {
        completeWithScan(*request, scan.volume);
        // --T and --eps, or the probe's: the speed that moves the level set, so it places the
        // 3D view's surface between voxels too
        p.speed = {static_cast<double>(request->params.T), static_cast<double>(request->params.eps),
                   true};
    }
    auto context = platform::createOffscreenContext();
    // The level set comes from the solver's brick pool; the renderer never copies phi.
    session::Session session(std::move(scan.volume), std::move(scan.format),
                             request ? request->options : model::SolverOptions{});
    if (const auto mask = args.value("mask")) {
        session.startFromMask(*mask);
    } else if (request) {
        applySegmentation(session, *request);
        (void)session.run(request->mode);
    }
    const render::ViewParams defaults = session.defaultView(p.kind, p.size);
    p.camera = defaults.camera;
    p.transfer = defaults.transfer;
    p.window = defaults.window;
    applyCamera(args, g, p);
    applyIntensityOptions(args, session.scan(), p);
    if (p.content == render::SliceContent::Speed) {
        session.completeSpeed(); // the whole slice, not only where the front went
    }
    session.render(p);
    exports::writeImage(output, session.picture());
    return 0;
}

} // namespace steerseg::cli
