#pragma once

#include "gpu/gl.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::gpu {

class GlError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

std::string glErrorName(GLenum code);

// Throws GlError naming `what` if the GL error flag is set (drains all pending errors).
void checkGl(const char* what);

} // namespace steerseg::gpu
