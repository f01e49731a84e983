#include "files/io_faults.hpp"

#include <array>
#include <atomic>
#include <mutex>
#include <stdexcept>

namespace steerseg::files {

namespace {

struct Plan {
    IoCall call = IoCall::Open;
    int nth = -1;
    int error = 0;
    bool fired = false;
    std::array<std::size_t, kIoCallCount> calls{};
};

std::atomic<bool> g_armed{false};
std::mutex g_mutex; // the autosave writes from its own thread
Plan g_plan;

std::size_t slot(IoCall call) {
    return static_cast<std::size_t>(call);
}

} // namespace

IoFault::IoFault(IoCall call, int nth, int error) {
    const std::lock_guard lock(g_mutex);
    if (g_armed.load()) {
        throw std::logic_error("files::IoFault: one at a time");
    }
    g_plan = Plan{call, nth, error, false, {}};
    g_armed.store(true);
}

IoFault::~IoFault() {
    const std::lock_guard lock(g_mutex);
    g_armed.store(false);
}

std::size_t IoFault::calls(IoCall kind) const {
    const std::lock_guard lock(g_mutex);
    return g_plan.calls[slot(kind)];
}

bool IoFault::fired() const {
    const std::lock_guard lock(g_mutex);
    return g_plan.fired;
}

int injectedError(IoCall call) {
    if (!g_armed.load(std::memory_order_relaxed)) {
        return 0;
    }
    const std::lock_guard lock(g_mutex);
    const std::size_t n = g_plan.calls[slot(call)]++;
    if (call == g_plan.call && g_plan.nth >= 0 && n == static_cast<std::size_t>(g_plan.nth)) {
        g_plan.fired = true;
        return g_plan.error;
    }
    return 0;
}

} // namespace steerseg::files
