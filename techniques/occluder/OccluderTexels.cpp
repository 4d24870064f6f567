#include "techniques/occluder/OccluderTexels.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/Error.h"
#include "core/PngFile.h"
#include "scenes/Mesh.h"

namespace sb {
namespace {

constexpr uint8_t kClear = 255;
constexpr int kMaxResolution = 16384;

std::string planeLabel(const ShadowPlane& plane) {
    return "shadow plane '" + plane.name + "'";
}

/// Rec. 709 luma of 8-bit encoded values (no linearisation: the image's own encoding is the convention).
uint8_t luma(float r, float g, float b) {
    const float y = 0.2126f * r + 0.7152f * g + 0.0722f * b;
    return uint8_t(std::lround(std::clamp(y, 0.0f, 255.0f)));
}

} // namespace

std::vector<uint8_t> OccluderTexels::dilate(const std::vector<uint8_t>& texels, int width, int height,
                                            int k) {
    if (k <= 0) return texels;
    // A square's min filter is separable: rows, then columns. O(k) per texel is fine for setup work.
    auto pass = [&](const std::vector<uint8_t>& in, int dx, int dy) {
        std::vector<uint8_t> out(in.size());
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                uint8_t m = kClear;
                for (int d = -k; d <= k; ++d) {
                    const int sx = std::clamp(x + d * dx, 0, width - 1),
                              sy = std::clamp(y + d * dy, 0, height - 1);
                    m = std::min(m, in[size_t(sy) * size_t(width) + size_t(sx)]);
                }
                out[size_t(y) * size_t(width) + size_t(x)] = m;
            }
        return out;
    };
    return pass(pass(texels, 1, 0), 0, 1);
}

std::vector<uint8_t> OccluderTexels::load(const std::string& path, int& width, int& height) {
    const std::string what = "occluder texture '" + path + "'";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw Error(what + ": no such file");
    // PngFile keeps the stored values (alpha, which is ignored, is not multiplied in).
    PngImage image;
    try {
        image = PngFile::read(path);
    } catch (const Error& e) {
        throw Error(what + ": " + e.what());
    }
    const int w = image.width, h = image.height, channels = image.channels;
    // Normalised floats, so 8-bit values come through exactly (x / 255 * 255) and 16-bit ones are
    // rounded once.
    std::vector<uint8_t> texels(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            auto at = [&](int c) { return image.normalized(x, y, c); };
            const uint8_t value = channels >= 3
                                      ? luma(at(0) * 255.0f, at(1) * 255.0f, at(2) * 255.0f)
                                      : uint8_t(std::lround(std::clamp(at(0), 0.0f, 1.0f) * 255.0f));
            texels[size_t(h - 1 - y) * size_t(w) + size_t(x)] = value; // images are top-down
        }
    width = w;
    height = h;
    return texels;
}

void OccluderTexels::write(const std::string& path, const std::vector<uint8_t>& texels, int width,
                           int height) {
    const std::string what = "occluder texture '" + path + "'";
    if (width <= 0 || height <= 0 || texels.size() != size_t(width) * size_t(height))
        throw Error(what + ": " + std::to_string(texels.size()) + " texels do not make " +
                    std::to_string(width) + "x" + std::to_string(height));
    std::vector<uint8_t> image(texels.size());
    for (int y = 0; y < height; ++y) // texture rows are bottom-up, images top-down
        std::copy_n(&texels[size_t(height - 1 - y) * size_t(width)], size_t(width),
                    &image[size_t(y) * size_t(width)]);
    PngFile::write(path, width, height, 1, image.data());
}

/// The index ranges plane.parts names; the whole mesh when the list is empty.
std::vector<MeshPart> OccluderTexels::parts(const Mesh& mesh, const ShadowPlane& plane) {
    if (plane.parts.empty()) return {MeshPart{"", 0, uint32_t(mesh.indices.size())}};
    std::vector<MeshPart> ranges;
    for (const std::string& name : plane.parts) {
        auto it = std::find_if(mesh.parts.begin(), mesh.parts.end(),
                               [&](const MeshPart& part) { return part.name == name; });
        if (it == mesh.parts.end()) {
            std::string known;
            for (const MeshPart& part : mesh.parts) known += (known.empty() ? "" : ", ") + part.name;
            throw Error(planeLabel(plane) + " of mesh '" + mesh.name + "': no part '" + name +
                        "' (parts: " + (known.empty() ? "none" : known) + ")");
        }
        ranges.push_back(*it);
    }
    return ranges;
}

void OccluderTexels::validate(const Mesh& mesh, const ShadowPlane& plane,
                              const OccluderBakeOptions& options) {
    plane.validate("occluder texture bake");
    if (options.resolution < 1 || options.resolution > kMaxResolution)
        throw Error(planeLabel(plane) + ": occluder texture resolution must be in [1, " +
                    std::to_string(kMaxResolution) + "], got " + std::to_string(options.resolution));
    if (options.dilate < 0 || options.dilate > options.resolution)
        throw Error(planeLabel(plane) + ": dilate must be in [0, resolution " +
                    std::to_string(options.resolution) + "], got " + std::to_string(options.dilate));
    if (mesh.indices.size() % 3 != 0)
        throw Error(planeLabel(plane) + ": mesh '" + mesh.name + "' index count is not a multiple of 3");
}

} // namespace sb
