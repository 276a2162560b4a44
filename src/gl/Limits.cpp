#include "gl/Limits.h"

#include <algorithm>
#include <cstdio>

namespace gi::gl {

bool fitsResourceBudget(const std::string& what, double bytes, std::string& error) {
    if (bytes <= double(kResourceBudgetBytes)) return true;
    char text[64];
    std::snprintf(text, sizeof text, " needs %.0f MiB, over the %llu MiB budget",
            bytes / (1024.0 * 1024.0),
            static_cast<unsigned long long>(kResourceBudgetBytes >> 20));
    error = what + text;
    return false;
}

bool fitsResourceBudget(const std::string& what, const std::vector<MemoryItem>& items,
        std::string& error) {
    double bytes = 0.0;
    for (const MemoryItem& item : items) bytes += double(item.bytes);
    return fitsResourceBudget(what, bytes, error);
}

int supportedSamples(std::initializer_list<GLenum> formats, int requested) {
    int supported = std::max(requested, 1);
    for (const GLenum format : formats) {
        GLint count = 0;
        glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_NUM_SAMPLE_COUNTS, 1, &count);
        std::vector<GLint> counts(std::size_t(std::max(count, 0)));
        if (!counts.empty()) {
            glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_SAMPLES,
                    GLsizei(counts.size()), counts.data());
        }
        int best = 1;
        for (const GLint c : counts) best = c <= supported ? std::max(best, int(c)) : best;
        supported = best;
    }
    return supported;
}

std::string glErrorName(GLenum error) {
    const char* name = "unknown GL error";
    switch (error) {
    case GL_NO_ERROR: name = "GL_NO_ERROR"; break;
    case GL_INVALID_ENUM: name = "GL_INVALID_ENUM"; break;
    case GL_INVALID_VALUE: name = "GL_INVALID_VALUE"; break;
    case GL_INVALID_OPERATION: name = "GL_INVALID_OPERATION"; break;
    case GL_INVALID_FRAMEBUFFER_OPERATION: name = "GL_INVALID_FRAMEBUFFER_OPERATION"; break;
    case GL_OUT_OF_MEMORY: name = "GL_OUT_OF_MEMORY"; break;
    case GL_STACK_UNDERFLOW: name = "GL_STACK_UNDERFLOW"; break;
    case GL_STACK_OVERFLOW: name = "GL_STACK_OVERFLOW"; break;
    case GL_CONTEXT_LOST: name = "GL_CONTEXT_LOST"; break;
    default: break;
    }
    char text[64];
    std::snprintf(text, sizeof text, "%s (0x%04x)", name, unsigned(error));
    return text;
}

} // namespace gi::gl
