// The weight by which the area estimator draws a sender texel, shared by the draw
// (sender_sampling.comp) and the gather that divides by it (gather.frag).
// With atlas.importance=power it is the power the texel sends, a(y) mean(L(y)) over both sides.
// Otherwise each side's power is multiplied by I(y) + share x I_mean: I(y) how much of that
// side's light the receivers can receive (the importance step: the surfaces the camera sees,
// or points on the scene's triangles), I_mean its power-weighted mean over the atlas, so every
// lit texel keeps a share of the draw whatever the receivers see.
// The draw's tables hold two prefix sums, sum a mean(L) I (x) and sum a mean(L) (y), so the
// floor is added once the totals are known: weight = x + share x (X / Y) x y.
#ifndef GI_ATLAS_SENDER_WEIGHT_GLSL
#define GI_ATLAS_SENDER_WEIGHT_GLSL

#include "atlas_common.glsl"

layout(binding = BIND_TEX_ATLAS_IMPORTANCE) uniform sampler2D atlasImportance;

bool drawsByImportance() { return atlas.importance.x > 0.0; }

// The importance of the texel's front (x) and back (y) side; 1 without one.
vec2 senderImportance(ivec2 t) {
    return drawsByImportance() ? texelFetch(atlasImportance, t, 0).rg : vec2(1.0);
}

// share x I_mean from the tables' totals: what each unit of power adds to I(y).
float importanceFloor(vec2 totals) {
    return drawsByImportance() && totals.y > 0.0 ? atlas.importance.x * totals.x / totals.y
                                                 : 0.0;
}

// A pair of sums (x: with importance, y: power alone) as one weight.
float combinedWeight(vec2 sums, float floorPerPower) {
    return sums.x + floorPerPower * sums.y;
}

// Per unit of the texel's area, the pair of weights of radiances `front` and `back`.
vec2 senderWeightsPerArea(vec3 front, vec3 back, vec2 importance) {
    float f = dot(front, vec3(1.0 / 3.0)), b = dot(back, vec3(1.0 / 3.0));
    return vec2(f * importance.x + b * importance.y, f + b);
}

#endif
