// Cone tracing through the voxel cascade (thesis 4.2.5, 4.3.3.4, Listing 4.5), shared by the
// screen-space trace (cone_trace.frag) and the voxels' own gather of a further bounce
// (bounce_gather.comp): coneIrradiance traces the cones of voxel.cones over a surface's
// hemisphere (ConeSet.h: the thesis' 9, one along the normal and eight rotated by 50 degrees
// around it, or 19 in two rings), each marched front to back until it is opaque or leaves
// the volume. Voxels facing away from the cone are skipped (thesis).
//
// Calibration (so the output is E_ind in W/m^2, DESIGN.md): a voxel's outgoing radiance is
// albedo/pi * E; a cone returns the composited radiance L_i seen along it, and the sky's
// radiance times what stays transparent where it escapes; E_ind = pi * sum_i w_i L_i, where w_i is the fraction of the
// cosine-weighted hemisphere the cone stands for (ConeSet.h; for the thesis' 9, central cap
// sin^2(theta_b), each ring cone cos^2(theta_b)/8, theta_b halfway between the central axis
// and the ring). The thesis' weights (cos theta_i, normalised by their sum) differ from these
// by under 10%. Albedo and E
// are both stored premultiplied by coverage, so a filtered read's light per covered area is
// albedo x E / coverage^2: an empty neighbour lowers a trilinear read's coverage, not the
// albedo it returns.
//
// Finer levels (the thesis' cascade): the cone steps by its diameter through the level whose
// voxels match it, reading filtered voxels; a sample of coverage a is as opaque as
// 1 - (1 - a)^(step / voxel size), so two samples in one voxel add up to one voxel's worth
// (every sample counts: reading each voxel once, as the thesis does, left a wall half its
// optical depth wherever steps were half a voxel).
//
// The coarsest level: a cone there is a ray to the voxels it reads, narrower than them near
// its start and wider than any voxel the cascade has once it outgrows them (the cascade is
// centred on the camera, so a scene seen from outside lies wholly in the coarsest level).
// Its axis is walked voxel by voxel (a 3D DDA). A voxel holding one flat surface
// (voxel_plane.glsl) is met where the axis crosses that plane, with opacity = coverage, or
// not at all; other occupied voxels occlude like finer levels' samples over the axis' path
// through them. Whenever the cascade has more than one level the coarsest is propagated, and
// its normals cannot tell one plane from several: with voxel.coarse_planes (the default) the
// walk takes each of its voxels for one plane, so a voxel where surfaces meet is met at their
// mean plane; without it every coarser voxel occludes along the path (the honest rule, which
// measured worse: a Cornell box seen from outside, relative RMSE 0.46 -> 1.01, the walls'
// voxels smeared over their whole path let the ceiling's hot patch reach every cone near
// it). The light met there is the
// reflected light over the cone's footprint: the filtered voxels while the cone is narrower
// than they are, then the pyramid above the coarsest level (RadiancePyramidPass.h) at the
// cone's width. The pyramid keeps its light per face for either kind of voxels, and the wide
// read weighs each face by the area it shows the cone's directions (voxel.light_read=cone) or
// the surface met (surface): one average of every surface a texel held, by coverage, mixed a
// sunlit floor with the shaded flanks of the piers standing on it and lost a fifth to a third
// of the light in sunlit scenes (accuracy-analysis.md). voxel.pyramid_mips caps the width: a
// texel's light is averaged across its whole footprint, so a wide one straddling a wall shows
// a cone in one room the other room's light on the faces both rooms' walls show.
// The pyramid mip is picked for voxel.footprint cone diameters (0.6 by default, the thesis
// 1): a texel as wide as the cone, read trilinearly, averages a box one texel wide blurred by
// a tent two texels wide, a kernel of twice the spread (standard deviation) of the cone's
// disc, which carried bright patches (a lamp's spot, a sunlit strip) into the dim surfaces
// around them and lost light in every closed room (closed white box: energy 0.93 at 1, 0.99
// at 0.6). 0.5 would match the spreads and measured worse where a lamp makes a tiny hot
// patch (the Cornell box); accuracy-analysis.md has the suite. The filtered voxels read while
// the cone is narrower than two voxels keep their own width: there a narrower cone would
// only shift the blend towards one voxel's light, which on the fixed plan's 9 cm voxels
// paints the lamp's patch over the ceiling.
// Reading one voxel instead made the cone a ray that sees a small bright patch (the ceiling
// over a light) in full or not at all, which finer voxels alias ever more; and filtered
// coverage spread each wall over two half-opaque voxel layers that let a quarter of a
// crossing ray through. The pyramid holds light only: its coverage would halve a one-voxel
// wall's opacity per mip and let cones through walls.
//
// Anisotropic voxels (voxel.anisotropic, voxel_directional.glsl): the light a cone meets is
// read from the faces the cone sees, each weighted by the area it shows the cone: along the
// cone's axis (three faces) from the directional voxels, and over the cone's directions (all
// six once it is wide) from the pyramid, composited per face; a voxel faces away when none of those
// faces holds a surface facing the cone. Opacity stays the
// isotropic coverage (directional_build.comp says why).
#ifndef GI_VOXEL_CONE_TRACING_GLSL
#define GI_VOXEL_CONE_TRACING_GLSL

