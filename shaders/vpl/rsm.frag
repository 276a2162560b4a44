// Reflective shadow map (Dachsbacher and Stamminger 2005; SEEDS.md section 4): every pixel of
// a light's view holds the surface the light sees there, its normal on the lit side and the
// flux it reflects,
//   phi = rho * E * A,
// A being the surface area the pixel covers and E this light's unshadowed irradiance (the
// view's depth test is the shadowing; light_view.glsl). For a point light this is rho * I * (the pixel's solid
// angle), so the pixels of six faces hold rho times the light's whole power. The flux
// target's alpha keeps A: the lit area sets the clamp's scale (VplGi.h). Area lights are
// seen from their centre, E being the emitters' exact irradiance (lighting.glsl): the texels'
// flux sums to the reflected power as the direct pass lights it. rho is what the surface sends
// on of the light (reflectance.glsl): the base colour, or with the glTF model its BRDF's
// albedo for the light's direction.
#include "../common/light_view.glsl"
#include "../common/material.glsl"
#include "../common/reflectance.glsl"
#include "../common/vertex_data.glsl"

layout(early_fragment_tests) in;

layout(location = LOC_RSM_AXIS) uniform vec4 viewAxis;   // w = 1: orthographic
layout(location = LOC_RSM_FOOTPRINT) uniform float pixelFootprint;
layout(location = LOC_RSM_LIGHT) uniform int lightIndex;
layout(location = LOC_RSM_GLTF) uniform int gltfReflectance;

in VertexData { VERTEX_DATA_MEMBERS } vin;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outFlux;

void main() {
    GpuMaterial m = materials[drawMaterial];
    vec4 baseColor = materialBaseColor(m, vin.texcoord0, vin.texcoord1, vin.color);
    if (materialCutOut(m, baseColor.a)) discard;
    LitSurface lit = litSurface(lights[lightIndex], vin.position, normalize(vin.normal));
    float cosSurface = max(dot(lit.normal, lit.toLight), 1e-3);
    float area = lightPixelArea(viewAxis, pixelFootprint, lit, cosSurface);
    outPosition = vec4(vin.position, 1.0);
    outNormal = vec4(lit.normal, 1.0);
    vec3 reflectance = reflectanceOfLight(m, baseColor.rgb, dot(lit.normal, lit.toLight),
            gltfReflectance != 0);
    outFlux = vec4(reflectance * lit.irradiance * area, area);
}
