#include "GltfTestFiles.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace gi::test {
namespace {

void appendToVector(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

void appendLe32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(value >> (8 * i)));
}

} // namespace

GltfBuilder::GltfBuilder() {
    mDoc["asset"] = {{"version", "2.0"}, {"generator", "voxatlas GltfTestFiles"}};
}

int GltfBuilder::append(const char* array, const nlohmann::json& value) {
    nlohmann::json& list = mDoc[array];
    if (!list.is_array()) list = nlohmann::json::array();
    list.push_back(value);
    return int(list.size()) - 1;
}

int GltfBuilder::addBufferView(const void* bytes, std::size_t size, std::size_t byteStride) {
    while (mBinary.size() % 4 != 0) mBinary.push_back(0);
    const std::size_t offset = mBinary.size();
    const auto* data = static_cast<const std::uint8_t*>(bytes);
    mBinary.insert(mBinary.end(), data, data + size);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
    if (byteStride != 0) view["byteStride"] = byteStride;
    return append("bufferViews", view);
}

int GltfBuilder::addAccessor(int bufferView, int componentType, std::size_t count,
        const std::string& type, std::size_t byteOffset, bool normalized) {
    nlohmann::json accessor = {{"componentType", componentType}, {"count", count},
            {"type", type}};
    if (bufferView >= 0) accessor["bufferView"] = bufferView;
    if (byteOffset != 0) accessor["byteOffset"] = byteOffset;
    if (normalized) accessor["normalized"] = true;
    return append("accessors", accessor);
}

int GltfBuilder::addVec3(const std::vector<glm::vec3>& values, bool withMinMax) {
    const int view = addBufferView(values);
    const int accessor = addAccessor(view, kGltfFloat, values.size(), "VEC3");
    if (withMinMax && !values.empty()) {
        glm::vec3 lo = values[0], hi = values[0];
        for (const glm::vec3& v : values) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        mDoc["accessors"][std::size_t(accessor)]["min"] = {lo.x, lo.y, lo.z};
        mDoc["accessors"][std::size_t(accessor)]["max"] = {hi.x, hi.y, hi.z};
    }
    return accessor;
}

int GltfBuilder::addVec2(const std::vector<glm::vec2>& values) {
    return addAccessor(addBufferView(values), kGltfFloat, values.size(), "VEC2");
}

int GltfBuilder::addVec4(const std::vector<glm::vec4>& values) {
    return addAccessor(addBufferView(values), kGltfFloat, values.size(), "VEC4");
}

int GltfBuilder::addIndices(const std::vector<std::uint32_t>& indices, int componentType) {
    std::vector<std::uint8_t> bytes;
    for (std::uint32_t index : indices) {
        if (componentType == kGltfUnsignedByte) {
            bytes.push_back(std::uint8_t(index));
        } else if (componentType == kGltfUnsignedShort) {
            bytes.push_back(std::uint8_t(index));
            bytes.push_back(std::uint8_t(index >> 8));
        } else {
            appendLe32(bytes, index);
        }
    }
    return addAccessor(addBufferView(bytes), componentType, indices.size(), "SCALAR");
}

int GltfBuilder::addMesh(const nlohmann::json& primitives) {
    return append("meshes", {{"primitives", primitives}});
}

int GltfBuilder::addTriangleMesh(const std::vector<glm::vec3>& positions,
        const std::vector<std::uint32_t>& indices, nlohmann::json extraAttributes, int material) {
    nlohmann::json attributes = extraAttributes.is_object() ? extraAttributes
                                                            : nlohmann::json::object();
    attributes["POSITION"] = addVec3(positions);
    nlohmann::json primitive = {{"attributes", attributes}};
    if (!indices.empty()) primitive["indices"] = addIndices(indices);
    if (material >= 0) primitive["material"] = material;
    return addMesh(nlohmann::json::array({primitive}));
}

int GltfBuilder::addNode(const nlohmann::json& node) { return append("nodes", node); }

