#include "gi/voxel/LevelDispatch.h"

#include "gl/Shared.h"

namespace gi::voxel {

void dispatchLevelByLevel(GLuint program, GLuint groups, int firstLevel, int levels) {
    for (int level = firstLevel; level < levels; ++level) {
        glProgramUniform1i(program, LOC_VOXEL_LEVEL, level);
        glDispatchCompute(groups, groups, groups);
        // Consumer: the next level reads this one's results.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    // Consumers: cone tracing, the pyramid and the debug views sample the textures.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

} // namespace gi::voxel
