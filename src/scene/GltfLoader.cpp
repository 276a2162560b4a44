#include "scene/GltfLoader.h"

#include "scene/Animation.h"
#include "scene/GltfAccessorReader.h"
#include "scene/ImageDecoder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

namespace gi::scene {
namespace {

// World-space coordinates allowed (metres): squares of distances stay finite in float.
constexpr float kMaxCoordinate = 1e18f;

constexpr const char* kSupportedExtensions[] = {
        "KHR_lights_punctual",
        "KHR_materials_emissive_strength",
};

std::string indexed(const char* array, long long index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

std::string primitiveName(int mesh, int primitive) {
    return indexed("meshes", mesh) + "." + indexed("primitives", primitive);
}

std::string doesNotExist(const char* what, long long index, std::size_t count, const char* array) {
    return std::string(what) + " " + std::to_string(index) + " does not exist (the file has " +
           std::to_string(count) + " " + array + ")";
}

bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

// glTF URIs are percent-encoded (RFC 3986); file names are not.
std::string percentDecode(const std::string& uri) {
    std::string out;
    out.reserve(uri.size());
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out.push_back(char(hex(uri[i + 1]) * 16 + hex(uri[i + 2])));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

std::string joinPath(const std::string& dir, const std::string& file) {
    if (dir.empty()) return file;
    return dir.back() == '/' ? dir + file : dir + "/" + file;
}

// Reads a whole regular file; on failure `reason` says why (strerror wording).
bool readWholeFile(const std::string& path, std::vector<unsigned char>& out, std::string& reason) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
        reason = ec ? ec.message() : std::strerror(ENOENT);
        return false;
    }
    if (!std::filesystem::is_regular_file(status)) {
        reason = "not a regular file";
        return false;
    }
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        reason = std::strerror(errno);
        return false;
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        std::fclose(file);
        reason = ec.message();
        return false;
    }
    out.resize(std::size_t(size));
    const std::size_t got = size == 0 ? 0 : std::fread(out.data(), 1, out.size(), file);
    const bool readError = std::ferror(file) != 0;
    std::fclose(file);
    if (readError || got != out.size()) {
        reason = readError ? std::strerror(EIO) : "the file changed size while being read";
        return false;
    }
    return true;
}

// File access handed to tinygltf: only regular files under the glTF file's directory
// (tinygltf also tries the working directory; that fallback is refused), never when the scene
// was loaded from memory without a base directory.
struct FileAccess {
    bool enabled = false;
    std::string prefix; // base directory ending in '/'
};

bool fsFileExists(const std::string& path, void* user) {
    const auto* access = static_cast<const FileAccess*>(user);
    if (!access->enabled || path.rfind(access->prefix, 0) != 0) return false;
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

std::string fsExpandFilePath(const std::string& path, void*) { return path; }

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
        void* user) {
    if (!fsFileExists(path, user)) {
        if (err) *err += "cannot read " + path + "\n";
        return false;
    }
    std::string reason;
    if (!readWholeFile(path, *out, reason)) {
        if (err) *err += reason + "\n";
        return false;
    }
    return true;
}

bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
        void*) {
    if (err) *err += "the loader never writes files\n";
    return false;
}

// Why an external file cannot serve as a buffer of `byteLength` bytes; empty when it can.
std::string externalFileProblem(const FileAccess& access, const std::string& uri,
        std::uint64_t byteLength, bool checkSize) {
    if (!access.enabled) return "cannot read '" + uri + "' (external files are disabled)";
    const std::string path = joinPath(access.prefix, percentDecode(uri));
    std::vector<unsigned char> bytes;
    std::string reason;
    if (!readWholeFile(path, bytes, reason)) return "cannot read '" + uri + "' (" + reason + ")";
    if (checkSize && bytes.size() != byteLength) {
        return "'" + uri + "' holds " + std::to_string(bytes.size()) +
               " bytes but byteLength is " + std::to_string(byteLength);
    }
    if (bytes.empty()) return "'" + uri + "' is empty (0 bytes)";
    return {};
}

// Why a data URI cannot serve as a buffer of `byteLength` bytes; empty when it can. Spares the
// user tinygltf's message, which quotes the whole URI.
std::string dataUriProblem(const std::string& uri, std::uint64_t byteLength) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos || comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0) {
        return "the data URI is not base64-encoded";
    }
    std::uint64_t digits = 0, padding = 0;
    for (std::size_t i = comma + 1; i < uri.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(uri[i]);
        if (c == '=') {
            ++padding;
        } else if ((std::isalnum(c) || c == '+' || c == '/') && padding == 0) {
            ++digits;
        } else {
            return "the data URI is not valid base64";
        }
    }
    const std::uint64_t decoded = digits * 3 / 4;
    if (decoded != byteLength) {
        return "the data URI holds " + std::to_string(decoded) + " bytes but byteLength is " +
               std::to_string(byteLength);
    }
    return {};
}

// tinygltf's image callback: keeps the encoded bytes (decoded later, in parallel) and checks
// what tinygltf does not: that an image's bufferView lies inside its buffer.
struct ImageCapture {
    const tinygltf::Model* model = nullptr;
    std::string error; // "<element>: <what>"
};

bool captureEncodedImage(tinygltf::Image* image, const int index, std::string* err, std::string*,
        int, int, const unsigned char* bytes, int size, void* user) {
    auto* capture = static_cast<ImageCapture*>(user);
    if (image->bufferView >= 0) {
        const tinygltf::Model& model = *capture->model;
        bool valid = std::size_t(image->bufferView) < model.bufferViews.size();
        if (valid) {
            const tinygltf::BufferView& view = model.bufferViews[std::size_t(image->bufferView)];
            valid = view.buffer >= 0 && std::size_t(view.buffer) < model.buffers.size();
            std::uint64_t end = 0;
            valid = valid && !__builtin_add_overflow(view.byteOffset, view.byteLength, &end) &&
                    end <= model.buffers[std::size_t(view.buffer)].data.size() &&
                    view.byteLength <= std::uint64_t(INT_MAX);
        }
        if (!valid) {
            capture->error = indexed("images", index) + ": " +
                             indexed("bufferViews", image->bufferView) +
                             " does not lie inside its buffer";
            if (err) *err += capture->error + "\n";
            return false;
        }
    }
    if (size < 0 || (size > 0 && bytes == nullptr)) {
        capture->error = indexed("images", index) + ": has no data";
        if (err) *err += capture->error + "\n";
        return false;
    }
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// Deepest nesting of JSON arrays/objects, ignoring brackets inside strings. tinygltf copies
// `extras` recursively, so a hostile nesting depth must be refused before it parses.
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

std::uint32_t readLe32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

// Checks the GLB container (glTF 2.0 section 4.4) more strictly than tinygltf, which reads up to
// 8 bytes past a BIN chunk that claims more than the file holds. Finds the JSON chunk.
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

// tinygltf's messages are newline-separated; ours must be one line.
std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    std::string line;
    while (std::getline(stream, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) lines.push_back(line);
    }
    return lines;
}

