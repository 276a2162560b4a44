// The diffuse cone sets (gi/voxel/ConeSet.h): their weights tile the cosine-weighted
// hemisphere, and the interleaved pixel classes each trace their share of the rings.
#include "core/Settings.h"
#include "gi/voxel/ConeSet.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gi::test {
namespace {

using voxel::ConeSet;
using voxel::coneSet;
using voxel::conePixelClasses;

// The cosine-weighted mean of cos theta over the hemisphere is 2/3; a set whose cones sit at
// their parts' centres gives nearly that.
float meanCosine(const ConeSet& set) {
    float mean = set.centralWeight;
    for (const voxel::ConeRing& ring : set.rings) {
        mean += float(ring.count) * ring.weight * std::cos(ring.elevation);
    }
    return mean;
}

TEST(ConeSet, ThesisNineConesAtFiftyDegreesWithFortyFiveDegreeApertures) {
    const ConeSet set = coneSet(VOXEL_CONES_THESIS, 0.0f);
    EXPECT_EQ(set.rings[0].count, 8);
    EXPECT_EQ(set.rings[1].count, 0);
    EXPECT_NEAR(set.rings[0].elevation, 50.0f * 3.14159265f / 180.0f, 1e-5f);
    EXPECT_NEAR(set.centralWeight, std::pow(std::sin(25.0f * 3.14159265f / 180.0f), 2.0f), 1e-6f);
    EXPECT_FLOAT_EQ(set.apertureDegrees, 45.0f);
    EXPECT_NEAR(set.totalWeight(), 1.0f, 1e-6f);
    EXPECT_EQ(set.conesPerPixel(1), 9);
}

TEST(ConeSet, NineteenEqualSharesTileTheHemisphere) {
    const ConeSet set = coneSet(VOXEL_CONES_RINGS, 0.0f);
    EXPECT_EQ(set.rings[0].count, 6);
    EXPECT_EQ(set.rings[1].count, 12);
    EXPECT_NEAR(set.centralWeight, 1.0f / 19.0f, 1e-6f);
    EXPECT_EQ(set.rings[2].count, 0);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(set.rings[k].weight, 1.0f / 19.0f, 1e-6f);
    EXPECT_NEAR(set.totalWeight(), 1.0f, 1e-6f);
    // Ring k at the middle (in sin^2 theta) of its band: 4/19 and 13/19.
    EXPECT_NEAR(std::pow(std::sin(set.rings[0].elevation), 2.0f), 4.0f / 19.0f, 1e-5f);
    EXPECT_NEAR(std::pow(std::sin(set.rings[1].elevation), 2.0f), 13.0f / 19.0f, 1e-5f);
    // 19 caps of the aperture's solid angle fill the hemisphere's.
    const float half = set.apertureDegrees * 0.5f * 3.14159265f / 180.0f;
    EXPECT_NEAR(19.0f * (1.0f - std::cos(half)), 1.0f, 1e-4f);
    EXPECT_NEAR(set.apertureDegrees, 37.3f, 0.05f);
    EXPECT_EQ(set.conesPerPixel(1), 19);
}

TEST(ConeSet, ThirtySevenEqualSharesTileTheHemisphereInThreeRings) {
    const ConeSet set = coneSet(VOXEL_CONES_DENSE, 0.0f);
    EXPECT_EQ(set.rings[0].count, 6);
    EXPECT_EQ(set.rings[1].count, 12);
    EXPECT_EQ(set.rings[2].count, 18);
    EXPECT_NEAR(set.centralWeight, 1.0f / 37.0f, 1e-6f);
    for (const voxel::ConeRing& ring : set.rings) EXPECT_NEAR(ring.weight, 1.0f / 37.0f, 1e-6f);
    EXPECT_NEAR(set.totalWeight(), 1.0f, 1e-6f);
    // Bands 1-7, 7-19 and 19-37 of 37 shares; each ring at its band's middle.
    EXPECT_NEAR(set.rings[2].bandLow, 19.0f / 37.0f, 1e-6f);
    EXPECT_NEAR(set.rings[2].bandHigh, 1.0f, 1e-6f);
    EXPECT_NEAR(std::pow(std::sin(set.rings[2].elevation), 2.0f), 28.0f / 37.0f, 1e-5f);
    const float half = set.apertureDegrees * 0.5f * 3.14159265f / 180.0f;
    EXPECT_NEAR(37.0f * (1.0f - std::cos(half)), 1.0f, 1e-4f);
    EXPECT_EQ(set.conesPerPixel(1), 37);
    EXPECT_EQ(set.conesPerPixel(2), 19);
}

// voxel.jitter_elevation moves a ring's cones by up to riseReach in sin^2 theta either way:
// they stay within the ring's band, and the outer ring's rims stay above the surface.
TEST(ConeSet, ElevationJitterStaysInTheBandAndAboveTheSurface) {
    for (const int cones : {VOXEL_CONES_THESIS, VOXEL_CONES_RINGS, VOXEL_CONES_DENSE}) {
        for (const float aperture : {0.0f, 30.0f, 60.0f}) {
            const ConeSet set = coneSet(cones, aperture);
            const float half = set.apertureDegrees * 0.5f * 3.14159265f / 180.0f;
            const float rim = std::cos(half) * std::cos(half);
            for (const voxel::ConeRing& ring : set.rings) {
                if (ring.count == 0) continue;
                const float middle = std::pow(std::sin(ring.elevation), 2.0f);
                EXPECT_GE(ring.riseReach, 0.0f);
                EXPECT_GE(middle - ring.riseReach, ring.bandLow - 1e-6f);
                EXPECT_LE(middle + ring.riseReach, ring.bandHigh + 1e-6f);
                // A ring whose rims already dip below the surface (wide apertures) stays put.
                if (middle >= rim) EXPECT_EQ(ring.riseReach, 0.0f);
                else EXPECT_LE(middle + ring.riseReach, rim + 1e-6f);
            }
        }
    }
    // 19 cones: the inner ring sweeps its whole band, the outer one until its rim meets the
    // surface (cos^2 of its half-aperture, cos = 1 - 1/19).
    const ConeSet nineteen = coneSet(VOXEL_CONES_RINGS, 0.0f);
    EXPECT_NEAR(nineteen.rings[0].riseReach, 3.0f / 19.0f, 1e-5f);
    EXPECT_NEAR(nineteen.rings[1].riseReach, std::pow(18.0f / 19.0f, 2.0f) - 13.0f / 19.0f, 1e-5f);
}

TEST(ConeSet, EverySetCentresItsConesOnTheCosineWeightedMean) {
    EXPECT_NEAR(meanCosine(coneSet(VOXEL_CONES_DENSE, 0.0f)), 2.0f / 3.0f, 0.02f);
    EXPECT_NEAR(meanCosine(coneSet(VOXEL_CONES_RINGS, 0.0f)), 2.0f / 3.0f, 0.03f);
    EXPECT_NEAR(meanCosine(coneSet(VOXEL_CONES_THESIS, 0.0f)), 2.0f / 3.0f, 0.05f);
}

TEST(ConeSet, GivenApertureReplacesTheSetsOwn) {
    EXPECT_FLOAT_EQ(coneSet(VOXEL_CONES_RINGS, 30.0f).apertureDegrees, 30.0f);
    EXPECT_FLOAT_EQ(coneSet(VOXEL_CONES_THESIS, 60.0f).apertureDegrees, 60.0f);
}

TEST(ConeSet, TwoPixelClassesTraceTenOfNineteenOnlyWithAFilterAndNotTheThesisSet) {
    EXPECT_EQ(conePixelClasses(VOXEL_CONES_RINGS, true, 2), 2);
    EXPECT_EQ(conePixelClasses(VOXEL_CONES_RINGS, true, 0), 1);
    EXPECT_EQ(conePixelClasses(VOXEL_CONES_RINGS, false, 4), 1);
    EXPECT_EQ(conePixelClasses(VOXEL_CONES_THESIS, true, 4), 1);
    EXPECT_EQ(coneSet(VOXEL_CONES_RINGS, 0.0f).conesPerPixel(2), 10);
}

} // namespace
} // namespace gi::test
