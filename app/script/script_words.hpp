#pragma once

// The readers of a script line's typed words (states, parameters, slice axes, comparisons,
// paths, voxels, timeouts) and the bounds every verb shares; each throws LineError with one
// line naming what it expected.
#include "script/script.hpp"
#include "script/script_tokens.hpp"

#include <string>
#include <string_view>

namespace steerseg::script::detail {

inline constexpr double kMaxSeconds = 1e6;    // a script clock time or a timeout
inline constexpr double kMaxCoordinate = 1e5; // voxel indices and screen pixels
inline constexpr double kMaxValue = 1e9;      // parameters, window, field bounds

// platform/input_event.hpp's key names.
bool isKeyName(std::string_view key);
model::State stateWord(Words& words);
model::Param paramWord(Words& words);
model::SliceAxis axisWord(Words& words);
Condition::Op opWord(Words& words);
// A non-empty path whose $VARIABLES are known.
std::string pathWord(Words& words, const char* what);
glm::dvec3 voxelWords(Words& words);
// `timeout S` if it follows, else the default wait.
double timeoutWords(Words& words);

} // namespace steerseg::script::detail
