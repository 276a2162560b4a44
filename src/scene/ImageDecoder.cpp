#include "scene/ImageDecoder.h"

#include <climits>
#include <cstring>
#include <memory>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wshadow"
#if defined(__clang__)
#pragma GCC diagnostic ignored "-Wunknown-warning-option"
#else
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#define STBI_NO_HDR
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace gi::scene {

bool readImageSize(const std::uint8_t* bytes, std::size_t size, int& width, int& height,
        std::string& error) {
    if (bytes == nullptr || size == 0) {
        error = "the image is empty";
        return false;
    }
    if (size > std::size_t(INT_MAX)) {
        error = "the encoded image is larger than 2 GiB";
        return false;
    }
    int channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels)) {
        // stbi_info tries every format and reports the last one's failure, so an image with a
        // PNG or JPEG signature is read again by that format's own reader, for its own reason.
        static constexpr std::uint8_t kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        const bool png = size >= sizeof kPng && std::memcmp(bytes, kPng, sizeof kPng) == 0;
        const bool jpeg = size >= 2 && bytes[0] == 0xff && bytes[1] == 0xd8;
        if (png || jpeg) {
            stbi__context context;
            stbi__start_mem(&context, bytes, int(size));
            if (png ? stbi__png_info(&context, nullptr, nullptr, nullptr) == 0
                    : stbi__jpeg_info(&context, nullptr, nullptr, nullptr) == 0) {
                error = std::string(png ? "a PNG" : "a JPEG") + " stb_image cannot read (" +
                        stbi_failure_reason() + ")";
                return false;
            }
        }
        error = std::string("not a PNG or JPEG image stb_image can read (") +
                stbi_failure_reason() + ")";
        return false;
    }
    return true;
}

bool decodeImageRgba8(const std::uint8_t* bytes, std::size_t size, std::uint64_t maxPixels,
        DecodedImage& out, std::string& error) {
    int width = 0, height = 0, channels = 0;
    if (!readImageSize(bytes, size, width, height, error)) return false;
    const int length = int(size);
    if (width < 1 || height < 1 || std::uint64_t(width) * std::uint64_t(height) > maxPixels) {
        error = std::to_string(width) + "x" + std::to_string(height) +
                " pixels is outside the loader's limit of 1.." + std::to_string(maxPixels);
        return false;
    }
    int decodedWidth = 0, decodedHeight = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
            stbi_load_from_memory(bytes, length, &decodedWidth, &decodedHeight, &channels, 4),
            stbi_image_free);
    if (!pixels) {
        error = std::string("cannot decode the image (") + stbi_failure_reason() + ")";
        return false;
    }
    if (decodedWidth != width || decodedHeight != height) {
        error = "the image's header and its pixel data disagree on its size";
        return false;
    }
    out.width = width;
    out.height = height;
    const std::size_t byteCount = std::size_t(width) * std::size_t(height) * 4;
    out.rgba8.resize(byteCount);
    std::memcpy(out.rgba8.data(), pixels.get(), byteCount);
    return true;
}

} // namespace gi::scene
