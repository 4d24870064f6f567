// The instruction-count gate's pure parts (bench/ci/): the callgrind parser on a hand-written file with
// hand-computed self costs (tests/data/callgrind/two_calls.out, its header comment has the sums), the
// cost categories, pairing dumps with bench rows, the per-frame diff, the fingerprint comparison and the
// one-line reason a child under valgrind died (on tests/data/callgrind/sigill-libhwy.stderr.txt, the log
// of `valgrind --tool=callgrind bench --version` on an AMD EPYC whose CPUID hides RDTSCP, with the bench
// linking OpenImageIO and through it libhwy). No valgrind needed: InstructionCountValgrindTest runs the
// real thing.
#include <csignal>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include "TestPaths.h"
#include "bench/lib/callgrind/CallgrindDump.h"
#include "bench/lib/callgrind/InstructionCount.h"
#include "bench/lib/callgrind/InstructionDiff.h"
#include "bench/lib/callgrind/ValgrindDiagnosis.h"
#include "bench/lib/gate/Fingerprint.h"
#include "core/Error.h"

using namespace sb;

namespace {

std::string fixture() {
    return std::string(SB_SOURCE_DIR) + "/tests/data/callgrind/two_calls.out";
}

uint64_t irOf(const CallgrindDump& d, const std::string& function) {
    for (const FunctionIr& f : d.functions)
        if (f.function == function) return f.ir;
    return 0;
}

CallgrindDump parseText(const std::string& text) {
    std::istringstream in(text);
    return CallgrindDump::parse(in, "inline");
}

} // namespace

TEST(CallgrindDumpTest, SelfCostsSkipCallCostsAndResolveCompressedNames) {
    const CallgrindDump d = CallgrindDump::read(fixture());
    EXPECT_EQ(d.part, 2);
    EXPECT_EQ(d.dumpName, "shadowmap");
    EXPECT_EQ(d.trigger, "Client Request: shadowmap");
    EXPECT_EQ(d.totalIr, 14490u); // from totals:, the summary: 0 line before it ignored
    ASSERT_EQ(d.functions.size(), 6u);
    // Counting the calls= lines' inclusive costs as self cost would give renderFrame 183 + 14000.
    EXPECT_EQ(irOf(d, "sb::Harness::renderFrame(sb::Technique&)"), 183u);
    EXPECT_EQ(irOf(d, "glDrawElements"), 2500u); // defined by cfn=(2), used as fn=(2)
    EXPECT_EQ(irOf(d, "memcpy"), 2500u);
    EXPECT_EQ(irOf(d, "0x000000001ff4a880"), 9000u);
    EXPECT_EQ(irOf(d, "llvm::SelectionDAG::Combine"), 300u);
    EXPECT_EQ(irOf(d, "epoxy_glDrawElements"), 7u);
    // Descending; the tie of 2500 keeps (object, function) order: dri/ before libc.
    EXPECT_EQ(d.functions[0].function, "0x000000001ff4a880");
    EXPECT_EQ(d.functions[0].object, "???");
    EXPECT_EQ(d.functions[1].function, "glDrawElements");
    EXPECT_EQ(d.functions[1].object, "/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so");
    EXPECT_EQ(d.functions[2].function, "memcpy");
}

TEST(CallgrindDumpTest, CategoriesOfTheFixture) {
    const CallgrindDump d = CallgrindDump::read(fixture());
    const TechniqueInstructions t =
        TechniqueInstructions::fromDump(d, "shadowmap", "", 4, "/opt/sb/build/bench");
    EXPECT_EQ(t.byCategory[int(CostCategory::Harness)], 183u);
    EXPECT_EQ(t.byCategory[int(CostCategory::Mesa)], 2500u);
    EXPECT_EQ(t.byCategory[int(CostCategory::System)], 2500u);
    EXPECT_EQ(t.byCategory[int(CostCategory::ShaderJit)], 9000u);
    EXPECT_EQ(t.byCategory[int(CostCategory::Llvm)], 300u);
    EXPECT_EQ(t.byCategory[int(CostCategory::Other)], 7u);
    EXPECT_DOUBLE_EQ(t.irPerFrame, 14490.0 / 4.0);
    EXPECT_NEAR(t.fraction(CostCategory::ShaderJit), 9000.0 / 14490.0, 1e-12);
    const nlohmann::json j = t.toJson(2);
    EXPECT_EQ(j["categories"]["shader_jit"], 9000u);
    EXPECT_EQ(j["top_functions"].size(), 2u);
    EXPECT_EQ(j["top_functions"][1]["function"], "glDrawElements");
}

