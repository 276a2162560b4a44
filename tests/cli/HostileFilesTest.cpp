// Every broken scene in tests/hostile is refused by `voxatlas render` and `voxatlas info` as
// DESIGN.md promises for bad input: exit status 2, within the time limit, exactly one line on
// stderr that names the file and says what is wrong, and no output file. The expected
// message fragments live in tests/hostile/manifest.tsv, written by make_corpus.py with the
// files themselves.
#include "Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = fs::path(VOXATLAS_TEST_DATA_DIR) / "hostile";

// A refused scene returns well within this; the limit only turns a hang into a failure.
constexpr int kTimeoutSeconds = 30;

struct HostileCase {
    std::string file;     // relative to tests/hostile
    std::string fragment; // must appear in the message
};

std::vector<HostileCase> readManifest() {
    std::vector<HostileCase> cases;
    std::ifstream in(kCorpus / "manifest.tsv");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t a = line.find('\t');
        const std::size_t b = line.find('\t', a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        cases.push_back({line.substr(0, a), line.substr(a + 1, b - a - 1)});
    }
    return cases;
}

// The refusal DESIGN.md asks for: exit 2, one line "voxatlas <command>: <file>: ..." holding
// the expected fragment.
void expectOneLineRefusal(const ProcessResult& r, const std::string& command,
        const std::string& path, const std::string& fragment) {
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    const std::string prefix = "voxatlas " + command + ": " + path + ": ";
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << "stderr should start with '" << prefix << "': "
                                          << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n') << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos)
            << "stderr should contain '" << fragment << "': " << r.err;
}

class HostileFile : public testing::TestWithParam<HostileCase> {};

TEST_P(HostileFile, RenderRefusesWithOneLineAndNoOutput) {
    const HostileCase& c = GetParam();
    const std::string path = (kCorpus / c.file).string();
    const std::string dir = makeTempDir("hostile-render");
    const std::string out = dir + "/out.png";
    const ProcessResult r = runVoxatlas({"render", path, "--out", out, "--mode", "direct",
                                                "--width", "16", "--height", "16"},
            kTimeoutSeconds);
    expectOneLineRefusal(r, "render", path, c.fragment);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0)
            << "render left a file in " << dir;
    fs::remove_all(dir);
}

TEST_P(HostileFile, InfoRefusesWithOneLine) {
    const HostileCase& c = GetParam();
    const std::string path = (kCorpus / c.file).string();
    const ProcessResult r = runVoxatlas({"info", path}, kTimeoutSeconds);
    expectOneLineRefusal(r, "info", path, c.fragment);
    EXPECT_TRUE(r.out.empty()) << r.out;
}

std::string caseName(const testing::TestParamInfo<HostileCase>& info) {
    std::string name = info.param.file;
    std::replace_if(
            name.begin(), name.end(), [](unsigned char ch) { return !std::isalnum(ch); }, '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, HostileFile, testing::ValuesIn(readManifest()), caseName);

// The manifest and the corpus agree: no scene without an expected message, no stale entry.
TEST(HostileCorpus, ManifestListsEverySceneFile) {
    std::set<std::string> listed, onDisk;
    for (const HostileCase& c : readManifest()) {
        EXPECT_FALSE(c.fragment.empty()) << c.file;
        EXPECT_TRUE(listed.insert(c.file).second) << c.file << " is listed twice";
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(kCorpus)) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".gltf" || ext == ".glb") onDisk.insert(entry.path().filename().string());
    }
    EXPECT_FALSE(listed.empty());
    EXPECT_EQ(listed, onDisk);
}

} // namespace
} // namespace gi::test
