#include "render/LineSpaceLayout.h"

#include "gl/Limits.h"
#include "gl/Shared.h"
#include "render/ShadowCasters.h"

#include <algorithm>
#include <cmath>

namespace gi::render {

std::uint64_t LineSpaceLayout::resolution(int level) const {
    std::uint64_t r = 1;
    for (int i = 0; i < level; ++i) r *= std::uint64_t(n);
    return r;
}

std::uint64_t LineSpaceLayout::cells(int level) const {
    const std::uint64_t r = resolution(level);
    return r * r * r;
}

std::uint64_t LineSpaceLayout::occupancyOffset(int level) const {
    std::uint64_t words = 0;
    for (int l = 0; l < level; ++l) words += (cells(l) + 31) / 32;
    return words;
}

std::uint64_t LineSpaceLayout::shaftsPerNode() const {
    const std::uint64_t faces = std::uint64_t(n) * std::uint64_t(n);
    return 15 * faces * faces;
}

LineSpaceLayout lineSpaceLayout(const scene::Aabb& bounds, int n, int depth) {
    LineSpaceLayout layout;
    layout.n = n;
    layout.depth = depth;
    const glm::vec3 size = bounds.size();
    const float edge = std::max(std::max(size.x, size.y), size.z);
    layout.rootSize = edge > 0.0f ? 1.02f * edge : 1.0f;
    const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
    layout.rootMin = centre - glm::vec3(0.5f * layout.rootSize);
    return layout;
}

namespace {

// Inner nodes of the deepest inner level whose cells the triangles' bounding boxes touch,
// plus every level above counted in full up to its size: a bound, not a count.
double nodeCountBound(const LineSpaceLayout& layout, const std::vector<glm::vec4>& corners) {
    const int inner = layout.depth - 1;
    const std::uint64_t r = layout.resolution(inner);
    std::vector<bool> touched(std::size_t(layout.cells(inner)), false);
    const float cell = layout.rootSize / float(r);
    std::uint64_t marked = 0;
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
        const glm::vec3 lo = glm::min(glm::vec3(corners[t]), glm::min(glm::vec3(corners[t + 1]), glm::vec3(corners[t + 2])));
        const glm::vec3 hi = glm::max(glm::vec3(corners[t]), glm::max(glm::vec3(corners[t + 1]), glm::vec3(corners[t + 2])));
        const glm::ivec3 a = glm::clamp(glm::ivec3(glm::floor((lo - layout.rootMin) / cell)) - 1, 0, int(r) - 1);
        const glm::ivec3 b = glm::clamp(glm::ivec3(glm::floor((hi - layout.rootMin) / cell)) + 1, 0, int(r) - 1);
        for (int z = a.z; z <= b.z; ++z) {
            for (int y = a.y; y <= b.y; ++y) {
                for (int x = a.x; x <= b.x; ++x) {
                    const std::size_t i = std::size_t(x) + std::size_t(r) * (std::size_t(y) + std::size_t(r) * std::size_t(z));
                    if (!touched[i]) {
                        touched[i] = true;
                        ++marked;
                    }
                }
            }
        }
    }
    double nodes = double(marked);
    for (int l = 0; l < inner; ++l) nodes += std::min(double(layout.cells(l)), double(marked));
    return nodes;
}

} // namespace

double lineSpaceBytesBound(const LineSpaceLayout& layout, const std::vector<glm::vec4>& corners) {
    const double occupancy = double(layout.occupancyWords()) * 4.0;
    const double triangles = double(corners.size()) * sizeof(glm::vec4);
    // The leaf grid alone may be past any budget (N = 10, depth 4: 10^12 bits); counting the
    // nodes would then mark a grid as large, so it is refused on the grid first.
    if (occupancy > double(gl::kResourceBudgetBytes)) return occupancy + triangles;
    const double nodes = nodeCountBound(layout, corners);
    const double perNode = double(layout.wordsPerNode()) * 4.0 + double(layout.cells(1)) * 4.0 + 16.0;
    return occupancy + triangles + nodes * perNode;
}

bool lineSpaceFits(const scene::Scene& scene, const Settings& settings, std::string& error) {
    if (settings.shadow.method != SHADOW_METHOD_LINESPACE || !settings.shadow.enabled) return true;
    const int n = settings.lineSpace.n, depth = settings.lineSpace.depth;
    const LineSpaceLayout layout = lineSpaceLayout(scene.bounds, n, depth);
    const double bytes = lineSpaceBytesBound(layout, shadowCasterCorners(scene));
    return gl::fitsResourceBudget("the line space at linespace.n " + std::to_string(n) +
                    ", linespace.depth " + std::to_string(depth),
            bytes, error);
}

} // namespace gi::render
