// The accuracy scoreboard's page says which materials it scored: Lambertian surfaces (the
// default, material.specular=0) or glTF's BRDF on both sides (--set material.model=gltf).
#include "bench/AccuracyReport.h"

#include <gtest/gtest.h>

#include <string>

namespace gi::bench {
namespace {

std::string page(bool glossy) {
    SuiteRunInfo info;
    info.size = "quick";
    info.command = "voxatlas bench --suite quick";
    info.glossy = glossy;
    return accuracyMarkdown({}, {}, info);
}

TEST(AccuracyPage, SaysTheSurfacesAreLambertianByDefault) {
    const std::string text = page(false);
    EXPECT_NE(text.find("`material.specular=0`"), std::string::npos);
    EXPECT_EQ(text.find("material.model=gltf"), std::string::npos);
}

TEST(AccuracyPage, SaysWhenBothSidesRenderedGlossyMaterials) {
    const std::string text = page(true);
    EXPECT_NE(text.find("`material.model=gltf`"), std::string::npos);
    EXPECT_EQ(text.find("`material.specular=0`"), std::string::npos);
}

} // namespace
} // namespace gi::bench
