#pragma once
// The registry: one explicit table of every technique (docs/ARCHITECTURE.md, "The technique contract").
// Adding a technique is one line in TechniqueRegistry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "techniques/Technique.h"

namespace sb {

class TechniqueRegistry {
public:
    using Factory = std::function<std::unique_ptr<Technique>()>;
    struct Entry {
        const char* name;
        Factory create;
    };
    static const std::vector<Entry>& entries();
    static std::vector<std::string> names();
    /// Throws sb::Error "unknown technique 'x' (known: none, shadowmap)".
    static std::unique_ptr<Technique> create(const std::string& name);
    /// Creates the technique and applies the spec's properties ("shadowmap:resolution=2048").
    static std::unique_ptr<Technique> create(const TechniqueSpec& spec);
};

} // namespace sb
