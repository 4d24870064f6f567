#pragma once
// `bench merge -o OUT.csv IN.csv...`: the shards of one sweep joined into one CSV (CsvMerge.h says
// what is checked). `bench export IN.csv --format json|md|csv` lives in ExportCommand.h.
namespace sb {

class MergeCommand {
public:
    /// argv[0] is "merge". Returns the exit code.
    static int main(int argc, char** argv);
};

} // namespace sb
