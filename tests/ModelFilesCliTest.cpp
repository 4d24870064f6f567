// Model files through the bench binary, for every technique of `bench --list`: a model with an
// infinite vertex is refused (exit 2, one error line naming the model file, and the scene file when it
// came from one) on both paths, --model and a scene file's model entry; a multi-object model (each
// object its own caster) runs with every technique, and the row still counts the instances asked for.
// Hostile files (a truncated PLY, a scene nested 100000 deep or holding 1e400) are bad input too:
// exit 2 and one line, where they crashed (exit 139) or left as an unknown exception (exit 1).
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "SecondDriver.h"
#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"

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

/// The techniques `bench --list` prints, one at the start of each technique's block, in its order, and
/// whether the block's `apis:` line says it has no GL form ("apis: vulkan (no GL form: ...)").
std::vector<std::pair<std::string, bool>> listedBlocks() {
    const auto r = runCommand(bench("--list"));
    std::vector<std::pair<std::string, bool>> blocks;
    std::istringstream lines(r.output);
    static const std::regex head("^([a-z_]+)  \\S");
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_search(line, m, head))
            blocks.emplace_back(m[1], false);
        else if (!blocks.empty() && line.find("  apis:") == 0 && line.find("no GL form") != std::string::npos)
            blocks.back().second = true;
    }
    return blocks;
}

std::vector<std::string> listedTechniques() {
    std::vector<std::string> names;
    for (const auto& [name, withoutGl] : listedBlocks()) names.push_back(name);
    return names;
}

std::vector<std::string> techniquesWithoutGlForm() {
    std::vector<std::string> names;
    for (const auto& [name, withoutGl] : listedBlocks())
        if (withoutGl) names.push_back(name);
    return names;
}

/// The one "bench: error:" line of `output` ("" when there is none or more than one).
std::string errorLine(const std::string& output) {
    const size_t at = output.find("bench: error:");
    if (at == std::string::npos || output.find("bench: error:", at + 1) != std::string::npos) return "";
    return output.substr(at, output.find('\n', at) - at);
}

/// The options that run `t` on a form it has: a technique without a GL form runs on Vulkan on the second
/// driver, whose lavapipe offers what the only such technique (raytraced) needs (tests/SecondDriver.h).
std::string formOf(const std::string& t, const std::vector<std::string>& withoutGl) {
    if (std::find(withoutGl.begin(), withoutGl.end(), t) == withoutGl.end()) return "";
    return std::string(" --api vulkan --driver ") + test::kSecondDriver;
}

} // namespace

TEST(ModelFilesCli, ListNamesEveryTechnique) {
    // The tests below walk this list: it must hold every technique (the shadow-map family after
    // shadowmap), the reference and the calibration workloads, in the registry's order.
    EXPECT_EQ(listedTechniques(),
              (std::vector<std::string>{
                  "none",   "shadowmap",  "cubemap", "paraboloid", "cascaded",  "pcss",      "vsm",
                  "esm",    "evsm",       "msm",     "virtual",    "volume",    "occluder",  "proxy",
                  "planar", "projective", "blob",    "hybrid",     "raytraced", "reference", "synthetic"}));
    EXPECT_EQ(techniquesWithoutGlForm(), std::vector<std::string>{"raytraced"});
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
    const std::vector<std::string> withoutGl = techniquesWithoutGlForm();
    if (!withoutGl.empty()) REQUIRE_SECOND_DRIVER();
    const std::vector<std::string> techniques = listedTechniques();
    for (const std::string& t : techniques) {
        auto r = runCommand(bench("-t " + t + formOf(t, withoutGl) + " --instances 3 --model " + kRoom +
                                  " --csv " + csv + kQuick));
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

namespace {

/// `bytes` written to `path` as they are (binary).
void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

/// A binary PLY square of two triangles with its last 7 bytes cut off (inside the second face).
std::string truncatedBinaryPly() {
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 2\n"
                      "property list uchar int vertex_indices\nend_header\n";
    const float vertices[12] = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
    ply.append(reinterpret_cast<const char*>(vertices), sizeof vertices);
    for (const std::array<int32_t, 3>& face :
         {std::array<int32_t, 3>{0, 2, 1}, std::array<int32_t, 3>{0, 3, 2}}) {
        ply += char(3);
        ply.append(reinterpret_cast<const char*>(face.data()), 12);
    }
    return ply.substr(0, ply.size() - 7);
}

} // namespace

TEST(ModelFilesCli, TruncatedBinaryPlyIsBadInputOnBothPaths) {
    // It crashed inside assimp's post-processing (SIGSEGV, exit 139) on both paths.
    const std::string dir = test::freshDir("model-files-cli-hostile");
    const std::string ply = dir + "/truncated.ply", scene = dir + "/truncated.json";
    writeBytes(ply, truncatedBinaryPly());
    writeBytes(scene, R"({"meshes": [{"name": "m", "file": "truncated.ply"}], "instances": [{"mesh": "m"}],
                          "cameras": [{"name": "far", "eye": [0, 5, 10]}]})");
    const std::string reason =
        "': the PLY header declares 2 'face' records but the file ends after 1 of them: "
        "the file is truncated";
    auto model = runCommand(bench("-t planar --instances 2 --model " + ply + kQuick));
    EXPECT_EQ(model.exitCode, 2) << model.output;
    EXPECT_EQ(errorLine(model.output), "bench: error: model file '" + ply + reason) << model.output;
    auto fromScene = runCommand(bench("-t planar --scene " + scene + kQuick));
    EXPECT_EQ(fromScene.exitCode, 2) << fromScene.output;
    EXPECT_EQ(errorLine(fromScene.output),
              "bench: error: " + scene + ": /meshes/0/file: model file '" + ply + reason)
        << fromScene.output;
}

TEST(ModelFilesCli, HostileSceneFilesAreBadInput) {
    // 100000 nested arrays crashed (SIGSEGV, exit 139); 1e400 left as nlohmann's out_of_range, exit 1,
    // naming neither file nor place.
    const std::string dir = test::freshDir("scene-files-cli-hostile");
    const struct {
        const char* name;
        std::string text;
        std::string error;
    } cases[] = {
        {"deep.json", std::string(100000, '[') + std::string(100000, ']'),
         "invalid JSON at line 1, column 65: arrays and objects nested deeper than 64 levels"},
        {"overflow.json", "{\n  \"name\": 1e400}",
         "invalid JSON at line 2, column 11: the number 1e400 is beyond"},
    };
    for (const auto& c : cases) {
        const std::string path = dir + "/" + c.name;
        writeBytes(path, c.text);
        auto r = runCommand(bench("-t planar --scene " + path + kQuick));
        EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.output;
        EXPECT_EQ(errorLine(r.output).rfind("bench: error: " + path + ": " + c.error, 0), 0u)
            << c.name << ": " << r.output;
    }
}
