#pragma once

// Reads a finished frame back to the host: the offscreen backend's frames written to PNG, the
// window backend's screenshots, and the tests comparing the two. Needs a current GLES context.
#include <cstdint>
#include <vector>

namespace steerseg::platform {

// The colour of `framebuffer` (0: the default framebuffer's back buffer, before present) in
// [0, width) x [0, height), as RGBA8 rows from the top row down (GL's rows run bottom-up).
// Leaves the read framebuffer, pack buffer and pack alignment bindings as it found them.
std::vector<std::uint8_t> readFramebuffer(unsigned int framebuffer, int width, int height);

} // namespace steerseg::platform
