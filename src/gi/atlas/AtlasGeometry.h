// The scene's triangles with their atlas coordinates on the GPU: the vertex buffer of every
// atlas pass. Charts split mesh vertices along their borders, so it has its own vertices and
// indices, but the same triangles in the same order as scene::GpuScene, whose draws (materials,
// textures, culling) the atlas passes issue with this vertex array (GpuScene::drawAll).
// Attributes: the scene's (ATTR_POSITION .. ATTR_COLOR, world space) plus ATTR_ATLAS_UV and
// ATTR_ATLAS_INFO (chart index, double-sided flag).
#pragma once

#include "gi/atlas/AtlasBuilder.h"
#include "gl/Objects.h"

#include <vector>

namespace gi::atlas {

struct GpuAtlasVertex { // interleaved, 72 bytes (ATLAS_VERTEX_FLOATS floats)
    float position[3];  // world space, metres
    float normal[3];    // world space, unit
    float texcoord0[2];
    float texcoord1[2];
    float color[4];   // linear RGBA
    float atlasUv[2]; // [0,1]^2
    float info[2];    // x = chart index (exact up to 2^24), y = 1 if double-sided
};

class AtlasGeometry {
public:
    // `followsPose`: also keep, per atlas vertex, the mesh (= GpuScene) vertex it was split
    // from, so AtlasPosePass can move the vertices with animated instances.
    void upload(const AtlasMesh& mesh, const Atlas& atlas, bool followsPose);
    const gl::VertexArray& vertexArray() const { return mVertexArray; }
    const gl::Buffer& vertexBuffer() const { return mVertices; }
    const gl::Buffer& indexBuffer() const { return mIndices; }   // 3 per triangle, the scene's order
    const gl::Buffer& sources() const { return mSources; }   // empty unless followsPose
    std::size_t vertexCount() const { return mVertexCount; }

private:
    gl::Buffer mVertices, mIndices, mSources;
    gl::VertexArray mVertexArray;
    std::size_t mVertexCount = 0;
};

} // namespace gi::atlas
