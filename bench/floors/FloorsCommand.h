#pragma once
// `bench floors [options]`: each pass of each technique against its floor, the least a pass of its kind
// must do for an output of the same formats and size with the same number of fragments
// (bench/floors/FloorPass.h). For each technique of a run's options (GL): the census frame
// (bench/lib/harness/WorkCensus.h) gives each pass's fragments (fragment-shader invocations, as `bench
// explain` prints them), an inspecting frame each pass's target and kind (bench/floors/PassTarget.h);
// then the measured frames alternate the technique's frame, cut at its pass boundaries
// (bench/floors/PassProbe.h), with the floors of its passes, in alternating order. One row per pass:
// the fragments, the pass's and the floor's wall time (medians) and the median of their per-frame
// ratios; run under callgrind, also the instructions of each (exact: one dump per pass and per floor,
// read back at the end) and their ratio.
namespace sb {

class FloorsCommand {
public:
    /// argv from "floors" on. Returns 0, or the worst refusal's code (1 over 2 over 3) when a technique
    /// could not be prepared; bad options throw sb::Error (exit 2); --api vulkan exits 3.
    static int main(int argc, char** argv);
};

} // namespace sb
