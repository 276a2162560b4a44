// SceneBuilder's mesh primitives: attributes read and checked, strips and fans turned into
// triangle lists, missing or zero normals generated, and each primitive decoded once per
// winding (a mirroring node transform gets a copy wound the other way).
#include "scene/GltfSceneBuilder.h"

#include "scene/GltfMessages.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <sstream>

namespace gi::scene::gltf {
namespace {

std::string formatVector(const float* v, int n) {
    std::ostringstream s;
    s << "(";
    for (int i = 0; i < n; ++i) s << (i ? ", " : "") << v[i];
    s << ")";
    return s.str();
}

// Sum of the (unnormalized, so area-weighted) face normals around each vertex.
std::vector<glm::vec3> areaWeightedNormals(const Primitive& primitive) {
    std::vector<glm::dvec3> sums(primitive.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
        const std::uint32_t a = primitive.indices[t], b = primitive.indices[t + 1],
                            c = primitive.indices[t + 2];
        const glm::dvec3 pa(primitive.positions[a]), pb(primitive.positions[b]),
                pc(primitive.positions[c]);
        const glm::dvec3 face = glm::cross(pb - pa, pc - pa);
        sums[a] += face;
        sums[b] += face;
        sums[c] += face;
    }
    std::vector<glm::vec3> normals(sums.size());
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const double length = glm::length(sums[i]);
        normals[i] = length > 0.0 && std::isfinite(length) ? glm::vec3(sums[i] / length)
                                                           : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return normals;
}

} // namespace

// Scene primitive for glTF mesh primitive (mesh, primitive), wound counter-clockwise for
// a mirroring transform when `flipped`; -1 when the primitive is skipped.
bool SceneBuilder::primitiveFor(int mesh, int primitive, bool flipped, int& sceneIndex) {
    const auto key = std::make_tuple(mesh, primitive, flipped);
    auto found = mPrimitiveCache.find(key);
    if (found != mPrimitiveCache.end()) {
        sceneIndex = found->second;
        return true;
    }
    if (flipped) {
        int unflipped = -1;
        if (!primitiveFor(mesh, primitive, false, unflipped)) return false;
        if (unflipped >= 0) {
            Primitive copy = mScene.primitives[std::size_t(unflipped)];
            if (!reserveGeometry(primitiveName(mesh, primitive), copy.positions.size(),
                        copy.indices.size())) {
                return false;
            }
            for (std::size_t t = 0; t + 2 < copy.indices.size(); t += 3) {
                std::swap(copy.indices[t + 1], copy.indices[t + 2]);
            }
            sceneIndex = int(mScene.primitives.size());
            mScene.primitives.push_back(std::move(copy));
        }
    } else {
        Primitive decoded;
        bool skipped = false;
        if (!decodePrimitive(mesh, primitive, decoded, skipped)) return false;
        if (!skipped) {
            sceneIndex = int(mScene.primitives.size());
            mScene.primitives.push_back(std::move(decoded));
        }
    }
    mPrimitiveCache[key] = sceneIndex;
    return true;
}

bool SceneBuilder::reserveGeometry(const std::string& element, std::uint64_t vertices,
        std::uint64_t indices) {
    if (mVertexTotal + vertices > mLimits.maxVertices ||
            mIndexTotal + indices > mLimits.maxIndices) {
        return fail(element, "the scene exceeds the loader's limit of " +
                                     std::to_string(mLimits.maxVertices) + " vertices or " +
                                     std::to_string(mLimits.maxIndices) + " indices");
    }
    mVertexTotal += vertices;
    mIndexTotal += indices;
    return true;
}

// Reads attribute `name` of a primitive as `count` elements of 2..4 floats; false on error.
// `present` is false (and no error) when the primitive lacks the attribute.
bool SceneBuilder::readAttribute(const tinygltf::Primitive& source, const std::string& element,
        const char* name, std::initializer_list<int> allowedComponents, std::size_t count,
        AccessorFloats& out, bool& present) {
    present = false;
    auto it = source.attributes.find(name);
    if (it == source.attributes.end()) return true;
    const int accessor = it->second;
    if (accessor < 0 || std::size_t(accessor) >= mModel.accessors.size()) {
        return fail(element, doesNotExist((std::string("attribute ") + name).c_str(),
                                     accessor, mModel.accessors.size(), "accessors"));
    }
    const int type = mModel.accessors[std::size_t(accessor)].type;
    const int components = accessorComponentCount(type);
    if (std::find(allowedComponents.begin(), allowedComponents.end(), components) ==
                    allowedComponents.end() ||
            type == TINYGLTF_TYPE_MAT2) {
        return fail(element, std::string(name) + " (" + indexed("accessors", accessor) +
                                     ") has type " + accessorTypeName(type));
    }
    std::string error;
    if (!readAccessorFloats(mModel, accessor, mLimits.maxAccessorCount, out, error)) {
        return failWith(error);
    }
    if (count != std::size_t(-1) && out.count != count) {
        return fail(element, std::string(name) + " has " + std::to_string(out.count) +
                                     " elements but POSITION has " + std::to_string(count));
    }
    for (std::size_t i = 0; i < out.values.size(); ++i) {
        if (!std::isfinite(out.values[i])) {
            const std::size_t e = i / std::size_t(out.components);
            return fail(indexed("accessors", accessor),
                    "element " + std::to_string(e) + " " +
                            formatVector(&out.values[e * std::size_t(out.components)],
                                    out.components) +
                            " is not finite (" + name + " of " + element + ")");
        }
    }
    present = true;
    return true;
}

bool SceneBuilder::decodePrimitive(int mesh, int primitiveIndex, Primitive& out, bool& skipped) {
    const tinygltf::Primitive& source =
            mModel.meshes[std::size_t(mesh)].primitives[std::size_t(primitiveIndex)];
    const std::string element = primitiveName(mesh, primitiveIndex);
    skipped = false;
    const int mode = source.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
        static constexpr const char* kModes[] = {"POINTS", "LINES", "LINE_LOOP",
                "LINE_STRIP"};
        warn(element, std::string("mode ") + kModes[mode] + " is not triangles; skipped");
        skipped = true;
        return true;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        return fail(element, "mode " + std::to_string(mode) + " is not a glTF primitive mode");
    }
    if (source.material < -1 || source.material >= int(mModel.materials.size())) {
        return fail(element, doesNotExist("material", source.material,
                                     mModel.materials.size(), "materials"));
    }
    out.material = source.material;
    if (source.attributes.find("POSITION") == source.attributes.end()) {
        return fail(element, "has no POSITION attribute");
    }

