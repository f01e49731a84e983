// Session::setSpeed: the speed's GPU inputs (smoothing, edge factor, the classifier's training)
// built from the plain SpeedSettings. Apart from session.cpp because it is the session's one
// long piece of work, with its own reuse rules for textures and the forest.
#include "gpu/gl.hpp"
#include "gpu/gl_counts.hpp"
#include "session/session.hpp"
#include "session/session_gpu.hpp"
#include "speed/classifier_features_cpu.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/edge_factor.hpp"
#include "speed/smoothing.hpp"

#include <chrono>
#include <utility>
#include <vector>

namespace steerseg::session {

void Session::setSpeed(const SpeedSettings& settings, const SpeedProgress& progress) {
    validateSpeedSettings(settings, scan_.dims());
    Gpu& g = *gpu_;
    // A box that moved alone changes only where the speed blocks: the textures and the
    // classifier stand (each knob detent on a box's face would retrain the forest).
    SpeedSettings sameBox = settings;
    sameBox.box = g.speed.box;
    if (sameBox == g.speed) {
        g.solver.setBox(settings.box);
        g.speed.box = settings.box;
        return;
    }
    const glm::ivec3 dims = scan_.dims();
    // Back to the raw scan first: the solver must not hold textures freed below, and a failure
    // half way leaves a consistent (default) speed.
    g.solver.setSpeedInputs({});
    g.speed = {};
    g.timing = {};
    g.factor.reset();
    const bool smooth = !(settings.smoothing == g.smoothedWith) ||
                        (settings.smoothing.iterations > 0 && !g.smoothed);
    // A retrained classifier writes over its predecessor's texture (allocating a 256^3 one
    // was 0.12 s of a correction's first visible change on llvmpipe). Only where nothing else
    // is allocated before it: kept through a smoothing pass, it would raise the GPU memory's
    // peak by a scan's floats.
    gpu::Texture recycled;
    if (g.classifier && settings.kind == model::SpeedKind::Classify && !smooth) {
        recycled = g.classifier->takeTexture();
    }
    g.classifier.reset();
    const auto start = std::chrono::steady_clock::now();
    if (smooth) {
        g.smoothed.reset(); // before the new copy: two smoothed copies would not fit a large scan
        g.smoothedWith = {};
        speed::SmoothingProgress step;
        if (progress) {
            step = [&progress](int done, int total) { progress("smoothing", done, total); };
        }
        g.smoothed = speed::smoothScan(g.texture.exact(), dims, settings.smoothing, step);
        g.smoothedWith = settings.smoothing;
    }
    const GLuint intensity = g.smoothed ? g.smoothed.id() : g.texture.exact();
    if (settings.kind == model::SpeedKind::Edge) {
        g.factor = speed::edgeFactor(intensity, dims, settings.kappa);
        if (progress) {
            progress("edge factor", 1, 1);
        }
    }
    gpu::finish(); // the time covers the GPU work
    const auto prepared = std::chrono::steady_clock::now();
    g.timing.preprocessingSeconds = std::chrono::duration<double>(prepared - start).count();
    GLuint factor = g.factor.id();
    if (settings.kind == model::SpeedKind::Classify) {
        if (progress) {
            progress("training", 0, 1);
        }
        const auto examples = [](const std::vector<model::Sphere>& spheres) {
            std::vector<speed::Example> out;
            out.reserve(spheres.size());
            for (const model::Sphere& s : spheres) {
                out.push_back({s.centre, s.radius});
            }
            return out;
        };
        // Evaluated where the front goes: the whole scan costs about 30 s on llvmpipe at 256^3,
        // and would stop the kiosk's screen for that long (docs/speed.md).
        speed::ClassifierParams params;
        params.evaluation = speed::ClassifierEvaluation::OnDemand;
        params.placeReach = static_cast<float>(settings.placeReach);
        params.sphereScale = g.solver.sphereScale();
        params.featureStride = speed::classifierFeatureStride(scan_.geometry().spacing);
        g.classifier.emplace(intensity, dims, examples(settings.inside), examples(settings.outside),
                             params, std::move(recycled), g.smoothed ? nullptr : &scan_);
        factor = g.classifier->texture();
        g.timing.trainingSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - prepared).count();
        if (progress) {
            progress("training", 1, 1);
        }
    }
    g.solver.setSpeedInputs(
        {settings.kind, g.smoothed.id(), factor,
         g.classifier ? g.classifier->onDemandForest() : speed::OnDemandForest{},
         settings.withinWindow});
    g.solver.setBox(settings.box);
    g.speed = settings;
}

} // namespace steerseg::session
