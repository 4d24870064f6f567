// Every picture the bench writes, on a disk with no room left (tests/HostileSupport.h): --screenshot,
// --visibility, bench accuracy --images and bench golden --update must fail as --csv fails there (the
// same exit code, one line naming the path and the OS reason), keep what the folder held before byte for
// byte (a CSV and an older image at the very path being written) and leave no 0-byte, partial or
// temporary file. The independent answer for the exit code is --csv's own, measured on the same disk in
// the same test.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HostileSupport.h"
#include "TestSupport.h"
#include "core/PngFile.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

const std::string kQuick = " --scene sphere_plane --size 32x32 --frames 1 --warmup 0 --no-timer-check -q";
const std::string kPreCsv = "technique,wall_ms_median\nnone,1.5\n";

/// A real 2x1 PNG's bytes: the older image that must survive a failed replacement.
std::string oldPngBytes(const std::string& scratch) {
    const uint8_t grey[2] = {7, 200};
    PngFile::write(scratch, 2, 1, 1, grey);
    const std::string bytes = test::readFile(scratch);
    fs::remove(scratch);
    return bytes;
}

/// Every regular file under `dir` (relative name -> content), the filler of the full disk left out.
std::map<std::string, std::string> filesUnder(const std::string& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() && e.path().filename() != ".filler")
            out[fs::relative(e.path(), dir).string()] = test::readFile(e.path().string());
    return out;
}

/// Runs bench `args` ("{dir}" is the full disk's folder) against `disk`, stdout dropped: exit code and
/// stderr's lines.
std::pair<int, std::vector<std::string>> runOnDisk(const test::FullDisk& disk, std::string args) {
    for (size_t at; (at = args.find("{dir}")) != std::string::npos;) args.replace(at, 5, disk.dir());
    const std::string inner = std::string(SB_BENCH_BINARY) + " " + args + " 2>&1 >/dev/null";
    const test::CommandResult r = test::runCommand("sh -c " + test::shellQuoted(disk.wrap(inner)));
    std::vector<std::string> lines;
    size_t start = 0;
    for (size_t nl; (nl = r.output.find('\n', start)) != std::string::npos; start = nl + 1)
        lines.push_back(r.output.substr(start, nl - start));
    if (start < r.output.size()) lines.push_back(r.output.substr(start));
    return {r.exitCode, lines};
}

struct ImageCase {
    const char* name;
    std::string args; ///< "{dir}" is the full disk
    std::string
        target; ///< the image the command writes first, relative to the disk; an older one waits there
};

TEST(ImageOutputCli, AFullDiskFailsEveryImageAsTheCsvFailsAndLosesNothing) {
    const std::string scratch = test::freshTestDir("imagefull");
    const std::string oldPng = oldPngBytes(scratch + "/old.png");
    int csvCode = -1;
    {
        test::FullDisk disk(scratch + "/csv");
        disk.plant("pre.csv", kPreCsv);
        csvCode = runOnDisk(disk, kQuick + " --csv {dir}/pre.csv").first;
        EXPECT_EQ(test::readFile(disk.dir() + "/pre.csv"), kPreCsv) << "--csv lost rows on " << disk.how();
    }
    ASSERT_EQ(csvCode, 1) << "--csv on a full disk is a failure of the run (exit 1)";

    const std::vector<ImageCase> cases = {
        {"--screenshot", kQuick + " --screenshot {dir}/shot.png", "shot.png"},
        {"--visibility", kQuick + " --visibility {dir}/vis.png", "vis.png"},
        {"accuracy --images", "accuracy" + kQuick + " --images {dir}/maps",
         "maps/sphere_plane.shadowmap.light0.technique.png"},
        // 16x16 differs from the 2x1 golden planted, so the update must replace it.
        {"golden --update", "golden --update --dir {dir} --technique none --scene sphere_plane --size 16",
         "sphere_plane/none.visibility.png"},
    };
    for (const ImageCase& c : cases) {
        SCOPED_TRACE(c.name);
        test::FullDisk disk(scratch + "/disk");
        fs::create_directories(fs::path(disk.dir()) / fs::path(c.target).parent_path());
        disk.plant("pre.csv", kPreCsv);
        disk.plant(c.target, oldPng);
        const std::map<std::string, std::string> before = filesUnder(disk.dir());
        const auto [code, lines] = runOnDisk(disk, c.args);

        EXPECT_EQ(code, csvCode) << "on " << disk.how();
        std::vector<std::string> errors;
        for (const std::string& line : lines) {
            if (line.find("error") != std::string::npos) errors.push_back(line);
            EXPECT_EQ(line.find("libpng"), std::string::npos) << line;
        }
        ASSERT_EQ(errors.size(), 1u) << "on " << disk.how() << ": " << testing::PrintToString(lines);
        const std::string& message = errors.front();
        EXPECT_EQ(message.rfind("bench: error: cannot write image '" + disk.dir() + "/", 0), 0u) << message;
        const bool osReason = message.find("No space left on device") != std::string::npos ||
                              message.find("File too large") != std::string::npos;
        EXPECT_TRUE(osReason) << message;
        // Nothing earlier lost and nothing added: no 0-byte image, no partial one, no temporary file.
        EXPECT_EQ(filesUnder(disk.dir()), before) << "on " << disk.how();
    }
    fs::remove_all(scratch);
}

} // namespace
