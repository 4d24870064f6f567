// Technique properties (docs/ARCHITECTURE.md, "The technique contract"): typed parsing, ranges, canonical
// round trip, and error messages that name the owner, the knob, the value and the range. Values are compared
// exactly: the round trip promises bit-identical doubles, so no tolerance is allowed.
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "techniques/PropertySet.h"

using namespace sb;

namespace {

const char* const kOwner = "demo";

PropertySet makeSet() {
    return PropertySet(kOwner,
                       {
                           {"resolution", PropertyType::Int, "2048", 16, 8192, {}, "texels"},
                           {"bias", PropertyType::Float, "0.5", 0, 100, {}, "bias"},
                           {"hw", PropertyType::Bool, "true", 0, 0, {}, "compare"},
                           {"mode", PropertyType::Enum, "zfail", 0, 0, {"zfail", "zpass", "auto"}, "mode"},
                           {"offset", PropertyType::Float, "-2.0", -10, 10, {}, "signed"},
                       });
}

/// The message of the error set(k, v) throws; fails the test when it does not throw.
std::string errorOf(PropertySet& p, const std::string& k, const std::string& v) {
    try {
        p.set(k, v);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "set(" << k << ", '" << v << "') was accepted";
    return "";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(PropertySetTest, TypeNamesAndRangeTexts) {
    EXPECT_STREQ(propertyTypeName(PropertyType::Int), "int");
    EXPECT_STREQ(propertyTypeName(PropertyType::Float), "float");
    EXPECT_STREQ(propertyTypeName(PropertyType::Bool), "bool");
    EXPECT_STREQ(propertyTypeName(PropertyType::Enum), "enum");
    PropertySet set = makeSet();
    const auto& d = set.descs();
    EXPECT_EQ(d[0].rangeText(), "[16, 8192]");
    EXPECT_EQ(d[1].rangeText(), "[0, 100]");
    EXPECT_EQ(d[2].rangeText(), "{true, false}");
    EXPECT_EQ(d[3].rangeText(), "{zfail, zpass, auto}");
    EXPECT_EQ(d[4].rangeText(), "[-10, 10]");
    // Int bounds print in plain digits, Float bounds in their shortest round-trip form.
    EXPECT_EQ((PropertyDesc{"n", PropertyType::Int, "1", 0, 1000000, {}, ""}.rangeText()), "[0, 1000000]");
    EXPECT_EQ((PropertyDesc{"f", PropertyType::Float, "0.1", 0.1, 1e-7 + 1, {}, ""}.rangeText()),
              "[0.1, 1.0000001]");
}

TEST(PropertySetTest, DefaultsAreCanonicalAndTyped) {
    PropertySet p = makeSet();
    EXPECT_EQ(p.getInt("resolution"), 2048);
    EXPECT_EQ(p.getFloat("bias"), 0.5);
    EXPECT_TRUE(p.getBool("hw"));
    EXPECT_EQ(p.getEnum("mode"), "zfail");
    EXPECT_EQ(p.getFloat("offset"), -2.0);
    EXPECT_EQ(p.getText("offset"), "-2"); // "-2.0" as declared, stored canonically
    EXPECT_EQ(p.toString(), "resolution=2048:bias=0.5:hw=true:mode=zfail:offset=-2");
}

TEST(PropertySetTest, SetAcceptsEachTypesSpellingsAndStoresCanonicalText) {
    PropertySet p = makeSet();
    p.set("resolution", "4096");
    p.set("bias", "1e-7");
    p.set("hw", "off");
    p.set("mode", "auto");
    p.set("offset", "-0");
    EXPECT_EQ(p.getInt("resolution"), 4096);
    EXPECT_EQ(p.getFloat("bias"), 1e-7);
    EXPECT_FALSE(p.getBool("hw"));
    EXPECT_EQ(p.getEnum("mode"), "auto");
    EXPECT_EQ(p.getText("hw"), "false");
    EXPECT_EQ(p.getText("offset"), "0"); // -0 folds to 0: one setting, one spelling
    const struct {
        const char* text;
        bool value;
    } kBools[] = {{"true", true},   {"1", true},  {"on", true},   {"yes", true}, {"TRUE", true},
                  {"false", false}, {"0", false}, {"off", false}, {"no", false}, {"No", false}};
    for (const auto& b : kBools) {
        p.set("hw", b.text);
        EXPECT_EQ(p.getBool("hw"), b.value) << b.text;
        EXPECT_EQ(p.getText("hw"), b.value ? "true" : "false") << b.text;
    }
    p.set("resolution", "16"); // both ends of the range are inclusive
    p.set("resolution", "8192");
    p.set("bias", "100");
    EXPECT_EQ(p.getFloat("bias"), 100.0);
}

TEST(PropertySetTest, CanonicalStringRoundTripsBitIdentically) {
    // 0.1, 1/3 and 1e-7 are not exact in binary; the canonical text must parse back to the same double.
    const double kValues[] = {0.1,  1e-7, 1.0 / 3.0, 2.0 / 3.0 * 99.0, 5e-324, std::nextafter(0.5, 1.0),
                              100.0};
    for (double v : kValues) {
        PropertySet a = makeSet();
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", v); // 17 significant digits identify any double
        a.set("bias", text);
        ASSERT_EQ(a.getFloat("bias"), v) << text;
        PropertySet b = makeSet();
        b.apply(TechniqueSpec::parse(std::string(kOwner) + ":" + a.toString()).properties);
        EXPECT_EQ(b.getFloat("bias"), v) << a.toString();
        EXPECT_EQ(b.toString(), a.toString());
    }
    PropertySet a = makeSet();
    a.set("bias", "0.1");
    EXPECT_EQ(a.getText("bias"), "0.1"); // shortest form, not 0.10000000000000001
    a.set("bias", "1e-7");
    EXPECT_EQ(a.getText("bias"), "1e-07");
}

TEST(PropertySetTest, EveryRejectionNamesOwnerKnobValueAndRange) {
    const struct {
        const char* knob;
        const char* value;
        const char* range;
    } kBad[] = {
        {"resolution", "99999", "[16, 8192]"},                // above range
        {"resolution", "15", "[16, 8192]"},                   // below range
        {"resolution", "1.5", "[16, 8192]"},                  // not an integer
        {"resolution", "12abc", "[16, 8192]"},                // trailing garbage
        {"resolution", " 12", "[16, 8192]"},                  // leading space
        {"resolution", "99999999999999999999", "[16, 8192]"}, // int64 overflow
        {"bias", "nan", "[0, 100]"},                          // not finite
        {"bias", "inf", "[0, 100]"},
        {"bias", "1e999", "[0, 100]"}, // overflows double
        {"bias", "-1", "[0, 100]"},
        {"bias", "0.5x", "[0, 100]"},
        {"bias", "0x10", "[0, 100]"}, // no hex floats
        {"hw", "maybe", "{true, false}"},
        {"hw", "2", "{true, false}"},
        {"mode", "sometimes", "{zfail, zpass, auto}"},
        {"mode", "ZFAIL", "{zfail, zpass, auto}"}, // enum choices are exact
    };
    for (const auto& c : kBad) {
        PropertySet p = makeSet();
        std::string e = errorOf(p, c.knob, c.value);
        EXPECT_TRUE(contains(e, kOwner)) << e;
        EXPECT_TRUE(contains(e, "'" + std::string(c.knob) + "'")) << e;
        EXPECT_TRUE(contains(e, c.value)) << e;
        EXPECT_TRUE(contains(e, c.range)) << e;
    }
    PropertySet p = makeSet();
    EXPECT_EQ(errorOf(p, "resolution", "99999"),
              "demo: property 'resolution' = 99999 is out of range [16, 8192]");
}

TEST(PropertySetTest, EmptyValueNamesKnobAndRange) {
    PropertySet p = makeSet();
    for (const PropertyDesc& d : p.descs()) {
        std::string e = errorOf(p, d.name, "");
        EXPECT_TRUE(contains(e, "'" + d.name + "'")) << e;
        EXPECT_TRUE(contains(e, "empty value")) << e;
        EXPECT_TRUE(contains(e, d.rangeText())) << e;
    }
}

TEST(PropertySetTest, FailedSetKeepsTheOldValue) {
    PropertySet p = makeSet();
    p.set("resolution", "512");
    errorOf(p, "resolution", "99999");
    EXPECT_EQ(p.getInt("resolution"), 512);
}

TEST(PropertySetTest, UnknownPropertyListsKnownOnes) {
    PropertySet p = makeSet();
    std::string e = errorOf(p, "resolutoin", "2048");
    EXPECT_EQ(e, "demo: unknown property 'resolutoin' (did you mean resolution?) (known: resolution, bias, "
                 "hw, mode, offset)");
    EXPECT_THROW(p.getInt("nope"), Error);
    PropertySet none("none", {});
    EXPECT_EQ(errorOf(none, "x", "1"), "none: unknown property 'x' (known: none)");
    EXPECT_EQ(none.toString(), "");
}

TEST(PropertySetTest, WrongTypedGetterIsAProgrammingError) {
    PropertySet p = makeSet();
    try {
        p.getInt("bias");
        FAIL() << "no throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Failure);
        EXPECT_TRUE(contains(e.what(), "'bias' is float, not int")) << e.what();
    }
    EXPECT_EQ(p.getText("bias"), "0.5"); // getText serves every type
}

TEST(PropertySetTest, ApplyGoesInOrderAndLastValueWins) {
    PropertySet p = makeSet();
    p.apply(TechniqueSpec::parse("demo:resolution=256:mode=zpass:resolution=1024").properties);
    EXPECT_EQ(p.getInt("resolution"), 1024);
    EXPECT_EQ(p.getEnum("mode"), "zpass");
}

TEST(PropertySetTest, BadDeclarationsFailAtConstruction) {
    using V = std::vector<PropertyDesc>;
    const struct {
        const char* name;
        V descs;
    } kBad[] = {
        {"default out of range", V{{"r", PropertyType::Int, "1", 16, 8192, {}, ""}}},
        {"duplicate name",
         V{{"r", PropertyType::Int, "16", 16, 32, {}, ""}, {"r", PropertyType::Int, "16", 16, 32, {}, ""}}},
        {"name with ':'", V{{"a:b", PropertyType::Bool, "true", 0, 0, {}, ""}}},
        {"enum without choices", V{{"e", PropertyType::Enum, "x", 0, 0, {}, ""}}},
        {"choice with '='", V{{"e", PropertyType::Enum, "a=b", 0, 0, {"a=b"}, ""}}},
        {"empty range", V{{"f", PropertyType::Float, "1", 2, 1, {}, ""}}},
    };
    for (const auto& c : kBad) EXPECT_THROW(PropertySet("demo", c.descs), Error) << c.name;
}

TEST(PropertySetTest, TechniqueSpecParsing) {
    TechniqueSpec s = TechniqueSpec::parse("shadowmap");
    EXPECT_EQ(s.name, "shadowmap");
    EXPECT_TRUE(s.properties.empty());
    s = TechniqueSpec::parse("shadowmap:resolution=2048:pcf=3");
    EXPECT_EQ(s.name, "shadowmap");
    ASSERT_EQ(s.properties.size(), 2u);
    EXPECT_EQ(s.properties[0], (std::pair<std::string, std::string>{"resolution", "2048"}));
    EXPECT_EQ(s.properties[1], (std::pair<std::string, std::string>{"pcf", "3"}));
    // An empty value parses; PropertySet::set rejects it with the knob's range.
    s = TechniqueSpec::parse("shadowmap:pcf=");
    ASSERT_EQ(s.properties.size(), 1u);
    EXPECT_EQ(s.properties[0].second, "");
}

TEST(PropertySetTest, TechniqueSpecRejections) {
    const struct {
        const char* text;
        const char* why; ///< part of the message
    } kBad[] = {
        {"", "empty technique spec"},
        {":x=1", "empty technique name"},
        {"shadowmap:resolution", "'resolution' has no '=value'"},
        {"shadowmap:=3", "empty property name"},
        {"shadowmap:", "empty property"},
        {"shadowmap::pcf=3", "empty property"},
        {"shadowmap:pcf=3=4", "more than one '='"}, // '=' never occurs in a canonical value
        {"shadow=map", "contains '='"},
    };
    for (const auto& c : kBad) {
        try {
            TechniqueSpec::parse(c.text);
            ADD_FAILURE() << "accepted '" << c.text << "'";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput);
            EXPECT_TRUE(contains(e.what(), "'" + std::string(c.text) + "'")) << e.what(); // quotes the input
            EXPECT_TRUE(contains(e.what(), c.why)) << e.what();
        }
    }
}
} // namespace
