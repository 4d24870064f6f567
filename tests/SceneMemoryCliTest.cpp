// --max-memory-gib before the cost, through the bench binary, with the peak resident memory measured
// (test::runCommandPeak), not assumed: a scene file of 10^7 instances and model files of 10^6 and 10^7
// triangles are refused with one line before they are parsed or imported (they took 3.6 GB or more,
// and the 10^7-triangle STL was accepted under the default limit with an estimate of 1.0 GiB), and a
// model accepted under the limit costs no more than its estimate said.
//
// Each heavy command runs under an address-space limit of 4 GiB (ulimit -v), far above what a refusal
// needs (~100 MiB): code that pays the cost first fails that way within the limit, instead of taking
// the shared test machine's memory.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HostileSupport.h"
#include "TestSupport.h"

using namespace sb;

namespace {

const std::string kQuick = " -t none --size 64x64 --frames 1 --warmup 0 --no-timer-check -q";
/// The model replaces the teapot scene's layout mesh, one instance of it.
const std::string kModelScene = " --scene teapot --instances 1";

std::string bench(const std::string& args) {
    return "ulimit -v 4194304; exec " + std::string(SB_BENCH_BINARY) + kQuick + " " + args;
}

/// The one "bench: error:" line of `output` ("" when there is none or more than one).
std::string errorLine(const std::string& output) {
    const size_t at = output.find("bench: error:");
    if (at == std::string::npos || output.find("bench: error:", at + 1) != std::string::npos) return "";
    return output.substr(at, output.find('\n', at) - at);
}

/// A binary STL of `triangles` separate unit triangles scattered over a 100^3 box (a fixed LCG):
/// no two share a corner, so every corner is one assimp keeps until it welds them, the worst case
/// of the import's cost per triangle.
void writeScatteredStl(const std::string& path, uint32_t triangles) {
    std::ofstream out(path, std::ios::binary);
    const char header[80] = "scattered triangles";
    out.write(header, sizeof header);
    out.write(reinterpret_cast<const char*>(&triangles), 4);
    uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24) * 100.0f;
    };
    std::vector<char> record(50, 0);
    for (uint32_t t = 0; t < triangles; ++t) {
        const float x = next(), y = next(), z = next();
        const float v[12] = {0, 0, 1, x, y, z, x + 1, y, z, x, y + 1, z};
        std::memcpy(record.data(), v, sizeof v);
        out.write(record.data(), 50);
    }
}

/// The estimate a refusal names ("estimated memory 205.1 MiB"), in MiB; -1 when there is none.
double estimatedMiB(const std::string& line) {
    static const std::regex kEstimate("estimated memory ([0-9.]+) (GiB|MiB|bytes)");
    std::smatch m;
    if (!std::regex_search(line, m, kEstimate)) return -1.0;
    const double value = std::stod(m[1]);
    return m[2] == "GiB" ? value * 1024.0 : m[2] == "MiB" ? value : value / 1048576.0;
}

} // namespace

TEST(SceneMemoryCli, TenMillionInstancesAreRefusedBeforeTheDocumentIsParsed) {
    // 10^7 entries of {"mesh":"b"} (130 MB of text): the document alone would take ~2.4 GB and the
    // instances ~3 GB more, over the 1 GiB given here. The refusal reads the text once and counts it
    // (a SAX pass): bounded by 512 MiB = the text (130 MB) + the process (~100 MiB) with room for the
    // reader's copies. Before, the document and instances were built first (3.6 GB when the 4 GiB
    // address-space cap stopped it; 8.8 GB uncapped).
    const std::string dir = test::freshTestDir("scenememory");
    const std::string scene = dir + "/many.json";
    {
        std::ofstream out(scene, std::ios::binary);
        out << R"({"meshes": [{"name": "b", "generator": "box"}],)"
            << "\n"
            << R"( "instances": [)";
        const std::string entry = R"({"mesh":"b"},)";
        std::string block;
        for (int i = 0; i < 100000; ++i) block += entry;
        for (int i = 0; i < 100; ++i) out << (i == 99 ? block.substr(0, block.size() - 1) : block);
        out << "]}\n";
    }
    const test::PeakResult r = test::runCommandPeak(bench("--scene " + scene + " --max-memory-gib 1"));
    const std::string line = errorLine(r.output);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(line.find(scene + ": "), std::string::npos) << r.output;
    EXPECT_NE(line.find("10000000 instances: estimated memory "), std::string::npos) << line;
    EXPECT_NE(line.find("exceeds the limit of 1.0 GiB (--max-memory-gib)"), std::string::npos) << line;
    EXPECT_LT(r.peakRssKiB, 512 * 1024) << "peak " << r.peakRssKiB << " KiB";
    std::filesystem::remove_all(dir);
}

