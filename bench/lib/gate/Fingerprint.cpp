#include "bench/lib/gate/Fingerprint.h"

#include <fstream>
#include <gnu/libc-version.h>
#include <regex>
#include <set>
#include <sstream>

#include "core/Error.h"

namespace sb {

namespace {

std::string firstMatch(const std::string& text, const std::regex& re) {
    std::smatch m;
    return std::regex_search(text, m, re) ? m[1].str() : "";
}

/// The value of the first "key\t: value" line of /proc/cpuinfo.
std::string cpuinfoField(const std::string& key) {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key, 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string v = line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(' '));
        return v;
    }
    return "";
}

std::string text(const nlohmann::json& row, const char* key) {
    auto it = row.find(key);
    return it != row.end() && it->is_string() ? it->get<std::string>() : "";
}

// The JSON names, one place for toJson, fromJson and differences.
using Field = std::string Fingerprint::*;
const std::vector<std::pair<const char*, Field>>& fields() {
    static const std::vector<std::pair<const char*, Field>> kFields = {
        {"renderer", &Fingerprint::renderer},
        {"gl_version", &Fingerprint::glVersion},
        {"mesa_version", &Fingerprint::mesaVersion},
        {"llvm_version", &Fingerprint::llvmVersion},
        {"vector_bits", &Fingerprint::vectorBits},
        {"backend", &Fingerprint::backend},
        {"cpu_model", &Fingerprint::cpuModel},
        {"cpu_flags", &Fingerprint::cpuFlags},
        {"valgrind", &Fingerprint::valgrind},
        {"glibc", &Fingerprint::glibc},
        {"compiler", &Fingerprint::compiler},
        {"driver", &Fingerprint::driver},
        {"driver_version", &Fingerprint::driverVersion},
    };
    return kFields;
}

} // namespace

const std::vector<std::string>& Fingerprint::relevantCpuFlags() {
    static const std::vector<std::string> kFlags = {"sse4_1", "sse4_2",  "avx",      "avx2",    "f16c",
                                                    "fma",    "avx512f", "avx512bw", "avx512vl"};
    return kFlags;
}

std::string Fingerprint::relevantFlags(const std::string& cpuinfoFlags) {
    std::istringstream in(cpuinfoFlags);
    std::set<std::string> present;
    for (std::string f; in >> f;) present.insert(f);
    std::string out;
    for (const std::string& f : relevantCpuFlags())
        if (present.count(f)) out += (out.empty() ? "" : " ") + f;
    return out;
}

Fingerprint Fingerprint::capture(const nlohmann::json& row, const std::string& valgrindVersion,
                                 const std::map<std::string, std::string>& environment) {
    Fingerprint f;
    f.renderer = text(row, "renderer");
    f.glVersion = text(row, "gl_version");
    const std::regex mesa(R"(Mesa ([0-9][0-9A-Za-z.\-~+]*))");
    f.mesaVersion = firstMatch(f.glVersion.empty() ? text(row, "gl_vendor") : f.glVersion, mesa);
    f.driver = text(row, "driver");
    f.driverVersion = text(row, "driver_version");
    f.llvmVersion = firstMatch(f.renderer, std::regex(R"(LLVM ([0-9][0-9.]*))"));
    f.vectorBits = firstMatch(f.renderer, std::regex(R"(([0-9]+) bits)"));
    f.backend = text(row, "backend");
    f.cpuModel = cpuinfoField("model name");
    f.cpuFlags = relevantFlags(cpuinfoField("flags"));
    f.valgrind = valgrindVersion;
    f.glibc = gnu_get_libc_version();
#if defined(__clang__)
    f.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
    f.compiler = "gcc " __VERSION__;
#endif
    f.environment = environment;
    return f;
}

nlohmann::json Fingerprint::toJson() const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, field] : fields()) j[name] = this->*field;
    j["environment"] = environment;
    return j;
}

Fingerprint Fingerprint::fromJson(const nlohmann::json& j, const std::string& source) {
    if (!j.is_object()) throw Error(source + ": fingerprint: expected an object");
    Fingerprint f;
    for (const auto& [name, field] : fields()) {
        auto it = j.find(name);
        if (it == j.end()) continue;
        if (!it->is_string()) throw Error(source + ": /" + name + ": expected a string");
        f.*field = it->get<std::string>();
    }
    if (auto it = j.find("environment"); it != j.end()) {
        if (!it->is_object()) throw Error(source + ": /environment: expected an object");
        for (const auto& [k, v] : it->items()) {
            if (!v.is_string()) throw Error(source + ": /environment/" + k + ": expected a string");
            f.environment[k] = v.get<std::string>();
        }
    }
    return f;
}

std::vector<std::string> Fingerprint::differences(const Fingerprint& other) const {
    std::vector<std::string> out;
    // Records written before the driver table lack the driver's name and version: unknown, not different.
    const std::set<std::string> ifBoth = {"driver", "driver_version"};
    for (const auto& [name, field] : fields()) {
        if (ifBoth.count(name) && ((this->*field).empty() || (other.*field).empty())) continue;
        if (this->*field != other.*field) out.push_back(name);
    }
    std::set<std::string> keys;
    for (const auto& [k, v] : environment) keys.insert(k);
    for (const auto& [k, v] : other.environment) keys.insert(k);
    for (const std::string& k : keys) {
        auto a = environment.find(k), b = other.environment.find(k);
        const bool same = a != environment.end() && b != other.environment.end() && a->second == b->second;
        if (!same) out.push_back("environment." + k);
    }
    return out;
}

std::vector<std::string> Fingerprint::differencesBesidesDriver(const Fingerprint& other,
                                                               const std::set<std::string>& tested) const {
    static const std::set<std::string> kDriverFields = {
        "renderer", "gl_version", "mesa_version", "llvm_version", "vector_bits", "driver", "driver_version"};
    std::vector<std::string> out = differences(other);
    std::erase_if(out, [&](const std::string& d) {
        const bool variable = d.rfind("environment.", 0) == 0;
        return kDriverFields.count(d) || (variable && tested.count(d.substr(12)));
    });
    return out;
}

void Fingerprint::requireComparable(const Fingerprint& base, const Fingerprint& current,
                                    FingerprintUse layer) {
    if (layer == FingerprintUse::ExactCounters) return;
    const std::vector<std::string> diff = base.differences(current);
    if (diff.empty()) return;
    std::string list;
    for (const std::string& d : diff) {
        list += (list.empty() ? "" : ", ") + d;
    }
    throw Error(std::string("fingerprints differ (") + list +
                "): " + (layer == FingerprintUse::Instructions ? "instruction counts" : "wall times") +
                " compare only on the same machine, driver and environment");
}

} // namespace sb
