#include "bench/lib/options/ManPage.h"

#include <cctype>
#include <sstream>

#include "core/Strings.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

namespace sb {

namespace {

std::string escape(const std::string& text) {
    return ManPage::escape(text);
}

std::string bold(const std::string& text) {
    return "\\fB" + ManPage::escape(text) + "\\fR";
}

std::string italic(const std::string& text) {
    return "\\fI" + ManPage::escape(text) + "\\fR";
}

/// Lines of a preformatted block (a mode's footer, the exit codes) as no-fill roff, so that the columns
/// --help aligned stay aligned.
void preformatted(std::ostream& os, const std::string& block) {
    os << ".PP\n.nf\n";
    std::istringstream lines(block);
    for (std::string line; std::getline(lines, line);) os << ManPage::escape(line) << "\n";
    os << ".fi\n";
}

/// ".TP" with the option's names and argument, then its description and default.
void option(std::ostream& os, const CliOption& o) {
    os << ".TP\n";
    if (!o.positional.empty()) {
        os << italic(o.positional) << (o.repeatable ? " ..." : "") << "\n";
    } else {
        std::string names;
        for (const std::string& f : o.flags) names += (names.empty() ? "" : ", ") + bold(f);
        os << names << (o.argument.empty() ? "" : " " + italic(o.argument)) << (o.repeatable ? " ..." : "")
           << "\n";
    }
    os << escape(o.description.empty() ? "(no description)" : o.description);
    if (o.required) os << " Required.";
    if (!o.defaultValue.empty()) os << " Default: " << escape(o.defaultValue) << ".";
    os << "\n";
}

void synopsis(std::ostream& os, const std::vector<CliCommand>& commands) {
    os << ".SH SYNOPSIS\n";
    for (const CliCommand& c : commands) os << ".br\n" << bold(c.usage) << "\n";
    os << ".br\n" << bold("bench --version") << "\n";
}

void description(std::ostream& os, const std::vector<CliCommand>& commands) {
    os << ".SH DESCRIPTION\n"
       << escape(commands.front().description) << ".\n"
       << "The first argument picks the mode; without one, \\fBbench\\fR measures frame times.\n"
          "Each mode's options follow in a section of its own; \\fBbench\\fR \\fIMODE\\fR \\fB\\-\\-help\\fR "
          "prints the same.\n";
    for (const CliCommand& c : commands) {
        std::string summary = c.summary;
        for (char& ch : summary)
            if (ch == '\n') ch = ' ';
        os << ".TP\n" << bold(c.usage) << "\n" << escape(summary) << "\n";
    }
}

std::string heading(const std::string& mode) {
    std::string out = "BENCH ";
    for (char c : mode) out += char(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

void mode(std::ostream& os, const CliCommand& c) {
    os << ".SH " << (c.name.empty() ? std::string("OPTIONS") : heading(c.name)) << "\n";
    if (!c.name.empty()) os << bold(c.usage) << "\n.PP\n" << escape(c.description) << ".\n";
    for (const CliOption& o : c.options) option(os, o);
    if (!c.name.empty() && !c.footer.empty()) preformatted(os, c.footer);
}

void techniques(std::ostream& os) {
    os << ".SH TECHNIQUES\n"
          "Given with \\fB\\-t\\fR \\fIname\\fR[:\\fIproperty\\fR=\\fIvalue\\fR...]; "
          "\\fBbench \\-\\-list\\fR shows their effects and passes too.\n";
    for (const TechniqueRegistry::Entry& entry : TechniqueRegistry::entries()) {
        const std::unique_ptr<Technique> technique =
            TechniqueRegistry::describe(TechniqueSpec{entry.name, {}}); // owns the info below
        const TechniqueInfo& info = technique->info();
        os << ".TP\n" << bold(info.name) << "\n" << escape(info.description) << "\n";
        if (info.properties.empty()) continue;
        os << ".RS\n";
        for (const PropertyDesc& p : info.properties)
            os << ".TP\n"
               << bold(p.name) << " " << italic(propertyTypeName(p.type)) << " " << escape(p.rangeText())
               << "\n"
               << escape(p.description) << " Default: " << escape(p.defaultValue) << ".\n";
        os << ".RE\n";
    }
}

void examples(std::ostream& os, const std::string& block) {
    os << ".SH EXAMPLES\n";
    std::istringstream lines(block);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("  bench", 0) != 0) continue; // the "Examples:" heading
        // --help aligns each explanation after a run of spaces; an example without one is a command only.
        const size_t gap = line.find("  ", 2);
        const std::string command = line.substr(2, gap == std::string::npos ? gap : gap - 2);
        const size_t text = gap == std::string::npos ? gap : line.find_first_not_of(' ', gap);
        os << ".TP\n"
           << bold(command) << "\n"
           << (text == std::string::npos ? "" : escape(line.substr(text))) << "\n";
    }
}

void ending(std::ostream& os, const ManPage::Text& text) {
    os << ".SH EXIT STATUS\n";
    preformatted(os, text.exitCodes);
    os << ".SH FILES\n"
          ".TP\n"
       << italic("PREFIX/share/shadowbench/")
       << "\nThe shaders, built-in scenes and tools of an installed \\fBbench\\fR; a \\fBbench\\fR run from "
          "its build folder reads the source tree's. \\fBbench \\-\\-version\\fR names the folder in use.\n"
          ".TP\n"
       << italic("~/.cache/shadowbench/auto-calibration.csv")
       << "\nThe calibration cache of \\fB\\-t auto\\fR (\\fB\\-\\-calibration\\fR overrides).\n"
          ".SH SEE ALSO\n"
          "\\fBbench \\-\\-help\\fR, \\fBbench\\fR \\fIMODE\\fR \\fB\\-\\-help\\fR, \\fBbench "
          "\\-\\-list\\fR; "
          "README.md and docs/ARCHITECTURE.md in the source tree.\n";
}

} // namespace

std::string ManPage::escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\\')
            out += "\\e";
        else if (c == '-')
            out += "\\-";
        else
            out += c;
    }
    // A line that starts with '.' or '\'' would be a request.
    for (size_t at = 0; at != std::string::npos; at = out.find('\n', at + 1)) {
        const size_t start = at == 0 ? 0 : at + 1;
        if (start < out.size() && (out[start] == '.' || out[start] == '\'')) out.insert(start, "\\&");
    }
    return out;
}

std::string ManPage::render(const std::vector<CliCommand>& commands, const Text& text) {
    std::ostringstream os;
    os << ".TH BENCH 1 \"\" \"" << escape(text.version) << "\" \"User Commands\"\n"
       << ".nh\n.SH NAME\nbench \\- measure and compare real\\-time shadow techniques\n";
    synopsis(os, commands);
    description(os, commands);
    for (const CliCommand& c : commands) mode(os, c);
    techniques(os);
    os << ".SH SCENES\nBuilt in, given with \\fB\\-\\-scene\\fR \\fIname\\fR (or a scene JSON file): "
       << escape(join(SceneLoader::listBuiltinScenes(), ", ")) << ".\n";
    examples(os, text.examples);
    ending(os, text);
    return os.str();
}

} // namespace sb
