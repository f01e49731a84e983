#pragma once

#include "gpu/gl_handle.hpp"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace steerseg::gpu {

// `#define NAME VALUE` lines inserted after a shader's #version line, for constants the host
// chooses at run time (brick size, work-group size).
using Defines = std::vector<std::pair<std::string, std::string>>;

// Builds a compute program from an embedded shader. Throws GlError with the shader's name and
// the driver's log on failure.
Program buildComputeProgram(std::string_view name, const Defines& defines = {});

// Builds a compute program from source text that is not part of the product (the tests' own
// shaders); `label` names it in errors.
Program buildComputeProgramFromSource(std::string_view label, std::string_view source,
                                      const Defines& defines = {});

// Builds a vertex + fragment program from two embedded shaders.
Program buildGraphicsProgram(std::string_view vertexName, std::string_view fragmentName,
                             const Defines& defines = {});

// Source with the defines inserted (exposed for tests).
std::string withDefines(std::string_view source, const Defines& defines);

} // namespace steerseg::gpu
