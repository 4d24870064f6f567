#include "bench/lib/images/RunImageNames.h"

#include <filesystem>
#include <set>

#include "bench/lib/images/AccuracyImages.h"

namespace sb {

namespace fs = std::filesystem;

std::string RunImageNames::changedProperties(const PropertySet& properties) {
    // A set built from the same declarations holds the canonical defaults, so "2.0" and "2" compare equal.
    const PropertySet defaults("", properties.descs());
    std::string out;
    for (const PropertyDesc& d : properties.descs())
        if (properties.getText(d.name) != defaults.getText(d.name))
            out += (out.empty() ? "" : ":") + d.name + "=" + properties.getText(d.name);
    return out;
}

std::vector<std::string> RunImageNames::labels(const std::vector<Configuration>& run) {
    std::vector<std::string> out(run.size());
    if (run.size() < 2) return out;
    std::set<std::string> taken;
    for (size_t i = 0; i < run.size(); ++i) {
        size_t sameTechnique = 0;
        for (const Configuration& c : run) sameTechnique += c.technique == run[i].technique ? 1 : 0;
        std::string label = run[i].technique;
        // Only where a name alone would not tell the files apart: a run of distinct techniques keeps
        // the short names.
        if (const std::string changed = changedProperties(run[i].properties);
            sameTechnique > 1 && !changed.empty())
            label += "_" + changed;
        label = AccuracyImages::fileLabel(label);
        if (taken.count(label)) label += "_" + std::to_string(i + 1);
        taken.insert(label);
        out[i] = label;
    }
    return out;
}

std::string RunImageNames::withLabel(const std::string& path, const std::string& label) {
    if (label.empty()) return path;
    const fs::path p(path);
    return (p.parent_path() / (p.stem().string() + "_" + label + p.extension().string())).string();
}

std::string RunImageNames::lightFile(const std::string& path, size_t light) {
    return light == 0 ? path : withLabel(path, "light" + std::to_string(light));
}

std::string RunImageNames::recorded(const std::string& image, const std::string& csvPath) {
    if (csvPath.empty()) return image;
    const fs::path folder = fs::absolute(fs::path(csvPath)).lexically_normal().parent_path();
    return fs::absolute(fs::path(image)).lexically_normal().lexically_relative(folder).generic_string();
}

} // namespace sb
