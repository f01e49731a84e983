#include "gpu/gl_error.hpp"

namespace steerseg::gpu {

std::string glErrorName(GLenum code) {
    switch (code) {
    case GL_NO_ERROR:
        return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
        return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
        return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
        return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
        return "GL_OUT_OF_MEMORY";
    default:
        return "GL error " + std::to_string(code);
    }
}

void checkGl(const char* what) {
    GLenum first = glGetError();
    if (first == GL_NO_ERROR) {
        return;
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    if (first == GL_OUT_OF_MEMORY) {
        // Out of GPU memory is the scan or level set not fitting, as the CLI's exit 3 says.
        throw GpuCapacityError(std::string(what) + ": " + glErrorName(first) +
                               " (the GPU's memory is full)");
    }
    throw GlError(std::string(what) + ": " + glErrorName(first));
}

} // namespace steerseg::gpu
