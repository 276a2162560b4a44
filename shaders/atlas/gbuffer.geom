// Atlas G-buffer, geometry stage of the conservative draw (Hasselgren, Akenine-Moeller and
// Ohlsson 2005, "Conservative Rasterization", GPU Gems 2 ch. 42): every edge of the triangle
// is pushed outwards by half a texel diagonal in atlas texel space, so the enlarged triangle
// covers the centre of every texel the original one touches. The new corners' attributes are
// extrapolated linearly over the triangle's plane (barycentric coordinates outside [0,1]),
// and the fragment stage discards texels outside the original triangle's bounding box, which
// the enlarged corners overshoot at acute angles.
// With SAMPLE_AREA the fragment stage also gets the original triangle (texel units) and its
// world area per texel^2, to add up the surface area inside each texel (gbuffer.frag).
#include "atlas_common.glsl"
#include "atlas_vertex.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in AtlasVertex { ATLAS_VERTEX_MEMBERS } vin[];

out AtlasVertex { ATLAS_VERTEX_MEMBERS } vout;

flat out vec4 texelBounds;   // xy = min, zw = max corner of the triangle (texels)
#ifdef SAMPLE_AREA
flat out vec4 triangleAB;    // xy = corner 0, zw = corner 1 of the triangle (texels)
flat out vec4 triangleC;     // xy = corner 2 (texels), z = world area per texel^2 (m^2), w unused
#endif

void main() {
    float resolution = float(atlas.size.x);
    vec2 p[3];
    for (int i = 0; i < 3; ++i) p[i] = (gl_in[i].gl_Position.xy * 0.5 + 0.5) * resolution;
    vec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    float area = e1.x * e2.y - e1.y * e2.x;
    if (area == 0.0) return;
    float orientation = sign(area);
    // Edge i runs from p[i] to p[i+1]; its outward line n.x = c, moved out by the support of
    // the half-texel square in direction n.
    vec3 line[3];
    for (int i = 0; i < 3; ++i) {
        vec2 d = p[(i + 1) % 3] - p[i];
        vec2 n = normalize(orientation * vec2(d.y, -d.x));
        line[i] = vec3(n, dot(n, p[i]) + 0.5 * (abs(n.x) + abs(n.y)));
    }
    vec2 lo = min(p[0], min(p[1], p[2])), hi = max(p[0], max(p[1], p[2]));
#ifdef SAMPLE_AREA
    float worldArea = 0.5 * length(cross(vin[1].position - vin[0].position,
                                         vin[2].position - vin[0].position));
    float areaPerTexel = worldArea / (0.5 * abs(area));
#endif
    for (int i = 0; i < 3; ++i) {
        // Corner i is where the lines of its two edges (i-1 and i) meet.
        vec3 a = line[(i + 2) % 3], b = line[i];
        float det = a.x * b.y - a.y * b.x;
        vec2 q = abs(det) > 1e-12 ? vec2(a.z * b.y - a.y * b.z, a.x * b.z - a.z * b.x) / det : p[i];
        // Barycentric coordinates of q in the original triangle.
        vec2 r = q - p[0];
        float w1 = (r.x * e2.y - r.y * e2.x) / area;
        float w2 = (e1.x * r.y - e1.y * r.x) / area;
        float w0 = 1.0 - w1 - w2;
        vout.position = w0 * vin[0].position + w1 * vin[1].position + w2 * vin[2].position;
        vout.normal = w0 * vin[0].normal + w1 * vin[1].normal + w2 * vin[2].normal;
        vout.texcoord0 = w0 * vin[0].texcoord0 + w1 * vin[1].texcoord0 + w2 * vin[2].texcoord0;
        vout.texcoord1 = w0 * vin[0].texcoord1 + w1 * vin[1].texcoord1 + w2 * vin[2].texcoord1;
        vout.color = w0 * vin[0].color + w1 * vin[1].color + w2 * vin[2].color;
        vout.doubleSided = vin[0].doubleSided;
        texelBounds = vec4(lo, hi);
#ifdef SAMPLE_AREA
        triangleAB = vec4(p[0], p[1]);
        triangleC = vec4(p[2], areaPerTexel, 0.0);
#endif
        gl_Position = vec4(q / resolution * 2.0 - 1.0, gl_in[i].gl_Position.zw);
        EmitVertex();
    }
    EndPrimitive();
}
