#include "core/Injection.h"

#include <array>
#include <cstdlib>
#include <string_view>

#include "core/Error.h"

namespace sb {

namespace {

constexpr std::array<std::string_view, 3> kNames = {"extra_fullscreen_pass", "no_caster_culling",
                                                    "double_shadow_resolution"};

struct Parsed {
    std::array<bool, kNames.size()> on{};
    std::string unknown; ///< the first entry that names nothing
    std::string text;
};

Parsed parse() {
    Parsed p;
    const char* env = std::getenv("SHADOWBENCH_INJECT");
    std::string_view rest = env ? env : "";
    while (!rest.empty()) {
        const size_t comma = rest.find(',');
        const std::string_view entry = rest.substr(0, comma);
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
        if (entry.empty()) continue;
        bool known = false;
        for (size_t i = 0; i < kNames.size(); ++i) {
            if (entry != kNames[i]) continue;
            known = true;
            if (!p.on[i]) p.text += (p.text.empty() ? "" : ",") + std::string(entry);
            p.on[i] = true;
        }
        if (!known && p.unknown.empty()) p.unknown = std::string(entry);
    }
    return p;
}

const Parsed& parsed() {
    static const Parsed p = parse();
    return p;
}

} // namespace

bool injected(Injection which) {
    return parsed().on[size_t(which)];
}

void checkInjections() {
    if (parsed().unknown.empty()) return;
    std::string known;
    for (std::string_view n : kNames) known += (known.empty() ? "" : ", ") + std::string(n);
    throw Error("SHADOWBENCH_INJECT: '" + parsed().unknown.substr(0, 60) +
                "' is not a known regression (known: " + known + ")");
}

std::string injectionsText() {
    return parsed().text;
}

} // namespace sb
