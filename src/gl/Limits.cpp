#include "gl/Limits.h"

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
