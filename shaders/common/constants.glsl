// Numbers more than one shader needs, written once.
#ifndef GI_CONSTANTS_GLSL
#define GI_CONSTANTS_GLSL

const float PI = 3.14159265358979;

// The largest value the passes store into RGBA16F images: half floats overflow to infinity
// above 65504, and clamping a little below keeps any store rounding from reaching it.
const float HALF_STORE_MAX = 65000.0;

#endif
