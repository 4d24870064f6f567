#pragma once
// `bench bisect GOOD BAD -c CONFIG [--signal work|instructions|image]`: the first commit of the
// project's own first-parent history after GOOD up to BAD where one configuration's exact work,
// instructions per frame or image changed (bench/lib/bisect/Bisection.h). CONFIG names a configuration
// of the perf gate's suite (results/ci/suite.json), or run options follow `--`. Exit 0 when found,
// 1 when GOOD and BAD do not differ (or skipped commits hide the answer), 2 for bad input (an unknown
// commit, GOOD not an ancestor of BAD, an unknown configuration), 3 when git, cmake, ninja or (for
// instructions) valgrind is missing.
namespace sb {

class BisectCommand {
public:
    /// argv[0] is "bisect". Returns the exit code.
    static int main(int argc, char** argv);
};

} // namespace sb
