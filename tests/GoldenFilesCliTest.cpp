// The golden files of `bench golden` under damage: a kill -9 in the middle of --update, a golden truncated
// to nothing or to part of itself, a forged header claiming a huge image. The answers are written down
// here: a golden is either the old image or the new one (PngFile reads it), an unreadable golden fails
// its own cell only (the other cells' verdicts printed, exit 1 as for any failed check) and --update
// replaces it, saying so in one line; a forged header is refused before its pixels are allocated.
#include <csignal>
#include <filesystem>
#include <poll.h>
#include <string>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "ForgedPng.h"
#include "HostileSupport.h"
#include "TestSupport.h"
#include "core/Error.h"
#include "core/PngFile.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

// One technique on the smallest built-in scene: each golden run is a few seconds.
const std::string kCells = " --technique none,pcss --scene sphere_plane";

/// A scratch golden folder holding the committed goldens of none and pcss on sphere_plane and the
/// committed bounds.
std::string goldenCopy(const std::string& dir) {
    const fs::path from = fs::path(SB_SOURCE_DIR) / "results" / "goldens";
    fs::create_directories(fs::path(dir) / "sphere_plane");
    for (const char* technique : {"none", "pcss"})
        for (const char* kind : {"visibility", "colour"}) {
            const std::string name = std::string("sphere_plane/") + technique + "." + kind + ".png";
            fs::copy_file(from / name, fs::path(dir) / name);
        }
    fs::copy_file(from / "bounds.json", fs::path(dir) / "bounds.json");
    return dir;
}

std::string golden(const std::string& dir, const std::string& technique, const std::string& kind) {
    return dir + "/sphere_plane/" + technique + "." + kind + ".png";
}

/// Lines of `text` that contain `word`.
std::vector<std::string> linesWith(const std::string& text, const std::string& word) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string::npos) nl = text.size();
        const std::string line = text.substr(start, nl - start);
        if (line.find(word) != std::string::npos) out.push_back(line);
        start = nl + 1;
    }
    return out;
}

/// "" when every golden in `dir`'s scene folder is a PNG that reads; else which is not and why.
std::string unreadableGolden(const std::string& dir) {
    for (const auto& e : fs::directory_iterator(fs::path(dir) / "sphere_plane")) {
        if (e.path().extension() != ".png") continue; // a killed writer's "<golden>.tmp" is no golden
        try {
            PngFile::read(e.path().string());
        } catch (const Error& err) {
            return err.what();
        }
    }
    return "";
}

