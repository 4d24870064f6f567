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
#include "bench/golden/MatrixPage.h"
#include "bench/golden/MatrixProgress.h"
#include "bench/golden/MatrixVariants.h"
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
    if (!v.notRun.empty()) { // always said: a cell this driver cannot run is not checked here
        out << v.cell << ": not run: " << v.notRun << "\n";
        return out.str();
    }
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
    size_t checked = 0, unsupported = 0, failed = 0, notRun = 0;
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
            notRun += !v.notRun.empty();
            checked += !skipped && v.notRun.empty();
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
              << " unsupported (--verbose lists them), " << notRun
              << " not run on this driver (listed above) against " << cli.dir << " on the driver "
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

/// The cell a technique's row and golden come from (GoldenMatrix::goldenCellOf; the GL retained cell
/// itself when the scene's cells lack it).
const MatrixCell& goldenCell(const std::vector<MatrixCell>& cells, const MatrixCell& glRetained) {
    const MatrixCell* cell = GoldenMatrix::goldenCellOf(cells, glRetained);
    return cell ? *cell : glRetained;
}

/// " on the driver NAME" where the update runs on a driver other than the system's.
std::string driverNote() {
    const std::string driver = DriverTable::current();
    return driver == "system" ? "" : " on the driver " + driver;
}

/// How many of a technique's cells of one API ran and passed every check, or why they did not run.
std::string modesText(const std::vector<CellVerdict>& verdicts, const std::vector<MatrixCell>& cells,
                      const std::string& technique, bool vulkan) {
    size_t modes = 0, passed = 0;
    std::string why;
    for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].technique != technique || cells[i].vulkan() != vulkan) continue;
        if (!cells[i].unsupported.empty()) {
            why = cells[i].unsupported;
            continue;
        }
        ++modes;
        passed += verdicts[i].passed() && cells[i].ran();
    }
    return modes ? std::to_string(passed) + "/" + std::to_string(modes) + " pass"
                 : "unsupported (" + why + ")";
}

/// One line of MATRIX.md: the golden cell's accuracy and bound, how many modes of each API pass every
/// check. "" for a golden cell this driver cannot run: its row is the page's as it was (MatrixPage).
std::string matrixRow(const std::vector<CellVerdict>& verdicts, const std::vector<MatrixCell>& cells,
                      const MatrixCell& glRetained) {
    const MatrixCell& golden = goldenCell(cells, glRetained);
    if (golden.refusal == MatrixCell::Refusal::Driver) return "";
    std::ostringstream row;
    row << "| " << MatrixVariants::key(golden.technique) << " | " << golden.scene << " | ";
    if (golden.autoPick)
        row << "chose " << golden.autoPick->spec.substr(0, golden.autoPick->spec.find(':')) << ", ";
    if (!golden.unsupported.empty()) {
        row << "unsupported | " << golden.unsupported << " |";
        return row.str();
    }
    if (glRetained.refusal == MatrixCell::Refusal::NoForm)
        row << "no GL form (" << glRetained.unsupported << ")";
    else
        row << modesText(verdicts, cells, golden.technique, false);
    row << "; Vulkan " << modesText(verdicts, cells, golden.technique, true) << driverNote() << " | ";
    for (size_t l = 0; l < golden.lights.size(); ++l) {
        const AccuracyBound b = AccuracyBounds::derive(golden, l);
        std::ostringstream value;
        value.precision(3);
        if (l) value << "; ";
        if (b.judged())
            value << b.metric << " " << b.measured(golden.lights[l]) << " <= " << b.max << " (" << b.rule
                  << ")";
        else
            value << "not judged";
        row << value.str();
    }
    row << " |";
    return row.str();
}

/// The row of a technique whose golden cell this driver cannot run and that the page has no row of yet.
std::string notRunRow(const MatrixCell& golden) {
    return "| " + MatrixVariants::key(golden.technique) + " | " + golden.scene + " | not run on the driver " +
           DriverTable::current() + " (" + golden.unsupported + "): bench golden --update --technique " +
           golden.technique + " on a driver that has it writes this row | - |";
}

