#include "kiosk/settings_from_config.hpp"

#include <algorithm>

namespace steerseg::kiosk {

namespace {

void turnOffFailedSpeeds(workflow::Settings& s, const session::NumericsReport& numerics) {
    for (const session::SpeedNumerics& n : numerics.speeds) {
        if (!n.passed) {
            s.speedsOff.push_back({n.kind, n.failure});
        }
    }
    if (numerics.passed(s.defaultSpeed)) {
        return;
    }
    const auto passed = std::find_if(model::kSpeedKinds.begin(), model::kSpeedKinds.end(),
                                     [&](model::SpeedKind k) { return numerics.passed(k); });
    // None passed: the solver itself is wrong here. The paper's speed stays on, the alarm says
    // what failed, and the operator's eyes judge the masks.
    s.defaultSpeed = passed != model::kSpeedKinds.end() ? *passed : model::SpeedKind::Threshold;
    for (const workflow::SpeedOff& off : s.speedsOff) {
        if (off.kind == s.defaultSpeed) {
            s.defaultSpeedFailed = off.why;
        }
    }
    std::erase_if(s.speedsOff,
                  [&](const workflow::SpeedOff& off) { return off.kind == s.defaultSpeed; });
}

} // namespace

workflow::Settings workflowSettings(const config::KioskConfig& config,
                                    const session::NumericsReport* numerics) {
    workflow::Settings s;
    for (const config::Preset& p : config.presets) {
        s.presets.push_back(
            {p.name, p.T, p.eps, p.alpha, p.windowLevel, p.windowWidth, p.transfer});
    }
    s.epsFloor = config.probe.epsFloor;
    s.probeEpsFactor = config.probe.epsFactor;
    s.probeRadiusMm = config.probe.radiusMm;
    s.defaultRadius = config.brush.radius;
    s.correctionReach = config.brush.correctionReach;
    s.eraseRunGrowth = config.brush.eraseRunGrowth;
    s.eraseWithdrawMm = config.brush.eraseWithdrawMm;
    s.defaultSpeed = config.speed.kind;
    s.classifyWithinWindow = config.speed.classifyWithinWindow;
    s.classifyPlaceReach = config.speed.classifyPlaceReach;
    s.exportFolder = config.exports.folder;
    s.exportFormats = config.exports.formats;
    s.structureKinds = config.structures;
    s.structuresOverlap = config.segmentation.structuresOverlap;
    if (numerics != nullptr) {
        turnOffFailedSpeeds(s, *numerics);
    }
    return s;
}

platform::DisplayOptions displayOptions(const config::DisplayConfig& display) {
    platform::DisplayOptions o;
    o.width = display.width;
    o.height = display.height;
    o.fullscreen = display.fullscreen;
    o.drmDevice = display.drmDevice;
    o.connector = display.connector;
    o.mode = display.mode;
    o.touchCalibration = display.touchCalibration;
    return o;
}

} // namespace steerseg::kiosk
