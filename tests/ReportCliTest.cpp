// `bench report` end to end, in a real browser: a small real run (three techniques, two rounds, their
// screenshots) is turned into a page by `bench report`, and headless Chromium loads it from file://.
// The checks are independent of tools/report.py: the page's script ran to its end without an error
// (the negative controls prove a syntax error and a run-time error are both caught), the table cells
// after the script ran are the CSV's cells (read here with CsvWriter), sorting through the heading's
// click handler puts the rows in the order this test computes from the CSV, the screenshots sit in the
// rows of their techniques, and a screenshot of the page is a real rendering. The page opens with
// pictures: a bar per row as long as its median time (checked against the CSV's medians), accuracy
// against time only where the rows hold accuracy (a hand-made column, the points checked against it),
// the screenshots side by side, and the table behind a closed toggle. Skipped without Debian's
// chromium package.
#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/golden/GoldenImage.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;

bool haveChromium() {
    return runCommand("command -v chromium").exitCode == 0;
}

/// The text of an HTML cell as Chromium serialises it, back to the characters (only the entities
/// the serialiser writes: &amp; &lt; &gt; &quot; &nbsp;).
std::string unescape(std::string s) {
    const std::pair<const char*, const char*> entities[] = {
        {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&nbsp;", "\xc2\xa0"}, {"&amp;", "&"}};
    for (const auto& [from, to] : entities)
        for (size_t at = s.find(from); at != std::string::npos;
             at = s.find(from, at + std::string(to).size()))
            s.replace(at, std::string(from).size(), to);
    return s;
}

struct Browser {
    std::string dom, log; ///< the DOM after the page's script ran; Chromium's stderr
    int exitCode = -1;
};

/// Loads `url` in headless Chromium and dumps the DOM once the load event's handlers have run. The
/// profile is per test directory, so parallel runs share nothing.
Browser load(const std::string& dir, const std::string& url, const std::string& extra = "") {
    const std::string dom = dir + "/dom.html", err = dir + "/chromium.log";
    Browser b;
    b.exitCode =
        runCommand("(timeout 60 chromium --headless --no-sandbox --disable-gpu --user-data-dir=" + dir +
                   "/profile --enable-logging=stderr --v=0 --virtual-time-budget=5000 " + extra +
                   " --dump-dom '" + url + "' > " + dom + " 2> " + err + ")")
            .exitCode;
    b.dom = test::readFile(dom);
    b.log = test::readFile(err);
    return b;
}

/// What is wrong with a loaded page's script, "" when nothing: it must have reached its end
/// (data-js-ready on <body>), reported no error into the page (data-js-errors, #js-errors) and logged
/// nothing to the console (Chromium writes page console messages and uncaught errors as CONSOLE lines).
std::string scriptProblems(const Browser& b) {
    std::string out;
    if (b.exitCode != 0) out += "chromium exit code " + std::to_string(b.exitCode) + "; ";
    if (b.dom.find("data-js-ready=\"1\"") == std::string::npos) out += "the script did not run to its end; ";
    if (b.dom.find("data-js-errors=") != std::string::npos) out += "the page reported script errors; ";
    std::smatch m;
    if (std::regex_search(b.dom, m, std::regex(R"re(<pre id="js-errors"[^>]*>([^<]+)</pre>)re")))
        out += "js-errors: " + m[1].str() + "; ";
    for (size_t at = b.log.find("CONSOLE"); at != std::string::npos; at = b.log.find("CONSOLE", at + 1))
        out += "console: " + b.log.substr(at, b.log.find('\n', at) - at) + "; ";
    return out;
}

/// Table `id`'s body rows in page order: each row's cells, column name -> text.
std::vector<std::map<std::string, std::string>> tableRows(const std::string& dom, const std::string& id) {
    std::vector<std::map<std::string, std::string>> rows;
    const size_t start = dom.find("<table class=\"rows\" id=\"" + id + "\"");
    if (start == std::string::npos) return rows;
    const std::string table = dom.substr(start, dom.find("</table>", start) - start);
    const std::regex row(R"re(<tr data-row="(\d+)">([\s\S]*?)</tr>)re");
    const std::regex cell(R"re(<td data-col="([^"]+)" data-value="[^"]*"[^>]*>([^<]*)</td>)re");
    for (auto r = std::sregex_iterator(table.begin(), table.end(), row); r != std::sregex_iterator(); ++r) {
        std::map<std::string, std::string> cells;
        const std::string body = (*r)[2];
        for (auto c = std::sregex_iterator(body.begin(), body.end(), cell); c != std::sregex_iterator(); ++c)
            cells[unescape((*c)[1])] = unescape((*c)[2]);
        cells["<html>"] = body;
        rows.push_back(cells);
    }
    return rows;
}

/// The sort order this test expects for a numeric column: by value, ties in CSV order (the rows'
/// numbers), as the page promises.
std::vector<std::string> expectedOrder(const CsvTable& csv, const std::string& column, bool descending) {
    const size_t k = size_t(std::find(csv.header.begin(), csv.header.end(), column) - csv.header.begin());
    std::vector<size_t> order(csv.rows.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const double x = std::stod(csv.rows[a][k]), y = std::stod(csv.rows[b][k]);
        return descending ? x > y : x < y;
    });
    std::vector<std::string> out;
    for (size_t i : order) out.push_back(std::to_string(i + 1));
    return out;
}

class ReportCli : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!haveChromium()) return;
        dir = test::freshDir("report-cli");
        // Three techniques, two rounds: six rows whose times differ, and a screenshot per technique.
        run = runCommand(
            kBench +
            " -t none -t shadowmap -t blob --repeat 2 --frames 3 --warmup 1 --size 128x128 -q --csv " + dir +
            "/run.csv --screenshot " + dir + "/shot.png");
        test::writeFile(dir + "/README.md",
                        "# A small run\n\n```sh\nbuild/bench -t none -t shadowmap -t blob "
                        "--repeat 2 --frames 3 --size 128x128 --csv run.csv\n```\n");
        report =
            runCommand(kBench + " report " + dir + " -o " + dir + "/page/index.html --title 'ReportCliTest'");
    }
    void SetUp() override {
        if (!haveChromium()) GTEST_SKIP() << "headless Chromium is needed: apt-get install chromium";
        ASSERT_EQ(run.exitCode, 0) << run.output;
        ASSERT_EQ(report.exitCode, 0) << report.output;
    }
    static std::string url(const std::string& fragment = "") {
        return "file://" + dir + "/page/index.html" + (fragment.empty() ? "" : "#" + fragment);
    }
    static inline std::string dir;
    static inline test::CommandResult run, report;
};

