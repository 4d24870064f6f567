#pragma once
// results/goldens/MATRIX.md, the matrix's page: one row per technique and built-in scene, then the cells
// held to an exception with their reasons. `bench golden --update` renders some scenes and techniques,
// or all of them, and some cells it renders cannot run on the driver it runs on (a capability a form
// needs: bench/golden/MatrixCheck.h); the page is read back first and every row the update did not
// render anew is written back as it was, as bounds.json keeps the bounds of cells not rendered. So an
// update of one technique on the driver that can run it (bench --driver mesa-25.0.7 golden --update
// --technique T) writes T's rows, and a later update of the whole matrix on the system driver keeps them.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sb {

class MatrixPage {
public:
    /// The rows and exception lines of the page at `path`; no file gives an empty page. Lines that are
    /// neither (the header, the table's head) are not kept: text() writes them.
    static MatrixPage read(const std::string& path);
    /// `technique` is a row's key: a technique's name, or a variant's MatrixVariants::key.
    /// Sets the row of `technique` on `scene` ("| technique | scene | modes | accuracy |") and its
    /// exception lines ("- `technique/scene/light0`: why"), replacing what the page had for them.
    void set(const std::string& technique, const std::string& scene, const std::string& row,
             const std::vector<std::string>& exceptions);
    bool has(const std::string& technique, const std::string& scene) const;
    /// The whole page for frames of `size`: the header, then the rows of `scenes` x `techniques` in that
    /// order (scene by scene), then the exceptions in the same order. Rows of other scenes or techniques
    /// (no longer built in or registered) are left out.
    std::string text(int size, const std::vector<std::string>& scenes,
                     const std::vector<std::string>& techniques) const;

private:
    struct Entry {
        std::string row;
        std::vector<std::string> exceptions;
    };
    std::map<std::pair<std::string, std::string>, Entry> mEntries; ///< by technique, scene
};

} // namespace sb