#include "../common/constants.glsl"
#include "../common/frame.glsl"
#include "../common/voxel_cascade.glsl"
#include "../common/voxel_plane.glsl"
#include "voxel_directional.glsl"

layout(binding = BIND_TEX_VOXEL_ALBEDO) uniform sampler3D voxelAlbedoTexture;
layout(binding = BIND_TEX_VOXEL_IRRADIANCE) uniform sampler3D voxelIrradianceTexture;
layout(binding = BIND_TEX_VOXEL_NORMAL) uniform sampler3D voxelNormalTexture;
layout(binding = BIND_TEX_VOXEL_PYRAMID) uniform sampler3D voxelPyramidTexture;
layout(binding = BIND_TEX_VOXEL_DIRECTIONAL) uniform sampler3D voxelDirectionalTexture;

// A ray crosses at most 3 v voxels of the coarsest level; finer levels add fewer steps.
const int kMaxSteps = 1024;
// On a propagated coarsest level the axis meets a flat voxel's plane up to this many voxel
// sizes, measured along the axis, before or after its path through the voxel.
const float kAxisCrossingSlack = 0.01;
// Anisotropic voxels whose faces towards a cone are covered less than this hold nothing that
// faces it.
const float kNothingFaces = 1e-3;

struct VoxelSample {
    vec4 albedo;       // rgb = albedo x coverage, a = coverage
    vec3 irradiance;   // E x coverage
    vec3 normal;
};

VoxelSample readLevel(vec3 p, int level) {
    vec3 tc = voxelTexcoord(p, level);
    VoxelSample s;
    s.albedo = texture(voxelAlbedoTexture, tc);
    s.irradiance = texture(voxelIrradianceTexture, tc).rgb;
    s.normal = texture(voxelNormalTexture, tc).xyz;
    return s;
}

#ifdef VOXEL_SHAPE_ANISOTROPIC
bool anisotropicVoxels() { return VOXEL_SHAPE_ANISOTROPIC != 0; }
#else
bool anisotropicVoxels() { return anisotropicKind(); }
#endif

// The directional voxels of `level` around p as a cone travelling along dir sees them:
// rgb = rho E x a, a = facing coverage, each face weighted by the area it shows along dir.
vec4 readDirectional(vec3 p, int level, vec3 dir) {
    vec3 tc = voxelTexcoord(p, level);
    vec3 weight = abs(dir);
    vec4 sum = vec4(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        float face = float(faceSeenAlong(dir, axis));
        sum += weight[axis] * texture(voxelDirectionalTexture,
                vec3((tc.x + face) / float(VOXEL_FACES), tc.yz));
    }
    return sum;
}

// Slab `slab` of `slabs` (x-slabs of the pyramid's every mip) at uvw (the coarsest level's
// [0, 1]^3), kept half a texel inside the slab so filtering never mixes slabs.
vec4 readPyramidSlab(vec3 uvw, int mip, int slab, int slabs) {
    float side = float(max((voxelResolution() / 2) >> mip, 1));
    vec3 local = clamp(uvw * side, vec3(0.5), vec3(side - 0.5));
    vec3 tc = vec3((local.x + float(slab) * side) / (side * float(slabs)), local.yz / side);
    return textureLod(voxelPyramidTexture, tc, float(mip));
}