TEST(GoldenFilesCli, AKillDuringUpdateLeavesEveryGoldenReadable) {
    // --size 256 changes every golden (they are 128x128), so every one is rewritten. The kill lands on
    // the k-th change the folder sees (inotify: a file created, written or renamed into it), i.e. inside
    // the write of the first golden, just after it, and inside the second: where a golden written in
    // place is truncated or half written.
    for (int k : {1, 2, 4}) {
        SCOPED_TRACE("killed at change " + std::to_string(k));
        const std::string dir = goldenCopy(test::freshTestDir("goldenkill") + "/goldens");
        const int watch = inotify_init1(IN_CLOEXEC);
        ASSERT_GE(watch, 0);
        ASSERT_GE(
            inotify_add_watch(watch, (dir + "/sphere_plane").c_str(), IN_CREATE | IN_MODIFY | IN_MOVED_TO),
            0);
        const std::string command = std::string("exec ") + SB_BENCH_BINARY + " golden --update --dir " + dir +
                                    " --technique none --scene sphere_plane --size 256 >/dev/null 2>&1";
        const pid_t pid = fork();
        if (pid == 0) {
            execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        int seen = 0;
        bool killed = false;
        char events[4096];
        pollfd p{watch, POLLIN, 0};
        while (!killed && poll(&p, 1, 30000) > 0) {
            const ssize_t n = read(watch, events, sizeof events);
            for (ssize_t at = 0; at < n && !killed;) {
                const auto* e = reinterpret_cast<const inotify_event*>(events + at);
                at += ssize_t(sizeof(inotify_event) + e->len);
                if (++seen == k) killed = kill(pid, SIGKILL) == 0;
            }
        }
        int status = 0;
        waitpid(pid, &status, 0);
        close(watch);
        EXPECT_TRUE(killed && WIFSIGNALED(status)) << "the update ended before change " << k;
        EXPECT_EQ(unreadableGolden(dir), "");
        // A "<golden>.tmp" the kill left behind is allowed: the next write of that golden reuses it.
        for (const auto& e : fs::directory_iterator(dir + "/sphere_plane"))
            if (e.path().extension() == ".png")
                EXPECT_GT(fs::file_size(e.path()), 0u) << e.path() << " is empty";
        fs::remove_all(fs::path(dir).parent_path());
    }
}

TEST(GoldenFilesCli, AnUnreadableGoldenFailsItsCellAndUpdateReplacesIt) {
    const std::string dir = goldenCopy(test::freshTestDir("goldenbroken") + "/goldens");
    const std::string emptied = golden(dir, "none", "visibility"), cut = golden(dir, "none", "colour");
    test::writeFile(emptied, "");
    test::writeFile(cut, test::readFile(cut).substr(0, 100));
    const std::string bench = std::string(SB_BENCH_BINARY) + " golden --dir " + dir;

    // --check: none's cells fail naming each file and why, pcss's still pass, exit 1 (a failed check).
    const test::CommandResult check =
        test::runCommand("(" + bench + " --check --verbose" + kCells + " 2>" + dir + "/../stderr.txt)");
    EXPECT_EQ(check.exitCode, 1) << check.output;
    EXPECT_EQ(linesWith(check.output, "pcss/sphere_plane/retained: ok").size(), 1u) << check.output;
    EXPECT_EQ(linesWith(check.output, "none/sphere_plane/retained: FAILED").size(), 1u) << check.output;
    EXPECT_FALSE(linesWith(check.output, "'" + emptied + "': not a PNG file").empty()) << check.output;
    EXPECT_FALSE(linesWith(check.output, "'" + cut + "': truncated").empty()) << check.output;
    EXPECT_FALSE(linesWith(check.output, "golden check: 12 cells checked, 6 failed").empty()) << check.output;
    const std::string stderrText = test::readFile(dir + "/../stderr.txt");
    EXPECT_TRUE(linesWith(stderrText, "libpng").empty()) << stderrText;
    EXPECT_TRUE(linesWith(stderrText, "error").empty()) << stderrText;

    // --update replaces both, one line each saying so; then none's cells pass.
    const test::CommandResult update =
        test::runCommand("(" + bench + " --update --technique none --scene sphere_plane 2>/dev/null)");
    EXPECT_EQ(update.exitCode, 0) << update.output;
    EXPECT_EQ(linesWith(update.output, emptied + ": replaced an unreadable golden").size(), 1u)
        << update.output;
    EXPECT_EQ(linesWith(update.output, cut + ": replaced an unreadable golden").size(), 1u) << update.output;
    EXPECT_EQ(unreadableGolden(dir), "");
    const test::CommandResult again =
        test::runCommand("(" + bench + " --check --technique none --scene sphere_plane 2>/dev/null)");
    EXPECT_EQ(again.exitCode, 0) << again.output;
    fs::remove_all(fs::path(dir).parent_path());
}

TEST(GoldenFilesCli, AForgedHugeHeaderIsRefusedBeforeItsPixelsAreAllocated) {
    // 74-byte PNGs: a valid signature and IHDR (correct CRC), an IDAT of 1000 zero bytes, IEND. One
    // claims 65535x65535 (a side no image of the suite has), the other 16384x16384 RGBA at 16 bits,
    // within every side limit, whose 2 GiB of rows the old reader allocated (and zeroed) before finding
    // the data missing.
    const std::string dir = goldenCopy(test::freshTestDir("goldenforged") + "/goldens");
    test::writeFile(golden(dir, "none", "visibility"), test::forgedPng(65535, 65535, 8, 6));
    test::writeFile(golden(dir, "none", "colour"), test::forgedPng(16384, 16384, 16, 6));
    const test::PeakResult r =
        test::runCommandPeak(std::string("exec ") + SB_BENCH_BINARY + " golden --check --dir " + dir +
                             " --technique none --scene sphere_plane --size 16");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_FALSE(linesWith(r.output, "claims 65535x65535 pixels, over the 16384 a side").empty()) << r.output;
    EXPECT_FALSE(linesWith(r.output, "claims 16384x16384").empty()) << r.output;
    EXPECT_TRUE(linesWith(r.output, "libpng").empty()) << r.output;
    // Under 600 MiB: the check itself peaks near 170 MiB (GL and Vulkan contexts, a 16x16 matrix); the
    // old reader reached 2.2 GB on the 16-bit header.
    EXPECT_LT(r.peakRssKiB, 600 * 1024) << r.output;
    fs::remove_all(fs::path(dir).parent_path());
}

// A technique's variant (bench/golden/MatrixVariants.h) is chosen by its spec and refused by a driver as
// its technique is. The system driver has no ray queries: raytraced:mode=soft's two Vulkan cells are said
// not run (its GL cells have no form), a check passes, and an update there keeps the variant's goldens,
// bounds and row of MATRIX.md as they were (they are written on mesa-25.0.7). A spec that is not one of
// the technique's variants is bad input naming the forms it has.
TEST(GoldenFilesCli, AVariantIsChosenByItsSpecAndKeptWhereItsDriverCannotRunIt) {
    const std::string dir = goldenCopy(test::freshTestDir("goldenvariant") + "/goldens");
    const fs::path from = fs::path(SB_SOURCE_DIR) / "results" / "goldens";
    for (const char* name : {"sphere_plane/raytraced.mode=soft.visibility.png",
                             "sphere_plane/raytraced.mode=soft.colour.png", "MATRIX.md"})
        fs::copy_file(from / name, fs::path(dir) / name);
    const std::string bounds = test::readFile(dir + "/bounds.json"),
                      page = test::readFile(dir + "/MATRIX.md");
    const std::string golden = test::readFile(dir + "/sphere_plane/raytraced.mode=soft.visibility.png");
    ASSERT_NE(bounds.find("\"raytraced.mode=soft/sphere_plane/light0\""), std::string::npos);
    ASSERT_NE(page.find("| raytraced.mode=soft | sphere_plane | no GL form"), std::string::npos);
    const std::string cells = " --dir " + dir + " --scene sphere_plane --technique raytraced:mode=soft";

    const auto check = test::runCommand(std::string(SB_BENCH_BINARY) + " golden --check" + cells);
    EXPECT_EQ(check.exitCode, 0) << check.output;
    for (const char* mode : {"retained", "instanced"}) {
        const std::string notRun = std::string("raytraced:mode=soft/sphere_plane/") + mode +
                                   "/vulkan: not run: not on the driver system: raytraced needs";
        EXPECT_EQ(linesWith(check.output, notRun).size(), 1u) << check.output;
    }
    EXPECT_EQ(linesWith(check.output, "0 cells checked, 0 failed, 4 unsupported").size(), 1u) << check.output;
    EXPECT_EQ(linesWith(check.output, "2 not run on this driver").size(), 1u) << check.output;

    const auto update = test::runCommand(std::string(SB_BENCH_BINARY) + " golden --update" + cells);
    EXPECT_EQ(update.exitCode, 0) << update.output;
    EXPECT_EQ(linesWith(update.output, "(1 rows of cells this driver cannot run kept as they were)").size(),
              1u)
        << update.output;
    EXPECT_EQ(test::readFile(dir + "/sphere_plane/raytraced.mode=soft.visibility.png"), golden);
    EXPECT_EQ(test::readFile(dir + "/bounds.json"), bounds);
    EXPECT_EQ(test::readFile(dir + "/MATRIX.md"), page);

    const auto hard = test::runCommand(std::string(SB_BENCH_BINARY) + " golden --check --dir " + dir +
                                       " --technique raytraced:mode=hard");
    EXPECT_EQ(hard.exitCode, 2) << hard.output;
    EXPECT_EQ(linesWith(hard.output, "bench: error: --technique raytraced:mode=hard: not a form the matrix "
                                     "renders; raytraced's are raytraced, raytraced:mode=soft, "
                                     "raytraced:mode=guided")
                  .size(),
              1u)
        << hard.output;
    fs::remove_all(fs::path(dir).parent_path());
}

} // namespace
