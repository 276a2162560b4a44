#include "gl/ShaderLibrary.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace gi::gl {
namespace {

constexpr int kMaxIncludeDepth = 16;

bool readFile(const std::filesystem::path& path, std::string& text) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return false;
    std::ostringstream buffer;
    buffer << file.rdbuf();
    text = buffer.str();
    return true;
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    if (isProgram) glGetProgramInfoLog(object, length, nullptr, log.data());
    else glGetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

std::string definesLine(const std::vector<std::string>& defines) {
    if (defines.empty()) return "";
    std::string line = "\n  (defines:";
    for (const auto& d : defines) line += " " + d;
    return line + ")";
}

} // namespace

ShaderLibrary::ShaderLibrary()
    : ShaderLibrary([] {
          const char* env = std::getenv("VOXATLAS_SHADER_DIR");
          return std::filesystem::path(env && *env ? env : VOXATLAS_DATA_DIR "/shaders");
      }()) {}

ShaderLibrary::ShaderLibrary(std::filesystem::path root) : mRoot(std::move(root)) {}

int ShaderLibrary::fileIndex(const std::string& relativePath) {
    for (std::size_t i = 0; i < mFiles.size(); ++i) {
        if (mFiles[i] == relativePath) return int(i);
    }
    mFiles.push_back(relativePath);
    return int(mFiles.size() - 1);
}

bool ShaderLibrary::expand(const std::filesystem::path& file, int depth, std::string& out,
        std::string& error) {
    const std::string relative = file.lexically_relative(mRoot).generic_string();
    if (depth > kMaxIncludeDepth) {
        error = "shaders/" + relative + ": includes nested deeper than " +
                std::to_string(kMaxIncludeDepth) + " (a cycle?)";
        return false;
    }
    std::string text;
    if (!readFile(file, text)) {
        error = "shaders/" + relative + ": cannot read file";
        return false;
    }
    const int index = fileIndex(relative);
    static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    std::istringstream lines(text);
    std::string line;
    int lineNumber = 0;
    out += "#line 1 " + std::to_string(index) + "\n";
    while (std::getline(lines, line)) {
        ++lineNumber;
        std::smatch match;
        if (std::regex_match(line, match, includeLine)) {
            std::filesystem::path target = file.parent_path() / match[1].str();
            if (!std::filesystem::exists(target)) target = mRoot / match[1].str();
            if (!std::filesystem::exists(target)) {
                error = "shaders/" + relative + ":" + std::to_string(lineNumber) +
                        ": included file \"" + match[1].str() + "\" not found";
                return false;
            }
            if (!expand(target.lexically_normal(), depth + 1, out, error)) return false;
            out += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
        } else {
            out += line;
            out += '\n';
        }
    }
    return true;
}

bool ShaderLibrary::preprocess(const std::string& path, const std::vector<std::string>& defines,
        std::string& source, std::string& error) {
    source = "#version 450 core\n";
    for (const auto& define : defines) source += "#define " + define + "\n";
    return expand((mRoot / path).lexically_normal(), 0, source, error);
}

std::string ShaderLibrary::mapLog(const std::string& log) const {
    // Mesa writes "0:42(5): error: ..."; other drivers "0(42) : error ...". Both start with
    // the source-string number, which is our file index.
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex other(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream lines(log);
    std::string line, result;
    while (std::getline(lines, line)) {
        std::smatch m;
        std::string mapped = line;
        auto name = [&](const std::string& index) {
            const std::size_t i = std::stoul(index);
            return i < mFiles.size() ? "shaders/" + mFiles[i] : "shader string " + index;
        };
        if (std::regex_match(line, m, mesa)) mapped = name(m[1]) + ":" + m[2].str() + ": " + m[4].str();
        else if (std::regex_match(line, m, other)) mapped = name(m[1]) + ":" + m[2].str() + ": " + m[3].str();
        if (!result.empty()) result += '\n';
        result += mapped;
    }
    return result;
}

bool ShaderLibrary::compile(const ProgramDesc& desc, Program& program, std::string& error) {
    Program linked(glCreateProgram());
    glObjectLabel(GL_PROGRAM, linked.id(), -1, desc.name.c_str());
    std::vector<Shader> shaders;
    for (const ShaderStage& stage : desc.stages) {
        std::string source;
        if (!preprocess(stage.path, desc.defines, source, error)) return false;
        Shader shader(glCreateShader(stage.type));
        const char* text = source.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            error = mapLog(infoLog(shader.id(), false)) + definesLine(desc.defines);
            return false;
        }
        glAttachShader(linked.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(linked.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(linked.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        error = desc.name + ": link failed: " + mapLog(infoLog(linked.id(), true)) +
                definesLine(desc.defines);
        return false;
    }
    for (const Shader& shader : shaders) glDetachShader(linked.id(), shader.id());
    program = std::move(linked);
    return true;
}

ProgramRef ShaderLibrary::build(const ProgramDesc& desc, std::string& error) {
    Program program;
    if (!compile(desc, program, error)) return {};
    auto& slot = mPrograms.emplace_back(desc, ProgramEntry{});
    slot.second.program = std::move(program);
    return ProgramRef(&slot.second);
}

bool ShaderLibrary::reloadAll(std::string& errors) {
    bool allOk = true;
    for (auto& [desc, entry] : mPrograms) {
        Program program;
        std::string error;
        if (compile(desc, program, error)) {
            entry.program = std::move(program);
        } else {
            allOk = false;
            if (!errors.empty()) errors += '\n';
            errors += error;
        }
    }
    return allOk;
}

} // namespace gi::gl
