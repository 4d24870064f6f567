#include "bench/golden/GoldenCommand.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "bench/golden/AccuracyBounds.h"
#include "bench/golden/GoldenDiff.h"
#include "bench/golden/GoldenImage.h"
#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/MatrixCheck.h"
#include "bench/golden/MatrixProgress.h"
#include "bench/lib/images/AccuracyImages.h"
#include "bench/lib/options/CliParse.h"
#include "bench/lib/options/DriverOption.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/select/AutoResolver.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/Paths.h"
#include "core/Strings.h"
#include "core/Suggestion.h"
#include "registry/TechniqueRegistry.h"

namespace sb {

namespace {

struct GoldenCli {
    bool check = false, update = false, verbose = false;
    std::string dir;
    std::string diffDir; ///< --check: where the pictures of changed goldens go
    MatrixOptions matrix;
};

/// --diff-dir's default: a folder of the system's temporary directory (the source tree stays clean).
std::string defaultDiffDir() {
    return (std::filesystem::temp_directory_path() / "shadowbench-golden-diff").string();
}

/// results/goldens of the source tree (or of an install): the first search root that has one. A results/
/// folder without goldens (a run's output beside the binary) is not it.
std::string defaultGoldenDir() {
    for (const std::string& root : Paths::searchRoots())
        if (std::filesystem::is_directory(std::filesystem::path(root) / "results" / "goldens"))
            return (std::filesystem::path(root) / "results" / "goldens").string();
    throw Error("cannot find the source tree's results/goldens folder: pass --dir", ExitCode::Failure);
}

std::map<std::string, AccuracyBound> readBounds(const std::string& dir) {
    const std::string path = dir + "/bounds.json";
    return std::filesystem::exists(path) ? AccuracyBounds::read(path)
                                         : std::map<std::string, AccuracyBound>{};
}

/// What --check prints of one cell: failures always, passes and details with --verbose.
std::string describeVerdict(const GoldenCli& cli, const CellVerdict& v) {
    std::ostringstream out;
    if (!v.unsupported.empty() && v.passed()) {
        if (cli.verbose) out << v.cell << ": unsupported: " << v.unsupported << "\n";
        return out.str();
    }
    if (!v.passed() || cli.verbose) out << v.cell << (v.passed() ? ": ok\n" : ": FAILED\n");
    for (const std::string& f : v.failures) out << "  " << f << "\n";
    for (const GoldenChange& change : v.changed) {
        out << "  " << change.kind << " difference against " << change.goldenPath << ":";
        for (const std::string& path : GoldenDiff::write(cli.diffDir, v.cell, change)) out << " " << path;
        out << "\n";
    }
    if (cli.verbose)
        for (const std::string& d : v.details) out << "  " << d << "\n";
    return out.str();
}

int runCheck(const GoldenCli& cli, const std::vector<std::string>& scenes) {
    const std::map<std::string, AccuracyBound> bounds = readBounds(cli.dir);
    // Checked before the first scene renders: a folder that cannot take the pictures fails in
    // milliseconds, not after the matrix.
    AccuracyImages::prepareDirectory(cli.diffDir, "--diff-dir");
    size_t checked = 0, unsupported = 0, failed = 0;
    std::vector<CellVerdict> verdicts; // of the scene rendering now, judged as each cell finishes
    std::map<std::string, Image8> goldens;
    MatrixProgress run(
        scenes.size() * GoldenMatrix::cellsPerScene(cli.matrix), [&](const std::vector<MatrixCell>& cells) {
            verdicts.push_back(MatrixCheck::checkCell(cells, cells.size() - 1, cli.dir, bounds, goldens));
            return verdicts.back().passed();
        });
    for (const std::string& scene : scenes) {
        verdicts.clear();
        goldens.clear();
        GoldenMatrix::renderScene(scene, cli.matrix, run.observer());
        std::string text;
        for (const CellVerdict& v : verdicts) {
            const bool skipped = !v.unsupported.empty() && v.passed();
            unsupported += skipped;
            checked += !skipped;
            failed += !v.passed();
            text += describeVerdict(cli, v);
        }
        if (!text.empty()) {
            run.pause();
            std::cout << text << std::flush;
        }
    }
    run.finish();
    std::cout << "golden check: " << checked << " cells checked, " << failed << " failed, " << unsupported
              << " unsupported (--verbose lists them) against " << cli.dir << " on the driver "
              << DriverTable::current() << "\n";
    return failed ? int(ExitCode::Failure) : 0;
}

/// Writes one golden, printing whether it is new, unchanged or changed and by how much. A golden that
/// cannot be read (a truncated file, a forged header) is what --update exists to repair: it is replaced,
/// and the line says so and why.
void updateGolden(const std::string& path, const Image8& image) {
    std::string what = "new";
    if (std::filesystem::exists(path)) {
        Image8 old;
        try {
            old = GoldenImage::read(path);
        } catch (const Error& e) {
            what = std::string("replaced an unreadable golden (") + e.what() + ")";
        }
        if (!old.empty()) {
            const ImageDiffResult d = ImageDiff::compare(old, image, MatrixCheck::kGoldenTolerance);
            if (d.comparable && d.maxChannelDiff == 0) return; // byte-identical: leave the file alone
            what = (d.passes(MatrixCheck::kGoldenTolerance) ? "changed within tolerance: " : "CHANGED: ") +
                   d.describe(MatrixCheck::kGoldenTolerance);
        }
    }
    GoldenImage::write(path, image);
    std::cout << path << ": " << what << "\n";
}

/// One line of MATRIX.md: the retained cell's accuracy and bound, how many modes pass every check.
std::string matrixRow(const std::vector<CellVerdict>& verdicts, const std::vector<MatrixCell>& cells,
                      const MatrixCell& retained) {
    std::ostringstream row;
    row << "| " << retained.technique << " | " << retained.scene << " | ";
    if (retained.autoPick)
        row << "chose " << retained.autoPick->spec.substr(0, retained.autoPick->spec.find(':')) << ", ";
    if (!retained.unsupported.empty()) {
        row << "unsupported | " << retained.unsupported << " |";
        return row.str();
    }
    size_t modes = 0, passed = 0, vulkanModes = 0, vulkanPassed = 0;
    std::string vulkanWhy;
    for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].technique != retained.technique) continue;
        const bool ok = verdicts[i].passed() && cells[i].ran();
        if (!cells[i].vulkan()) {
            ++modes;
            passed += ok;
        } else if (!cells[i].unsupported.empty()) {
            vulkanWhy = cells[i].unsupported;
        } else {
            ++vulkanModes;
            vulkanPassed += ok;
        }
    }
    row << passed << "/" << modes << " pass; Vulkan "
        << (vulkanModes ? std::to_string(vulkanPassed) + "/" + std::to_string(vulkanModes) + " pass"
                        : "unsupported (" + vulkanWhy + ")")
        << " | ";
    for (size_t l = 0; l < retained.lights.size(); ++l) {
        const AccuracyBound b = AccuracyBounds::derive(retained, l);
        std::ostringstream value;
        value.precision(3);
        if (l) value << "; ";
        if (b.judged())
            value << b.metric << " " << b.measured(retained.lights[l]) << " <= " << b.max << " (" << b.rule
                  << ")";
        else
            value << "not judged";
        row << value.str();
    }
    row << " |";
    return row.str();
}

