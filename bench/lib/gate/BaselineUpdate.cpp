#include "bench/lib/gate/BaselineUpdate.h"

#include <algorithm>
#include <set>

#include "bench/lib/gate/InstructionLayer.h"
#include "bench/lib/output/ResultColumns.h"
#include "core/Error.h"

namespace sb {

namespace {

bool ranNow(const CsvTable& fresh, size_t configColumn, const std::string& name) {
    return std::any_of(fresh.rows.begin(), fresh.rows.end(),
                       [&](const std::vector<std::string>& row) { return row[configColumn] == name; });
}

/// The fields in which two fingerprints of the same machine, toolchain and driver differ when one was
/// counted on GL and the other on Vulkan: a Vulkan run has no GL version, its backend is "vulkan", and
/// its driver version is the device's words ("Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)" where GL says "Mesa
/// 25.0.7-2~bpo12+1"); the Mesa and LLVM versions, compared still, name the driver on both.
std::vector<std::string> besidesApi(const Fingerprint& kept, const Fingerprint& fresh) {
    std::vector<std::string> out = kept.differences(fresh);
    if (kept.glVersion.empty() != fresh.glVersion.empty())
        std::erase_if(out, [](const std::string& f) {
            return f == "gl_version" || f == "backend" || f == "driver_version";
        });
    return out;
}

} // namespace

CsvTable BaselineUpdate::work(const CsvTable& committed, const CsvTable& fresh,
                              const std::vector<const CiConfig*>& belong) {
    const auto freshConfig = std::find(fresh.header.begin(), fresh.header.end(), col::kCiConfig);
    const auto keptConfig = std::find(committed.header.begin(), committed.header.end(), col::kCiConfig);
    if (freshConfig == fresh.header.end() || keptConfig == committed.header.end()) return fresh;
    const size_t freshAt = size_t(freshConfig - fresh.header.begin());
    const size_t keptAt = size_t(keptConfig - committed.header.begin());
    CsvTable out;
    out.header = committed.header;
    for (const std::string& column : fresh.header)
        if (!out.hasColumn(column)) out.header.push_back(column);
    // Each row in the merged header's columns.
    auto widen = [&](const CsvTable& from, const std::vector<std::string>& row) {
        std::vector<std::string> cells;
        for (const std::string& column : out.header) cells.push_back(from.cell(row, column));
        return cells;
    };
    size_t kept = 0;
    for (const CiConfig* c : belong) {
        const bool fromFresh = ranNow(fresh, freshAt, c->name);
        const CsvTable& from = fromFresh ? fresh : committed;
        const size_t at = fromFresh ? freshAt : keptAt;
        for (const auto& row : from.rows)
            if (row[at] == c->name) {
                out.rows.push_back(widen(from, row));
                kept += !fromFresh;
            }
    }
    return kept ? out : fresh;
}

nlohmann::json BaselineUpdate::instructions(const nlohmann::json& committed, const nlohmann::json& fresh,
                                            const std::vector<const CiConfig*>& belong,
                                            const std::string& path) {
    if (committed.is_null() || !committed.contains("configs") || !committed.contains("fingerprint"))
        return fresh;
    const Fingerprint freshFingerprint =
        Fingerprint::fromJson(fresh.at("fingerprint"), "the new instruction record");
    // The committed record's configurations that stay, each checked against this update's machine.
    std::vector<std::string> keep;
    for (const CiConfig* c : belong) {
        if (fresh["configs"].contains(c->name) || !committed["configs"].contains(c->name)) continue;
        const std::vector<std::string> differ =
            besidesApi(InstructionLayer::committed(committed, c->name)->fingerprint, freshFingerprint);
        if (!differ.empty()) {
            std::string list;
            for (const std::string& d : differ) list += (list.empty() ? "" : ", ") + d;
            throw Error(
                path + ": " + c->name +
                "'s instructions were counted under another fingerprint than this update's (" + list +
                "); keeping them beside the new counts would mix machines: count every configuration "
                "of layer B again (bench ci --update --layers B without --configs or --driver-bound)");
        }
        keep.push_back(c->name);
    }
    if (keep.empty()) return fresh;
    // The committed record's fingerprint stays the record's, so the kept entries read as they did; a
    // fresh configuration counted under another (its API's) carries its own.
    nlohmann::json out;
    out["fingerprint"] = committed["fingerprint"];
    const Fingerprint recordFingerprint = Fingerprint::fromJson(committed["fingerprint"], path);
    for (const CiConfig* c : belong) {
        if (std::find(keep.begin(), keep.end(), c->name) != keep.end()) {
            out["configs"][c->name] = committed["configs"][c->name];
        } else if (fresh["configs"].contains(c->name)) {
            nlohmann::json entry = fresh["configs"][c->name];
            const Fingerprint own = entry.contains("fingerprint")
                                        ? Fingerprint::fromJson(entry["fingerprint"], path)
                                        : freshFingerprint;
            entry.erase("fingerprint");
            if (!own.differences(recordFingerprint).empty()) entry["fingerprint"] = own.toJson();
            out["configs"][c->name] = entry;
        }
    }
    return out;
}

} // namespace sb
