// Runs shaders/common/tonemap.glsl on the values of ToneCurveGpuTest.cpp, one invocation per
// value. The test binds its own two buffers at 0 and 1; no pass uses this.
#include "shaders/common/tonemap.glsl"

layout(local_size_x = 1) in;

layout(std430, binding = 0) readonly buffer Inputs {
    vec4 inputs[];    // rgb = exposed radiance
};
layout(std430, binding = 1) writeonly buffer Results {
    vec4 filmic[];    // rgb = toneCurve(input, TONE_CURVE_FILMIC)
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    filmic[i] = vec4(toneCurve(inputs[i].rgb, TONE_CURVE_FILMIC), 0.0);
}
