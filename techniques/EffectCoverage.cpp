#include "techniques/EffectCoverage.h"

namespace sb {

EffectCoverage EffectCoverage::of(EffectMask requested, EffectMask produced) {
    EffectCoverage c;
    c.requested = requested;
    c.produced = produced;
    c.delivered = requested & produced;
    c.missing = requested & ~produced;
    return c;
}

std::string EffectCoverage::shortfall(const std::string& technique, const std::string& scene) const {
    if (missing == 0) return "";
    return technique + " cannot produce " + effectMaskToString(missing) + ", which scene " + scene +
           " asks for";
}

} // namespace sb
