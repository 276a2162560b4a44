// Work split to fit SHADER_LOOP_ITERATIONS (shaders/common/shared.h): llvmpipe ends every loop
// of a shader invocation once all of its loops together have run that many iterations, and
// says nothing. A gather whose loops outran it lost the rest of its samples without a trace
// (the atlas' 4000 samples with voxel visibility in one frame: 0.33 of the light). A pass whose
// invocations loop over items (samples, VPLs) gives each draw or dispatch a range of them that
// stays within the budget in the worst case, and adds the ranges up.
#pragma once

#include "gl/Shared.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace gi::gl {

// Items one draw or dispatch may give each invocation when an item runs at most
// `iterationsPerItem` loop iterations, its own loop's included: at least one.
[[nodiscard]] constexpr int itemsWithinLoopBudget(int iterationsPerItem) {
    return std::max(1, SHADER_LOOP_ITERATIONS / std::max(iterationsPerItem, 1));
}

// Consecutive ranges [x, y) covering items [0, items), as few as itemsWithinLoopBudget allows
// and of equal length within one: one draw or dispatch each. None for no items.
[[nodiscard]] inline std::vector<glm::ivec2> rangesWithinLoopBudget(int items, int iterationsPerItem) {
    std::vector<glm::ivec2> ranges;
    if (items <= 0) return ranges;
    const long long most = itemsWithinLoopBudget(iterationsPerItem);
    const long long count = (items + most - 1) / most;
    for (long long i = 0; i < count; ++i) {
        ranges.emplace_back(int(i * items / count), int((i + 1) * items / count));
    }
    return ranges;
}

} // namespace gi::gl
