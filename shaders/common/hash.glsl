// Integer hashing for per-pixel and per-texel random numbers.
#ifndef GI_HASH_GLSL
#define GI_HASH_GLSL

// Wellons' lowbias32: every input bit changes about half the output bits.
uint hash(uint v) {
    v ^= v >> 16;
    v *= 0x7feb352du;
    v ^= v >> 15;
    v *= 0x846ca68bu;
    v ^= v >> 16;
    return v;
}

// A number in [0, 1) from the running state, which it advances.
float random01(inout uint state) {
    state = hash(state);
    return float(state >> 8) / 16777216.0;
}

#endif
