#include "gpu/gl_counts.hpp"

namespace steerseg::gpu {

namespace {
// Per thread: the kiosk's loader and the DICOM node's threads issue no GL, and a test's
// counts are its own.
thread_local GlCounts counts;
} // namespace

GlCounts GlCounts::operator-(const GlCounts& earlier) const {
    return {dispatches - earlier.dispatches, barriers - earlier.barriers,
            readBacks - earlier.readBacks, finishes - earlier.finishes};
}

GlCounts glCounts() {
    return counts;
}

void dispatchCompute(GLuint x, GLuint y, GLuint z) {
    ++counts.dispatches;
    glDispatchCompute(x, y, z);
}

void dispatchComputeIndirect(GLintptr offset) {
    ++counts.dispatches;
    glDispatchComputeIndirect(offset);
}

void memoryBarrier(GLbitfield bits) {
    ++counts.barriers;
    glMemoryBarrier(bits);
}

void finish() {
    ++counts.finishes;
    glFinish();
}

void countReadBack() {
    ++counts.readBacks;
}

} // namespace steerseg::gpu
