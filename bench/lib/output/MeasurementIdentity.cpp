#include "bench/lib/output/MeasurementIdentity.h"

#include <algorithm>

#include "bench/lib/output/ResultColumns.h"

namespace sb {

namespace {

/// An identity column, and whether its values are compared within each api rather than across all rows.
struct IdentityColumn {
    const char* name;
    bool perApi;
};

constexpr IdentityColumn kIdentity[] = {{col::kGitCommit, false},
                                        {col::kCpuModel, false},
                                        {col::kDriver, false},
                                        {col::kRenderer, true},
                                        {col::kDriverVersion, true}};

// A column of fifty commits is listed by its first values; the count says how many more.
constexpr size_t kMaxListedValues = 4;

std::string inQuotes(const std::string& s) {
    return "'" + s + "'";
}

std::optional<size_t> columnOf(const CsvTable& table, const char* column) {
    const auto it = std::find(table.header.begin(), table.header.end(), column);
    if (it == table.header.end()) return std::nullopt;
    return size_t(it - table.header.begin());
}

/// "'A' in 'a.csv:2' but 'B' in 'b.csv:2'", or for more values "'A' in ..., 'B' in ... and 'C' in ...".
std::string valuesWithPlaces(const std::vector<SeenValue>& values) {
    const size_t listed = std::min(values.size(), kMaxListedValues);
    std::string out;
    for (size_t i = 0; i < listed; ++i) {
        if (i > 0) out += values.size() == 2 ? " but " : i + 1 == listed ? " and " : ", ";
        out += inQuotes(values[i].value) + " in " + inQuotes(values[i].where);
    }
    if (values.size() > listed) out += " and " + std::to_string(values.size() - listed) + " more values";
    return out;
}

} // namespace

std::string Mixture::label() const {
    return api.empty() ? column : column + " (api " + api + ")";
}

void MeasurementIdentity::add(const CsvTable& table, const std::string& path,
                              const std::vector<size_t>& lines) {
    const std::optional<size_t> api = columnOf(table, col::kApi);
    // Rows written before the host column existed lack it: they name no host.
    const std::optional<size_t> host = columnOf(table, col::kHost);
    mHostColumn = mHostColumn || host.has_value();
    for (const IdentityColumn& identity : kIdentity) {
        const std::optional<size_t> c = columnOf(table, identity.name);
        if (!c) continue;
        for (size_t r = 0; r < table.rows.size(); ++r) {
            const std::vector<std::string>& row = table.rows[r];
            const std::string scope = identity.perApi && api ? row[*api] : "";
            if (!row[*c].empty()) count(identity.name, scope, row[*c], path, lines[r]);
        }
    }
    if (!host) return;
    for (const auto& row : table.rows)
        if (!row[*host].empty()) mHosts.insert(row[*host]);
}

void MeasurementIdentity::count(const std::string& column, const std::string& api, const std::string& value,
                                const std::string& path, size_t line) {
    auto tally = std::find_if(mTallies.begin(), mTallies.end(),
                              [&](const Tally& t) { return t.column == column && t.api == api; });
    if (tally == mTallies.end()) tally = mTallies.insert(mTallies.end(), Tally{column, api, {}});
    auto seen = std::find_if(tally->values.begin(), tally->values.end(),
                             [&](const SeenValue& v) { return v.value == value; });
    if (seen == tally->values.end())
        seen =
            tally->values.insert(tally->values.end(), SeenValue{value, 0, path + ":" + std::to_string(line)});
    ++seen->rows;
}

std::vector<Mixture> MeasurementIdentity::mixtures() const {
    std::vector<Mixture> out;
    for (const IdentityColumn& identity : kIdentity)
        for (const Tally& t : mTallies)
            if (t.column == identity.name && t.values.size() > 1) out.push_back({t.column, t.api, t.values});
    return out;
}

std::optional<size_t> MeasurementIdentity::hosts() const {
    return mHostColumn ? std::optional<size_t>(mHosts.size()) : std::nullopt;
}

std::string MeasurementIdentity::refusal(const std::vector<Mixture>& mixtures) {
    std::string out = "rows of different measurements mixed:";
    for (size_t i = 0; i < mixtures.size(); ++i)
        out += (i ? "; " : " ") + mixtures[i].label() + " " + valuesWithPlaces(mixtures[i].values);
    return out + "; merge the shards of one commit, CPU model, renderer and driver, or pass --allow-mixed "
                 "to merge them anyway";
}

std::string MeasurementIdentity::describe(const Mixture& mixture) {
    std::string out = mixture.label() + ":";
    for (size_t i = 0; i < mixture.values.size(); ++i)
        out += (i ? ", " : " ") + inQuotes(mixture.values[i].value) + " " +
               std::to_string(mixture.values[i].rows) + (mixture.values[i].rows == 1 ? " row" : " rows") +
               " (first in " + inQuotes(mixture.values[i].where) + ")";
    return out;
}

} // namespace sb
