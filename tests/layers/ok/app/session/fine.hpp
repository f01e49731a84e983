#pragma once
// Within the rule: the session sees the layers below it.
#include "core/volume.hpp"
#include "render/renderer.hpp"
#include "solver/level_set_solver.hpp"
