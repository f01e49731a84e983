// The engine's side of an erase's run's limit (model::WithdrawLimit, docs/steering.md): checked
// when the workflow sets it, turned into the solver's kept voxels at the run's first step.
#include "core/mask_depth.hpp"
#include "core/volume.hpp"
#include "engine/session_engine.hpp"

#include <cmath>
#include <stdexcept>

namespace steerseg::engine {

// Checked now, kept from the next step: the voxels deeper than the depth in the surface the
// step starts from (on a 256^3 brain the mask's read and its distances took 0.3 s, which the
// erase's first visible change need not wait for). The surface does not move in between.
void SessionEngine::limitWithdrawal(const std::optional<model::WithdrawLimit>& limit) {
    pendingLimit_.reset();
    if (!limit) {
        if (session_) {
            requireSession().setKept({});
        }
        return;
    }
    const session::Session& s = requireSession();
    model::validateSphere(limit->around, s.scan().dims());
    if (!std::isfinite(limit->depthMm) || limit->depthMm < 0.0) {
        throw std::invalid_argument("a withdrawal's depth must be a finite number of mm >= 0");
    }
    pendingLimit_ = limit;
}

// The surface's voxels deeper than the limit's depth, less those in its sphere, where the
// erase's run may take back all it names.
void SessionEngine::keepBeyondLimit(const model::WithdrawLimit& limit) {
    const ScopedSeconds timed(work_.edit);
    session::Session& s = requireSession();
    const glm::ivec3 dims = s.scan().dims();
    const glm::dvec3 spacing = s.scan().geometry().spacing;
    std::vector<std::uint8_t> kept = deeperThan(dims, spacing, s.mask(), limit.depthMm);
    const glm::vec3 scale = model::sphereScale(spacing);
    const model::VoxelBox box = model::sphereVoxelBox(limit.around, scale, dims);
    for (int k = box.lo.z; k <= box.hi.z; ++k) {
        for (int j = box.lo.y; j <= box.hi.y; ++j) {
            for (int i = box.lo.x; i <= box.hi.x; ++i) {
                if (model::sphereHolds(limit.around, glm::dvec3(i, j, k), scale)) {
                    kept[linearIndex(dims, i, j, k)] = 0;
                }
            }
        }
    }
    s.setKept(kept);
}

} // namespace steerseg::engine
