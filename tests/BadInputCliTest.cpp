// The bad-input table: every class of wrong input a hostile user tried, fed to the bench binary, each
// asserting the exit code (2: the input is wrong), one line on stderr naming what was wrong and where,
// and that a CSV written before is byte-identical afterwards with no file added beside it. Each row is
// an independent answer written by hand: the exit code the README's "Exit codes" promise and the words
// the message must contain.
#include <algorithm>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "ForgedPng.h"
#include "TestSupport.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

const std::string kQuick = " --size 64x64 --frames 1 --warmup 0 --no-timer-check";
const std::string kQuickSweep = " --size 64x64 --frames 1 --warmup 0 --no-progress";
const std::string kPreCsv = "technique,wall_ms_median\nnone,1.5\nshadowmap,\"2,5\"\n";

/// One bad input. `args` run in a scratch folder holding pre.csv (the earlier results) and whatever
/// `setup` makes there; "{dir}" in `args` is that folder. The run gets `--csv pre.csv` unless `args`
/// name a CSV of their own (then pre.csv must survive untouched all the same).
struct BadInput {
    const char* name;
    std::string args;
    std::vector<std::string> mustContain; ///< the message names what and where
    int exitCode = 2;
    std::function<bool(const std::string& dir)> setup; ///< false: the case cannot be made here (skipped)
    bool closeStdout = false;
    /// The args are a whole command line of their own (a subcommand that takes no run options, such as
    /// report, merge, export or golden): nothing is appended to them.
    bool bare = false;
};

bool makeFifo(const std::string& dir) {
    return ::mkfifo((dir + "/fifo.csv").c_str(), 0644) == 0;
}
bool makeDevices(const std::string& dir) {
    return ::mknod((dir + "/null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0 &&
           ::mknod((dir + "/zero").c_str(), S_IFCHR | 0666, makedev(1, 5)) == 0;
}

/// "from,from+1,...": `n` numbers, for the axes of a sweep too large to run.
std::string numberList(int from, int n) {
    std::string list;
    for (int i = 0; i < n; ++i) list += (i ? "," : "") + std::to_string(from + i);
    return list;
}

/// A setup that writes one file into the scratch folder.
std::function<bool(const std::string&)> file(const std::string& name, std::string text) {
    return [name, text](const std::string& dir) {
        test::writeFile(dir + "/" + name, text);
        return true;
    };
}

/// A scene of one sphere instance whose `position` is the given text, and ten more in a layout.
std::string sceneWith(const std::string& position, int tessellation = 8) {
    return R"({"meshes": [{"name": "ball", "generator": "sphere", "tessellation": )" +
           std::to_string(tessellation) +
           R"(}],
  "instances": [{"mesh": "ball", "position": )" +
           position + R"(}],
  "layout": {"mesh": "ball", "count": 10, "region": [[-5, 1, -5], [5, 2, 5]]},
  "cameras": [{"name": "far", "eye": [0, 20, 30]}]})";
}

/// A scene whose one mesh carries a shadow plane textured with `png` (huge.png), for the occluder
/// technique, which reads the texture as it prepares.
std::function<bool(const std::string&)> occluderTexture(std::string png) {
    return [png](const std::string& dir) {
        test::writeFile(dir + "/huge.png", png);
        test::writeFile(dir + "/plate.obj", "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
                                            "g plate\nf 1 4 3\nf 1 3 2\n");
        test::writeFile(dir + "/plate.json", R"({"name": "plate", "meshes": [{"name": "plate", "file":
  "plate.obj", "shadow_planes": [{"name": "p", "origin": [-0.5, 1, 0.5], "normal": [0, 1, 0], "right":
  [1, 0, 0], "up": [0, 0, -1], "width": 1, "height": 1, "texture": "huge.png"}]}],
  "instances": [{"mesh": "plate", "position": [0, 0, 0]}],
  "cameras": [{"name": "far", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1]}],
  "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}]})");
        return true;
    };
}