// One mip of the pyramid, each face weighted as faceWeightsOverCone weighs it for the cone
// reading (face 2 axis + 1 is the one directions of positive component see).
// coarsestLight moves the read half a texel in front of the surface met.
vec4 readPyramidFaces(vec3 uvw, int mip, vec3 towardPositive, vec3 towardNegative) {
    vec4 sum = vec4(0.0);
    for (int face = 0; face < VOXEL_FACES; ++face) {
        float weight = (face & 1) != 0 ? towardPositive[face / 2] : towardNegative[face / 2];
        sum += weight * readPyramidSlab(uvw, mip, face, VOXEL_FACES);
    }
    return sum;
}

// One mip of the pyramid as seen along `seen` alone: the three faces it travels towards, each
// by |seen_axis| (faceWeightsOverCone of a cone of no width, without the other three fetches).
vec4 readPyramidAlong(vec3 uvw, int mip, vec3 seen) {
    vec4 sum = vec4(0.0);
    for (int axis = 0; axis < 3; ++axis) {
        sum += abs(seen[axis]) * readPyramidSlab(uvw, mip, faceSeenAlong(seen, axis), VOXEL_FACES);
    }
    return sum;
}

// The pyramid at a fractional mip as the directions of a cone along dir of half-angle tangent
// tanHalf see it: the slabs' clamp differs per mip, so the two mips are read apart, with the
// same weights, and blended here. All six faces once the cone is wide for anisotropic voxels
// and for a lone cone (`alone`: the specular lobe, whose light from the faces beside and
// behind its axis no other cone brings; the glossy box's metal block, accuracy-analysis.md);
// otherwise, and for a read of no width (the surface read, tanHalf = 0), the three faces the
// axis travels towards, at half the fetches: the cones of a set leave the faces beside each
// axis to its neighbours (isotropic voxels: no score of the suite moved by more than 0.004).
vec4 pyramidAt(vec3 uvw, float lod, vec3 dir, float tanHalf, bool alone) {
    int mip = int(floor(lod));
    float blend = lod - float(mip);
    if (!(anisotropicVoxels() || alone) || tanHalf <= 0.0) {
        vec4 lower = readPyramidAlong(uvw, mip, dir);
        return blend > 0.0 ? mix(lower, readPyramidAlong(uvw, mip + 1, dir), blend) : lower;
    }
    vec3 towardPositive, towardNegative;
    faceWeightsOverCone(dir, tanHalf, towardPositive, towardNegative);
    vec4 lower = readPyramidFaces(uvw, mip, towardPositive, towardNegative);
    return blend > 0.0 ? mix(lower, readPyramidFaces(uvw, mip + 1, towardPositive,
                                            towardNegative), blend)
                       : lower;
}

// Whether the light read where a cone meets a surface takes the faces the surface's
// direction sees (voxel.light_read=surface: the wide read averages the surfaces facing as the
// one met does and leaves out the other sides of what its texels hold, a pier's shaded flank
// beside a sunlit floor) instead of those the cone's directions see (Crassin et al. 2011).
bool surfaceRead() {
    return voxel.grid.z == VOXEL_KIND_ANISOTROPIC_SURFACE_READ ||
            voxel.grid.z == VOXEL_KIND_ISOTROPIC_SURFACE_READ;
}

