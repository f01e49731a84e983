// steerseg-mask-stats SCAN MASK: intensity mean/std inside an expert mask and a seed well inside
// it, as JSON; the ITK benchmark derives T, eps and the seed from these.
#include "itk_image_io.hpp"
#include "mask_stats.hpp"

#include <cstdio>
#include <exception>
#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: steerseg-mask-stats SCAN MASK\n");
        return 2;
    }
    try {
        using namespace steerseg::itkbench;
        const FloatImage::Pointer scan = readFloatImage(argv[1]);
        const MaskImage::Pointer mask = readMask(argv[2]);
        const MaskStats s = maskStats(scan, mask);
        nlohmann::ordered_json j;
        j["voxels"] = s.voxels;
        j["mean"] = s.mean;
        j["std"] = s.std;
        j["centroid"] = {s.centroid[0], s.centroid[1], s.centroid[2]};
        j["centroid_inside"] = s.centroidInside;
        j["deepest"] = {s.deepest[0], s.deepest[1], s.deepest[2]};
        j["depth"] = s.depth;
        j["probe_voxels"] = s.probeVoxels;
        j["probe_mean"] = s.probeMean;
        j["probe_std"] = s.probeStd;
        char seed[128];
        std::snprintf(seed, sizeof seed, "%.0f,%.0f,%.0f,%.3g", s.seed.i, s.seed.j, s.seed.k,
                      s.seed.r);
        j["seed"] = seed;
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "steerseg-mask-stats: %s\n", e.what());
        return 1;
    }
}
