// Writes small glTF 2.0 files from test code, so each loader test states its whole input next
// to its assertions: GltfBuilder collects binary data in one buffer and the JSON document in
// nlohmann::json, then writes .gltf (external .bin or base64-embedded buffer) or .glb.
// Also encodes tiny PNG/JPEG images (stb_image_write, compiled privately) for texture tests.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gi::test {

enum class BufferStorage {
    External, // buffers[0].uri names "<name>.bin" next to the .gltf
    Embedded, // buffers[0].uri is a base64 data URI
};

// glTF componentType values.
constexpr int kGltfByte = 5120;
constexpr int kGltfUnsignedByte = 5121;
constexpr int kGltfShort = 5122;
constexpr int kGltfUnsignedShort = 5123;
constexpr int kGltfUnsignedInt = 5125;
constexpr int kGltfFloat = 5126;

class GltfBuilder {
public:
    GltfBuilder();

    // The document; "buffers" is filled in when the file is written.
    nlohmann::json& doc() { return mDoc; }
    std::vector<std::uint8_t>& binary() { return mBinary; }

    // Appends bytes to buffer 0 (at a 4-byte aligned offset) and a bufferView over them.
    int addBufferView(const void* bytes, std::size_t size, std::size_t byteStride = 0);
    template <class T> int addBufferView(const std::vector<T>& values, std::size_t stride = 0) {
        return addBufferView(values.data(), values.size() * sizeof(T), stride);
    }
    int addAccessor(int bufferView, int componentType, std::size_t count, const std::string& type,
            std::size_t byteOffset = 0, bool normalized = false);
    // Tightly packed float data in a new bufferView; POSITION accessors get min/max.
    int addVec3(const std::vector<glm::vec3>& values, bool withMinMax = true);
    int addVec2(const std::vector<glm::vec2>& values);
    int addVec4(const std::vector<glm::vec4>& values);
    // Index data of the given unsigned component type in a new bufferView.
    int addIndices(const std::vector<std::uint32_t>& indices,
            int componentType = kGltfUnsignedShort);

    int addMesh(const nlohmann::json& primitives);
    // One primitive: POSITION (and indices when not empty) plus any extra attributes.
    int addTriangleMesh(const std::vector<glm::vec3>& positions,
            const std::vector<std::uint32_t>& indices, nlohmann::json extraAttributes = {},
            int material = -1);
    int addNode(const nlohmann::json& node);
    int addScene(const std::vector<int>& roots);
    int append(const char* array, const nlohmann::json& value); // returns the new index

    // Writes <dir>/<name>.gltf (and <name>.bin when External); returns the .gltf path.
    std::string writeGltf(const std::filesystem::path& dir, const std::string& name,
            BufferStorage storage = BufferStorage::External) const;
    // Writes <dir>/<name>.glb; returns its path.
    std::string writeGlb(const std::filesystem::path& dir, const std::string& name) const;
    std::vector<std::uint8_t> glb() const;
    std::string gltfText(BufferStorage storage, const std::string& binUri) const;

private:
    nlohmann::json documentWithBuffer(const nlohmann::json& buffer) const;

    nlohmann::json mDoc;
    std::vector<std::uint8_t> mBinary;
};

// A fresh empty directory <build>/test-output/gltf/<name>.
std::filesystem::path freshGltfTestDir(const std::string& name);
void writeBytes(const std::filesystem::path& path, const void* data, std::size_t size);
void writeText(const std::filesystem::path& path, const std::string& text);
std::vector<std::uint8_t> readBytes(const std::filesystem::path& path);
std::string base64Encode(const std::vector<std::uint8_t>& bytes);

// Encodes width x height pixels of `channels` (1..4) interleaved 8-bit channels.
std::vector<std::uint8_t> encodePng(int width, int height, int channels,
        const std::vector<std::uint8_t>& pixels);
std::vector<std::uint8_t> encodeJpeg(int width, int height, int channels,
        const std::vector<std::uint8_t>& pixels, int quality = 95);

} // namespace gi::test
