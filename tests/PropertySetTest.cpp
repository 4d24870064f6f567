// Technique properties: typed parsing, ranges, canonical round trip, and the error messages that name
// the knob and its range (DESIGN.md section 4).
#include <gtest/gtest.h>

#include "scenes/Error.h"
#include "techniques/PropertySet.h"

using namespace sb;

namespace {

PropertySet makeSet() {
    return PropertySet("demo", {
                                   {"resolution", PropertyType::Int, "2048", 16, 8192, {}, "texels"},
                                   {"bias", PropertyType::Float, "0.5", 0, 100, {}, "bias"},
                                   {"hw", PropertyType::Bool, "true", 0, 0, {}, "compare"},
                                   {"mode", PropertyType::Enum, "zfail", 0, 0, {"zfail", "zpass", "auto"}, "mode"},
                               });
}

std::string errorOf(PropertySet& p, const std::string& k, const std::string& v) {
    try {
        p.set(k, v);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        return e.what();
    }
    return "";
}

TEST(PropertySetTest, DefaultsAndTypedGets) {
    PropertySet p = makeSet();
    EXPECT_EQ(p.getInt("resolution"), 2048);
    EXPECT_EQ(p.getFloat("bias"), 0.5);
    EXPECT_TRUE(p.getBool("hw"));
    EXPECT_EQ(p.getEnum("mode"), "zfail");
    EXPECT_EQ(p.toString(), "resolution=2048:bias=0.5:hw=true:mode=zfail");
}

TEST(PropertySetTest, SetAcceptsEachTypesSpellings) {
    PropertySet p = makeSet();
    p.set("resolution", "4096");
    p.set("bias", "1e-7");
    p.set("hw", "off");
    p.set("mode", "auto");
    EXPECT_EQ(p.getInt("resolution"), 4096);
    EXPECT_EQ(p.getFloat("bias"), 1e-7);
    EXPECT_FALSE(p.getBool("hw"));
    EXPECT_EQ(p.getEnum("mode"), "auto");
    EXPECT_EQ(p.getText("hw"), "false"); // canonical form
}

TEST(PropertySetTest, CanonicalStringRoundTripsExactly) {
    // 0.1 and 1/3 are not exact in binary: the canonical text must still parse back to the same double.
    PropertySet a = makeSet();
    a.set("bias", "0.1");
    a.set("resolution", "16");
    PropertySet b = makeSet();
    b.apply(TechniqueSpec::parse("demo:" + a.toString()).properties);
    EXPECT_EQ(b.getFloat("bias"), 0.1);
    EXPECT_EQ(b.toString(), a.toString());
    a.set("bias", std::to_string(1.0 / 3.0));
    PropertySet c = makeSet();
    c.apply(TechniqueSpec::parse("demo:" + a.toString()).properties);
    EXPECT_EQ(c.getFloat("bias"), a.getFloat("bias"));
}

TEST(PropertySetTest, ErrorsNameKnobValueAndRange) {
    PropertySet p = makeSet();
    std::string e = errorOf(p, "resolution", "99999");
    EXPECT_NE(e.find("resolution"), std::string::npos) << e;
    EXPECT_NE(e.find("[16, 8192]"), std::string::npos) << e;
    EXPECT_NE(e.find("99999"), std::string::npos) << e;
    e = errorOf(p, "resolution", "1.5");
    EXPECT_NE(e.find("resolution"), std::string::npos) << e;
    e = errorOf(p, "resolution", "12abc");
    EXPECT_NE(e.find("12abc"), std::string::npos) << e;
    e = errorOf(p, "bias", "nan");
    EXPECT_NE(e.find("bias"), std::string::npos) << e;
    e = errorOf(p, "bias", "-1");
    EXPECT_NE(e.find("[0, 100]"), std::string::npos) << e;
    e = errorOf(p, "hw", "maybe");
    EXPECT_NE(e.find("hw"), std::string::npos) << e;
    e = errorOf(p, "mode", "sometimes");
    EXPECT_NE(e.find("zpass"), std::string::npos) << e; // lists the choices
    e = errorOf(p, "resolutoin", "2048");
    EXPECT_NE(e.find("resolutoin"), std::string::npos) << e;
    EXPECT_NE(e.find("resolution"), std::string::npos) << e; // lists the known knobs
    e = errorOf(p, "bias", "");
    EXPECT_NE(e.find("bias"), std::string::npos) << e;
    // A failed set leaves the old value.
    EXPECT_EQ(p.getInt("resolution"), 2048);
}

TEST(PropertySetTest, TechniqueSpecParsing) {
    TechniqueSpec s = TechniqueSpec::parse("shadowmap");
    EXPECT_EQ(s.name, "shadowmap");
    EXPECT_TRUE(s.properties.empty());
    s = TechniqueSpec::parse("shadowmap:resolution=2048:pcf=3");
    ASSERT_EQ(s.properties.size(), 2u);
    EXPECT_EQ(s.properties[0], (std::pair<std::string, std::string>{"resolution", "2048"}));
    EXPECT_EQ(s.properties[1], (std::pair<std::string, std::string>{"pcf", "3"}));
    for (const char* bad : {"", ":x=1", "shadowmap:resolution", "shadowmap:=3"})
        EXPECT_THROW(TechniqueSpec::parse(bad), Error) << "accepted '" << bad << "'";
}
} // namespace
