// `bench report` on hostile folders: nothing lost, nothing unbounded, nothing unsafe. Each results
// folder is a few hand-written rows (no benchmark runs), and every check is an outcome the test sees
// itself: the file a planted link points at, the kind of a device node after the run, the run ending
// under its own timeout, the links of the page parsed from its attributes, the page's bytes on a full
// disk. The cases the bad-input table can hold (-o a device or a folder, an input that is a FIFO) are
// rows of tests/BadInputCliTest.cpp; the sorting of a column whose name holds a quote is checked in
// the browser by tests/ReportCliTest.cpp.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "HostileSupport.h"
#include "TestSupport.h"

namespace fs = std::filesystem;

namespace {

const std::string kBench = SB_BENCH_BINARY;
const std::string kRows = "technique,wall_ms_median\nnone,1.5\nshadowmap,2.5\n";

/// `command` with its stdout thrown away and its stderr on stdout (runCommand adds 2>&1 after it).
std::string stderrOnly(const std::string& command) {
    return "(" + command + " 2>&1 >/dev/null)";
}

/// `bench report ARGS` with stdout thrown away: the result's output is what it wrote on stderr.
sb::test::CommandResult reportErr(const std::string& args) {
    return sb::test::runCommand(stderrOnly(kBench + " report " + args));
}

/// The non-empty lines of `text`.
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> out;
    std::string line;
    for (char c : text) {
        if (c != '\n') {
            line += c;
            continue;
        }
        if (!line.empty()) out.push_back(line);
        line.clear();
    }
    if (!line.empty()) out.push_back(line);
    return out;
}

/// The values of every href and src attribute of `page`, entities &amp; &quot; &#x27; &lt; &gt;
/// turned back into their characters (the values a browser would follow).
std::vector<std::string> linkValues(const std::string& page) {
    std::vector<std::string> out;
    const std::regex attribute(R"re(\s(?:href|src)\s*=\s*"([^"]*)")re", std::regex::icase);
    for (auto m = std::sregex_iterator(page.begin(), page.end(), attribute); m != std::sregex_iterator();
         ++m) {
        std::string v = (*m)[1];
        const std::pair<const char*, const char*> entities[] = {
            {"&quot;", "\""}, {"&#x27;", "'"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}};
        for (const auto& [from, to] : entities)
            for (size_t at; (at = v.find(from)) != std::string::npos;)
                v.replace(at, std::string(from).size(), to);
        out.push_back(v);
    }
    return out;
}

/// `name` as RFC 3986 percent-encoding writes it with only unreserved characters kept: the link this
/// test expects for a file of that name beside the page (an independent encoder, not the script's).
std::string percentEncoded(const std::string& name) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : name) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~') {
            out += char(c);
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

bool validUtf8(const std::string& s) {
    for (size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        const size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
        if (n == 0 || i + n > s.size()) return false;
        for (size_t k = 1; k < n; ++k)
            if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return false;
        i += n;
    }
    return true;
}

// The page's temporary name is not followed: a link planted there towards a file outside the folder
// leaves that file as it was, and the page is written all the same; so does a link planted as the page
// itself. A dead writer's temporary file is cleared and the page written.
TEST(ReportHostileCli, PlantedPartialLinkIsNotFollowed) {
    const std::string dir = sb::test::freshTestDir("report-hostile");
    fs::create_directories(dir + "/results");
    sb::test::writeFile(dir + "/results/run.csv", kRows);
    sb::test::writeFile(dir + "/outside.txt", "not yours\n");
    fs::create_symlink(dir + "/outside.txt", dir + "/results/report.html.partial");
    const auto r = reportErr(dir + "/results");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(sb::test::readFile(dir + "/outside.txt"), "not yours\n");
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir + "/results/report.html")));
    EXPECT_EQ(sb::test::readFile(dir + "/results/report.html").rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_FALSE(fs::exists(fs::symlink_status(dir + "/results/report.html.partial")));

    // The page's own name planted as a link to a file outside: the link is replaced, the file kept.
    fs::remove(dir + "/results/report.html");
    fs::create_symlink(dir + "/outside.txt", dir + "/results/report.html");
    const auto page = reportErr(dir + "/results");
    EXPECT_EQ(page.exitCode, 0) << page.output;
    EXPECT_EQ(sb::test::readFile(dir + "/outside.txt"), "not yours\n");
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir + "/results/report.html")));

    sb::test::writeFile(dir + "/results/report.html.partial", "a writer killed half-way");
    const auto again = reportErr(dir + "/results");
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_FALSE(fs::exists(dir + "/results/report.html.partial"));
    EXPECT_EQ(sb::test::readFile(dir + "/results/report.html").rfind("<!DOCTYPE html>", 0), 0u);
    fs::remove_all(dir);
}

