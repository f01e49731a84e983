#pragma once

// What the workflow takes from the configuration: tissue presets, the probe's rules, the brush,
// the export folder and the depth of undo. Plain data; config/ fills it from TOML and
// validateSettings() says in one line what is wrong with it.
#include "model/speed_kind.hpp" // the enum only
#include "model/structure.hpp"

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace steerseg::workflow {

// A one-touch alternative to probing: the speed's parameters and the display for one tissue.
struct TissuePreset {
    std::string name; // "CT soft tissue"
    double T = 0.0;   // real units
    double eps = 0.0; // real units
    double alpha = 0.8;
    double windowLevel = 0.0;
    double windowWidth = 0.0; // <= 0: keep the current window
    std::string transfer;     // transfer-function preset name ("" = keep the current one)
};

using WallClock = std::function<std::chrono::system_clock::time_point()>;

// A speed this GPU computed wrong in the start-up numerics check (session/numerics_check): the
// check's one line on why.
struct SpeedOff {
    model::SpeedKind kind = model::SpeedKind::Classify;
    std::string why;
};

struct Settings {
    std::vector<TissuePreset> presets; // in the order the panel lists them
    // A small probe in homogeneous tissue has a tiny spread and the front would never move:
    // a probe sets eps = max(probeEpsFactor * stddev, epsFloor). Real units.
    double epsFloor = 0.0;
    double probeEpsFactor = 2.0;
    double probeRadiusMm = 5.0; // a model::Probe action's radius when it gives none (<= 0)
    double defaultRadius = 3.0; // the brush after a load, voxels (clamped to the scan's range)
    // A later correction's run moves the surface only within this many of its brush radii of
    // the click (docs/steering.md): the rest stays as the operator accepted it. 0: everywhere.
    double correctionReach = 3.0;
    // An erase that changed the speed runs over the whole surface, so that the tissue it names
    // leaves it wherever it lies; that run may leave the surface larger than before the erase
    // by at most this fraction of its volume. Past it the front is creeping through tissue the
    // speed cannot tell from the structure (docs/steering.md): the run is taken back to the
    // erase and goes on with the surface beyond the correction's reach only withdrawing, and
    // later erases' runs do so from the start until T, eps, alpha or the kind of speed change.
    // 0: no limit.
    double eraseRunGrowth = 0.25;
    // Beyond its reach an erase's run takes the surface back at most this far (mm) from where
    // it stood after the erase: appearance cannot tell an erased leak from the structure's own
    // tissue, and a leak lies at the surface where the structure's tissue lies deep
    // (docs/steering.md). 0: as far as the speed says.
    double eraseWithdrawMm = 4.0;
    // Default exports: <folder>/<scan>_<UTC time>.<format>.
    std::filesystem::path exportFolder = ".";
    // A default export writes one file per format, in this order ("nii.gz", "nii", "nrrd": the
    // extensions the engine's writer knows); the first is the one the status reports.
    std::vector<std::string> exportFormats{"nii.gz"};
    int maxUndo = 32; // undo entries kept; older ones are dropped
    // The speed after a load. Classify runs the threshold speed until it has an example of
    // each kind; a speed the engine refuses after a load leaves the threshold speed, with a
    // notice.
    model::SpeedKind defaultSpeed = model::SpeedKind::Threshold;
    // Classify bounded by the threshold's window T +- eps (docs/speed.md "Classify within the
    // window"): the classifier removes what the window admits and adds nothing it refuses,
    // where an unbounded forest may take in tissue unlike any example (the air around a liver
    // after one erase: docs/steering.md).
    bool classifyWithinWindow = true;
    // Classify: an example decides where the classifier is unsure, within this many of its
    // radii (speed/place_vote, docs/speed.md "Where appearance is unsure"): an erase in a
    // tumour's leak holds the tissue around it out though it looks like the tumour. 0: never.
    double classifyPlaceReach = 3.0;
    // Speeds off on this GPU: the panel leaves them out, SetSpeed refuses them, and whatever
    // names one (a resumed session) runs defaultSpeed instead, which must not be one of them;
    // the screen says why all along (Status::gpuAlarm).
    std::vector<SpeedOff> speedsOff;
    // Set when the default speed failed the check too (every speed did: the solver itself is
    // wrong on this GPU), with the check's why: it runs, and the alarm says so.
    std::string defaultSpeedFailed;
    // The site's structures (the config's [[structures]]): a new structure of one of these names
    // takes its codes and colour; any other name is free text, coded as tissue.
    std::vector<model::StructureInfo> structureKinds;
    // Structures may overlap; by default the others act as barriers to the active one.
    bool structuresOverlap = false;
    WallClock clock; // export names' time stamps; empty: the system clock (tests fix it)
};

// Throws std::invalid_argument with one line naming the first bad value: non-finite numbers,
// a negative eps floor, a probe factor or radius <= 0, maxUndo outside [1, 10000], an unknown
// default speed, a preset without a name or with a duplicate one, or with eps < 0 or alpha
// outside [0, 1].
void validateSettings(const Settings& settings);

} // namespace steerseg::workflow
