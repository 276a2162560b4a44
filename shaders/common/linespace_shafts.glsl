// How a line space numbers its shafts (render/LineSpaceLayout.h). In a node's own units the
// node is [0, N]^3 and its children unit cubes. Face f = 2 axis + side (side 0 at 0, 1 at N);
// a sub-face of face f with axis a is cu + N cv, (cu, cv) its cell along the axes a + 1 and
// a + 2 (mod 3). A shaft joins sub-face ia of face fa to sub-face ib of face fb, fa < fb (the
// reverse pair is the same shaft; pairs on one face have no volume and are not stored):
// index = pair(fa, fb) N^4 + ia N^2 + ib, with the 15 face pairs numbered in order.
#ifndef GI_LINESPACE_SHAFTS_GLSL
#define GI_LINESPACE_SHAFTS_GLSL

uint lineSpaceFacePair(int fa, int fb) {
    return uint(fa * (11 - fa) / 2 + (fb - fa - 1));
}

uint lineSpaceShaftIndex(int faceA, uint subA, int faceB, uint subB, int n) {
    uint faces = uint(n * n);
    if (faceA > faceB) return lineSpaceFacePair(faceB, faceA) * faces * faces + subB * faces + subA;
    return lineSpaceFacePair(faceA, faceB) * faces * faces + subA * faces + subB;
}

// The sub-face of face axis `axis` that the point `p` (node units) on it lies in.
uint lineSpaceSubFace(int axis, vec3 p, int n) {
    int cu = clamp(int(floor(p[(axis + 1) % 3])), 0, n - 1);
    int cv = clamp(int(floor(p[(axis + 2) % 3])), 0, n - 1);
    return uint(cu + n * cv);
}

#endif
