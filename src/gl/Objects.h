// Creation helpers for the GL objects the passes use. Each allocates immutable storage with
// the DSA entry points, labels the object (the label shows in debug output and captures) and
// records the storage's size in gl/MemoryRegistry.h, which the memory reports read. They are
// the only place in src/ that allocates texture or buffer storage.
#pragma once

#include "gl/Handle.h"
#include "gl/MemoryRegistry.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace gi::gl {

// Bytes per texel of the sized internal formats the project uses (0 for unknown formats).
[[nodiscard]] std::size_t bytesPerTexel(GLenum internalFormat);

// Bytes of immutable storage for a texture of `size` texels with `levels` mip levels (layers
// and cube faces count in size.z).
[[nodiscard]] std::size_t textureBytes(GLenum internalFormat, glm::ivec3 size, int levels);

[[nodiscard]] Buffer createBuffer(std::size_t bytes, const void* data, GLbitfield flags,
        const char* label);
[[nodiscard]] Texture createTexture2D(GLenum internalFormat, glm::ivec2 size, int levels,
        const char* label);
// `samples` samples a texel at fixed positions (a multisampled render target).
[[nodiscard]] Texture createTexture2DMultisample(GLenum internalFormat, glm::ivec2 size,
        int samples, const char* label);
[[nodiscard]] Texture createTexture3D(GLenum internalFormat, glm::ivec3 size, int levels,
        const char* label);
[[nodiscard]] Texture createTextureCubeArray(GLenum internalFormat, int size, int layers,
        const char* label);
[[nodiscard]] Texture createTexture2DArray(GLenum internalFormat, glm::ivec2 size, int layers,
        const char* label);
[[nodiscard]] Framebuffer createFramebuffer(const char* label);
[[nodiscard]] VertexArray createVertexArray(const char* label);
[[nodiscard]] Sampler createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap,
        const char* label);

// Checks glCheckNamedFramebufferStatus; on failure writes a message naming the framebuffer.
[[nodiscard]] bool framebufferComplete(const Framebuffer& framebuffer, const char* label,
        std::string& error);

// Number of mip levels of a full chain for the largest of the given extents.
[[nodiscard]] int fullMipCount(int largestExtent);

} // namespace gi::gl