// JSON numbers are doubles; the Scene stores floats, so "finite" means finite as a float.
bool finite(double v) { return std::isfinite(v) && std::abs(v) <= double(FLT_MAX); }

template <class Vec> bool allFinite(const Vec& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return finite(v); });
}

bool finiteMatrix(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!finite(m[c][r])) return false;
        }
    }
    return true;
}

std::string formatVector(const float* v, int n) {
    std::ostringstream s;
    s << "(";
    for (int i = 0; i < n; ++i) s << (i ? ", " : "") << v[i];
    s << ")";
    return s.str();
}

// Turns a validated tinygltf::Model into a Scene.
class SceneBuilder {
public:
    SceneBuilder(const tinygltf::Model& model, const std::string& name, const FileAccess& access,
            const GltfLimits& limits, std::vector<std::string>& warnings)
        : mModel(model), mName(name), mAccess(access), mLimits(limits), mWarnings(warnings) {}

    bool build(Scene& scene, std::string& error) {
        const bool ok = checkExtensions() && checkSamplersAndTextures() && checkCameras() &&
                        checkLights() && convertMaterials() && decodeTextures() &&
                        checkNodes() && instantiate() && computeBounds() && readAnimations();
        if (!ok) {
            error = mError;
            return false;
        }
        mScene.sourcePath = mName;
        scene = std::move(mScene);
        return true;
    }

private:
    struct PendingTexture {
        int sceneTexture;
        int image;
    };

    bool fail(const std::string& element, const std::string& what) {
        mError = mName + ": " + element + ": " + what;
        return false;
    }
    // `elementAndWhat` is already "<element>: <what>" (from the accessor reader).
    bool failWith(const std::string& elementAndWhat) {
        mError = mName + ": " + elementAndWhat;
        return false;
    }
    void warn(const std::string& element, const std::string& what) {
        mWarnings.push_back(mName + ": " + element + ": " + what);
    }

    bool checkExtensions() {
        auto supported = [](const std::string& name) {
            return std::find_if(std::begin(kSupportedExtensions), std::end(kSupportedExtensions),
                           [&](const char* s) { return name == s; }) !=
                   std::end(kSupportedExtensions);
        };
        for (const std::string& name : mModel.extensionsRequired) {
            if (!supported(name)) {
                return fail("extensionsRequired",
                        "extension '" + name + "' is not supported (supported: " +
                                "KHR_lights_punctual, KHR_materials_emissive_strength)");
            }
        }
        std::string ignored;
        for (const std::string& name : mModel.extensionsUsed) {
            if (!supported(name)) ignored += (ignored.empty() ? "" : ", ") + name;
        }
        if (!ignored.empty()) warn("extensionsUsed", "ignoring unsupported " + ignored);
        return true;
    }

    bool checkSamplersAndTextures() {
        for (std::size_t i = 0; i < mModel.samplers.size(); ++i) {
            const tinygltf::Sampler& sampler = mModel.samplers[i];
            for (const auto& [axis, wrap] : {std::pair{"wrapS", sampler.wrapS},
                         std::pair{"wrapT", sampler.wrapT}}) {
                if (wrap != TINYGLTF_TEXTURE_WRAP_REPEAT &&
                        wrap != TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
                        wrap != TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) {
                    return fail(indexed("samplers", long(i)),
                            std::string(axis) + " " + std::to_string(wrap) +
                                    " is not CLAMP_TO_EDGE, MIRRORED_REPEAT or REPEAT");
                }
            }
        }
        for (std::size_t i = 0; i < mModel.textures.size(); ++i) {
            const tinygltf::Texture& texture = mModel.textures[i];
            if (texture.source < -1 || texture.source >= int(mModel.images.size())) {
                return fail(indexed("textures", long(i)),
                        doesNotExist("source", texture.source, mModel.images.size(), "images"));
            }
            if (texture.sampler < -1 || texture.sampler >= int(mModel.samplers.size())) {
                return fail(indexed("textures", long(i)),
                        doesNotExist("sampler", texture.sampler, mModel.samplers.size(),
                                "samplers"));
            }
        }
        return true;
    }

    bool checkCameras() {
        for (std::size_t i = 0; i < mModel.cameras.size(); ++i) {
            const tinygltf::Camera& camera = mModel.cameras[i];
            if (camera.type != "perspective") continue;
            const tinygltf::PerspectiveCamera& p = camera.perspective;
            const std::string element = indexed("cameras", long(i));
            if (!finite(p.yfov) || p.yfov <= 0.0 || p.yfov >= glm::pi<double>()) {
                return fail(element, "perspective.yfov " + std::to_string(p.yfov) +
                                             " is not in (0, pi)");
            }
            if (!finite(p.znear) || p.znear <= 0.0) {
                return fail(element, "perspective.znear " + std::to_string(p.znear) +
                                             " is not a positive number");
            }
            if (!finite(p.zfar) || (p.zfar != 0.0 && p.zfar <= p.znear)) {
                return fail(element, "perspective.zfar " + std::to_string(p.zfar) +
                                             " is not greater than znear");
            }
        }
        return true;
    }

