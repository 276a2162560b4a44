#include "gi/atlas/AtlasGeometry.h"

#include "gl/Shared.h"

#include <algorithm>
#include <cstddef>

namespace gi::atlas {

static_assert(sizeof(GpuAtlasVertex) == ATLAS_VERTEX_FLOATS * sizeof(float),
        "GpuAtlasVertex must match atlas/follow_pose.comp");
static_assert(offsetof(GpuAtlasVertex, atlasUv) == ATLAS_VERTEX_UV_OFFSET * sizeof(float),
        "GpuAtlasVertex::atlasUv must be where atlas/near_field.glsl reads it");

void AtlasGeometry::upload(const AtlasMesh& mesh, const Atlas& atlas, bool followsPose) {
    std::vector<GpuAtlasVertex> vertices(atlas.vertices.size());
    for (std::size_t i = 0; i < atlas.vertices.size(); ++i) {
        const AtlasVertex& a = atlas.vertices[i];
        GpuAtlasVertex& v = vertices[i];
        std::copy_n(&mesh.positions[a.source].x, 3, v.position);
        std::copy_n(&mesh.normals[a.source].x, 3, v.normal);
        std::copy_n(&mesh.texcoords0[a.source].x, 2, v.texcoord0);
        std::copy_n(&mesh.texcoords1[a.source].x, 2, v.texcoord1);
        std::copy_n(&mesh.colors[a.source].x, 4, v.color);
        v.atlasUv[0] = a.uv.x;
        v.atlasUv[1] = a.uv.y;
        v.info[0] = float(a.chart);
        v.info[1] = mesh.doubleSided[a.source] ? 1.0f : 0.0f;
    }
    mVertexCount = vertices.size();
    mSources = {};
    if (followsPose && !atlas.vertices.empty()) {
        std::vector<std::uint32_t> sources(atlas.vertices.size());
        for (std::size_t i = 0; i < sources.size(); ++i) sources[i] = atlas.vertices[i].source;
        mSources = gl::createBuffer(sources.size() * sizeof(std::uint32_t), sources.data(), 0,
                "atlas/vertex_sources");
    }
    mVertices = gl::createBuffer(vertices.size() * sizeof(GpuAtlasVertex), vertices.data(), 0,
            "atlas/vertices");
    mIndices = gl::createBuffer(atlas.indices.size() * sizeof(std::uint32_t), atlas.indices.data(),
            0, "atlas/indices");
    mVertexArray = gl::createVertexArray("atlas/vertex_array");
    const GLuint vao = mVertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, mVertices.id(), 0, sizeof(GpuAtlasVertex));
    glVertexArrayElementBuffer(vao, mIndices.id());
    auto attribute = [vao](GLuint location, int components, std::size_t offset) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribFormat(vao, location, components, GL_FLOAT, GL_FALSE, GLuint(offset));
        glVertexArrayAttribBinding(vao, location, 0);
    };
    attribute(ATTR_POSITION, 3, offsetof(GpuAtlasVertex, position));
    attribute(ATTR_NORMAL, 3, offsetof(GpuAtlasVertex, normal));
    attribute(ATTR_TEXCOORD0, 2, offsetof(GpuAtlasVertex, texcoord0));
    attribute(ATTR_TEXCOORD1, 2, offsetof(GpuAtlasVertex, texcoord1));
    attribute(ATTR_COLOR, 4, offsetof(GpuAtlasVertex, color));
    attribute(ATTR_ATLAS_UV, 2, offsetof(GpuAtlasVertex, atlasUv));
    attribute(ATTR_ATLAS_INFO, 2, offsetof(GpuAtlasVertex, info));
}

} // namespace gi::atlas
