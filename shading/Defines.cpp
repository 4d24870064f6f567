#include "shading/Defines.h"

#include "core/Fnv1a.h"

namespace sb {

std::string hash64(const std::string& text) {
    Fnv1a h;
    h.bytes(text.data(), text.size());
    return h.hex();
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
