#include "platform/gl_readback.hpp"

#include "platform/display.hpp"

#include <GLES3/gl31.h>
#include <cstring>
#include <string>

namespace steerseg::platform {

std::vector<std::uint8_t> readFramebuffer(unsigned int framebuffer, int width, int height) {
    if (width <= 0 || height <= 0) {
        throw DisplayError("readback: bad size " + std::to_string(width) + "x" +
                           std::to_string(height));
    }
    GLint previousRead = 0;
    GLint previousPack = 0;
    GLint previousAlignment = 4;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previousRead);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &previousPack);
    glGetIntegerv(GL_PACK_ALIGNMENT, &previousAlignment);

    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    const auto rowBytes = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> bottomUp(rowBytes * static_cast<std::size_t>(height));
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const GLenum error = glGetError();

    glPixelStorei(GL_PACK_ALIGNMENT, previousAlignment);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(previousPack));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previousRead));
    if (error != GL_NO_ERROR) {
        throw DisplayError("readback: glReadPixels of framebuffer " + std::to_string(framebuffer) +
                           " failed (GL error " + std::to_string(error) + ")");
    }

    std::vector<std::uint8_t> topDown(bottomUp.size());
    for (int row = 0; row < height; ++row) {
        std::memcpy(topDown.data() + static_cast<std::size_t>(row) * rowBytes,
                    bottomUp.data() + static_cast<std::size_t>(height - 1 - row) * rowBytes,
                    rowBytes);
    }
    return topDown;
}

} // namespace steerseg::platform
