#include "bench/golden/MatrixPage.h"

#include <filesystem>
#include <sstream>

#include "bench/golden/GoldenMatrix.h"
#include "core/Paths.h"

namespace sb {

namespace {

constexpr const char* kExceptionsHeading = "## Exceptions";

std::string trimmed(const std::string& s) {
    const size_t first = s.find_first_not_of(' ');
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(' ') - first + 1);
}

/// The first two cells of a table row ("| technique | scene | ..."): empty for the table's head and
/// its separator line.
std::pair<std::string, std::string> rowKey(const std::string& line) {
    if (line.rfind("| ", 0) != 0) return {};
    const size_t second = line.find('|', 1);
    const size_t third = second == std::string::npos ? second : line.find('|', second + 1);
    if (third == std::string::npos) return {};
    std::pair<std::string, std::string> key{trimmed(line.substr(1, second - 1)),
                                            trimmed(line.substr(second + 1, third - second - 1))};
    if (key.first == "technique" || key.first.rfind("---", 0) == 0) return {};
    return key;
}

/// The technique and scene of an exception line ("- `technique/scene/light0`: why").
std::pair<std::string, std::string> exceptionKey(const std::string& line) {
    if (line.rfind("- `", 0) != 0) return {};
    const std::string cell = line.substr(3, line.find('`', 3) - 3);
    const size_t slash = cell.find('/');
    const size_t light = cell.find('/', slash + 1);
    if (slash == std::string::npos || light == std::string::npos) return {};
    return {cell.substr(0, slash), cell.substr(slash + 1, light - slash - 1)};
}

std::string header(int size) {
    const std::string n = std::to_string(size);
    return "# The technique x submission x scene matrix\n\nWritten by `bench golden --update` "
           "(bench/golden/); checked by `bench golden --check` and tests/MatrixGLTest.cpp. Each row is one "
           "technique on one built-in scene at " +
           n + "x" + n + ", its camera `mid` where the scene has one, its layout cut to at most " +
           std::to_string(MatrixOptions{}.maxTriangles) +
           " triangles in proportion (bench/golden/GoldenMatrix.h, MatrixOptions::maxTriangles: aircraft, "
           "teapot and synthetic_triangles draw 99 of 200, 63 of 200 and 66 of 256 instances). *modes*: "
           "the submission modes whose cell passes "
           "every check (image equal to retained's and to the golden, accuracy within the bound), then the "
           "Vulkan axis: the technique on Vulkan (lavapipe) in retained and instanced submission, each "
           "image held to the GL retained cell's and to the same golden, the retained one to the same "
           "bound, with the validation layer on (immediate and display lists are GL's own). A technique "
           "with no GL form is held to the golden and bound of its Vulkan retained cell instead, on a "
           "driver whose Vulkan device has the capabilities it needs (the row names the driver where it "
           "is not the system's); *accuracy*: that golden cell (GL retained, else Vulkan retained) against "
           "the Embree reference, per light, and its bound (rules in bench/golden/AccuracyBounds.h). An "
           "unsupported cell gives the technique's reason. A variant that a technique declares (a form at "
           "other properties, with the rule it is held to: `bench --list`, its `matrix:` line) has rows of "
           "its own, named by its spec with ':' as '.' (`raytraced.mode=soft`), as are its goldens and "
           "bounds.\n\n"
           "| technique | scene | modes | accuracy |\n|---|---|---|---|\n";
}

} // namespace

MatrixPage MatrixPage::read(const std::string& path) {
    MatrixPage page;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return page;
    std::istringstream lines(Paths::readTextFile(path));
    for (std::string line; std::getline(lines, line);) {
        if (const auto key = rowKey(line); !key.first.empty())
            page.mEntries[key].row = line;
        else if (const auto owner = exceptionKey(line); !owner.first.empty())
            page.mEntries[owner].exceptions.push_back(line);
    }
    return page;
}

void MatrixPage::set(const std::string& technique, const std::string& scene, const std::string& row,
                     const std::vector<std::string>& exceptions) {
    mEntries[{technique, scene}] = {row, exceptions};
}

bool MatrixPage::has(const std::string& technique, const std::string& scene) const {
    const auto it = mEntries.find({technique, scene});
    return it != mEntries.end() && !it->second.row.empty();
}

std::string MatrixPage::text(int size, const std::vector<std::string>& scenes,
                             const std::vector<std::string>& techniques) const {
    std::string rows, exceptions;
    for (const std::string& scene : scenes)
        for (const std::string& technique : techniques) {
            const auto it = mEntries.find({technique, scene});
            if (it == mEntries.end()) continue;
            if (!it->second.row.empty()) rows += it->second.row + "\n";
            for (const std::string& line : it->second.exceptions) exceptions += line + "\n";
        }
    return header(size) + rows +
           (exceptions.empty() ? "" : "\n" + std::string(kExceptionsHeading) + "\n\n" + exceptions);
}

} // namespace sb
