// Line-space build, pass 2: a cell of level LOC_LINESPACE_LEVEL is occupied when any of its
// N^3 children on the level below is; run from the deepest inner level up to the root.
#include "linespace_common.glsl"

layout(location = LOC_LINESPACE_LEVEL) uniform int level;

void main() {
    uint r = levelResolution(level);
    uint i = flatInvocation();
    if (i >= r * r * r) return;
    uvec3 cell = uvec3(i % r, (i / r) % r, i / (r * r));
    uint n = uint(lineSpace.shape.x);
    uint below = levelOffset(level + 1);
    uint rb = r * n;
    bool found = false;
    for (uint z = 0u; z < n; ++z) {
        for (uint y = 0u; y < n; ++y) {
            for (uint x = 0u; x < n; ++x) found = found || occupied(below, rb, cell * n + uvec3(x, y, z));
        }
    }
    if (found) markOccupied(levelOffset(level), r, cell);
}