// Reflected light rho E (W/m^2) per covered area that a cone of the given diameter sees
// around p on the coarsest level: the filtered voxels while the cone is narrower than they
// are, then the pyramid mip whose texels are voxel.footprint diameters wide (blended with the
// filtered voxels over the first octave). `front` points from the surface met to the side
// the cone came from: the pyramid is read half a texel that way, so its trilinear kernel
// (two texels wide) lies mostly in front of the surface. Centred on the surface, half the
// kernel lay behind it and averaged in what the surface hides: the other side of a wall, the
// shaded back of a pier, the dark outside of a lit room (accuracy-analysis.md). tanHalf is
// the cone's half-angle tangent: the wide read sees the faces all its directions see. The
// surface read takes one direction, the one a cone meeting the surface head-on would have.
// Selects, not branches: llvmpipe would run both sides.
vec3 coarsestLight(vec3 p, float diameter, vec3 dir, float tanHalf, vec3 front, bool alone) {
    int coarsest = voxelLevels() - 1;
    // The specular cone reads as its directions see, whatever voxel.light_read: read as the
    // surface met faces, the glossy box's metal block got 0.82 of the path tracer's light
    // instead of 0.96 (accuracy-analysis.md).
    bool bySurface = surfaceRead() && !alone;
    vec3 seen = bySurface ? -front : dir;
    float seenSpread = bySurface ? 0.0 : tanHalf;
    float spread = log2(diameter / levelVoxelSize(coarsest));
    vec4 wide = vec4(0.0);
    if (spread > 0.0) {
        float mip = max(spread + voxel.smoothing.z - 1.0, 0.0);
        if (voxel.grid.w >= 0) mip = min(mip, float(voxel.grid.w));
        vec3 read = p + front * (0.5 * exp2(mip + 1.0) * levelVoxelSize(coarsest));
        wide = pyramidAt((read - levelOrigin(coarsest)) / levelExtent(coarsest), mip, seen,
                seenSpread, alone);
        if (spread >= 1.0 && wide.a > 0.0) return wide.rgb / wide.a;
    }
    if (anisotropicVoxels()) {
        // Centred half a voxel back along the cone, the filtered read blends the voxel met
        // with the one in front of it, not with the one behind: behind a wall, that one
        // shows the other room's light.
        vec4 faces = readDirectional(p, coarsest, seen);
        vec3 light = faces.rgb / max(faces.a, 1e-4);
        return wide.a > 0.0 ? mix(light, wide.rgb / wide.a, spread) : light;
    }
    vec3 tc = voxelTexcoord(p, coarsest);
    vec4 albedo = texture(voxelAlbedoTexture, tc);
    float coverage = max(albedo.a, 1e-4);
    vec3 light = albedo.rgb * texture(voxelIrradianceTexture, tc).rgb / (coverage * coverage);
    return wide.a > 0.0 ? mix(light, wide.rgb / wide.a, spread) : light;
}

// Distance along dir, in voxels, from `local` (coarsest-level voxel units, inside the box from
// lo to hi) out of that box; at least a thousandth of a voxel, so the walk always moves.
float boxExit(vec3 local, vec3 dir, vec3 lo, vec3 hi) {
    vec3 toExit = mix(local - lo, hi - local, greaterThan(dir, vec3(0.0)));
    vec3 exitAt = toExit / max(abs(dir), vec3(1e-6));
    return max(min(exitAt.x, min(exitAt.y, exitAt.z)), 1e-3);
}

