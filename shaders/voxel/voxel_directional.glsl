// Anisotropic voxels (voxel.anisotropic; Crassin et al. 2011, "Interactive Indirect
// Illumination Using Voxel Cone Tracing", section 3.2): a voxel is stored as seen from each
// of its 6 faces (VOXEL_FACE_*), rgb = rho E x a, a = how much of the face the surfaces
// facing it cover (directional_build.comp), premultiplied as the isotropic textures are. A coarser voxel seen from a face is its 2x2x2 children
// composited front to back along that face's axis, column by column, averaged over the 4
// columns: a wall whose lit side faces away from a face shows that face its dark side, where
// an average of the children would show the mean of both sides.
#ifndef GI_VOXEL_DIRECTIONAL_GLSL
#define GI_VOXEL_DIRECTIONAL_GLSL

#include "../common/voxel_cascade.glsl"

// Whether the voxels are anisotropic (VoxelUniforms.grid.z, VOXEL_KIND_*).
bool anisotropicKind() {
    return voxel.grid.z == VOXEL_KIND_ANISOTROPIC ||
            voxel.grid.z == VOXEL_KIND_ANISOTROPIC_SURFACE_READ;
}

// Texel of face `face` of the cascade texel `texel` (level slab included).
ivec3 directionalTexel(ivec3 texel, int face) {
    return texel + ivec3(face * voxelResolution(), 0, 0);
}

// How much of a surface of unit normal n face `face` sees: its area projected onto the
// face, per unit area (0 when the surface faces away from it).
float faceProjection(vec3 n, int face) {
    float c = n[face / 2];
    return max((face & 1) == 0 ? c : -c, 0.0);
}

// Premultiplied "over": what lies in front hides what lies behind by its opacity.
vec4 compositeOver(vec4 front, vec4 back) {
    return front + (1.0 - clamp(front.a, 0.0, 1.0)) * back;
}

// The 2x2x2 block (child i at offset (i & 1, (i >> 1) & 1, (i >> 2) & 1)), each child's value
// as seen from `face`, seen from that face as one voxel.
vec4 compositeBlock(vec4 children[8], int face) {
    int step = 1 << (face / 2);   // index offset between a column's two children
    bool fromPositive = (face & 1) == 0;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i) {
        if ((i & step) != 0) continue;
        vec4 low = children[i], high = children[i + step];
        sum += fromPositive ? compositeOver(high, low) : compositeOver(low, high);
    }
    return sum / 4.0;
}

// The face a cone travelling along `dir` sees of the voxels it meets on `axis`: the one
// towards where it comes from.
int faceSeenAlong(vec3 dir, int axis) {
    return 2 * axis + (dir[axis] > 0.0 ? 1 : 0);
}

// How much of each face the directions of a cone along `dir` (unit) of half-angle tangent
// tanHalf see, as the mean projected area a unit face shows them: per axis, towardPositive
// weighs the face travelling directions of positive component see (faceSeenAlong), toward-
// Negative the opposite face. A direction d sees a face by |d_axis|; over the cone's cap
// (uniform in solid angle) the component has mean m = (1 + cos) / 2 dir_axis and second
// moment e2 dir_axis^2 + (1 - e2)(1 - dir_axis^2) / 2, e2 = (1 + cos + cos^2) / 3, and taken
// as normal its positive part's mean is m Phi(m / s) + s phi(m / s). A narrow cone gives
// |dir_axis| to the faces it travels towards; a wide one also the faces beside and behind its
// axis that its outer directions see (a wall along a corridor a wide cone runs down).
void faceWeightsOverCone(vec3 dir, float tanHalf, out vec3 towardPositive,
        out vec3 towardNegative) {
    float c = inversesqrt(1.0 + tanHalf * tanHalf);
    float firstMoment = 0.5 * (1.0 + c);
    float secondMoment = (1.0 + c + c * c) / 3.0;
    vec3 mean = firstMoment * dir;
    vec3 square = secondMoment * dir * dir + (1.0 - secondMoment) * (1.0 - dir * dir) * 0.5;
    vec3 sigma = sqrt(max(square - mean * mean, vec3(1e-8)));
    vec3 z = clamp(mean / sigma, vec3(-8.0), vec3(8.0));
    vec3 cdf = 1.0 / (1.0 + exp(-1.702 * z));             // logistic approximation of Phi
    vec3 pdf = 0.3989423 * exp(-0.5 * z * z);
    towardPositive = max(mean * cdf + sigma * pdf, vec3(0.0));
    towardNegative = max(towardPositive - mean, vec3(0.0));
}

#ifdef VOXEL_DIRECTIONAL_SUMS
#include "voxel_lock.glsl"

// The per-face sums that voxelization (areas) and injection (flux) add to, under the voxel's
// lock (voxel_lock.glsl); directional_build.comp turns them into the directional voxels.
layout(binding = BIND_IMG_VOXEL_DIRECTIONAL, rgba16f) coherent uniform image3D voxelDirectional;

// Adds `amount` times the share each face sees of a surface of unit normal n to the faces of
// the cascade texel `texel` it faces, rounded with the lock's dither u (roundToHalf).
void addToFacingFaces(ivec3 texel, vec3 n, vec4 amount, float u) {
    for (int face = 0; face < VOXEL_FACES; ++face) {
        float projection = faceProjection(n, face);
        if (projection <= 0.0) continue;
        ivec3 faceTexel = directionalTexel(texel, face);
        vec4 sums = imageLoad(voxelDirectional, faceTexel);
        imageStore(voxelDirectional, faceTexel, roundToHalf(sums + amount * projection, u));
    }
}
#endif

#endif
