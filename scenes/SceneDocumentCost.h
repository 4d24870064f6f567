#pragma once
// What a scene file's JSON text will cost in memory once parsed, measured without parsing it into a
// document: one pass of nlohmann's SAX parser over the text counts every value and what the document
// would allocate for it, and the elements of the top-level "instances" array. The scene loader refuses
// a document whose cost exceeds --max-memory-gib before the document exists (a 10^7-element instances
// array took 8.8 GB before the limit was checked).
#include <cstdint>
#include <string>

namespace sb {

class SceneDocumentCost {
public:
    /// Bytes the parsed document (nlohmann::json on libstdc++ and glibc malloc) allocates, as an upper
    /// estimate: every value's 16 B, an object's map and one tree node per member (key included), a
    /// string's heap copy, an array's storage at twice its size (the growth while it is filled).
    uint64_t documentBytes = 0;
    uint64_t values = 0;    ///< every value of the document, containers included
    uint64_t instances = 0; ///< elements of the top-level "instances" array

    /// Counts `text` (comments allowed, as JsonReader::parse allows them). Text that is not valid JSON
    /// is counted as far as it parses: JsonReader::parse reports the error itself.
    static SceneDocumentCost measure(const std::string& text);
};

} // namespace sb
