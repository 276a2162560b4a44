#include "scene/GpuScene.h"

#include "gl/Shared.h"
#include "scene/Exposure.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace gi::scene {

static_assert(sizeof(SceneVertex) == SCENE_VERTEX_FLOATS * sizeof(float),
        "SceneVertex must match atlas/follow_pose.comp");
namespace {

constexpr glm::vec4 kDefaultBaseColor{0.8f, 0.8f, 0.8f, 1.0f};

} // namespace

GpuScene::GpuScene(const Scene& scene) : mBounds(scene.bounds) {
    uploadGeometry(scene);
    uploadMaterials(scene);
    setLights(scene.lights);
}

namespace {

// The instance's vertices in world space, as the vertex buffer holds them.
void appendInstanceVertices(const Scene& scene, const Instance& instance,
        std::vector<SceneVertex>& vertices) {
    const Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(instance.worldFromLocal)));
    for (std::size_t i = 0; i < primitive.positions.size(); ++i) {
        SceneVertex v{};
        const glm::vec3 p = glm::vec3(instance.worldFromLocal * glm::vec4(primitive.positions[i], 1.0f));
        glm::vec3 n = normalMatrix * primitive.normals[i];
        const float length = glm::length(n);
        n = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
        const glm::vec2 uv0 = i < primitive.texcoords0.size() ? primitive.texcoords0[i] : glm::vec2(0.0f);
        const glm::vec2 uv1 = i < primitive.texcoords1.size() ? primitive.texcoords1[i] : glm::vec2(0.0f);
        const glm::vec4 c = i < primitive.colors.size() ? primitive.colors[i] : glm::vec4(1.0f);
        std::copy_n(&p.x, 3, v.position);
        std::copy_n(&n.x, 3, v.normal);
        std::copy_n(&uv0.x, 2, v.texcoord0);
        std::copy_n(&uv1.x, 2, v.texcoord1);
        std::copy_n(&c.x, 4, v.color);
        vertices.push_back(v);
    }
}

} // namespace

void GpuScene::uploadGeometry(const Scene& scene) {
    std::vector<SceneVertex> vertices;
    std::vector<std::uint32_t> indices;
    vertices.reserve(scene.vertexCount());
    indices.reserve(scene.triangleCount() * 3);
    const int defaultMaterial = int(scene.materials.size());
    for (std::size_t k = 0; k < scene.instances.size(); ++k) {
        const Instance& instance = scene.instances[k];
        const Primitive& primitive = scene.primitives[std::size_t(instance.primitive)];
        const auto base = std::uint32_t(vertices.size());
        appendInstanceVertices(scene, instance, vertices);
        if (instance.dynamic) mDynamicRanges.push_back({k, base, primitive.positions.size()});
        Draw draw;
        draw.dynamic = instance.dynamic;
        draw.firstIndex = std::uint32_t(indices.size());
        draw.indexCount = std::uint32_t(primitive.indices.size());
        draw.material = primitive.material >= 0 ? primitive.material : defaultMaterial;
        if (primitive.material >= 0) {
            const Material& material = scene.materials[std::size_t(primitive.material)];
            draw.doubleSided = material.doubleSided;
            draw.alphaMasked = material.alphaMode == AlphaMode::Mask;
        }
        // The loader already made every world-space triangle counter-clockwise, mirrored
        // instances included (Scene.h), so indices are copied as they are.
        for (const std::uint32_t index : primitive.indices) indices.push_back(base + index);
        if (draw.indexCount > 0) mDraws.push_back(draw);
    }
    // Animated instances rewrite their vertices every frame (updateDynamic).
    mVertices = gl::createBuffer(vertices.size() * sizeof(SceneVertex), vertices.data(),
            mDynamicRanges.empty() ? 0 : GL_DYNAMIC_STORAGE_BIT, "scene/vertices");
    mIndices = gl::createBuffer(indices.size() * sizeof(std::uint32_t), indices.data(), 0,
            "scene/indices");

    mVertexArray = gl::createVertexArray("scene/vertex_array");
    const GLuint vao = mVertexArray.id();
    glVertexArrayVertexBuffer(vao, 0, mVertices.id(), 0, sizeof(SceneVertex));
    glVertexArrayElementBuffer(vao, mIndices.id());
    auto attribute = [vao](GLuint location, int components, std::size_t offset) {
        glEnableVertexArrayAttrib(vao, location);
        glVertexArrayAttribFormat(vao, location, components, GL_FLOAT, GL_FALSE, GLuint(offset));
        glVertexArrayAttribBinding(vao, location, 0);
    };
    attribute(ATTR_POSITION, 3, offsetof(SceneVertex, position));
    attribute(ATTR_NORMAL, 3, offsetof(SceneVertex, normal));
    attribute(ATTR_TEXCOORD0, 2, offsetof(SceneVertex, texcoord0));
    attribute(ATTR_TEXCOORD1, 2, offsetof(SceneVertex, texcoord1));
    attribute(ATTR_COLOR, 4, offsetof(SceneVertex, color));
}

