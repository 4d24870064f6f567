#pragma once
// `bench ci`: the perf gate (README "Gate a change"). Runs the committed suite (results/ci/suite.json)
// with its three layers and judges the head build against a base:
//   A  exact work per pass (WorkGate.h): against the committed baseline, or a base measured now;
//   B  instructions per frame under valgrind (InstructionLayer.h): against the committed baseline when
//      the fingerprint matches, or a base measured now; an A/A pair of the head in every job;
//   C  wall time (WallLayer.h): base and head interleaved per round with an A/A control; without a
//      base only the control runs, to say what the job could see.
// The base is the committed baseline unless --base-bench or --base-env names another build or driver
// environment (a driver A/B: `--base-env LP_NUM_THREADS=2 --head-env LP_NUM_THREADS=1`). Writes
// report.md, report.json and the rows of every run to --out; exit 1 only when a gating layer fails,
// 2 for bad input, 3 when the machine lacks what a layer needs (valgrind for B).
// `--update` rewrites the baseline from the head instead of judging it.
namespace sb {

class CiCommand {
public:
    /// argv[0] is "ci". Returns the exit code.
    static int main(int argc, char** argv);
};

} // namespace sb
