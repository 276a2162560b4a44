#include "core/ImageIO.h"

#include "core/Colour.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace gi::core {
namespace {

std::string temporaryPath(const std::string& path) {
    return path + ".partial-" + std::to_string(::getpid());
}

// Moves the finished temporary file into place; removes it on failure.
bool commit(const std::string& temporary, const std::string& path, std::string& error) {
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        error = path + ": cannot write file (" + ec.message() + ")";
        return false;
    }
    return true;
}

bool fail(const std::string& temporary, const std::string& message, std::string& error) {
    std::error_code ec;
    std::filesystem::remove(temporary, ec);
    error = message;
    return false;
}

bool writePfm(const std::string& file, const Image& image) {
    std::FILE* out = std::fopen(file.c_str(), "wb");
    if (!out) return false;
    // PFM: "PF" colour, negative scale = little-endian, rows stored bottom to top.
    std::fprintf(out, "PF\n%d %d\n-1.0\n", image.width, image.height);
    bool ok = true;
    for (int y = image.height - 1; y >= 0 && ok; --y) {
        const float* row = image.rgb.data() + std::size_t(y) * std::size_t(image.width) * 3;
        ok = std::fwrite(row, sizeof(float), std::size_t(image.width) * 3, out) ==
             std::size_t(image.width) * 3;
    }
    return std::fclose(out) == 0 && ok;
}

bool readPfm(const std::string& path, Image& image, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int width = 0, height = 0;
    float scale = 0.0f;
    if (!(in >> magic >> width >> height >> scale) || magic != "PF" || width <= 0 ||
            height <= 0 || width > 65536 || height > 65536 || scale >= 0.0f) {
        error = path + ": not a little-endian colour PFM file";
        return false;
    }
    in.get();
    Image result(width, height);
    for (int y = height - 1; y >= 0; --y) {
        in.read(reinterpret_cast<char*>(result.rgb.data() + std::size_t(y) * std::size_t(width) * 3),
                std::streamsize(std::size_t(width) * 3 * sizeof(float)));
    }
    if (!in) {
        error = path + ": PFM file is truncated";
        return false;
    }
    image = std::move(result);
    return true;
}

} // namespace

bool hasExtension(const std::string& path, const std::string& extension) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == extension;
}

bool checkWritable(const std::string& path, std::string& error) {
    const std::filesystem::path file(path);
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        error = path + ": is a directory, not an output file";
        return false;
    }
    const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : ".";
    if (!std::filesystem::is_directory(dir, ec)) {
        error = path + ": output directory " + dir.string() + " does not exist";
        return false;
    }
    if (::access(dir.c_str(), W_OK) != 0) {
        error = path + ": output directory " + dir.string() + " is not writable";
        return false;
    }
    return true;
}

bool writePng(const std::string& path, const Image& image, std::string& error) {
    std::vector<unsigned char> bytes(image.rgb.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const float encoded = core::linearToSrgb(image.rgb[i]);
        bytes[i] = static_cast<unsigned char>(std::lround(encoded * 255.0f));
    }
    const std::string temporary = temporaryPath(path);
    if (!stbi_write_png(temporary.c_str(), image.width, image.height, 3, bytes.data(),
                image.width * 3)) {
        return fail(temporary, path + ": cannot write PNG file", error);
    }
    return commit(temporary, path, error);
}

bool writeHdr(const std::string& path, const Image& image, std::string& error) {
    const std::string temporary = temporaryPath(path);
    if (hasExtension(path, ".pfm")) {
        if (!writePfm(temporary, image)) return fail(temporary, path + ": cannot write PFM file", error);
        return commit(temporary, path, error);
    }
    if (!hasExtension(path, ".exr")) {
        error = path + ": HDR output must end in .exr or .pfm";
        return false;
    }
    const char* exrError = nullptr;
    if (SaveEXR(image.rgb.data(), image.width, image.height, 3, 0, temporary.c_str(), &exrError) !=
            TINYEXR_SUCCESS) {
        std::string message = path + ": cannot write EXR file";
        if (exrError) {
            message += std::string(" (") + exrError + ")";
            FreeEXRErrorMessage(exrError);
        }
        return fail(temporary, message, error);
    }
    return commit(temporary, path, error);
}

bool readPng(const std::string& path, Image& image, std::string& error) {
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
    if (!pixels) {
        error = path + ": cannot read PNG (" + (stbi_failure_reason() ? stbi_failure_reason() : "?") + ")";
        return false;
    }
    Image result(width, height);
    for (std::size_t i = 0; i < result.rgb.size(); ++i) {
        result.rgb[i] = core::srgbToLinear(float(pixels[i]) / 255.0f);
    }
    stbi_image_free(pixels);
    image = std::move(result);
    return true;
}

bool readHdr(const std::string& path, Image& image, std::string& error) {
    if (hasExtension(path, ".pfm")) return readPfm(path, image, error);
    float* rgba = nullptr;
    int width = 0, height = 0;
    const char* exrError = nullptr;
    if (LoadEXR(&rgba, &width, &height, path.c_str(), &exrError) != TINYEXR_SUCCESS) {
        error = path + ": cannot read EXR file";
        if (exrError) {
            error += std::string(" (") + exrError + ")";
            FreeEXRErrorMessage(exrError);
        }
        return false;
    }
    Image result(width, height);
    for (std::size_t p = 0; p < std::size_t(width) * std::size_t(height); ++p) {
        for (int c = 0; c < 3; ++c) result.rgb[p * 3 + std::size_t(c)] = rgba[p * 4 + std::size_t(c)];
    }
    std::free(rgba);
    image = std::move(result);
    return true;
}

} // namespace gi::core
