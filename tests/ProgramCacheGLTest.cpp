// ProgramCache on a real context: caching, permutation keys, #include expansion and compile errors
// that name the fixture file and line (tests/shaders/).
#include <gtest/gtest.h>

#include <string>

#include "TestPaths.h"
#include "core/Error.h"
#include "gl/Context.h"
#include "gl/ProgramCache.h"
#include "gl/backends/BackendRegistry.h"
#include "shading/ShaderDump.h"

namespace sb {
namespace {

const std::string kShaderRoot = std::string(SB_SOURCE_DIR) + "/tests/shaders";

class ProgramCacheGLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { sContext = createContext(ContextOptions{}); }
    static void TearDownTestSuite() { sContext.reset(); }

    /// The sb::Error message of `get`, or "" when it did not throw.
    std::string errorOf(const ShaderSources& sources, const Defines& defines = {}) {
        try {
            mCache.get(sources, defines);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::Failure) << e.what();
            return e.what();
        }
        return "";
    }

    static std::unique_ptr<Context> sContext;
    ProgramCache mCache{kShaderRoot};
};
std::unique_ptr<Context> ProgramCacheGLTest::sContext;

const ShaderSources kFill{"fill.vert", "fill.frag", ""};

TEST(DefinesKeyTest, SortedCommaSeparatedWithOneOmitted) {
    EXPECT_EQ(definesKey({}), "");
    EXPECT_EQ(definesKey({{"SB_INSTANCED", ""}, {"PCF_SIZE", "3"}, {"A_FLAG", "1"}}),
              "A_FLAG,PCF_SIZE=3,SB_INSTANCED");
}

// A value past kLongDefineValue characters is keyed by its 64-bit FNV-1a (the hash below computed
// independently, with Python); up to that length it is written out.
TEST(DefinesKeyTest, LongValuesAreHashed) {
    EXPECT_EQ(definesKey({{"SB_LIGHT_COLORS", "vec4[4](vec4(1.0),vec4(0.0))"}}),
              "SB_LIGHT_COLORS=#a4300e2f19d5af15");
    const std::string longest(kLongDefineValue, 'x');
    EXPECT_EQ(definesKey({{"A", longest}}), "A=" + longest);
}

// A permutation past 255 characters (a file name's limit) names its dump folder by its head and its
// hash: two keys that share the head still get folders of their own.
TEST(ShaderDumpPath, LongPermutationFitsAFileName) {
    Defines a, b;
    for (int i = 0; i < 16; ++i) a["SB_A_RATHER_LONG_DEFINE_NAME_" + std::to_string(i)] = "";
    b = a;
    b["ZZ_LAST"] = "";
    const ShaderSources sources{"x.vert", "x.frag", ""};
    const auto folder = [&](const Defines& d) {
        const std::string p = ShaderDump::path("t", sources, d, ShaderStage::Fragment);
        const size_t end = p.rfind('/');
        return p.substr(p.rfind('/', end - 1) + 1, end - p.rfind('/', end - 1) - 1);
    };
    ASSERT_GT(definesKey(a).size(), 255u);
    EXPECT_EQ(folder(a).size(), 255u);
    EXPECT_EQ(folder(a).substr(0, 238), definesKey(a).substr(0, 238));
    EXPECT_EQ(folder(a).substr(238), "~" + hash64(definesKey(a)));
    EXPECT_NE(folder(a), folder(b));
    EXPECT_EQ(folder({{"PCF_SIZE", "3"}}), "PCF_SIZE=3");
}

TEST_F(ProgramCacheGLTest, SecondGetIsACacheHit) {
    const Program& first = mCache.get(kFill, {{"VIS_VALUE", "0.5"}});
    EXPECT_NE(first.id(), 0u);
    EXPECT_EQ(first.key(), "VIS_VALUE=0.5");
    EXPECT_EQ(mCache.compileCount(), 1u);
    const Program& again = mCache.get(kFill, {{"VIS_VALUE", "0.5"}});
    EXPECT_EQ(&again, &first);
    EXPECT_EQ(mCache.compileCount(), 1u);
    EXPECT_EQ(mCache.size(), 1u);
    // A different permutation is a different program.
    const Program& other = mCache.get(kFill, {{"VIS_VALUE", "0.25"}});
    EXPECT_NE(&other, &first);
    EXPECT_EQ(mCache.compileCount(), 2u);
    mCache.clear();
    EXPECT_EQ(mCache.size(), 0u);
}

