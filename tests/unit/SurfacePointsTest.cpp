// The receivers of atlas.importance=surfaces: points on the mesh's triangles, stratified by
// area, inside their triangles, and the same for the same mesh.
#include "gi/atlas/SurfacePoints.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <array>

namespace gi::atlas {
namespace {

// A 2 m x 1 m quad (two triangles, 1 m^2 each) and a triangle of 0.125 m^2 beside it.
AtlasMesh quadAndTriangle() {
    AtlasMesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1},
                      {3, 0, 0}, {3.5f, 0, 0}, {3, 0, 0.5f}};
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 1, 0));
    mesh.doubleSided = {0, 0, 0, 0, 1, 1, 1};
    mesh.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    return mesh;
}

glm::vec3 placeOf(const AtlasMesh& mesh, const SurfacePoint& p) {
    const float b0 = 1.0f - p.b1 - p.b2;
    return b0 * mesh.positions[p.vertex[0]] + p.b1 * mesh.positions[p.vertex[1]] +
           p.b2 * mesh.positions[p.vertex[2]];
}

TEST(SurfacePoints, AreSpreadByAreaInsideTheirTriangles) {
    const AtlasMesh mesh = quadAndTriangle();
    const SurfacePoints points = surfacePoints(mesh, 1024);
    ASSERT_EQ(points.points.size(), 1024u);
    EXPECT_NEAR(points.areaPerPoint, 2.125 / 1024.0, 1e-12);
    std::array<int, 3> perTriangle{};
    for (const SurfacePoint& p : points.points) {
        EXPECT_GE(p.b1, 0.0f);
        EXPECT_GE(p.b2, 0.0f);
        EXPECT_LE(p.b1 + p.b2, 1.0f + 1e-6f);
        const int t = p.vertex[0] == 4u ? 2 : (p.vertex[2] == 2u ? 0 : 1);
        ++perTriangle[std::size_t(t)];
        EXPECT_EQ(p.doubleSided, t == 2 ? 1u : 0u);
        const glm::vec3 at = placeOf(mesh, p);
        if (t == 2) {
            EXPECT_GE(at.x, 3.0f - 1e-5f);
            EXPECT_LE(at.x + at.z, 3.5f + 1e-5f);
        } else {
            EXPECT_LE(at.x, 2.0f + 1e-5f);
        }
    }
    // 1 : 1 : 0.125 of 2.125 m^2, within one point each.
    EXPECT_NEAR(perTriangle[0], 1024.0 / 2.125, 1.0);
    EXPECT_NEAR(perTriangle[1], 1024.0 / 2.125, 1.0);
    EXPECT_NEAR(perTriangle[2], 1024.0 * 0.125 / 2.125, 1.0);
    // Uniform over a triangle: as many points in the quad's left half as in its right.
    int left = 0;
    for (const SurfacePoint& p : points.points) left += placeOf(mesh, p).x < 1.0f;
    EXPECT_NEAR(left, (perTriangle[0] + perTriangle[1]) / 2, 24);
}

TEST(SurfacePoints, DependOnlyOnTheMesh) {
    const AtlasMesh mesh = quadAndTriangle();
    const SurfacePoints a = surfacePoints(mesh, 256), b = surfacePoints(mesh, 256);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
        EXPECT_EQ(a.points[i].vertex[0], b.points[i].vertex[0]);
        EXPECT_EQ(a.points[i].b1, b.points[i].b1);
        EXPECT_EQ(a.points[i].b2, b.points[i].b2);
    }
}

TEST(SurfacePoints, NoneOnAnEmptyOrFlatMesh) {
    EXPECT_TRUE(surfacePoints(AtlasMesh{}, 64).points.empty());
    AtlasMesh flat;
    flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.normals.assign(3, glm::vec3(0, 1, 0));
    flat.indices = {0, 1, 2};
    EXPECT_TRUE(surfacePoints(flat, 64).points.empty());
}

} // namespace
} // namespace gi::atlas
