// Decodes the PNG and JPEG images glTF 2.0 allows into RGBA8, always 4 channels: grey, grey+alpha
// and RGB images are expanded (grey replicated, alpha 255), 16-bit PNGs are reduced to 8 bits.
// stb_image is compiled privately into ImageDecoder.cpp (static functions), so the decoder never
// depends on how the system libstb was built, can check an image's size before it allocates,
// and is safe to call from several threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gi::scene {

struct DecodedImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba8; // width * height * 4 bytes, rows top to bottom
};

// Reads only the header: the image's size in pixels. Fails (with a reason) when the bytes are
// not a PNG or JPEG header stb_image understands.
[[nodiscard]] bool readImageSize(const std::uint8_t* bytes, std::size_t size, int& width,
        int& height, std::string& error);

// Fails with a one-phrase reason in `error` (no file name) when the bytes are not a PNG or
// JPEG stb_image can decode, or when the image has more than maxPixels pixels (checked from
// the header, before any pixel memory is allocated).
[[nodiscard]] bool decodeImageRgba8(const std::uint8_t* bytes, std::size_t size,
        std::uint64_t maxPixels, DecodedImage& out, std::string& error);

} // namespace gi::scene