TEST(CallgrindDumpTest, ClassifiesMesaLibrariesAndTheHarnessByFileName) {
    EXPECT_EQ(classifyObject("", ""), CostCategory::ShaderJit);
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/libgallium-24.2.so", ""), CostCategory::Mesa);
    // lavapipe, the Vulkan side of the same driver
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/libvulkan_lvp.so", ""), CostCategory::Mesa);
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/libOSMesa.so.8", ""), CostCategory::Mesa);
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/libLLVM-15.so.1", ""), CostCategory::Llvm);
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/libm.so.6", ""), CostCategory::System);
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/ld-linux-x86-64.so.2", ""), CostCategory::System);
    EXPECT_EQ(classifyObject("/other/tree/build/bench", "/work/build/bench"), CostCategory::Harness);
    EXPECT_EQ(classifyObject("/usr/lib/x86_64-linux-gnu/libGLdispatch.so.0", "/work/build/bench"),
              CostCategory::Other);
}

TEST(CallgrindDumpTest, IrIsFoundByItsEventIndexAndTrailingZerosAreOmitted) {
    // Two subpositions (instr line), Ir the second event; "0x20 3 4" has Dr only, so its Ir is 0.
    const CallgrindDump d = parseText("events: Dr Ir\npositions: instr line\nob=/lib/libc.so.6\nfn=f\n"
                                      "0x10 3 7 5\n+4 * 1 2\n0x20 3 4\ntotals: 12 7\n");
    EXPECT_EQ(d.totalIr, 7u);
    EXPECT_EQ(irOf(d, "f"), 7u); // 12 if the Dr column were read
}

TEST(CallgrindDumpTest, RefusesTotalsThatDoNotAddUpAndUndefinedNames) {
    EXPECT_THROW(parseText("events: Ir\nfn=f\n0 5\ntotals: 6\n"), Error);
    EXPECT_THROW(parseText("events: Ir\nfn=(7)\n0 5\ntotals: 5\n"), Error);
    EXPECT_THROW(parseText("events: Dr\nfn=f\n0 5\n"), Error); // no Ir to count
    EXPECT_NO_THROW(parseText("events: Ir\nfn=(7) f\nfn=(7)\n0 5\ntotals: 5\n"));
}

TEST(InstructionCountTest, DumpsPairWithRowsByNameAndTheProgramEndDumpIsSkipped) {
    CallgrindDump none, shadow, end;
    none.part = 1, none.dumpName = "none", none.totalIr = 400;
    shadow.part = 2, shadow.dumpName = "shadowmap", shadow.totalIr = 1000;
    end.part = 3, end.trigger = "Program termination";
    const nlohmann::json rows = nlohmann::json::parse(R"([
        {"technique": "none", "frames": 4, "properties": null},
        {"technique": "volume", "status": "unsupported", "frames": 0},
        {"technique": "shadowmap", "frames": 5, "properties": "pcf=3"}])");
    const auto t = InstructionCount::match({none, shadow, end}, rows, "bench");
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].technique, "none");
    EXPECT_DOUBLE_EQ(t[0].irPerFrame, 100.0);
    EXPECT_EQ(t[1].properties, "pcf=3");
    EXPECT_DOUBLE_EQ(t[1].irPerFrame, 200.0);
    // Rows but no dumps: a bench built without the client requests.
    EXPECT_THROW(InstructionCount::match({end}, rows, "bench"), Error);
    // A dump no row names.
    CallgrindDump stray = shadow;
    stray.dumpName = "planar";
    EXPECT_THROW(InstructionCount::match({stray}, rows, "bench"), Error);
}

