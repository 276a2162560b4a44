// One program description built once per set of #defines, on first use. Passes whose shaders
// read a switch from a uniform (the cascade's shape, the shadow method, the material model)
// get a variant with it as a constant, so the compiler drops the paths that variant never
// takes. On llvmpipe this is worth more than on a GPU: both sides of every branch run with
// lanes masked off, so an untaken path costs as much as a taken one (docs/
// results-performance.md: the Cornell box's cone trace x0.64, its forward pass x0.39).
#pragma once

#include "gl/ShaderLibrary.h"

#include <map>
#include <string>
#include <vector>

namespace gi::gl {

class ProgramVariants {
public:
    // Builds the variant-free program (every switch read at run time), which also checks
    // that the sources compile.
    [[nodiscard]] bool init(ShaderLibrary& shaders, ProgramDesc desc, std::string& error);

    // The program with `defines` added. A variant whose build fails (the variant-free
    // program compiled, so only a driver limit could) is reported once on stderr and runs
    // the variant-free program.
    [[nodiscard]] GLuint id(const std::vector<std::string>& defines);
    // The variant-free program.
    [[nodiscard]] GLuint genericId() const { return mGeneric.id(); }

private:
    ShaderLibrary* mShaders = nullptr;
    ProgramDesc mDesc;
    ProgramRef mGeneric;
    std::map<std::vector<std::string>, ProgramRef> mVariants;
};

} // namespace gi::gl
