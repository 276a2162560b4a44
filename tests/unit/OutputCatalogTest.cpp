// The mode and output tables are the only place their names live: every entry must parse on
// the command line and be listed by `voxatlas render --help`.
#include "render/OutputCatalog.h"

#include "app/CommandLine.h"
#include "app/Usage.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace gi::app {
namespace {

std::optional<Config> parseRender(const char* flag, const char* value, std::string& error) {
    const std::vector<const char*> args = {"voxatlas", "render", "s.gltf", "--out", "a.png", flag,
            value};
    return parseCommandLine(int(args.size()), args.data(), error);
}

// A line of the help that starts with `name` as its own word (after indentation).
bool helpListsLine(const std::string& help, const std::string& name) {
    return help.find("\n  " + name + " ") != std::string::npos;
}

TEST(OutputCatalog, EveryModeParsesAndIsInHelp) {
    const std::string help = usage(Command::Render);
    std::set<std::string> names;
    for (const render::ModeEntry& entry : render::modeCatalog()) {
        EXPECT_TRUE(names.insert(entry.name).second) << "duplicate mode " << entry.name;
        std::string error;
        const auto config = parseRender("--mode", entry.name, error);
        ASSERT_TRUE(config) << entry.name << ": " << error;
        EXPECT_EQ(config->mode, entry.mode) << entry.name;
        EXPECT_STREQ(render::giModeName(entry.mode), entry.name);
        EXPECT_TRUE(helpListsLine(help, entry.name)) << entry.name << " missing from:\n" << help;
        EXPECT_NE(help.find(entry.description), std::string::npos) << entry.name;
    }
}

TEST(OutputCatalog, EveryOutputParsesAndIsInHelp) {
    const std::string help = usage(Command::Render);
    std::set<std::string> names;
    for (const render::OutputEntry& entry : render::outputCatalog()) {
        EXPECT_TRUE(names.insert(entry.name).second) << "duplicate output " << entry.name;
        std::string error;
        const auto config = parseRender("--output", entry.name, error);
        ASSERT_TRUE(config) << entry.name << ": " << error;
        EXPECT_EQ(config->output, entry.output) << entry.name;
        EXPECT_STREQ(render::outputComponentName(entry.output), entry.name);
        EXPECT_TRUE(helpListsLine(help, entry.name)) << entry.name << " missing from:\n" << help;
        EXPECT_NE(help.find(entry.description), std::string::npos) << entry.name;
        EXPECT_NE(entry.modes, 0u) << entry.name << " applies to no mode";
    }
    EXPECT_EQ(render::allOutputComponents().size(), render::outputCatalog().size());
}

// A debug view belongs to exactly one GPU technique; the radiance components to every mode.
TEST(OutputCatalog, DebugViewsBelongToTheirTechniqueOnly) {
    for (const render::OutputEntry& entry : render::outputCatalog()) {
        const bool debug = render::isDebugView(entry.output);
        EXPECT_EQ(debug, entry.debugView != DebugView::None) << entry.name;
        EXPECT_EQ(render::outputAvailable(entry.output, render::GiMode::Reference), !debug)
                << entry.name;
        EXPECT_EQ(render::outputAvailable(entry.output, render::GiMode::Direct), !debug)
                << entry.name;
        if (!debug) continue;
        int owners = 0;
        for (const render::GiMode mode :
                {render::GiMode::Voxel, render::GiMode::Atlas, render::GiMode::Vpl}) {
            if (!render::outputAvailable(entry.output, mode)) continue;
            ++owners;
            const std::string prefix = std::string(render::giModeName(mode)) + "-";
            EXPECT_EQ(std::string(entry.name).rfind(prefix, 0), 0u) << entry.name;
        }
        EXPECT_EQ(owners, 1) << entry.name;
    }
}

TEST(OutputCatalog, RejectionsListEveryName) {
    std::string error;
    EXPECT_FALSE(parseRender("--mode", "magic", error));
    for (const render::ModeEntry& entry : render::modeCatalog()) {
        EXPECT_NE(error.find(entry.name), std::string::npos) << error;
    }
    EXPECT_FALSE(parseRender("--output", "all", error));
    for (const render::OutputEntry& entry : render::outputCatalog()) {
        EXPECT_NE(error.find(entry.name), std::string::npos) << error;
    }
}

} // namespace
} // namespace gi::app
