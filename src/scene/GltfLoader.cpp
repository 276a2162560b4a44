#include "scene/GltfLoader.h"

#include "scene/GltfContainerChecks.h"
#include "scene/GltfFileAccess.h"
#include "scene/GltfMessages.h"
#include "scene/GltfSceneBuilder.h"

#include <tiny_gltf.h>

#include <climits>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <sstream>

namespace gi::scene {
namespace {

using namespace gltf;

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
