// One triangle that covers the viewport, generated from gl_VertexID (no vertex buffer), for
// the passes that run once per pixel or per atlas texel. uv runs 0..1 over the visible part,
// bottom-left origin, matching the GL row order of textures and the default framebuffer.
out vec2 uv;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
