#pragma once
// `bench compare BASE.csv NEW.csv`: the perf gate on two result files a user brings (rows of bench,
// sweeps, bench ci's work.csv). Layer A (exact work, WorkGate.h) is judged on every configuration in
// both; where a file carries repeated rounds of a configuration (--repeat, a sweep's repeat), layer C's
// statistics are reported: the median ratio and Mann-Whitney U over the rounds (unpaired: the files were
// not measured interleaved), with the minimum detectable effect. What needs interleaving or valgrind
// (layer B, C's A/A control) says that it needs `bench ci`. Exit 1 only when layer A fails or layer C
// fails beyond max(5%, noise) at p < alpha.
namespace sb {

class CompareCommand {
public:
    /// argv[0] is "compare". Returns the exit code.
    static int main(int argc, char** argv);
};

} // namespace sb
