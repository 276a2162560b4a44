// What one pixel of a light's own view shows (light injection, the reflective shadow maps):
// the surface turned to the side the light sees, the light's unshadowed irradiance there, and
// the surface area the pixel covers,
//   A = footprint * d^2 * cos^3(theta_axis) / cos(theta_surface)   (perspective)
//   A = footprint / cos(theta_surface)                              (orthographic),
// footprint being the pixel's area at unit distance along the axis, or in the orthographic
// view's plane.
#ifndef GI_COMMON_LIGHT_VIEW_GLSL
#define GI_COMMON_LIGHT_VIEW_GLSL

#include "lighting.glsl"

struct LitSurface {
    vec3 normal;       // on the lit side, as the path tracer turns normals
    vec3 toLight;
    float distance;
    vec3 irradiance;   // E from this light, unshadowed (the view's depth test shadows)
};

LitSurface litSurface(GpuLight light, vec3 position, vec3 normal) {
    LitSurface s;
    lightDirection(light, position, s.toLight, s.distance);
    s.normal = dot(normal, s.toLight) < 0.0 ? -normal : normal;
    s.irradiance = lightIrradiance(light, position, s.normal);
    return s;
}

// viewAxis.xyz: the view's axis, w = 1 for an orthographic view. cosSurface is the caller's
// clamped cos(theta_surface): a grazing surface's area grows as its irradiance shrinks.
float lightPixelArea(vec4 viewAxis, float footprint, LitSurface s, float cosSurface) {
    float area = footprint / cosSurface;
    if (viewAxis.w == 0.0) {
        float cosAxis = max(dot(-s.toLight, viewAxis.xyz), 0.0);
        area *= s.distance * s.distance * cosAxis * cosAxis * cosAxis;
    }
    return area;
}

#endif
