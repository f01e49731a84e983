#pragma once
// Deliberately against the rule: core must not see the renderer.
#include "render/renderer.hpp"
