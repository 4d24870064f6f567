#include "bench/lib/gate/WorkColumns.h"

namespace sb {

namespace {

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// The census counts by their name's ending (load_<count> and work_<pass>_<count> alike). The clipper's
/// primitives come before the submitted ones: "_clipped_primitives" also ends in "_primitives".
WorkClass censusClass(const std::string& column) {
    for (const char* driver : {"_clipped_primitives", "_vertices", "_fragments"})
        if (endsWith(column, driver)) return WorkClass::Driver;
    // The remaining census counts (gl_calls, draws, triangles, primitives) are the application's; a
    // count added later without a class here is held exactly too, the stricter reading.
    return WorkClass::Application;
}

} // namespace

WorkClass WorkColumns::classOf(const std::string& column) {
    if (column.find("per_second") != std::string::npos) return WorkClass::None;
    if (startsWith(column, "counter_"))
        return endsWith(column, "_ms") ? WorkClass::None : WorkClass::Application;
    // load_vertices is "_vertices" with the prefix's underscore: match the name with a leading '_'.
    if (startsWith(column, "load_") || startsWith(column, "work_")) return censusClass("_" + column);
    return WorkClass::None;
}

const char* WorkColumns::name(WorkClass c) {
    switch (c) {
    case WorkClass::Application:
        return "application";
    case WorkClass::Driver:
        return "driver";
    case WorkClass::None:
        break;
    }
    return "";
}

} // namespace sb