    std::vector<std::size_t> degenerateNormals;
    if (!readVertices(source, element, out, degenerateNormals)) return false;
    const std::size_t vertexCount = out.positions.size();
    std::vector<std::uint32_t> corners;
    if (!readCorners(source, element, vertexCount, corners)) return false;
    if (!toTriangleList(element, mode, corners, out.indices)) return false;
    if (out.indices.empty()) {
        warn(element, "has no triangles; skipped");
        skipped = true;
        return true;
    }
    if (!reserveGeometry(element, vertexCount, out.indices.size())) return false;

    completeAttributes(element, degenerateNormals, out);
    for (const glm::vec3& p : out.positions) out.localBounds.extend(p);
    return true;
}

// POSITION, NORMAL (unit; the indices of zero or non-finite ones in `degenerateNormals`),
// TEXCOORD_0/1 and COLOR_0 (alpha 1 when it has three components).
bool SceneBuilder::readVertices(const tinygltf::Primitive& source, const std::string& element,
        Primitive& out, std::vector<std::size_t>& degenerateNormals) {
    AccessorFloats data;
    bool present = false;
    if (!readAttribute(source, element, "POSITION", {3}, std::size_t(-1), data, present)) {
        return false;
    }
    const std::size_t vertexCount = data.count;
    out.positions.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) {
        out.positions[i] = glm::make_vec3(&data.values[3 * i]);
    }

    if (!readAttribute(source, element, "NORMAL", {3}, vertexCount, data, present)) {
        return false;
    }
    if (present) {
        out.normals.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const glm::vec3 n = glm::make_vec3(&data.values[3 * i]);
            const float length = glm::length(n);
            if (length > 1e-20f && std::isfinite(length)) {
                out.normals[i] = n / length;
            } else {
                degenerateNormals.push_back(i);
            }
        }
    }
    for (int set = 0; set < 2; ++set) {
        const std::string name = "TEXCOORD_" + std::to_string(set);
        if (!readAttribute(source, element, name.c_str(), {2}, vertexCount, data, present)) {
            return false;
        }
        if (present) {
            auto& texcoords = set == 0 ? out.texcoords0 : out.texcoords1;
            texcoords.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i) {
                texcoords[i] = glm::make_vec2(&data.values[2 * i]);
            }
        }
    }
    if (!readAttribute(source, element, "COLOR_0", {3, 4}, vertexCount, data, present)) {
        return false;
    }
    if (present) {
        out.colors.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) {
            const float* c = &data.values[i * std::size_t(data.components)];
            out.colors[i] = glm::vec4(c[0], c[1], c[2], data.components == 4 ? c[3] : 1.0f);
        }
    }
    return true;
}

