#pragma once
// Typed, path-aware access to a parsed JSON value for the scene loader: every failure throws sb::Error
// "<source>: <JSON pointer>: expected <what>, got <value>" (docs/ARCHITECTURE.md, "Errors and exit codes").
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace sb {

class JsonReader {
public:
    /// The deepest nesting of arrays and objects parse accepts. Real scene files nest about 5 deep; the
    /// bound keeps hostile files (200 KB of "[[[[...") from recursing through nlohmann's dump, copy and
    /// comparison code, which overflowed the stack.
    static constexpr int kMaxDepth = 64;
    /// Parses `text` (// and /* */ comments allowed). Every failure is sb::Error (bad input) naming
    /// `source`, the line and column, and why: a syntax error, nesting deeper than kMaxDepth, or a
    /// number beyond double range (1e400). The message is one line of bounded length.
    static nlohmann::json parse(const std::string& text, const std::string& source);
    /// `text` quoted for a one-line message: at most `maxChars` bytes of it (then "..."), control
    /// characters escaped, so a huge or multi-line name in a file cannot flood or split the message.
    static std::string excerpt(std::string_view text, size_t maxChars = 60);

    /// `value` must outlive the reader; `path` is a JSON pointer ("" for the document root).
    JsonReader(const nlohmann::json& value, std::string source, std::string path = "");

    const nlohmann::json& value() const { return *mValue; }
    /// The JSON pointer of this value, "/" for the root.
    std::string path() const { return mPath.empty() ? "/" : mPath; }
    const std::string& source() const { return mSource; }

    /// Requires an object whose keys are all in `allowed`; an unknown key (a typo) is an error that
    /// lists the valid ones.
    void requireObject(std::initializer_list<std::string_view> allowed) const;
    void requireObject(std::span<const std::string_view> allowed) const;
    bool has(const char* key) const;
    /// The member `key`; an error naming the key if it is missing.
    JsonReader operator[](const char* key) const;
    /// The elements of an array (`nonEmpty`: at least one).
    std::vector<JsonReader> elements(bool nonEmpty = false) const;

    std::string string() const;
    bool boolean() const;
    double number() const;
    /// The float getters below also require the number to be finite as a float (|x| <= FLT_MAX): a
    /// 1e308 would otherwise become +inf (strictly, undefined behaviour) and pass every later check.
    float positiveNumber() const;    ///< > 0
    float nonNegativeNumber() const; ///< >= 0
    /// A number in [lo, hi] (`what` describes it for the message, e.g. "an angle in (0, 90]").
    float numberIn(double lo, double hi, const char* what) const;
    /// An integer in [lo, hi]; `what` describes it ("a positive integer").
    int64_t integer(int64_t lo, int64_t hi, const char* what) const;
    glm::vec3 vec3() const;          ///< [x, y, z], each finite as a float
    glm::vec3 positiveVec3() const;  ///< [x, y, z], all > 0
    glm::vec3 unitDirection() const; ///< non-zero [x, y, z], normalised

    /// Throws "<source>: <path>: expected <expected>, got <value>".
    [[noreturn]] void fail(const std::string& expected) const;
    /// Throws "<source>: <path>: <message>".
    [[noreturn]] void error(const std::string& message) const;

private:
    /// The value for a message: at most about 60 characters, built without dumping (or recursing
    /// through) more of the value than that.
    std::string describeValue() const;

    const nlohmann::json* mValue;
    std::string mSource;
    std::string mPath;
};

} // namespace sb