/// Writes the retained cells' goldens and returns their bounds with the measured values.
void writeGoldens(const GoldenCli& cli, const std::vector<MatrixCell>& cells,
                  std::map<std::string, std::pair<AccuracyBound, double>>& fresh) {
    for (const MatrixCell& cell : cells) {
        // An `auto` cell has no golden of its own: it is held to the chosen technique's.
        if (cell.mode != SubmitMode::Retained || !cell.failure.empty() ||
            cell.technique == AutoResolver::kName || cell.vulkan())
            continue;
        const std::string vis = MatrixCheck::goldenPath(cli.dir, cell.scene, cell.technique, "visibility");
        const std::string col = MatrixCheck::goldenPath(cli.dir, cell.scene, cell.technique, "colour");
        if (!cell.ran()) {
            for (const std::string& p : {vis, col})
                if (std::filesystem::remove(p)) std::cout << p << ": removed (" << cell.unsupported << ")\n";
            continue;
        }
        updateGolden(vis, cell.visibility);
        updateGolden(col, cell.colour);
        for (size_t l = 0; l < cell.lights.size(); ++l) {
            const AccuracyBound b = AccuracyBounds::derive(cell, l);
            fresh[b.cell] = {b, b.measured(cell.lights[l])};
        }
    }
}

void writeBounds(const std::string& dir,
                 const std::map<std::string, std::pair<AccuracyBound, double>>& fresh) {
    std::map<std::string, AccuracyBound> kept = readBounds(dir); // cells of scenes not rendered this time
    std::vector<AccuracyBound> bounds;
    std::vector<double> measured;
    for (const auto& [name, entry] : fresh) kept.erase(name);
    for (const auto& [name, b] : kept) {
        bounds.push_back(b);
        measured.push_back(b.recorded); // as measured when it was last written
    }
    for (const auto& [name, entry] : fresh) {
        bounds.push_back(entry.first);
        measured.push_back(entry.second);
    }
    CsvWriter::writeText(dir + "/bounds.json", AccuracyBounds::toJson(bounds, measured));
}

