#include "scene/GltfContainerChecks.h"

#include "scene/GltfMessages.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>

namespace gi::scene::gltf {
namespace {

std::uint32_t readLe32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

} // namespace

std::size_t jsonNestingDepth(const char* text, std::size_t size) {
    std::size_t depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

bool checkGlbContainer(const std::uint8_t* data, std::size_t size, const char*& json,
        std::size_t& jsonSize, std::string& what) {
    if (size < 20) {
        what = "the file is " + std::to_string(size) + " bytes, shorter than a GLB header";
        return false;
    }
    const std::uint32_t version = readLe32(data + 4);
    const std::uint64_t length = readLe32(data + 8);
    const std::uint64_t jsonLength = readLe32(data + 12);
    if (version != 2) {
        what = "GLB version " + std::to_string(version) + " is not 2";
        return false;
    }
    if (length > size) {
        what = "header length " + std::to_string(length) + " exceeds the file size " +
               std::to_string(size);
        return false;
    }
    if (readLe32(data + 16) != 0x4E4F534Au || jsonLength == 0 || 20 + jsonLength > length) {
        what = "the first chunk is not a JSON chunk inside the file";
        return false;
    }
    if (jsonLength % 4 != 0) {
        what = "the JSON chunk length " + std::to_string(jsonLength) + " is not a multiple of 4";
        return false;
    }
    const std::uint64_t binStart = 20 + jsonLength;
    if (binStart < length) {
        if (binStart + 8 > length) {
            what = "a chunk header is cut off by the end of the file";
            return false;
        }
        const std::uint64_t binLength = readLe32(data + binStart);
        if (readLe32(data + binStart + 4) != 0x004E4942u) {
            what = "the second chunk is not a BIN chunk";
            return false;
        }
        if (binStart + 8 + binLength > length || binLength < 4 || binLength % 4 != 0) {
            what = "the BIN chunk length " + std::to_string(binLength) +
                   " is not a multiple of 4 that fits in the file";
            return false;
        }
    }
    json = reinterpret_cast<const char*>(data + 20);
    jsonSize = std::size_t(jsonLength);
    return true;
}

std::string leadingBytes(const std::uint8_t* data, std::size_t size) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string text;
    for (std::size_t i = 0; i < std::min<std::size_t>(size, 4); ++i) {
        text += std::string(i ? " " : "") + kHex[data[i] >> 4] + kHex[data[i] & 15];
    }
    return text;
}

bool startsLikeJsonObject(const char* text, std::size_t size) {
    std::size_t i = size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (i < size && space(text[i])) ++i;
    return i < size && text[i] == '{';
}

std::string diagnoseBuffers(const char* json, std::size_t size, const FileAccess& access) {
    const nlohmann::json root = nlohmann::json::parse(json, json + size, nullptr, false);
    if (root.is_discarded() || !root.is_object()) return {};
    auto buffers = root.find("buffers");
    if (buffers == root.end() || !buffers->is_array()) return {};
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const nlohmann::json& buffer = (*buffers)[i];
        if (!buffer.is_object()) continue;
        auto uri = buffer.find("uri");
        auto length = buffer.find("byteLength");
        if (uri == buffer.end() || !uri->is_string()) continue;
        std::uint64_t byteLength = 0;
        if (length != buffer.end() && length->is_number_unsigned()) {
            byteLength = length->get<std::uint64_t>();
        }
        const std::string& text = uri->get_ref<const std::string&>();
        const std::string problem = isDataUri(text)
                                            ? dataUriProblem(text, byteLength)
                                            : externalFileProblem(access, text, byteLength, true);
        if (!problem.empty()) return indexed("buffers", long(i)) + ": " + problem;
    }
    return {};
}

std::string checkOptionalIntegers(const char* json, std::size_t size) {
    struct Property {
        const char* array;
        const char* nested; // array inside each element, or nullptr
        const char* name;
    };
    static constexpr Property kProperties[] = {
            {"bufferViews", nullptr, "byteOffset"},
            {"bufferViews", nullptr, "byteStride"},
            {"accessors", nullptr, "byteOffset"},
            {"accessors", nullptr, "bufferView"},
            {"meshes", "primitives", "indices"},
            {"meshes", "primitives", "material"},
            {"meshes", "primitives", "mode"},
            {"nodes", nullptr, "mesh"},
            {"nodes", nullptr, "camera"},
            {"textures", nullptr, "source"},
            {"textures", nullptr, "sampler"},
    };
    const nlohmann::json root = nlohmann::json::parse(json, json + size, nullptr, false);
    if (root.is_discarded() || !root.is_object()) return {};
    auto check = [](const nlohmann::json& object, const std::string& element,
                         const char* name) -> std::string {
        if (!object.is_object()) return {};
        auto value = object.find(name);
        if (value == object.end() || value->is_number_unsigned()) return {};
        return element + ": " + name + " " + value->dump() + " is not an integer >= 0";
    };
    for (const Property& property : kProperties) {
        auto array = root.find(property.array);
        if (array == root.end() || !array->is_array()) continue;
        for (std::size_t i = 0; i < array->size(); ++i) {
            const nlohmann::json& item = (*array)[i];
            const std::string element = indexed(property.array, long(i));
            std::string problem;
            if (property.nested == nullptr) {
                problem = check(item, element, property.name);
            } else if (item.is_object() && item.contains(property.nested) &&
                       item[property.nested].is_array()) {
                const nlohmann::json& nested = item[property.nested];
                for (std::size_t k = 0; k < nested.size() && problem.empty(); ++k) {
                    problem = check(nested[k], element + "." + indexed(property.nested, long(k)),
                            property.name);
                }
            }
            if (!problem.empty()) return problem;
        }
    }
    return {};
}

} // namespace gi::scene::gltf