    bool checkLights() {
        for (std::size_t i = 0; i < mModel.lights.size(); ++i) {
            const tinygltf::Light& light = mModel.lights[i];
            const std::string element = "KHR_lights_punctual." + indexed("lights", long(i));
            if (light.type != "point" && light.type != "spot" && light.type != "directional") {
                return fail(element, "type '" + light.type +
                                             "' is not point, spot or directional");
            }
            if (!(light.color.empty() || light.color.size() == 3) || !allFinite(light.color) ||
                    std::any_of(light.color.begin(), light.color.end(),
                            [](double c) { return c < 0.0; })) {
                return fail(element, "color must be 3 finite numbers >= 0");
            }
            if (!finite(light.intensity) || light.intensity < 0.0) {
                return fail(element, "intensity " + std::to_string(light.intensity) +
                                             " is not a finite number >= 0");
            }
            if (!finite(light.range) || light.range < 0.0) {
                return fail(element, "range " + std::to_string(light.range) +
                                             " is not a finite number >= 0");
            }
            if (light.type == "spot") {
                const double inner = light.spot.innerConeAngle;
                const double outer = light.spot.outerConeAngle;
                if (!finite(inner) || !finite(outer) || inner < 0.0 || outer <= inner ||
                        outer > glm::half_pi<double>() + 1e-6) {
                    return fail(element, "spot cone angles (inner " + std::to_string(inner) +
                                                 ", outer " + std::to_string(outer) +
                                                 ") must satisfy 0 <= inner < outer <= pi/2");
                }
            }
        }
        return true;
    }

    // Scene texture for a material's texture slot; -1 when the slot is empty or ignored.
    bool textureFor(const std::string& element, const char* slot,
            const tinygltf::TextureInfo& info, int& sceneTexture, int& texCoord) {
        sceneTexture = -1;
        texCoord = 0;
        if (info.index == -1) return true;
        if (info.index < 0 || std::size_t(info.index) >= mModel.textures.size()) {
            return fail(element, doesNotExist((std::string(slot) + ".index").c_str(), info.index,
                                         mModel.textures.size(), "textures"));
        }
        if (info.texCoord < 0) {
            return fail(element, std::string(slot) + ".texCoord " +
                                         std::to_string(info.texCoord) + " is negative");
        }
        if (info.texCoord > 1) {
            warn(element, std::string(slot) + " uses TEXCOORD_" +
                                  std::to_string(info.texCoord) +
                                  "; only TEXCOORD_0 and TEXCOORD_1 are loaded, texture ignored");
            return true;
        }
        const tinygltf::Texture& texture = mModel.textures[std::size_t(info.index)];
        if (texture.source < 0) {
            warn(indexed("textures", info.index), "has no source image; texture ignored");
            return true;
        }
        texCoord = info.texCoord;
        auto found = mTextureMap.find(info.index);
        if (found != mTextureMap.end()) {
            sceneTexture = found->second;
            return true;
        }
        Texture out;
        const tinygltf::Image& image = mModel.images[std::size_t(texture.source)];
        out.name = !texture.name.empty() ? texture.name
                   : !image.name.empty() ? image.name
                   : !image.uri.empty() && !isDataUri(image.uri)
                           ? image.uri
                           : indexed("textures", info.index);
        out.srgb = true;
        if (texture.sampler >= 0) {
            out.wrapS = mModel.samplers[std::size_t(texture.sampler)].wrapS;
            out.wrapT = mModel.samplers[std::size_t(texture.sampler)].wrapT;
        }
        sceneTexture = int(mScene.textures.size());
        mScene.textures.push_back(std::move(out));
        mTextureMap[info.index] = sceneTexture;
        mPendingTextures.push_back({sceneTexture, texture.source});
        return true;
    }

    bool convertMaterials() {
        for (std::size_t i = 0; i < mModel.materials.size(); ++i) {
            const tinygltf::Material& source = mModel.materials[i];
            const std::string element = indexed("materials", long(i));
            Material material;
            material.name = source.name.empty() ? element : source.name;
            const std::vector<double>& base = source.pbrMetallicRoughness.baseColorFactor;
            if (base.size() != 4 || !allFinite(base) ||
                    std::any_of(base.begin(), base.end(), [](double v) { return v < 0.0; })) {
                return fail(element, "pbrMetallicRoughness.baseColorFactor must be 4 finite "
                                     "numbers >= 0");
            }
            material.baseColorFactor = glm::vec4(base[0], base[1], base[2], base[3]);
            const std::vector<double>& emissive = source.emissiveFactor;
            if (emissive.size() != 3 || !allFinite(emissive) ||
                    std::any_of(emissive.begin(), emissive.end(),
                            [](double v) { return v < 0.0; })) {
                return fail(element, "emissiveFactor must be 3 finite numbers >= 0");
            }
            material.emissiveFactor = glm::vec3(emissive[0], emissive[1], emissive[2]);
            auto strength = source.extensions.find("KHR_materials_emissive_strength");
            if (strength != source.extensions.end()) {
                const tinygltf::Value& ext = strength->second;
                double value = 1.0;
                if (ext.IsObject() && ext.Has("emissiveStrength")) {
                    const tinygltf::Value& v = ext.Get("emissiveStrength");
                    value = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
                }
                if (!finite(value) || value < 0.0) {
                    return fail(element, "KHR_materials_emissive_strength.emissiveStrength is "
                                         "not a finite number >= 0");
                }
                material.emissiveFactor *= float(value);
                if (!finite(glm::length(glm::dvec3(material.emissiveFactor)))) {
                    return fail(element, "emissiveFactor x emissiveStrength is not finite");
                }
            }
            if (source.alphaMode == "OPAQUE") {
                material.alphaMode = AlphaMode::Opaque;
            } else if (source.alphaMode == "MASK") {
                material.alphaMode = AlphaMode::Mask;
            } else if (source.alphaMode == "BLEND") {
                material.alphaMode = AlphaMode::Blend;
            } else {
                return fail(element, "alphaMode '" + source.alphaMode +
                                             "' is not OPAQUE, MASK or BLEND");
            }
            if (!finite(source.alphaCutoff) || source.alphaCutoff < 0.0) {
                return fail(element, "alphaCutoff " + std::to_string(source.alphaCutoff) +
                                             " is not a finite number >= 0");
            }
            material.alphaCutoff = float(source.alphaCutoff);
            material.doubleSided = source.doubleSided;
            if (!textureFor(element, "pbrMetallicRoughness.baseColorTexture",
                        source.pbrMetallicRoughness.baseColorTexture, material.baseColorTexture,
                        material.baseColorTexCoord) ||
                    !textureFor(element, "emissiveTexture", source.emissiveTexture,
                            material.emissiveTexture, material.emissiveTexCoord)) {
                return false;
            }
            mScene.materials.push_back(std::move(material));
        }
        return true;
    }