TEST_F(ReportCli, ScriptRunsCleanAndBrokenScriptsAreCaught) {
    const Browser good = load(dir, url());
    EXPECT_EQ(scriptProblems(good), "") << good.log.substr(0, 2000);

    // Negative controls: the same page with a syntax error in its main script, and with a run-time
    // error at its end, must both be reported by the check above.
    const std::string page = test::readFile(dir + "/page/index.html");
    const std::pair<std::string, std::string> breakages[] = {
        {"function sortTable(", "function sortTable((("},
        {"document.body.setAttribute(\"data-js-ready\", \"1\");",
         "null.boom; document.body.setAttribute(\"data-js-ready\", \"1\");"}};
    for (const auto& [from, to] : breakages) {
        SCOPED_TRACE(to);
        const size_t at = page.find(from);
        ASSERT_NE(at, std::string::npos) << "the page's script changed: update this negative control";
        std::string broken = page;
        broken.replace(at, from.size(), to);
        test::writeFile(dir + "/page/broken.html", broken);
        const Browser b = load(dir, "file://" + dir + "/page/broken.html");
        EXPECT_NE(scriptProblems(b), "");
        EXPECT_NE(b.log.find("Uncaught"), std::string::npos) << b.log.substr(0, 2000);
    }
}

TEST_F(ReportCli, TablesCarryTheCsvCellsAndImagesSitInTheirRows) {
    const Browser b = load(dir, url());
    ASSERT_EQ(scriptProblems(b), "");
    const CsvTable csv = CsvWriter::read(dir + "/run.csv");
    ASSERT_EQ(csv.rows.size(), 6u);
    const auto rows = tableRows(b.dom, "t1");
    ASSERT_EQ(rows.size(), csv.rows.size());
    // The key table shows these columns, cell for cell as the CSV has them; the "all columns" table
    // shows every column.
    const std::vector<std::string> key = {
        "status",    "technique", "scene",          "instances",  "width",       "height",
        "frames",    "repeat",    "wall_ms_median", "wall_ms_p5", "wall_ms_p95", "cpu_submit_ms_median",
        "fps_median"};
    const auto all = tableRows(b.dom, "t1-all");
    ASSERT_EQ(all.size(), csv.rows.size());
    for (size_t i = 0; i < csv.rows.size(); ++i) {
        SCOPED_TRACE("row " + std::to_string(i + 1));
        EXPECT_EQ(rows[i].at("row"), std::to_string(i + 1)) << "CSV order before any sorting";
        for (size_t k = 0; k < csv.header.size(); ++k) {
            const std::string& column = csv.header[k];
            const std::string value = k < csv.rows[i].size() ? csv.rows[i][k] : "";
            if (std::find(key.begin(), key.end(), column) != key.end()) {
                ASSERT_TRUE(rows[i].count(column)) << column;
                EXPECT_EQ(rows[i].at(column), value) << column;
            }
            ASSERT_TRUE(all[i].count(column)) << column;
            EXPECT_EQ(all[i].at(column), value) << column;
        }
        // bench --screenshot shot.png with several techniques writes shot_<technique>.png.
        const std::string technique = rows[i].at(col::kTechnique);
        EXPECT_NE(rows[i].at("<html>").find("shot_" + technique + ".png"), std::string::npos) << technique;
        for (const std::string other : {"none", "shadowmap", "blob"}) {
            if (other != technique) {
                EXPECT_EQ(rows[i].at("<html>").find("shot_" + other + ".png"), std::string::npos) << other;
            }
        }
    }
    // The environment: the renderer and the GL version the rows record.
    for (const std::string column : {"renderer", "gl_version", "cpu_model", "git_commit"}) {
        const size_t k = size_t(std::find(csv.header.begin(), csv.header.end(), column) - csv.header.begin());
        ASSERT_LT(k, csv.header.size()) << column;
        std::string cell = "<td data-col=\"" + column + "\">" + csv.rows[0][k] + "</td>";
        EXPECT_NE(unescape(b.dom).find(cell), std::string::npos) << cell;
    }
    // The commands: rebuilt from the rows, and the README's.
    const std::string text = unescape(b.dom);
    EXPECT_NE(text.find("bench -t none -t shadowmap:"), std::string::npos);
    EXPECT_NE(text.find("--size 128x128 --frames 3 --warmup 1 --repeat 2"), std::string::npos);
    EXPECT_NE(text.find("build/bench -t none -t shadowmap -t blob --repeat 2"), std::string::npos);
}

