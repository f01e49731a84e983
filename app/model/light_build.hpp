#pragma once

// The light build (CMake option STEERSEG_LIGHT; tools/bench-gpu.sh --pack makes it): the kiosk
// and the benchmarks without the libraries the lent GPU machine cannot be given (OpenImageIO's
// some 280, GDCM, DCMTK, SDL2, libinput). Each part it leaves out is a module of its own
// (*_light.cpp) that refuses with this one sentence, worded alike in every room.
#include <string>
#include <string_view>

namespace steerseg::model {

// "WHAT is not in this light build of steerseg (STEERSEG_LIGHT, ...): it needs LIBRARY; ...".
inline std::string leftOutOfLightBuild(std::string_view what, std::string_view library) {
    return std::string(what) +
           " is not in this light build of steerseg (STEERSEG_LIGHT, the GPU pack's): it needs " +
           std::string(library) + "; use the full build";
}

} // namespace steerseg::model
