#include "shading/GlslLiteral.h"

#include <charconv>

namespace sb {

std::string glslFloat(float v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::string text(buf, r.ptr);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

} // namespace sb
