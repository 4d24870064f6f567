#include "bench/lib/gate/CiSuite.h"

#include <algorithm>
#include <set>

#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/JsonReader.h"
#include "core/Paths.h"
#include "core/Strings.h"

namespace sb {

namespace {

std::vector<std::string> strings(const JsonReader& r) {
    std::vector<std::string> out;
    for (const JsonReader& e : r.elements()) out.push_back(e.string());
    return out;
}

bool validName(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

CiLayerRuns layer(const JsonReader& r, bool wall) {
    if (wall)
        r.requireObject({"frames", "warmup", "rounds", "control", "configs"});
    else
        r.requireObject({"frames", "warmup", "configs"});
    CiLayerRuns out;
    if (r.has("frames")) out.frames = int(r["frames"].integer(1, 100000, "a frame count >= 1"));
    if (r.has("warmup")) out.warmup = int(r["warmup"].integer(0, 100000, "a frame count >= 0"));
    if (r.has("configs")) out.configs = strings(r["configs"]);
    if (wall && r.has("rounds")) out.rounds = int(r["rounds"].integer(2, 1000, "a round count >= 2"));
    if (wall && r.has("control")) out.control = r["control"].string();
    return out;
}

/// A configuration bound to drivers names drivers of the table, at least one, and says why.
void checkDrivers(const CiConfig& config, const std::string& where) {
    if (config.drivers.empty() && config.why.empty()) return;
    if (config.drivers.empty())
        throw Error(where +
                    "/why: says why other drivers cannot run it, but no \"drivers\" name those that can");
    if (config.why.empty())
        throw Error(where +
                    "/drivers: a configuration bound to drivers says why the others cannot run it (\"why\")");
    const std::vector<std::string> known = DriverTable::names();
    for (const std::string& d : config.drivers)
        if (std::find(known.begin(), known.end(), d) == known.end())
            throw Error(where + "/drivers: " + JsonReader::excerpt(d) +
                        " is not a driver of the driver table (" + join(known, ", ") + ")");
}

int techniqueCount(const std::vector<std::string>& args) {
    int n = 0;
    for (const std::string& a : args)
        if (a == "-t" || a == "--technique" || a.rfind("--technique=", 0) == 0) ++n;
    return n;
}

} // namespace

CiSuite CiSuite::load(const std::string& path) {
    const nlohmann::json doc = JsonReader::parse(Paths::readTextFile(path), path);
    const JsonReader root(doc, path);
    root.requireObject({"name", "args", "work", "instructions", "wall", "configs"});
    CiSuite s;
    s.path = path;
    s.name = root["name"].string();
    if (root.has("args")) s.args = strings(root["args"]);
    std::set<std::string> names;
    for (const JsonReader& c : root["configs"].elements(true)) {
        c.requireObject({"name", "bound", "args", "drivers", "why"});
        CiConfig config{c["name"].string(), c.has("bound") ? c["bound"].string() : "balanced",
                        strings(c["args"]),
                        c.has("drivers") ? strings(c["drivers"]) : std::vector<std::string>{},
                        c.has("why") ? c["why"].string() : ""};
        auto where = path + ": " + c.path();
        checkDrivers(config, where);
        if (!validName(config.name))
            throw Error(where + "/name: '" + JsonReader::excerpt(config.name) +
                        "' is not a name of [a-z0-9_] characters");
        if (!names.insert(config.name).second)
            throw Error(where + "/name: '" + config.name + "' is given twice");
        static const std::set<std::string> kBounds = {"cpu", "vertex", "fill", "balanced"};
        if (!kBounds.count(config.bound))
            throw Error(where + "/bound: '" + JsonReader::excerpt(config.bound) +
                        "' is not one of cpu, vertex, fill, balanced");
        if (techniqueCount(config.args) != 1)
            throw Error(where + "/args: a configuration measures exactly one technique (one -t), got " +
                        std::to_string(techniqueCount(config.args)));
        s.configs.push_back(std::move(config));
    }
    if (root.has("work")) s.work = layer(root["work"], false);
    if (root.has("instructions")) s.instructions = layer(root["instructions"], false);
    if (root.has("wall")) s.wall = layer(root["wall"], true);
    for (const auto* l : {&s.work, &s.instructions, &s.wall}) {
        for (const std::string& n : l->configs)
            if (!names.count(n))
                throw Error(path + ": a layer names '" + n + "', which is not a configuration");
    }
    if (!s.wall.control.empty() && !names.count(s.wall.control))
        throw Error(path + ": /wall/control: '" + s.wall.control + "' is not a configuration");
    return s;
}

bool CiConfig::runsOn(const std::string& driver) const {
    return drivers.empty() || std::find(drivers.begin(), drivers.end(), driver) != drivers.end();
}

std::string CiConfig::notRunReason() const {
    std::string names;
    for (const std::string& d : drivers) names += (names.empty() ? "" : ", ") + d;
    return "runs on " + names + " only: " + why;
}

const CiConfig& CiSuite::config(const std::string& wanted) const {
    for (const CiConfig& c : configs)
        if (c.name == wanted) return c;
    throw Error(path + ": no configuration '" + wanted + "'");
}

std::vector<const CiConfig*> CiSuite::select(const CiLayerRuns& layer,
                                             const std::vector<std::string>& only) const {
    for (const std::string& n : only) config(n); // an unknown name is bad input
    std::vector<const CiConfig*> out;
    for (const CiConfig& c : configs) {
        const bool inLayer = layer.configs.empty() || std::find(layer.configs.begin(), layer.configs.end(),
                                                                c.name) != layer.configs.end();
        const bool asked = only.empty() || std::find(only.begin(), only.end(), c.name) != only.end();
        if (inLayer && asked) out.push_back(&c);
    }
    return out;
}

std::vector<const CiConfig*> CiSuite::selectOn(const CiLayerRuns& layer, const std::vector<std::string>& only,
                                               const std::vector<std::string>& drivers,
                                               bool boundOnly) const {
    std::vector<const CiConfig*> out = select(layer, only);
    std::erase_if(out, [&](const CiConfig* c) {
        for (const std::string& d : drivers)
            if (!c->runsOn(d) || (boundOnly && c->drivers.empty())) return true;
        return false;
    });
    return out;
}

} // namespace sb
