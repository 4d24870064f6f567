#pragma once
// What a merge of a sweep's shards lacks, shard by shard: the configurations no input holds (missing)
// and the rows whose status says they failed, each as ranges of config_index under the shard that runs
// them, so that `bench merge` can print the one command per shard that completes the sweep.
//
// A failed row names its shard itself (its `shard` cell). A missing configuration has no row, so its
// shard is worked out the way bench/lib/sweep/SweepPlan.cpp deals them: configurations are numbered
// group by group (a group's indices are contiguous, groups in order), and group g runs in shard
// (g mod N) + 1 of N. The group of a missing index is known
// - from the group size, where exactly one size fits every row: a sweep's groups all hold the same
//   techniques and rounds, so a configuration's group is config_index / size. The size is the divisor of
//   sweep_configs that puts every row in its own config_group; or
// - when rows of one group lie on both sides of the gap (that group's indices are contiguous).
// Either way only when the rows bear the rule out: groups rise with indices and each row's own shard
// cell is its group's shard. Otherwise (a plan of unlike groups with a whole group missing,
// config_group cells absent or damaged) the shard stays unknown, and the merge tells the user to rerun
// every shard with --resume.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sb {

/// Ranges [first, last] of config_index, sorted and disjoint.
using IndexRanges = std::vector<std::pair<size_t, size_t>>;

/// One row of the inputs, as far as the gaps need it.
struct RowPlace {
    size_t index = 0;            ///< config_index
    std::optional<size_t> group; ///< config_group; nullopt when the cell is absent or not a number
    size_t shard = 0;            ///< i of the row's "i/N"
    bool failed = false;         ///< status is neither ok nor unsupported
};

/// What one shard lacks.
struct ShardGap {
    size_t shard = 0; ///< 1-based i of N; 0 when the shard of these configurations is not known
    IndexRanges missing;
    size_t missingCount = 0;
    IndexRanges failed;
    size_t failedCount = 0;
    /// The part file to rerun the shard into: the input holding its rows, else a name the other
    /// inputs' names imply ("part{i}.csv"), else empty. Filled in by CsvMerge, which knows the files.
    std::string partFile;
    bool partFileIsInput = false; ///< partFile is one of the inputs (else the shard wrote no row given)
};

class ShardGaps {
public:
    /// The shards that lack something, ascending, with the unknown one (shard 0), if any, first.
    /// `missing` are the ranges no row covers (CsvMerge works them out); `shardCount` is the N every
    /// row's shard cell agrees on. A gap spanning more than kMaxPieces groups is not split further: the
    /// rest of it is put under shard 0, so a damaged sweep_configs of 10^12 costs nothing.
    static std::vector<ShardGap> compute(const std::vector<RowPlace>& rows, const IndexRanges& missing,
                                         size_t configs, size_t shardCount);

    /// The one group size (rows per group) that sweep_configs and every row's (index, group) agree on;
    /// nullopt when none or several do, or when the rows' groups do not rise with their indices.
    static std::optional<size_t> uniformGroupSize(const std::vector<RowPlace>& rows, size_t configs);

    /// "5, 17-19": the first kMaxListedRanges ranges, then ", ..." when there are more.
    static std::string rangesText(const IndexRanges& ranges);

    static constexpr size_t kMaxPieces = 100000;
    static constexpr size_t kMaxListedRanges = 10;
};

} // namespace sb
