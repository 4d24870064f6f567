#include "techniques/ContactShadows.h"

#include <utility>

#include "techniques/ViewDepth.h"

namespace sb {

std::vector<PropertyDesc> ContactShadows::properties() {
    return {
        flag(kContact, "false",
             "screen-space contact shadows: a short march towards the light through the view's depth "
             "closes the light the map's bias lets in under a caster's foot"),
        real(kLength, "0.25", 0.001, 100, "contact: how far the march goes towards the light (world units)"),
        integer(kSteps, "8", 1, 64, "contact: points of the march along contact_length"),
    };
}

bool ContactShadows::enabled(const PropertySet& p) {
    return p.getBool(kContact);
}

void ContactShadows::addDefines(const PropertySet& p, Defines& defines) {
    if (!enabled(p)) return;
    defines["SB_CONTACT_SHADOWS"] = "1";
}

glm::vec4 ContactShadows::block(const PropertySet& p) {
    return {float(p.getFloat(kLength)), float(p.getInt(kSteps)), 0.0f, 0.0f};
}

std::vector<std::string> ContactShadows::passes(const PropertySet& p, std::vector<std::string> passes) {
    if (!enabled(p)) return passes;
    passes.insert(passes.begin(), kPass);
    return passes;
}

TechniqueInfo ContactShadows::declare(TechniqueInfo info) {
    const std::vector<PropertyDesc> contact = properties();
    info.properties.insert(info.properties.end(), contact.begin(), contact.end());
    info.resources = [own = std::move(info.resources)](const PropertySet& p, const ResourceInputs& in) {
        ResourceEstimate e = own(p, in);
        if (!enabled(p)) return e;
        e.bytes += ViewDepth::bytes(in.width, in.height);
        e.how += " + " + ViewDepth::describe(in.width, in.height, "contact");
        return e;
    };
    return info;
}

} // namespace sb
