#include "gi/voxel/VoxelShape.h"

namespace gi::voxel {

std::vector<std::string> VoxelShape::defines() const {
    return {"VOXEL_SHAPE_RESOLUTION " + std::to_string(resolution),
            "VOXEL_SHAPE_LEVELS " + std::to_string(levels),
            std::string("VOXEL_SHAPE_ANISOTROPIC ") + (anisotropic ? "1" : "0")};
}

} // namespace gi::voxel
