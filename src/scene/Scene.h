// The in-memory scene every pass and the reference renderer read: triangle meshes with their
// node transforms, Lambertian/Blinn-Phong materials, textures, punctual lights and cameras,
// in glTF units (metres; light colour x intensity per KHR_lights_punctual, see DESIGN.md).
// The loader fills it and validates everything passes rely on, so passes never re-check.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace gi::scene {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& other) {
        if (!other.empty()) {
            extend(other.min);
            extend(other.max);
        }
    }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return empty() ? glm::vec3(0.0f) : max - min; }
    // How far rays start off a surface (shadow rays, the VPLs' rays through the BVH): 1e-4 of
    // the scene's diagonal, as far in any scene.
    float rayOffset() const { return 1e-4f * std::max(glm::length(size()), 1e-12f); }
};

// Decoded texture pixels, always RGBA8. Colour textures are stored as authored (sRGB
// encoded); the GPU decodes them through an SRGB8_ALPHA8 format, the CPU with srgbToLinear.
struct Texture {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba8;  // width * height * 4 bytes, rows top to bottom
    bool srgb = true;                 // base colour and emissive textures are sRGB
    int wrapS = 10497, wrapT = 10497; // GL wrap enums from the glTF sampler (REPEAT default)
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};     // linear RGBA
    int baseColorTexture = -1;           // index into Scene::textures, or -1
    int baseColorTexCoord = 0;           // which TEXCOORD_n the texture uses (0 or 1)
    glm::vec3 emissiveFactor{0.0f};      // linear radiance scale (glTF emissive), already
                                         // multiplied by KHR_materials_emissive_strength
    int emissiveTexture = -1;
    int emissiveTexCoord = 0;            // which TEXCOORD_n the emissive texture uses (0 or 1)
    // glTF metallic-roughness, used only by the glossy material model (material.model=gltf);
    // the Lambertian model ignores them. A primitive without a material is a diffuse white
    // (metallic 0), not glTF's default material (metallic 1).
    float metallicFactor = 0.0f;         // [0, 1]
    float roughnessFactor = 1.0f;        // perceptual roughness [0, 1]; GGX alpha = its square
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;            // MASK: texels with alpha below this are cut out
    bool doubleSided = false;
};

// One glTF primitive in its mesh's local space, converted to an indexed triangle list.
struct Primitive {
    std::vector<glm::vec3> positions;    // metres, local space
    std::vector<glm::vec3> normals;      // unit length; generated when the file has none
    std::vector<glm::vec2> texcoords0;   // empty when absent, unless the material samples a
    std::vector<glm::vec2> texcoords1;   // texture through it (then zero-filled, with a warning)
    std::vector<glm::vec4> colors;       // COLOR_0 as linear RGBA; empty when absent
    std::vector<std::uint32_t> indices;  // 3 per triangle, each < positions.size(); front
                                         // faces counter-clockwise in the world space of every
                                         // instance that uses this primitive (see Instance)
    int material = -1;                   // index into Scene::materials, or -1 (default white)
    Aabb localBounds;
};

// A primitive placed in the world by a node.
// Mirroring transforms (det(worldFromLocal) < 0, e.g. one negative scale) turn counter-clockwise
// triangles clockwise. The loader handles this once: such an instance points at its own copy of
// the primitive whose triangles have two corners swapped, so every triangle of every instance is
// counter-clockwise in world space. flipWinding only records that this happened; passes must
// NOT swap corners again (normals are fine: transform them with the inverse transpose).
struct Instance {
    int primitive = 0;                   // index into Scene::primitives
    int node = -1;                       // glTF node index that placed it
    glm::mat4 worldFromLocal{1.0f};
    bool flipWinding = false;            // det(worldFromLocal) < 0; indices already reversed
    bool dynamic = false;                // its node or an ancestor is animated (scene/Animation.h)
};

// A glTF node's place in the hierarchy and its rest transform, kept so animations can move it.
struct SceneNode {
    int parent = -1;                     // glTF node index, -1 for a root
    glm::dvec3 translation{0.0};         // rest pose (TRS nodes)
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
    glm::dmat4 matrix{1.0};              // the rest local transform (TRS or the node's matrix)
    bool hasMatrix = false;              // given as a matrix: glTF forbids animating it
};

