// Model files through the bench binary, for every technique of `bench --list`: a model with an
// infinite vertex is refused (exit 2, one error line naming the model file, and the scene file when it
// came from one) on both paths, --model and a scene file's model entry; a multi-object model (each
// object its own caster) runs with every technique, and the row still counts the instances asked for.
#include <filesystem>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/output/CsvWriter.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kQuick = " --size 64x64 --frames 1 --warmup 0 --no-timer-check -q";
const std::string kInfiniteModel = std::string(SB_SOURCE_DIR) + "/tests/data/infinite_vertex.obj";
const std::string kInfiniteScene = std::string(SB_SOURCE_DIR) + "/tests/data/infinite_vertex.json";
const std::string kRoom = "/usr/share/assimp/models/3DS/test1.3ds"; // nine objects (assimp-testmodels)

std::string bench(const std::string& args) {
    return std::string(SB_BENCH_BINARY) + " " + args;
}

/// The technique names `bench --list` prints, one at the start of each technique's block.
std::vector<std::string> listedTechniques() {
    const auto r = runCommand(bench("--list"));
    std::vector<std::string> names;
    std::istringstream lines(r.output);
    static const std::regex head("^([a-z_]+)  \\S");
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_search(line, m, head)) names.push_back(m[1]);
    }
    return names;
}

/// The one "bench: error:" line of `output` ("" when there is none or more than one).
std::string errorLine(const std::string& output) {
    const size_t at = output.find("bench: error:");
    if (at == std::string::npos || output.find("bench: error:", at + 1) != std::string::npos) return "";
    return output.substr(at, output.find('\n', at) - at);
}

} // namespace

TEST(ModelFilesCli, ListNamesEveryTechnique) {
    // The tests below walk this list: it must hold the nine techniques and the reference.
    EXPECT_EQ(listedTechniques().size(), 10u);
}

TEST(ModelFilesCli, InfiniteVertexIsRefusedByEveryTechniqueOnEveryPath) {
    for (const std::string& t : listedTechniques()) {
        auto model = runCommand(bench("-t " + t + " --instances 2 --model " + kInfiniteModel + kQuick));
        EXPECT_EQ(model.exitCode, 2) << t << ": " << model.output;
        EXPECT_NE(errorLine(model.output).find("model file '" + kInfiniteModel + "': vertex 1 "),
                  std::string::npos)
            << t << ": " << model.output;
        auto scene = runCommand(bench("-t " + t + " --scene " + kInfiniteScene + kQuick));
        EXPECT_EQ(scene.exitCode, 2) << t << ": " << scene.output;
        const std::string line = errorLine(scene.output);
        EXPECT_NE(line.find(kInfiniteScene + ": /meshes/0/file: model file '"), std::string::npos)
            << t << ": " << scene.output;
        EXPECT_NE(line.find("infinite_vertex.obj': vertex 1 "), std::string::npos) << t << ": " << line;
    }
}

TEST(ModelFilesCli, EveryTechniqueRunsAMultiObjectModel) {
    if (!std::filesystem::exists(kRoom)) GTEST_SKIP() << kRoom << " not installed (scripts/install-deps.sh)";
    const std::string csv = test::freshDir("model-files-cli") + "/rows.csv";
    const std::vector<std::string> techniques = listedTechniques();
    for (const std::string& t : techniques) {
        auto r = runCommand(bench("-t " + t + " --instances 3 --model " + kRoom + " --csv " + csv + kQuick));
        EXPECT_EQ(r.exitCode, 0) << t << ": " << r.output;
    }
    // One row per technique, each counting the 3 instances asked for (not 3 x 9 object instances).
    const CsvTable table = CsvWriter::read(csv);
    ASSERT_EQ(table.rows.size(), techniques.size());
    const size_t column =
        size_t(std::find(table.header.begin(), table.header.end(), "instances") - table.header.begin());
    ASSERT_LT(column, table.header.size());
    for (const auto& row : table.rows) EXPECT_EQ(row[column], "3");
}
