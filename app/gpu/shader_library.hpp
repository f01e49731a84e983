#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace steerseg::gpu {

// Shaders from shaders/, validated by glslang at build time and embedded in the binary; names
// are paths relative to shaders/ ("solver/update_phi.comp"). Defined in generated code.
std::optional<std::string_view> findShaderSource(std::string_view name);
std::vector<std::string_view> shaderNames();

} // namespace steerseg::gpu