// Two configurations of one technique: each row shows the picture its row records (screenshot_file),
// never the other's, whatever the names have in common. Its own small run, not the fixture's; the rows
// are read from the page as written (they are static HTML: no browser needed).
TEST(ReportCliRows, EachRowShowsThePictureItRecords) {
    const std::string own = test::freshDir("report-cli-rows");
    const auto r = runCommand(kBench +
                              " -t shadowmap -t shadowmap:resolution=256 --frames 1 --warmup 0 "
                              "--size 64x64 --no-timer-check -q --csv " +
                              own + "/run.csv --screenshot " + own + "/shot.png");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto page = runCommand(kBench + " report " + own + " -o " + own + "/index.html");
    ASSERT_EQ(page.exitCode, 0) << page.output;
    const auto csv = test::csvRowMaps(own + "/run.csv");
    const auto rows = tableRows(test::readFile(own + "/index.html"), "t1");
    ASSERT_EQ(rows.size(), 2u);
    ASSERT_EQ(csv.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        ASSERT_TRUE(csv[i].count(col::kScreenshotFile)) << "row " << i + 1 << " records no screenshot";
        const std::string mine = csv[i].at(col::kScreenshotFile), other = csv[1 - i].at(col::kScreenshotFile);
        EXPECT_NE(rows[i].at("<html>").find("alt=\"" + mine + "\""), std::string::npos) << mine;
        EXPECT_EQ(rows[i].at("<html>").find("alt=\"" + other + "\""), std::string::npos) << other;
    }
}

