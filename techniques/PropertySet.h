#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "techniques/Property.h"

namespace sb {

/// Values for a list of PropertyDesc. Errors throw sb::Error(ExitCode::BadInput) naming the
/// technique, the knob and the range, e.g.
///   "shadowmap: property 'resolution' = 99999 is out of range [256, 8192]"
///   "shadowmap: unknown property 'resolutoin' (known: resolution, bias_constant, ...)"
class PropertySet {
public:
    PropertySet() = default;
    PropertySet(std::string owner, std::vector<PropertyDesc> descs); ///< values = defaults
    const std::vector<PropertyDesc>& descs() const { return mDescs; }

    /// Parses and validates `value` for `name` (Int: decimal integer; Float: finite number;
    /// Bool: true/false/1/0/on/off/yes/no; Enum: one of choices). Stores the canonical form.
    void set(const std::string& name, const std::string& value);
    /// Applies "k=v" pairs in order (as parsed from a technique spec).
    void apply(const std::vector<std::pair<std::string, std::string>>& kv);

    int64_t getInt(const std::string& name) const;
    double getFloat(const std::string& name) const;
    bool getBool(const std::string& name) const;
    const std::string& getEnum(const std::string& name) const;
    const std::string& getText(const std::string& name) const; ///< canonical text of any type

    /// "resolution=2048:bias_constant=2:pcf=3" in declaration order (all knobs, defaults included).
    std::string toString() const;

private:
    size_t indexOf(const std::string& name) const; ///< throws on unknown
    std::string mOwner;
    std::vector<PropertyDesc> mDescs;
    std::vector<std::string> mValues; ///< canonical text, parallel to mDescs
};

/// A parsed `-t` argument: "shadowmap:resolution=2048:pcf=3" -> {"shadowmap", {{"resolution","2048"},
/// {"pcf","3"}}}. Throws sb::Error for "shadowmap:resolution" (missing '=') or an empty name.
struct TechniqueSpec {
    std::string name;
    std::vector<std::pair<std::string, std::string>> properties;
    static TechniqueSpec parse(const std::string& text);
    /// The text parse() reads back: "name:k=v:k=v" (just "name" without properties).
    std::string toString() const;
};

} // namespace sb
