#include "shading/Defines.h"

#include <cstdint>
#include <cstdio>

namespace sb {

std::string hash64(const std::string& text) {
    uint64_t h = 14695981039346656037ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::string definesKey(const Defines& d) {
    std::string key;
    for (const auto& [name, value] : d) {
        if (!key.empty()) key += ",";
        key += name;
        if (value.empty() || value == "1") continue;
        key += "=" + (value.size() > kLongDefineValue ? "#" + hash64(value) : value);
    }
    return key;
}

std::string fullDefinesKey(const Defines& d) {
    std::string key;
    for (const auto& [name, value] : d) key += name + "=" + (value.empty() ? "1" : value) + ";";
    return key;
}

} // namespace sb
