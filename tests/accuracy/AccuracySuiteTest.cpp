// The accuracy scoreboard's CI form: `voxatlas bench --suite quick` over every scene of the
// suite, each score held to a per-scene threshold so a change that makes any GI mode worse on
// any scene turns the build red. The thresholds are the quick form's measured scores with a
// margin for the run-to-run spread of the stochastic atlas (not the targets, which
// docs/results-accuracy.md reports from the full form); lower them when a change improves a
// score, never raise them to pass.
//
// Each test runs one group of scenes in its own process, so ctest can run groups side by side;
// references are cached in the test home's cache directory like every other test's.
#include "BenchOutput.h"
#include "GpuTest.h"
#include "Process.h"
#include "Sponza.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>

namespace gi::test {
namespace {

namespace fs = std::filesystem;

// Both bounds measure distance from the truth, so a change that improves a score never
// breaks its threshold: relative RMSE, and |indirect energy ratio - 1|.
struct Threshold {
    const char* scene;
    const char* configuration;
    double maxRelRmse;                 // indirect component
    double maxEnergyError;             // |energy ratio - 1| of the indirect component
    std::optional<double> maxLeak = {};   // the dark room: its indirect light over the lit room's
};

#include "AccuracyThresholds.inc"

BenchTable runSuite(const std::string& scenes, const std::string& tag,
        const std::vector<std::string>& env = {}) {
    const std::string dir = makeTempDir("accuracy-" + tag);
    const std::vector<std::string> args = {"bench", "--suite", "quick", "--scene", scenes,
            "--out-dir", dir};
    // Twice the longest run seen on a loaded two-core machine.
    constexpr int kTimeoutSeconds = 1200;
    const ProcessResult r = runVoxatlas(args, kTimeoutSeconds, env);
    EXPECT_FALSE(r.timedOut) << "bench --suite quick did not finish in " << kTimeoutSeconds
                             << " s";
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    std::printf("%s", r.out.c_str());
    BenchTable table = readBenchCsv(dir + "/accuracy.csv");
    EXPECT_TRUE(fs::exists(dir + "/results-accuracy.md"));
    fs::remove_all(dir);
    return table;
}

// Every row of `table` whose scene has a threshold is checked against it, and every threshold
// must have found its row (a configuration that silently stopped running is a failure).
void expectWithinThresholds(const BenchTable& table) {
    ASSERT_FALSE(table.rows.empty()) << "no accuracy.csv";
    std::set<std::string> scenes = table.distinct("scene");
    for (const Threshold& t : kThresholds) {
        if (!scenes.count(t.scene)) continue;
        bool found = false;
        for (std::size_t row = 0; row < table.rows.size(); ++row) {
            if (table.field(row, "scene") != t.scene ||
                    table.field(row, "configuration") != t.configuration) {
                continue;
            }
            found = true;
            const std::string what = std::string(t.scene) + " / " + t.configuration;
            ASSERT_EQ(table.field(row, "available"), "1") << what << " was not run";
            if (t.maxLeak) {
                const double leak = std::stod(table.field(row, "leak"));
                EXPECT_LE(leak, *t.maxLeak) << what << ": light leaking into the dark room";
                std::printf("%-24s %-16s leak %.4f (<= %.4f)\n", t.scene, t.configuration,
                        leak, *t.maxLeak);
                continue;
            }
            const double rmse = std::stod(table.field(row, "rel_rmse_indirect"));
            const double energy = std::stod(table.field(row, "energy_indirect"));
            EXPECT_LE(rmse, t.maxRelRmse) << what << ": relative RMSE of the indirect light";
            EXPECT_LE(std::abs(energy - 1.0), t.maxEnergyError)
                    << what << ": indirect energy ratio " << energy;
            std::printf("%-24s %-16s rel. RMSE %.3f (<= %.3f)  energy %.3f (1 +- %.3f)\n",
                    t.scene, t.configuration, rmse, t.maxRelRmse, energy, t.maxEnergyError);
        }
        EXPECT_TRUE(found) << t.scene << " / " << t.configuration << ": no row in accuracy.csv";
    }
}

TEST(AccuracySuite, CornellVariantsStayWithinTheirThresholds) {
    expectWithinThresholds(runSuite("cornell_classic,cornell_double_sided,cornell_low_light,"
                                    "cornell_x10,cornell_spot,cornell_open_front_sun",
            "cornell"));
}

TEST(AccuracySuite, ThinWallAndWhiteBoxStayWithinTheirThresholds) {
    expectWithinThresholds(runSuite("two_rooms_lit,two_rooms_dark,closed_white_box", "rooms"));
}

TEST(AccuracySuite, SponzaStaysWithinItsThresholds) {
    VOXATLAS_SPONZA_OR_SKIP(sponza);
    expectWithinThresholds(
            runSuite("sponza_sun,sponza_arcade", "sponza", {"VOXATLAS_SPONZA=" + sponza}));
}

} // namespace
} // namespace gi::test
