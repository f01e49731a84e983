#pragma once

// The null backend: a context that provides no GL. The workflow, the action layer and the UI's
// logic run on it in tests and on machines without a GPU; anything that needs GL (the session's
// solver and renderer) must check providesGl() and refuse, never call into a missing driver.
#include "platform/gpu_context.hpp"

#include <memory>

namespace steerseg::platform {

std::unique_ptr<GpuContext> createNullContext();

} // namespace steerseg::platform