// Radiance seen along a cone from origin along dir whose half-angle has tangent tanHalf.
vec3 traceCone(vec3 origin, vec3 dir, float maxDistance, float tanHalf, bool alone) {
    float finest = levelVoxelSize(0);
    int coarsest = voxelLevels() - 1;
    float coarsestSize = levelVoxelSize(coarsest);
    vec3 coarsestOrigin = levelOrigin(coarsest);
    ivec3 coarsestSlab = ivec3(0, 0, coarsest * voxelResolution());
    int startLevel = max(finestLevel(origin), 0);
    // The origin stands a voxel off the surface already. The thesis' walk starts one voxel
    // further out, which skips every surface within two voxels of the receiving one: the
    // wall beside a concave edge, whose light a point there mostly receives. On one level
    // (level 0: each voxel's own plane) the walk starts voxel.walk_start voxels out, at the
    // origin by default; a cascade's coarse levels hold mean planes, which the cones'
    // first voxels would meet where no surface is (the fixed plan's Cornell box: energy
    // 1.15 -> 1.20), and keep the thesis' start.
    bool walkFromNear = coarsest == 0;
    float dist = (walkFromNear ? voxel.cones.w : 1.0) * levelVoxelSize(startLevel);
    vec3 radiance = vec3(0.0);
    float opacity = 0.0;
    int steps = 0;
    while (steps < kMaxSteps && dist < maxDistance && opacity < 0.99) {
        vec3 p = origin + dir * dist;
        int available = finestLevel(p);
        if (available < 0) break;
        float diameter = max(2.0 * tanHalf * dist, finest);
        float lod = clamp(log2(diameter / finest), float(available), float(coarsest));
        int level = int(floor(lod));
        float blend = lod - float(level);
        float corrected;
        vec3 reflected;
        if (coarsest == 0 || level == coarsest) {   // a compile-time 0 drops the branch below
            // Walk the axis voxel by voxel through the coarsest level (a 3D DDA) to the
            // first voxel it meets a surface in; the loop fetches one normal texel a step
            // (which tells an occupied voxel from an empty one, and how far the nearest
            // occupied one is: voxel_plane.glsl), so the coverage and the costly reads below
            // run once per surface met.
            bool found = false, crossed = false;
            ivec3 metTexel = ivec3(0);
            vec3 front = -dir;   // where no plane is met: back along the cone
            float hit = 0.0, coverage = 0.0, path = 0.0, entry = dist;
            while (steps < kMaxSteps && dist < maxDistance) {
                ++steps;
                p = origin + dir * dist;
                vec3 local = (p - coarsestOrigin) / coarsestSize;
                if (any(lessThan(local, vec3(0.0))) ||
                        any(greaterThanEqual(local, vec3(voxelResolution())))) {
                    dist = maxDistance;
                    break;
                }
                // A finer level takes over again where the cone is still narrow enough (the
                // test the level choice above makes); empty blocks are skipped only where none
                // can (the cone only widens).
                bool narrow = coarsest > 0 && log2(diameter / finest) < float(coarsest);
                if (narrow && insideLevel(p, coarsest - 1)) break;
                bool skipEmpty = !narrow;
                vec3 cell = floor(local);
                ivec3 texel = ivec3(cell) + coarsestSlab;
                vec4 plane = texelFetch(voxelNormalTexture, texel, 0);
                int empty = voxelOccupied(plane) ? 0 : voxelEmptyDistance(plane);
                if (skipEmpty && empty >= 2) {
                    // Every voxel within empty - 1 of this one is empty: leave their cube.
                    float reach = float(empty - 1);
                    dist += (boxExit(local, dir, cell - reach, cell + 1.0 + reach) + 1e-3) *
                            coarsestSize;
                    diameter = max(2.0 * tanHalf * dist, finest);
                    continue;
                }
                path = boxExit(local, dir, cell, cell + 1.0) * coarsestSize;
                entry = dist;
                dist += path + 1e-3 * coarsestSize;
                diameter = max(2.0 * tanHalf * dist, finest);
                if (!voxelOccupied(plane)) continue;
                float cosine = dot(dir, plane.xyz);
                // A voxel facing away from the cone is skipped, as in the thesis: its surface
                // sends no light this way, and its occlusion would mostly be the cone's own
                // surface seen from behind (the voxel layer the cone starts in). The mean
                // normal decides for anisotropic voxels too: asking their faces (three fetches
                // per voxel met) cost x1.36 of the trace and scored no better on the suite
                // (accuracy-analysis.md).
                if (cosine > 0.0) continue;
                if (voxelHoldsOnePlane(plane, coarsest, voxel.modes.w != 0.0)) {
                    // One flat surface: the axis meets it where it crosses its plane, or not
                    // at all in this voxel, and crossing it is an occlusion of `coverage`.
                    // On level 0 within kPlaneTolerance, as the visibility marches: each
                    // voxel's plane offset is 8-bit and stochastically rounded, so a floor's
                    // neighbouring voxels disagree by up to two steps, and with the slack of
                    // 0.01 voxels along the axis that the walk keeps on a cascade's coarsest
                    // level, an axis crossing where two of them meet passed through the floor
                    // between their planes: 13 % of the cones meeting a sunlit floor at a
                    // slant (accuracy-analysis.md). A propagated level's planes are means of
                    // their children's, which the wider tolerance would meet where they are
                    // not (the thesis' cascade: energy 1.18 on the Cornell box).
                    vec3 centre = coarsestOrigin + (cell + 0.5) * coarsestSize;
                    vec3 exitPoint = p + dir * path;
                    float tolerance = coarsest == 0
                            ? kPlaneTolerance
                            : kAxisCrossingSlack * -cosine / length(plane.xyz);
                    if (!segmentCrossesVoxelPlane(plane, centre, coarsestSize, p, exitPoint,
                            tolerance)) {
                        continue;
                    }
                    float entrySide = voxelPlaneDistance(plane, centre, coarsestSize, p);
                    float exitSide = voxelPlaneDistance(plane, centre, coarsestSize, exitPoint);
                    hit = path * entrySide / (entrySide - exitSide);
                    crossed = true;
                    front = plane.xyz / length(plane.xyz);   // faces the cone (cosine < 0)
                } else {
                    // Several surfaces within a voxel of the origin are mostly where the
                    // receiving surface meets another (a wall's foot on a sunlit floor): their
                    // mean plane faces the cone, but much of their light is the receiver's
                    // own. Passed: the surfaces there that hold one plane are met at it.
                    if (walkFromNear && entry < coarsestSize) continue;
                    // Several surfaces: occluding along the whole path, light read halfway.
                    hit = 0.5 * path;
                }
                metTexel = texel;
                found = true;
                break;
            }
            if (!found) continue;
            coverage = clamp(texelFetch(voxelAlbedoTexture, metTexel, 0).a, 0.0, 1.0);
            corrected = crossed ? coverage
                    : 1.0 - pow(1.0 - min(coverage, 0.9999), path / coarsestSize);
            hit = clamp(hit, 0.0, path);
            reflected = coarsestLight(p + dir * hit, max(2.0 * tanHalf * (entry + hit), finest),
                    dir, tanHalf, front, alone);
        } else {
            ++steps;
            float path = max(min(diameter, levelVoxelSize(level + (blend > 0.0 ? 1 : 0))) *
                    voxel.trace.z, 0.25 * finest);
            dist += path;
            VoxelSample s = readLevel(p, level);
            float voxelSize = levelVoxelSize(level);
            if (blend > 0.0) {
                VoxelSample t = readLevel(p, level + 1);
                s.albedo = mix(s.albedo, t.albedo, blend);
                s.irradiance = mix(s.irradiance, t.irradiance, blend);
                s.normal = mix(s.normal, t.normal, blend);
                voxelSize = mix(voxelSize, levelVoxelSize(level + 1), blend);
            }
            float coverage = clamp(s.albedo.a, 0.0, 1.0);
            if (coverage <= 0.0) continue;
            if (anisotropicVoxels()) {
                // Facing away: nothing in the voxels faces the cone.
                vec4 seen = readDirectional(p, level, dir);
                if (blend > 0.0) seen = mix(seen, readDirectional(p, level + 1, dir), blend);
                if (seen.a <= kNothingFaces) continue;
                reflected = seen.rgb / seen.a;
            } else {
                // Facing away: skipped as above.
                if (dot(s.normal, dir) > 0.0) continue;
                reflected = s.albedo.rgb * s.irradiance / (coverage * coverage);
            }
            corrected = 1.0 - pow(1.0 - min(coverage, 0.9999), path / voxelSize);
        }
        vec3 light = reflected / PI * corrected;
        if (voxel.trace.w != 0.0) light /= 1.0 + dist * dist; // the thesis' falloff
        radiance += (1.0 - opacity) * light;
        opacity += (1.0 - opacity) * corrected;
    }
    // What the cone has not met when it leaves the volume or reaches its range is the sky
    // (unless it gave up after kMaxSteps inside).
    if (steps < kMaxSteps) radiance += (1.0 - opacity) * frame.sky.rgb;
    return radiance;
}

