#include "scene/SunWindow.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gi::scene {
namespace {

SunWindow windowWithUp(const glm::vec3& direction, const Aabb& box, const glm::vec3& up) {
    SunWindow w;
    const glm::vec3 center = box.center();
    const float radius = std::max(0.5f * glm::length(box.size()), 1e-6f);
    w.view = glm::lookAt(center - direction * (2.0f * radius), center, up);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                (i & 4) ? box.max.z : box.min.z);
        const glm::vec3 v = glm::vec3(w.view * glm::vec4(corner, 1.0f));
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    // A margin of a thousandth keeps surfaces on the box's faces inside the window (a
    // thousandth of the box's diagonal across a side the box is flat along). In depth it is a
    // hundredth of the diagonal at least: shading looks the map up from points pushed a few
    // texels off their surfaces (shadows.glsl), which a flat box (a lone floor under a sun
    // overhead) would otherwise put outside a window no deeper than the floor, all in
    // shadow. The view looks down -z, so near and far are the corners' negated depths.
    const float diagonal = 2.0f * radius;
    glm::vec3 margin = 1e-3f * glm::max(hi - lo, glm::vec3(1e-3f * diagonal));
    margin.z = std::max(margin.z, 1e-2f * diagonal);
    lo -= margin;
    hi += margin;
    w.projection = glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z);
    w.size = glm::vec2(hi.x - lo.x, hi.y - lo.y);
    w.depth = hi.z - lo.z;
    return w;
}

} // namespace

SunWindow sunWindow(const glm::vec3& direction, const Aabb& box) {
    Aabb region = box;
    if (region.empty()) {
        region.min = glm::vec3(-1.0f);
        region.max = glm::vec3(1.0f);
    }
    SunWindow best;
    float bestSide = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 up(0.0f);
        up[axis] = 1.0f;
        if (std::abs(glm::dot(up, direction)) > 0.99f) continue;   // looking along it
        const SunWindow w = windowWithUp(direction, region, up);
        const float side = std::max(w.size.x, w.size.y);
        if (side < bestSide) {
            best = w;
            bestSide = side;
        }
    }
    return best;
}

} // namespace gi::scene
