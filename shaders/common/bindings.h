// Binding points of the compute passes' buffers, images and samplers: one list for the shaders
// (`#include "common/bindings.h"`, expanded at build time by tools/shader_expand.cmake) and for
// the C++ that binds them (include path shaders/). Only comments, #define and include guards,
// so that the file is valid GLSL ES 3.10 and C++.
#ifndef STEERSEG_SHADERS_COMMON_BINDINGS_H
#define STEERSEG_SHADERS_COMMON_BINDINGS_H

// Shader storage buffers. The brick pool's two (common/brick_pool.glsl) are the renderer's too.
#define PAGE_TABLE_BINDING 0
#define PHI_POOL_BINDING 1
// The solver's bookkeeping (solver/solver_common.glsl, solver/brick_shell.glsl).
#define SHELL_NEXT_BINDING 2
#define CONTROL_BINDING 3
#define SLOT_BRICK_BINDING 4
#define FREE_LIST_BINDING 5
#define ACTIVE_LIST_BINDING 6
#define REQUESTS_BINDING 7
#define WANT_EPOCH_BINDING 8
#define SLOT_STATE_BINDING 9
// Sleeping bricks (solver/solver_common.glsl): every used slot, and each slot's last measure.
#define BAND_LIST_BINDING 10
#define SLOT_FRONT_BINDING 11
// The 3D view's surface search: the box of bricks that are not constant outside
// (render/band_bounds.comp writes it, render/raycast.comp reads it); no program of the
// solver's, whose SHELL_NEXT_BINDING has the same number, runs with it.
#define VIEW_BAND_BOUNDS_BINDING 2
// The classifier speed (speed/classifier_gather.comp, speed/classifier_evaluate.comp);
// below 16: gpu::GlStateGuard saves bindings 0-15.
#define CLASSIFIER_SAMPLES_BINDING 12  // voxel coordinates of the training samples
#define CLASSIFIER_FEATURES_BINDING 13 // their feature vectors, read back once
#define CLASSIFIER_NODES_BINDING 14    // the forest's nodes
#define CLASSIFIER_ROOTS_BINDING 15    // each tree's root node
// The solver's evaluation of the classifier where the front goes (solver/evaluate_speed.comp):
// a count, then one word per brick, non-zero once its speed is stored. The training's gather,
// which has the same number, runs alone.
#define SPEED_READY_BINDING 12
// Each slot's speeds (solver/speed_cache.glsl), read by the solver's steps; the training's
// features, which have the same number, are gathered alone.
#define SPEED_CACHE_BINDING 13

// gpu/texture_readback (gpu/read_volume.comp), which runs alone: the buffer it fills.
#define READ_VOLUME_BINDING 0

// Texture units of the samplers (glActiveTexture(GL_TEXTURE0 + unit)).
#define SOLVER_SCAN_UNIT 0    // speed/data_speed.glsl, solver: I (scan or smoothed copy)
#define SOLVER_FACTOR_UNIT 1  // speed/data_speed.glsl, solver: edge g or classifier output
#define SOLVER_CLAIMED_UNIT 3 // solver/barrier_speed.glsl: voxels other structures hold
#define SOLVER_KEPT_UNIT 4    // solver/barrier_speed.glsl: voxels the surface keeps
#define SPEED_SOURCE_UNIT 0   // speed/*.comp (each runs alone): the texture it reads
#define READ_VOLUME_UNIT 0    // gpu/read_volume.comp (runs alone): the texture it reads
#define VIEW_SCAN_UNIT 0      // render/view_common.glsl: the scan, linear filtering
#define VIEW_TF_LUT_UNIT 1    // render/raycast.comp: transfer function
#define VIEW_SKIP_GRID_UNIT 2 // render/raycast.comp: a byte per block, visible or skipped
#define VIEW_OCCUPANCY_UNIT 3 // render/raycast.comp: occupied transfer-function bins
#define VIEW_GRADIENT_UNIT 4  // render/raycast.comp: the scan's gradient (render/gradient.comp)
// render/slice.comp's speed view (speed/data_speed.glsl): the ray caster's units 1 and 2, which
// the slice views do not read.
#define VIEW_SPEED_INTENSITY_UNIT 1
#define VIEW_SPEED_FACTOR_UNIT 2
// render/raycast.comp's surface between voxels (render/surface_smooth.glsl: the data term's
// zero crossing), the same textures as the solver's.
#define VIEW_SURFACE_INTENSITY_UNIT 5
#define VIEW_SURFACE_FACTOR_UNIT 6
// speed/classifier_forest.glsl (speed/classifier_evaluate.comp, solver/evaluate_speed.comp): the
// examples' vote of where (speed/place_vote), linear filtering; within gpu::GlStateGuard's 8.
#define CLASSIFIER_PLACE_UNIT 2

// Image units.
#define VIEW_OUT_IMAGE_UNIT 0      // render/view_common.glsl: the rendered picture
#define VIEW_GRADIENT_IMAGE_UNIT 0 // render/gradient.comp (runs alone): the gradient it fills
#define SPEED_OUT_IMAGE_UNIT 0     // speed/*.comp (each runs alone): the R32F texture it fills
#define SOLVER_SPEED_IMAGE_UNIT 0  // solver/evaluate_speed.comp: the classifier speed it fills

#endif