int GltfBuilder::addScene(const std::vector<int>& roots) {
    return append("scenes", {{"nodes", roots}});
}

nlohmann::json GltfBuilder::documentWithBuffer(const nlohmann::json& buffer) const {
    nlohmann::json doc = mDoc;
    if (!mBinary.empty() && !doc.contains("buffers")) {
        doc["buffers"] = nlohmann::json::array({buffer});
    }
    return doc;
}

std::string GltfBuilder::gltfText(BufferStorage storage, const std::string& binUri) const {
    nlohmann::json buffer = {{"byteLength", mBinary.size()}};
    buffer["uri"] = storage == BufferStorage::External
                            ? binUri
                            : "data:application/octet-stream;base64," + base64Encode(mBinary);
    return documentWithBuffer(buffer).dump(1);
}

std::string GltfBuilder::writeGltf(const std::filesystem::path& dir, const std::string& name,
        BufferStorage storage) const {
    const std::filesystem::path path = dir / (name + ".gltf");
    if (storage == BufferStorage::External && !mBinary.empty()) {
        writeBytes(dir / (name + ".bin"), mBinary.data(), mBinary.size());
    }
    writeText(path, gltfText(storage, name + ".bin"));
    return path.string();
}

std::vector<std::uint8_t> GltfBuilder::glb() const {
    std::string json = documentWithBuffer({{"byteLength", mBinary.size()}}).dump();
    while (json.size() % 4 != 0) json.push_back(' ');
    std::vector<std::uint8_t> bin = mBinary;
    while (bin.size() % 4 != 0) bin.push_back(0);
    std::vector<std::uint8_t> out;
    const std::size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
    out.insert(out.end(), {'g', 'l', 'T', 'F'});
    appendLe32(out, 2);
    appendLe32(out, std::uint32_t(total));
    appendLe32(out, std::uint32_t(json.size()));
    appendLe32(out, 0x4E4F534Au);
    out.insert(out.end(), json.begin(), json.end());
    if (!bin.empty()) {
        appendLe32(out, std::uint32_t(bin.size()));
        appendLe32(out, 0x004E4942u);
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

std::string GltfBuilder::writeGlb(const std::filesystem::path& dir, const std::string& name) const {
    const std::filesystem::path path = dir / (name + ".glb");
    const std::vector<std::uint8_t> bytes = glb();
    writeBytes(path, bytes.data(), bytes.size());
    return path.string();
}

std::filesystem::path freshGltfTestDir(const std::string& name) {
    const std::filesystem::path dir =
            std::filesystem::path(VOXATLAS_TEST_OUTPUT_DIR) / "gltf" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void writeBytes(const std::filesystem::path& path, const void* data, std::size_t size) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(static_cast<const char*>(data), std::streamsize(size));
    if (!file) throw std::runtime_error("cannot write " + path.string());
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    writeBytes(path, text.data(), text.size());
}

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

std::string base64Encode(const std::vector<std::uint8_t>& bytes) {
    static constexpr char kAlphabet[] =
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t chunk = std::uint32_t(bytes[i]) << 16 |
                                    (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                    (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
        out.push_back(kAlphabet[(chunk >> 18) & 63]);
        out.push_back(kAlphabet[(chunk >> 12) & 63]);
        out.push_back(i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=');
        out.push_back(i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=');
    }
    return out;
}

std::vector<std::uint8_t> encodePng(int width, int height, int channels,
        const std::vector<std::uint8_t>& pixels) {
    std::vector<std::uint8_t> out;
    stbi_write_png_to_func(appendToVector, &out, width, height, channels, pixels.data(),
            width * channels);
    return out;
}

std::vector<std::uint8_t> encodeJpeg(int width, int height, int channels,
        const std::vector<std::uint8_t>& pixels, int quality) {
    std::vector<std::uint8_t> out;
    stbi_write_jpg_to_func(appendToVector, &out, width, height, channels, pixels.data(), quality);
    return out;
}

} // namespace gi::test