enum class AnimationPath { Translation, Rotation, Scale };
enum class AnimationInterpolation { Step, Linear, CubicSpline };

// One animated property of one node (glTF 2.0 section 3.11). values holds one vec4 per key
// (xyz, or a quaternion as x, y, z, w); for cubic splines three per key: in-tangent, value,
// out-tangent.
struct AnimationChannel {
    int node = -1;
    AnimationPath path = AnimationPath::Translation;
    AnimationInterpolation interpolation = AnimationInterpolation::Linear;
    std::vector<float> times;            // seconds, strictly increasing
    std::vector<glm::vec4> values;
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
    float duration = 0.0f;               // the last key time over all channels (s)
};

enum class LightType { Point, Spot, Directional, Area, Sky };

// One triangle of an area light, in world space. Emissive surfaces become area lights
// (scene/EmissionLights.h); their triangles keep where they came from so the path tracer can
// weigh a bounce ray that hits one against sampling the light (multiple importance sampling).
struct EmitterTriangle {
    glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};   // counter-clockwise seen from the front side
    glm::vec3 radiance{0.0f};            // W/(m^2 sr) per channel, uniform over the triangle:
                                         // emissiveFactor x the emissive texture's mean over it
    bool twoSided = false;               // emits from the back side too (doubleSided material)
    int instance = -1;                   // into Scene::instances, -1 for a command-line light
    int triangle = -1;                   // index of the triangle in the instance's primitive
    int material = -1;                   // into Scene::materials, -1 for a command-line light
    glm::vec3 normal() const;            // unit, front side (zero for a degenerate triangle)
    float area() const;                  // m^2
    bool operator==(const EmitterTriangle&) const = default;
};

struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};            // world space, metres (point, spot)
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // world space unit vector the light travels along
    glm::vec3 color{1.0f};               // linear RGB
    float intensity = 1.0f;              // W/sr-like radiant intensity (point, spot);
                                         // irradiance (directional); colour x intensity
    float range = 0.0f;                  // 0 = infinite; never attenuates (DESIGN.md)
    float innerConeAngle = 0.0f;         // radians (spot)
    float outerConeAngle = 0.7853982f;   // radians (spot)
    // Area: the emitting triangles. `position` is their area-weighted centre (where the
    // shadow map looks from), `color` x `intensity` is unused (1): the radiance is per
    // triangle. Sky: constant radiance colour x intensity (W/(m^2 sr)) from every direction
    // no geometry blocks; an unoccluded plane receives E = pi L (DESIGN.md).
    std::vector<EmitterTriangle> emitters;
    bool isDefault = false;              // added because the scene had no lights
    bool operator==(const Light&) const = default;
};

// How strong a light is, for choices that rank lights or set a scale: the largest channel of
// colour x intensity (W/sr for point and spot lights, W/m^2 for directional ones); for an
// area light its on-axis intensity, the sum of L x area over its triangles (W/sr); for the sky
// the irradiance it gives an open plane, pi L (W/m^2). Directional lights and the sky light
// everything alike (isDistant); the others fall off with distance.
double lightStrength(const Light& light);
// The radiance of all sky lights together (colour x intensity summed), zero without a sky.
glm::vec3 skyRadiance(const std::vector<Light>& lights);
inline bool isDistant(LightType type) { return type == LightType::Directional || type == LightType::Sky; }

struct Camera {
    std::string name;
    glm::mat4 worldFromCamera{1.0f};     // camera looks down its local -Z, +Y up
    float yfov = 0.8f;                   // vertical field of view, radians
    float znear = 0.01f;
    float zfar = 0.0f;                   // 0 = derived from the scene bounds
    bool isDefault = false;              // added because the scene had no camera
};

struct Scene {
    std::string sourcePath;
    std::vector<Primitive> primitives;
    std::vector<Instance> instances;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    Aabb bounds;                         // world-space bounds of all instances (in every
                                         // pose, for animated scenes)
    std::vector<SceneNode> nodes;        // indexed like the file's nodes
    std::vector<Animation> animations;   // all played together, looping
    glm::vec3 origin{0.0f};              // the file's point at world (0,0,0): non-zero when
                                         // a far-away scene was recentred (scene/Recentre.h)

    std::size_t triangleCount() const;   // over all instances
    std::size_t vertexCount() const;     // over all instances
};

} // namespace gi::scene
