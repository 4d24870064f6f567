#include "techniques/Property.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <utility>

#include "core/NameTable.h"

namespace sb {

namespace {

// Range bounds are printed the way a user would type them back: Int bounds in plain fixed notation
// ("8192", never "8.192e+03"), Float bounds in the shortest form that parses back to the same double
// (the same form PropertySet stores as canonical text), so "[0, 0.1]" means exactly what it says.
std::string formatBound(double v, PropertyType type) {
    char buf[64];
    std::to_chars_result r = type == PropertyType::Int
                                 ? std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed)
                                 : std::to_chars(buf, buf + sizeof buf, v);
    if (r.ec != std::errc()) return "?"; // cannot happen for 64 bytes; keeps the error path total
    return std::string(buf, r.ptr);
}

constexpr Named<PropertyType> kPropertyTypeNames[] = {
    {PropertyType::Int, "int"},
    {PropertyType::Float, "float"},
    {PropertyType::Bool, "bool"},
    {PropertyType::Enum, "enum"},
};
constexpr NameTable kPropertyTypes{kPropertyTypeNames};

std::string joinChoices(const std::vector<std::string>& choices) {
    std::string out = "{";
    for (size_t i = 0; i < choices.size(); ++i) out += (i ? ", " : "") + choices[i];
    return out + "}";
}

} // namespace

const char* propertyTypeName(PropertyType t) {
    return kPropertyTypes.name(t, "unknown"); // "unknown" only for a cast of an out-of-range integer
}

std::string PropertyDesc::rangeText() const {
    switch (type) {
    case PropertyType::Int:
    case PropertyType::Float:
        return "[" + formatBound(min, type) + ", " + formatBound(max, type) + "]";
    case PropertyType::Bool:
        return "{true, false}";
    case PropertyType::Enum:
        return joinChoices(choices);
    }
    return "";
}

PropertyDesc integer(std::string name, std::string defaultValue, double min, double max,
                     std::string description) {
    return {std::move(name),       PropertyType::Int, std::move(defaultValue), min, max, {},
            std::move(description)};
}

PropertyDesc real(std::string name, std::string defaultValue, double min, double max,
                  std::string description) {
    return {std::move(name),       PropertyType::Float, std::move(defaultValue), min, max, {},
            std::move(description)};
}

PropertyDesc flag(std::string name, std::string defaultValue, std::string description) {
    return {std::move(name), PropertyType::Bool, std::move(defaultValue), 0, 0, {}, std::move(description)};
}

PropertyDesc choice(std::string name, std::string defaultValue, std::vector<std::string> choices,
                    std::string description) {
    return {std::move(name),    PropertyType::Enum,    std::move(defaultValue), 0, 0,
            std::move(choices), std::move(description)};
}

} // namespace sb
