#include "scenes/BezierPatch.h"

#include <sstream>

#include "core/Error.h"
#include "core/Paths.h"

namespace sb {
namespace {

glm::vec4 bernstein(float t) {
    const float s = 1.0f - t;
    return {s * s * s, 3.0f * t * s * s, 3.0f * t * t * s, t * t * t};
}

glm::vec4 bernsteinDerivative(float t) {
    const float s = 1.0f - t;
    return {-3.0f * s * s, 3.0f * s * s - 6.0f * t * s, 6.0f * t * s - 3.0f * t * t, 3.0f * t * t};
}

glm::vec3 combine(const glm::vec3 (&c)[4][4], const glm::vec4& bu, const glm::vec4& bv) {
    glm::vec3 sum(0.0f);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) sum += bu[i] * bv[j] * c[i][j];
    return sum;
}

/// Reads lines one at a time and counts them, so errors can say where the file is wrong.
class LineReader {
public:
    LineReader(const std::string& text, const std::string& source) : mStream(text), mSource(source) {}

    std::istringstream next(const char* what) {
        std::string line;
        while (std::getline(mStream, line)) {
            ++mLine;
            if (line.find_first_not_of(" \t\r") != std::string::npos) return std::istringstream(line);
        }
        fail(std::string("unexpected end of file, expected ") + what);
    }

    [[noreturn]] void fail(const std::string& why) const {
        throw Error("patch file '" + mSource + "': line " + std::to_string(mLine) + ": " + why);
    }

private:
    std::istringstream mStream;
    std::string mSource;
    int mLine = 0;
};

} // namespace

glm::vec3 BezierPatch::evaluate(float u, float v) const {
    return combine(control, bernstein(u), bernstein(v));
}

glm::vec3 BezierPatch::derivativeU(float u, float v) const {
    return combine(control, bernsteinDerivative(u), bernstein(v));
}

glm::vec3 BezierPatch::derivativeV(float u, float v) const {
    return combine(control, bernstein(u), bernsteinDerivative(v));
}

std::vector<BezierPatch> BezierPatch::readBptFile(const std::string& path) {
    return parseBpt(Paths::readTextFile(path), path);
}

std::vector<BezierPatch> BezierPatch::parseBpt(const std::string& text, const std::string& sourceName) {
    LineReader reader(text, sourceName);
    int count = 0;
    if (!(reader.next("the patch count") >> count) || count <= 0)
        reader.fail("expected a positive patch count");
    std::vector<BezierPatch> patches(size_t(count), BezierPatch{});
    for (auto& patch : patches) {
        int degreeU = 0, degreeV = 0;
        reader.next("a patch header \"3 3\"") >> degreeU >> degreeV;
        if (degreeU != 3 || degreeV != 3) reader.fail("expected \"3 3\" (bicubic patch)");
        for (int k = 0; k < 16; ++k) {
            glm::vec3& p = patch.control[k / 4][k % 4];
            if (!(reader.next("a control point") >> p.x >> p.y >> p.z))
                reader.fail("expected a control point \"x y z\"");
        }
    }
    return patches;
}

} // namespace sb
