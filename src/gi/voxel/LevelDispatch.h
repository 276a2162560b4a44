// The coarse-to-fine build both per-level voxel passes share (propagate, directional faces):
// one dispatch per cascade level from `firstLevel`, each level read by the next, so an image
// barrier between levels and a texture-fetch barrier for the cone trace after the last.
#pragma once

#include <glad/gl.h>

namespace gi::voxel {

// Dispatches `program` (bound by the caller) groups^3 times for each level in
// [firstLevel, levels), setting LOC_VOXEL_LEVEL; leaves the program unbound.
void dispatchLevelByLevel(GLuint program, GLuint groups, int firstLevel, int levels);

} // namespace gi::voxel
