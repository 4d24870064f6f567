// The Debian package as Debian's own tools judge it: CPack builds the .deb, dpkg-deb reads its files
// and control fields, and lintian checks it against Debian policy (no error and no warning). One test,
// so the package is built once (ctest runs every gtest test in a process of its own). The expected values
// come from the source tree (CITATION.cff's version and licence) and from what the installed bench reads at
// run time. About 15 s on an idle machine (cpack: ~4 s, most of it dpkg-shlibdeps; lintian: ~8 s).
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "TestSupport.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

std::string shellQuoted(const fs::path& p) {
    return "'" + p.string() + "'";
}

/// The value of CITATION.cff's top-level "KEY: VALUE" line.
std::string citationField(const std::string& key) {
    const std::string text = test::readFile((fs::path(SB_SOURCE_DIR) / "CITATION.cff").string());
    std::smatch m;
    return std::regex_search(text, m, std::regex("(^|\\n)" + key + ": *([^\\n]*)")) ? m[2].str() : "";
}

/// The package CPack builds from this build folder, unpacked beside it.
class PackageCliTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = test::freshTestDir("package");
        const fs::path build = fs::path(SB_BENCH_BINARY).parent_path();
        const auto pack =
            test::runCommand("cd " + shellQuoted(mDir) + " && cpack -G DEB --config " +
                             shellQuoted(build / "CPackConfig.cmake") + " -B " + shellQuoted(mDir));
        for (const auto& e : fs::directory_iterator(mDir))
            if (e.path().extension() == ".deb") mDeb = e.path();
        ASSERT_FALSE(mDeb.empty()) << "cpack built no .deb:\n" << pack.output;
        const auto unpack = test::runCommand("dpkg-deb -x " + shellQuoted(mDeb) + " " + shellQuoted(root()));
        ASSERT_EQ(unpack.exitCode, 0) << unpack.output;
    }
    void TearDown() override { fs::remove_all(mDir); }

    fs::path root() const { return fs::path(mDir) / "root"; }
    std::string field(const std::string& name) const {
        return test::runCommand("dpkg-deb -f " + shellQuoted(mDeb) + " " + name).output;
    }

    void expectWhatTheInstalledBenchReadsAndItsDependencies() const;
    void expectStrippedBinariesAndPolicyDocuments() const;
    void expectLintianClean() const;

    std::string mDir;
    fs::path mDeb;
};

} // namespace

void PackageCliTest::expectWhatTheInstalledBenchReadsAndItsDependencies() const {
    const fs::path share = root() / "usr" / "share";
    for (const fs::path& f :
         {root() / "usr" / "bin" / "bench", root() / "usr" / "bin" / "handshadow",
          share / "shadowbench" / "shaders" / "common" / "lighting.glsl",
          share / "shadowbench" / "scenes" / "data" / "aircraft.json",
          share / "shadowbench" / "tools" / "plot.py", share / "shadowbench" / "tools" / "report.py",
          share / "shadowbench" / "results" / "figures" / "figures.json",
          share / "shadowbench" / "results" / "ci" / "suite.json", share / "man" / "man1" / "bench.1.gz",
          share / "bash-completion" / "completions" / "bench", share / "man" / "man1" / "handloop.1.gz",
          share / "man" / "man1" / "handshadow.1.gz"})
        EXPECT_TRUE(fs::exists(f)) << f << " not in the package";
    // Every manual page is compressed, whoever installed it (cmake/debian/GzipManPages.cmake).
    for (const auto& e : fs::recursive_directory_iterator(share / "man"))
        if (e.is_regular_file()) {
            EXPECT_EQ(e.path().extension(), ".gz") << e.path();
        }
    // dpkg-shlibdeps found the shared libraries the binaries link (Embree's among them); python3 runs
    // the tools, the plot libraries are recommended.
    const std::string depends = field("Depends");
    for (const char* d : {"libembree", "libassimp", "libvulkan1", "python3", "libegl1"})
        EXPECT_NE(depends.find(d), std::string::npos) << d << " not in Depends: " << depends;
    EXPECT_NE(field("Recommends").find("python3-matplotlib"), std::string::npos);
    EXPECT_EQ(field("Package"), "shadowbench\n");
    EXPECT_EQ(field("Version"), citationField("version") + "\n");
    EXPECT_EQ(field("Section"), "graphics\n");
    EXPECT_EQ(field("Priority"), "optional\n");
}

void PackageCliTest::expectStrippedBinariesAndPolicyDocuments() const {
    const fs::path unpacked = root();
    for (const char* b : {"bench", "handloop", "handshadow"}) {
        const auto sections = test::runCommand("readelf -S " + shellQuoted(unpacked / "usr" / "bin" / b));
        ASSERT_EQ(sections.exitCode, 0) << sections.output;
        EXPECT_EQ(sections.output.find(".symtab"), std::string::npos) << b << " is not stripped";
        EXPECT_EQ(sections.output.find(".debug_"), std::string::npos) << b << " carries debug information";
    }
    const fs::path doc = unpacked / "usr" / "share" / "doc" / "shadowbench";
    const std::string copyright = test::readFile((doc / "copyright").string());
    EXPECT_EQ(
        copyright.rfind("Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n", 0),
        0u)
        << copyright;
    EXPECT_NE(copyright.find("\nLicense: " + citationField("license") + "\n"), std::string::npos)
        << copyright;
    // A Debian changelog entry for this version, compressed as policy asks.
    const auto changelog = test::runCommand("gzip -dc " + shellQuoted(doc / "changelog.gz"));
    ASSERT_EQ(changelog.exitCode, 0) << changelog.output;
    EXPECT_EQ(changelog.output.rfind("shadowbench (" + citationField("version") + ") ", 0), 0u)
        << changelog.output;
    EXPECT_NE(field("Maintainer").find("@"), std::string::npos);
    EXPECT_EQ(field("Maintainer").find("localhost"), std::string::npos);
}

void PackageCliTest::expectLintianClean() const {
    // Root or not, lintian checks the same; it only says it would rather not run as root.
    const auto lint = test::runCommand("lintian --fail-on error,warning " + shellQuoted(mDeb));
    EXPECT_EQ(lint.exitCode, 0) << lint.output;
    EXPECT_FALSE(std::regex_search(lint.output, std::regex("(^|\\n)[EW]: "))) << lint.output;
}

TEST_F(PackageCliTest, DebIsCompleteStrippedAndLintianClean) {
    expectWhatTheInstalledBenchReadsAndItsDependencies();
    expectStrippedBinariesAndPolicyDocuments();
    expectLintianClean();
}
