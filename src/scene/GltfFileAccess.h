// The files a glTF scene may read besides itself: external buffers and images, only regular
// files under the scene's directory, opened through callbacks handed to tinygltf. Also the
// messages for a buffer that cannot be read, clearer than tinygltf's (which quote whole URIs).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gi::scene::gltf {

inline bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

std::string joinPath(const std::string& dir, const std::string& file);

// Reads a whole regular file; on failure `reason` says why (strerror wording).
bool readWholeFile(const std::string& path, std::vector<unsigned char>& out, std::string& reason);

// File access handed to tinygltf: only regular files under the glTF file's directory
// (tinygltf also tries the working directory; that fallback is refused), never when the scene
// was loaded from memory without a base directory.
struct FileAccess {
    bool enabled = false;
    std::string prefix; // base directory ending in '/'
};

// tinygltf's file system callbacks; `user` is the FileAccess.
bool fsFileExists(const std::string& path, void* user);
std::string fsExpandFilePath(const std::string& path, void*);
bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
        void* user);
bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&,
        void*);

// Why an external file cannot serve as a buffer of `byteLength` bytes; empty when it can.
std::string externalFileProblem(const FileAccess& access, const std::string& uri,
        std::uint64_t byteLength, bool checkSize);

// Why a data URI cannot serve as a buffer of `byteLength` bytes; empty when it can. Spares the
// user tinygltf's message, which quotes the whole URI.
std::string dataUriProblem(const std::string& uri, std::uint64_t byteLength);

} // namespace gi::scene::gltf
