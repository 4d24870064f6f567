// Every command the documentation shows runs as written. The commands are the lines of the ```sh blocks
// of README.md, docs/*.md and techniques/*/README.md (a line ending in '\' continues on the next; lines
// starting with '#' are comments). Each file's commands run in order, in a fresh temporary folder that
// stands for a checkout after the quick start: every top-level entry of the source tree linked in, and
// build/ holding links to this build's bench, handloop and handshadow; `bench` is on PATH too. So
// `build/bench ... --csv out/x.csv` writes into the temporary folder, and a command that reads
// sweeps/ or scenes/ reads the source tree.
//
// A command runs unless it starts with one of kNotRun's prefixes, each with the reason it is too long or
// needs what a test cannot have (root, a cluster, a display). A command that is neither a short one (it
// starts, after `mkdir -p ... &&` and NAME=value assignments, with bench, build/bench or
// /usr/bin/python3 tools/) nor listed fails the test, so a new long command cannot slip in unnoticed; a
// listed prefix that no command starts with fails it too (the list cannot go stale). Every run command
// must exit 0 within kCommandLimitS and leave the source tree's `git status` as it found it.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"

namespace fs = std::filesystem;
using sb::test::runCommand;
using sb::test::shellQuoted;

namespace {

/// One command of the documentation and where it was found.
struct DocCommand {
    std::string file; ///< relative to the source tree
    int line = 0;     ///< 1-based line of its first line
    std::string text; ///< continuation lines joined with a space
};

struct NotRun {
    std::string prefix;
    std::string reason;
};

// The documented commands this test does not run, and why. Keep it to what cannot run in a test.
const std::vector<NotRun> kNotRun = {
    {"bash scripts/bench.sh", "installs packages (root) and builds the project: what this build already did"},
    {"bash scripts/test.sh", "the whole test suite, of which this test is a part"},
    {"bash scripts/gate.sh", "builds and runs the whole perf gate (minutes)"},
    {"bash scripts/sanitize.sh", "a second build with ASan and UBSan (about 12 minutes)"},
    {"bash scripts/fuzz.sh", "fuzzes for minutes"},
    {"SB_FUZZ_TARGETS=", "fuzzes for minutes"},
    {"bash scripts/vulkan.sh", "measures results/vulkan/ (about 12 minutes)"},
    {"cmake ", "configures or builds the project: what this build already did"},
    {"ctest ", "runs tests of the suite this test belongs to"},
    {"(cd build && cpack", "packages the build (InstallCliTest builds the package)"},
    {"build/bench golden", "renders the whole matrix (minutes; MatrixGLTest is its test)"},
    {"build/bench figures", "reruns or replots every figure (minutes; FiguresCliTest and PlotCliTest)"},
    {"build/bench ci", "the perf gate (minutes; PerfGateCliTest)"},
    {"build/bench sweep", "sweeps of many configurations (minutes; SweepCliTest)"},
    {"build/bench bottleneck", "a bottleneck study (minutes; BottleneckCliTest)"},
    {"build/bench --window", "needs a display (ViewerCliTest drives it under Xvfb)"},
    {"build/bench compare", "needs two result files of the gate (PerfGateCliTest)"},
    {"build/bench merge", "needs the shards of a sweep (SweepCliTest)"},
    {"parallel ", "a sharded sweep under GNU parallel (SweepCliTest)"},
    {"sbatch ", "a Slurm cluster"},
    {"bash scripts/slurm-submit.sh", "a Slurm cluster (JobArraySlurmTest runs it on one)"},
    {"bash tools/slurm/cluster.sh", "starts Slurm's daemons as root (JobArraySlurmTest, label slurm)"},
    {"export SLURM_CONF=", "names the cluster tools/slurm/cluster.sh started"},
    {"build/handloop", "alternates a hundred frame pairs (HandShadowCliTest runs it short)"},
    {"bash scripts/install-deps.sh", "installs packages as root (the test command installs its groups)"},
    {"tools/perf/glmark2-compare.sh",
     "alternates glmark2 and bench for minutes (Glmark2CompareCliTest runs one round)"},
};

constexpr int kCommandLimitS = 60;

std::string trim(const std::string& s) {
    const size_t b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

/// The documentation files whose commands are checked, relative to the source tree, sorted.
std::vector<std::string> docFiles(const fs::path& root) {
    std::vector<std::string> files = {"README.md"};
    for (const auto& e : fs::directory_iterator(root / "docs"))
        if (e.path().extension() == ".md") files.push_back(fs::relative(e.path(), root).string());
    for (const auto& e : fs::directory_iterator(root / "techniques"))
        if (fs::exists(e.path() / "README.md"))
            files.push_back(fs::relative(e.path() / "README.md", root).string());
    std::sort(files.begin() + 1, files.end());
    return files;
}

/// The commands of one file's ```sh blocks, in order.
std::vector<DocCommand> commandsOf(const fs::path& root, const std::string& file) {
    std::ifstream in(root / file);
    std::vector<DocCommand> out;
    std::string line;
    bool inSh = false, continued = false;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = trim(line);
        if (t.rfind("```", 0) == 0) {
            inSh = !inSh && t == "```sh";
            continued = false;
            continue;
        }
        if (!inSh || (!continued && (t.empty() || t[0] == '#'))) continue;
        const bool continues = !t.empty() && t.back() == '\\';
        const std::string part = continues ? trim(t.substr(0, t.size() - 1)) : t;
        if (continued)
            out.back().text += " " + part;
        else
            out.push_back({file, n, part});
        continued = continues;
    }
    return out;
}

/// The entry of kNotRun the command starts with, or nullptr.
const NotRun* notRunEntry(const std::string& command) {
    for (const auto& e : kNotRun)
        if (command.rfind(e.prefix, 0) == 0) return &e;
    return nullptr;
}

/// The command with a leading `mkdir -p ... &&` and NAME=value assignments taken off.
std::string programPart(std::string c) {
    if (c.rfind("mkdir -p ", 0) == 0 && c.find("&&") != std::string::npos)
        c = trim(c.substr(c.find("&&") + 2));
    while (!c.empty() && c.find('=') != std::string::npos && c.find('=') < c.find(' ') &&
           std::isupper(static_cast<unsigned char>(c[0])))
        c = trim(c.substr(c.find(' ')));
    return c;
}

bool isShort(const std::string& command) {
    const std::string p = programPart(command);
    for (const char* start : {"bench ", "build/bench ", "/usr/bin/python3 tools/"})
        if (p.rfind(start, 0) == 0) return true;
    return false;
}

/// A folder that stands for a checkout after the quick start (see the file's comment).
fs::path makeCheckout(const fs::path& root, const std::string& name) {
    const fs::path dir = sb::test::freshDir("docs-" + name);
    for (const auto& e : fs::directory_iterator(root)) {
        const std::string n = e.path().filename().string();
        if (n == "build" || n == ".git" || n.rfind("build-", 0) == 0) continue;
        fs::create_directory_symlink(e.path(), dir / n);
    }
    const fs::path bin = fs::path(SB_BENCH_BINARY).parent_path();
    fs::create_directories(dir / "build");
    for (const char* tool : {"bench", "handloop", "handshadow"})
        if (fs::exists(bin / tool)) fs::create_symlink(bin / tool, dir / "build" / tool);
    return dir;
}

std::string gitStatus(const fs::path& root) {
    return runCommand("git -C " + shellQuoted(root.string()) + " status --porcelain --untracked-files=all")
        .output;
}

std::vector<DocCommand> allCommands(const fs::path& root) {
    std::vector<DocCommand> all;
    for (const auto& f : docFiles(root)) {
        auto c = commandsOf(root, f);
        all.insert(all.end(), c.begin(), c.end());
    }
    return all;
}

/// Each technique's properties as `bench --list` prints them: name -> "type default", in order.
std::map<std::string, std::vector<std::string>> listedProperties() {
    const auto r = runCommand(std::string(SB_BENCH_BINARY) + " --list");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::map<std::string, std::vector<std::string>> out;
    std::istringstream in(r.output);
    const std::regex property(R"(^\s+(\w+)\s+(int|float|bool|enum)\s+default (\S+))");
    std::string line, technique;
    std::smatch m;
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] != ' ') technique = line.substr(0, line.find(' '));
        if (std::regex_search(line, m, property))
            out[technique].push_back(m[1].str() + " " + m[2].str() + " " + m[3].str());
    }
    return out;
}

