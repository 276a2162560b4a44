#include "gl/ProgramVariants.h"

#include <cstdio>

namespace gi::gl {

bool ProgramVariants::init(ShaderLibrary& shaders, ProgramDesc desc, std::string& error) {
    mShaders = &shaders;
    mDesc = std::move(desc);
    mVariants.clear();
    mGeneric = shaders.build(mDesc, error);
    return bool(mGeneric);
}

GLuint ProgramVariants::id(const std::vector<std::string>& defines) {
    auto found = mVariants.find(defines);
    if (found == mVariants.end()) {
        ProgramDesc desc = mDesc;
        desc.name += "[";
        for (const std::string& define : defines) {
            desc.name += (desc.name.back() == '[' ? "" : ", ") + define;
        }
        desc.name += "]";
        desc.defines.insert(desc.defines.end(), defines.begin(), defines.end());
        std::string error;
        ProgramRef program = mShaders->build(desc, error);
        if (!program) {
            std::fprintf(stderr, "voxatlas: %s: %s; using the program without them\n",
                    desc.name.c_str(), error.c_str());
            program = mGeneric;
        }
        found = mVariants.emplace(defines, program).first;
    }
    return found->second.id();
}

} // namespace gi::gl
