#pragma once
// What a sweep runs, fully expanded: an ordered list of groups, each one harness setting (one
// worker process, one GL context, one scene) and the rows measured in it. A row is one configuration:
// one technique spec in one round; its config_index is its position in the complete sweep and is what
// --resume, --shard and `bench merge` key on.
//
// Inside a group the techniques are interleaved round by round (A B C, A B C, ...), the first technique
// first in every round, so that each row's ratio to the first technique (wall_ratio_vs_baseline) is
// taken from runs measured next to each other on the same context: the only ratios worth having on a
// noisy shared machine.
//
// Sweeps (bench sweep), bottleneck studies (bench bottleneck) and figures (bench figures) all build a
// SweepPlan; SweepRunner runs any of them the same way.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sb {

using KeyValues = std::vector<std::pair<std::string, std::string>>;

/// One configuration = one CSV row.
struct PlannedRow {
    size_t index = 0;      ///< config_index: position in the complete sweep
    std::string technique; ///< spec as given to -t ("shadowmap:resolution=1024")
    int round = 1;         ///< 1-based repetition (the `repeat` column)
};

struct SweepGroup {
    size_t index = 0;              ///< config_group
    std::vector<std::string> args; ///< worker command line without -t (e.g. --scene aircraft --scale 10)
    KeyValues env;                 ///< extra environment of the worker (LP_NO_RAST=1)
    /// Identity columns of the group's rows (scene, instances, submit ...), written into the failed row
    /// of a configuration that never produced its own.
    KeyValues columns;
    KeyValues tags;                      ///< extra columns on every row of the group (perturbation ...)
    std::vector<std::string> techniques; ///< declared order; techniques[0] is the round's baseline
    std::vector<PlannedRow> rows;        ///< execution order: round by round
    /// "scene=aircraft instances=200 submit=retained ..." for messages; with `only`, just those columns.
    std::string describe(const std::vector<std::string>* only = nullptr) const;
};

class SweepPlan {
public:
    enum class Mode { Measure, Accuracy };
    static const char* modeName(Mode m); ///< "measure", "accuracy"

    std::string name; ///< for messages ("instances", "bottleneck", a file stem)
    Mode mode = Mode::Measure;
    std::vector<std::string> commonArgs; ///< given to every worker before the group's args
    std::vector<SweepGroup> groups;

    /// Adds a group whose rows are `rounds` rounds over `techniques`; indices are assigned here.
    SweepGroup& addGroup(std::vector<std::string> args, KeyValues columns,
                         std::vector<std::string> techniques, int rounds, KeyValues env = {},
                         KeyValues tags = {});
    size_t configCount() const { return mConfigCount; }
    /// Adds `other`'s groups after this plan's (re-indexed), each with `other`'s common options in
    /// front of its own: one plan from several definitions (a figure of unlike workloads). This plan's
    /// own common options stay; the combined plan is measured and resumed as one sweep.
    void append(const SweepPlan& other);
    /// The identity columns whose value differs between groups (what a progress line needs to say).
    std::vector<std::string> varyingColumns() const;
    /// 16 hex digits over everything that defines the rows (mode, arguments, environment, tags,
    /// techniques, rounds, order), so a changed definition can never resume or merge into another's CSV.
    std::string id() const;
    /// The groups shard `shard` (1-based) of `count` runs: group g goes to shard (g mod count) + 1, so
    /// every shard gets a spread of the sweep rather than one corner of it.
    std::vector<const SweepGroup*> shard(int shard, int count) const;

private:
    size_t mConfigCount = 0;
};

/// "i/N" -> {i, N}; throws sb::Error naming `option` unless 1 <= i <= N <= 10000.
std::pair<int, int> parseShard(const std::string& text, const std::string& option = "--shard");

} // namespace sb