/// The rows of a README's knob table: "name type default", in order.
std::vector<std::string> documentedProperties(const fs::path& readme) {
    std::ifstream in(readme);
    const std::regex row(R"(^\| `(\w+)` \| (int|float|bool|enum) \| (\S+) \|)");
    std::vector<std::string> out;
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
        if (std::regex_search(line, m, row)) out.push_back(m[1].str() + " " + m[2].str() + " " + m[3].str());
    return out;
}

// A technique folder named after its technique documents that technique's knobs as `bench --list` gives
// them (name, type, default, in order; a family folder at least names each), so the table cannot drift
// from the code.
TEST(DocsCommandsCli, TechniqueReadmesListTheKnobsOfBenchList) {
    const fs::path root = SB_SOURCE_DIR;
    const auto listed = listedProperties();
    int checked = 0;
    for (const auto& e : fs::directory_iterator(root / "techniques")) {
        const std::string name = e.path().filename().string();
        if (!fs::exists(e.path() / "README.md") || !listed.count(name) || listed.at(name).empty()) continue;
        const auto documented = documentedProperties(e.path() / "README.md");
        if (documented.empty()) {
            // A family folder (techniques/shadowmap) names its members' knobs in a table of its own.
            const std::string text = sb::test::readFile((e.path() / "README.md").string());
            for (const auto& p : listed.at(name)) {
                const std::string knob = "`" + p.substr(0, p.find(' ')) + "`";
                EXPECT_NE(text.find(knob), std::string::npos) << "techniques/" << name << " lacks " << knob;
            }
        } else {
            EXPECT_EQ(documented, listed.at(name)) << "techniques/" << name;
        }
        ++checked;
    }
    EXPECT_GE(checked, 8) << "technique READMEs with knob tables";
}

