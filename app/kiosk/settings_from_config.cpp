#include "kiosk/settings_from_config.hpp"

namespace steerseg::kiosk {

workflow::Settings workflowSettings(const config::KioskConfig& config) {
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
    s.defaultSpeed = config.speed.kind;
    s.classifyWithinWindow = config.speed.classifyWithinWindow;
    s.classifyPlaceReach = config.speed.classifyPlaceReach;
    s.exportFolder = config.exports.folder;
    s.exportFormats = config.exports.formats;
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
