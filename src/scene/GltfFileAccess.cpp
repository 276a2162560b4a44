#include "scene/GltfFileAccess.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace gi::scene::gltf {
namespace {

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

} // namespace

std::string joinPath(const std::string& dir, const std::string& file) {
    if (dir.empty()) return file;
    return dir.back() == '/' ? dir + file : dir + "/" + file;
}

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

} // namespace gi::scene::gltf
