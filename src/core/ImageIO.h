// Image files: PNG (the linear values at exposure 1, clamped, sRGB-encoded, per DESIGN.md),
// linear HDR as OpenEXR (tinyexr, 32-bit float) or PFM. Writers go through a temporary file
// renamed into place, so a failed write never leaves a partial file that looks finished.
#pragma once

#include "core/Image.h"

#include <string>

namespace gi::core {

[[nodiscard]] bool writePng(const std::string& path, const Image& image, std::string& error);
// Chooses EXR or PFM from the extension (.exr / .pfm).
[[nodiscard]] bool writeHdr(const std::string& path, const Image& image, std::string& error);

// PNG readers return the decoded sRGB values converted back to linear.
[[nodiscard]] bool readPng(const std::string& path, Image& image, std::string& error);
[[nodiscard]] bool readHdr(const std::string& path, Image& image, std::string& error);

// Checks that `path` can be created (its directory exists and is writable) without leaving
// anything behind, so a long render fails before it starts rather than after.
[[nodiscard]] bool checkWritable(const std::string& path, std::string& error);

[[nodiscard]] bool hasExtension(const std::string& path, const std::string& extension);

} // namespace gi::core
