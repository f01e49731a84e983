#include "kiosk/screen_compositor.hpp"

#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace steerseg::kiosk {

namespace {

int quarterTurnsOf(int rotationDeg) {
    if (rotationDeg != 0 && rotationDeg != 90 && rotationDeg != 180 && rotationDeg != 270) {
        throw std::invalid_argument("display rotation " + std::to_string(rotationDeg) +
                                    " is not 0, 90, 180 or 270");
    }
    return rotationDeg / 90;
}

GLuint newFramebuffer() {
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    return fb;
}

} // namespace

glm::ivec2 logicalSize(const glm::ivec2& physical, int rotationDeg) {
    return quarterTurnsOf(rotationDeg) % 2 == 1 ? glm::ivec2(physical.y, physical.x) : physical;
}

ScreenCompositor::ScreenCompositor(const glm::ivec2& physicalSize, int rotationDeg)
    : size_(logicalSize(physicalSize, rotationDeg)), quarterTurns_(quarterTurnsOf(rotationDeg)) {
    if (size_.x <= 0 || size_.y <= 0) {
        throw std::invalid_argument("screen size must be positive");
    }
    gpu::GlStateGuard guard;
    screen_.ensureSize(size_);
    source_ = gpu::Framebuffer(newFramebuffer());
    if (quarterTurns_ != 0) {
        present_ = gpu::buildGraphicsProgram("kiosk/present.vert", "kiosk/present.frag");
        GLuint vao = 0;
        glGenVertexArrays(1, &vao);
        vertexArray_ = gpu::VertexArray(vao);
    }
    gpu::checkGl("creating the logical screen");
}

void ScreenCompositor::begin(const glm::vec3& background) {
    glBindFramebuffer(GL_FRAMEBUFFER, screen_.framebuffer());
    glViewport(0, 0, size_.x, size_.y);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(background.r, background.g, background.b, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT);
}

void ScreenCompositor::drawPicture(unsigned int texture, const glm::ivec2& pictureSize,
                                   const ui::Rect& rect) {
    if (texture == 0 || pictureSize.x <= 0 || pictureSize.y <= 0 || rect.w <= 0 || rect.h <= 0) {
        return;
    }
    gpu::GlStateGuard guard;
    // The compute shaders' writes must land before the blit reads them.
    gpu::memoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source_.id());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, screen_.framebuffer());
    glDisable(GL_SCISSOR_TEST);
    // Row 0 of the picture is its top; GL counts rows from the bottom: the blit flips.
    const int top = size_.y - rect.y;
    const int bottom = size_.y - rect.y - rect.h;
    const bool exact = pictureSize.x == rect.w && pictureSize.y == rect.h;
    glBlitFramebuffer(0, 0, pictureSize.x, pictureSize.y, rect.x, top, rect.x + rect.w, bottom,
                      GL_COLOR_BUFFER_BIT, exact ? GL_NEAREST : GL_LINEAR);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    gpu::checkGl("drawing a view onto the screen");
}

void ScreenCompositor::present(unsigned int displayFramebuffer, const glm::ivec2& displaySize) {
    gpu::GlStateGuard guard;
    if (quarterTurns_ == 0) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, screen_.framebuffer());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, displayFramebuffer);
        glDisable(GL_SCISSOR_TEST);
        glBlitFramebuffer(0, 0, size_.x, size_.y, 0, 0, displaySize.x, displaySize.y,
                          GL_COLOR_BUFFER_BIT, displaySize == size_ ? GL_NEAREST : GL_LINEAR);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, displayFramebuffer);
        glViewport(0, 0, displaySize.x, displaySize.y);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glUseProgram(present_.id());
        glUniform1i(glGetUniformLocation(present_.id(), "quarterTurns"), quarterTurns_);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, screen_.texture());
        glBindVertexArray(vertexArray_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }
    gpu::checkGl("presenting the screen");
}

RgbaImage ScreenCompositor::capture() const {
    const RgbaImage bottomUp = screen_.readback();
    RgbaImage image{size_.x, size_.y, std::vector<std::uint8_t>(bottomUp.pixels.size())};
    const auto row = static_cast<std::ptrdiff_t>(size_.x) * 4;
    for (int y = 0; y < size_.y; ++y) {
        std::copy_n(bottomUp.pixels.begin() + row * (size_.y - 1 - y), row,
                    image.pixels.begin() + row * y);
    }
    // A screen has no transparency: the 3D view's picture carries its own coverage in alpha.
    for (std::size_t n = 3; n < image.pixels.size(); n += 4) {
        image.pixels[n] = 255;
    }
    return image;
}

} // namespace steerseg::kiosk
