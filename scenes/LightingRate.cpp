#include "scenes/LightingRate.h"

namespace sb {

const NameTable<Named<LightingRate>>& lightingRateNames() {
    static constexpr Named<LightingRate> kNames[] = {
        {LightingRate::Fragment, "fragment"},
        {LightingRate::Vertex, "vertex"},
    };
    static constexpr NameTable kTable{kNames};
    return kTable;
}

const char* lightingRateName(LightingRate rate) {
    return lightingRateNames().name(rate, "fragment");
}

std::optional<LightingRate> parseLightingRate(const std::string& text) {
    return lightingRateNames().parse(text);
}

} // namespace sb
