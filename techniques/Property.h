#pragma once
// Typed technique knobs (docs/ARCHITECTURE.md, "The technique contract"): a technique declares each knob with
// type, default and range; PropertySet holds the values, validates every set, and prints a canonical
// "name=value:name=value" string that parses back to the same values, so every CSV row can be re-run exactly
// with `-t technique:<that string>`.
#include <string>
#include <vector>

namespace sb {

enum class PropertyType { Int, Float, Bool, Enum };
const char* propertyTypeName(PropertyType t); ///< "int", "float", "bool", "enum"

struct PropertyDesc {
    std::string name; ///< lower_snake_case, unique within a technique
    PropertyType type = PropertyType::Int;
    std::string defaultValue; ///< canonical text form, e.g. "2048", "0.5", "true", "pcf"
    double min = 0.0;         ///< Int/Float: inclusive range
    double max = 0.0;
    std::vector<std::string> choices; ///< Enum: allowed values
    std::string description;          ///< one line for --list
    /// "[256, 8192]" / "{on, off}" / "{true, false}": the range text used in --list and errors.
    std::string rangeText() const;
};

// The makers a technique declares its knobs with, one call per knob: type, name, default (canonical
// text) and range on its first line, the description after them.
//   integer(kResolution, "2048", 16, 8192, "shadow map width and height (texels)"),
PropertyDesc integer(std::string name, std::string defaultValue, double min, double max,
                     std::string description);
PropertyDesc real(std::string name, std::string defaultValue, double min, double max,
                  std::string description);
PropertyDesc flag(std::string name, std::string defaultValue, std::string description);
PropertyDesc choice(std::string name, std::string defaultValue, std::vector<std::string> choices,
                    std::string description);

} // namespace sb
