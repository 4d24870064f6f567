#pragma once
// Shared helpers of the GL and CLI tests: small run configurations, read-backs with world positions,
// running the bench binary.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "TestPaths.h"
#include "bench/lib/options/RunConfig.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

namespace sb::test {

/// A quick configuration: tiny frame counts, no timer calibration, fixed size.
inline RunConfig quickConfig(const std::string& scene, const std::string& camera, int size,
                             SubmitMode submit = SubmitMode::Retained) {
    return RunConfig::oneFrame(scene, camera, size, submit);
}

/// The value of counter `name` in a technique's counters() (a failure, and 0, when it is missing).
inline double counter(const std::vector<std::pair<std::string, double>>& counters, const std::string& name) {
    for (const auto& [n, v] : counters)
        if (n == name) return v;
    ADD_FAILURE() << "no counter " << name;
    return 0.0;
}

/// World position of every pixel from the depth buffer (row-major, bottom-up as GL reads). Pixels at
/// depth 1 (background) get w = 0, others w = 1.
inline std::vector<glm::vec4> unprojectDepth(const std::vector<float>& depth, int w, int h,
                                             const glm::mat4& viewProj) {
    glm::mat4 inv = glm::inverse(viewProj);
    std::vector<glm::vec4> out(depth.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float d = depth[size_t(y) * size_t(w) + size_t(x)];
            if (d >= 1.0f) continue;
            glm::vec4 ndc((x + 0.5f) / float(w) * 2.0f - 1.0f, (y + 0.5f) / float(h) * 2.0f - 1.0f,
                          d * 2.0f - 1.0f, 1.0f);
            glm::vec4 p = inv * ndc;
            out[size_t(y) * size_t(w) + size_t(x)] = glm::vec4(glm::vec3(p) / p.w, 1.0f);
        }
    return out;
}

struct CommandResult {
    int exitCode = -1;
    std::string output; ///< stdout and stderr together
};

/// Runs a shell command, capturing stdout+stderr.
inline CommandResult runCommand(const std::string& command) {
    CommandResult r;
    FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf{};
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
    int status = pclose(p);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// `s` as one word for /bin/sh: single-quoted, each ' written as '\''.
inline std::string shellQuoted(const std::string& s) {
    std::string q = "'";
    for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
}

/// Every row of the CSV at `path`, column name -> cell (a missing cell is the empty string).
inline std::vector<std::map<std::string, std::string>> csvRowMaps(const std::string& path) {
    const CsvTable t = CsvWriter::read(path);
    std::vector<std::map<std::string, std::string>> out;
    for (const auto& row : t.rows) {
        std::map<std::string, std::string> m;
        for (size_t i = 0; i < t.header.size() && i < row.size(); ++i) m[t.header[i]] = row[i];
        out.push_back(m);
    }
    return out;
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// A fresh empty directory for the running gtest test: `prefix`, suite and test name (a parameterised
/// name's '/' made '-') and the process id, so parallel ctest runs never share one.
inline std::string freshTestDir(const std::string& prefix) {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "-" + info->name();
    std::replace(name.begin(), name.end(), '/', '-');
    const auto dir = std::filesystem::temp_directory_path() /
                     ("shadowbench-" + prefix + "-" + name + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

/// A fresh empty directory under the build tree's temp area for one test.
inline std::string freshDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("shadowbench-test-" + name + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

/// Every column of the table in bench/lib/output/ResultColumns.h, families with their `<placeholder>`.
/// tests/CsvDocTest.cpp holds docs/CSV.md equal to that table, so this is the documented list too,
/// read from its one home rather than parsed from the document a second time.
inline std::vector<std::string> documentedColumns() {
    std::vector<std::string> cols;
    for (const ColumnInfo& c : ResultColumns::all()) cols.emplace_back(c.name);
    return cols;
}

/// Whether `header` has the column `documented` or, for a family, some member of it.
inline bool headerHas(const std::vector<std::string>& header, const std::string& documented) {
    const ColumnInfo* info = nullptr;
    for (const ColumnInfo& c : ResultColumns::all())
        if (c.name == documented) info = &c;
    if (!info) return false; // not a documented column at all
    return std::any_of(header.begin(), header.end(),
                       [&](const std::string& h) { return ResultColumns::matches(*info, h); });
}

/// Documented columns a plain run does not write: only sweeps, bottleneck studies, failed
/// configurations, bench ci (ci_*), runs with a deliberate regression switched on (injected), rows
/// of `-t auto` (auto_*: AutoCliTest checks those) and runs without --screenshot or --visibility (*_file:
/// CliTest's short run writes them).
inline const std::set<std::string>& sweepOnlyColumns() {
    static const std::set<std::string> kColumns = {
        "error",       "technique_spec",  "config_index",    "config_group",   "sweep_id",
        "sweep_name",  "sweep_configs",   "shard",           "perturbation",   "study_base",
        "injected",    "ci_config",       "ci_side",         "ci_round",       "ci_role",
        "auto_choice", "auto_candidates", "screenshot_file", "visibility_file"};
    return kColumns;
}

} // namespace sb::test
