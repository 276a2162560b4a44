// Framebuffers over textures of one size, checked for completeness when they are made.
// RenderTarget owns a colour and/or a depth texture and reallocates them when the size it is
// asked for changes (targets at the output or trace resolution); attachFramebuffer() points a
// framebuffer at textures owned elsewhere (the atlas layers).
#pragma once

#include "gl/Objects.h"

#include <glm/glm.hpp>

#include <initializer_list>
#include <string>

namespace gi::gl {

// One texture of a render target.
struct TargetTexture {
    GLenum format = GL_NONE;   // sized internal format; GL_NONE: no such attachment
    const char* label = "";
    // Sampled with GL_LINEAR and clamped to the edge (read at another resolution); otherwise
    // the texture keeps GL's default sampling state.
    bool bilinear = false;
};

// A one-level 2D texture of `size` as `texture` describes (also for compute-written images).
[[nodiscard]] Texture createTargetTexture(const TargetTexture& texture, glm::ivec2 size);

// Makes `framebuffer` (labelled `label`) draw into `colors` (attachment i = colors[i]; a
// nullptr entry leaves draw buffer i unattached, its output dropped) and `depth` (nullptr:
// none). False with a message naming it if the result is incomplete.
[[nodiscard]] bool attachFramebuffer(Framebuffer& framebuffer, const char* label,
        std::initializer_list<const Texture*> colors, const Texture* depth, std::string& error);

class RenderTarget {
public:
    RenderTarget(const char* label, TargetTexture color, TargetTexture depth = {})
            : mLabel(label), mColorSpec(color), mDepthSpec(depth) {}

    // Reallocates the textures at `size` (at least 1x1) and `samples` a texel (1: plain 2D
    // textures, more: multisampled ones) when either differs from the current one.
    // An incomplete framebuffer is reported on stderr: the formats are fixed, so it can only
    // mean a driver without them, and the frame goes on (drawing nothing into it).
    void resize(glm::ivec2 size, int samples = 1);
    // Binds the framebuffer for drawing with a viewport covering it.
    void bind() const;
    // Clears colour to 0 and depth to 1 (enabling their write masks, which gate clears).
    void clear() const;

    const Texture& color() const { return mColor; }
    const Texture& depth() const { return mDepth; }
    const Framebuffer& framebuffer() const { return mFramebuffer; }
    glm::ivec2 size() const { return mSize; }
    int samples() const { return mSamples; }

private:
    const char* mLabel;
    TargetTexture mColorSpec, mDepthSpec;
    Texture mColor, mDepth;
    Framebuffer mFramebuffer;
    glm::ivec2 mSize{0};
    int mSamples = 1;
};

} // namespace gi::gl
