#include "bench/lib/options/DriverOption.h"

#include "core/DriverTable.h"

namespace sb {

void DriverOption::add(CLI::App& app, std::string& into) {
    std::string names;
    for (const std::string& n : DriverTable::names()) names += (names.empty() ? "" : ", ") + n;
    app.add_option("--driver", into,
                   "the GL and Vulkan driver build to load: " + names +
                       " (bash scripts/install-deps.sh driver), or a Mesa install prefix's path "
                       "(default: system)");
}

} // namespace sb
