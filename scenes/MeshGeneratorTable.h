#pragma once
// The scene files' mesh generators ("generator": "sphere" ...), in one table (MeshGeneratorTable.cpp):
// each row names a generator, its tessellation (default, minimum, whether --tess and --tess-factor
// apply), the parameters it takes besides the keys every mesh has, and how it builds its mesh from
// them. SceneLoader's checks and errors ("expected one of sphere, box, ...") come from the table, so
// adding a generator is one MeshGenerators function and one row.
#include <string>
#include <string_view>
#include <vector>

#include "core/JsonReader.h"
#include "scenes/Mesh.h"

namespace sb {

struct MeshGeneratorEntry {
    const char* name;
    int defaultTessellation;
    int minimumTessellation;
    /// --tess replaces and --tess-factor scales the tessellation (the vertex-load knobs); false for the
    /// ground plane, whose grid is not a load anyone studies.
    bool followsTessellationOptions;
    std::vector<std::string_view> parameters; ///< keys of its own ("radius", "half_extent" ...)
    /// Builds the mesh from the mesh's JSON object (parameters already checked against the list) at
    /// tessellation `tess`. Throws sb::Error naming the parameter at fault.
    Mesh (*build)(const JsonReader& mesh, int tess);
};

class MeshGeneratorTable {
public:
    /// The keys every generated mesh may have, before its generator's own.
    static const std::vector<std::string_view>& commonKeys();
    /// Every generator, in the order errors list them.
    static const std::vector<MeshGeneratorEntry>& entries();
    /// The generator called `name`, or nullptr.
    static const MeshGeneratorEntry* find(const std::string& name);
    /// "sphere, box, cylinder, plane, aircraft, teapot, lantern".
    static std::string names();
};

} // namespace sb