TEST(InstructionCountTest, CommandLineCountsOnlyBetweenTheClientRequests) {
    InstructionCount::Options o;
    o.bench = "/b/bench";
    o.benchArgs = {"-t", "none"};
    o.outDir = "/tmp/x";
    const std::vector<std::string> argv = InstructionCount(o).commandLine();
    const std::vector<std::string> want = {"valgrind",
                                           "--tool=callgrind",
                                           "--instr-atstart=no",
                                           "--callgrind-out-file=/tmp/x/callgrind.out",
                                           "/b/bench",
                                           "-t",
                                           "none",
                                           "-q",
                                           "--format",
                                           "json"};
    EXPECT_EQ(argv, want);
    EXPECT_EQ(InstructionCount::pinnedEnvironment().at("LP_NUM_THREADS"), "0");
    o.benchArgs = {"--format", "csv"};
    EXPECT_THROW(InstructionCount(o).run(), Error);
}

TEST(InstructionDiffTest, PerFrameChangesLargestFirstWithJitCodeAsOneEntry) {
    TechniqueInstructions base, now;
    base.technique = now.technique = "shadowmap";
    base.frames = 4;
    now.frames = 8; // twice the frames: the diff is per frame
    base.functions = {{"???", "0x1000", 400},
                      {"???", "0x2000", 400},
                      {"/a/swrast_dri.so", "draw", 800},
                      {"/a/build/bench", "renderFrame", 40}};
    now.functions = {{"???", "0x9000", 2000},
                     {"/a/swrast_dri.so", "draw", 1600},
                     {"/b/build/bench", "renderFrame", 80},
                     {"/lib/libc.so.6", "memcpy", 16}};
    base.totalIr = 1640, now.totalIr = 3696;
    base.irPerFrame = 410, now.irPerFrame = 462;
    const InstructionDiff d = InstructionDiff::compare(base, now, 3);
    EXPECT_NEAR(d.relativeChange(), 52.0 / 410.0, 1e-12);
    ASSERT_EQ(d.functions.size(), 3u);
    // JIT: 800/4 = 200 per frame before, 2000/8 = 250 after, whatever the addresses.
    EXPECT_EQ(d.functions[0].function, "[shader JIT]");
    EXPECT_DOUBLE_EQ(d.functions[0].deltaIrPerFrame(), 50.0);
    EXPECT_EQ(d.functions[1].function, "memcpy"); // only in the new run: 2 per frame
    EXPECT_DOUBLE_EQ(d.functions[1].baseIrPerFrame, 0.0);
    EXPECT_DOUBLE_EQ(d.functions[1].deltaIrPerFrame(), 2.0);
    // draw and renderFrame are unchanged per frame (renderFrame matched across build trees).
    EXPECT_DOUBLE_EQ(d.functions[2].deltaIrPerFrame(), 0.0);
    now.frames = 0;
    EXPECT_THROW(InstructionDiff::compare(base, now), Error);
}

TEST(FingerprintTest, ParsesTheRendererAndNamesEveryDifferingField) {
    const nlohmann::json row = {{"renderer", "llvmpipe (LLVM 15.0.6, 256 bits)"},
                                {"gl_version", "4.5 (Compatibility Profile) Mesa 22.3.6"},
                                {"backend", "egl-surfaceless"}};
    const Fingerprint a = Fingerprint::capture(row, "valgrind-3.19.0", InstructionCount::pinnedEnvironment());
    EXPECT_EQ(a.llvmVersion, "15.0.6");
    EXPECT_EQ(a.mesaVersion, "22.3.6");
    EXPECT_EQ(a.vectorBits, "256");
    EXPECT_FALSE(a.glibc.empty());
    EXPECT_EQ(Fingerprint::relevantFlags("fpu sse4_2 avx2 sse4_1 avx hle avx512f"),
              "sse4_1 sse4_2 avx avx2 avx512f");
    const Fingerprint back = Fingerprint::fromJson(a.toJson(), "inline");
    EXPECT_TRUE(back.differences(a).empty());

    Fingerprint b = a;
    b.vectorBits = "128";
    b.environment["LP_NUM_THREADS"] = "2";
    b.environment.erase("MESA_SHADER_CACHE_DISABLE");
    const std::vector<std::string> want = {"vector_bits", "environment.LP_NUM_THREADS",
                                           "environment.MESA_SHADER_CACHE_DISABLE"};
    EXPECT_EQ(a.differences(b), want);
    EXPECT_THROW(Fingerprint::requireComparable(a, b, FingerprintUse::Instructions), Error);
    EXPECT_THROW(Fingerprint::requireComparable(a, b, FingerprintUse::WallTime), Error);
    EXPECT_NO_THROW(Fingerprint::requireComparable(a, b, FingerprintUse::ExactCounters));
    EXPECT_NO_THROW(Fingerprint::requireComparable(a, back, FingerprintUse::Instructions));
    EXPECT_THROW(Fingerprint::fromJson({{"renderer", 3}}, "inline"), Error);
}