// Column names holding the characters that end an HTML attribute, a CSS selector's string or a script's
// string (" < ' \): the page loads without a script error and sorting by the quoted column (the
// fragment #sort= clicks its heading) puts the rows in the order this test computes from the values.
// A CSV written by hand: no run needed.
TEST(ReportCliNames, ColumnNamesWithQuotesSortAndBreakNothing) {
    if (!haveChromium()) GTEST_SKIP() << "headless Chromium is needed: apt-get install chromium";
    const std::string own = test::freshDir("report-cli-names");
    test::writeFile(own + "/run.csv",
                    "technique,\"a\"\"b\",c<d,e'f,g\\h\nnone,3,x,2,b\nshadowmap,1,y,5,a\nblob,2,z,1,c\n");
    const auto page = runCommand(kBench + " report " + own + " -o " + own + "/index.html");
    ASSERT_EQ(page.exitCode, 0) << page.output;
    // a"b descending: 3 (row 1), 2 (row 3), 1 (row 2).
    const Browser b = load(own, "file://" + own + "/index.html#sort=t1:a%22b:desc");
    EXPECT_EQ(scriptProblems(b), "") << b.log.substr(0, 2000);
    std::vector<std::string> order;
    for (const auto& r : tableRows(b.dom, "t1")) order.push_back(r.at("row"));
    EXPECT_EQ(order, (std::vector<std::string>{"1", "3", "2"}));
    for (const std::string name : {"a\"b", "c<d", "e'f", "g\\h"})
        EXPECT_TRUE(tableRows(b.dom, "t1").at(0).count(name)) << name << " is a column of the table";
}

TEST_F(ReportCli, SortingByClickOrdersTheRows) {
    const CsvTable csv = CsvWriter::read(dir + "/run.csv");
    bool moved = false;
    for (const bool descending : {false, true}) {
        SCOPED_TRACE(descending ? "descending" : "ascending");
        const Browser b =
            load(dir, url(std::string("sort=t1:wall_ms_median:") + (descending ? "desc" : "asc")));
        ASSERT_EQ(scriptProblems(b), "");
        std::vector<std::string> order;
        for (const auto& r : tableRows(b.dom, "t1")) order.push_back(r.at("row"));
        const std::vector<std::string> expected = expectedOrder(csv, "wall_ms_median", descending);
        EXPECT_EQ(order, expected);
        moved = moved || expected != std::vector<std::string>{"1", "2", "3", "4", "5", "6"};
    }
    EXPECT_TRUE(moved) << "the CSV's order was already sorted both ways: the check above proved nothing";

    // The page's own self-test clicks every heading of every table twice and checks each order.
    const Browser self = load(dir, url("selftest"));
    ASSERT_EQ(scriptProblems(self), "");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(
        self.dom, m, std::regex(R"re(<output id="selftest" data-checks="(\d+)" data-result="(\w+)">)re")))
        << self.dom.substr(0, 3000);
    EXPECT_EQ(m[2].str(), "pass") << self.dom.substr(0, 3000);
    // Two clicks per sortable column: the key table's and the all-columns table's, plus their "row".
    EXPECT_GE(std::stoi(m[1].str()), 2 * int(csv.header.size() + 1));
}