// -o naming a null device: refused (exit 2, one line naming it), and the node is still a character
// device afterwards (the old code renamed a regular file over it).
TEST(ReportHostileCli, DeviceNodeOutputStaysADevice) {
    const std::string dir = sb::test::freshTestDir("report-hostile");
    sb::test::writeFile(dir + "/run.csv", kRows);
    if (::mknod((dir + "/null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
        GTEST_SKIP() << "mknod needs root here";
    const auto r = reportErr(dir + " -o " + dir + "/null");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    ASSERT_EQ(linesOf(r.output).size(), 1u) << r.output;
    EXPECT_NE(r.output.find(dir + "/null"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("character device"), std::string::npos) << r.output;
    struct stat st {};
    ASSERT_EQ(::lstat((dir + "/null").c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    EXPECT_FALSE(fs::exists(dir + "/null.partial"));
    fs::remove_all(dir);
}

// A link to /dev/zero and a FIFO among the results (as a CSV, an image and a README): the report
// ends (the old one read /dev/zero without end, or blocked on the FIFO), well inside `timeout 30`,
// and names each skipped entry with its reason in one line on stderr and in the page.
TEST(ReportHostileCli, EndlessAndBlockingEntriesAreSkippedAndNamed) {
    const std::string dir = sb::test::freshTestDir("report-hostile");
    sb::test::writeFile(dir + "/run.csv", kRows);
    fs::create_symlink("/dev/zero", dir + "/zero.csv");
    fs::create_symlink("/dev/zero", dir + "/shot_none.png");
    fs::create_symlink("/dev/zero", dir + "/README.md");
    ASSERT_EQ(::mkfifo((dir + "/fifo.csv").c_str(), 0644), 0);
    const auto start = std::chrono::steady_clock::now();
    const auto r = sb::test::runCommand(stderrOnly("timeout 30 " + kBench + " report " + dir));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(r.exitCode, 0) << "124 is the timeout: " << r.output;
    // Generous against a loaded machine: the page of two rows takes well under a second.
    EXPECT_LT(seconds, 20.0);
    const std::vector<std::string> lines = linesOf(r.output);
    ASSERT_EQ(lines.size(), 1u) << r.output;
    for (const std::string entry : {"zero.csv", "shot_none.png", "README.md", "fifo.csv"})
        EXPECT_NE(lines[0].find(dir + "/" + entry), std::string::npos) << entry << ": " << lines[0];
    EXPECT_NE(lines[0].find("character device"), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("FIFO"), std::string::npos) << lines[0];
    const std::string page = sb::test::readFile(dir + "/report.html");
    const size_t listed = page.find("<ul id=\"skipped\">");
    ASSERT_NE(listed, std::string::npos);
    const std::string list = page.substr(listed, page.find("</ul>", listed) - listed);
    for (const std::string entry : {"zero.csv", "shot_none.png", "README.md", "fifo.csv"})
        EXPECT_NE(list.find(entry), std::string::npos) << entry;
    EXPECT_LT(page.size(), 1u << 20) << "nothing of /dev/zero in the page";
    fs::remove_all(dir);
}

// Images whose names are a script URL, and a name that is not UTF-8: every href and src of the page
// (parsed from its attributes) is a relative path with no scheme, the names percent-encoded as this
// test encodes them; the page is UTF-8 (the old script stopped with a traceback on the second name).
TEST(ReportHostileCli, ImageNamesNeverBecomeSchemesAndNonUtf8NamesAreShown) {
    const std::string dir = sb::test::freshTestDir("report-hostile");
    sb::test::writeFile(dir + "/run.csv", kRows);
    const std::vector<std::string> names = {"javascript:alert(document.domain).png", "data:text,x.png",
                                            "shot_\xff\xfe.png", "r\xe9sum\xe9 'q\" <b>.png"};
    for (const std::string& n : names) sb::test::writeFile(dir + "/" + n, "not really a PNG");
    sb::test::writeFile(dir + "/r\xe9.csv", kRows);
    const auto r = reportErr(dir);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output, "") << "nothing skipped, no traceback";
    const std::string page = sb::test::readFile(dir + "/report.html");
    EXPECT_TRUE(validUtf8(page));
    const std::vector<std::string> links = linkValues(page);
    ASSERT_FALSE(links.empty());
    const std::regex scheme("^[A-Za-z][A-Za-z0-9+.-]*:");
    for (const std::string& link : links) {
        SCOPED_TRACE(link);
        EXPECT_FALSE(std::regex_search(link, scheme)) << "a URL scheme";
        EXPECT_NE(link.rfind("/", 0), 0u) << "an absolute path or a host";
        EXPECT_EQ(link.find_first_of(" \"'<>\\"), std::string::npos);
    }
    for (const std::string& n : names) {
        const std::string expected = percentEncoded(n);
        EXPECT_NE(std::find(links.begin(), links.end(), expected), links.end()) << expected;
    }
    fs::remove_all(dir);
}

// A cell of 200 KiB (Python's csv module stops at 128 KiB by default): the page holds it whole, and the
// run is one line of success, not a traceback.
TEST(ReportHostileCli, CellLargerThan128KiBIsTabulated) {
    const std::string dir = sb::test::freshTestDir("report-hostile");
    const std::string cell = std::string(200 * 1024, 'x') + "END";
    sb::test::writeFile(dir + "/run.csv", "technique,error\nnone," + cell + "\n");
    const auto r = reportErr(dir);
    ASSERT_EQ(r.exitCode, 0) << r.output.substr(0, 2000);
    EXPECT_EQ(r.output, "");
    const std::string page = sb::test::readFile(dir + "/report.html");
    EXPECT_NE(page.find(">" + cell + "</td>"), std::string::npos);
    fs::remove_all(dir);
}

// A full disk (test::FullDisk): exit 1 as `--csv` on a full disk (AtomicFile: an OS failure), one
// line naming the page and the OS reason, the old page byte for byte, no temporary file left.
TEST(ReportHostileCli, FullDiskKeepsTheOldPageAndLeavesNoPartial) {
    const std::string dir = sb::test::freshTestDir("report-hostile");
    sb::test::writeFile(dir + "/run.csv", kRows);
    {
        sb::test::FullDisk disk(dir + "/full"); // unmounted at the end of this block, before the folder goes
        const std::string old = "<!DOCTYPE html><p>the page of yesterday</p>\n";
        disk.plant("report.html", old);
        const std::string page = disk.dir() + "/report.html";
        const auto r = sb::test::runCommand(disk.wrap(stderrOnly(kBench + " report " + dir + " -o " + page)));
        SCOPED_TRACE(disk.how());
        EXPECT_EQ(r.exitCode, 1) << r.output;
        const std::vector<std::string> lines = linesOf(r.output);
        ASSERT_EQ(lines.size(), 1u) << r.output;
        EXPECT_EQ(lines[0].rfind("bench: error: ", 0), 0u) << lines[0];
        EXPECT_NE(lines[0].find(page), std::string::npos) << lines[0];
        EXPECT_TRUE(lines[0].find("No space left on device") != std::string::npos ||
                    lines[0].find("File too large") != std::string::npos)
            << lines[0];
        EXPECT_EQ(sb::test::readFile(page), old);
        EXPECT_FALSE(fs::exists(fs::symlink_status(page + ".partial")));
    }
    fs::remove_all(dir);
}

} // namespace
