#include "bench/lib/options/BashCompletion.h"

#include <sstream>
#include <utility>

#include "bench/lib/output/RowExport.h"
#include "core/Strings.h"
#include "gl/backends/BackendRegistry.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Scene.h"
#include "scenes/SceneLoader.h"
#include "techniques/Submission.h"

namespace sb {

namespace {

/// "a, b, c" -> "a b c": the tables' lists for help text, as a word list for compgen.
std::string words(const std::string& commaList) {
    std::string out;
    for (char c : commaList)
        if (c != ',') out += c;
    return out;
}

/// The options whose value is one of a fixed set, wherever a mode declares them. The sets come from the
/// tables that parse them; the few that are spelt out are checked as literal words by their commands
/// (--api, --camera's presets, sweep's --mode, ci's --scheme).
std::vector<std::pair<std::string, std::string>> fixedValues() {
    return {{"--api", "gl vulkan"},
            {"--submit", submitModes().list(" ")},
            {"--back-faces", "cull draw"},
            {"--light", lightTypeNames().list(" ")},
            {"--lighting", lightingRateNames().list(" ")},
            {"--format", rowFormats().list(" ")},
            {"--backend", words(backendNames())},
            {"--camera", "far mid near top path"},
            {"--mode", "measure accuracy"},
            {"--scheme", "abba random"}};
}

std::string optionWords(const CliCommand& c) {
    std::string out;
    for (const CliOption& o : c.options)
        for (const std::string& f : o.flags) out += (out.empty() ? "" : " ") + f;
    return out;
}

void tables(std::ostream& os, const std::vector<CliCommand>& commands) {
    std::string subcommands;
    for (const CliCommand& c : commands)
        if (!c.name.empty()) subcommands += (subcommands.empty() ? "" : " ") + c.name;
    os << "_bench_subcommands='" << subcommands << "'\n"
       << "_bench_techniques='" << join(TechniqueRegistry::names(), " ") << "'\n"
       << "_bench_scenes='" << join(SceneLoader::listBuiltinScenes(), " ") << "'\n\n";
    os << "# The property keys of technique $1.\n_bench_properties() {\n    case \"$1\" in\n";
    for (const TechniqueRegistry::Entry& e : TechniqueRegistry::entries())
        os << "    " << e.name << ") echo '"
           << join(TechniqueRegistry::describe(TechniqueSpec{e.name, {}})->info().properties, " ",
                   [](const PropertyDesc& p) { return p.name; })
           << "' ;;\n";
    os << "    esac\n}\n\n# The options of subcommand $1 ('' for the plain run).\n_bench_options() {\n"
          "    case \"$1\" in\n";
    for (const CliCommand& c : commands) os << "    '" << c.name << "') echo '" << optionWords(c) << "' ;;\n";
    os << "    esac\n}\n\n# Whether option $2 of subcommand $1 takes a value.\n_bench_takes_value() {\n"
          "    case \"$1 $2\" in\n";
    for (const CliCommand& c : commands)
        for (const CliOption& o : c.options)
            if (!o.argument.empty())
                for (const std::string& f : o.flags)
                    os << "    '" << c.name << " " << f << "') return 0 ;;\n";
    os << "    esac\n    return 1\n}\n\n# The fixed values of option $1, if it has them.\n_bench_values() {\n"
          "    case \"$1\" in\n";
    for (const auto& [option, values] : fixedValues())
        os << "    " << option << ") echo '" << values << "' ;;\n";
    os << "    esac\n}\n\n";
}

// The function itself: which list the word under the cursor completes from. Bash splits words at ':'
// and '=' (COMP_WORDBREAKS), so the line is split again at blanks only where bash gave it (COMP_LINE);
// the replies are then cut back to the part after the word's last ':', which is what readline replaces.
constexpr const char* kFunction = R"BASH(_bench() {
    local words=()
    if [[ -n "${COMP_LINE-}" ]]; then
        local line="${COMP_LINE:0:COMP_POINT}"
        read -ra words <<<"$line"
        [[ -z "$line" || "$line" == *[[:blank:]] ]] && words+=("")
    else
        words=("${COMP_WORDS[@]:0:COMP_CWORD+1}")
    fi
    local cur="${words[${#words[@]}-1]}" prev=""
    (( ${#words[@]} > 1 )) && prev="${words[${#words[@]}-2]}"
    local sub=""
    if (( ${#words[@]} > 2 )) && [[ " $_bench_subcommands " == *" ${words[1]} "* ]]; then
        sub="${words[1]}"
    fi
    local replies=() values
    if [[ "$prev" == -t || "$prev" == --technique ]] && [[ "$cur" == *:* ]]; then
        local last="${cur##*:}"
        if [[ "$last" != *=* ]]; then
            mapfile -t replies < <(compgen -P "${cur%:*}:" -S = -W "$(_bench_properties "${cur%%:*}")" -- "$last")
            compopt -o nospace 2>/dev/null
        fi
    elif [[ "$prev" == -t || "$prev" == --technique ]]; then
        mapfile -t replies < <(compgen -W "$_bench_techniques" -- "$cur")
    elif [[ "$prev" == --scene ]]; then
        mapfile -t replies < <(compgen -W "$_bench_scenes" -- "$cur"; compgen -f -X '!*.json' -- "$cur")
    elif _bench_takes_value "$sub" "$prev"; then
        values="$(_bench_values "$prev")"
        if [[ -n "$values" ]]; then
            mapfile -t replies < <(compgen -W "$values" -- "$cur")
        else
            mapfile -t replies < <(compgen -f -- "$cur")
            compopt -o filenames 2>/dev/null
        fi
    elif [[ "$cur" == -* ]]; then
        mapfile -t replies < <(compgen -W "$(_bench_options "$sub")" -- "$cur")
    elif (( ${#words[@]} == 2 )); then
        mapfile -t replies < <(compgen -W "$_bench_subcommands" -- "$cur")
    else
        mapfile -t replies < <(compgen -f -- "$cur")
        compopt -o filenames 2>/dev/null
    fi
    local prefix=""
    [[ -n "${COMP_LINE-}" && "${COMP_WORDBREAKS-}" == *:* && "$cur" == *:* ]] && prefix="${cur%"${cur##*:}"}"
    COMPREPLY=("${replies[@]#"$prefix"}")
}
complete -F _bench bench
)BASH";

} // namespace

std::string BashCompletion::render(const std::vector<CliCommand>& commands) {
    std::ostringstream os;
    os << "# bash completion for bench (shadowbench), written by `bench --completion bash` from the tables\n"
          "# of its --help and its technique registry: regenerate it rather than edit it.\n\n";
    tables(os, commands);
    os << kFunction;
    return os.str();
}

} // namespace sb
