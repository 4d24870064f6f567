#pragma once
// `bench bottleneck`: runs the perturbation set of BottleneckStudy.h for every technique and
// base setting, classifies each as CPU-, vertex- or fill-limited, prints the table with its evidence
// and writes it as CSV next to the measurement rows. `--from FILE.csv` classifies rows measured before.
namespace sb {

class BottleneckCommand {
public:
    /// argv[0] is "bottleneck". Returns the exit code (as bench sweep's).
    static int main(int argc, char** argv);
};

} // namespace sb
