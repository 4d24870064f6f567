#include "bench/lib/output/ShardGaps.h"

#include <algorithm>
#include <iterator>
#include <map>

namespace sb {

namespace {

/// (config_index, config_group) of the rows whose group is known, by index.
using GroupAt = std::map<size_t, size_t>;

GroupAt knownGroups(const std::vector<RowPlace>& rows) {
    GroupAt out;
    for (const RowPlace& r : rows)
        if (r.group) out.emplace(r.index, *r.group);
    return out;
}

// Groups are numbered in index order, so a later index never has an earlier group. When the rows say
// otherwise a config_group cell is damaged, and nothing is worked out from any of them.
bool groupsRise(const GroupAt& groups) {
    size_t last = 0;
    for (const auto& [index, group] : groups) {
        if (group < last) return false;
        last = group;
    }
    return true;
}

void addRange(IndexRanges& ranges, size_t& count, size_t first, size_t last) {
    if (!ranges.empty() && ranges.back().second + 1 == first)
        ranges.back().second = last;
    else
        ranges.emplace_back(first, last);
    count += last - first + 1;
}

/// The group of the gap [first, last] when rows of one group lie right below and right above it.
std::optional<size_t> bracketingGroup(const GroupAt& groups, size_t first, size_t last) {
    const auto above = groups.upper_bound(last);
    const auto below = groups.lower_bound(first);
    if (above == groups.end() || below == groups.begin()) return std::nullopt;
    const size_t group = std::prev(below)->second;
    return group == above->second ? std::optional<size_t>(group) : std::nullopt;
}

/// Collects the ranges per shard, in the order they are added (ascending within each shard).
class ShardTable {
public:
    void missing(size_t shard, size_t first, size_t last) {
        ShardGap& g = at(shard);
        addRange(g.missing, g.missingCount, first, last);
    }
    void failed(size_t shard, size_t index) {
        ShardGap& g = at(shard);
        addRange(g.failed, g.failedCount, index, index);
    }
    std::vector<ShardGap> take() {
        std::vector<ShardGap> out;
        for (auto& entry : mShards) out.push_back(std::move(entry.second));
        return out;
    }

private:
    ShardGap& at(size_t shard) {
        ShardGap& g = mShards[shard];
        g.shard = shard;
        return g;
    }
    std::map<size_t, ShardGap> mShards; ///< shard 0 (not known) sorts first
};

} // namespace

std::string ShardGaps::rangesText(const IndexRanges& ranges) {
    std::string out;
    for (size_t i = 0; i < ranges.size() && i < kMaxListedRanges; ++i) {
        const auto& [first, last] = ranges[i];
        out += (i ? ", " : "") + std::to_string(first) + (first == last ? "" : "-" + std::to_string(last));
    }
    if (ranges.size() > kMaxListedRanges) out += ", ...";
    return out;
}

std::optional<size_t> ShardGaps::uniformGroupSize(const std::vector<RowPlace>& rows, size_t configs) {
    const GroupAt groups = knownGroups(rows);
    if (groups.empty() || configs == 0 || !groupsRise(groups)) return std::nullopt;
    // Row (i, g) lies in group g of size G when g*G <= i < (g+1)*G: G > i/(g+1) and G <= i/g.
    size_t low = 1, high = configs, lastGroup = 0;
    for (const auto& [index, group] : groups) {
        low = std::max(low, index / (group + 1) + 1);
        if (group > 0) high = std::min(high, index / group);
        lastGroup = std::max(lastGroup, group);
    }
    // Every group holds G rows, so G divides sweep_configs, and there are more groups than the last seen.
    std::optional<size_t> found;
    auto consider = [&](size_t size) {
        if (size < low || size > high || configs / size <= lastGroup) return true;
        if (found && *found != size) return false; // two sizes fit: the rows do not tell
        found = size;
        return true;
    };
    for (size_t d = 1; d <= configs / d; ++d) {
        if (configs % d != 0) continue;
        if (!consider(d) || !consider(configs / d)) return std::nullopt;
    }
    return found;
}

std::vector<ShardGap> ShardGaps::compute(const std::vector<RowPlace>& rows, const IndexRanges& missing,
                                         size_t configs, size_t shardCount) {
    ShardTable table;
    std::vector<size_t> failedOrder;
    for (size_t r = 0; r < rows.size(); ++r)
        if (rows[r].failed) failedOrder.push_back(r);
    std::sort(failedOrder.begin(), failedOrder.end(),
              [&](size_t a, size_t b) { return rows[a].index < rows[b].index; });
    for (size_t r : failedOrder) table.failed(rows[r].shard, rows[r].index);
    if (missing.empty() || shardCount == 0) return table.take();

    const GroupAt groups = knownGroups(rows);
    auto shardOf = [&](size_t group) { return group % shardCount + 1; };
    // Each row's own shard cell must be where its group is dealt; if not, the groups are not the plan's.
    const bool trusted = groupsRise(groups) && std::all_of(rows.begin(), rows.end(), [&](const RowPlace& r) {
                             return !r.group || shardOf(*r.group) == r.shard;
                         });
    // 0: no one group size fits the rows.
    const size_t size = trusted ? uniformGroupSize(rows, configs).value_or(0) : 0;
    size_t pieces = 0;
    for (const auto& [first, last] : missing) {
        if (size > 0) {
            // One piece per group the gap crosses, each under its group's shard.
            for (size_t start = first; start <= last;) {
                if (pieces == kMaxPieces) {
                    table.missing(0, start, last);
                    break;
                }
                const size_t group = start / size;
                const size_t end = std::min(last, (group + 1) * size - 1);
                table.missing(shardOf(group), start, end);
                ++pieces;
                start = end + 1;
            }
            continue;
        }
        const std::optional<size_t> group = trusted ? bracketingGroup(groups, first, last) : std::nullopt;
        table.missing(group ? shardOf(*group) : 0, first, last);
    }
    return table.take();
}

} // namespace sb
