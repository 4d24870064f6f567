#include "core/JsonReader.h"
#include "core/Strings.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/Error.h"

namespace sb {
namespace {

/// The longest excerpt of a value or of nlohmann's reason a message carries.
constexpr size_t kValueChars = 60;
constexpr size_t kReasonChars = 160;

/// `text` cut to `maxChars` bytes (then "..."), never inside a UTF-8 sequence.
std::string truncated(std::string_view text, size_t maxChars) {
    if (text.size() <= maxChars) return std::string(text);
    size_t cut = maxChars > 3 ? maxChars - 3 : 0;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    return std::string(text.substr(0, cut)) + "...";
}

/// Control characters (a newline inside a JSON string or key) escaped, so a message stays one line.
std::string escapeControls(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) {
            out += c;
            continue;
        }
        char code[8];
        std::snprintf(code, sizeof code, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
        out += code;
    }
    return out;
}

/// "<source>: invalid JSON at line L, column C: " for byte `offset` of `text` (lines and columns from 1).
std::string locate(const std::string& source, const std::string& text, size_t offset) {
    size_t line = 1, column = 1;
    for (size_t i = 0; i < offset && i < text.size(); ++i) {
        column = text[i] == '\n' ? 1 : column + 1;
        line += text[i] == '\n';
    }
    return source + ": invalid JSON at line " + std::to_string(line) + ", column " + std::to_string(column) +
           ": ";
}

bool numberChar(char c) {
    return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
}

/// What nlohmann's parser lets through or reports badly, found before it runs: nesting deeper than
/// kMaxDepth (the parser itself is iterative, but dump(), copies and comparisons of the result recurse
/// once per level), and numbers beyond double range (nlohmann throws out_of_range 406 without a
/// position). Strings and comments are skipped the way the parser reads them; anything else that is
/// malformed is left to the parser's own message.
void prescan(const std::string& text, const std::string& source) {
    int depth = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"') {
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
        } else if (c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*')) {
            const size_t end = text[i + 1] == '/' ? text.find('\n', i) : text.find("*/", i + 2);
            if (end == std::string::npos) return;
            i = text[i + 1] == '/' ? end : end + 1;
        } else if (c == '[' || c == '{') {
            if (++depth > JsonReader::kMaxDepth)
                throw Error(locate(source, text, i) + "arrays and objects nested deeper than " +
                            std::to_string(JsonReader::kMaxDepth) + " levels (a scene file needs about 5)");
        } else if (c == ']' || c == '}') {
            --depth;
        } else if ((c == '-' || (c >= '0' && c <= '9')) &&
                   (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
            size_t end = i;
            while (end < text.size() && numberChar(text[end])) ++end;
            const std::string token = text.substr(i, end - i);
            // strtod reads "1e400" as HUGE_VAL; an underflow (1e-400) is 0 or denormal, which nlohmann
            // accepts as well.
            if (std::isinf(std::strtod(token.c_str(), nullptr)))
                throw Error(locate(source, text, i) + "the number " + truncated(token, kValueChars) +
                            " is beyond the range of a double (about 1.8e308)");
            i = end - 1;
        }
    }
}

/// nlohmann's reason without its "[json.exception...] parse error at line L, column C: " prefix
/// (the line and column are given in front already) and cut short: it ends with the token read so
/// far, which for an unterminated string is the rest of the file.
std::string parseReason(const std::string& what) {
    const size_t column = what.find("column ");
    const size_t colon = column == std::string::npos ? std::string::npos : what.find(": ", column);
    const std::string_view reason =
        colon == std::string::npos ? std::string_view(what) : std::string_view(what).substr(colon + 2);
    return truncated(escapeControls(reason), kReasonChars);
}

/// Appends `v` as compact JSON (dump()'s format) to `out` until `out` is longer than `limit`, then
/// stops: a value of any size or depth costs about `limit` characters, and the recursion is at most
/// about `limit` deep because every level appends a bracket before it descends.
void render(const nlohmann::json& v, std::string& out, size_t limit) {
    if (out.size() > limit) return;
    const auto quote = [&](const std::string& s) {
        out += nlohmann::json(truncated(s, limit))
                   .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    };
    if (v.is_array()) {
        out += '[';
        for (size_t i = 0; i < v.size() && out.size() <= limit; ++i) {
            if (i) out += ',';
            render(v[i], out, limit);
        }
        out += ']';
    } else if (v.is_object()) {
        out += '{';
        bool first = true;
        for (auto it = v.begin(); it != v.end() && out.size() <= limit; ++it) {
            if (!first) out += ',';
            first = false;
            quote(it.key());
            out += ':';
            render(it.value(), out, limit);
        }
        out += '}';
    } else if (v.is_string()) {
        quote(v.get_ref<const std::string&>());
    } else {
        out += v.dump();
    }
}

/// A number that converts to a finite float.
bool fitsFloat(const nlohmann::json& v) {
    return v.is_number() && std::abs(v.get<double>()) <= double(FLT_MAX);
}

constexpr const char* kFloatRange = " within float range (|x| <= 3.4e38)";

} // namespace

