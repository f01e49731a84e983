#include "workflow/settings.hpp"

#include "model/speed_kind.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace steerseg::workflow {

namespace {

void require(bool ok, const std::string& what) {
    if (!ok) {
        throw std::invalid_argument("workflow settings: " + what);
    }
}

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

} // namespace

void validateSettings(const Settings& s) {
    require(std::isfinite(s.epsFloor) && s.epsFloor >= 0.0,
            "eps floor must be a finite number >= 0 (got " + number(s.epsFloor) + ")");
    require(std::isfinite(s.probeEpsFactor) && s.probeEpsFactor > 0.0,
            "probe eps factor must be a finite number > 0 (got " + number(s.probeEpsFactor) + ")");
    require(std::isfinite(s.probeRadiusMm) && s.probeRadiusMm > 0.0,
            "probe radius must be a finite number of mm > 0 (got " + number(s.probeRadiusMm) + ")");
    require(std::isfinite(s.defaultRadius) && s.defaultRadius > 0.0,
            "brush radius must be a finite number of voxels > 0 (got " + number(s.defaultRadius) +
                ")");
    require(std::isfinite(s.correctionReach) && s.correctionReach >= 0.0,
            "correction reach must be a finite number of brush radii >= 0 (got " +
                number(s.correctionReach) + ")");
    require(std::isfinite(s.eraseRunGrowth) && s.eraseRunGrowth >= 0.0,
            "erase run growth must be a finite fraction >= 0 (got " + number(s.eraseRunGrowth) +
                ")");
    require(std::isfinite(s.eraseWithdrawMm) && s.eraseWithdrawMm >= 0.0,
            "erase withdraw depth must be a finite number of mm >= 0 (got " +
                number(s.eraseWithdrawMm) + ")");
    require(std::isfinite(s.classifyPlaceReach) && s.classifyPlaceReach >= 0.0,
            "classify place reach must be a finite number of example radii >= 0 (got " +
                number(s.classifyPlaceReach) + ")");
    require(s.maxUndo >= 1 && s.maxUndo <= 10000,
            "undo depth must be within [1, 10000] (got " + std::to_string(s.maxUndo) + ")");
    require(model::validSpeedKind(s.defaultSpeed), "the default speed is not a known speed");
    for (const SpeedOff& off : s.speedsOff) {
        require(off.kind != s.defaultSpeed, "the default speed is off on this GPU");
    }
    require(!s.exportFormats.empty(), "at least one export format is needed");
    for (const std::string& format : s.exportFormats) {
        require(!format.empty() && format.find_first_of("/\\") == std::string::npos &&
                    format.front() != '.',
                "export format '" + format + "' is not a file extension");
    }
    std::set<std::string> names;
    for (const TissuePreset& p : s.presets) {
        require(!p.name.empty(), "a tissue preset has no name");
        require(names.insert(p.name).second, "tissue preset '" + p.name + "' is named twice");
        const std::string where = "tissue preset '" + p.name + "': ";
        require(std::isfinite(p.T), where + "T must be a finite number");
        require(std::isfinite(p.eps) && p.eps >= 0.0, where + "eps must be a finite number >= 0");
        require(std::isfinite(p.alpha) && p.alpha >= 0.0 && p.alpha <= 1.0,
                where + "alpha must be within [0, 1]");
        require(std::isfinite(p.windowLevel) && std::isfinite(p.windowWidth),
                where + "window level and width must be finite numbers");
    }
    std::set<std::string> kinds;
    for (const model::StructureInfo& k : s.structureKinds) {
        const std::string problem = model::structureNameProblem(k.name);
        require(problem.empty(), "a structure kind: " + problem);
        require(kinds.insert(k.name).second, "structure '" + k.name + "' is listed twice");
        const std::string where = "structure '" + k.name + "': ";
        const std::string category = model::structureCodeProblem(k.category);
        require(category.empty(), where + "category: " + category);
        const std::string type = model::structureCodeProblem(k.type);
        require(type.empty(), where + "type: " + type);
        for (int c = 0; c < 3; ++c) {
            require(k.colour[c] >= 0.0 && k.colour[c] <= 1.0,
                    where + "a colour's r, g and b lie within 0..1");
        }
    }
}

} // namespace steerseg::workflow