/// Every `<tag ...>` of `svg` (a chart's text) whose class is `cls`: its attributes, name -> value.
std::vector<std::map<std::string, std::string>> svgElements(const std::string& svg, const std::string& tag,
                                                            const std::string& cls) {
    std::vector<std::map<std::string, std::string>> out;
    const std::regex element("<" + tag + R"re((\s[^>]*)>)re"), attribute(R"re(([\w-]+)="([^"]*)")re");
    for (auto e = std::sregex_iterator(svg.begin(), svg.end(), element); e != std::sregex_iterator(); ++e) {
        std::map<std::string, std::string> attributes;
        const std::string text = (*e)[1];
        for (auto a = std::sregex_iterator(text.begin(), text.end(), attribute); a != std::sregex_iterator();
             ++a)
            attributes[(*a)[1]] = (*a)[2];
        if (attributes["class"] == cls) out.push_back(attributes);
    }
    return out;
}

/// The element `<svg id="id" ...>...</svg>` of a page, "" when it has none.
std::string svgById(const std::string& dom, const std::string& id) {
    const size_t start = dom.find("<svg id=\"" + id + "\"");
    return start == std::string::npos ? "" : dom.substr(start, dom.find("</svg>", start) - start);
}

/// Column `name` of every CSV row, as numbers.
std::vector<double> csvNumbers(const CsvTable& csv, const std::string& name) {
    const size_t k = size_t(std::find(csv.header.begin(), csv.header.end(), name) - csv.header.begin());
    std::vector<double> out;
    for (const auto& row : csv.rows) out.push_back(k < row.size() ? std::stod(row[k]) : 0.0);
    return out;
}

TEST_F(ReportCli, PicturesLeadThePageAndTheTableWaitsBehindAToggle) {
    const Browser b = load(dir, url());
    ASSERT_EQ(scriptProblems(b), "");
    const CsvTable csv = CsvWriter::read(dir + "/run.csv");
    // The first picture of the page is the time chart, above the environment and every table.
    const size_t chart = b.dom.find("<svg id=\"t1-time\"");
    ASSERT_NE(chart, std::string::npos) << b.dom.substr(0, 3000);
    EXPECT_EQ(chart, b.dom.find("<svg")) << "another picture comes first";
    EXPECT_LT(chart, b.dom.find("<table"));
    EXPECT_LT(chart, b.dom.find(">Environment<"));
    // One bar per row, fastest first, each as long as its median (the axis starts at 0): width over
    // median is the same for every bar, within 1%.
    const std::vector<double> medians = csvNumbers(csv, "wall_ms_median");
    const auto bars = svgElements(svgById(b.dom, "t1-time"), "rect", "bar");
    ASSERT_EQ(bars.size(), csv.rows.size());
    std::set<size_t> seen;
    double scale = 0.0, previous = 0.0;
    for (const auto& bar : bars) {
        const size_t row = std::stoul(bar.at("data-row"));
        ASSERT_GE(row, 1u);
        ASSERT_LE(row, csv.rows.size());
        seen.insert(row);
        const double median = medians[row - 1], width = std::stod(bar.at("width"));
        EXPECT_GE(median, previous) << "bars sorted by time";
        previous = median;
        if (scale == 0.0) scale = width / median;
        EXPECT_NEAR(width / median, scale, 0.01 * scale) << "row " << row;
    }
    EXPECT_EQ(seen.size(), csv.rows.size()) << "each row once";
    // Without accuracy columns there is no accuracy plot.
    EXPECT_TRUE(std::none_of(csv.header.begin(), csv.header.end(),
                             [](const std::string& c) { return c.rfind("acc_", 0) == 0; }));
    EXPECT_EQ(b.dom.find("t1-accuracy"), std::string::npos);
    // The screenshots side by side, before the table.
    const size_t gallery = b.dom.find("<div class=\"gallery\">");
    ASSERT_NE(gallery, std::string::npos);
    for (const std::string technique : {"none", "shadowmap", "blob"})
        EXPECT_LT(b.dom.find("shot_" + technique + ".png", gallery), b.dom.find("<table class=\"rows\""));
    // The table sits inside a closed <details>.
    const size_t table = b.dom.find("<table class=\"rows\" id=\"t1\"");
    ASSERT_NE(table, std::string::npos);
    const size_t details = b.dom.rfind("<details", table);
    ASSERT_NE(details, std::string::npos);
    EXPECT_EQ(b.dom.find("</details>", details), b.dom.find("</details>", table))
        << "closed before the table";
    const std::string tag = b.dom.substr(details, b.dom.find('>', details) - details);
    EXPECT_EQ(tag.find("open"), std::string::npos) << tag;
}

TEST_F(ReportCli, AccuracyIsPlottedAgainstTimeWhereMeasured) {
    // The run's rows with an accuracy column added by hand: the plot must place each row at its median
    // time (x) and its accuracy (y, up is worse).
    const std::string acc = dir + "/accuracy";
    std::filesystem::create_directories(acc);
    CsvTable csv = CsvWriter::read(dir + "/run.csv");
    const std::vector<std::string> wrong = {"12.5", "3.25", "0.5", "12", "3", "0.75"};
    ASSERT_EQ(csv.rows.size(), wrong.size());
    csv.header.push_back("acc_wrong_pct");
    for (size_t i = 0; i < csv.rows.size(); ++i) csv.rows[i].push_back(wrong[i]);
    CsvWriter::writeTable(acc + "/acc.csv", csv);
    const auto made = runCommand(kBench + " report " + acc + " -o " + acc + "/index.html");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    const Browser b = load(dir, "file://" + acc + "/index.html");
    ASSERT_EQ(scriptProblems(b), "");
    const std::string plot = svgById(b.dom, "t1-accuracy");
    ASSERT_NE(plot, "") << b.dom.substr(0, 3000);
    EXPECT_LT(b.dom.find("<svg id=\"t1-time\""), b.dom.find("<svg id=\"t1-accuracy\""));
    const auto points = svgElements(plot, "circle", "point");
    ASSERT_EQ(points.size(), csv.rows.size());
    const std::vector<double> medians = csvNumbers(csv, "wall_ms_median");
    // Positions are linear in the values from a common origin: x - x0 proportional to the median and
    // y0 - y to the accuracy. Two points fix each line; every other point must lie on it within 1%.
    std::map<size_t, std::pair<double, double>> at;
    for (const auto& p : points)
        at[std::stoul(p.at("data-row"))] = {std::stod(p.at("cx")), std::stod(p.at("cy"))};
    ASSERT_EQ(at.size(), csv.rows.size());
    const double kx = (at[2].first - at[1].first) / (medians[1] - medians[0]);
    const double ky = (at[2].second - at[1].second) / (12.5 - 3.25);
    for (size_t row = 1; row <= csv.rows.size(); ++row) {
        SCOPED_TRACE("row " + std::to_string(row));
        const double span = (at[2].first - at[1].first);
        EXPECT_NEAR(at[row].first - at[1].first, kx * (medians[row - 1] - medians[0]), 0.01 * std::abs(span));
        EXPECT_NEAR(at[row].second - at[1].second, ky * (12.5 - std::stod(wrong[row - 1])), 0.01 * ky * 12.5);
    }
    EXPECT_GT(ky, 0.0) << "more wrong pixels are drawn higher";
}

TEST_F(ReportCli, ScreenshotIsARealRendering) {
    const std::string png = dir + "/page.png";
    const int rc =
        runCommand("timeout 60 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
                   "--user-data-dir=" +
                   dir + "/profile --virtual-time-budget=5000 --window-size=1200,1600 --screenshot=" + png +
                   " '" + url() + "'")
            .exitCode;
    ASSERT_EQ(rc, 0);
    const Image8 image = GoldenImage::read(png);
    EXPECT_EQ(image.width, 1200);
    EXPECT_EQ(image.height, 1600);
    // Text, tables and the screenshots drawn: many colours (a blank or error page has a handful), and
    // a fair share of the page not background white.
    std::set<uint32_t> colours;
    size_t inked = 0;
    const int c = image.channels;
    for (size_t p = 0; p < image.pixelCount(); ++p) {
        const uint8_t* px = &image.pixels[p * size_t(c)];
        colours.insert(uint32_t(px[0]) << 16 | uint32_t(px[c > 1 ? 1 : 0]) << 8 | px[c > 2 ? 2 : 0]);
        if (px[0] < 200 || px[c > 1 ? 1 : 0] < 200 || px[c > 2 ? 2 : 0] < 200) ++inked;
    }
    EXPECT_GT(colours.size(), 200u);
    EXPECT_GT(double(inked) / double(image.pixelCount()), 0.01);
}

TEST_F(ReportCli, BadInputsExitWithBenchCodes) {
    auto missing = runCommand(kBench + " report " + dir + "/nosuch");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("nosuch"), std::string::npos) << missing.output;
    const std::string empty = dir + "/empty";
    std::filesystem::create_directories(empty);
    auto nothing = runCommand(kBench + " report " + empty);
    EXPECT_EQ(nothing.exitCode, 2) << nothing.output;
    auto noPython = runCommand("SHADOWBENCH_PYTHON=/nonexistent/python3 " + kBench + " report " + dir);
    EXPECT_EQ(noPython.exitCode, 3) << noPython.output;
    EXPECT_NE(noPython.output.find("python3"), std::string::npos) << noPython.output;
    auto help = runCommand(kBench + " report --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("Examples:"), std::string::npos) << help.output;
}

} // namespace
