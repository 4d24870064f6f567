#include "shading/Defines.h"

namespace sb {

std::string definesKey(const Defines& d) {
    std::string key;
    for (const auto& [name, value] : d) {
        if (!key.empty()) key += ",";
        key += name;
        if (!value.empty() && value != "1") key += "=" + value;
    }
    return key;
}

std::string fullDefinesKey(const Defines& d) {
    std::string key;
    for (const auto& [name, value] : d) key += name + "=" + (value.empty() ? "1" : value) + ";";
    return key;
}

} // namespace sb