TEST(SceneMemoryCli, MillionTriangleStlPastTheLimitIsRefusedBeforeImport) {
    // 10^6 separate triangles (50 MB): the import alone takes ~2 GB (assimp's welding records), over
    // the 0.05 GiB given. Refused from the header's count: bounded by 256 MiB, the process's own
    // ~100 MiB with room (the file is not read). Before, it was imported first (2.0 GB, 33 s) and
    // refused afterwards under an estimate of 0.1 GiB.
    const std::string dir = test::freshTestDir("scenememory");
    const std::string model = dir + "/scattered.stl";
    writeScatteredStl(model, 1000000);
    const test::PeakResult r =
        test::runCommandPeak(bench(kModelScene + " --model " + model + " --max-memory-gib 0.05"));
    const std::string line = errorLine(r.output);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(line.find("model file '" + model + "': 1000000 triangles, 3000000 vertices before welding"),
              std::string::npos)
        << r.output;
    EXPECT_NE(line.find("exceeds the limit of 51.2 MiB (--max-memory-gib)"), std::string::npos) << line;
    EXPECT_LT(r.peakRssKiB, 256 * 1024) << "peak " << r.peakRssKiB << " KiB";
    std::filesystem::remove_all(dir);
}

TEST(SceneMemoryCli, TenMillionTriangleStlIsRefusedUnderTheDefaultLimit) {
    // The header says 10^7 triangles and the size agrees (84 + 50 * 10^7 bytes, sparse: no disk
    // used). Importing it takes ~21 GB (3 * 10^7 corners at ~700 B), over the default 8 GiB; it was
    // accepted, with an estimate of 1.0 GiB made after the import. Bounded by 256 MiB as above.
    const std::string dir = test::freshTestDir("scenememory");
    const std::string model = dir + "/huge.stl";
    {
        std::ofstream out(model, std::ios::binary);
        const char header[80] = {};
        const uint32_t triangles = 10000000;
        out.write(header, sizeof header);
        out.write(reinterpret_cast<const char*>(&triangles), 4);
    }
    std::filesystem::resize_file(model, 84 + 50ull * 10000000);
    const test::PeakResult r = test::runCommandPeak(bench(kModelScene + " --model " + model));
    const std::string line = errorLine(r.output);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(line.find("model file '" + model + "': 10000000 triangles"), std::string::npos) << r.output;
    EXPECT_NE(line.find("exceeds the limit of 8.0 GiB (--max-memory-gib)"), std::string::npos) << line;
    EXPECT_GT(estimatedMiB(line), 8.0 * 1024) << line;
    EXPECT_LT(r.peakRssKiB, 256 * 1024) << "peak " << r.peakRssKiB << " KiB";
    std::filesystem::remove_all(dir);
}

TEST(SceneMemoryCli, AcceptedStlCostsWhatItsEstimateSays) {
    // 10^5 separate triangles. The estimate (named by a refusal under a 1 MiB limit) must cover what
    // the model adds to the run's peak: the peak with the model minus the peak of the same run on
    // the scene's own mesh (the process, llvmpipe and the teapot scene, which no model estimate
    // counts). Measured: ~165 MiB added, estimated ~210 MiB; before, 0.0 GiB was estimated. Slack:
    // the estimate may be up to 3x the measure (an over-estimate refuses models that would fit, but
    // the per-corner cost differs between formats and assimp versions), never below it.
    const std::string dir = test::freshTestDir("scenememory");
    const std::string model = dir + "/scattered.stl";
    writeScatteredStl(model, 100000);
    const test::PeakResult refused =
        test::runCommandPeak(bench(kModelScene + " --model " + model + " --max-memory-gib 0.001"));
    ASSERT_EQ(refused.exitCode, 2) << refused.output;
    const double estimate = estimatedMiB(errorLine(refused.output));
    const test::PeakResult base = test::runCommandPeak(bench(kModelScene));
    const test::PeakResult run = test::runCommandPeak(bench(kModelScene + " --model " + model));
    ASSERT_EQ(base.exitCode, 0) << base.output;
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const double added = double(run.peakRssKiB - base.peakRssKiB) / 1024.0;
    std::cout << "estimate " << estimate << " MiB, measured " << added << " MiB added to the peak ("
              << run.peakRssKiB / 1024 << " - " << base.peakRssKiB / 1024 << ")\n";
    EXPECT_GE(estimate, added) << errorLine(refused.output);
    EXPECT_LE(estimate, 3.0 * added) << errorLine(refused.output);
    std::filesystem::remove_all(dir);
}
