#include "techniques/PropertySet.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>

#include "core/Error.h"
#include "core/Strings.h"
#include "core/Suggestion.h"

namespace sb {

namespace {

// ':' separates knobs and '=' separates name from value in a technique spec, so neither may appear in
// a canonical value; otherwise toString() would not parse back.
constexpr const char* kSpecSeparators = ":=";
constexpr char kPairSeparator = ':';
constexpr char kValueSeparator = '=';

// Whole-string parses: from_chars stops at the first character it cannot use, so "12abc" or "1.5" (for
// an int) leave ptr short of the end and are rejected rather than silently truncated.
std::optional<int64_t> parseInt(const std::string& s, std::errc& ec) {
    int64_t v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v, 10);
    ec = r.ec;
    if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
    return v;
}

std::optional<double> parseFloat(const std::string& s, std::errc& ec) {
    double v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::general);
    ec = r.ec;
    // from_chars accepts "inf" and "nan": a knob value that is not finite is never meaningful.
    if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// Shortest representation that parses back to the identical double (to_chars guarantees the round
// trip), so a CSV row re-run from its recorded properties uses bit-identical values. -0 is folded to
// 0 so the same setting never prints two ways.
std::string formatFloat(double v) {
    if (v == 0.0) v = 0.0;
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::optional<bool> parseBool(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (s == "true" || s == "1" || s == "on" || s == "yes") return true;
    if (s == "false" || s == "0" || s == "off" || s == "no") return false;
    return std::nullopt;
}

// Every rejection names owner, knob, the offending value and the accepted range, in one line.
[[noreturn]] void throwBadValue(const std::string& owner, const PropertyDesc& d, const std::string& value,
                                const std::string& problem) {
    throw Error(owner + ": property '" + d.name + "' = " + value + " " + problem + " " + d.rangeText());
}

std::string canonicalInt(const std::string& owner, const PropertyDesc& d, const std::string& value) {
    std::errc ec{};
    std::optional<int64_t> v = parseInt(value, ec);
    if (ec == std::errc::result_out_of_range) throwBadValue(owner, d, value, "is out of range");
    if (!v) throwBadValue(owner, d, value, "is not an integer; expected int in");
    // long double holds every int64 exactly on the platforms we build for, so bounds near 2^63 compare
    // correctly instead of rounding the value to a neighbouring double.
    if ((long double)*v < (long double)d.min || (long double)*v > (long double)d.max)
        throwBadValue(owner, d, value, "is out of range");
    return std::to_string(*v);
}

std::string canonicalFloat(const std::string& owner, const PropertyDesc& d, const std::string& value) {
    std::errc ec{};
    std::optional<double> v = parseFloat(value, ec);
    if (ec == std::errc::result_out_of_range) throwBadValue(owner, d, value, "is out of range");
    if (!v) throwBadValue(owner, d, value, "is not a finite number; expected float in");
    if (*v < d.min || *v > d.max) throwBadValue(owner, d, value, "is out of range");
    return formatFloat(*v);
}

// Parses and validates `value` against `d`; returns the canonical text form stored and printed.
std::string canonicalize(const std::string& owner, const PropertyDesc& d, const std::string& value) {
    if (value.empty())
        throw Error(owner + ": property '" + d.name + "' has an empty value; expected " +
                    propertyTypeName(d.type) +
                    (d.type == PropertyType::Int || d.type == PropertyType::Float ? " in " : " one of ") +
                    d.rangeText());
    switch (d.type) {
    case PropertyType::Int:
        return canonicalInt(owner, d, value);
    case PropertyType::Float:
        return canonicalFloat(owner, d, value);
    case PropertyType::Bool:
        if (std::optional<bool> b = parseBool(value)) return *b ? "true" : "false";
        throwBadValue(owner, d, value, "is not a bool (also accepted: 1/0, on/off, yes/no); expected one of");
    case PropertyType::Enum:
        if (std::find(d.choices.begin(), d.choices.end(), value) != d.choices.end()) return value;
        throwBadValue(owner, d, value, "is not one of");
    }
    throwBadValue(owner, d, value, "has an unknown property type; range");
}

// Declarations are code, not user input, but a broken one would make every row of a technique
// unreproducible, so it fails loudly at construction (ExitCode::Failure: a bug, not a bad argument).
void validateDescs(const std::string& owner, const std::vector<PropertyDesc>& descs) {
    for (size_t i = 0; i < descs.size(); ++i) {
        const PropertyDesc& d = descs[i];
        auto fail = [&](const std::string& why) {
            throw Error(owner + ": property declaration '" + d.name + "' " + why, ExitCode::Failure);
        };
        if (d.name.empty() || d.name.find_first_of(kSpecSeparators) != std::string::npos)
            fail("needs a non-empty name without ':' or '='");
        for (size_t j = 0; j < i; ++j)
            if (descs[j].name == d.name) fail("is declared twice");
        if (d.type == PropertyType::Enum && d.choices.empty()) fail("is an enum without choices");
        for (const std::string& c : d.choices)
            if (c.empty() || c.find_first_of(kSpecSeparators) != std::string::npos)
                fail("has a choice that is empty or contains ':' or '='");
        if ((d.type == PropertyType::Int || d.type == PropertyType::Float) && !(d.min <= d.max))
            fail("has an empty range " + d.rangeText());
    }
}

} // namespace

PropertySet::PropertySet(std::string owner, std::vector<PropertyDesc> descs)
    : mOwner(std::move(owner)), mDescs(std::move(descs)) {
    validateDescs(mOwner, mDescs);
    // Defaults go through the same validation as user values, so a default outside its own range is
    // caught here and "2.0" is stored as the canonical "2".
    mValues.reserve(mDescs.size());
    for (const PropertyDesc& d : mDescs) mValues.push_back(canonicalize(mOwner, d, d.defaultValue));
}

void PropertySet::set(const std::string& name, const std::string& value) {
    size_t i = indexOf(name);
    mValues[i] = canonicalize(mOwner, mDescs[i], value); // validate first: a failed set changes nothing
}

// Pairs are applied left to right, so a knob given twice ("pcf=3:pcf=5") takes the last value, like a
// repeated command-line option. A failing pair leaves the earlier pairs applied; callers treat the
// error as fatal, so a partial state is never used.
void PropertySet::apply(const std::vector<std::pair<std::string, std::string>>& kv) {
    for (const auto& [name, value] : kv) set(name, value);
}

namespace {
// Typed getters on the wrong type are programming errors in a technique, not bad input.
void checkType(const std::string& owner, const PropertyDesc& d, PropertyType wanted) {
    if (d.type != wanted)
        throw Error(owner + ": property '" + d.name + "' is " + propertyTypeName(d.type) + ", not " +
                        propertyTypeName(wanted),
                    ExitCode::Failure);
}
} // namespace

int64_t PropertySet::getInt(const std::string& name) const {
    size_t i = indexOf(name);
    checkType(mOwner, mDescs[i], PropertyType::Int);
    std::errc ec{};
    return *parseInt(mValues[i], ec); // canonical text always parses
}

double PropertySet::getFloat(const std::string& name) const {
    size_t i = indexOf(name);
    checkType(mOwner, mDescs[i], PropertyType::Float);
    std::errc ec{};
    return *parseFloat(mValues[i], ec);
}

bool PropertySet::getBool(const std::string& name) const {
    size_t i = indexOf(name);
    checkType(mOwner, mDescs[i], PropertyType::Bool);
    return mValues[i] == "true";
}

const std::string& PropertySet::getEnum(const std::string& name) const {
    size_t i = indexOf(name);
    checkType(mOwner, mDescs[i], PropertyType::Enum);
    return mValues[i];
}

const std::string& PropertySet::getText(const std::string& name) const {
    return mValues[indexOf(name)];
}

std::string PropertySet::toString() const {
    std::string out;
    for (size_t i = 0; i < mDescs.size(); ++i)
        out += (i ? std::string(1, kPairSeparator) : std::string()) + mDescs[i].name + kValueSeparator +
               mValues[i];
    return out;
}

size_t PropertySet::indexOf(const std::string& name) const {
    for (size_t i = 0; i < mDescs.size(); ++i)
        if (mDescs[i].name == name) return i;
    std::vector<std::string> names;
    for (const PropertyDesc& d : mDescs) names.push_back(d.name);
    const std::string known = names.empty() ? "none" : join(names, ", ");
    throw Error(mOwner + ": unknown property '" + name + "'" + Suggestion::didYouMean(name, names) +
                " (known: " + known + ")");
}

namespace {
[[noreturn]] void throwBadSpec(const std::string& text, const std::string& why) {
    throw Error("technique spec '" + text + "': " + why + " (expected name[:property=value...])");
}

// One "name=value" piece. Exactly one '=' is accepted: no canonical value contains '=' (see
// kSpecSeparators), so "a=b=c" can only be a typo and is rejected here instead of being reported later
// as a strange value.
std::pair<std::string, std::string> parsePair(const std::string& text, const std::string& piece) {
    if (piece.empty()) throwBadSpec(text, "empty property (two ':' in a row or a trailing ':')");
    size_t eq = piece.find(kValueSeparator);
    if (eq == std::string::npos) throwBadSpec(text, "property '" + piece + "' has no '=value'");
    if (eq == 0) throwBadSpec(text, "'" + piece + "' has an empty property name");
    if (piece.find(kValueSeparator, eq + 1) != std::string::npos)
        throwBadSpec(text, "property '" + piece + "' has more than one '='");
    // An empty value ("pcf=") is passed on: PropertySet::set rejects it with the knob's range.
    return {piece.substr(0, eq), piece.substr(eq + 1)};
}
} // namespace

TechniqueSpec TechniqueSpec::parse(const std::string& text) {
    if (text.empty()) throwBadSpec(text, "empty technique spec");
    TechniqueSpec spec;
    size_t colon = text.find(kPairSeparator);
    spec.name = text.substr(0, colon);
    if (spec.name.empty()) throwBadSpec(text, "empty technique name");
    if (spec.name.find(kValueSeparator) != std::string::npos)
        throwBadSpec(text, "technique name '" + spec.name + "' contains '='");
    while (colon != std::string::npos) {
        size_t next = text.find(kPairSeparator, colon + 1);
        std::string piece =
            text.substr(colon + 1, next == std::string::npos ? std::string::npos : next - colon - 1);
        spec.properties.push_back(parsePair(text, piece));
        colon = next;
    }
    return spec;
}

std::string TechniqueSpec::toString() const {
    std::string out = name;
    for (const auto& [k, v] : properties) out += kPairSeparator + k + kValueSeparator + v;
    return out;
}

} // namespace sb
