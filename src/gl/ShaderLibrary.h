// Builds GLSL programs from files under shaders/. The library expands `#include "..."` itself
// (no dependence on GL_ARB_shading_language_include), inserts `#version 450 core`, then the
// variant #defines, then `#line 1 <fileIndex>`, and keeps the fileIndex -> path table so a
// driver message "0:42(5): error" is reported as "shaders/render/forward.frag:42: error".
// Programs are owned here and handed out as ProgramRef, so a hot reload (R in the viewer)
// swaps a program in place; a reload that fails keeps the previous program.
#pragma once

#include "gl/Handle.h"

#include <deque>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gi::gl {

struct ShaderStage {
    GLenum type;          // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
    std::string path;     // relative to the shader root, e.g. "render/forward.vert"
};

struct ProgramDesc {
    std::string name;                  // pass name, e.g. "render/forward"
    std::vector<ShaderStage> stages;
    std::vector<std::string> defines;  // "NAME" or "NAME VALUE"
};

class ShaderLibrary;

// The slot a program lives in; its address stays fixed while the library exists.
struct ProgramEntry {
    Program program;
};

// A stable reference to a program owned by a ShaderLibrary; id() follows hot reloads.
class ProgramRef {
public:
    ProgramRef() = default;
    GLuint id() const { return mEntry ? mEntry->program.id() : 0; }
    explicit operator bool() const { return mEntry != nullptr; }

private:
    friend class ShaderLibrary;
    explicit ProgramRef(const ProgramEntry* entry) : mEntry(entry) {}
    const ProgramEntry* mEntry = nullptr;
};

class ShaderLibrary {
public:
    // Shader root: $VOXATLAS_SHADER_DIR if set, else <source tree>/shaders.
    ShaderLibrary();
    explicit ShaderLibrary(std::filesystem::path root);

    // Compiles and links; on failure returns an empty ref and writes every error, one per
    // line, as "<path>:<line>: <driver message>" followed by the active defines.
    [[nodiscard]] ProgramRef build(const ProgramDesc& desc, std::string& error);

    // Rebuilds every program from the files on disk; programs that fail keep their old
    // binary. Returns false and the messages if anything failed.
    bool reloadAll(std::string& errors);

    // The source that was handed to the driver for one stage, after include expansion
    // (exposed for tests of the expansion and the #line mapping).
    [[nodiscard]] bool preprocess(const std::string& path, const std::vector<std::string>& defines,
            std::string& source, std::string& error);

    // Maps a driver info log back to file paths and lines.
    [[nodiscard]] std::string mapLog(const std::string& log) const;

    const std::filesystem::path& root() const { return mRoot; }

private:
    bool compile(const ProgramDesc& desc, Program& program, std::string& error);
    bool expand(const std::filesystem::path& file, int depth, std::string& out,
            std::string& error);
    int fileIndex(const std::string& relativePath);

    std::filesystem::path mRoot;
    std::vector<std::string> mFiles;  // fileIndex -> path relative to the shader root
    std::deque<std::pair<ProgramDesc, ProgramEntry>> mPrograms;
};

} // namespace gi::gl
