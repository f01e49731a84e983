#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "scan/scan_reader.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

namespace steerseg::cli {

int runInfo(std::span<const std::string> words) {
    const Args args(words, {}, {});
    if (args.positional().size() != 1) {
        throw UsageError("expected exactly one scan PATH");
    }
    const scan::LoadedScan scan = scan::readScan(args.positional().front());
    const Geometry& g = scan.volume.geometry();
    const IntensityStats& s = scan.volume.stats();
    nlohmann::ordered_json j;
    j["dims"] = {g.dims.x, g.dims.y, g.dims.z};
    j["spacing"] = {g.spacing.x, g.spacing.y, g.spacing.z};
    j["origin"] = {g.origin.x, g.origin.y, g.origin.z};
    j["direction"] = g.directionRowMajor();
    j["type"] = voxelTypeName(scan.volume.type());
    j["min"] = s.min;
    j["max"] = s.max;
    j["mean"] = s.mean;
    j["format"] = scan.format;
    j["rescale"] = {{"slope", scan.volume.rescale().slope},
                    {"intercept", scan.volume.rescale().intercept}};
    j["world"] = "LPS";
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
}

} // namespace steerseg::cli
