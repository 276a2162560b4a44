// Move-only RAII ownership of OpenGL object names. Every GL object in the project lives in a
// gl::Handle created with glCreate* (direct state access) and labelled for debuggers; the
// destructor deletes it. Copies are impossible, so an object is deleted exactly once.
#pragma once

#include "gl/MemoryRegistry.h"

#include <glad/gl.h>

#include <utility>

namespace gi::gl {

template <class Traits>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) noexcept : mId(id) {}
    Handle(Handle&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        reset(std::exchange(other.mId, 0));
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }

    GLuint id() const noexcept { return mId; }
    explicit operator bool() const noexcept { return mId != 0; }
    // Gives up ownership, for interop with code that deletes the object itself. A texture's or
    // buffer's entry in gl/MemoryRegistry.h stays: its memory is still allocated.
    GLuint release() noexcept { return std::exchange(mId, 0); }
    void reset(GLuint id = 0) noexcept {
        if (mId) Traits::destroy(mId);
        mId = id;
    }

private:
    GLuint mId = 0;
};

// Textures and buffers leave the memory record (gl/MemoryRegistry.h) as they are deleted.
struct BufferTraits {
    static void destroy(GLuint id) {
        forgetAllocation(StorageKind::Buffer, id);
        glDeleteBuffers(1, &id);
    }
};
struct TextureTraits {
    static void destroy(GLuint id) {
        forgetAllocation(StorageKind::Texture, id);
        glDeleteTextures(1, &id);
    }
};
struct FramebufferTraits { static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); } };
struct VertexArrayTraits { static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); } };
struct SamplerTraits { static void destroy(GLuint id) { glDeleteSamplers(1, &id); } };
struct QueryTraits { static void destroy(GLuint id) { glDeleteQueries(1, &id); } };
struct ProgramTraits { static void destroy(GLuint id) { glDeleteProgram(id); } };
struct ShaderTraits { static void destroy(GLuint id) { glDeleteShader(id); } };

using Buffer = Handle<BufferTraits>;
using Texture = Handle<TextureTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Sampler = Handle<SamplerTraits>;
using Query = Handle<QueryTraits>;
using Program = Handle<ProgramTraits>;
using Shader = Handle<ShaderTraits>;

} // namespace gi::gl