namespace {

std::string readFixture(const std::string& name) {
    std::ifstream in(std::string(SB_SOURCE_DIR) + "/tests/data/callgrind/" + name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A wait status as waitpid reports a child killed by `signal` / exiting with `code` (POSIX's encoding,
/// decoded by WIFSIGNALED/WTERMSIG and WIFEXITED/WEXITSTATUS).
int killedBy(int signal) {
    return signal & 0x7f;
}
int exitedWith(int code) {
    return (code & 0xff) << 8;
}

} // namespace

// The log of a real failure: the reason names the signal, the instruction, the function and library, and
// that it happened while a library was loaded; it is the machine lacking what layer B needs.
TEST(ValgrindDiagnosisTest, AnInstructionValgrindCannotRunIsUnsupportedAndNamed) {
    const std::string log = readFixture("sigill-libhwy.stderr.txt");
    ASSERT_FALSE(log.empty());
    ASSERT_TRUE(WIFSIGNALED(killedBy(SIGILL)));
    ASSERT_EQ(WTERMSIG(killedBy(SIGILL)), SIGILL);
    const ValgrindDiagnosis d = ValgrindDiagnosis::of(killedBy(SIGILL), log);
    EXPECT_TRUE(d.unsupported);
    EXPECT_EQ(d.reason,
              "killed by SIGILL: valgrind cannot execute the instruction at 0x2251d522 (bytes 0F 01 F9, "
              "RDTSCP) in hwy::platform::TimerResolution() (libhwy.so.1.0.3), while a shared library was "
              "being loaded (before main)");
    EXPECT_EQ(d.reason.find('\n'), std::string::npos);
}

TEST(ValgrindDiagnosisTest, InstructionNamesFromTheirBytes) {
    EXPECT_EQ(ValgrindDiagnosis::instructionName("0xF 0x1 0xF9 0x48 0xC1"), "RDTSCP");
    EXPECT_EQ(ValgrindDiagnosis::instructionName("0x62 0xF1 0x7D 0x48 0xEF 0xC0"),
              "an AVX-512 (EVEX-encoded) instruction");
    EXPECT_EQ(ValgrindDiagnosis::instructionName("0xF3 0xF 0xC7 0xF8"), "RDPID");
    EXPECT_EQ(ValgrindDiagnosis::instructionName("0x48 0xF 0xC7 0xF0"), "RDRAND");
    EXPECT_EQ(ValgrindDiagnosis::instructionName("0xF 0xB"), ""); // ud2: not one of the table's
    EXPECT_EQ(ValgrindDiagnosis::instructionName(""), "");
}

// Other ways a child ends: the program's own failure is reported with its own last line, not valgrind's
// summary ("I refs: 0"), and only its exit 3 is "unsupported".
TEST(ValgrindDiagnosisTest, TheProgramsOwnFailureKeepsItsOwnLine) {
    const std::string log = "==12== Callgrind, a call-graph generating cache profiler\n"
                            "bench: --size 0x0: width and height must be positive\n"
                            "==12== \n==12== I   refs:      0\n";
    const ValgrindDiagnosis bad = ValgrindDiagnosis::of(exitedWith(2), log);
    EXPECT_FALSE(bad.unsupported);
    EXPECT_EQ(bad.reason, "exit 2: bench: --size 0x0: width and height must be positive");
    EXPECT_TRUE(ValgrindDiagnosis::of(exitedWith(3), log).unsupported);
    const ValgrindDiagnosis segv = ValgrindDiagnosis::of(
        killedBy(SIGSEGV), "==9== Process terminating with default action of signal 11 (SIGSEGV)\n"
                           "==9==    at 0x4011: sb::Harness::measure() (in /tmp/bench)\n");
    EXPECT_FALSE(segv.unsupported);
    EXPECT_EQ(segv.reason, "killed by SIGSEGV in sb::Harness::measure() (bench)");
}
