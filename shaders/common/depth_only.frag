// Depth pre-pass shared by every pass that shades each visible surface once: alpha-masked
// texels are cut out, everything else only writes depth. The shading pass then runs with
// an early LEQUAL test against it (its vertex stage declares gl_Position invariant).
#include "material.glsl"
#include "vertex_data.glsl"

in VertexData { VERTEX_DATA_MEMBERS } vin;

void main() {
    GpuMaterial m = materials[drawMaterial];
    if (materialMaskedOut(m, vin.texcoord0, vin.texcoord1, vin.color)) discard;
}
