// Include expansion and error mapping of the ShaderLibrary; no GL context is needed for
// either, so they are tested on the CPU over a temporary shader tree.
#include "gl/ShaderLibrary.h"

#include "Process.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace gi::gl {
namespace {

void writeFile(const std::string& path, const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path) << text;
}

TEST(ShaderLibrary, ExpandsIncludesWithLineDirectives) {
    const std::string root = test::makeTempDir("shaders-expand");
    writeFile(root + "/common/a.glsl", "float a() { return 1.0; }\n");
    writeFile(root + "/pass/main.frag", "// top\n#include \"../common/a.glsl\"\nvoid main() {}\n");
    ShaderLibrary library(root);
    std::string source, error;
    ASSERT_TRUE(library.preprocess("pass/main.frag", {"FOO 2"}, source, error)) << error;
    EXPECT_EQ(source.rfind("#version 450 core\n#define FOO 2\n#line 1 0\n", 0), 0u) << source;
    EXPECT_NE(source.find("#line 1 1\nfloat a()"), std::string::npos) << source;
    EXPECT_NE(source.find("#line 3 0\nvoid main()"), std::string::npos) << source;
    std::filesystem::remove_all(root);
}

TEST(ShaderLibrary, MapsDriverMessagesToFiles) {
    const std::string root = test::makeTempDir("shaders-map");
    writeFile(root + "/common/a.glsl", "x\n");
    writeFile(root + "/pass/main.frag", "#include \"../common/a.glsl\"\n");
    ShaderLibrary library(root);
    std::string source, error;
    ASSERT_TRUE(library.preprocess("pass/main.frag", {}, source, error)) << error;
    EXPECT_EQ(library.mapLog("1:1(2): error: syntax error"),
            "shaders/common/a.glsl:1: error: syntax error");
    EXPECT_EQ(library.mapLog("0:7(1): error: bad"), "shaders/pass/main.frag:7: error: bad");
    std::filesystem::remove_all(root);
}

TEST(ShaderLibrary, ReportsMissingIncludesAndCycles) {
    const std::string root = test::makeTempDir("shaders-errors");
    writeFile(root + "/a.frag", "#include \"nothere.glsl\"\n");
    writeFile(root + "/loop.glsl", "#include \"loop.glsl\"\n");
    ShaderLibrary library(root);
    std::string source, error;
    EXPECT_FALSE(library.preprocess("a.frag", {}, source, error));
    EXPECT_NE(error.find("shaders/a.frag:1"), std::string::npos) << error;
    EXPECT_NE(error.find("nothere.glsl"), std::string::npos) << error;
    EXPECT_FALSE(library.preprocess("loop.glsl", {}, source, error));
    EXPECT_NE(error.find("nested"), std::string::npos) << error;
    EXPECT_FALSE(library.preprocess("none.frag", {}, source, error));
    EXPECT_NE(error.find("cannot read"), std::string::npos) << error;
    std::filesystem::remove_all(root);
}

} // namespace
} // namespace gi::gl