int GpuScene::textureKinds() const {
    int kinds = 0;
    for (int texture : mBaseColorTexture) kinds |= texture >= 0 ? MATERIAL_TEXTURES_BASE_COLOR : 0;
    for (int texture : mEmissiveTexture) kinds |= texture >= 0 ? MATERIAL_TEXTURES_EMISSIVE : 0;
    return kinds;
}

void GpuScene::uploadMaterials(const Scene& scene) {
    // One memory-report row for them all (the white fallback too), however many there are.
    const gl::MemoryGroup textures("scene/textures");
    for (const Texture& texture : scene.textures) {
        const int levels = gl::fullMipCount(std::max(texture.width, texture.height));
        gl::Texture gpu = gl::createTexture2D(texture.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8,
                {texture.width, texture.height}, levels, ("scene/texture/" + texture.name).c_str());
        glTextureSubImage2D(gpu.id(), 0, 0, 0, texture.width, texture.height, GL_RGBA,
                GL_UNSIGNED_BYTE, texture.rgba8.data());
        glGenerateTextureMipmap(gpu.id());
        glTextureParameteri(gpu.id(), GL_TEXTURE_WRAP_S, texture.wrapS);
        glTextureParameteri(gpu.id(), GL_TEXTURE_WRAP_T, texture.wrapT);
        glTextureParameteri(gpu.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(gpu.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        mTextures.push_back(std::move(gpu));
    }
    mWhite = gl::createTexture2D(GL_RGBA8, {1, 1}, 1, "scene/white");
    const std::uint8_t white[4] = {255, 255, 255, 255};
    glTextureSubImage2D(mWhite.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);

    std::vector<shader::GpuMaterial> table;
    for (const Material& m : scene.materials) {
        shader::GpuMaterial g{};
        g.baseColorFactor = m.baseColorFactor;
        g.emissiveAndCutoff = glm::vec4(m.emissiveFactor, m.alphaCutoff);
        g.flags = glm::ivec4(m.baseColorTexture >= 0,
                m.emissiveTexture >= 0 ? MATERIAL_EMISSIVE_TEXTURE : 0,
                m.alphaMode == AlphaMode::Mask ? ALPHA_MASK : ALPHA_OPAQUE,
                m.baseColorTexCoord);
        g.metallicRoughness = glm::vec4(m.metallicFactor, m.roughnessFactor, 0.0f, 0.0f);
        table.push_back(g);
        mBaseColorTexture.push_back(m.baseColorTexture);
        mEmissiveTexture.push_back(m.emissiveTexture);
    }
    shader::GpuMaterial fallback{};
    fallback.baseColorFactor = kDefaultBaseColor;
    fallback.emissiveAndCutoff = glm::vec4(0.0f, 0.0f, 0.0f, 0.5f);
    fallback.metallicRoughness = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
    table.push_back(fallback);
    mBaseColorTexture.push_back(-1);
    mEmissiveTexture.push_back(-1);
    mMaterialTable = std::move(table);
    mEmitsAsLight.assign(mMaterialTable.size(), false);
    for (const shader::GpuMaterial& m : mMaterialTable) {
        mMaxEmission = std::max({mMaxEmission, m.emissiveAndCutoff.r, m.emissiveAndCutoff.g,
                m.emissiveAndCutoff.b});
    }
}

void GpuScene::updateDynamic(const Scene& scene) {
    if (mDynamicRanges.empty()) return;
    std::vector<SceneVertex> vertices;
    for (const DynamicRange& range : mDynamicRanges) {
        vertices.clear();
        appendInstanceVertices(scene, scene.instances[range.instance], vertices);
        glNamedBufferSubData(mVertices.id(), GLintptr(range.firstVertex * sizeof(SceneVertex)),
                GLsizeiptr(vertices.size() * sizeof(SceneVertex)), vertices.data());
    }
    ++mGeometryVersion;
}

void GpuScene::setLights(const std::vector<Light>& lights) {
    const float exposure = preExposure(lights, mBounds, mMaxEmission);
    mEmitsAsLight.assign(mMaterialTable.size(), false);
    for (const Light& light : lights) {
        for (const EmitterTriangle& t : light.emitters) {
            if (t.material >= 0 && std::size_t(t.material) < mEmitsAsLight.size()) {
                mEmitsAsLight[std::size_t(t.material)] = true;
            }
        }
    }
    std::vector<shader::GpuMaterial> exposed = mMaterialTable;
    for (std::size_t i = 0; i < exposed.size(); ++i) {
        shader::GpuMaterial& m = exposed[i];
        m.emissiveAndCutoff = glm::vec4(glm::vec3(m.emissiveAndCutoff) * exposure, m.emissiveAndCutoff.w);
        if (mEmitsAsLight[i]) m.flags.y |= MATERIAL_EMITS_AS_LIGHT;
    }
    mMaterials = gl::createBuffer(exposed.size() * sizeof(shader::GpuMaterial), exposed.data(), 0,
            "scene/materials");
    mExposure = exposure;
    // 1/r^2 is cut off within 1e-4 of the scene's size of a light (lighting.glsl): 0.1 mm in a
    // 1 m box, and the same fraction of a 1 mm or a 10 km one.
    const glm::vec3 size = mBounds.empty() ? glm::vec3(1.0f) : mBounds.max - mBounds.min;
    const float minDistance = 1e-4f * std::max(glm::length(size), 1e-12f);
    const float minDistanceSquared = std::max(minDistance * minDistance, 1e-36f);
    std::vector<shader::GpuLight> table;
    std::vector<shader::GpuEmitter> emitters;
    mLightKinds = 0;
    for (const Light& light : lights) {
        shader::GpuLight g{};
        const int type = light.type == LightType::Point ? LIGHT_POINT
                         : light.type == LightType::Spot ? LIGHT_SPOT
                         : light.type == LightType::Area ? LIGHT_AREA
                         : light.type == LightType::Sky ? LIGHT_SKY
                                                        : LIGHT_DIRECTIONAL;
        mLightKinds |= 1 << type;
        g.positionAndType = glm::vec4(light.position, float(type));
        g.directionAndRange = glm::vec4(glm::normalize(light.direction), light.range);
        g.radiantIntensity = glm::vec4(light.color * light.intensity * exposure, 0.0f);
        g.spotCone = glm::vec4(std::cos(light.innerConeAngle), std::cos(light.outerConeAngle),
                minDistanceSquared, 0.0f);
        if (light.type == LightType::Area) {
            g.spotCone.x = float(emitters.size());
            g.spotCone.y = float(light.emitters.size());
            float radius = 0.0f;
            for (const EmitterTriangle& t : light.emitters) {
                for (const glm::vec3& p : {t.p0, t.p1, t.p2}) {
                    radius = std::max(radius, glm::length(p - light.position));
                }
            }
            g.spotCone.w = radius;
            for (const EmitterTriangle& t : light.emitters) {
                emitters.push_back({glm::vec4(t.p0, 0.0f), glm::vec4(t.p1, 0.0f), glm::vec4(t.p2, 0.0f),
                        glm::vec4(t.radiance * exposure, t.twoSided ? 1.0f : 0.0f)});
            }
        }
        table.push_back(g);
    }
    mLightCount = int(table.size());
    mLights = gl::createBuffer(std::max<std::size_t>(table.size(), 1) * sizeof(shader::GpuLight),
            table.empty() ? nullptr : table.data(), 0, "scene/lights");
    mEmitters = gl::createBuffer(std::max<std::size_t>(emitters.size(), 1) * sizeof(shader::GpuEmitter),
            emitters.empty() ? nullptr : emitters.data(), 0, "scene/emitters");
}

void GpuScene::bindLights() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_LIGHTS, mLights.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BIND_SSBO_EMITTERS, mEmitters.id());
}

