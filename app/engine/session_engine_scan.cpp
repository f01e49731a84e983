// What the engine reads of the scan for the workflow (workflow::Engine's probe, measure and
// values): intensity statistics in a sphere, and a sample of the values in a box.
#include "engine/session_engine.hpp"
#include "workflow/probe_sphere.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::engine {

workflow::ProbeResult SessionEngine::probe(const glm::dvec3& voxel, double radiusMm) const {
    const session::ProbeStats s =
        requireSession().probeAt(voxel, radiusMm, session::Stray::LeaveOut);
    const workflow::ProbeResult r{s.mean, s.stddev, s.count, s.leftOut};
    if (r.count > 0) {
        // At least one voxel: the noise is measured between neighbours inside the sphere.
        const Geometry& g = requireSession().scan().geometry();
        lastProbe_ = workflow::probeSphere(voxel, radiusMm, g.spacing, g.dims, 1.0);
    }
    return r;
}

workflow::ProbeResult SessionEngine::measure(const glm::dvec3& voxel, double radiusMm) const {
    const session::ProbeStats s = requireSession().probeAt(voxel, radiusMm, session::Stray::Keep);
    return {s.mean, s.stddev, s.count};
}

std::vector<double> SessionEngine::values(const model::Box& box, std::size_t most) const {
    const Volume& scan = requireSession().scan();
    model::validateBox(box, scan.dims());
    const glm::ivec3 size = model::sizeOf(box);
    const double count = static_cast<double>(size.x) * size.y * size.z;
    // The same stride along every axis: the sample stays spread through the whole box.
    const int stride =
        std::max(1, static_cast<int>(std::ceil(
                        std::cbrt(count / static_cast<double>(std::max<std::size_t>(most, 1))))));
    std::vector<double> out;
    for (int k = box.lo.z; k <= box.hi.z; k += stride) {
        for (int j = box.lo.y; j <= box.hi.y; j += stride) {
            for (int i = box.lo.x; i <= box.hi.x && out.size() < most; i += stride) {
                out.push_back(scan.valueAt(i, j, k));
            }
        }
    }
    return out;
}

} // namespace steerseg::engine
