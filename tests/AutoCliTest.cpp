// `-t auto` through the bench binary (bench/lib/select/): the first run measures every candidate on this
// machine and caches them; a second run reads the cache and measures nothing; costs written into the
// cache (an injected calibration) move the choice, and a candidate whose cached error misses the bound
// is passed over however cheap. The chosen technique's row records the choice and the candidates. On a
// point-lit scene the refusal of every flat shadow map names the configurations that shade a point
// light, and auto tries each of them (hybrid with an omni cast part instead of its default).
#include <algorithm>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
// sphere_plane asks for hard shadows only, so planar, projective, shadowmap, volume ... all qualify.
const std::string kRun = " -t auto --scene sphere_plane --size 64x64 --frames 2 --warmup 0 --no-timer-check";

/// Sets every cached candidate's cost to `others` ms and `cheap`'s to 1 ms (errors as given).
void injectCosts(const std::string& cache, const std::string& cheap, double others,
                 const std::map<std::string, std::string>& wrong = {}) {
    CsvTable t = CsvWriter::read(cache);
    const auto column = [&](const std::string& name) {
        return size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
    };
    const size_t candidate = column("candidate"), wall = column("wall_ms"), wrongPct = column("wrong_pct");
    const size_t rounds = column("wall_rounds"), batch = column("batch");
    ASSERT_LT(wall, t.header.size());
    ASSERT_LT(rounds, t.header.size());
    ASSERT_LT(batch, t.header.size());
    for (auto& row : t.rows) {
        const std::string name = row[candidate].substr(0, row[candidate].find(':'));
        if (row[wall].empty()) continue; // refused
        // An injected calibration has one cost per candidate and no rounds, as a hand-written cache:
        // the medians decide (AutoSelection::faster).
        row[rounds] = "";
        row[batch] = "";
        row[wall] = name == cheap ? "1" : std::to_string(others);
        if (auto it = wrong.find(name); it != wrong.end()) row[wrongPct] = it->second;
    }
    CsvWriter::writeTable(cache, t);
}

std::string chosenIn(const std::string& csv) {
    const auto rows = test::csvRowMaps(csv);
    return rows.empty() ? "" : rows.back().at(col::kTechnique);
}

} // namespace

TEST(AutoCli, MeasuresOnceThenFollowsTheCachedCosts) {
    const std::string dir = test::freshTestDir("auto");
    const std::string cache = dir + "/calibration.csv", csv = dir + "/r.csv";
    const auto first = runCommand(kBench + kRun + " --calibration " + cache + " --csv " + csv);
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("0 from " + cache), std::string::npos) << first.output;
    EXPECT_NE(first.output.find("auto: chose "), std::string::npos) << first.output;
    // The reference judges, it is not a candidate; planar lacks nothing sphere_plane asks for.
    EXPECT_EQ(first.output.find("  reference "), std::string::npos) << first.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_NE(rows[0].at(col::kAutoChoice).find("the cheapest of"), std::string::npos);
    EXPECT_NE(rows[0].at(col::kAutoCandidates).find("planar"), std::string::npos);

    injectCosts(cache, "volume", 100.0);
    const auto second = runCommand(kBench + kRun + " --calibration " + cache + " --csv " + csv);
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_NE(second.output.find(", 0 measured now"), std::string::npos) << second.output;
    EXPECT_EQ(chosenIn(csv), "volume") << second.output;

    injectCosts(cache, "planar", 100.0);
    ASSERT_EQ(runCommand(kBench + kRun + " --calibration " + cache + " --csv " + csv).exitCode, 0);
    EXPECT_EQ(chosenIn(csv), "planar");

    // Cheapest but 30% wrong: passed over at the default bound, taken when the bound allows it.
    injectCosts(cache, "planar", 100.0, {{"planar", "30"}});
    const auto bounded = runCommand(kBench + kRun + " --calibration " + cache + " --csv " + csv);
    ASSERT_EQ(bounded.exitCode, 0) << bounded.output;
    EXPECT_NE(chosenIn(csv), "planar") << bounded.output;
    EXPECT_NE(bounded.output.find("30% wrong > bound 10%"), std::string::npos) << bounded.output;
    ASSERT_EQ(
        runCommand(kBench + kRun + " --auto-max-wrong 40 --calibration " + cache + " --csv " + csv).exitCode,
        0);
    EXPECT_EQ(chosenIn(csv), "planar");
}

TEST(AutoCli, NoQualifyingCandidateIsExitThreeAndPropertiesAreBadInput) {
    const std::string dir = test::freshTestDir("auto_none");
    const std::string cache = dir + "/calibration.csv";
    // Every measured candidate made 50% wrong: nothing meets a 1% bound.
    ASSERT_EQ(runCommand(kBench + kRun + " --calibration " + cache).exitCode, 0);
    CsvTable t = CsvWriter::read(cache);
    const size_t wrong = size_t(std::find(t.header.begin(), t.header.end(), "wrong_pct") - t.header.begin());
    for (auto& row : t.rows)
        if (!row[wrong].empty()) row[wrong] = "50";
    CsvWriter::writeTable(cache, t);
    const auto none = runCommand(kBench + kRun + " --auto-max-wrong 1 --calibration " + cache);
    EXPECT_EQ(none.exitCode, 3) << none.output;
    EXPECT_NE(none.output.find("auto: no candidate delivers hard_shadows within 1% wrong"), std::string::npos)
        << none.output;
    const auto props = runCommand(kBench + " -t auto:resolution=512 --scene sphere_plane");
    EXPECT_EQ(props.exitCode, 2) << props.output;
    EXPECT_NE(props.output.find("-t auto takes no properties"), std::string::npos) << props.output;
    EXPECT_EQ(runCommand(kBench + kRun + " --auto-max-wrong 101").exitCode, 2);
    // A sweep does not make the choice: bad input that says which commands do, before any GL.
    const auto sweep = runCommand(kBench + " sweep -t auto --scene sphere_plane --csv " + dir + "/s.csv");
    EXPECT_EQ(sweep.exitCode, 2) << sweep.output;
    EXPECT_NE(sweep.output.find("-t auto is taken by `bench` and `bench accuracy` runs only"),
              std::string::npos)
        << sweep.output;
}