nlohmann::json JsonReader::parse(const std::string& text, const std::string& source) {
    prescan(text, source);
    try {
        return nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is the 1-based index of the byte the parser stopped at.
        throw Error(locate(source, text, e.byte ? e.byte - 1 : 0) + parseReason(e.what()));
    } catch (const nlohmann::json::exception& e) {
        throw Error(source + ": invalid JSON: " + truncated(escapeControls(e.what()), kReasonChars));
    }
}

std::string JsonReader::excerpt(std::string_view text, size_t maxChars) {
    return "\"" + truncated(escapeControls(text), maxChars) + "\"";
}

JsonReader::JsonReader(const nlohmann::json& value, std::string source, std::string path)
    : mValue(&value), mSource(std::move(source)), mPath(std::move(path)) {}

void JsonReader::requireObject(std::initializer_list<std::string_view> allowed) const {
    requireObject(std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

void JsonReader::requireObject(std::span<const std::string_view> allowed) const {
    if (!mValue->is_object()) fail("an object");
    for (const auto& item : mValue->items()) {
        bool known = false;
        for (auto key : allowed) known = known || key == item.key();
        if (known) continue;
        std::string valid = join(allowed, ", ", [](std::string_view k) { return std::string(k); });
        // The key as written, cut short: a hostile file's key can be any length.
        JsonReader(item.value(), mSource, mPath + "/" + truncated(item.key(), kValueChars))
            .error("unknown key (valid keys: " + valid + ")");
    }
}

bool JsonReader::has(const char* key) const {
    return mValue->is_object() && mValue->contains(key);
}

JsonReader JsonReader::operator[](const char* key) const {
    if (!mValue->is_object()) fail("an object");
    const auto it = mValue->find(key);
    if (it == mValue->end()) error(std::string("missing required key \"") + key + "\"");
    return JsonReader(*it, mSource, mPath + "/" + key);
}

std::vector<JsonReader> JsonReader::elements(bool nonEmpty) const {
    if (!mValue->is_array() || (nonEmpty && mValue->empty()))
        fail(nonEmpty ? "a non-empty array" : "an array");
    std::vector<JsonReader> out;
    for (size_t i = 0; i < mValue->size(); ++i)
        out.emplace_back((*mValue)[i], mSource, mPath + "/" + std::to_string(i));
    return out;
}

std::string JsonReader::string() const {
    if (!mValue->is_string()) fail("a string");
    return mValue->get<std::string>();
}

bool JsonReader::boolean() const {
    if (!mValue->is_boolean()) fail("true or false");
    return mValue->get<bool>();
}

double JsonReader::number() const {
    if (!mValue->is_number()) fail("a number");
    return mValue->get<double>();
}

float JsonReader::positiveNumber() const {
    if (!mValue->is_number() || !(mValue->get<double>() > 0.0)) fail("a positive number");
    if (!fitsFloat(*mValue)) fail(std::string("a positive number") + kFloatRange);
    return float(mValue->get<double>());
}

float JsonReader::nonNegativeNumber() const {
    if (!mValue->is_number() || !(mValue->get<double>() >= 0.0)) fail("a number >= 0");
    if (!fitsFloat(*mValue)) fail(std::string("a number >= 0") + kFloatRange);
    return float(mValue->get<double>());
}

float JsonReader::numberIn(double lo, double hi, const char* what) const {
    if (!mValue->is_number()) fail(what);
    const double v = mValue->get<double>();
    if (!(v >= lo && v <= hi)) fail(what);
    if (!fitsFloat(*mValue)) fail(what + std::string(kFloatRange));
    return float(v);
}

int64_t JsonReader::integer(int64_t lo, int64_t hi, const char* what) const {
    // Unsigned values beyond int64 and fractional numbers are both "not an integer in range".
    if (mValue->is_number_unsigned() && mValue->get<uint64_t>() > uint64_t(INT64_MAX)) fail(what);
    if (!mValue->is_number_integer()) fail(what);
    const int64_t v = mValue->get<int64_t>();
    if (v < lo || v > hi) fail(what);
    return v;
}

glm::vec3 JsonReader::vec3() const {
    if (!mValue->is_array() || mValue->size() != 3) fail("an array of 3 numbers");
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
        if (!(*mValue)[size_t(i)].is_number()) fail("an array of 3 numbers");
        if (!fitsFloat((*mValue)[size_t(i)])) fail(std::string("an array of 3 numbers") + kFloatRange);
        v[i] = float((*mValue)[size_t(i)].get<double>());
    }
    return v;
}

glm::vec3 JsonReader::positiveVec3() const {
    const glm::vec3 v = vec3();
    if (!(v.x > 0 && v.y > 0 && v.z > 0)) fail("an array of 3 positive numbers");
    return v;
}

glm::vec3 JsonReader::unitDirection() const {
    const glm::vec3 v = vec3();
    const float len = glm::length(v);
    if (!(len > 1e-12f) || !std::isfinite(len)) fail("a non-zero direction [x, y, z]");
    return v / len;
}

std::string JsonReader::describeValue() const {
    std::string text;
    render(*mValue, text, kValueChars);
    return truncated(text, kValueChars);
}

void JsonReader::fail(const std::string& expected) const {
    error("expected " + expected + ", got " + describeValue());
}

void JsonReader::error(const std::string& message) const {
    throw Error(escapeControls(mSource + ": " + path() + ": " + message));
}

} // namespace sb
