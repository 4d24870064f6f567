#include "techniques/ShadowMapProperties.h"

#include <utility>

namespace sb {

PropertyDesc ShadowMapProperties::resolution(std::string defaultValue, std::string description) {
    return integer(kResolution, std::move(defaultValue), 16, 8192, std::move(description));
}

PropertyDesc ShadowMapProperties::biasConstant(std::string description) {
    return real(kBiasConstant, "2", 0, 10000, std::move(description));
}

PropertyDesc ShadowMapProperties::biasSlope(std::string description) {
    return real(kBiasSlope, "2", 0, 64, std::move(description));
}

PropertyDesc ShadowMapProperties::pcf(std::string description) {
    return integer(kPcf, "1", 1, 9, std::move(description));
}

} // namespace sb