std::string matrixHeader(int size) {
    return "# The technique x submission x scene matrix\n\nWritten by `bench golden --update` "
           "(bench/golden/); "
           "checked by `bench golden --check` and tests/MatrixGLTest.cpp. Each row is one technique on one "
           "built-in scene at " +
           std::to_string(size) + "x" + std::to_string(size) +
           ", its camera `mid` where the scene has one. *modes*: the submission modes whose cell passes "
           "every "
           "check (image equal to retained's and to the golden, accuracy within the bound), then the Vulkan "
           "axis: the technique on Vulkan (lavapipe) in retained and instanced submission, each image held "
           "to "
           "the GL retained cell's and to the same golden, the retained one to the same bound, with the "
           "validation layer on (immediate and display lists are GL's own); *accuracy*: the "
           "retained cell against the Embree reference, per light, and its bound (rules in "
           "bench/golden/AccuracyBounds.h). An unsupported cell gives the technique's reason.\n\n"
           "| technique | scene | modes | accuracy |\n|---|---|---|---|\n";
}

/// The cells held to an exception instead of their rule, each with its reason.
std::string exceptionList(const std::vector<std::vector<MatrixCell>>& rendered) {
    std::string out;
    for (const std::vector<MatrixCell>& cells : rendered)
        for (const MatrixCell& cell : cells) {
            if (cell.mode != SubmitMode::Retained || !cell.ran() || cell.autoPick || cell.vulkan()) continue;
            for (size_t l = 0; l < cell.lights.size(); ++l) {
                const AccuracyBound b = AccuracyBounds::derive(cell, l);
                if (b.rule == "exception") out += "- `" + b.cell + "`: " + b.why + "\n";
            }
        }
    return out.empty() ? "" : "\n## Exceptions\n\n" + out;
}

int runUpdate(const GoldenCli& cli, const std::vector<std::string>& scenes, bool wholeMatrix) {
    std::map<std::string, std::pair<AccuracyBound, double>> fresh;
    std::vector<std::vector<MatrixCell>> rendered;
    // The cells are judged after the goldens are written; while rendering, a cell that threw is a failure.
    MatrixProgress run(scenes.size() * GoldenMatrix::cellsPerScene(cli.matrix),
                       [](const std::vector<MatrixCell>& cells) { return cells.back().failure.empty(); });
    for (const std::string& scene : scenes) {
        rendered.push_back(GoldenMatrix::renderScene(scene, cli.matrix, run.observer()));
        run.pause();
        writeGoldens(cli, rendered.back(), fresh);
    }
    run.finish();
    writeBounds(cli.dir, fresh);
    // The update is checked like any other run: a cell that fails (a mode that differs from retained,
    // an accuracy outside its rule) is printed and makes the exit code 1, goldens written or not.
    const std::map<std::string, AccuracyBound> bounds = readBounds(cli.dir);
    std::string rows;
    size_t failed = 0, written = 0;
    for (const std::vector<MatrixCell>& cells : rendered) {
        const std::vector<CellVerdict> verdicts = MatrixCheck::check(cells, cli.dir, bounds);
        for (size_t i = 0; i < cells.size(); ++i) {
            if (!verdicts[i].passed()) {
                ++failed;
                std::cout << verdicts[i].cell << ": FAILED\n";
                for (const std::string& f : verdicts[i].failures) std::cout << "  " << f << "\n";
            }
            if (cells[i].mode != SubmitMode::Retained || cells[i].vulkan()) continue;
            rows += matrixRow(verdicts, cells, cells[i]) + "\n";
            written += cells[i].ran();
        }
    }
    if (wholeMatrix)
        CsvWriter::writeText(cli.dir + "/MATRIX.md",
                             matrixHeader(cli.matrix.size) + rows + exceptionList(rendered));
    std::cout << "golden update: " << written << " technique x scene goldens in " << cli.dir
              << (wholeMatrix ? " (and MATRIX.md)" : " (MATRIX.md is written only for the whole matrix)")
              << "; " << failed << " cells fail their checks\n";
    return failed ? int(ExitCode::Failure) : 0;
}

} // namespace

