// Cascade addressing shared by the voxel passes and the atlas' voxel visibility: which level
// holds a world position, its voxel, and where that voxel lives in the (v, v, v*l) textures
// (level k = z-slab k).
#ifndef GI_VOXEL_CASCADE_GLSL
#define GI_VOXEL_CASCADE_GLSL

#include "shared.h"

layout(std140, binding = BIND_UBO_VOXEL) uniform VoxelBlock {
    VoxelUniforms voxel;
};

// A program built for one cascade shape (VOXEL_SHAPE_RESOLUTION and VOXEL_SHAPE_LEVELS, set
// by gi/voxel/VoxelShape.h) reads them as constants, so the compiler folds the loops over
// levels and drops the paths that shape never takes: llvmpipe runs both sides of every branch,
// lanes masked, so an untaken path costs as much as a taken one.
#ifdef VOXEL_SHAPE_LEVELS
int voxelResolution() { return VOXEL_SHAPE_RESOLUTION; }
int voxelLevels() { return VOXEL_SHAPE_LEVELS; }
#else
int voxelResolution() { return voxel.grid.x; }
int voxelLevels() { return voxel.grid.y; }
#endif
vec3 levelOrigin(int level) { return voxel.levelOrigin[level].xyz; }
float levelVoxelSize(int level) { return voxel.levelOrigin[level].w; }
float levelExtent(int level) { return voxel.levelOrigin[level].w * float(voxel.grid.x); }

bool insideLevel(vec3 p, int level) {
    vec3 local = p - levelOrigin(level);
    return all(greaterThanEqual(local, vec3(0.0))) && all(lessThan(local, vec3(levelExtent(level))));
}

// Finest level whose region contains p; -1 outside the volume.
int finestLevel(vec3 p) {
    for (int level = 0; level < voxelLevels(); ++level) {
        if (insideLevel(p, level)) return level;
    }
    return -1;
}

// Texel of p in the cascade textures (level slab offset included).
ivec3 voxelTexel(vec3 p, int level) {
    int v = voxelResolution();
    ivec3 local = clamp(ivec3(floor((p - levelOrigin(level)) / levelVoxelSize(level))), ivec3(0), ivec3(v - 1));
    return local + ivec3(0, 0, level * v);
}

// Normalised texture coordinate of p for filtered reads of `level`. z is clamped half a
// texel inside the slab so trilinear filtering never blends two levels.
vec3 voxelTexcoord(vec3 p, int level) {
    float v = float(voxelResolution());
    vec3 local = (p - levelOrigin(level)) / levelVoxelSize(level);   // texels within the level
    local = clamp(local, vec3(0.5), vec3(v - 0.5));
    return vec3(local.xy / v, (local.z + float(level) * v) / (v * float(voxelLevels())));
}

#endif
