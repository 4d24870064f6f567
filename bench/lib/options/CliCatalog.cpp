#include "bench/lib/options/CliCatalog.h"

#include <stdexcept>

#include <CLI/CLI.hpp>

#include "core/Suggestion.h"

namespace sb {

namespace {

/// Where capture() records while describe() runs; null otherwise. Set and read on one thread.
CliCommand* gSink = nullptr;

CliOption describeOption(const CLI::Option& o) {
    CliOption out;
    for (const std::string& s : o.get_snames()) out.flags.push_back("-" + s);
    for (const std::string& l : o.get_lnames()) out.flags.push_back("--" + l);
    if (o.get_positional() && out.flags.empty()) out.positional = o.get_name(true, false);
    if (o.get_type_size_max() > 0) out.argument = o.get_type_name();
    out.description = o.get_description();
    out.defaultValue = o.get_default_str();
    out.required = o.get_required();
    out.repeatable = o.get_expected_max() > 1;
    return out;
}

} // namespace

CliCommand CliCatalog::describe(const std::function<int()>& entry, const std::string& name,
                                const std::string& usage, const std::string& summary) {
    CliCommand out;
    out.name = name;
    out.usage = usage;
    out.summary = summary;
    struct Reset {
        ~Reset() { gSink = nullptr; }
    } reset;
    gSink = &out;
    entry();
    if (out.description.empty()) throw std::logic_error("bench " + name + ": no CLI::App reached parseCli");
    return out;
}

bool CliCatalog::capture(const CLI::App& app) {
    if (!gSink) return false;
    gSink->description = app.get_description();
    gSink->footer = app.get_footer();
    // An empty group is CLI11's "hidden": options a mode declares but refuses (bench's accuracy options).
    for (const CLI::Option* o : app.get_options())
        if (!o->get_group().empty()) gSink->options.push_back(describeOption(*o));
    return true;
}

std::vector<std::string> CliCatalog::optionNames(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options()) {
        if (o->get_group().empty()) continue;
        for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
        for (const std::string& s : o->get_snames()) names.push_back("-" + s);
    }
    return names;
}

std::string CliCatalog::unexpected(const CLI::App& app) {
    const std::vector<std::string> extras = app.remaining();
    for (const std::string& arg : extras) {
        if (arg.size() < 2 || arg[0] != '-') continue;
        const std::string name = arg.substr(0, arg.find('='));
        return "unknown option " + name + Suggestion::didYouMean(name, optionNames(app));
    }
    return "unexpected argument " + (extras.empty() ? std::string("?") : extras.front());
}

} // namespace sb
