#pragma once
// Layer B of the performance gate: a bench command line run once under callgrind, read back as the
// instructions each technique's measured frames retired (TechniqueInstructions).
//
// bench/lib/harness/Harness.cpp brackets the measured frames with callgrind client requests (instrumentation
// on for them only, one dump per technique named after it), and the child runs with
// `--instr-atstart=no`: set-up, shader compilation, warm-up and the census frame run uninstrumented
// (fast) and uncounted. The child's environment is pinned (pinnedEnvironment()) because llvmpipe's
// thread count and shader cache decide what code runs; everything else in the caller's environment is
// dropped except LD_LIBRARY_PATH (a Mesa of one's own), TMPDIR, DISPLAY (--backend glfw) and
// SHADOWBENCH_INJECT (the gate's proof, core/Injection.h; recorded in the rows), so that no
// LP_*, GALLIUM_* or MESA_* variable of the caller's changes the code that runs.
//
//     InstructionCount::Options o;
//     o.bench = "build/bench";
//     o.benchArgs = {"-t", "shadowmap", "--frames", "4", "--warmup", "1", "--size", "256x256",
//                    "--instances", "10", "--no-timer-check"};
//     o.outDir = "out/ir";
//     InstructionRun run = InstructionCount(o).run();
//     run.techniques[0].irPerFrame; // ~8.1e7 on llvmpipe 15, 256 bits
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/lib/callgrind/TechniqueInstructions.h"

namespace sb {

/// What one run under callgrind gave.
struct InstructionRun {
    std::vector<TechniqueInstructions> techniques;  ///< one per measured technique row, in run order
    nlohmann::json rows;                            ///< the bench's own rows (`--format json` "rows")
    std::vector<std::string> command;               ///< the child's argv (valgrind first)
    std::map<std::string, std::string> environment; ///< the child's whole environment
    std::map<std::string, std::string> pinned;      ///< Options::environment, what the fingerprint records
    double wallSeconds = 0;                         ///< the child's wall time, valgrind start-up included

    /// {"command": [...], "environment": {pinned}, "wall_s", "techniques": [TechniqueInstructions::toJson]}
    nlohmann::json toJson(size_t topN = 20) const;
};

class InstructionCount {
public:
    struct Options {
        std::string valgrind = "valgrind";  ///< found on PATH unless a path
        std::string bench;                  ///< the bench binary
        std::vector<std::string> benchArgs; ///< bench options; `-q --format json` are appended (no --format)
        std::string outDir;                 ///< created; callgrind.out.N, stdout.json, stderr.txt go here
        std::map<std::string, std::string> environment = pinnedEnvironment(); ///< set in the child
        double timeoutSeconds = 900; ///< the child is killed after this (a hung driver)
    };

    /// LP_NUM_THREADS=0: llvmpipe rasterises in the calling thread, so no thread interleaving decides
    /// the heap's history (measured, shadowmap at 256x256: four runs bit-identical with 0 threads; with
    /// 1 thread runs spread by up to 7.6e-4, libc's calloc clearing reused chunks but not fresh ones;
    /// 1 and 2 threads differ by 2e-4); MESA_SHADER_CACHE_DISABLE=true (a cold and a warm on-disk
    /// cache changed the count by 1.3e-4),
    /// PATH fixed (the bench runs git for its row, outside the measured frames), GALLIUM_DRIVER=llvmpipe
    /// and LIBGL_ALWAYS_SOFTWARE=1 (never a hardware driver), LD_BIND_NOW=1 (the
    /// dynamic linker resolves every symbol at start-up, not on a function's first call inside the
    /// measured frames, which would be counted once per run and make Ir per frame depend on the count).
    static std::map<std::string, std::string> pinnedEnvironment();
    /// True when `valgrind --version` runs and names callgrind's host (valgrind-3.x).
    static bool valgrindAvailable(const std::string& valgrind = "valgrind");
    /// `valgrind --version`'s line ("valgrind-3.19.0"), "" when it does not run.
    static std::string valgrindVersion(const std::string& valgrind = "valgrind");

    explicit InstructionCount(Options options);

    /// The child's argv: valgrind, its callgrind options, the bench and its arguments.
    std::vector<std::string> commandLine() const;
    /// Runs the child and reads its dumps. Throws Error: BadInput for --format in benchArgs,
    /// Unsupported when valgrind does not run or cannot run the bench on this CPU (an instruction its
    /// VEX does not know: the one-line reason names it, the function and library, and the log file;
    /// bench/lib/callgrind/ValgrindDiagnosis), Failure when the bench fails, times out, or its dumps do not
    /// match its rows (a technique measured without a dump: a bench built without SB_HAVE_VALGRIND).
    InstructionRun run() const;

    /// Pairs dumps (by part) with rows (in order, by technique name); the program-end dump is skipped.
    static std::vector<TechniqueInstructions> match(const std::vector<CallgrindDump>& dumps,
                                                    const nlohmann::json& rows, const std::string& harness);

private:
    Options mOptions;
};

} // namespace sb
