#pragma once

#include "gpu/gl.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::gpu {

class GlError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// The scan or the level set does not fit what this GPU offers (3D texture size, shader storage
// block size). A GlError, so that callers treat it as a GPU failure, not a bad file.
class GpuCapacityError : public GlError {
  public:
    using GlError::GlError;
};

// The GPU computed numbers that cannot be right (a buffer it should have written read back
// unwritten, values its CPU twin refutes): a GlError, so that callers treat it as a GPU failure.
class GpuNumericsError : public GlError {
  public:
    using GlError::GlError;
};

std::string glErrorName(GLenum code);

// Throws GlError naming `what` if the GL error flag is set (drains all pending errors).
void checkGl(const char* what);

} // namespace steerseg::gpu
