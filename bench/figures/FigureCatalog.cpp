#include "bench/figures/FigureCatalog.h"

#include <set>

#include "bench/lib/bottleneck/BottleneckStudy.h"
#include "core/Error.h"
#include "core/JsonReader.h"
#include "core/Paths.h"

namespace sb {

namespace {
constexpr const char* kCatalog = "results/figures/figures.json";

FigureDeclaration parseFigure(const JsonReader& r) {
    r.requireObject({"name", "title", "seed", "claim", "kind", "sweep", "plot", "reduced"});
    FigureDeclaration f;
    f.name = r["name"].string();
    if (f.name.empty() || f.name.find_first_of("/\\ .") != std::string::npos)
        r["name"].fail("a folder name without '/', '\\\\', '.' or spaces");
    f.title = r["title"].string();
    f.seed = r["seed"].string();
    f.claim = r["claim"].string();
    const std::string kind = r.has("kind") ? r["kind"].string() : "sweep";
    if (kind != "sweep" && kind != "bottleneck") r["kind"].fail("\"sweep\" or \"bottleneck\"");
    f.kind = kind == "bottleneck" ? FigureDeclaration::Kind::Bottleneck : FigureDeclaration::Kind::Sweep;
    f.sweep = r["sweep"].value();
    if (!f.sweep.is_object() && !(f.sweep.is_array() && !f.sweep.empty()))
        r["sweep"].fail("a sweep definition object or a non-empty array of them");
    if (r.has("reduced")) {
        f.reduced = r["reduced"].value();
        if (!f.reduced.is_object()) r["reduced"].fail("an object of sweep keys");
    }
    const JsonReader plot = r["plot"];
    plot.requireObject({"kind", "args"});
    f.plotKind = plot["kind"].string();
    if (plot.has("args"))
        for (const JsonReader& a : plot["args"].elements()) f.plotArgs.push_back(a.string());
    return f;
}
} // namespace

std::vector<SweepDefinition> FigureDeclaration::definitions(bool reducedRun,
                                                            const std::string& catalogPath) const {
    const nlohmann::json all = sweep.is_array() ? sweep : nlohmann::json::array({sweep});
    std::vector<SweepDefinition> out;
    for (size_t i = 0; i < all.size(); ++i) {
        nlohmann::json d = all[i];
        if (reducedRun)
            for (const auto& item : reduced.items()) d[item.key()] = item.value();
        const std::string path = "/" + name + "/sweep" + (sweep.is_array() ? "/" + std::to_string(i) : "");
        out.push_back(SweepDefinition::fromJson(d, catalogPath, path, name));
    }
    return out;
}

SweepPlan FigureDeclaration::plan(bool reducedRun, const std::string& catalogPath) const {
    SweepPlan out;
    out.name = name;
    for (const SweepDefinition& d : definitions(reducedRun, catalogPath)) {
        const SweepPlan p = kind == Kind::Bottleneck ? BottleneckStudy::plan(d) : d.expand();
        out.mode = p.mode;
        out.append(p);
    }
    return out;
}

std::vector<FigureDeclaration> FigureCatalog::load(const std::string& path) {
    // The scene files' reader (comments allowed, nesting bounded, errors at a line and column).
    const nlohmann::json doc = JsonReader::parse(Paths::readTextFile(path), path);
    std::vector<FigureDeclaration> out;
    std::set<std::string> names;
    for (const JsonReader& r : JsonReader(doc, path).elements(true)) {
        FigureDeclaration f = parseFigure(r);
        if (!names.insert(f.name).second) r["name"].error("duplicate figure name \"" + f.name + "\"");
        f.definitions(false, path); // the sweeps parse, reduced or not
        f.definitions(true, path);
        out.push_back(std::move(f));
    }
    return out;
}

std::string FigureCatalog::defaultPath() {
    const std::string found = Paths::findResource(kCatalog);
    if (found.empty()) throw Error(std::string("cannot find ") + kCatalog + " (pass --catalog FILE)");
    return found;
}

} // namespace sb
