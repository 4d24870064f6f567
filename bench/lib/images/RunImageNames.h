#pragma once
// The files `--screenshot FILE` and `--visibility FILE` give each configuration of a run
// (bench/run/RunCommand.cpp), so that no configuration overwrites another's picture.
//
// With one configuration FILE itself. With several, FILE's stem with the configuration's label inserted
// (shot.png -> shot_<label>.png). The label is the technique's name where no other configuration of the
// run has that technique (`-t none -t shadowmap`: shot_none.png, shot_shadowmap.png). Where two share it,
// the properties that differ from the technique's defaults follow the name, file-safe as
// AccuracyImages::fileLabel makes them (`-t shadowmap -t shadowmap:resolution=256`: shot_shadowmap.png
// and shot_shadowmap_resolution=256.png). A label an earlier configuration already has gets the
// configuration's 1-based position in the run (`-t shadowmap -t shadowmap`: shot_shadowmap.png and
// shot_shadowmap_2.png). Light L > 0 of --visibility adds `_lightL`. Each measured row records its
// files (docs/CSV.md: screenshot_file, visibility_file), so readers never guess them from the names.
#include <string>
#include <vector>

#include "techniques/PropertySet.h"

namespace sb {

class RunImageNames {
public:
    /// One configuration of the run: its technique's name and properties as it runs.
    struct Configuration {
        std::string technique;
        PropertySet properties;
    };

    /// Per configuration, in run order, the label its files get; every label is "" for a run of one.
    static std::vector<std::string> labels(const std::vector<Configuration>& run);
    /// "k=v:k=v" of the properties whose value is not the declared default, in declaration order ("" when
    /// all are).
    static std::string changedProperties(const PropertySet& properties);
    /// `path` with "_<label>" inserted before its extension; `path` itself when `label` is empty.
    static std::string withLabel(const std::string& path, const std::string& label);
    /// The visibility file of light `light` for the base name `path`: `path` for light 0, else
    /// withLabel(path, "light<L>").
    static std::string lightFile(const std::string& path, size_t light);
    /// How a row records `image`: relative to the folder of the CSV file `csvPath` the row goes to (so
    /// the pair can be moved together), or `image` as given where the rows go to no file.
    static std::string recorded(const std::string& image, const std::string& csvPath);
};

} // namespace sb
