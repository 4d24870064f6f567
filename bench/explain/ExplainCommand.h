#pragma once
// `bench explain [options]`: for the scene and each technique of a run's options, what the scene asks for
// and what the technique delivers of it (techniques/EffectCoverage.h), the shader permutation compile()
// chose, and the passes of one frame: those that ran, with their exact work from the census
// (bench/lib/harness/WorkCensus.h), and the declared passes that did not run. Nothing is timed; a technique
// that refuses the configuration is explained with its refusal. Takes every option of `bench` (RunOptions).
namespace sb {

class ExplainCommand {
public:
    /// argv from "explain" on. Returns 0, or the worst refusal's code (1 over 2 over 3) when a technique
    /// could not be prepared; bad options throw sb::Error (exit 2).
    static int main(int argc, char** argv);
};

} // namespace sb