TEST_F(ProgramCacheGLTest, DefineInsertionOrderDoesNotMatter) {
    Defines ab, ba;
    ab.emplace("FILL_RED", "0.75");
    ab.emplace("VIS_VALUE", "0.5");
    ba.emplace("VIS_VALUE", "0.5");
    ba.emplace("FILL_RED", "0.75");
    const Program& p1 = mCache.get(kFill, ab);
    const Program& p2 = mCache.get(kFill, ba);
    EXPECT_EQ(&p1, &p2);
    EXPECT_EQ(mCache.compileCount(), 1u);
    EXPECT_EQ(p1.key(), "FILL_RED=0.75,VIS_VALUE=0.5");
    EXPECT_EQ(mCache.preprocess("fill.frag", ab, ShaderStage::Fragment),
              mCache.preprocess("fill.frag", ba, ShaderStage::Fragment));
}

TEST_F(ProgramCacheGLTest, UniformLocationsAreCached) {
    const Program& program = mCache.get(kFill, {});
    GLint scale = program.uniform("uScale");
    EXPECT_GE(scale, 0);
    EXPECT_EQ(program.uniform("uScale"), scale);
    EXPECT_EQ(program.uniform("uNotThere"), -1);
    EXPECT_EQ(program.uniform("uNotThere"), -1);
}

TEST_F(ProgramCacheGLTest, PreprocessExpandsIncludesWithLineDirectives) {
    std::string source =
        mCache.preprocess("fill.frag", {{"VIS_VALUE", "0.5"}, {"B_FLAG", ""}}, ShaderStage::Fragment);
    // Header: version first, sorted defines, stage define.
    EXPECT_EQ(source.rfind("#version 450 compatibility\n#define B_FLAG 1\n#define VIS_VALUE 0.5\n"
                           "#define SB_FRAGMENT_SHADER 1\n#line 1 0\n",
                           0),
              0u)
        << source;
    EXPECT_EQ(source.find("#include"), std::string::npos) << source;
    // fill.frag (0) includes common/test_nested.glsl (1), which includes common/test_colors.glsl (2) twice:
    // the second include expands to nothing.
    EXPECT_NE(source.find("#line 1 1\n"), std::string::npos);
    EXPECT_NE(source.find("#line 1 2\n"), std::string::npos);
    EXPECT_EQ(source.find("#line 1 3\n"), std::string::npos);
    EXPECT_NE(source.find("vec4 testColor()"), std::string::npos);
    EXPECT_EQ(source.find("vec4 testColor()"), source.rfind("vec4 testColor()"));
    // Back in fill.frag after its include on line 2: the next line is line 3 of source string 0.
    EXPECT_NE(source.find("#line 3 0\n#ifndef VIS_VALUE"), std::string::npos) << source;
}

TEST_F(ProgramCacheGLTest, SyntaxErrorNamesFixtureFileAndLine) {
    std::string message = errorOf({"fill.vert", "errors/syntax_error.frag", ""}, {{"VIS_VALUE", "0.5"}});
    EXPECT_NE(message.find("errors/syntax_error.frag:7:"), std::string::npos) << message;
    EXPECT_NE(message.find("fragment shader 'errors/syntax_error.frag'"), std::string::npos) << message;
    EXPECT_NE(message.find("error"), std::string::npos) << message; // the driver's own text is kept
    EXPECT_EQ(message.find("0:7("), std::string::npos) << "unmapped driver location in: " << message;
    EXPECT_EQ(mCache.size(), 0u);
}

TEST_F(ProgramCacheGLTest, ErrorInIncludedFileNamesThatFile) {
    std::string message = errorOf({"fill.vert", "errors/include_error.frag", ""});
    EXPECT_NE(message.find("common/test_broken.glsl:4:"), std::string::npos) << message;
    EXPECT_NE(message.find("'errors/include_error.frag'"), std::string::npos) << message;
}

TEST_F(ProgramCacheGLTest, MissingFilesAreNamed) {
    std::string missingMain = errorOf({"fill.vert", "no_such_file.frag", ""});
    EXPECT_NE(missingMain.find("'no_such_file.frag' not found"), std::string::npos) << missingMain;
    try {
        mCache.get({"fill.vert", "errors/missing_include.frag", ""}, {});
        FAIL() << "missing include accepted";
    } catch (const Error& e) {
        std::string message = e.what();
        EXPECT_NE(
            message.find("errors/missing_include.frag:3: shader file 'common/does_not_exist.glsl' not found"),
            std::string::npos)
            << message;
    }
}

TEST_F(ProgramCacheGLTest, LinkErrorNamesTheFiles) {
    std::string message = errorOf({"fill.vert", "errors/link_error.frag", ""});
    EXPECT_NE(message.find("cannot link program"), std::string::npos) << message;
    EXPECT_NE(message.find("errors/link_error.frag"), std::string::npos) << message;
}

TEST_F(ProgramCacheGLTest, InvalidDefineNameIsRefused) {
    try {
        mCache.get(kFill, {{"NOT AN IDENTIFIER", "1"}});
        FAIL() << "bad define accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'NOT AN IDENTIFIER'"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace sb
