#pragma once
// `bench merge`: joins the result CSVs of the shards of one sweep (`--shard i/N`, one process or
// machine each) into the CSV the unsharded sweep would have written, and refuses inputs that do not
// fit together: rows of another sweep, another split, a configuration measured twice.
//
// Every sweep row carries four columns: sweep_id (hash of the sweep definition), sweep_configs (number
// of configurations = rows of the complete sweep), config_index (0-based index of the row's
// configuration in the complete sweep) and shard ("i/N"). Measured rows also carry timer_verdict: the
// shards of one sweep calibrate the GPU timer each on their own (one process or machine each), and rows
// measured under different verdicts (trusted with GPU columns next to untrusted without, or a device that
// calibrates differently) are not the one sweep the merge claims to produce, so a mixture is refused
// unless asked for, and then reported.
//
// Rows must also be one measurement: the same commit, CPU model, renderer and driver
// (bench/lib/output/MeasurementIdentity.h says which columns and why); a mixture is refused unless asked
// for, and then reported. Hosts may differ (a cluster's nodes of one kind), and are counted.
//
// What is missing or failed is reported per shard (bench/lib/output/ShardGaps.h), so that the one
// command per shard that completes the sweep can be printed; an incomplete merge writes nothing unless
// asked to.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/output/MeasurementIdentity.h"
#include "bench/lib/output/ShardGaps.h"

namespace sb {

struct MergeOptions {
    bool allowIncomplete = false; ///< write even when configurations are missing or failed
    bool force = false;           ///< replace an existing output file
    bool allowMixedTimer = false; ///< write even when rows carry different timer verdicts
    /// write even when rows are of different measurements (commit, CPU model, renderer, driver) or carry
    /// different timer verdicts: --allow-mixed covers what --allow-mixed-timer does and more
    bool allowMixed = false;
};

struct MergeReport {
    size_t files = 0;     ///< inputs read
    size_t rows = 0;      ///< rows read, all written when `written`
    bool written = false; ///< false only for an incomplete merge without allowIncomplete: nothing written
    std::string sweepId;
    std::string sweepName;   ///< sweep_name of the first row that has one (the definition's name)
    size_t configs = 0;      ///< sweep_configs
    size_t shardCount = 0;   ///< N of the rows' "i/N"
    size_t missingCount = 0; ///< configurations present in no input
    /// Those configurations as ranges [first, last] of indices, sorted; at most one more range than rows
    /// read, however large sweep_configs is.
    IndexRanges missing;
    /// Rows whose status is "failed", empty, anything but "ok" and "unsupported", or absent (no
    /// `status` column: no row is known to be ok). Unsupported rows are a final answer ("the context
    /// lacks it"), as the sweep's exit code has it: counted apart and never retried.
    size_t failedRows = 0;
    IndexRanges failed; ///< their config_index, as ranges
    size_t unsupportedRows = 0;
    /// Per shard, what it lacks (missing and failed configurations) and the part file to rerun it into;
    /// empty when the merge is complete.
    std::vector<ShardGap> gaps;
    /// "4 of 48 configurations missing (indices 5, 17-19), 2 failed (indices 7, 30)": at most 10 ranges
    /// each, then "..."; empty when nothing is missing or failed.
    std::string incomplete;
    /// Rows per timer_verdict value, in first-seen order (rows without a verdict, such as failed ones,
    /// are not counted). More than one entry only with allowMixedTimer or allowMixed.
    std::vector<std::pair<std::string, size_t>> timerVerdicts;
    /// The columns whose rows carry different values; non-empty only with allowMixed.
    std::vector<Mixture> mixtures;
    /// Distinct `host` values; nullopt when no input has the column.
    std::optional<size_t> hosts;
};

class CsvMerge {
public:
    /// Reads every input (CsvWriter::read), checks they belong to one sweep and fit together, and,
    /// unless configurations are missing or failed and !options.allowIncomplete, writes their union to
    /// `output` with CsvWriter::writeTable (atomic: temp file in the same directory, fsync, rename; a
    /// failure leaves no output and no temp file). Rows are sorted by config_index; the header is the
    /// union of the inputs' headers in first-seen order (inputs in the order given); cells of columns a
    /// file lacks are empty. An incomplete merge without allowIncomplete returns its report with
    /// `written` false and writes nothing (`bench merge` exits 1).
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
    /// - rows carry different non-empty timer_verdict values and neither allowMixedTimer nor allowMixed
    ///   ("rows measured under different GPU-timer verdicts: 'trusted' in '<file>:<line>' but
    ///   'untrusted' in ...");
    /// - rows of different measurements and !options.allowMixed (MeasurementIdentity::refusal: every
    ///   column that differs, each value with the first file and line holding it).
    /// I/O failures (unreadable input, unwritable output) throw sb::Error(ExitCode::Failure) naming the
    /// path and the OS error.
    static MergeReport merge(const std::vector<std::string>& inputs, const std::string& output,
                             const MergeOptions& options);
};

} // namespace sb