/// Writes the golden cells' goldens and returns their bounds with the measured values. A golden cell
/// this driver cannot run keeps its goldens and bounds: they are judged where it runs.
void writeGoldens(const GoldenCli& cli, const std::vector<MatrixCell>& cells,
                  std::map<std::string, std::pair<AccuracyBound, double>>& fresh) {
    for (const MatrixCell& cell : cells) {
        // An `auto` cell has no golden of its own: it is held to the chosen technique's.
        if (!cell.failure.empty() || cell.technique == AutoResolver::kName ||
            GoldenMatrix::goldenCellOf(cells, cell) != &cell || cell.refusal == MatrixCell::Refusal::Driver)
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
    // The cells not rendered this time as they were (their value as measured when last written), the
    // fresh ones replacing theirs: one map, so the file stays sorted by cell whatever was updated.
    std::map<std::string, std::pair<AccuracyBound, double>> all;
    for (const auto& [name, b] : readBounds(dir)) all[name] = {b, b.recorded};
    for (const auto& [name, entry] : fresh) all[name] = entry;
    std::vector<AccuracyBound> bounds;
    std::vector<double> measured;
    for (const auto& [name, entry] : all) {
        bounds.push_back(entry.first);
        measured.push_back(entry.second);
    }
    CsvWriter::writeText(dir + "/bounds.json", AccuracyBounds::toJson(bounds, measured));
}

/// The exception lines of a golden cell: its lights held to an exception instead of their rule.
std::vector<std::string> exceptionLines(const MatrixCell& golden) {
    std::vector<std::string> out;
    if (!golden.ran() || golden.autoPick) return out;
    for (size_t l = 0; l < golden.lights.size(); ++l) {
        const AccuracyBound b = AccuracyBounds::derive(golden, l);
        if (b.rule == "exception") out.push_back("- `" + b.cell + "`: " + b.why);
    }
    return out;
}

/// The keys of the page's rows, in the matrix's order: the registry's techniques, each followed by its
/// variants, then `auto`.
std::vector<std::string> pageTechniques() {
    std::vector<std::string> out;
    for (const std::string& form : MatrixVariants::all()) out.push_back(MatrixVariants::key(form));
    out.push_back(AutoResolver::kName);
    return out;
}

int runUpdate(const GoldenCli& cli, const std::vector<std::string>& scenes) {
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
    const std::string pagePath = cli.dir + "/MATRIX.md";
    MatrixPage page = MatrixPage::read(pagePath);
    size_t failed = 0, written = 0, kept = 0;
    for (const std::vector<MatrixCell>& cells : rendered) {
        const std::vector<CellVerdict> verdicts = MatrixCheck::check(cells, cli.dir, bounds);
        for (size_t i = 0; i < cells.size(); ++i) {
            if (!verdicts[i].passed()) {
                ++failed;
                std::cout << verdicts[i].cell << ": FAILED\n";
                for (const std::string& f : verdicts[i].failures) std::cout << "  " << f << "\n";
            }
            if (cells[i].mode != SubmitMode::Retained || cells[i].vulkan()) continue; // one row a technique
            const MatrixCell& golden = goldenCell(cells, cells[i]);
            const std::string key = MatrixVariants::key(golden.technique);
            const std::string row = matrixRow(verdicts, cells, cells[i]);
            if (!row.empty()) {
                page.set(key, golden.scene, row, exceptionLines(golden));
                written += golden.ran();
            } else if (page.has(key, golden.scene)) {
                ++kept;
            } else {
                page.set(key, golden.scene, notRunRow(golden), {});
            }
        }
    }
    CsvWriter::writeText(pagePath,
                         page.text(cli.matrix.size, GoldenMatrix::builtinScenes(), pageTechniques()));
    std::cout << "golden update: " << written << " technique x scene goldens in " << cli.dir
              << " and their rows of MATRIX.md (" << kept
              << " rows of cells this driver cannot run kept as they were); " << failed
              << " cells fail their checks\n";
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
  bench --driver mesa-25.0.7 golden --update --technique raytraced:mode=guided
                                               one variant's goldens, on the driver that runs it

Each cell: every submission mode's image must equal retained's, the retained image the golden
(results/goldens/<scene>/<technique>.{visibility,colour}.png), and the accuracy against the Embree
reference its bound in results/goldens/bounds.json. Exit 1 when a cell fails. An image that no
longer matches its golden gets pictures of where it differs in --diff-dir, their paths printed
under the cell (bench/golden/GoldenDiff.h).

A technique may declare variants (bench --list: its "matrix:" line), forms at other properties
with cells of their own, named by their spec (raytraced:mode=soft) and keyed by it with ':' as
'.' (raytraced.mode=soft.visibility.png, bounds "raytraced.mode=soft/<scene>/light0", its own
row of MATRIX.md). --technique NAME selects a technique with its variants, --technique SPEC one
variant. An update of some scenes or techniques keeps every other golden, bound and row.)");
    GoldenCli cli;
    std::vector<std::string> scenes, techniques;
    auto* check = app.add_flag("--check", cli.check, "judge every cell (the default)");
    app.add_flag("--update", cli.update, "rewrite goldens and bounds from this build's images")
        ->excludes(check);
    app.add_option("--scene", scenes, "comma-separated built-in scenes (default: all)")->delimiter(',');
    app.add_option("--technique", techniques,
                   "comma-separated techniques, each with the variants it declares (--list: matrix), or "
                   "one variant by its spec, e.g. raytraced:mode=soft (default: all)")
        ->delimiter(',');
    app.add_option("--size", cli.matrix.size, "frame size (default 128, the size of the committed goldens)")
        ->check(CLI::Range(16, 1024));
    app.add_option("--dir", cli.dir, "golden folder (default: the source tree's results/goldens)");
    app.add_option("--diff-dir", cli.diffDir,
                   "--check: write an error map and a signed difference map of every image that no longer "
                   "matches its golden into this folder (default: shadowbench-golden-diff in the temporary "
                   "directory)");
    app.add_flag("-v,--verbose", cli.verbose, "print every cell, its comparisons and unsupported cells");
    app.add_flag("--strict-driver", cli.matrix.strictDriver,
                 "a cell whose form needs a capability this driver lacks fails (default: it is listed as "
                 "not run here); for the check on the driver that is to run it");
    std::string driver; // acted on by BenchApp: the process already runs on it
    DriverOption::add(app, driver);
    if (int code = parseCli(app, argc, argv, "bench golden"); code >= 0) return code;
    const std::vector<std::string> known = GoldenMatrix::builtinScenes();
    const std::vector<std::string> chosen = scenes.empty() ? known : scenes;
    for (const std::string& s : chosen)
        if (std::find(known.begin(), known.end(), s) == known.end())
            throw Error("--scene " + s + ": not a built-in scene" + Suggestion::didYouMean(s, known) +
                        " (known: " + join(known, ", ") + ")");
    cli.matrix.techniques = MatrixVariants::select(techniques); // names what is unknown
    if (cli.dir.empty()) cli.dir = defaultGoldenDir();
    std::error_code ec; // --check reads the goldens; --update may write a new folder
    if (!cli.update && !std::filesystem::is_directory(cli.dir, ec))
        throw Error("--dir " + cli.dir + ": no such folder of goldens");
    if (cli.update && !cli.diffDir.empty())
        throw Error("--diff-dir belongs to --check (see bench golden --help)");
    if (cli.diffDir.empty()) cli.diffDir = defaultDiffDir();
    if (cli.update) return runUpdate(cli, chosen);
    return runCheck(cli, chosen);
}

} // namespace sb
