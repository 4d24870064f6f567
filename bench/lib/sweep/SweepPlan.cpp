#include "bench/lib/sweep/SweepPlan.h"

#include <algorithm>

#include "core/Error.h"
#include "core/Fnv1a.h"
#include "core/Strings.h"

namespace sb {

std::string SweepGroup::describe(const std::vector<std::string>* only) const {
    std::string out;
    for (const auto& [k, v] : columns) {
        if (only && std::find(only->begin(), only->end(), k) == only->end()) continue;
        out += (out.empty() ? "" : " ") + k + "=" + v;
    }
    for (const auto& [k, v] : tags)
        if (k == "perturbation") out += (out.empty() ? "" : " ") + v;
    return out;
}

std::vector<std::string> SweepPlan::varyingColumns() const {
    std::vector<std::string> out;
    if (groups.empty()) return out;
    for (size_t i = 0; i < groups.front().columns.size(); ++i) {
        const auto& [column, first] = groups.front().columns[i];
        for (const SweepGroup& g : groups)
            if (i < g.columns.size() && g.columns[i].second != first) {
                out.push_back(column);
                break;
            }
    }
    return out;
}

const char* SweepPlan::modeName(Mode m) {
    return m == Mode::Accuracy ? "accuracy" : "measure";
}

SweepGroup& SweepPlan::addGroup(std::vector<std::string> args, KeyValues columns,
                                std::vector<std::string> techniques, int rounds, KeyValues env,
                                KeyValues tags) {
    SweepGroup g;
    g.index = groups.size();
    g.args = std::move(args);
    g.columns = std::move(columns);
    g.env = std::move(env);
    g.tags = std::move(tags);
    g.techniques = std::move(techniques);
    // Index order = execution order: round by round, techniques in declared order.
    for (int round = 1; round <= rounds; ++round)
        for (const std::string& t : g.techniques) g.rows.push_back({mConfigCount++, t, round});
    groups.push_back(std::move(g));
    return groups.back();
}

void SweepPlan::append(const SweepPlan& other) {
    for (const SweepGroup& g : other.groups) {
        std::vector<std::string> args = other.commonArgs;
        args.insert(args.end(), g.args.begin(), g.args.end());
        const int rounds = g.rows.empty() ? 1 : g.rows.back().round;
        addGroup(std::move(args), g.columns, g.techniques, rounds, g.env, g.tags);
    }
}

std::string SweepPlan::id() const {
    Fnv1a h;
    h.string(modeName(mode));
    auto strings = [&](const std::vector<std::string>& v) {
        h.value(uint64_t(v.size()));
        for (const std::string& s : v) h.string(s);
    };
    auto pairs = [&](const KeyValues& kv) {
        h.value(uint64_t(kv.size()));
        for (const auto& [k, v] : kv) {
            h.string(k);
            h.string(v);
        }
    };
    strings(commonArgs);
    h.value(uint64_t(groups.size()));
    for (const SweepGroup& g : groups) {
        strings(g.args);
        pairs(g.env);
        pairs(g.tags);
        h.value(uint64_t(g.rows.size()));
        for (const PlannedRow& r : g.rows) {
            h.value(uint64_t(r.index));
            h.string(r.technique);
            h.value(r.round);
        }
    }
    return h.hex();
}

std::vector<const SweepGroup*> SweepPlan::shard(int shardIndex, int count) const {
    std::vector<const SweepGroup*> out;
    for (const SweepGroup& g : groups)
        if (int(g.index % size_t(count)) + 1 == shardIndex) out.push_back(&g);
    return out;
}

std::pair<int, int> parseShard(const std::string& text, const std::string& option) {
    auto bad = [&] {
        return Error(option + " " + text + ": expected i/N with 1 <= i <= N <= 10000, e.g. 2/4");
    };
    const size_t slash = text.find('/');
    if (slash == std::string::npos) throw bad();
    try {
        size_t a = 0, b = 0;
        const int i = std::stoi(text.substr(0, slash), &a);
        const int n = std::stoi(text.substr(slash + 1), &b);
        if (a != slash || b != text.size() - slash - 1 || i < 1 || n < i || n > 10000) throw bad();
        return {i, n};
    } catch (const std::logic_error&) {
        throw bad();
    }
}

} // namespace sb