/// A PLY header of 3 vertices and `faces` faces in `format`.
std::string plyHeader(const std::string& format, int faces) {
    return "ply\nformat " + format +
           " 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nelement face " +
           std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::vector<BadInput> table() {
    return {
        // Numbers that overflow or make no sense.
        {"memory limit inf", "--max-memory-gib inf", {"--max-memory-gib", "inf"}},
        {"memory limit 1e30", "--max-memory-gib 1e30", {"--max-memory-gib", "1e+30"}},
        {"memory limit 0", "--max-memory-gib 0", {"--max-memory-gib"}},
        {"memory limit nan", "--max-memory-gib nan", {"--max-memory-gib"}},
        {"scale 1e-30", "--scale 1e-30", {"--scale", "1e-30"}},
        {"scale 0", "--scale 0", {"--scale"}},
        {"scale inf", "--scale inf", {"--scale"}},
        {"scale 1e30", "--scale 1e30", {"--scale"}},
        {"size 0x0", "--size 0x0", {"--size"}},
        {"size too large", "--size 99999x64", {"--size"}},
        {"frames 0", "--frames 0", {"--frames"}},
        {"repeat 0", "--repeat 0", {"--repeat"}},
        {"tess 0", "--tess 0", {"--tess"}},
        {"tess 5000", "--tess 5000", {"--tess"}},
        {"tess factor 100", "--tess-factor 100", {"--tess-factor"}},
        {"seed -5", "--seed -5", {"--seed"}},
        {"instances 0", "--instances 0", {"--instances"}},
        {"instances past memory", "--instances 900000", {"--instances 900000", "GiB"}},
        {"seconds negative", "--seconds -1", {"--seconds"}},
        {"text for a number", "--frames many", {"--frames"}},
        // Names that do not exist.
        {"unknown option", "--bogus", {"--bogus"}},
        {"unknown technique", "-t nosuch", {"nosuch"}},
        {"unknown property", "-t shadowmap:nokey=1", {"nokey"}},
        {"property out of range", "-t shadowmap:resolution=7", {"resolution"}},
        {"unknown light type", "--light laser", {"--light", "laser"}},
        {"unknown submit mode", "--submit telepathy", {"--submit", "telepathy"}},
        {"unknown backend", "--backend vulkan9", {"backend", "vulkan9"}},
        {"unknown scene", "--scene nosuchscene", {"nosuchscene"}},
        {"missing model", "--model {dir}/nope.obj", {"nope.obj"}},
        // Devices and backends.
        {"gpu with osmesa", "--gpu 0 --backend osmesa", {"--gpu", "osmesa"}},
        {"gpu negative", "--gpu -3", {"--gpu"}},
        // Paths: empty, missing, not a regular file, not an image format.
        {"empty csv path", "--csv ''", {"--csv", "empty"}},
        {"empty samples path", "--samples ''", {"--samples", "empty"}},
        {"empty screenshot path", "--screenshot ''", {"--screenshot", "empty"}},
        {"empty scene", "--scene ''", {"--scene", "empty"}},
        {"csv in a missing folder", "--csv {dir}/no/such/r.csv", {"{dir}/no/such/r.csv", "No such file"}},
        {"csv is a folder", "--csv {dir}", {"{dir}", "directory"}},
        {"csv is a FIFO", "--csv {dir}/fifo.csv", {"{dir}/fifo.csv", "FIFO"}, 2, makeFifo},
        {"csv is a null device", "--csv {dir}/null", {"{dir}/null", "character device"}, 2, makeDevices},
        {"samples on a zero device",
         "--samples {dir}/zero",
         {"{dir}/zero", "character device"},
         2,
         makeDevices},
        {"screenshot in a missing folder", "--screenshot {dir}/no/x.png", {"{dir}/no"}},
        {"screenshot format unknown", "--screenshot {dir}/x.qqq", {"--screenshot", "x.qqq"}},
        {"visibility is a folder", "--visibility {dir}", {"{dir}", "directory"}},
        {"rows to a closed stdout", "--format csv", {"--format", "stdout is closed"}, 2, nullptr, true},
        // Scene files.
        {"scene not JSON",
         "--scene " + std::string(SB_SOURCE_DIR) + "/tests/data/malformed.json",
         {"malformed.json"}},
        {"scene wrong type",
         "--scene " + std::string(SB_SOURCE_DIR) + "/tests/data/wrong_type.json",
         {"wrong_type.json"}},
        {"scene nested 100000 deep",
         "--scene {dir}/deep.json",
         {"deep.json", "nested"},
         2,
         file("deep.json", std::string(100000, '[') + std::string(100000, ']'))},
        {"scene number 1e400",
         "--scene {dir}/big.json",
         {"big.json", "line"},
         2,
         file("big.json", sceneWith("[1e400, 0, 0]"))},
        {"scene position 1e308",
         "--scene {dir}/huge.json",
         {"huge.json", "/instances/0/position"},
         2,
         file("huge.json", sceneWith("[1e308, 0, 0]"))},
        {"scene tessellation 4096",
         "--scene {dir}/tess.json",
         {"tess.json", "tessellation 4096", "GiB"},
         2,
         file("tess.json", sceneWith("[0, 0, 0]", 4096))},
        // Model files.
        {"model with 3e38 coordinates",
         "--scene teapot --model {dir}/far.obj",
         {"far.obj"},
         2,
         file("far.obj", "v 3e38 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n")},
        {"model of degenerate triangles",
         "--scene teapot --model {dir}/flat.obj",
         {"flat.obj", "degenerate"},
         2,
         file("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 3 2\n")},
        {"model truncated ASCII PLY",
         "--scene teapot --model {dir}/cut.ply",
         {"cut.ply", "truncated"},
         2,
         file("cut.ply", plyHeader("ascii", 2) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")},
        {"model truncated binary PLY",
         "--scene teapot --model {dir}/cutb.ply",
         {"cutb.ply"},
         2,
         file("cutb.ply", plyHeader("binary_little_endian", 2) + std::string(36, '\0') + "\x03")},
        {"model face index out of range",
         "--scene teapot --model {dir}/index.ply",
         {"index.ply"},
         2,
         file("index.ply", plyHeader("ascii", 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n")},
        // Reports: the page's path and the inputs are checked before anything is opened or written.
        {"report page on a null device",
         "report {dir} -o {dir}/null",
         {"{dir}/null", "character device"},
         2,
         makeDevices,
         false,
         true},
        {"report page is a folder",
         "report {dir} -o {dir}",
         {"'{dir}'", "directory"},
         2,
         nullptr,
         false,
         true},
        {"report input is a FIFO",
         "report {dir}/fifo.csv",
         {"{dir}/fifo.csv", "FIFO"},
         2,
         makeFifo,
         false,
         true},
        // Goldens and images: a PNG whose 74 bytes claim an image no file of the suite can be, refused
        // with the reason before its pixels are allocated (the 16-bit one cost 2.2 GB before).
        {"image claiming 65535x65535",
         "--scene {dir}/plate.json -t occluder",
         {"huge.png", "claims 65535x65535 pixels, over the 16384 a side"},
         2,
         occluderTexture(test::forgedPng(65535, 65535, 8, 6))},
        {"image claiming 2 GiB of rows in 74 bytes",
         "--scene {dir}/plate.json -t occluder",
         {"huge.png", "claims 16384x16384", "74 bytes of file cannot hold"},
         2,
         occluderTexture(test::forgedPng(16384, 16384, 16, 6))},
        // Scene and model files: emitter sizes within the coordinate bound, keys a light does not take,
        // camera paths through their target, model headers that disagree with the file.
        {"scene emitter size 3e38",
         "--scene {dir}/emitter.json",
         {"emitter.json", "/lights/0/size", "1e18"},
         2,
         file("emitter.json", R"({"meshes": [{"name": "ball", "generator": "sphere"}],
  "instances": [{"mesh": "ball", "position": [0, 1, 0]}],
  "lights": [{"type": "point", "position": [0, 8, 0], "shape": "sphere", "size": 3e38}],
  "cameras": [{"name": "far", "eye": [0, 5, 10]}]})")},
        {"scene spot light with angular_radius_deg",
         "--scene {dir}/spot.json",
         {"spot.json", "/lights/0/angular_radius_deg", "directional"},
         2,
         file("spot.json", R"({"meshes": [{"name": "ball", "generator": "sphere"}],
  "instances": [{"mesh": "ball", "position": [0, 1, 0]}],
  "lights": [{"type": "spot", "position": [0, 8, 0], "direction": [0, -1, 0], "shape": "disk", "size": 0.5,
              "angular_radius_deg": 5}],
  "cameras": [{"name": "far", "eye": [0, 5, 10]}]})")},
        {"scene camera path through its target",
         "--scene {dir}/path.json --camera path",
         {"path.json", "/motion/camera", "frame 2 of 4", "target"},
         2,
         file("path.json", R"({"meshes": [{"name": "ball", "generator": "sphere"}],
  "instances": [{"mesh": "ball", "position": [0, 1, 0]}],
  "motion": {"frames": 4, "camera": [{"eye": [0, 0, 10], "target": [0, 0, 0]},
                                     {"eye": [0, 0, -10], "target": [0, 0, 0]}]}})")},
        {"model STL header claiming 10^7 triangles",
         "--scene teapot --model {dir}/lie.stl",
         {"lie.stl", "declares 10000000 triangles", "the file has 584"},
         2,
         file("lie.stl",
              std::string(80, '\0') + std::string("\x80\x96\x98\x00", 4) + std::string(500, '\0'))},
        // Run options and memory limits: every value a user can type is taken at its word (no -1 or 0
        // stands for "not given"), and the GL context's options are refused under --api vulkan.
        {"gpu -1", "--gpu -1", {"--gpu -1", "0..1023"}},
        {"vk-device -1", "--api vulkan --vk-device -1", {"--vk-device -1", "0..1023"}},
        {"path-frames 0", "--path-frames 0", {"--path-frames 0", "2..1000000"}},
        {"time -1", "--time -1", {"--time -1", "[0, 1]"}},
        {"instances -1", "--instances -1", {"--instances -1"}},
        {"tess -1", "--tess -1", {"--tess -1", "1..1024"}},
        {"seed -1", "--seed -1", {"--seed -1", "0..4294967295"}},
        {"backend under vulkan", "--api vulkan --backend osmesa", {"--backend osmesa", "--vk-device"}},
        {"gpu under vulkan", "--api vulkan --gpu 0", {"--gpu", "--vk-device"}},
        {"sweep max-configs -1", "sweep -t none --max-configs -1", {"--max-configs -1"}},
        {"sweep repeat 0", "sweep -t none --repeat 0", {"--repeat 0", "1..1000"}},
        // What a technique allocates counts against --max-memory-gib, refused before it is allocated:
        // proxy's IndexMap of 1024^2 cells x 4096 entries is 32 GiB, cascaded maps of 8192^2 x 4 cascades
        // x 4 B are 1 GiB, each over the limit given.
        {"proxy grid past memory",
         "-t proxy:capacity=4096:cells=1024 --max-memory-gib 1",
         {"-t proxy:capacity=4096:cells=1024", "32.0 GiB", "--max-memory-gib"}},
        {"shadow maps past memory",
         "--scene sphere_plane -t cascaded:resolution=8192:cascades=4 --max-memory-gib 0.5",
         {"-t cascaded:resolution=8192:cascades=4", "1.0 GiB", "--max-memory-gib"}},
        {"sweep technique past memory",
         "sweep -t proxy:cells=1024:capacity=4096 --max-memory-gib 1",
         {"sweep: combination", "-t proxy:cells=1024:capacity=4096", "--max-memory-gib"}},
        // Result files: every cell a dashboard export converts is checked, naming file, row and column.
        {"gbench negative frame count",
         "export {dir}/neg.csv --format gbench",
         {"neg.csv:2", "column 'frames'", "'-3' is negative"},
         2,
         file("neg.csv", "status,frames,wall_ms_median\nok,-3,1.5\n"),
         false,
         true},
        {"gbench frame count beyond 64 bits",
         "export {dir}/huge.csv --format gbench",
         {"huge.csv:3", "column 'frames'", "'1e30' is not a whole number"},
         2,
         file("huge.csv", "status,frames,wall_ms_median\nok,3,1.5\nok,1e30,1.5\n"),
         false,
         true},
        {"gbench wall time beyond double range",
         "export {dir}/wall.csv --format gbench",
         {"wall.csv:2", "column 'wall_ms_median'", "'1e999' is beyond the range"},
         2,
         file("wall.csv", "status,frames,wall_ms_median\nok,3,1e999\n"),
         false,
         true},
        {"gbench Latin-1 byte",
         "export {dir}/latin.csv --format gbench",
         {"latin.csv:2", "column 'scene'", "invalid UTF-8 (byte 0xE9"},
         2,
         file("latin.csv", "status,scene,frames,wall_ms_median\nok,caf\xE9,3,1.5\n"),
         false,
         true},
        // Merges: the shards of one sweep measured on two CPU models, or built from two commits.
        {"merge of two CPU models",
         "merge -o {dir}/all.csv {dir}/a.csv {dir}/b.csv",
         {"cpu_model 'AMD EPYC 7B13' in '{dir}/a.csv:2' but 'Intel Xeon' in '{dir}/b.csv:2'",
          "--allow-mixed"},
         2,
         [](const std::string& dir) {
             const std::string header = "sweep_id,sweep_configs,config_index,shard,status,cpu_model\n";
             test::writeFile(dir + "/a.csv", header + "s1,2,0,1/2,ok,AMD EPYC 7B13\n");
             test::writeFile(dir + "/b.csv", header + "s1,2,1,2/2,ok,Intel Xeon\n");
             return true;
         },
         false,
         true},
        {"merge of two commits",
         "merge -o {dir}/all.csv {dir}/a.csv {dir}/b.csv",
         {"git_commit 'fd7aef0' in '{dir}/a.csv:2' but 'c2b2495' in '{dir}/b.csv:2'", "--allow-mixed"},
         2,
         [](const std::string& dir) {
             const std::string header = "sweep_id,sweep_configs,config_index,shard,status,git_commit\n";
             test::writeFile(dir + "/a.csv", header + "s1,2,0,1/2,ok,fd7aef0\n");
             test::writeFile(dir + "/b.csv", header + "s1,2,1,2/2,ok,c2b2495\n");
             return true;
         },
         false,
         true},
        // A sweep's --retry-failed continues a sweep: alone it is refused.
        {"sweep retry-failed without resume", "sweep -t none --retry-failed", {"--retry-failed", "--resume"}},
        // The light fit of the flat maps: a fit that is not one of the choices, a negative margin.
        {"light fit unknown", "-t shadowmap:fit=view", {"fit", "view", "casters", "sphere", "scene"}},
        {"light fit of vsm unknown",
         "-t vsm:fit=receivers",
         {"fit", "receivers", "casters", "sphere", "scene"}},
        {"light fit margin negative", "-t pcss:fit_margin=-0.5", {"fit_margin", "-0.5"}},
        // bench floors: the options it would not honour and the techniques it cannot floor, refused before
        // any frame (its rows go to stdout only).
        {"floors with a CSV",
         "floors -t none --csv {dir}/pre.csv",
         {"bench floors does not take --csv"},
         2,
         nullptr,
         false,
         true},
        {"floors in rounds",
         "floors -t none --repeat 2",
         {"bench floors does not take --repeat"},
         2,
         nullptr,
         false,
         true},
        {"floors as JSON",
         "floors -t none --format json",
         {"bench floors does not take --format json"},
         2,
         nullptr,
         false,
         true},
        {"floors of -t auto",
         "floors -t auto",
         {"bench floors does not take -t auto"},
         2,
         nullptr,
         false,
         true},
        {"floors of an unknown technique", "floors -t shadowmapp", {"shadowmapp"}, 2, nullptr, false, true},
        // Back-face culling: the scene file's per-mesh "closed" and the run option.
        {"mesh closed not a boolean",
         "--scene {dir}/closed.json",
         {"closed.json", "/meshes/0/closed", "true or false"},
         2,
         file("closed.json", R"({"meshes": [{"name": "ball", "generator": "sphere", "closed": "yes"}],
  "instances": [{"mesh": "ball"}], "cameras": [{"name": "far", "eye": [0, 20, 30]}]})")},
        {"--back-faces of an unknown value", "--back-faces maybe", {"--back-faces maybe", "cull or draw"}, 2},
        // The lighting rate: the scene file's key and the run option.
        {"lighting of an unknown rate",
         "--scene {dir}/lighting.json",
         {"lighting.json", "/lighting", "fragment, vertex"},
         2,
         file("lighting.json", R"({"meshes": [{"name": "ball", "generator": "sphere"}], "lighting": "pixel",
  "instances": [{"mesh": "ball"}], "cameras": [{"name": "far", "eye": [0, 20, 30]}]})")},
        {"--lighting of an unknown rate", "--lighting phong", {"--lighting phong", "fragment or vertex"}, 2},
        // Sweeps: refused before anything is measured.
        {"sweep of a million",
         "sweep -t shadowmap:resolution=" + numberList(17, 100) + " -n " + numberList(1, 100) + " --scale " +
             numberList(1, 100),
         {"1000000 configurations", "--max-configs"}},
        {"sweep option a worker rejects", "sweep -t none -n 1,900000", {"instances=900000", "GiB"}},
        {"sweep bad value", "sweep -t none --scale 1,1e-30", {"scale=1e-30", "--scale"}},
        {"sweep max-configs 0", "sweep -t none --max-configs 0", {"--max-configs"}},
        {"sweep shard past count", "sweep -t none --shard 3/2", {"--shard"}},
    };
}

std::string substitute(std::string text, const std::string& dir) {
    for (size_t at; (at = text.find("{dir}")) != std::string::npos;) text.replace(at, 5, dir);
    return text;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

std::vector<std::string> listDir(const std::string& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

TEST(BadInputCli, EveryClassOfBadInputIsOneLineAndExitTwoAndLosesNothing) {
    int tried = 0, clean = 0, skipped = 0;
    for (const BadInput& c : table()) {
        SCOPED_TRACE(c.name);
        const std::string dir = test::freshDir("badinput");
        test::writeFile(dir + "/pre.csv", kPreCsv);
        if (c.setup && !c.setup(dir)) {
            ++skipped; // e.g. mknod without root: said in the summary below
            continue;
        }
        const std::vector<std::string> before = listDir(dir);
        const std::string args = substitute(c.args, dir);
        const bool ownCsv = args.find("--csv") != std::string::npos;
        const std::string err = dir + "/../badinput-stderr.txt";
        const bool sweep = args.rfind("sweep ", 0) == 0;
        const std::string appended =
            c.bare ? "" : std::string(sweep ? kQuickSweep : kQuick) + (ownCsv ? "" : " --csv pre.csv");
        std::string command = "cd " + dir + " && " + SB_BENCH_BINARY + " " + args + appended + " 2>" + err +
                              (c.closeStdout ? " >&-" : " >/dev/null");
        // A hung run (the FIFO case before the fix) is a failure, not a hang of the suite.
        const int code = test::runCommand("timeout 60 sh -c " + test::shellQuoted(command)).exitCode;
        ++tried;
        const std::vector<std::string> stderrLines = lines(test::readFile(err));
        bool ok = true;
        auto expect = [&](bool condition, const std::string& what) {
            EXPECT_TRUE(condition) << what;
            ok = ok && condition;
        };
        expect(code == c.exitCode, "exit code " + std::to_string(code) + ", expected " +
                                       std::to_string(c.exitCode) + " for: " + args);
        expect(stderrLines.size() == 1, "stderr has " + std::to_string(stderrLines.size()) +
                                            " lines, expected one: " + test::readFile(err));
        const std::string message = stderrLines.empty() ? "" : stderrLines.front();
        expect(message.rfind("bench: error: ", 0) == 0, "message: " + message);
        for (const std::string& word : c.mustContain)
            expect(message.find(substitute(word, dir)) != std::string::npos,
                   "message lacks '" + substitute(word, dir) + "': " + message);
        expect(test::readFile(dir + "/pre.csv") == kPreCsv, "pre.csv changed");
        expect(listDir(dir) == before, "files appeared or vanished in the scratch folder");
        clean += ok;
        fs::remove_all(dir);
    }
    std::cout << "bad-input table: " << tried << " tried, " << clean << " clean, " << skipped
              << " skipped (cannot be made here, e.g. mknod without root)\n";
    EXPECT_EQ(clean, tried);
}

} // namespace