// The extraction itself, on a block written here: continuation, comments, text blocks left alone.
TEST(DocsCommandsCli, ExtractsTheCommandsOfShBlocksOnly) {
    const fs::path dir = sb::test::freshDir("docs-extract");
    fs::create_directories(dir / "docs");
    fs::create_directories(dir / "techniques");
    sb::test::writeFile((dir / "README.md").string(),
                        "text\n```sh\n# a comment\nbench -t a \\\n    -t b   # two\n\nbench --list\n```\n"
                        "```text\nbench not a command\n```\n```\nbench nor this\n```\n");
    const auto c = allCommands(dir);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].text, "bench -t a -t b   # two");
    EXPECT_EQ(c[0].line, 4);
    EXPECT_EQ(c[1].text, "bench --list");
    EXPECT_TRUE(isShort("mkdir -p out && build/bench -t none"));
    EXPECT_TRUE(isShort("SB_X=1 build/bench -t none"));
    EXPECT_FALSE(isShort("cmake --install build"));
    fs::remove_all(dir);
}

// Every command is run or listed with its reason, and every listed prefix is still used.
TEST(DocsCommandsCli, EveryCommandIsRunOrListedWithItsReason) {
    const fs::path root = SB_SOURCE_DIR;
    const auto all = allCommands(root);
    ASSERT_GT(all.size(), 20u) << "too few documented commands found: is README.md there?";
    std::set<std::string> used;
    for (const auto& c : all) {
        if (const NotRun* e = notRunEntry(c.text)) {
            used.insert(e->prefix);
            std::cout << "not run: " << c.file << ":" << c.line << "  " << c.text << "  (" << e->reason
                      << ")\n";
            continue;
        }
        EXPECT_TRUE(isShort(c.text))
            << c.file << ":" << c.line << ": `" << c.text
            << "` is neither a short command nor in kNotRun (add it with the reason)";
    }
    for (const auto& e : kNotRun)
        EXPECT_TRUE(used.count(e.prefix)) << "kNotRun lists `" << e.prefix << "`, which no document uses";
}

// The short commands run as written, each file's in order in its own checkout-like folder.
TEST(DocsCommandsCli, TheShortCommandsRunAsWritten) {
    const fs::path root = SB_SOURCE_DIR;
    const std::string before = gitStatus(root);
    const std::string path = fs::path(SB_BENCH_BINARY).parent_path().string();
    for (const auto& file : docFiles(root)) {
        const auto commands = commandsOf(root, file);
        if (commands.empty()) continue;
        std::string name = file;
        std::replace(name.begin(), name.end(), '/', '-');
        const fs::path dir = makeCheckout(root, name);
        for (const auto& c : commands) {
            if (notRunEntry(c.text) || !isShort(c.text)) continue;
            const auto t0 = std::chrono::steady_clock::now();
            const auto r = runCommand("cd " + shellQuoted(dir.string()) + " && PATH=" + shellQuoted(path) +
                                      ":\"$PATH\" timeout " + std::to_string(kCommandLimitS) + " bash -c " +
                                      shellQuoted(c.text) + " </dev/null");
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::cout << file << ":" << c.line << "  " << s << " s  " << c.text << "\n";
            EXPECT_EQ(r.exitCode, 0) << file << ":" << c.line << ": `" << c.text << "` failed:\n" << r.output;
        }
        fs::remove_all(dir);
    }
    EXPECT_EQ(gitStatus(root), before) << "a documented command wrote into the source tree";
}

} // namespace
