#include "gi/voxel/VoxelShape.h"

#include <cstdio>

namespace gi::voxel {

std::vector<std::string> VoxelShape::defines() const {
    return {"VOXEL_SHAPE_RESOLUTION " + std::to_string(resolution),
            "VOXEL_SHAPE_LEVELS " + std::to_string(levels),
            std::string("VOXEL_SHAPE_ANISOTROPIC ") + (anisotropic ? "1" : "0")};
}

bool ShapedPrograms::init(gl::ShaderLibrary& shaders, gl::ProgramDesc desc, std::string& error) {
    mShaders = &shaders;
    mDesc = std::move(desc);
    mShaped.clear();
    mGeneric = shaders.build(mDesc, error);
    return bool(mGeneric);
}

GLuint ShapedPrograms::id(const VoxelShape& shape) {
    auto found = mShaped.find(shape);
    if (found == mShaped.end()) {
        gl::ProgramDesc desc = mDesc;
        desc.name += "[v" + std::to_string(shape.resolution) + " l" +
                std::to_string(shape.levels) + (shape.anisotropic ? " aniso]" : "]");
        std::vector<std::string> shapeDefines = shape.defines();
        desc.defines.insert(desc.defines.end(), shapeDefines.begin(), shapeDefines.end());
        std::string error;
        gl::ProgramRef program = mShaders->build(desc, error);
        if (!program) {
            std::fprintf(stderr, "voxatlas: %s: %s; using the shape-free program\n",
                    desc.name.c_str(), error.c_str());
            program = mGeneric;
        }
        found = mShaped.emplace(shape, program).first;
    }
    return found->second.id();
}

} // namespace gi::voxel
