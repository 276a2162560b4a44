#include "SceneVariants.h"

#include "GltfTestFiles.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace gi::test {
namespace {

using nlohmann::json;

const std::string kCornellPath =
        std::string(VOXATLAS_DATA_DIR) + "/assets/cornell_box/cornell_box.gltf";

json readCornell() {
    std::ifstream in(kCornellPath);
    if (!in) throw std::runtime_error("cannot read " + kCornellPath);
    return json::parse(in);
}

std::string writeScene(const std::string& dir, const std::string& name, const json& doc) {
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/" + name + ".gltf";
    writeText(path, doc.dump(1));
    return path;
}

// Puts every root node of scene 0 under one new root node carrying `transform`.
void wrapRoots(json& doc, const json& transform) {
    json root = transform;
    root["name"] = "variant_root";
    root["children"] = doc["scenes"][0]["nodes"];
    doc["nodes"].push_back(root);
    doc["scenes"][0]["nodes"] = json::array({doc["nodes"].size() - 1});
}

json& cornellLight(json& doc) {
    return doc["extensions"]["KHR_lights_punctual"]["lights"][0];
}

// Appends a buffer (as a data URI), a view and an accessor; returns the accessor index.
int addAccessor(json& doc, const std::vector<std::uint8_t>& bytes, int componentType,
        const std::string& type, int count, const json& extra = json::object()) {
    json buffer = {{"byteLength", bytes.size()},
            {"uri", "data:application/octet-stream;base64," + base64Encode(bytes)}};
    doc["buffers"].push_back(buffer);
    doc["bufferViews"].push_back(
            {{"buffer", doc["buffers"].size() - 1}, {"byteLength", bytes.size()}});
    json accessor = {{"bufferView", doc["bufferViews"].size() - 1},
            {"componentType", componentType}, {"type", type}, {"count", count}};
    accessor.update(extra);
    doc["accessors"].push_back(accessor);
    return int(doc["accessors"].size()) - 1;
}

template <class T>
std::vector<std::uint8_t> bytesOf(const std::vector<T>& values) {
    std::vector<std::uint8_t> bytes(values.size() * sizeof(T));
    std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

constexpr int kFloat = 5126, kUnsignedShort = 5123;

// A mesh node from positions (xyz triples), one up normal per vertex and 16-bit indices.
void addMeshNode(json& doc, const std::vector<float>& positions,
        const std::vector<std::uint16_t>& indices, int material) {
    const int count = int(positions.size() / 3);
    std::vector<float> lo = {positions[0], positions[1], positions[2]}, hi = lo;
    for (int i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) {
            lo[std::size_t(c)] = std::min(lo[std::size_t(c)], positions[std::size_t(3 * i + c)]);
            hi[std::size_t(c)] = std::max(hi[std::size_t(c)], positions[std::size_t(3 * i + c)]);
        }
    }
    std::vector<float> normals;
    for (int i = 0; i < count; ++i) normals.insert(normals.end(), {0.0f, 1.0f, 0.0f});
    const int position = addAccessor(doc, bytesOf(positions), kFloat, "VEC3", count,
            {{"min", lo}, {"max", hi}});
    const int normal = addAccessor(doc, bytesOf(normals), kFloat, "VEC3", count);
    const int index = addAccessor(doc, bytesOf(indices), kUnsignedShort, "SCALAR",
            int(indices.size()));
    json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
            {"indices", index}, {"mode", 4}};
    if (material >= 0) primitive["material"] = material;
    doc["meshes"].push_back({{"primitives", json::array({primitive})}});
    doc["nodes"].push_back({{"mesh", doc["meshes"].size() - 1}});
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
}

json emptyDocument() {
    return {{"asset", {{"version", "2.0"}, {"generator", "voxatlas SceneVariants"}}},
            {"scene", 0}, {"scenes", json::array({{{"nodes", json::array()}}})},
            {"nodes", json::array()}, {"meshes", json::array()}, {"buffers", json::array()},
            {"bufferViews", json::array()}, {"accessors", json::array()}};
}

} // namespace

double cornellLightIntensity() {
    json doc = readCornell();
    return cornellLight(doc)["intensity"].get<double>();
}

SceneVariant scaledCornell(const std::string& dir, double scale) {
    json doc = readCornell();
    wrapRoots(doc, {{"scale", {scale, scale, scale}}});
    cornellLight(doc)["intensity"] = cornellLight(doc)["intensity"].get<double>() * scale * scale;
    // The camera's clip planes are distances in metres: they scale with the scene.
    for (json& camera : doc["cameras"]) {
        json& perspective = camera["perspective"];
        for (const char* plane : {"znear", "zfar"}) {
            if (perspective.contains(plane)) perspective[plane] = perspective[plane].get<double>() * scale;
        }
    }
    return {writeScene(dir, "cornell_scaled", doc), 1.0, 0.0};
}

