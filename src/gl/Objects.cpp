#include "gl/Objects.h"

#include <algorithm>
#include <cstdio>

namespace gi::gl {
namespace {

void label(GLenum type, GLuint id, const char* name) {
    if (name && *name) glObjectLabel(type, id, -1, name);
}

// Array layers and cube faces count in size.z. textureBytes() halves z at each level, which
// is right only for 3D textures: the array helpers allocate a single level.
void recordTexture(GLuint id, const char* name, GLenum internalFormat, glm::ivec3 size,
        int levels) {
    recordAllocation(StorageKind::Texture, id, name, textureBytes(internalFormat, size, levels));
}

} // namespace

std::size_t bytesPerTexel(GLenum internalFormat) {
    switch (internalFormat) {
    case GL_R8: case GL_R8UI: return 1;
    case GL_RG8: case GL_R16F: case GL_DEPTH_COMPONENT16: return 2;
    case GL_RGBA8: case GL_RGBA8_SNORM: case GL_SRGB8_ALPHA8: case GL_R32UI: case GL_R32F: case GL_RG16F:
    case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8:
    case GL_R11F_G11F_B10F: case GL_RGB10_A2: case GL_R32I:
        return 4;
    case GL_RGBA16F: case GL_RG32F: case GL_RGBA16: return 8;
    case GL_RGBA32F: case GL_RGBA32UI: return 16;
    default: return 0;
    }
}

Buffer createBuffer(std::size_t bytes, const void* data, GLbitfield flags, const char* name) {
    // GL refuses empty storage; an empty table still needs an object to bind.
    const std::size_t allocated = std::max<std::size_t>(bytes, 1);
    GLuint id = 0;
    glCreateBuffers(1, &id);
    glNamedBufferStorage(id, GLsizeiptr(allocated), data, flags);
    label(GL_BUFFER, id, name);
    recordAllocation(StorageKind::Buffer, id, name, allocated);
    return Buffer(id);
}

Texture createTexture2D(GLenum internalFormat, glm::ivec2 size, int levels, const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, levels, internalFormat, size.x, size.y);
    label(GL_TEXTURE, id, name);
    recordTexture(id, name, internalFormat, {size, 1}, levels);
    return Texture(id);
}

Texture createTexture2DMultisample(GLenum internalFormat, glm::ivec2 size, int samples,
        const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
    glTextureStorage2DMultisample(id, samples, internalFormat, size.x, size.y, GL_TRUE);
    label(GL_TEXTURE, id, name);
    recordTexture(id, name, internalFormat, {size, samples}, 1);   // a sample weighs a texel
    return Texture(id);
}

Texture createTexture3D(GLenum internalFormat, glm::ivec3 size, int levels, const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    glTextureStorage3D(id, levels, internalFormat, size.x, size.y, size.z);
    label(GL_TEXTURE, id, name);
    recordTexture(id, name, internalFormat, size, levels);
    return Texture(id);
}

Texture createTextureCubeArray(GLenum internalFormat, int size, int layers, const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP_ARRAY, 1, &id);
    glTextureStorage3D(id, 1, internalFormat, size, size, 6 * layers);
    label(GL_TEXTURE, id, name);
    recordTexture(id, name, internalFormat, {size, size, 6 * layers}, 1);
    return Texture(id);
}

Texture createTexture2DArray(GLenum internalFormat, glm::ivec2 size, int layers,
        const char* name) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glTextureStorage3D(id, 1, internalFormat, size.x, size.y, layers);
    label(GL_TEXTURE, id, name);
    recordTexture(id, name, internalFormat, {size, layers}, 1);
    return Texture(id);
}

Framebuffer createFramebuffer(const char* name) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    label(GL_FRAMEBUFFER, id, name);
    return Framebuffer(id);
}

VertexArray createVertexArray(const char* name) {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    label(GL_VERTEX_ARRAY, id, name);
    return VertexArray(id);
}

Sampler createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap, const char* name) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, GLint(wrap));
    label(GL_SAMPLER, id, name);
    return Sampler(id);
}

bool framebufferComplete(const Framebuffer& framebuffer, const char* name, std::string& error) {
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return true;
    error = std::string("framebuffer ") + name + " is incomplete (status 0x" +
            [&] {
                char hex[16];
                std::snprintf(hex, sizeof hex, "%04X", status);
                return std::string(hex);
            }() + ")";
    return false;
}

std::size_t textureBytes(GLenum internalFormat, glm::ivec3 size, int levels) {
    std::size_t texels = 0;
    for (int level = 0; level < levels; ++level) {
        texels += std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z);
        size = glm::max(size / 2, glm::ivec3(1));
    }
    return texels * bytesPerTexel(internalFormat);
}

int fullMipCount(int largestExtent) {
    int levels = 1;
    while (largestExtent > 1) {
        largestExtent /= 2;
        ++levels;
    }
    return levels;
}

} // namespace gi::gl