// E_ind (W/m^2) on the side of a surface facing n, from the cones of voxel.cones (ConeSet.h)
// starting at origin (a voxel off the surface): one along n and the rings around it, each ring
// turned by `turn` (a fraction of its spacing) and ring k by a further k halves of it, so the
// rings interlace, and moved by `rise` (0..1, 0.5 = the ring's own elevation) up to its reach
// within its band. Pixel class c of `classes` traces ring cones c, c + classes, ... weighted
// x classes (the filter merges the classes); class 0 of 1 traces them all.
vec3 coneIrradiance(vec3 origin, vec3 n, float turn, float rise, int coneClass, int classes,
                    float maxDistance) {
    vec3 t = normalize(abs(n.y) < 0.99 ? cross(n, vec3(0.0, 1.0, 0.0)) : cross(n, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(n, t);
    float tanHalf = voxel.trace.x;
    vec3 e = voxel.cones.x * traceCone(origin, n, maxDistance, tanHalf, false);
    for (int k = 0; k < 3; ++k) {
        vec4 ring = voxel.coneRings[k];
        int count = int(ring.x);
        float sine2 = clamp(ring.y + (2.0 * rise - 1.0) * ring.z, 0.0, 1.0);
        float sine = sqrt(sine2), cosine = sqrt(1.0 - sine2);
        float spacing = 2.0 * PI / max(ring.x, 1.0);
        for (int i = coneClass; i < count; i += classes) {
            float phi = (float(i) + 0.5 * float(k) + turn) * spacing;
            vec3 dir = cosine * n + sine * (cos(phi) * t + sin(phi) * b);
            e += ring.w * float(classes) * traceCone(origin, dir, maxDistance, tanHalf, false);
        }
    }
    return PI * e;
}

#endif
