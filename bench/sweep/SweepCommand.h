#pragma once
// `bench sweep [FILE.json] [axes] --csv OUT`: a cartesian product of techniques, scenes,
// instances, scale, tessellation, submission, camera, resolution and light type, each combination in
// its own worker process, rows appended as they finish. Axes come from a definition file
// (SweepDefinition.h documents the format) and/or the command line as comma lists; options named on
// the command line replace the file's. See SweepRunner.h for --resume, --shard and failure handling.
namespace sb {

class SweepCommand {
public:
    /// argv[0] is "sweep". Returns the exit code: 0 all rows ok, 1 some configurations failed (their
    /// rows say why) or another process runs this shard of --csv, 2 bad input, 130 interrupted
    /// (continue with --resume).
    static int main(int argc, char** argv);
};

} // namespace sb
