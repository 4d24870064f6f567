#pragma once
// The pictures of a golden that changed (`bench golden --check --diff-dir DIR`): where a cell's image
// differs from its committed golden, drawn with bench accuracy's maps (bench/lib/images/), the golden in the
// reference's place. <cell> is the cell's name (technique/scene/mode, "/vulkan" for the Vulkan axis)
// with '/' made '.'.
//   visibility, for every light channel with a difference:
//     DIR/<cell>.visibility.light<i>.error.png   ErrorMap (bench/lib/images/ErrorMap.h): samples whose
//                                                shadowed/lit call (value < 128 of 255) flipped, the
//                                                edge band being the golden's; every pixel is judged;
//     DIR/<cell>.visibility.light<i>.signed.png  DifferenceMap of rendered − golden, at
//                                                DifferenceMap::niceScale of the largest difference;
//   colour:
//     DIR/<cell>.colour.signed.png               DifferenceMap of the luminance (Rec. 709 weights),
//                                                rendered − golden, at niceScale.
// Pictures only: the verdict is MatrixCheck's (bench/golden/MatrixCheck.h), not changed by them.
#include <string>
#include <vector>

#include "bench/golden/MatrixCheck.h"

namespace sb {

class GoldenDiff {
public:
    /// Writes the pictures of `change` (a change of cell `cell`) into `dir`; returns their paths. Throws
    /// sb::Error naming a path that cannot be written.
    static std::vector<std::string> write(const std::string& dir, const std::string& cell,
                                          const GoldenChange& change);
    /// "<cell>" as it appears in the file names.
    static std::string fileStem(const std::string& cell);
};

} // namespace sb