    // "'file.png': " for external images, so messages name the file; empty otherwise.
    static std::string imageSource(const tinygltf::Image& image) {
        return !image.uri.empty() && !isDataUri(image.uri) ? "'" + image.uri + "': " : "";
    }

    // Decodes every image a scene texture needs, each once, on up to one thread per core.
    bool decodeTextures() {
        std::vector<int> images;
        for (const PendingTexture& pending : mPendingTextures) images.push_back(pending.image);
        std::sort(images.begin(), images.end());
        images.erase(std::unique(images.begin(), images.end()), images.end());

        for (int index : images) {
            const tinygltf::Image& image = mModel.images[std::size_t(index)];
            if (image.image.empty()) {
                const std::string element = indexed("images", index);
                if (!image.uri.empty() && !isDataUri(image.uri)) {
                    const std::string problem = externalFileProblem(mAccess, image.uri, 0, false);
                    return fail(element, problem.empty() ? "cannot read '" + image.uri + "'"
                                                         : problem);
                }
                return fail(element, "has no image data");
            }
        }
        // Headers first: refuse images too large in total before decoding any of them.
        std::uint64_t totalPixels = 0;
        for (int index : images) {
            const tinygltf::Image& image = mModel.images[std::size_t(index)];
            int width = 0, height = 0;
            std::string error;
            if (!readImageSize(image.image.data(), image.image.size(), width, height, error)) {
                return fail(indexed("images", index), imageSource(image) + error);
            }
            totalPixels += std::uint64_t(std::max(width, 0)) * std::uint64_t(std::max(height, 0));
            if (totalPixels > mLimits.maxTotalImagePixels) {
                return fail(indexed("images", index),
                        "the scene's images exceed the loader's limit of " +
                                std::to_string(mLimits.maxTotalImagePixels) + " pixels in total");
            }
        }

        std::vector<DecodedImage> decoded(images.size());
        std::vector<std::string> errors(images.size());
        std::atomic<std::size_t> next{0};
        auto work = [&]() {
            for (std::size_t k = next++; k < images.size(); k = next++) {
                try {
                    const tinygltf::Image& image = mModel.images[std::size_t(images[k])];
                    if (!decodeImageRgba8(image.image.data(), image.image.size(),
                                mLimits.maxImagePixels, decoded[k], errors[k])) {
                        if (errors[k].empty()) errors[k] = "cannot decode the image";
                    }
                } catch (const std::bad_alloc&) {
                    errors[k] = "out of memory while decoding the image";
                } catch (...) {
                    errors[k] = "cannot decode the image";
                }
            }
        };
        const std::size_t threadCount = std::min<std::size_t>(
                images.size(), std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
        std::vector<std::thread> threads;
        for (std::size_t t = 1; t < threadCount; ++t) {
            try {
                threads.emplace_back(work);
            } catch (const std::system_error&) {
                break;
            }
        }
        work();
        for (std::thread& thread : threads) thread.join();

        for (std::size_t k = 0; k < images.size(); ++k) {
            if (!errors[k].empty()) {
                const tinygltf::Image& image = mModel.images[std::size_t(images[k])];
                return fail(indexed("images", images[k]), imageSource(image) + errors[k]);
            }
        }
        std::vector<int> usesLeft(images.size(), 0);
        auto slot = [&](int image) {
            return std::size_t(std::lower_bound(images.begin(), images.end(), image) -
                               images.begin());
        };
        for (const PendingTexture& pending : mPendingTextures) ++usesLeft[slot(pending.image)];
        for (const PendingTexture& pending : mPendingTextures) {
            const std::size_t k = slot(pending.image);
            Texture& texture = mScene.textures[std::size_t(pending.sceneTexture)];
            texture.width = decoded[k].width;
            texture.height = decoded[k].height;
            if (--usesLeft[k] == 0) {
                texture.rgba8 = std::move(decoded[k].rgba8);
            } else {
                texture.rgba8 = decoded[k].rgba8;
            }
        }
        return true;
    }

    // Local transforms, references and the hierarchy of every node: one parent at most, no
    // cycles (glTF 2.0 section 3.5.2).
    bool checkNodes() {
        const std::size_t count = mModel.nodes.size();
        mParent.assign(count, -1);
        mLocal.assign(count, glm::dmat4(1.0));
        for (std::size_t i = 0; i < count; ++i) {
            const tinygltf::Node& node = mModel.nodes[i];
            const std::string element = indexed("nodes", long(i));
            if (node.mesh < -1 || node.mesh >= int(mModel.meshes.size())) {
                return fail(element, doesNotExist("mesh", node.mesh, mModel.meshes.size(),
                                             "meshes"));
            }
            if (node.camera < -1 || node.camera >= int(mModel.cameras.size())) {
                return fail(element, doesNotExist("camera", node.camera, mModel.cameras.size(),
                                             "cameras"));
            }
            if (!localTransform(node, element, mLocal[i])) return false;
            for (int child : node.children) {
                if (child < 0 || std::size_t(child) >= count) {
                    return fail(element, doesNotExist("child", child, count, "nodes"));
                }
                int& parent = mParent[std::size_t(child)];
                if (parent == int(i)) {
                    return fail(indexed("nodes", child),
                            "is listed twice in " + element + ".children");
                }
                if (parent != -1) {
                    return fail(indexed("nodes", child), "has two parents (" +
                                                                 indexed("nodes", parent) +
                                                                 " and " + element + ")");
                }
                parent = int(i);
            }
        }
        // With one parent per node, a cycle is a loop of parent links: walk up from every node,
        // marking the walk, until reaching a root or a node already known to reach one.
        std::vector<int> walk(count, -1); // start node of the walk that visited it
        std::vector<char> reachesRoot(count, 0);
        for (std::size_t start = 0; start < count; ++start) {
            int n = int(start);
            while (n != -1 && !reachesRoot[std::size_t(n)]) {
                if (walk[std::size_t(n)] == int(start)) return failCycle(n);
                walk[std::size_t(n)] = int(start);
                n = mParent[std::size_t(n)];
            }
            for (n = int(start); n != -1 && !reachesRoot[std::size_t(n)];
                    n = mParent[std::size_t(n)]) {
                reachesRoot[std::size_t(n)] = 1;
            }
        }
        return true;
    }

    bool failCycle(int member) {
        std::vector<int> loop{member};
        for (int n = mParent[std::size_t(member)]; n != member; n = mParent[std::size_t(n)]) {
            loop.push_back(n);
        }
        std::reverse(loop.begin(), loop.end()); // parent -> child order
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        std::string path;
        const std::size_t shown = std::min<std::size_t>(loop.size(), 8);
        for (std::size_t k = 0; k < shown; ++k) path += indexed("nodes", loop[k]) + " -> ";
        path += loop.size() > shown ? "... -> " + indexed("nodes", loop.front())
                                    : indexed("nodes", loop.front());
        return fail(indexed("nodes", loop.front()), "is part of a cycle in the node hierarchy (" +
                                                            path + ")");
    }

    bool localTransform(const tinygltf::Node& node, const std::string& element, glm::dmat4& out) {
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16 || !allFinite(node.matrix)) {
                return fail(element, "matrix must be 16 finite numbers");
            }
            out = glm::make_mat4(node.matrix.data());
            return true;
        }
        glm::dvec3 translation(0.0), scale(1.0);
        glm::dquat rotation(1.0, 0.0, 0.0, 0.0);
        if (!node.translation.empty()) {
            if (node.translation.size() != 3 || !allFinite(node.translation)) {
                return fail(element, "translation must be 3 finite numbers");
            }
            translation = glm::make_vec3(node.translation.data());
        }
        if (!node.scale.empty()) {
            if (node.scale.size() != 3 || !allFinite(node.scale)) {
                return fail(element, "scale must be 3 finite numbers");
            }
            scale = glm::make_vec3(node.scale.data());
        }
        if (!node.rotation.empty()) {
            if (node.rotation.size() != 4 || !allFinite(node.rotation)) {
                return fail(element, "rotation must be 4 finite numbers");
            }
            // glTF stores quaternions as (x, y, z, w).
            rotation = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1],
                    node.rotation[2]);
            const double length = glm::length(rotation);
            if (!(length > 1e-12) || !finite(length)) {
                return fail(element, "rotation is not a unit quaternion");
            }
            rotation /= length;
        }
        out = glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) *
              glm::scale(glm::dmat4(1.0), scale);
        return true;
    }

    bool selectRoots(std::vector<int>& roots) {
        if (mModel.scenes.empty()) {
            for (std::size_t i = 0; i < mModel.nodes.size(); ++i) {
                if (mParent[i] == -1) roots.push_back(int(i));
            }
            return true;
        }
        int sceneIndex = mModel.defaultScene;
        if (sceneIndex < -1 || sceneIndex >= int(mModel.scenes.size())) {
            return fail("scene", doesNotExist("scene", sceneIndex, mModel.scenes.size(),
                                         "scenes"));
        }
        if (sceneIndex == -1) sceneIndex = 0;
        const std::string element = indexed("scenes", sceneIndex);
        std::set<int> seen;
        for (int root : mModel.scenes[std::size_t(sceneIndex)].nodes) {
            if (root < 0 || std::size_t(root) >= mModel.nodes.size()) {
                return fail(element, doesNotExist("node", root, mModel.nodes.size(), "nodes"));
            }
            if (mParent[std::size_t(root)] != -1) {
                return fail(element, indexed("nodes", root) + " is listed as a root but is a "
                                             "child of " +
                                             indexed("nodes", mParent[std::size_t(root)]));
            }
            if (!seen.insert(root).second) {
                return fail(element, indexed("nodes", root) + " is listed twice");
            }
            roots.push_back(root);
        }
        return true;
    }

    // Walks the selected scene's node trees (iteratively: hostile files nest deeply) and
    // places primitives, cameras and lights.
    bool instantiate() {
        std::vector<int> roots;
        if (!selectRoots(roots)) return false;
        struct Item {
            int node;
            glm::dmat4 parentWorld;
        };
        std::vector<Item> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) {
            stack.push_back({*it, glm::dmat4(1.0)});
        }
        bool warnedSkin = false;
        while (!stack.empty()) {
            const Item item = stack.back();
            stack.pop_back();
            const tinygltf::Node& node = mModel.nodes[std::size_t(item.node)];
            const std::string element = indexed("nodes", item.node);
            const glm::dmat4 world = item.parentWorld * mLocal[std::size_t(item.node)];
            if (!finiteMatrix(world)) {
                return fail(element, "world transform is not finite");
            }
            if (node.skin >= 0 && !warnedSkin) {
                warn(element, "skinning is ignored; meshes are drawn in their bind pose");
                warnedSkin = true;
            }
            if (node.mesh >= 0 && !placeMesh(item.node, world)) return false;
            if (node.camera >= 0 && !placeCamera(item.node, world)) return false;
            if (!placeLight(item.node, world)) return false;
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
                stack.push_back({*it, world});
            }
        }
        return true;
    }

    bool placeMesh(int nodeIndex, const glm::dmat4& world) {
        const int mesh = mModel.nodes[std::size_t(nodeIndex)].mesh;
        const bool flipped = glm::determinant(glm::dmat3(world)) < 0.0;
        const auto& primitives = mModel.meshes[std::size_t(mesh)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            int sceneIndex = -1;
            if (!primitiveFor(mesh, int(p), flipped, sceneIndex)) return false;
            if (sceneIndex < 0) continue;
            if (mScene.instances.size() >= mLimits.maxInstances) {
                return fail(indexed("nodes", nodeIndex),
                        "the scene places more than the loader's limit of " +
                                std::to_string(mLimits.maxInstances) + " primitives");
            }
            Instance instance;
            instance.primitive = sceneIndex;
            instance.node = nodeIndex;
            instance.worldFromLocal = glm::mat4(world);
            instance.flipWinding = flipped;
            mScene.instances.push_back(instance);
        }
        return true;
    }

    bool placeCamera(int nodeIndex, const glm::dmat4& world) {
        const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
        const tinygltf::Camera& source = mModel.cameras[std::size_t(node.camera)];
        const std::string element = indexed("cameras", node.camera);
        if (source.type != "perspective") {
            warn(element, "camera type '" + source.type + "' is not supported; skipped");
            return true;
        }
        // Cameras ignore scale (glTF 2.0 section 3.10.1): orthonormalize, keeping -Z and +Y.
        const glm::dvec3 back = glm::dvec3(world[2]);
        const glm::dvec3 up = glm::dvec3(world[1]);
        const double backLength = glm::length(back);
        const glm::dvec3 z = back / backLength;
        const glm::dvec3 yRaw = up - glm::dot(up, z) * z;
        const double yLength = glm::length(yRaw);
        if (!(backLength > 1e-12) || !(yLength > 1e-12 * glm::length(up)) || !(yLength > 0.0)) {
            return fail(indexed("nodes", nodeIndex),
                    "the transform of " + element + " is singular");
        }
        const glm::dvec3 y = yRaw / yLength;
        const glm::dvec3 x = glm::cross(y, z);
        Camera camera;
        camera.name = !source.name.empty() ? source.name
                      : !node.name.empty() ? node.name
                                           : element;
        camera.worldFromCamera = glm::mat4(glm::dmat4(glm::dvec4(x, 0.0), glm::dvec4(y, 0.0),
                glm::dvec4(z, 0.0), world[3]));
        camera.yfov = float(source.perspective.yfov);
        camera.znear = float(source.perspective.znear);
        camera.zfar = float(source.perspective.zfar);
        mScene.cameras.push_back(std::move(camera));
        return true;
    }

    bool placeLight(int nodeIndex, const glm::dmat4& world) {
        const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
        auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end()) return true;
        const std::string element = indexed("nodes", nodeIndex);
        const tinygltf::Value& value = ext->second;
        if (!value.IsObject() || !value.Has("light") || !value.Get("light").IsInt()) {
            return fail(element, "KHR_lights_punctual.light is not a light index");
        }
        const int index = value.Get("light").GetNumberAsInt();
        if (index < 0 || std::size_t(index) >= mModel.lights.size()) {
            return fail(element, doesNotExist("KHR_lights_punctual.light", index,
                                         mModel.lights.size(), "lights"));
        }
        const tinygltf::Light& source = mModel.lights[std::size_t(index)];
        Light light;
        light.name = !source.name.empty() ? source.name
                     : !node.name.empty() ? node.name
                                          : "KHR_lights_punctual." + indexed("lights", index);
        light.type = source.type == "spot"          ? LightType::Spot
                     : source.type == "directional" ? LightType::Directional
                                                    : LightType::Point;
        light.position = glm::vec3(world[3]);
        const glm::dvec3 direction = -glm::dvec3(world[2]);
        const double length = glm::length(direction);
        if (light.type != LightType::Point && !(length > 1e-12)) {
            return fail(element, "the transform is singular, so the light has no direction");
        }
        if (length > 1e-12) light.direction = glm::vec3(direction / length);
        if (source.color.size() == 3) {
            light.color = glm::vec3(source.color[0], source.color[1], source.color[2]);
        }
        light.intensity = float(source.intensity);
        light.range = float(source.range);
        if (light.type == LightType::Spot) {
            light.innerConeAngle = float(source.spot.innerConeAngle);
            light.outerConeAngle = float(source.spot.outerConeAngle);
        }
        mScene.lights.push_back(std::move(light));
        return true;
    }

    // Scene primitive for glTF mesh primitive (mesh, primitive), wound counter-clockwise for
    // a mirroring transform when `flipped`; -1 when the primitive is skipped.
    bool primitiveFor(int mesh, int primitive, bool flipped, int& sceneIndex) {
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

    bool reserveGeometry(const std::string& element, std::uint64_t vertices,
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
    bool readAttribute(const tinygltf::Primitive& source, const std::string& element,
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

    bool decodePrimitive(int mesh, int primitiveIndex, Primitive& out, bool& skipped) {
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
        std::vector<std::size_t> degenerateNormals;
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

        std::vector<std::uint32_t> corners;
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
        if (!toTriangleList(element, mode, corners, out.indices)) return false;
        if (out.indices.empty()) {
            warn(element, "has no triangles; skipped");
            skipped = true;
            return true;
        }
        if (!reserveGeometry(element, vertexCount, out.indices.size())) return false;

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
        for (const glm::vec3& p : out.positions) out.localBounds.extend(p);
        return true;
    }

    // glTF 2.0 section 3.7.2.1: strips and fans to lists, keeping the first triangle's winding.
    bool toTriangleList(const std::string& element, int mode,
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

    // Sum of the (unnormalized, so area-weighted) face normals around each vertex.
    static std::vector<glm::vec3> areaWeightedNormals(const Primitive& primitive) {
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

    // The node hierarchy and every animation channel (glTF 2.0 section 3.11), validated;
    // then the instances they move are marked dynamic and the bounds cover every pose.
    bool readAnimations() {
        mScene.nodes.resize(mModel.nodes.size());
        for (std::size_t i = 0; i < mModel.nodes.size(); ++i) {
            const tinygltf::Node& node = mModel.nodes[i];
            SceneNode& out = mScene.nodes[i];
            out.parent = mParent[i];
            out.matrix = mLocal[i];
            out.hasMatrix = !node.matrix.empty();
            // localTransform validated these arrays.
            if (node.translation.size() == 3) out.translation = glm::make_vec3(node.translation.data());
            if (node.scale.size() == 3) out.scale = glm::make_vec3(node.scale.data());
            if (node.rotation.size() == 4) {
                out.rotation = glm::normalize(glm::dquat(node.rotation[3], node.rotation[0],
                        node.rotation[1], node.rotation[2]));
            }
        }
        bool warnedWeights = false;
        for (std::size_t a = 0; a < mModel.animations.size(); ++a) {
            const tinygltf::Animation& source = mModel.animations[a];
            Animation animation;
            animation.name = source.name.empty() ? indexed("animations", long(a)) : source.name;
            for (std::size_t c = 0; c < source.channels.size(); ++c) {
                const std::string element =
                        indexed("animations", long(a)) + ".channels[" + std::to_string(c) + "]";
                AnimationChannel channel;
                if (!readChannel(source, source.channels[c], element, channel, warnedWeights)) {
                    return false;
                }
                if (channel.node < 0) continue;   // a skipped (morph weights) channel
                animation.duration = std::max(animation.duration, channel.times.back());
                animation.channels.push_back(std::move(channel));
            }
            if (!animation.channels.empty()) mScene.animations.push_back(std::move(animation));
        }
        markDynamicInstances(mScene);
        mScene.bounds = animatedBounds(mScene);
        return true;
    }

    bool readChannel(const tinygltf::Animation& animation, const tinygltf::AnimationChannel& in,
            const std::string& element, AnimationChannel& out, bool& warnedWeights) {
        if (in.target_path == "weights") {
            if (!warnedWeights) warn(element, "morph target weights are not animated; skipped");
            warnedWeights = true;
            return true;
        }
        if (in.target_path == "translation") out.path = AnimationPath::Translation;
        else if (in.target_path == "rotation") out.path = AnimationPath::Rotation;
        else if (in.target_path == "scale") out.path = AnimationPath::Scale;
        else return fail(element, "target.path '" + in.target_path + "' is not translation, "
                                  "rotation, scale or weights");
        if (in.target_node < 0 || std::size_t(in.target_node) >= mModel.nodes.size()) {
            return fail(element, doesNotExist("target.node", in.target_node, mModel.nodes.size(),
                                         "nodes"));
        }
        if (!mModel.nodes[std::size_t(in.target_node)].matrix.empty()) {
            return fail(element, indexed("nodes", in.target_node) +
                                         " has a matrix, and glTF forbids animating such nodes");
        }
        if (in.sampler < 0 || std::size_t(in.sampler) >= animation.samplers.size()) {
            return fail(element, doesNotExist("sampler", in.sampler, animation.samplers.size(),
                                         "samplers of its animation"));
        }
        const tinygltf::AnimationSampler& sampler = animation.samplers[std::size_t(in.sampler)];
        if (sampler.interpolation.empty() || sampler.interpolation == "LINEAR") {
            out.interpolation = AnimationInterpolation::Linear;
        } else if (sampler.interpolation == "STEP") {
            out.interpolation = AnimationInterpolation::Step;
        } else if (sampler.interpolation == "CUBICSPLINE") {
            out.interpolation = AnimationInterpolation::CubicSpline;
        } else {
            return fail(element, "interpolation '" + sampler.interpolation +
                                         "' is not LINEAR, STEP or CUBICSPLINE");
        }
        AccessorFloats input, output;
        std::string error;
        for (const auto& [index, data] : {std::pair{sampler.input, &input}, {sampler.output, &output}}) {
            if (index < 0 || std::size_t(index) >= mModel.accessors.size()) {
                return fail(element, doesNotExist("sampler accessor", index,
                                             mModel.accessors.size(), "accessors"));
            }
            if (!readAccessorFloats(mModel, index, mLimits.maxAccessorCount, *data, error)) {
                return failWith(error);
            }
            for (float v : data->values) {
                if (!std::isfinite(v)) {
                    return fail(element, indexed("accessors", index) + " holds a non-finite value");
                }
            }
        }
        const int components = out.path == AnimationPath::Rotation ? 4 : 3;
        const std::size_t perKey = out.interpolation == AnimationInterpolation::CubicSpline ? 3 : 1;
        if (input.components != 1 || input.count == 0) {
            return fail(element, "its sampler's input must be a non-empty SCALAR accessor of times");
        }
        for (std::size_t k = 0; k < input.count; ++k) {
            if (input.values[k] < 0.0f || (k > 0 && !(input.values[k] > input.values[k - 1]))) {
                return fail(element, "key times must be >= 0 and strictly increasing (key " +
                                             std::to_string(k) + ")");
            }
        }
        if (output.components != components || output.count != input.count * perKey) {
            return fail(element, "its sampler's output has " + std::to_string(output.count) +
                                         " elements of " + std::to_string(output.components) +
                                         " components; " + in.target_path + " needs " +
                                         std::to_string(input.count * perKey) + " of " +
                                         std::to_string(components));
        }
        out.node = in.target_node;
        out.times = input.values;
        out.values.resize(output.count, glm::vec4(0.0f));
        for (std::size_t k = 0; k < output.count; ++k) {
            for (int i = 0; i < components; ++i) {
                out.values[k][i] = output.values[k * std::size_t(components) + std::size_t(i)];
            }
        }
        return true;
    }

    bool computeBounds() {
        for (const Instance& instance : mScene.instances) {
            const Primitive& primitive = mScene.primitives[std::size_t(instance.primitive)];
            for (const glm::vec3& p : primitive.positions) {
                const glm::vec3 world = glm::vec3(instance.worldFromLocal * glm::vec4(p, 1.0f));
                if (!std::isfinite(world.x) || !std::isfinite(world.y) ||
                        !std::isfinite(world.z)) {
                    return fail(indexed("nodes", instance.node),
                            "a vertex placed by this node is not finite in world space");
                }
                mScene.bounds.extend(world);
            }
            // Passes and addDefaults square distances and sum extents in single precision.
            if (glm::any(glm::greaterThan(glm::max(-mScene.bounds.min, mScene.bounds.max),
                        glm::vec3(kMaxCoordinate)))) {
                return fail(indexed("nodes", instance.node),
                        "places vertices beyond +-1e18 m, too far for single precision maths");
            }
        }
        return true;
    }

    const tinygltf::Model& mModel;
    const std::string& mName;
    const FileAccess& mAccess;
    const GltfLimits& mLimits;
    std::vector<std::string>& mWarnings;
    std::string mError;
    Scene mScene;
    std::map<int, int> mTextureMap; // glTF texture -> Scene::textures index
    std::vector<PendingTexture> mPendingTextures;
    std::vector<int> mParent;
    std::vector<glm::dmat4> mLocal;
    std::map<std::tuple<int, int, bool>, int> mPrimitiveCache;
    std::uint64_t mVertexTotal = 0;
    std::uint64_t mIndexTotal = 0;
};

// After tinygltf failed: a clearer message for the common cause, an unreadable external buffer.
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

// tinygltf reads an optional index, byteOffset or byteStride that is negative or not an integer
// as if it were absent; glTF requires non-negative integers, so the JSON itself is checked.
// Returns "<element>: <what>" for the first offender, empty when there is none.
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

// The first bytes of a file that is neither GLB nor a JSON object, for the message.
std::string leadingBytes(const std::uint8_t* data, std::size_t size) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string text;
    for (std::size_t i = 0; i < std::min<std::size_t>(size, 4); ++i) {
        text += std::string(i ? " " : "") + kHex[data[i] >> 4] + kHex[data[i] & 15];
    }
    return text;
}

// True when the text's first character after an optional UTF-8 byte order mark and white
// space opens a JSON object.
bool startsLikeJsonObject(const char* text, std::size_t size) {
    std::size_t i = size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (i < size && space(text[i])) ++i;
    return i < size && text[i] == '{';
}

bool loadFromBytes(const std::uint8_t* data, std::size_t size, const std::string& name,
        const FileAccess& access, Scene& out, std::string& error,
        std::vector<std::string>& warnings, const GltfLimits& limits) {
    auto fail = [&](const std::string& element, const std::string& what) {
        error = name + ": " + element + ": " + what;
        return false;
    };
    if (size == 0) return fail("file", "is empty (0 bytes)");
    if (size > std::size_t(UINT32_MAX)) return fail("file", "larger than 4 GiB");
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const char* json = reinterpret_cast<const char*>(data);
    std::size_t jsonSize = size;
    if (binary) {
        std::string what;
        if (!checkGlbContainer(data, size, json, jsonSize, what)) return fail("GLB header", what);
    } else if (!startsLikeJsonObject(json, jsonSize)) {
        return fail("file", "is neither GLB (magic 'glTF') nor JSON text holding an object (it "
                            "starts with bytes " + leadingBytes(data, size) + ")");
    }
    if (jsonNestingDepth(json, jsonSize) > limits.maxJsonDepth) {
        return fail("JSON", "nesting deeper than " + std::to_string(limits.maxJsonDepth) +
                                    " levels");
    }

    tinygltf::Model model;
    tinygltf::TinyGLTF parser;
    ImageCapture capture;
    capture.model = &model;
    parser.SetImageLoader(&captureEncodedImage, &capture);
    FileAccess fileAccess = access;
    parser.SetFsCallbacks({&fsFileExists, &fsExpandFilePath, &fsReadWholeFile, &fsWriteWholeFile,
            &fileAccess});
    std::string tinyError, tinyWarning;
    const std::string baseDir = access.enabled ? access.prefix : std::string();
    const bool parsed = binary ? parser.LoadBinaryFromMemory(&model, &tinyError, &tinyWarning,
                                         data, unsigned(size), baseDir)
                               : parser.LoadASCIIFromString(&model, &tinyError, &tinyWarning,
                                         json, unsigned(jsonSize), baseDir);
    for (const std::string& line : splitLines(tinyWarning)) {
        warnings.push_back(name + ": glTF: " + line);
    }
    if (!parsed || !tinyError.empty()) {
        if (!capture.error.empty()) {
            error = name + ": " + capture.error;
            return false;
        }
        const std::string buffer = diagnoseBuffers(json, jsonSize, access);
        if (!buffer.empty()) {
            error = name + ": " + buffer;
            return false;
        }
        // tinygltf quotes whole data URIs; a message stays readable at a few hundred bytes.
        constexpr std::size_t kMaxLine = 240;
        std::string joined;
        for (std::string line : splitLines(tinyError)) {
            if (line.size() > kMaxLine) line = line.substr(0, kMaxLine) + "...";
            joined += (joined.empty() ? "" : "; ") + line;
        }
        return fail("glTF", joined.empty() ? "tinygltf could not parse the file" : joined);
    }
    const std::string malformed = checkOptionalIntegers(json, jsonSize);
    if (!malformed.empty()) {
        error = name + ": " + malformed;
        return false;
    }
    SceneBuilder builder(model, name, access, limits, warnings);
    return builder.build(out, error);
}

// Messages quote names and URIs from the file, which may hold line breaks or other control
// characters; every message must stay one printable line.
void makeOneLine(std::string& text) {
    for (char& c : text) {
        if ((unsigned char)c < 0x20 || c == 0x7f) c = ' ';
    }
}

// Runs a load, turning any exception into an error, and keeps every message on one line.
template <class Load>
bool guarded(const std::string& name, std::string& error, std::vector<std::string>& warnings,
        Load load) {
    error.clear();
    const std::size_t firstWarning = warnings.size();
    bool ok = false;
    try {
        ok = load();
    } catch (const std::bad_alloc&) {
        error = name + ": file: out of memory while loading";
    } catch (const std::exception& e) {
        error = name + ": file: " + e.what();
    } catch (...) {
        error = name + ": file: unknown failure while loading";
    }
    makeOneLine(error);
    for (std::size_t i = firstWarning; i < warnings.size(); ++i) makeOneLine(warnings[i]);
    return ok;
}

} // namespace

bool loadGltf(const std::string& path, Scene& out, std::string& error,
        std::vector<std::string>& warnings, const GltfLimits& limits) {
    return guarded(path, error, warnings, [&]() {
        std::vector<unsigned char> bytes;
        std::string reason;
        if (!readWholeFile(path, bytes, reason)) {
            error = path + ": file: cannot read (" + reason + ")";
            return false;
        }
        FileAccess access;
        access.enabled = true;
        const std::string dir = std::filesystem::path(path).parent_path().string();
        access.prefix = joinPath(dir.empty() ? "." : dir, "");
        return loadFromBytes(bytes.data(), bytes.size(), path, access, out, error, warnings,
                limits);
    });
}

bool loadGltfFromMemory(const std::uint8_t* data, std::size_t size,
        const std::string& displayName, const std::string& baseDir, Scene& out,
        std::string& error, std::vector<std::string>& warnings, const GltfLimits& limits) {
    return guarded(displayName, error, warnings, [&]() {
        if (data == nullptr && size > 0) {
            error = displayName + ": file: no data";
            return false;
        }
        static const std::uint8_t kEmpty = 0;
        FileAccess access;
        access.enabled = !baseDir.empty();
        access.prefix = joinPath(baseDir, "");
        return loadFromBytes(data ? data : &kEmpty, size, displayName, access, out, error,
                warnings, limits);
    });
}

} // namespace gi::scene
