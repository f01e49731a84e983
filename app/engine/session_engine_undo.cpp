// The engine's undo (workflow::Engine's snapshot, restore and drop): copies of the level set in
// GPU memory within a budget, the oldest moved to host memory as masks beyond it.
#include "engine/session_engine.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace steerseg::engine {

workflow::SnapshotId SessionEngine::snapshot() {
    const ScopedSeconds timed(work_.snapshot);
    const workflow::SnapshotId id = nextSnapshot_++;
    Snapshot s{std::nullopt, {}, barriers_};
    std::size_t bytes = 0;
    if (hasLevelSet()) {
        session::Session& session = requireSession();
        try {
            s.copy = session.copyLevelSet();
            bytes = s.copy->levelSet.bytes();
            undoGpuBytes_ += bytes;
        } catch (const std::exception&) {
            // The GPU could not hold another copy: this one goes to host memory at once.
            s.copy.reset();
            s.mask = encodeRuns(session.mask());
        }
    }
    snapshots_[id] = std::move(s);
    // Moving the older copies out reads each back and encodes its mask: 0.13-0.19 s of a
    // correction's first visible change on a 207x256x215 scan, were it done here. It waits
    // for the frame after the change (keepUndoWithinBudget), which leaves the copies within
    // the budget: meanwhile the copies since then, an edit's two (before and after it), may
    // stand above it. A third, or a copy that does not fit alone, and they go out now.
    if (++untidyCopies_ > kUntidyCopies || bytes > undoGpuBudget_) {
        keepUndoWithinBudget();
    }
    return id;
}

// The oldest copies leave the GPU first: undo reaches them last. A copy that cannot be read
// back stays a copy, above the budget, and the next call tries again: the kiosk calls this
// every frame, outside any edit that could be taken back, and a failing GPU says so elsewhere.
void SessionEngine::keepUndoWithinBudget() {
    untidyCopies_ = 0;
    for (auto it = snapshots_.begin(); it != snapshots_.end() && undoGpuBytes_ > undoGpuBudget_;
         ++it) {
        Snapshot& s = it->second;
        if (s.copy) {
            try {
                s.mask = encodeRuns(requireSession().maskOf(*s.copy));
            } catch (const std::exception&) {
                return;
            }
            undoGpuBytes_ -= s.copy->levelSet.bytes();
            s.copy.reset();
        }
    }
}

std::size_t SessionEngine::undoMasks() const {
    return static_cast<std::size_t>(
        std::count_if(snapshots_.begin(), snapshots_.end(),
                      [](const auto& entry) { return !entry.second.mask.runs.empty(); }));
}

void SessionEngine::restore(workflow::SnapshotId id) {
    const ScopedSeconds timed(work_.restore);
    const auto it = snapshots_.find(id);
    if (it == snapshots_.end()) {
        throw std::logic_error("undo: snapshot " + std::to_string(id) + " is gone");
    }
    setBarriers(it->second.barriers);
    if (it->second.copy) {
        requireSession().restoreLevelSet(*it->second.copy);
        insideCounted_.reset();
        changed();
    } else {
        putMask(it->second.mask);
    }
}

void SessionEngine::setMask(const MaskRuns& mask) {
    setBarriers({}); // a mask alone: whoever restores the barriers places them again
    putMask(mask);
}

void SessionEngine::putMask(const MaskRuns& mask) {
    if (mask.runs.empty()) {
        requireSession().clearLevelSet();
    } else {
        requireSession().setMask(decodeRuns(mask));
    }
    insideCounted_.reset();
    changed();
}

void SessionEngine::drop(workflow::SnapshotId id) {
    const auto it = snapshots_.find(id);
    if (it == snapshots_.end()) {
        return;
    }
    if (it->second.copy) {
        undoGpuBytes_ -= it->second.copy->levelSet.bytes();
    }
    snapshots_.erase(it);
}

} // namespace steerseg::engine
