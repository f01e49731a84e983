#pragma once

// A picture as PNG with zlib alone: the light build's pictures (the kiosk's --frames, render's
// --output), where OpenImageIO is not carried. The full build writes PNG through OpenImageIO.
#include "core/rgba_image.hpp"

#include <vector>

namespace steerseg::exports {

// 8-bit RGBA, not interlaced; each row filtered as libpng does by default (of None, Sub, Up,
// Average and Paeth, the one whose bytes sum smallest as signed values), deflated at zlib's
// default level, so a frame costs about what OpenImageIO's PNG does.
std::vector<unsigned char> encodePng(const RgbaImage& image);

} // namespace steerseg::exports
