#pragma once

// The one place that includes the GLES headers: the core targets OpenGL ES 3.1 (compute
// shaders, SSBOs, image load/store, indirect dispatch) and nothing newer.
#include <GLES3/gl31.h>
