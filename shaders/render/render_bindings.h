// Binding points of the renderer's own buffers, shared by its shaders and the C++ that binds
// them (include path shaders/); the rest are in common/bindings.h. Only comments, #define and
// include guards, so GLSL and C++ both read it.
#ifndef STEERSEG_SHADERS_RENDER_RENDER_BINDINGS_H
#define STEERSEG_SHADERS_RENDER_RENDER_BINDINGS_H

// render/raycast.comp: the pixels whose ray hit an opaque surface, for its second pass (after
// the pool's 0 and 1 and VIEW_BAND_BOUNDS_BINDING 2; GLES 3.1 guarantees 4 per compute shader)
#define VIEW_SURFACE_HITS_BINDING 3

// render/raycast.comp's other structures (app/render/structure_labels.hpp): an R8UI label per
// voxel, 0 for none (after the units of common/bindings.h, which end at 6), and how many
// colours its table holds (render::kMaxStructureSurfaces).
#define VIEW_LABELS_UNIT 7
#define VIEW_MAX_STRUCTURE_LABELS 64

#endif