void GpuScene::drawDepthPrepass(GLuint depthProgram) const {
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(depthProgram);
    drawAll(depthProgram, true);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
}

void GpuScene::drawAll(GLuint program, bool cullBackFaces, const gl::VertexArray* vertexArray,
        DrawSet set) const {
    glBindVertexArray(vertexArray ? vertexArray->id() : mVertexArray.id());
    glBindSampler(BIND_TEX_BASE_COLOR, 0);
    glBindSampler(BIND_TEX_EMISSIVE, 0);
    for (const Draw& draw : mDraws) {
        if ((set == DrawSet::Static && draw.dynamic) || (set == DrawSet::Dynamic && !draw.dynamic) ||
                (set == DrawSet::NotEmittingLight && mEmitsAsLight[std::size_t(draw.material)])) {
            continue;
        }
        if (cullBackFaces && !draw.doubleSided) glEnable(GL_CULL_FACE);
        else glDisable(GL_CULL_FACE);
        const int baseColor = mBaseColorTexture[std::size_t(draw.material)];
        const int emissive = mEmissiveTexture[std::size_t(draw.material)];
        glBindTextureUnit(BIND_TEX_BASE_COLOR,
                baseColor >= 0 ? mTextures[std::size_t(baseColor)].id() : mWhite.id());
        glBindTextureUnit(BIND_TEX_EMISSIVE,
                emissive >= 0 ? mTextures[std::size_t(emissive)].id() : mWhite.id());
        glProgramUniform1i(program, LOC_DRAW_MATERIAL, draw.material);
        glDrawElements(GL_TRIANGLES, GLsizei(draw.indexCount), GL_UNSIGNED_INT,
                reinterpret_cast<const void*>(std::size_t(draw.firstIndex) * sizeof(std::uint32_t)));
    }
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
}

} // namespace gi::scene
