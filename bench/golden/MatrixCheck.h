#pragma once
// Judges the cells of the matrix (GoldenMatrix) three ways:
//   (a) every submission mode's visibility and colour equal the golden cell's (GoldenMatrix::goldenCellOf:
//       the GL retained cell, or the Vulkan retained cell of a technique with no GL form; the mode and
//       the API must never change the image), within kModeTolerance;
//   (b) the image equals the committed golden (results/goldens/<scene>/<technique>.*.png, a variant's
//       file named by MatrixVariants::key: raytraced.mode=soft.*.png), within
//       kGoldenTolerance, and a golden cell that refuses its scene has no golden (so a technique that
//       starts refusing a scene is seen, as is one that stops);
//   (c) every light's accuracy against the Embree reference stays within the committed bound
//       (results/goldens/bounds.json), which itself must be no looser than the rule (AccuracyBounds).
// The numeric sanity of the visibility read-back (NaN, Inf, out of [0, 1]) must be zero everywhere.
// A cell this driver cannot run (MatrixCell::Refusal::Driver: a capability its form needs is missing) is
// judged by nothing here, neither passed nor unsupported: its verdict says that it was not run on this
// driver and why, and `bench golden --check` and MatrixGLTest print it for every such cell. Its golden
// and bound stay (they are judged on the driver that has the capability: the second driver's matrix
// test in tests/CMakeLists.txt, with --strict-driver).
#include <map>
#include <string>
#include <vector>

#include "bench/golden/AccuracyBounds.h"
#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/ImageDiff.h"

namespace sb {

/// A cell's image that no longer matches its golden (kind "visibility" or "colour"): both images, for
/// the difference pictures `bench golden --check` writes (bench/golden/GoldenDiff.h). Only comparable
/// images (same size and channels) that fail kGoldenTolerance are listed.
struct GoldenChange {
    std::string kind;
    std::string goldenPath;
    Image8 golden, rendered;
};

struct CellVerdict {
    std::string cell;                  ///< technique/scene/mode
    std::string unsupported;           ///< the technique's reason, when it refused the scene
    std::string notRun;                ///< why this driver cannot run the cell (Refusal::Driver)
    std::vector<std::string> failures; ///< one line per broken check
    std::vector<std::string> details;  ///< what was compared and by how much (for --verbose)
    std::vector<GoldenChange> changed; ///< images that no longer match their golden (a subset of failures)
    bool passed() const { return failures.empty(); }
};

class MatrixCheck {
public:
    /// (a) Visibility is compared in floats: a sample fails when it differs by more than 0.01, and 0.5%
    /// of a frame may fail. The modes feed identical vertices to identical programs, but the instanced
    /// mode reads the model matrix from an attribute and display lists may be re-encoded by the driver:
    /// a vertex can move by an ulp and flip the coverage of a pixel exactly on an edge, and at 128^2 a
    /// busy scene (city) has a few hundred edge pixels, of which a few flip. Colour uses the same rule
    /// at 2/255 per channel.
    static constexpr DiffTolerance kModeTolerance{2, 0.005};
    /// (b) Goldens are 8-bit: a channel may differ by 2/255 (rounding on either side of a step, and the
    /// lighting's last bits between compilers), and 0.5% of the pixels may fail (edge pixels that flip
    /// between the modes, compared with the retained golden too). Anything more is a changed image.
    static constexpr DiffTolerance kGoldenTolerance{2, 0.005};

    /// The golden of `technique` (a name, or a variant's spec: its file is named by MatrixVariants::key)
    /// on `scene`: kind "visibility" or "colour".
    static std::string goldenPath(const std::string& dir, const std::string& scene,
                                  const std::string& technique, const std::string& kind);
    /// Verdicts for the cells of one scene (as GoldenMatrix::renderScene returns them). `bounds` maps
    /// "technique/scene/light<i>" to the committed bound.
    /// The verdict of cells[index] alone (`bench golden --check` judges each cell as it finishes): it
    /// needs only the cells before it, since a technique's retained cell renders first. `goldens` keeps
    /// the goldens read so far by path (the modes of a cell share one); an empty image: no file.
    static CellVerdict checkCell(const std::vector<MatrixCell>& cells, size_t index,
                                 const std::string& goldenDir,
                                 const std::map<std::string, AccuracyBound>& bounds,
                                 std::map<std::string, Image8>& goldens);
    static std::vector<CellVerdict> check(const std::vector<MatrixCell>& cells, const std::string& goldenDir,
                                          const std::map<std::string, AccuracyBound>& bounds);
};

} // namespace sb
