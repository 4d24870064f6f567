#include "core/JsonReader.h"
#include "core/Strings.h"

#include <cmath>

#include "core/Error.h"

namespace sb {

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
        JsonReader(item.value(), mSource, mPath + "/" + item.key())
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
    return float(mValue->get<double>());
}

float JsonReader::nonNegativeNumber() const {
    if (!mValue->is_number() || !(mValue->get<double>() >= 0.0)) fail("a number >= 0");
    return float(mValue->get<double>());
}

float JsonReader::numberIn(double lo, double hi, const char* what) const {
    if (!mValue->is_number()) fail(what);
    const double v = mValue->get<double>();
    if (!(v >= lo && v <= hi)) fail(what);
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
        v[i] = (*mValue)[size_t(i)].get<float>();
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
    std::string text = mValue->dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
}

void JsonReader::fail(const std::string& expected) const {
    error("expected " + expected + ", got " + describeValue());
}

void JsonReader::error(const std::string& message) const {
    throw Error(mSource + ": " + path() + ": " + message);
}

} // namespace sb
