#pragma once
// `bench merge`: joins the result CSVs of the shards of one sweep (`--shard i/N`, one process or
// machine each) into the CSV the unsharded sweep would have written, and refuses inputs that do not
// fit together: rows of another sweep, another split, a configuration measured twice or never.
//
// Every sweep row carries four columns: sweep_id (hash of the sweep definition), sweep_configs (number
// of configurations = rows of the complete sweep), config_index (0-based index of the row's
// configuration in the complete sweep) and shard ("i/N"). Measured rows also carry timer_verdict: the
// shards of one sweep calibrate the GPU timer each on their own (one process or machine each), and rows
// measured under different verdicts (trusted with GPU columns next to untrusted without, or a device that
// calibrates differently) are not the one sweep the merge claims to produce, so a mixture is refused
// unless asked for, and then reported.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sb {

struct MergeOptions {
    bool allowIncomplete = false; ///< write even when configurations are missing
    bool force = false;           ///< replace an existing output file
    bool allowMixedTimer = false; ///< write even when rows carry different timer verdicts
};

struct MergeReport {
    size_t files = 0; ///< inputs read
    size_t rows = 0;  ///< rows written
    std::string sweepId;
    size_t configs = 0;      ///< sweep_configs
    size_t missingCount = 0; ///< configurations present in no input
    /// Those configurations as ranges [first, last] of indices, sorted; at most one more range than rows
    /// read, however large sweep_configs is.
    std::vector<std::pair<size_t, size_t>> missing;
    size_t failedRows = 0; ///< rows whose status is not "ok" (empty or absent counts as not ok)
    /// Rows per timer_verdict value, in first-seen order (rows without a verdict, such as failed ones,
    /// are not counted). More than one entry only with allowMixedTimer.
    std::vector<std::pair<std::string, size_t>> timerVerdicts;
};

class CsvMerge {
public:
    /// Reads every input (CsvWriter::read), checks they belong to one sweep and fit together, and
    /// writes their union to `output` with CsvWriter::writeTable (atomic: temp file in the same
    /// directory, fsync, rename; a failure leaves no output and no temp file). Rows are sorted by
    /// config_index; the header is the union of the inputs' headers in first-seen order (inputs in
    /// the order given); cells of columns a file lacks are empty.
    ///
    /// Throws sb::Error(ExitCode::BadInput) with a one-line message naming the file, and for a row
    /// "<file>:<line>" (the line the row starts on in a file CsvWriter wrote), when:
    /// - there are no inputs, an input is given twice, or an input is the output (compared after
    ///   std::filesystem::weakly_canonical);
    /// - the output exists and !options.force;
    /// - an input lacks a sweep column ("'<file>' is not a sweep CSV: column 'sweep_id' missing");
    /// - a sweep cell is empty or malformed: sweep_configs not an integer in [1, 10^12], config_index not an
    ///   integer in [0, sweep_configs), shard not "i/N" with 1 <= i <= N (integers are plain digits);
    /// - two sweep_id or two sweep_configs values appear, or shards of different N (names both places);
    /// - one config_index appears twice (names both places);
    /// - the inputs hold no rows at all;
    /// - configurations are missing and !options.allowIncomplete ("incomplete: 4 of 48 configurations
    ///   missing (indices 5, 17-19); rerun the shards that wrote them, or pass --allow-incomplete";
    ///   at most 10 ranges, then "...");
    /// - rows carry different non-empty timer_verdict values and !options.allowMixedTimer ("rows measured
    ///   under different GPU-timer verdicts: 'trusted' in '<file>:<line>' but 'untrusted' in ...").
    /// I/O failures (unreadable input, unwritable output) throw sb::Error(ExitCode::Failure) naming the
    /// path and the OS error.
    static MergeReport merge(const std::vector<std::string>& inputs, const std::string& output,
                             const MergeOptions& options);
};

} // namespace sb