int GoldenCommand::main(int argc, char** argv) {
    CLI::App app{"bench golden: render the technique x submission x scene matrix and check it against the "
                 "committed goldens and accuracy bounds, or rewrite them",
                 "bench golden"};
    app.footer(R"(Examples:
  bench golden --check                         every cell (about 30 s of CPU per scene)
  bench golden --check --scene teapot --verbose
  bench golden --update --technique projective  rewrite one technique's goldens, print what changed

Each cell: every submission mode's image must equal retained's, the retained image the golden
(results/goldens/<scene>/<technique>.{visibility,colour}.png), and the accuracy against the Embree
reference its bound in results/goldens/bounds.json. Exit 1 when a cell fails. An image that no
longer matches its golden gets pictures of where it differs in --diff-dir, their paths printed
under the cell (bench/golden/GoldenDiff.h).)");
    GoldenCli cli;
    std::vector<std::string> scenes, techniques;
    auto* check = app.add_flag("--check", cli.check, "judge every cell (the default)");
    app.add_flag("--update", cli.update, "rewrite goldens and bounds from this build's images")
        ->excludes(check);
    app.add_option("--scene", scenes, "comma-separated built-in scenes (default: all)")->delimiter(',');
    app.add_option("--technique", techniques, "comma-separated techniques (default: all)")->delimiter(',');
    app.add_option("--size", cli.matrix.size, "frame size (default 128, the size of the committed goldens)")
        ->check(CLI::Range(16, 1024));
    app.add_option("--dir", cli.dir, "golden folder (default: the source tree's results/goldens)");
    app.add_option("--diff-dir", cli.diffDir,
                   "--check: write an error map and a signed difference map of every image that no longer "
                   "matches its golden into this folder (default: shadowbench-golden-diff in the temporary "
                   "directory)");
    app.add_flag("-v,--verbose", cli.verbose, "print every cell, its comparisons and unsupported cells");
    std::string driver; // acted on by BenchApp: the process already runs on it
    DriverOption::add(app, driver);
    if (int code = parseCli(app, argc, argv, "bench golden"); code >= 0) return code;
    const std::vector<std::string> known = GoldenMatrix::builtinScenes();
    const std::vector<std::string> chosen = scenes.empty() ? known : scenes;
    for (const std::string& s : chosen)
        if (std::find(known.begin(), known.end(), s) == known.end())
            throw Error("--scene " + s + ": not a built-in scene" + Suggestion::didYouMean(s, known) +
                        " (known: " + join(known, ", ") + ")");
    cli.matrix.techniques = techniques;
    for (const std::string& t : cli.matrix.techniques)
        if (t != AutoResolver::kName)
            TechniqueRegistry::describe(TechniqueSpec{t, {}}); // names it if unknown
    if (cli.dir.empty()) cli.dir = defaultGoldenDir();
    std::error_code ec; // --check reads the goldens; --update may write a new folder
    if (!cli.update && !std::filesystem::is_directory(cli.dir, ec))
        throw Error("--dir " + cli.dir + ": no such folder of goldens");
    if (cli.update && !cli.diffDir.empty())
        throw Error("--diff-dir belongs to --check (see bench golden --help)");
    if (cli.diffDir.empty()) cli.diffDir = defaultDiffDir();
    if (cli.update) return runUpdate(cli, chosen, scenes.empty() && techniques.empty());
    return runCheck(cli, chosen);
}

} // namespace sb
