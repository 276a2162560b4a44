// Limits every large GPU allocation is checked against before it is made, and the names of GL
// errors for messages. Drivers differ in how they fail past their memory: llvmpipe may take
// the allocation and then swap or abort mid-frame, a GPU may return GL_OUT_OF_MEMORY later.
// So the voxel cascades, the atlas layers and the shadow maps are each refused up front, with
// a message naming the setting, when they would exceed one budget.
#pragma once

#include "gl/Objects.h"

#include <glad/gl.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace gi::gl {

// The most one resource (voxel cascades, atlas layers, shadow maps) may take: 2 GiB.
inline constexpr std::uint64_t kResourceBudgetBytes = std::uint64_t(2) << 30;

// True when `items` fit the budget; else false with "<what> needs N MiB of <kind>, over the
// 2048 MiB budget" in `error`.
[[nodiscard]] bool fitsResourceBudget(const std::string& what, const std::vector<MemoryItem>& items,
        std::string& error);
[[nodiscard]] bool fitsResourceBudget(const std::string& what, double bytes, std::string& error);

// The most samples a texel, up to `requested`, that multisampled 2D textures of every one of
// `formats` support (1 when some format has none); llvmpipe takes 4 for RGBA32F.
[[nodiscard]] int supportedSamples(std::initializer_list<GLenum> formats, int requested);

// "GL_OUT_OF_MEMORY (0x0505)" and the like.
[[nodiscard]] std::string glErrorName(GLenum error);

} // namespace gi::gl
