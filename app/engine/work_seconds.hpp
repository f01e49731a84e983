#pragma once

// Where the engine's time goes, summed over its life: the steering benchmark subtracts two of
// them around a click to break its first visible change down (docs/steering.md). Wall seconds
// of the calls themselves: GPU work a call queues without waiting for it counts for whoever
// waits next (on llvmpipe every dispatch and copy finishes inside its call).
#include <chrono>

namespace steerseg::engine {

struct WorkSeconds {
    double snapshot = 0.0; // undo copies of the level set taken (and moved to host memory)
    double restore = 0.0;  // undo and redo putting one back
    double edit = 0.0;     // seeds, erasers, barriers
    double speed = 0.0;    // parameters and the speed (classify's training)
    double count = 0.0;    // the exact volume (inside voxels counted)

    [[nodiscard]] WorkSeconds operator-(const WorkSeconds& earlier) const {
        return {snapshot - earlier.snapshot, restore - earlier.restore, edit - earlier.edit,
                speed - earlier.speed, count - earlier.count};
    }
    [[nodiscard]] double total() const { return snapshot + restore + edit + speed + count; }
};

// Adds the seconds of its scope to one of them, thrown out of or not.
class ScopedSeconds {
  public:
    explicit ScopedSeconds(double& into) : into_(into) {}
    ~ScopedSeconds() {
        into_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    ScopedSeconds(const ScopedSeconds&) = delete;
    ScopedSeconds& operator=(const ScopedSeconds&) = delete;

  private:
    double& into_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

} // namespace steerseg::engine
