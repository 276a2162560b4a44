// Screen-space cone tracing (thesis 4.3.3.4): every visible surface point gathers its
// indirect irradiance E_ind (W/m^2, DESIGN.md) from diffuse cones through the voxel cascade
// (cone_tracing.glsl: the cones, their weights and how they read the voxels). With glossy
// materials (SHADING_GLTF) one more cone follows the specular lobe's core towards the camera;
// with the diffuse cones' mean radiance for its tails, times the lobe's split-sum albedo
// F0 A + B, it is the indirect specular radiance (brdf.glsl: the cone's direction, its
// aperture and share from the roughness, the albedo table).
// Light the voxels hold is Lambertian (albedo x E / pi), so a metal seen in a mirror-like
// surface shows its diffuse stand-in.
#include "../common/brdf.glsl"
#include "../common/material.glsl"
#include "../common/vertex_data.glsl"
#include "cone_tracing.glsl"

// Tested against the depth pre-pass before shading: hidden surfaces trace no cones.
layout(early_fragment_tests) in;

in VertexData { VERTEX_DATA_MEMBERS } vin;

layout(location = 0) out vec4 outIndirect;
layout(location = 1) out vec4 outSpecular;   // only with SHADING_GLTF (ConeTracePass)

// Whether the specular cone is traced: ConeTracePass builds the trace with it for glossy
// materials (material.model=gltf) and without it otherwise.
bool traceSpecularCone() {
#ifdef CONE_TRACE_SPECULAR
    return CONE_TRACE_SPECULAR != 0;
#else
    return shadingModel() == SHADING_GLTF;
#endif
}

// A strided trace (TraceReusePass.h) covers pixel (stride x + y, stride y + z) of the full
// trace with its pixel (x, y): the ring's dither follows the full trace's pixel.
layout(location = LOC_CONE_TRACE_PATTERN) uniform ivec3 tracePattern;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
    float viewDepth = -(frame.view * vec4(vin.position, 1.0)).z;
    int level = finestLevel(vin.position);
    if (level < 0) {
        outIndirect = vec4(0.0, 0.0, 0.0, viewDepth);
        outSpecular = vec4(0.0, 0.0, 0.0, viewDepth);
        return;
    }
    vec3 n = normalize(vin.normal);
    // The side the viewer sees gathers, the side its own normal faces from the eye, as in the
    // path tracer and the forward pass (the winding picks the wrong side where normals point
    // against it).
    if (dot(n, frame.cameraPosition.xyz - vin.position) < 0.0) n = -n;
    // Leave the surface's own voxel before the first sample, and stand at least
    // voxel.cone_offset finest voxels out (a length, whatever level holds the surface).
    vec3 origin = vin.position +
            n * max(levelVoxelSize(level), voxel.smoothing.w * levelVoxelSize(0));
    // With voxel.jitter the rings turn by an ordered-dither fraction of their spacing: 4x4 or
    // 2x2 turns over cells of one or 2x2 pixels, as RingDither.h derives them from the
    // filter's window (smoothing.y = 8 x turns + cell); the filter pass averages them back into
    // a smooth result. The 2x2 corner of the 4x4 Bayer matrix holds turns 0, 4, 8 and 12 of
    // 16, evenly spaced. Where the window is too small for a dither (one turn) every pixel
    // turns by the 16 turns' mean, half the rings' spacing.
    ivec2 pixel = ivec2(gl_FragCoord.xy) * tracePattern.x + tracePattern.yz;
    float turn = 0.0, rise = 0.5;
    if (voxel.smoothing.y != 0.0) {
        const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0,
                                          3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
        int code = int(voxel.smoothing.y);
        int turns = code / 8, cellPixels = code % 8;
        ivec2 cell = (pixel / cellPixels) & (turns - 1);
        float step = turns == 1 ? 7.5 : bayer[cell.y * 4 + cell.x];   // 7.5: the 16 turns' mean
        turn = (step + 0.5) / 16.0;
        // voxel.jitter_elevation: the rise takes the turns' steps in another order (x 7
        // modulo 16, a rank-1 lattice), so each cell's turn and rise pair up evenly.
        if (voxel.cones.z != 0.0 && turns != 1) rise = (mod(step * 7.0, 16.0) + 0.5) / 16.0;
    }
    // With voxel.cone_interleave the pixels of a checkerboard trace alternate halves of the
    // rings (ConeSet.h), which the filter merges. Single pixels, not the dither's cells: each
    // cell holds both halves at its turn (cells of one half would give each half only some of
    // the turns and bunch the rings' directions).
    int classes = int(voxel.cones.y);
    int coneClass = (pixel.x + pixel.y) % classes;
    vec3 irradiance = coneIrradiance(origin, n, turn, rise, coneClass, classes, voxel.trace.y);
    outIndirect = vec4(irradiance, viewDepth);
    if (traceSpecularCone()) {
        vec3 v = normalize(frame.cameraPosition.xyz - vin.position);
        vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
        GltfSurface s = gltfSurface(baseColor.rgb, m.metallicRoughness.x, m.metallicRoughness.y);
        vec3 dir = specularDominantDirection(s, n, v);
        SpecularCone lobe = specularCone(s);
        vec3 cone = traceCone(origin, dir, voxel.trace.y, lobe.tanHalfAngle, true);
        vec3 incident = mix(irradiance / PI, cone, lobe.share);
        outSpecular = vec4(incident * specularAlbedo(s, max(dot(n, v), 0.0)), viewDepth);
    }
}
