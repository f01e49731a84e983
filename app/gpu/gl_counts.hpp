#pragma once

// The GL calls that set an iteration's cost on any GPU whatever its speed (issue 50): compute
// dispatches, memory barriers, and the host's waits for the GPU (a buffer or framebuffer read
// back, a glFinish). The app issues them through these wrappers, which count them in the calling
// thread, so that a report takes the difference over a run and the floor of the solver's passes
// is measured on llvmpipe as on a lent GPU.
#include "gpu/gl.hpp"

#include <cstdint>

namespace steerseg::gpu {

struct GlCounts {
    std::uint64_t dispatches = 0; // glDispatchCompute and glDispatchComputeIndirect
    std::uint64_t barriers = 0;   // glMemoryBarrier
    std::uint64_t readBacks = 0;  // host reads that wait for the GPU's writes (buffers, pixels)
    std::uint64_t finishes = 0;   // glFinish
    [[nodiscard]] std::uint64_t hostSyncs() const { return readBacks + finishes; }
    [[nodiscard]] GlCounts operator-(const GlCounts& earlier) const;
};

// This thread's counts since it started.
[[nodiscard]] GlCounts glCounts();

void dispatchCompute(GLuint x, GLuint y, GLuint z);
void dispatchComputeIndirect(GLintptr offset);
void memoryBarrier(GLbitfield bits);
void finish();
// For a host read the wrappers above do not make (gpu::readBufferBytes, glReadPixels).
void countReadBack();

} // namespace steerseg::gpu