// point_light's one light is a point light. The techniques with a flat map refuse it (exit 3) naming
// hybrid:cast=cubemap among what to use instead, and every configuration the words name is measured by
// the calibration in the same run and judged against the Embree reference within auto's own bound (10%
// of the shadow misplaced: a configuration that shades the light at all is near 0 here, one that does
// not is near 100).
TEST(AutoCli, APointLightIsRefusedWithEveryWorkingOmniConfigurationAndAutoTriesThem) {
    const std::string dir = test::freshTestDir("auto_point");
    const std::string csv = dir + "/r.csv";
    const auto r = runCommand(kBench +
                              " -t auto -t hybrid -t pcss --scene point_light --size 64x64 --frames 1 "
                              "--warmup 0 --no-timer-check -q --calibration " +
                              dir + "/calibration.csv --csv " + csv);
    EXPECT_EQ(r.exitCode, 3) << r.output; // the refusals keep the code of what the context lacks
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 3u) << r.output;
    const std::string candidates = rows[0].at(col::kAutoCandidates);
    // The refusals: hybrid's and pcss's own rows, and shadowmap's, cascaded's, vsm's and esm's in the
    // calibration. Each names the same configurations.
    std::vector<std::string> refusals = {rows[1].at(col::kError), rows[2].at(col::kError)};
    for (const char* name : {"shadowmap", "cascaded", "vsm", "esm"}) {
        const std::regex refused(std::string("(^|; )") + name + " - - refused: ([^;]*)");
        std::smatch m;
        ASSERT_TRUE(std::regex_search(candidates, m, refused)) << name << " not refused in: " << candidates;
        refusals.push_back(m[2].str());
    }
    const auto advice = [](const std::string& why) {
        return why.substr(std::min(why.find(": use "), why.size()));
    };
    for (const std::string& why : refusals) {
        EXPECT_NE(why.find("is a point light"), std::string::npos) << why;
        EXPECT_NE(why.find("-t hybrid:cast=cubemap"), std::string::npos) << why;
        EXPECT_EQ(advice(why), advice(refusals.front())) << "the refusals' words differ";
    }
    EXPECT_EQ(rows[1].at(col::kStatus), col::kStatusUnsupported);
    EXPECT_EQ(rows[2].at(col::kStatus), col::kStatusUnsupported);
    // Every configuration named runs and qualifies: "<name> <cost> ms <wrong>% qualifies|chosen".
    const std::string& words = refusals.front();
    std::vector<std::string> named;
    const std::regex option("-t ([a-z:=]+)");
    for (auto it = std::sregex_iterator(words.begin(), words.end(), option); it != std::sregex_iterator();
         ++it)
        named.push_back((*it)[1].str());
    EXPECT_EQ(named, (std::vector<std::string>{"cubemap", "paraboloid", "hybrid:cast=cubemap",
                                               "hybrid:cast=paraboloid"}));
    for (const std::string& spec : named) {
        const std::regex measured("(^|; )" + spec + " [0-9.e+]+ ms ([0-9.e+-]+)% (qualifies|chosen)");
        EXPECT_TRUE(std::regex_search(candidates, measured))
            << spec << " not measured within the bound: " << candidates;
    }
}

// On Vulkan, -t auto calibrates on the API it runs on: the candidates' Vulkan forms measured with the
// Vulkan harness, cached under api vulkan; a GL run with the same cache measures its own candidates (the
// two APIs' rows never answer for each other), and a second Vulkan run reads its rows back.
TEST(AutoCli, CalibratesOnVulkanWithItsFormsAndKeepsTheCacheApart) {
    const std::string dir = test::freshDir("auto-vulkan");
    const std::string cache = dir + "/calibration.csv", csv = dir + "/r.csv";
    const auto vulkan =
        runCommand(kBench + " --api vulkan" + kRun + " --calibration " + cache + " --csv " + csv);
    ASSERT_EQ(vulkan.exitCode, 0) << vulkan.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 1u) << vulkan.output;
    EXPECT_EQ(rows[0].at(col::kApi), "vulkan");
    EXPECT_FALSE(rows[0].at(col::kAutoChoice).empty()) << vulkan.output;
    for (const auto& row : test::csvRowMaps(cache)) EXPECT_EQ(row.at("api"), "vulkan") << row.at("candidate");
    const std::regex measured("[1-9][0-9]* measured now");
    EXPECT_TRUE(std::regex_search(vulkan.output, measured)) << vulkan.output;
    const auto gl = runCommand(kBench + kRun + " --calibration " + cache);
    ASSERT_EQ(gl.exitCode, 0) << gl.output;
    EXPECT_TRUE(std::regex_search(gl.output, measured)) << "GL read Vulkan's rows:\n" << gl.output;
    const auto again = runCommand(kBench + " --api vulkan" + kRun + " --calibration " + cache);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(again.output.find(", 0 measured now"), std::string::npos) << again.output;
}
