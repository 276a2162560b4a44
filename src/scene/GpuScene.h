// The scene on the GPU, shared by every pass that draws geometry: one world-space vertex
// buffer and one index buffer for all instances (passes need world positions, and one buffer
// keeps each pass to a single vertex array), a material table and a light table in storage
// buffers, and one sRGB texture per scene texture. Draws are grouped per instance so each
// pass binds its own textures and material index per draw.
#pragma once

#include "gl/Handle.h"
#include "gl/Objects.h"
#include "gl/Shared.h"
#include "scene/Scene.h"

#include <vector>

namespace gi::scene {

struct SceneVertex {             // interleaved, 56 bytes (SCENE_VERTEX_FLOATS floats)
    float position[3];           // world space, metres
    float normal[3];             // world space, unit
    float texcoord0[2];
    float texcoord1[2];
    float color[4];              // linear RGBA
};

class GpuScene {
public:
    struct Draw {
        std::uint32_t firstIndex = 0;   // into the index buffer
        std::uint32_t indexCount = 0;
        int material = 0;               // into the material table (a default material is last)
        bool doubleSided = false;
        bool alphaMasked = false;
        bool dynamic = false;           // an animated instance (Instance::dynamic)
    };
    // Which draws drawAll issues: passes that cache static geometry draw it once and the
    // dynamic draws every frame; an area light's shadow map leaves out the surfaces that are
    // area lights (a light does not shadow itself; its centre may lie inside a closed emitter).
    enum class DrawSet { All, Static, Dynamic, NotEmittingLight };

    explicit GpuScene(const Scene& scene);

    // Replaces the light table (lights may come from the scene and the command line) and
    // chooses the pre-exposure for it (scene/Exposure.h): lights and emission are uploaded
    // times exposure(), so everything the GPU computes from them is too.
    void setLights(const std::vector<Light>& lights);

    // Rewrites the vertices of the scene's dynamic (animated) instances from their current
    // worldFromLocal (scene/Animation.h poseScene) and bumps geometryVersion().
    void updateDynamic(const Scene& scene);
    bool hasDynamicGeometry() const { return !mDynamicRanges.empty(); }
    // Changes whenever vertices move: passes that cache geometry (the atlas) compare it.
    std::uint64_t geometryVersion() const { return mGeometryVersion; }

    // The factor k of scene/Exposure.h that every GPU radiometric value carries.
    float exposure() const { return mExposure; }

    // Issues every draw with the current program; binds base-colour and emissive textures
    // and sets LOC_DRAW_MATERIAL per draw. `cullBackFaces` culls single-sided draws only.
    // `vertexArray` replaces the scene's own vertex array; it must hold the same triangles in
    // the same order (e.g. the texture atlas' geometry, whose vertices are split at charts).
    void drawAll(GLuint program, bool cullBackFaces, const gl::VertexArray* vertexArray = nullptr,
            DrawSet set = DrawSet::All) const;
    // Draws every surface's depth with `depthProgram` and leaves depth at GL_LEQUAL without
    // writes and colour writes on, so the next draw shades only the surface in front of each
    // pixel (the forward pass, the cone trace).
    void drawDepthPrepass(GLuint depthProgram) const;

    // Every vertex (SceneVertex), for passes that copy posed positions (atlas/follow_pose).
    const gl::Buffer& vertexBuffer() const { return mVertices; }
    // Binds the light table and the area lights' triangles (lighting.glsl reads both).
    void bindLights() const;
    const gl::Buffer& materialBuffer() const { return mMaterials; }
    // MATERIAL_TEXTURES_* bits: the kinds of texture some material has.
    int textureKinds() const;
    int lightCount() const { return mLightCount; }
    // Bit (1 << LIGHT_*) for every kind of light in the table.
    int lightKinds() const { return mLightKinds; }
    const Aabb& bounds() const { return mBounds; }

private:
    void uploadGeometry(const Scene& scene);
    void uploadMaterials(const Scene& scene);

    gl::Buffer mVertices, mIndices, mMaterials, mLights, mEmitters;
    gl::VertexArray mVertexArray;
    std::vector<gl::Texture> mTextures;
    gl::Texture mWhite;                  // bound where a material has no texture
    gl::Sampler mSampler;
    std::vector<Draw> mDraws;
    std::vector<int> mBaseColorTexture, mEmissiveTexture;   // per material, -1 = none
    std::vector<bool> mEmitsAsLight;     // per material: its emission is an area light's
    int mLightCount = 0;
    int mLightKinds = 0;
    Aabb mBounds;
    // The material table as authored; uploaded with its emission times mExposure.
    std::vector<shader::GpuMaterial> mMaterialTable;
    float mMaxEmission = 0.0f;
    float mExposure = 1.0f;
    struct DynamicRange {
        std::size_t instance = 0;        // into Scene::instances
        std::size_t firstVertex = 0, vertexCount = 0;
    };
    std::vector<DynamicRange> mDynamicRanges;
    std::uint64_t mGeometryVersion = 0;
};

} // namespace gi::scene