SceneVariant translatedCornell(const std::string& dir, double offset) {
    json doc = readCornell();
    wrapRoots(doc, {{"translation", {offset, 0.0, 0.0}}});
    return {writeScene(dir, "cornell_translated", doc), 1.0, 0.0};
}

SceneVariant cornellWithLightIntensity(const std::string& dir, double candela) {
    json doc = readCornell();
    const double original = cornellLight(doc)["intensity"].get<double>();
    cornellLight(doc)["intensity"] = candela;
    return {writeScene(dir, "cornell_intensity", doc), candela / original, 0.0};
}

SceneVariant cornellWithLightGrid(const std::string& dir, int count) {
    json doc = readCornell();
    json light = cornellLight(doc);
    light["intensity"] = light["intensity"].get<double>() / count;
    json& lights = doc["extensions"]["KHR_lights_punctual"]["lights"];
    lights = json::array();
    // The box spans x 0..0.556, z -0.559..0 (metres), ceiling at y 0.5488.
    int side = 1;
    while (side * side < count) ++side;
    for (int i = 0; i < count; ++i) {
        lights.push_back(light);
        const double x = 0.05 + 0.456 * ((i % side) + 0.5) / side;
        const double z = -0.05 - 0.459 * ((i / side) + 0.5) / side;
        doc["nodes"].push_back({{"name", "grid_light_" + std::to_string(i)},
                {"translation", {x, 0.45, z}},
                {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}});
        doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
    }
    // Remove the original light node: it pointed at light 0, now one of the grid's.
    for (json& node : doc["nodes"]) {
        if (node.value("name", "") == "ceiling_light") node.erase("extensions");
    }
    // A light under the ceiling sees a different share of the box than the original one
    // 1 cm below it, so the image is comparable only roughly (the test's band is wide).
    return {writeScene(dir, "cornell_lights_" + std::to_string(count), doc), 1.0, 0.0};
}

SceneVariant cornellWithDegenerateTriangles(const std::string& dir) {
    json doc = readCornell();
    const std::vector<float> positions = {
            0.1f, 0.2f, -0.2f,  0.2f, 0.2f, -0.2f,  0.3f, 0.2f, -0.2f,   // collinear
            0.1f, 0.3f, -0.3f,  0.1f, 0.3f, -0.3f,                        // duplicate vertices
            0.2f, 0.3f, -0.3f,  0.2f, 0.3f + 1e-9f, -0.3f, 0.4f, 0.3f, -0.3f,   // needle
    };
    const std::vector<std::uint16_t> indices = {
            0, 1, 2,   // collinear: zero area
            3, 4, 5,   // two vertices at the same position
            6, 6, 6,   // one vertex three times
            0, 0, 1,   // a repeated index
            5, 6, 7,   // a needle: 1e-9 m wide
            3, 3, 4,   // repeated index on duplicates
    };
    addMeshNode(doc, positions, indices, 0);
    return {writeScene(dir, "cornell_degenerate", doc), 1.0, 0.0};
}

SceneVariant singleTriangle(const std::string& dir) {
    json doc = emptyDocument();
    doc["materials"] = json::array({{{"pbrMetallicRoughness",
            {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}}}}});
    // Counter-clockwise seen from above, so its front face (+Y) looks at the light.
    addMeshNode(doc, {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, -1.0f}, {0, 1, 2}, 0);
    doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    doc["extensions"] = {{"KHR_lights_punctual",
            {{"lights", json::array({{{"type", "point"}, {"intensity", 1.0}}})}}}};
    doc["nodes"].push_back({{"name", "light"}, {"translation", {0.0, 0.5, 0.0}},
            {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["scenes"][0]["nodes"].push_back(doc["nodes"].size() - 1);
    const double rhoOverPi = 0.8 / 3.14159265358979;
    // The triangle fills a good part of the default camera's view: its mean radiance is a
    // sizeable fraction of the ceiling, far above 1e-3 of it.
    const double ceiling = rhoOverPi * 1.0 / (0.5 * 0.5);
    return {writeScene(dir, "single_triangle", doc), 0.0, ceiling, 1e-3 * ceiling};
}

SceneVariant emptyScene(const std::string& dir) {
    return {writeScene(dir, "empty", emptyDocument()), 0.0, 1e-9};
}

} // namespace gi::test
