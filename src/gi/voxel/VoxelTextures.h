// The cascade's storage (thesis 4.3.2): 3D textures of size (v, v, v*l), level k in z-slab
// k. Albedo, irradiance and the per-light helper are RGBA16F; normals RGBA8_SNORM (they only
// decide whether a voxel faces a cone); the lock is R32UI (spinlock bit + fragment count).
// 32 bytes per voxel: 3.15 MB at v=32, l=3, under the thesis' 3.46 MB for the same data.
// Injection sums flux in fixed point, three R32UI per voxel (12 more bytes: 1.18 MB at v=32,
// l=3), so that the sum does not depend on the order fragments arrive in.
// Beyond the thesis, a mipmapped RGBA16F pyramid of the coarsest level, (v/2)^3 at mip 0,
// holds the reflected light over wider footprints (37 KB at v=32 beside the cascade's 3.15 MB);
// two scratch bytes per coarsest voxel serve EmptyDistancePass (64 KB).
// With voxel.anisotropic a directional copy of the cascade holds each voxel as seen from each
// of its 6 faces (RGBA16F, 48 more bytes per voxel: 4.72 MB at v=32, l=3) and the pyramid
// holds 6 faces too (DirectionalVoxelsPass.h). With gi.bounces > 1 one more RGBA16F volume
// remembers the indirect light the voxels gathered (BouncePass.h), 8 more bytes per voxel.
// The occupancy the visibility marches walk keeps its edge voxels' faces, 8 bytes per voxel of
// level 0 (EdgeFacesPass.h).
#pragma once

#include "gl/Objects.h"

#include <vector>

namespace gi::voxel {

struct VoxelTextures {
    gl::Texture albedo;       // rgb = mean albedo (linear) x coverage, a = coverage in [0, 1]
    gl::Texture normal;       // xyz = mean world-space normal (not normalised at level 0),
                              // w = mean offset of the surface from the voxel centre along
                              // it, in voxel sizes
    gl::Texture irradiance;   // rgb = sum over lights of E (W/m^2), premultiplied by coverage
    gl::Texture helper;       // rgb = current light's mean E, a = 1 where the light wrote
    gl::Texture lock;         // bit 0 = spinlock, bits 1..31 = values averaged
    gl::Texture fluxSum;      // (3v, v, v*l) R32UI, INJECT_AREA: x-slab c = channel c of the
                              // injected flux / face area in fixed point (voxel_flux_sum.glsl)
    gl::Texture pyramid;      // mip m: coarsest level averaged over 2^(m+1) voxels per axis,
                              // rgb = rho E x coverage (W/m^2), a = coverage; anisotropic:
                              // 6 x-slabs, one per face, as `directional`
    gl::Texture distanceScratch[2];   // R8UI (v^3): the empty-distance pass' distances along
                                      // x, then over x and y
    gl::Texture directional;  // anisotropic only, (6v, v, v*l): x-slab f = the voxel seen from
                              // face f (VOXEL_FACE_*), rgb = rho E x a, a = facing coverage
    gl::Texture gathered;     // gi.bounces > 1 only: rgb = the indirect E x coverage the voxel
                              // gathered from the other voxels, included in irradiance
    gl::Texture edgeFaces;    // the occupancy only (voxel.projectedAreas), (2v, v, v): level 0's
                              // edge voxels' two faces (EdgeFacesPass.h)
    int resolution = 0, levels = 0;
    bool anisotropic = false;

    void allocate(int v, int l, bool anisotropicVoxels, bool bounces, bool occupancy);
    [[nodiscard]] int pyramidLevels() const;   // log2(v): mip 0 is (v/2)^3, the last 1^3
    void clear() const;
    // What allocate(v, l) allocates, before allocating it.
    [[nodiscard]] static std::vector<gl::MemoryItem> memoryFor(int v, int l,
            bool anisotropicVoxels, bool bounces = false, bool occupancy = false);
};

} // namespace gi::voxel
