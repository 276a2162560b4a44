#include "gl/RenderTarget.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace gi::gl {

Texture createTargetTexture(const TargetTexture& spec, glm::ivec2 size) {
    Texture texture = createTexture2D(spec.format, size, 1, spec.label);
    if (spec.bilinear) {
        glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    return texture;
}

bool attachFramebuffer(Framebuffer& framebuffer, const char* label,
        std::initializer_list<const Texture*> colors, const Texture* depth, std::string& error) {
    framebuffer = createFramebuffer(label);
    std::vector<GLenum> drawBuffers;
    for (const Texture* color : colors) {
        const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(drawBuffers.size());
        if (color) glNamedFramebufferTexture(framebuffer.id(), attachment, color->id(), 0);
        drawBuffers.push_back(color ? attachment : GL_NONE);
    }
    if (depth) glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth->id(), 0);
    if (drawBuffers.empty()) {
        glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(framebuffer.id(), GLsizei(drawBuffers.size()),
                drawBuffers.data());
    }
    return framebufferComplete(framebuffer, label, error);
}

void RenderTarget::resize(glm::ivec2 size, int samples) {
    size = glm::max(size, glm::ivec2(1));
    samples = std::max(samples, 1);
    if (size == mSize && samples == mSamples && mFramebuffer) return;
    mSize = size;
    mSamples = samples;
    auto create = [&](const TargetTexture& spec) {
        if (spec.format == GL_NONE) return Texture();
        return samples > 1 ? createTexture2DMultisample(spec.format, size, samples, spec.label)
                           : createTargetTexture(spec, size);
    };
    mColor = create(mColorSpec);
    mDepth = create(mDepthSpec);
    std::string error;
    const bool complete = mColor
            ? attachFramebuffer(mFramebuffer, mLabel, {&mColor}, mDepth ? &mDepth : nullptr, error)
            : attachFramebuffer(mFramebuffer, mLabel, {}, mDepth ? &mDepth : nullptr, error);
    if (!complete) std::fprintf(stderr, "%s\n", error.c_str());
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mSize.x, mSize.y);
}

void RenderTarget::clear() const {
    if (mColor) {
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 0, zero);
    }
    if (mDepth) {
        const float clearDepth = 1.0f;
        glDepthMask(GL_TRUE);
        glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &clearDepth);
    }
}

} // namespace gi::gl