// The primitive's vertex indices, checked against `vertexCount`; 0, 1, 2, ... without indices.
bool SceneBuilder::readCorners(const tinygltf::Primitive& source, const std::string& element,
        std::size_t vertexCount, std::vector<std::uint32_t>& corners) {
    if (source.indices >= 0) {
        std::string error;
        if (!readAccessorIndices(mModel, source.indices, mLimits.maxAccessorCount, corners,
                    error)) {
            return failWith(error);
        }
        for (std::size_t i = 0; i < corners.size(); ++i) {
            if (corners[i] >= vertexCount) {
                return fail(indexed("accessors", source.indices),
                        "index " + std::to_string(corners[i]) + " at element " +
                                std::to_string(i) + " is out of range (POSITION of " +
                                element + " has " + std::to_string(vertexCount) +
                                " vertices)");
            }
        }
    } else {
        if (vertexCount > std::size_t(UINT32_MAX)) {
            return fail(element, "has more vertices than 32-bit indices can address");
        }
        corners.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i) corners[i] = std::uint32_t(i);
    }
    return true;
}

// Generated normals where the file has none or zero ones, and (0, 0) texture coordinates where
// the material samples a set the primitive lacks.
void SceneBuilder::completeAttributes(const std::string& element,
        const std::vector<std::size_t>& degenerateNormals, Primitive& out) {
    const std::size_t vertexCount = out.positions.size();
    if (out.normals.empty() || !degenerateNormals.empty()) {
        const std::vector<glm::vec3> generated = areaWeightedNormals(out);
        if (out.normals.empty()) {
            out.normals = generated;
        } else {
            for (std::size_t i : degenerateNormals) out.normals[i] = generated[i];
            warn(element, std::to_string(degenerateNormals.size()) +
                                  " zero-length NORMAL values replaced by generated normals");
        }
    }
    if (out.material >= 0) {
        const Material& material = mScene.materials[std::size_t(out.material)];
        auto requireTexcoords = [&](int texture, int set) {
            if (texture < 0) return;
            auto& texcoords = set == 0 ? out.texcoords0 : out.texcoords1;
            if (!texcoords.empty()) return;
            warn(element, "its material samples a texture with TEXCOORD_" +
                                  std::to_string(set) +
                                  ", which the primitive lacks; using (0, 0)");
            texcoords.assign(vertexCount, glm::vec2(0.0f));
        };
        requireTexcoords(material.baseColorTexture, material.baseColorTexCoord);
        requireTexcoords(material.emissiveTexture, material.emissiveTexCoord);
    }
}

// glTF 2.0 section 3.7.2.1: strips and fans to lists, keeping the first triangle's winding.
bool SceneBuilder::toTriangleList(const std::string& element, int mode,
        const std::vector<std::uint32_t>& corners, std::vector<std::uint32_t>& out) {
    const std::size_t n = corners.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0) {
            warn(element, std::to_string(n) + " triangle corners is not a multiple of 3; "
                                              "the last " +
                                  std::to_string(n % 3) + " are dropped");
        }
        out.assign(corners.begin(), corners.begin() + std::ptrdiff_t(n - n % 3));
        return true;
    }
    const std::size_t triangles = n >= 3 ? n - 2 : 0;
    out.clear();
    out.reserve(triangles * 3);
    for (std::size_t i = 0; i < triangles; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            const std::size_t odd = i % 2;
            out.insert(out.end(), {corners[i], corners[i + 1 + odd], corners[i + 2 - odd]});
        } else {
            out.insert(out.end(), {corners[i + 1], corners[i + 2], corners[0]});
        }
    }
    return true;
}

} // namespace gi::scene::gltf
