#include "bench/lib/images/AccuracyImages.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

#include "bench/lib/images/DifferenceMap.h"
#include "bench/lib/images/ErrorMap.h"
#include "bench/lib/images/FlipRows.h"
#include "bench/lib/output/ImageWriter.h"
#include "core/Error.h"

namespace sb {

namespace fs = std::filesystem;

namespace {

std::string percent(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", v);
    return text;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", v);
    return text;
}

/// 8-bit grey of a visibility, top row first: [0, 1] to 0..255, anything else (no geometry, NaN) 0.
std::vector<uint8_t> grey(const std::vector<float>& values) {
    std::vector<uint8_t> out(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const float v = values[i];
        out[i] = std::isfinite(v) && v > 0.0f ? uint8_t(std::lround(std::min(v, 1.0f) * 255.0f)) : 0;
    }
    return out;
}

void writeRgb(const std::string& path, const RgbImage& image) {
    ImageWriter::writeAtomic(path, image.width(), image.height(), 3, image.bytes().data());
}

} // namespace

void AccuracyImages::prepareDirectory(const std::string& dir, const std::string& option) {
    if (dir.empty()) throw Error(option + ": the path is empty");
    std::error_code ec;
    const fs::file_status status = fs::status(dir, ec);
    if (fs::exists(status) && !fs::is_directory(status))
        throw Error(option + " " + dir + ": exists and is not a directory");
    if (!fs::exists(status)) {
        const fs::path parent = fs::path(dir).parent_path();
        if (!parent.empty() && !fs::is_directory(parent))
            throw Error(option + " " + dir + ": its parent folder " + parent.string() +
                        " does not exist (only DIR itself is created)");
        if (!fs::create_directory(dir, ec) && !fs::is_directory(dir))
            throw Error(option + " " + dir + ": cannot create the directory: " + ec.message());
    }
    // A probe file shows what permission bits do not: read-only mounts, ACLs, root on a read-only bind.
    const std::string probe = (fs::path(dir) / (".shadowbench-probe-" + std::to_string(getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) throw Error(option + " " + dir + ": cannot write there: " + std::strerror(errno));
    ::close(fd);
    ::unlink(probe.c_str());
}

std::string AccuracyImages::fileLabel(const std::string& label) {
    std::string out = label;
    for (char& c : out)
        if (!std::isalnum(static_cast<unsigned char>(c)) && !std::strchr("._=+-", c)) c = '_';
    // A leading dot would hide the file; an empty name would leave two dots in a row.
    if (out.empty() || out[0] == '.') out.insert(out.begin(), '_');
    return out;
}

std::vector<LegendEntry> AccuracyImages::legend() {
    return {
        {ErrorMap::kFalseShadow, "false shadow: technique shadowed (< 0.5), reference lit"},
        {ErrorMap::kFalseLight, "false light: technique lit, reference shadowed"},
        {ErrorMap::kFalseShadowEdge, "false shadow in the edge band (1 px around a reference edge)"},
        {ErrorMap::kFalseLightEdge, "false light in the edge band"},
        {ErrorMap::kEdgeBand, "edge band, correct"},
        {ErrorMap::dimmed(1.0f), "correct: the reference dimmed (lit)"},
        {ErrorMap::dimmed(0.0f), "correct: the reference dimmed (shadowed)"},
        {ErrorMap::kNotJudged, "not judged (faces away from the light, or out of its reach)"},
    };
}

std::vector<std::string> AccuracyImages::header(const std::string& scene, int light, bool softReference,
                                                int width, int height) {
    return {"bench accuracy: scene " + scene + ", light " + std::to_string(light) + " (" +
                (softReference ? "soft" : "hard") + " reference), " + std::to_string(width) + "x" +
                std::to_string(height),
            "error maps: each technique's shadowed/lit call against the Embree reference"};
}

std::vector<std::string> AccuracyImages::figures(const HardMetrics& hard, const SoftMetrics& soft,
                                                 bool softTechnique) {
    // Short lines: 21 characters fit a 128 px tile.
    return {"wrong " + percent(hard.wrongPct), "false shadow " + percent(hard.falseShadowPct),
            "false light " + percent(hard.falseLightPct), "off edge band " + percent(hard.wrongNoEdgePct),
            "rmse " + number(soft.rmse) + (softTechnique ? " (soft)" : "")};
}

AccuracyImages::AccuracyImages(std::string dir, std::string scene, int light, int width, int height)
    : mDir(std::move(dir)), mScene(fileLabel(scene)), mLight(light), mWidth(width), mHeight(height) {}

std::string AccuracyImages::path(const std::string& label, const std::string& kind) const {
    return (fs::path(mDir) / (mScene + "." + label + ".light" + std::to_string(mLight) + "." + kind + ".png"))
        .string();
}

std::string AccuracyImages::contactSheetPath() const {
    return (fs::path(mDir) / (mScene + ".light" + std::to_string(mLight) + ".contact.png")).string();
}

bool AccuracyImages::fractional(const std::vector<float>& technique, const std::vector<uint8_t>& mask) {
    for (size_t i = 0; i < technique.size() && i < mask.size(); ++i) {
        if (!mask[i] || !std::isfinite(technique[i])) continue;
        const long level = std::lround(std::clamp(technique[i], 0.0f, 1.0f) * 255.0f);
        if (level >= 1 && level <= 254) return true;
    }
    return false;
}

std::vector<std::string> AccuracyImages::add(const std::string& label, const std::vector<float>& technique,
                                             const std::vector<float>& reference,
                                             const std::vector<uint8_t>& mask, const HardMetrics& hard,
                                             const SoftMetrics& soft, bool softTechnique,
                                             bool softReference) {
    mSoftReference = softReference; // one light per run: the same for every configuration
    std::string name = fileLabel(label);
    for (int k = 2; mLabels.count(name); ++k) name = fileLabel(label) + "-" + std::to_string(k);
    mLabels.insert(name);
    const std::vector<float> tech = flipRows(technique, mWidth, mHeight);
    const std::vector<float> ref = flipRows(reference, mWidth, mHeight);
    const std::vector<uint8_t> judged = flipRows(mask, mWidth, mHeight);

    std::vector<std::string> written;
    const std::string techPath = path(name, "technique"), refPath = path(name, "reference");
    ImageWriter::writeAtomic(techPath, mWidth, mHeight, 1, grey(tech).data());
    ImageWriter::writeAtomic(refPath, mWidth, mHeight, 1, grey(ref).data());
    written.push_back(techPath);
    written.push_back(refPath);
    ErrorMap map = ErrorMap::build(tech, ref, judged, mWidth, mHeight);
    const std::string errorPath = path(name, "error");
    writeRgb(errorPath, map.image());
    written.push_back(errorPath);
    if (softTechnique || softReference || fractional(tech, judged)) {
        const std::string signedPath = path(name, "signed");
        writeRgb(signedPath, DifferenceMap::build(tech, ref, judged, mWidth, mHeight));
        written.push_back(signedPath);
    }
    ContactTile tile;
    tile.title = label;
    tile.lines = figures(hard, soft, softTechnique);
    tile.map = map.image();
    mTiles.push_back(std::move(tile));
    return written;
}

std::string AccuracyImages::writeContactSheet() const {
    if (mTiles.empty()) return "";
    const std::string sheetPath = contactSheetPath();
    writeRgb(sheetPath, ContactSheet::compose(header(mScene, mLight, mSoftReference, mWidth, mHeight),
                                              legend(), mTiles));
    return sheetPath;
}

} // namespace sb
