#include "seed_level_set.hpp"

#include "cli/args.hpp"
#include "model/level_set_params.hpp"

#include <algorithm>
#include <glm/glm.hpp>
#include <itkImageRegionIteratorWithIndex.h>
#include <limits>
#include <stdexcept>

namespace steerseg::itkbench {

Seed parseSeed(const std::string& text) {
    const std::vector<double> v = cli::parseNumberList(text, 4, "--seed");
    if (!(v[3] > 0.0)) {
        throw cli::UsageError("--seed: radius must be > 0, got '" + text + "'");
    }
    return Seed{v[0], v[1], v[2], v[3]};
}

FloatImage::Pointer seedLevelSet(const itk::ImageBase<3>* grid, std::span<const Seed> seeds,
                                 SeedSpheres spheres) {
    if (seeds.empty()) {
        throw std::runtime_error("at least one seed is needed");
    }
    const auto size = grid->GetLargestPossibleRegion().GetSize();
    for (const Seed& s : seeds) {
        const double c[3] = {s.i, s.j, s.k};
        for (unsigned d = 0; d < 3; ++d) {
            if (c[d] < 0.0 || c[d] > static_cast<double>(size[d]) - 1.0) {
                throw std::runtime_error("seed centre outside the grid " + std::to_string(size[0]) +
                                         "x" + std::to_string(size[1]) + "x" +
                                         std::to_string(size[2]));
            }
        }
    }
    const auto spacing = grid->GetSpacing();
    const glm::vec3 scale = spheres == SeedSpheres::Voxels
                                ? glm::vec3(1.0F)
                                : model::sphereScale({spacing[0], spacing[1], spacing[2]});
    auto phi = FloatImage::New();
    phi->CopyInformation(grid);
    phi->SetRegions(grid->GetLargestPossibleRegion());
    phi->Allocate();
    itk::ImageRegionIteratorWithIndex<FloatImage> it(phi, phi->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        const auto idx = it.GetIndex();
        const glm::vec3 voxel(static_cast<float>(idx[0]), static_cast<float>(idx[1]),
                              static_cast<float>(idx[2]));
        float d = std::numeric_limits<float>::max();
        for (const Seed& s : seeds) {
            const model::Sphere sphere{glm::vec3(static_cast<float>(s.i), static_cast<float>(s.j),
                                                 static_cast<float>(s.k)),
                                       static_cast<float>(s.r)};
            d = std::min(d, model::sphereDistance(sphere, voxel, scale));
        }
        it.Set(d);
    }
    return phi;
}

} // namespace steerseg::itkbench
