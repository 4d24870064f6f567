#!/usr/bin/python3
"""One static HTML page from result CSVs, figures and images (`bench report`, bench/report/ReportCommand.h).

  /usr/bin/python3 tools/report.py DIR_OR_FILE... [--out PAGE.html] [--title T] [--embed]

Each argument is a result CSV, an image (PNG, SVG, JPEG), a README.md, or a folder searched for them
(recursively, in name order). The page opens with pictures, per CSV: a bar chart of each row's median
wall time (wall_ms_median) with its p5-p95 interval, fastest first; where the rows hold accuracy
(acc_wrong_pct, ...), that accuracy against the time as a scatter; then the rows' screenshots side by
side (inline SVG drawn here, no script library). Below, per CSV and behind a toggle (<details>), a table
of its rows (the key columns; every column under "all columns"), sortable by a click on a heading with
the page's own script (no server, nothing fetched: the page works from file://), the figures of the
CSV's folder beside it, and each row's screenshot where `bench --screenshot` named one after its
technique (shot_<technique>.png). Between them: the environment the rows record (renderer, GL version, CPU, commit ...) and the
commands that rerun them, rebuilt from the rows' columns, with the commands a README beside them gives.

The page is the same bytes for the same inputs (no generation time), so a committed example stays put.
Images are linked relative to the page, or with --embed written into it (a single file to send).

The script checks itself: a page opened with #selftest sorts every table by every column both ways
and writes the verdict into <output id="selftest">; #sort=TABLE:COLUMN:asc|desc sorts one table on
load as a click would. Script errors are written into <pre id="js-errors">, and <body> gets
data-js-ready="1" once the script has run to its end (tests/ReportCliTest.cpp reads both).

Hostile folders: only regular files are read, each within a size bound (a link to /dev/zero, a FIFO,
a file over its bound is skipped and named in the page and in one line on stderr); every link is a
percent-encoded relative path (no file name becomes a scheme); the page is written by the CSV writer's
rules (write_page). Every failure is one line "report.py: ..." on stderr: exit 2 wrong input, 1 an
OS failure such as a full disk.

Python standard library only (csv, html), so /usr/bin/python3 of any Debian 12 runs it.
"""
import argparse
import base64
import csv
import fcntl
import html
import io
import math
import os
import re
import stat
import sys
import urllib.parse

CSV_LIMIT = 10 * 1024 * 1024  # a result CSV larger than this is listed, not tabulated
# Every file read is read through one descriptor checked to be a regular file no larger than its bound,
# so a link to /dev/zero, a FIFO or a huge file costs nothing (each is skipped and listed instead).
README_LIMIT = 1024 * 1024  # a README.md larger than this is skipped
EMBED_LIMIT = 16 * 1024 * 1024  # with --embed, a larger image is skipped (the page is one file to send)
# The one temporary name of the page's writer, beside the page (write_page).
PARTIAL_SUFFIX = ".partial"
# A link of the page is a relative path, every byte outside these percent-encoded: no scheme ("javascript:"
# needs its colon), no host, no absolute path can appear.
SAFE_URL = re.compile(r"[A-Za-z0-9._~%/-]+")
IMAGE_EXTS = (".png", ".svg", ".jpg", ".jpeg", ".gif")
# The key columns of a bench row, in this order, where present (README.md, "CSV columns").
KEY_COLUMNS = [
    "status", "technique", "technique_spec", "properties", "scene", "instances", "camera", "submit", "width",
    "height", "frames", "repeat", "wall_ms_median", "wall_ms_p5", "wall_ms_p95", "cpu_submit_ms_median",
    "gpu_ms_median", "fps_median", "wall_ratio_vs_baseline", "acc_wrong_pct", "acc_wrong_no_edge_pct",
    "acc_rmse", "timer_verdict", "error",
]
# What a row says about the machine and build that measured it.
ENVIRONMENT_COLUMNS = [
    "api", "api_version", "renderer", "gl_version", "gl_vendor", "backend", "device", "cpu_model", "hw_threads",
    "lp_num_threads", "host", "slurm_job_id", "slurm_array_task_id", "git_commit", "timestamp",
]
WIDE = 14  # a table with more columns than this shows the key ones, the rest under "all columns"


def display(text):
    """`text` (a path or an argument, which may hold bytes that are not UTF-8) as text the page and
    messages can hold: each undecodable byte becomes U+FFFD."""
    return os.fsencode(text).decode("utf-8", "replace")


def say(message):
    """`message` as one line on stderr: a control character of a file name ("\\n") is written as \\xNN."""
    text = re.sub(r"[\x00-\x1f\x7f]", lambda m: f"\\x{ord(m.group()):02x}", display(message))
    print(f"report.py: {text}", file=sys.stderr)


def bad_input(message):
    """Exit code 2, bench's code for wrong input (core/Error.h), with the message on stderr (one line)."""
    say(message)
    sys.exit(2)


def os_failure(message):
    """Exit code 1, bench's code for a failure of the OS (a full disk), as the CSV writer reports it."""
    say(message)
    sys.exit(1)


def kind_of(mode):
    """What a file that is not a regular file is, in words (bench/lib/output/AtomicFile.cpp's words)."""
    for test, kind in ((stat.S_ISDIR, "a directory"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISFIFO, "a FIFO"), (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return kind
    return "not a regular file"


class Skipped(Exception):
    """An entry left out of the page: the reason, in words ("a FIFO", "larger than 1 MiB")."""


def mib(n):
    return f"{n // (1024 * 1024)} MiB"


def check_entry(path, limit=None):
    """The size of `path` (a link is followed), or Skipped when it is not a regular file or is larger
    than `limit`. Only stat() here: nothing is opened, so a FIFO cannot block."""
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise Skipped("a broken link") from None
    except OSError as e:
        raise Skipped(f"cannot inspect it: {e.strerror}") from None
    if not stat.S_ISREG(st.st_mode):
        raise Skipped(kind_of(st.st_mode) + ", not a regular file")
    if limit is not None and st.st_size > limit:
        raise Skipped(f"larger than {mib(limit)}")
    return st.st_size


def open_regular(path, limit):
    """`path` opened for reading (binary), checked through its descriptor: a regular file of at most
    `limit` bytes, else Skipped. O_NONBLOCK: a FIFO swapped in after check_entry does not block the open."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOCTTY | os.O_CLOEXEC)
    except OSError as e:
        raise Skipped(f"cannot open it: {e.strerror}") from None
    st = os.fstat(fd)
    if not stat.S_ISREG(st.st_mode) or st.st_size > limit:
        os.close(fd)
        raise Skipped(kind_of(st.st_mode) + ", not a regular file" if not stat.S_ISREG(st.st_mode)
                      else f"larger than {mib(limit)}")
    return os.fdopen(fd, "rb")


def read_text(path, limit):
    """A text file's content (bytes that are not UTF-8 replaced), at most `limit` bytes read."""
    with open_regular(path, limit) as f:
        return f.read(limit + 1).decode("utf-8", "replace")


def read_csv(path):
    """The header and rows of a CSV of at most CSV_LIMIT bytes (Skipped when larger). A cell may be as
    large as the file; a malformed one stops the report naming the file and the line (exit 2)."""
    csv.field_size_limit(CSV_LIMIT)  # the default 128 KiB is smaller than a file this script accepts
    with open_regular(path, CSV_LIMIT) as f:
        reader = csv.reader(io.TextIOWrapper(f, encoding="utf-8", errors="replace", newline=""))
        try:
            rows = list(reader)
        except csv.Error as e:
            bad_input(f"{path}: line {reader.line_num}: {e}")
    if not rows:
        return [], []
    header, body = rows[0], rows[1:]
    return header, [r + [""] * (len(header) - len(r)) for r in body]


def collect(paths, out_path, embed, skipped):
    """The CSVs, images and READMEs of the arguments, in a stable order; the page itself left out. Only
    regular files (a link is followed) within their size bound are taken, and only images whose link
    can be made safe; every other entry of those kinds is appended to `skipped` as (path, why)."""
    csvs, images, readmes = [], [], []
    out_real = os.path.realpath(out_path)
    out_dir = os.path.dirname(os.path.abspath(out_path))

    def add(path):
        low = path.lower()
        if low.endswith(".csv"):
            found, limit = csvs, None  # a larger CSV is listed as such (build)
        elif low.endswith(IMAGE_EXTS):
            found, limit = images, EMBED_LIMIT if embed else None
        elif os.path.basename(low) == "readme.md":
            found, limit = readmes, README_LIMIT
        else:
            return
        if os.path.realpath(path) == out_real:
            return
        try:
            check_entry(path, limit)
            if found is images and href(path, out_dir) is None:
                raise Skipped("its name cannot be written as a safe relative link")
        except Skipped as why:
            skipped.append((path, str(why)))
            return
        found.append(path)

    def unreadable(error):
        skipped.append((error.filename, f"cannot list it: {error.strerror}"))

    for p in paths:
        try:
            mode = os.stat(p).st_mode
        except OSError:
            bad_input(f"{p}: no such file or folder")
        if stat.S_ISDIR(mode):
            # Links to folders are not followed (os.walk's default): a loop cannot make the walk endless.
            for root, dirs, files in os.walk(p, onerror=unreadable):
                dirs.sort()
                for name in sorted(files):
                    add(os.path.join(root, name))
        elif stat.S_ISREG(mode):
            add(p)
        else:
            bad_input(f"{p}: it is {kind_of(mode)}, not a regular file or a folder")
    return csvs, images, readmes


def is_number(text):
    try:
        float(text)
        return text.strip() != ""
    except ValueError:
        return False


def href(path, out_dir):
    """`path` as a link of the page: relative to the page's folder, every byte but letters, digits and
    "._~-/" percent-encoded (a name that is not UTF-8 too), so no scheme, host or absolute path can
    appear; None where the result would still not be a plain relative path."""
    rel = os.path.relpath(path, out_dir).replace(os.sep, "/")
    url = urllib.parse.quote(os.fsencode(rel), safe="/")
    return url if SAFE_URL.fullmatch(url) and not url.startswith("/") else None


# The data: URLs of --embed, each image read once however often the page shows it.
EMBEDDED = {}
EMBED_TYPES = {"png": "image/png", "svg": "image/svg+xml", "jpg": "image/jpeg", "jpeg": "image/jpeg",
               "gif": "image/gif"}


def src(path, out_dir, embed):
    """The src of an image: its safe relative link, or with --embed the file itself as a data: URL of
    an image type ("" where the file changed into something unreadable since it was collected)."""
    if not embed:
        return href(path, out_dir) or ""
    if path not in EMBEDDED:
        mime = EMBED_TYPES.get(os.path.splitext(path)[1].lower().lstrip("."), "image/png")
        try:
            with open_regular(path, EMBED_LIMIT) as f:
                EMBEDDED[path] = f"data:{mime};base64," + base64.b64encode(f.read(EMBED_LIMIT + 1)).decode("ascii")
        except Skipped:
            EMBEDDED[path] = ""
    return EMBEDDED[path]


def picture(path, out_dir, embed, attributes=""):
    """An image of the page, linked to the file where it is linked (not embedded): `<a><img></a>`."""
    source = src(path, out_dir, embed)
    img = (f'<img{attributes} alt="{html.escape(display(os.path.basename(path)))}" '
           f'src="{html.escape(source)}">')
    return img if embed else f'<a href="{html.escape(source)}">{img}</a>'


def shown_path(path, out_dir):
    return display(os.path.relpath(path, out_dir).replace(os.sep, "/"))


def sanitized(name):
    return re.sub(r"[^A-Za-z0-9_.=-]", "_", name)


# The columns in which a row records its own pictures (docs/CSV.md; bench/lib/images/RunImageNames.h),
# relative to the CSV's folder.
IMAGE_COLUMNS = ("screenshot_file", "visibility_file")


def recorded_images(header, row, csv_dir, images):
    """The pictures `row` records that exist (as `images` spells them where it holds them), or None where
    it records none (a CSV written before the columns, or a run without --screenshot and --visibility)."""
    col = {name: k for k, name in enumerate(header)}
    cells = [row[col[c]] for c in IMAGE_COLUMNS if c in col and col[c] < len(row) and row[col[c]]]
    if not cells:
        return None
    known = {os.path.realpath(i): i for i in images}
    paths = [os.path.join(csv_dir, c) for c in cells]
    return [known.get(os.path.realpath(p), p) for p in paths if os.path.realpath(p) in known or usable_image(p)]


def usable_image(path):
    """An image a row records outside the inputs: shown where it is a regular file with an image's name
    and a safe link (collect's rules for the inputs' images)."""
    try:
        check_entry(path)
    except Skipped:
        return False
    return path.lower().endswith(IMAGE_EXTS) and href(path, os.getcwd()) is not None


def row_images(header, rows, images, csv_dir):
    """Per row, its pictures: the files the row records where it does; for rows written before it did, the
    images of the CSV's folder named after its technique (`bench --screenshot shot.png` with several
    techniques wrote shot_<technique>.png; with one, shot.png)."""
    recorded = [recorded_images(header, r, csv_dir, images) for r in rows]
    if all(r is not None for r in recorded):
        return recorded
    here = [i for i in images if os.path.dirname(i) == csv_dir]
    col = {name: k for k, name in enumerate(header)}
    found = []
    for r, mine_recorded in zip(rows, recorded):
        if mine_recorded is not None:
            found.append(mine_recorded)
            continue
        names = {r[col[c]] for c in ("technique", "technique_spec") if c in col and r[col[c]]}
        mine = []
        for image in here:
            stem = os.path.splitext(os.path.basename(image))[0]
            if any(stem.endswith("_" + n) or stem.endswith("_" + sanitized(n)) for n in names):
                mine.append(image)
        found.append(mine)
    if len(rows) == 1 and not found[0] and recorded[0] is None:  # one technique: the screenshot keeps its name
        found[0] = [i for i in here if not os.path.basename(i).startswith("figure")]
    return found


def table_html(table_id, header, rows, columns, pictures, out_dir, embed, caption):
    """A sortable table: the CSV's row number first, then `columns` (raw cell text, so the page shows
    exactly what the CSV holds), then the row's images if any."""
    index = {name: k for k, name in enumerate(header)}
    numeric = {c: all(is_number(r[index[c]]) for r in rows if r[index[c]].strip()) and
               any(r[index[c]].strip() for r in rows) for c in columns}
    out = [f'<table class="rows" id="{table_id}">', f"<caption>{html.escape(caption)}</caption>", "<thead><tr>"]
    out.append('<th data-col="row" data-type="number" title="the row\'s place in the CSV; click to sort">row</th>')
    if pictures is not None:  # the row's images next to its numbers, before the long columns
        out.append('<th class="nosort">image</th>')
    for c in columns:
        kind = "number" if numeric[c] else "text"
        out.append(f'<th data-col="{html.escape(c)}" data-type="{kind}" title="click to sort">{html.escape(c)}</th>')
    out.append("</tr></thead><tbody>")
    for n, r in enumerate(rows, start=1):
        cells = [f'<td data-col="row" data-value="{n}">{n}</td>']
        if pictures is not None:
            imgs = "".join(picture(p, out_dir, embed, ' class="thumb"') for p in pictures[n - 1])
            cells.append(f'<td class="pics">{imgs}</td>')
        for c in columns:
            v = r[index[c]]
            cls = ' class="num"' if numeric[c] else ""
            cells.append(f'<td data-col="{html.escape(c)}" data-value="{html.escape(v)}"{cls}>{html.escape(v)}</td>')
        out.append(f'<tr data-row="{n}">' + "".join(cells) + "</tr>")
    out.append("</tbody></table>")
    return "\n".join(out)


# The charts that open the page (inline SVG written here: no script library, nothing fetched).
TIME_COLUMN = "wall_ms_median"
# The interval drawn around each median: the first pair of columns the CSV has.
INTERVAL_COLUMNS = [("wall_ms_p5", "wall_ms_p95", "p5-p95 of the frames")]
# The accuracy plotted against time: the first of these the rows hold numbers in (README.md, "CSV columns").
ACCURACY_COLUMNS = [("acc_wrong_pct", "wrong pixels (%)"), ("acc_wrong_no_edge_pct", "wrong pixels off edges (%)"),
                    ("acc_rmse", "visibility RMSE")]
# What tells the rows apart in a label, where it differs between rows.
LABEL_COLUMNS = ["technique", "properties", "api", "scene", "submit", "instances", "camera", "width", "height", "repeat"]
LABEL_CHARS = 36  # a longer label is cut (the whole one is the bar's tooltip)
MAX_BARS = 200  # more rows than this: the fastest are drawn, the rest counted under the chart
NAMED_POINTS = 30  # a scatter with more points than this names them in tooltips only


def number(text):
    try:
        v = float(text)
    except ValueError:
        return None
    return v if v == v and abs(v) != float("inf") else None


def row_labels(header, rows):
    """Per row, the values of the identity columns that differ between the rows ("shadowmap, round 2")."""
    col = {name: k for k, name in enumerate(header)}
    varying = [c for c in LABEL_COLUMNS if c in col and len({r[col[c]] for r in rows}) > 1]
    if "properties" in varying and "technique" in col:
        # A technique's properties name a row only where one technique ran with several sets of them.
        sets = {}
        for r in rows:
            sets.setdefault(r[col["technique"]], set()).add(r[col["properties"]])
        if all(len(v) == 1 for v in sets.values()):
            varying.remove("properties")
    if "technique" in col and "technique" not in varying:
        varying.insert(0, "technique")  # always say what was measured
    labels = []
    for r in rows:
        parts = []
        for c in varying:
            v = r[col[c]]
            if not v:
                continue
            parts.append({"repeat": f"round {v}", "instances": f"x{v}", "width": f"{v}w", "height": f"{v}h"}.get(c, v))
        labels.append(", ".join(parts) or "row")
    return labels


def short(label):
    return label if len(label) <= LABEL_CHARS else label[:LABEL_CHARS - 1] + "\u2026"


def nice_max(v):
    """The axis end: 1, 2, 2.5, 5 or 10 times a power of ten, at least v."""
    if v <= 0:
        return 1.0
    scale = 10.0 ** math.floor(math.log10(v))
    return next(m * scale for m in (1, 2, 2.5, 5, 10) if m * scale >= v * (1 - 1e-12))


def fmt(v):
    return f"{v:.4g}"


def timed_rows(header, rows):
    """(row number, median, low, high) of each row with a median time; low/high None without an interval."""
    col = {name: k for k, name in enumerate(header)}
    interval = next(((lo, hi, what) for lo, hi, what in INTERVAL_COLUMNS if lo in col and hi in col), None)
    out = []
    for n, r in enumerate(rows, start=1):
        median = number(r[col[TIME_COLUMN]])
        if median is None:
            continue
        low = high = None
        if interval:
            low, high = number(r[col[interval[0]]]), number(r[col[interval[1]]])
        out.append((n, median, low, high))
    return out, (interval[2] if interval else None)


def time_chart(chart_id, header, rows, labels):
    """Horizontal bars of the median wall time per row, fastest first, each with its interval as a
    whisker; a bar's width is proportional to its median (the axis starts at 0)."""
    timed, interval = timed_rows(header, rows)
    if not timed:
        return ""
    timed.sort(key=lambda t: (t[1], t[0]))
    drawn, hidden = timed[:MAX_BARS], len(timed) - MAX_BARS
    top = max(max(m, h or 0) for _, m, _, h in drawn)
    axis = nice_max(top)
    left, plot, bar_h, gap, head = 260, 440, 14, 6, 24
    width = left + plot + 90
    height = head + len(drawn) * (bar_h + gap) + 30
    x = lambda v: left + plot * v / axis  # noqa: E731
    out = [f'<svg id="{chart_id}" class="chart time" xmlns="http://www.w3.org/2000/svg" width="{width}" '
           f'height="{height}" viewBox="0 0 {width} {height}" role="img" aria-label="median wall time per row">',
           f'<text x="{left}" y="14" class="axis-title">median wall time per frame (ms)'
           + (f", whiskers {html.escape(interval)}" if interval else "") + "</text>"]
    for k in range(5):
        v = axis * k / 4
        out.append(f'<line class="grid" x1="{x(v):.1f}" y1="{head - 4}" x2="{x(v):.1f}" y2="{height - 24}"/>'
                   f'<text class="tick" x="{x(v):.1f}" y="{height - 10}" text-anchor="middle">{fmt(v)}</text>')
    for i, (n, median, low, high) in enumerate(drawn):
        y = head + i * (bar_h + gap)
        label = labels[n - 1]
        out.append(f'<g class="bar-row" data-row="{n}"><title>{html.escape(label)}: {fmt(median)} ms'
                   + (f" ({fmt(low)}-{fmt(high)})" if low is not None and high is not None else "") + "</title>")
        out.append(f'<text class="label" x="{left - 6}" y="{y + bar_h - 3}" text-anchor="end">'
                   f"{html.escape(short(label))}</text>")
        out.append(f'<rect class="bar" data-row="{n}" data-value="{median!r}" x="{left}" y="{y}" '
                   f'width="{plot * median / axis:.3f}" height="{bar_h}"/>')
        if low is not None and high is not None:
            mid = y + bar_h / 2
            out.append(f'<path class="whisker" d="M{x(low):.1f},{mid - 4}v8M{x(low):.1f},{mid}H{x(high):.1f}'
                       f'M{x(high):.1f},{mid - 4}v8"/>')
        end = x(max(median, high or 0))
        out.append(f'<text class="value" x="{end + 4:.1f}" y="{y + bar_h - 3}">{fmt(median)}</text></g>')
    out.append("</svg>")
    if hidden > 0:
        out.append(f"<p>The {MAX_BARS} fastest of {len(timed)} rows; the other {hidden} are in the table.</p>")
    return "\n".join(out)


def accuracy_chart(chart_id, header, rows, labels):
    """Accuracy against median wall time, a point per row that has both: the cheap and right corner is
    the bottom left. "" when the rows hold no accuracy."""
    col = {name: k for k, name in enumerate(header)}
    metric = next(((c, what) for c, what in ACCURACY_COLUMNS
                   if c in col and any(number(r[col[c]]) is not None for r in rows)), None)
    if not metric or TIME_COLUMN not in col:
        return ""
    points = [(n, number(r[col[TIME_COLUMN]]), number(r[col[metric[0]]])) for n, r in enumerate(rows, start=1)]
    points = [p for p in points if p[1] is not None and p[2] is not None]
    if not points:
        return ""
    xmax, ymax = nice_max(max(p[1] for p in points)), nice_max(max(p[2] for p in points))
    left, top, plot_w, plot_h = 60, 24, 520, 300
    width, height = left + plot_w + 170, top + plot_h + 46
    sx = lambda v: left + plot_w * v / xmax  # noqa: E731
    sy = lambda v: top + plot_h - plot_h * v / ymax  # noqa: E731
    out = [f'<svg id="{chart_id}" class="chart accuracy" xmlns="http://www.w3.org/2000/svg" width="{width}" '
           f'height="{height}" viewBox="0 0 {width} {height}" role="img" aria-label="accuracy against time">',
           f'<text x="{left}" y="14" class="axis-title">{html.escape(metric[1])} ({metric[0]}) against median '
           "wall time (ms); lower left is cheap and right</text>",
           f'<rect class="frame" x="{left}" y="{top}" width="{plot_w}" height="{plot_h}"/>']
    for k in range(5):
        vx, vy = xmax * k / 4, ymax * k / 4
        out.append(f'<text class="tick" x="{sx(vx):.1f}" y="{top + plot_h + 16}" text-anchor="middle">{fmt(vx)}</text>'
                   f'<text class="tick" x="{left - 6}" y="{sy(vy) + 4:.1f}" text-anchor="end">{fmt(vy)}</text>')
    for n, t, a in points:
        label = labels[n - 1]
        out.append(f'<g class="point-row" data-row="{n}"><title>{html.escape(label)}: {fmt(t)} ms, '
                   f"{metric[0]} {fmt(a)}</title>"
                   f'<circle class="point" data-row="{n}" cx="{sx(t):.2f}" cy="{sy(a):.2f}" r="4"/>')
        if len(points) <= NAMED_POINTS:
            out.append(f'<text class="label" x="{sx(t) + 6:.1f}" y="{sy(a) + 4:.1f}">{html.escape(short(label))}</text>')
        out.append("</g>")
    out.append(f'<text class="tick" x="{left + plot_w / 2}" y="{height - 6}" text-anchor="middle">median wall '
               "time per frame (ms)</text></svg>")
    return "\n".join(out)


def gallery(pictures, labels, out_dir, embed):
    """Each distinct screenshot of the rows once, side by side, captioned with its first row's label."""
    seen, out = set(), []
    for n, ps in enumerate(pictures, start=1):
        for p in ps:
            if p in seen:
                continue
            seen.add(p)
            out.append(f"<figure>{picture(p, out_dir, embed)}<figcaption>{html.escape(short(labels[n - 1]))}</figcaption></figure>")
    return f'<div class="gallery">{"".join(out)}</div>' if out else ""


def glance(table_id, name, header, rows, pictures, out_dir, embed):
    """The pictures that open the page for one CSV: time per row, accuracy against time where measured,
    then the screenshots."""
    if TIME_COLUMN not in header and not any(pictures):
        return ""
    labels = row_labels(header, rows)
    parts = [time_chart(f"{table_id}-time", header, rows, labels) if TIME_COLUMN in header else "",
             accuracy_chart(f"{table_id}-accuracy", header, rows, labels),
             gallery(pictures, labels, out_dir, embed)]
    parts = [p for p in parts if p]
    if not parts:
        return ""
    return (f'<section class="glance" id="{table_id}-glance"><h2>{html.escape(name)}</h2>' + "\n".join(parts) +
            f'<p><a href="#{table_id}-section">the table of its {len(rows)} row(s)</a></p></section>')


def environment_html(tables):
    """Each environment column's distinct values over every row, with how many rows hold each."""
    seen = {}
    for header, rows in tables:
        for c in ENVIRONMENT_COLUMNS:
            if c in header:
                k = header.index(c)
                for r in rows:
                    if r[k].strip():
                        seen.setdefault(c, {}).setdefault(r[k], 0)
                        seen[c][r[k]] += 1
    if not seen:
        return "<p>The CSVs record no environment columns.</p>"
    out = ['<table class="env" id="environment"><thead><tr><th>column</th><th>value</th><th>rows</th></tr>'
           "</thead><tbody>"]
    for c in ENVIRONMENT_COLUMNS:
        if c not in seen:
            continue
        values = seen[c]
        if c == "timestamp":
            stamps = sorted(values)
            items = [(stamps[0] + (" ... " + stamps[-1] if len(stamps) > 1 else ""), sum(values.values()))]
        else:
            items = sorted(values.items(), key=lambda kv: (-kv[1], kv[0]))
        for v, count in items:
            out.append(f'<tr><td>{html.escape(c)}</td><td data-col="{html.escape(c)}">{html.escape(v)}</td>'
                       f"<td>{count}</td></tr>")
    out.append("</tbody></table>")
    return "\n".join(out)


def commands(header, rows):
    """`bench` commands that measure the rows again, rebuilt from their columns: one per group of rows
    sharing everything but the technique (the techniques become -t options of one command)."""
    if "command" in header:  # rows that record their own command line
        k = header.index("command")
        return list(dict.fromkeys(r[k] for r in rows if r[k]))
    col = {name: k for k, name in enumerate(header)}
    if "technique" not in col or "scene" not in col:
        return []
    groups = {}
    for r in rows:
        get = lambda c: r[col[c]].strip() if c in col else ""  # noqa: E731
        if get("status") not in ("", "ok"):
            continue
        accuracy = any(c.startswith("acc_") and r[k].strip() for c, k in col.items())
        opts = []
        if get("api") and get("api") != "gl":
            opts.append(f"--api {get('api')}")
        opts.append(f"--scene {get('scene')}")
        if get("instances") not in ("", "0"):
            opts.append(f"-n {get('instances')}")
        if get("scale") not in ("", "1", "1.0", "1.0000"):
            opts.append(f"--scale {get('scale')}")
        if get("tessellation") not in ("", "default"):
            opts.append(f"--tess {get('tessellation')}")
        if get("seed") not in ("", "default"):
            opts.append(f"--seed {get('seed')}")
        if get("camera"):
            opts.append(f"--camera {get('camera')}")
        if get("submit"):
            opts.append(f"--submit {get('submit')}")
        if get("width") and get("height"):
            opts.append(f"--size {get('width')}x{get('height')}")
        if get("frames"):
            opts.append(f"--frames {get('frames')}")
        if get("warmup"):
            opts.append(f"--warmup {get('warmup')}")
        group = groups.setdefault(("bench accuracy" if accuracy else "bench", " ".join(opts)),
                                  {"techniques": [], "rounds": 1})
        spec = get("technique_spec") or (get("technique") + (":" + get("properties") if get("properties") else ""))
        if spec not in group["techniques"]:
            group["techniques"].append(spec)
        if get("repeat").isdigit():  # the round a row was measured in: the largest is the round count
            group["rounds"] = max(group["rounds"], int(get("repeat")))
    out = []
    for (mode, opts), group in groups.items():
        ts = " ".join(f"-t {t}" for t in group["techniques"])
        out.append(f"{mode} {ts} {opts}" + (f" --repeat {group['rounds']}" if group["rounds"] > 1 else ""))
    return out


def readme_commands(text):
    """The command lines of a README's code blocks: those that run bench, a script or python."""
    out = []
    for block in re.findall(r"```[a-z]*\n(.*?)```", text, flags=re.S):
        for line in block.splitlines():
            s = line.strip()
            if re.match(r"^(\S*/)?(bench|build/bench)\b|^scripts/|^/usr/bin/python3|^python3", s):
                out.append(s)
    return out


SCRIPT_ERRORS = r"""
// Runs first, in its own element, so that it also reports a syntax error in the script below.
// Messages are kept until the body (and its error box) exists.
(function () {
  var pending = [];
  function flush() {
    var box = document.getElementById("js-errors");
    if (!box) return;
    pending.forEach(function (m) { box.hidden = false; box.textContent += m + "\n"; });
    pending = [];
  }
  function report(message) {
    pending.push(message);
    document.documentElement.setAttribute("data-js-errors", String((window.reportErrors = (window.reportErrors || 0) + 1)));
    flush();
  }
  document.addEventListener("DOMContentLoaded", flush);
  window.addEventListener("error", function (e) {
    report("error: " + e.message + " (line " + e.lineno + ")");
  });
  var original = console.error;
  console.error = function () {
    report("console.error: " + Array.prototype.join.call(arguments, " "));
    original.apply(console, arguments);
  };
})();
"""

SCRIPT_MAIN = r"""
"use strict";
// Sorting: a click on a heading sorts its table by that column, ascending, then descending. Numbers
// compare as numbers; empty cells go last either way; ties keep the CSV's order (the row number).
// A column is found by its place (every row has the heading's cells), never by its name in a selector:
// a name may hold any character (" < ' \).
function cellValue(row, index) {
  var cell = row.cells[index];
  return (cell && cell.getAttribute("data-value")) || "";
}
function compareRows(a, b, index, type, direction) {
  var x = cellValue(a, index), y = cellValue(b, index);
  if (x === "" || y === "") {
    if (x === y) return Number(a.dataset.row) - Number(b.dataset.row);
    return x === "" ? 1 : -1;
  }
  var d = type === "number" ? Number(x) - Number(y) : x.localeCompare(y);
  if (d === 0) return Number(a.dataset.row) - Number(b.dataset.row);
  return direction === "desc" ? -d : d;
}
function sortTable(table, th, direction) {
  var index = th.cellIndex, type = th.dataset.type;
  var body = table.tBodies[0];
  var rows = Array.prototype.slice.call(body.rows);
  rows.sort(function (a, b) { return compareRows(a, b, index, type, direction); });
  rows.forEach(function (r) { body.appendChild(r); });
  Array.prototype.forEach.call(table.tHead.rows[0].cells, function (c) { c.removeAttribute("aria-sort"); });
  th.setAttribute("aria-sort", direction === "desc" ? "descending" : "ascending");
}
function onHeading(event) {
  var th = event.currentTarget, table = th.closest("table");
  sortTable(table, th, th.getAttribute("aria-sort") === "ascending" ? "desc" : "asc");
}
function inOrder(table, th, direction) {
  var rows = table.tBodies[0].rows;
  for (var i = 1; i < rows.length; ++i)
    if (compareRows(rows[i - 1], rows[i], th.cellIndex, th.dataset.type, direction) > 0) return false;
  return true;
}
// #selftest: every sortable column of every table, clicked twice (ascending, descending), checked in
// order; then the CSV's order is restored.
function selfTest() {
  var checks = 0, failures = [];
  document.querySelectorAll("table.rows").forEach(function (table) {
    table.querySelectorAll("th[data-col]").forEach(function (th) {
      ["asc", "desc"].forEach(function (direction) {
        th.click();
        checks++;
        if (th.getAttribute("aria-sort") !== (direction === "asc" ? "ascending" : "descending") ||
            !inOrder(table, th, direction))
          failures.push(table.id + ":" + th.dataset.col + ":" + direction);
      });
    });
    var first = table.querySelector('th[data-col="row"]');
    sortTable(table, first, "asc");
  });
  var out = document.getElementById("selftest");
  out.setAttribute("data-checks", String(checks));
  out.setAttribute("data-result", failures.length ? "fail" : "pass");
  out.textContent = (failures.length ? "sort self-test FAILED: " + failures.join(", ")
                                     : "sort self-test passed") + " (" + checks + " checks)";
}
// #sort=TABLE:COLUMN:asc|desc: sorts one table on load the way clicks on its heading do.
function sortFromFragment(fragment) {
  var m = /^sort=([^:]+):(.+):(asc|desc)$/.exec(fragment);
  if (!m) return;
  var table = document.getElementById(m[1]);
  var th = table && Array.prototype.find.call(table.querySelectorAll("th[data-col]"),
                                              function (h) { return h.dataset.col === m[2]; });
  if (!th) { console.error("#sort: no column " + m[2] + " in table " + m[1]); return; }
  th.click();
  if (m[3] === "desc") th.click();
}
document.addEventListener("DOMContentLoaded", function () {
  document.querySelectorAll("table.rows th[data-col]").forEach(function (th) {
    th.addEventListener("click", onHeading);
    th.tabIndex = 0;
    th.addEventListener("keydown", function (e) { if (e.key === "Enter") th.click(); });
  });
  var fragment = decodeURIComponent(location.hash.replace(/^#/, ""));
  if (fragment === "selftest") selfTest();
  else sortFromFragment(fragment);
  document.body.setAttribute("data-js-ready", "1");
});
"""

STYLE = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; border-bottom: 1px solid #ccc; }
code, pre, td { font-family: ui-monospace, monospace; font-size: 12px; }
pre { background: #f5f5f5; padding: .6em; overflow-x: auto; white-space: pre-wrap; }
table { border-collapse: collapse; margin: .5em 0; }
th, td { border: 1px solid #ccc; padding: 2px 6px; vertical-align: top; }
td[data-col="properties"], td[data-col="technique_spec"], td[data-col="error"] { max-width: 22em; overflow-wrap: anywhere; font-size: 11px; }
th { background: #eef; position: sticky; top: 0; }
table.rows th[data-col] { cursor: pointer; user-select: none; }
th[aria-sort="ascending"]::after { content: " \\25B2"; } th[aria-sort="descending"]::after { content: " \\25BC"; }
td.num { text-align: right; }
caption { text-align: left; font-weight: bold; padding: .3em 0; }
.pair { display: flex; flex-wrap: wrap; gap: 1.5em; align-items: flex-start; }
.tablewrap { overflow-x: auto; max-width: 100%; }
.figures img { max-width: 560px; border: 1px solid #ddd; display: block; margin-bottom: .5em; }
img.thumb { width: 96px; image-rendering: pixelated; border: 1px solid #ccc; }
#js-errors { color: #a00; background: #fee; }
svg.chart { display: block; max-width: 100%; height: auto; margin: .5em 0 1em; font: 11px ui-monospace, monospace; }
svg.chart .bar { fill: #4a7ab5; } svg.chart .whisker { stroke: #222; stroke-width: 1.2; fill: none; }
svg.chart .grid { stroke: #ddd; } svg.chart .frame { fill: none; stroke: #bbb; }
svg.chart .point { fill: #c0504d; stroke: #fff; } svg.chart .axis-title { font-weight: bold; }
svg.chart .tick { fill: #555; } svg.chart .label, svg.chart .value { fill: #222; }
.gallery { display: flex; flex-wrap: wrap; gap: 1em; } .gallery figure { margin: 0; }
.gallery img { width: 256px; image-rendering: pixelated; border: 1px solid #ccc; display: block; }
.gallery figcaption { font-size: 12px; max-width: 256px; }
details.table > summary { cursor: pointer; font-weight: bold; }
output#selftest { display: block; color: #555; }
"""


def cannot_write(out, what, error=None):
    """The CSV writer's message for a page that cannot be written (AtomicFile.cpp's words)."""
    return f"cannot write report page '{out}': {what}" + (f": {error.strerror}" if error is not None else "")


def check_page_path(out):
    """`out` names a regular file or nothing: a device, a FIFO, a socket or a folder is refused (exit 2)
    before anything is opened. Returns its stat, or None where it does not exist."""
    try:
        st = os.stat(out)
    except FileNotFoundError:
        return None
    except OSError as e:
        bad_input(cannot_write(out, "cannot inspect it", e))
    if not stat.S_ISREG(st.st_mode):
        bad_input(cannot_write(out, f"it is {kind_of(st.st_mode)}, not a regular file (the page is written by "
                                    "replacing the file)"))
    return st


def same_file(fd, path):
    """`path` (not followed) still names the file open on `fd`."""
    try:
        a, b = os.fstat(fd), os.lstat(path)
    except OSError:
        return False
    return (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino)


def clear_stale_partial(tmp):
    """Removes `tmp` where no live writer holds it: a link or any other non-regular file planted there
    (removed, never followed), or the temporary file of a writer that died (a live writer holds an
    exclusive flock on it until it renames it: waiting for that lock, then finding the file still in
    place, means its writer is gone)."""
    try:
        st = os.lstat(tmp)
    except FileNotFoundError:
        return
    if not stat.S_ISREG(st.st_mode):
        os.unlink(tmp)
        return
    try:
        fd = os.open(tmp, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC)
    except FileNotFoundError:
        return  # its writer renamed it meanwhile
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        if same_file(fd, tmp):
            os.unlink(tmp)
    finally:
        os.close(fd)


def create_partial(tmp):
    """`tmp` created exclusively (O_EXCL: never an existing file, O_NOFOLLOW: never through a link) and
    locked; its descriptor. Whatever is in the way is cleared first (clear_stale_partial)."""
    for _ in range(100):  # each round lost means another writer got the name first and finished
        try:
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC, 0o666)
        except FileExistsError:
            clear_stale_partial(tmp)
            continue
        fcntl.flock(fd, fcntl.LOCK_EX)
        if same_file(fd, tmp):  # else a clearer took it for a dead writer's before the lock: again
            return fd
        os.close(fd)
    raise OSError(0, "other writers kept taking its name")


def write_page(out, data):
    """Writes the page by the CSV writer's rules (bench/lib/output/AtomicFile.h): a special file or a
    folder at `out` is refused (exit 2); the bytes go to "<page>.partial" beside the page (created
    exclusively, see create_partial), which is fsynced and renamed over the page, then the folder is
    fsynced. A failure (a full disk) is one line and exit 1, and leaves the old page and no
    temporary file. Unlike a CSV, a link at `out` is not followed but replaced by the page: the default
    page lies in the results folder, and a link planted there must not make the report overwrite a
    file outside it (a link to a device or a folder is still refused, as is the device itself)."""
    st = check_page_path(out)
    target = out
    directory = os.path.dirname(target) or "."
    try:
        os.makedirs(directory, exist_ok=True)
    except OSError as e:
        bad_input(cannot_write(out, f"cannot make its folder '{directory}'", e))
    tmp = target + PARTIAL_SUFFIX
    try:
        fd = create_partial(tmp)
    except OSError as e:
        os_failure(cannot_write(out, f"cannot create temporary file '{tmp}'", e))
    step = f"cannot write temporary file '{tmp}'"
    try:
        if st is not None:
            try:  # replacing the page keeps who may read it (best effort: a foreign-owned page may refuse)
                os.fchmod(fd, stat.S_IMODE(st.st_mode))
            except OSError:
                pass
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view):]
        os.fsync(fd)
        step = f"cannot rename '{tmp}' over it"
        os.rename(tmp, target)
    except OSError as e:
        if same_file(fd, tmp):
            os.unlink(tmp)
        os_failure(cannot_write(out, step, e))
    finally:
        os.close(fd)
    try:  # the rename itself survives a power cut (best effort: some file systems refuse)
        dir_fd = os.open(directory, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
        try:
            os.fsync(dir_fd)
        finally:
            os.close(dir_fd)
    except OSError:
        pass


def build(args):
    out_dir = os.path.dirname(os.path.abspath(args.out))
    check_page_path(args.out)  # before minutes of work: a device or a folder named by -o is refused
    skipped = []
    csvs, images, readmes = collect(args.inputs, args.out, args.embed, skipped)
    if not csvs and not images:
        bad_input(f"no CSV or image in {' '.join(args.inputs)}")
    tables, sections, glances, used_images = [], [], [], set()
    for t, path in enumerate(csvs, start=1):
        try:
            header, rows = read_csv(path)
        except Skipped as why:
            if str(why).startswith("larger than"):
                sections.append(f"<h2>{html.escape(shown_path(path, out_dir))}</h2><p>Larger than "
                                f"{mib(CSV_LIMIT)}: not tabulated.</p>")
            else:
                skipped.append((path, str(why)))
            continue
        if not header:
            continue
        tables.append((header, rows))
        csv_dir = os.path.dirname(path)
        pictures = row_images(header, rows, images, csv_dir)
        has_pictures = any(pictures)
        used_images.update(p for ps in pictures for p in ps)
        key = [c for c in KEY_COLUMNS if c in header] if len(header) > WIDE else list(header)
        if not key:
            key = header[:WIDE]
        table_id = f"t{t}"
        name = shown_path(path, out_dir)
        glances.append(glance(table_id, name, header, rows, pictures, out_dir, args.embed))
        # The table behind a toggle: the pictures above say what it holds, the table is for looking up.
        part = [f'<h2 id="{table_id}-section">{html.escape(name)}</h2>',
                '<div class="pair"><div class="tablewrap">',
                f'<details class="table" id="{table_id}-details"><summary>the table: {len(rows)} row(s), '
                f"{len(header)} column(s); click a heading to sort</summary>",
                table_html(table_id, header, rows, key, pictures if has_pictures else None, out_dir, args.embed,
                           f"{name}: key columns" if key != header else name)]
        if key != header:
            part.append(f"<details><summary>all {len(header)} columns</summary>")
            part.append(table_html(f"{table_id}-all", header, rows, header, None, out_dir, args.embed, name))
            part.append("</details>")
        part.append("</details></div>")
        # The figures of the CSV's folder (bench figures: figure.svg beside data.csv) go beside it.
        figures = [i for i in images if os.path.dirname(i) == csv_dir and i not in used_images]
        svgs = {os.path.splitext(i)[0] for i in figures if i.lower().endswith(".svg")}
        figures = [i for i in figures if not (i.lower().endswith(".png") and os.path.splitext(i)[0] in svgs)]
        if figures:
            part.append('<div class="figures">')
            for fig in figures:
                used_images.add(fig)
                part.append(f"<figure>{picture(fig, out_dir, args.embed)}<figcaption>{html.escape(shown_path(fig, out_dir))}</figcaption></figure>")
            used_images.update(i for i in images if os.path.splitext(i)[0] in svgs)
            part.append("</div>")
        part.append("</div>")
        rerun = commands(header, rows)
        if rerun:
            part.append("<p>Commands that measure these rows again (rebuilt from the rows' columns; "
                        "add --csv FILE to write them):</p><pre class=\"commands\">" +
                        html.escape("\n".join(rerun)) + "</pre>")
        sections.append("\n".join(part))
    rest = [i for i in images if i not in used_images]
    if rest:
        sections.append("<h2>Other images</h2><div class=\"pair\">" + "".join(
            f'<figure><img class="figure" style="max-width:400px" alt="{html.escape(display(os.path.basename(i)))}" '
            f'src="{html.escape(src(i, out_dir, args.embed))}"><figcaption>{html.escape(shown_path(i, out_dir))}'
            f"</figcaption></figure>" for i in rest) + "</div>")
    notes = []
    for path in readmes:
        try:
            text = read_text(path, README_LIMIT)
        except Skipped as why:
            skipped.append((path, str(why)))
            continue
        lines = readme_commands(text)
        notes.append(f"<h3>{html.escape(shown_path(path, out_dir))}</h3>")
        if lines:
            notes.append("<p>Its commands:</p><pre class=\"commands\">" + html.escape("\n".join(lines)) + "</pre>")
        notes.append(f"<details><summary>the whole file</summary><pre>{html.escape(text)}</pre></details>")
    inputs = ", ".join(html.escape(shown_path(p, out_dir)) for p in args.inputs)
    title = display(args.title or "shadowbench results: " +
                    ", ".join(os.path.basename(os.path.normpath(p)) for p in args.inputs))
    page = [
        "<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>{html.escape(title)}</title>", f"<style>{STYLE}</style>",
        f"<script>{SCRIPT_ERRORS}</script>", f"<script>{SCRIPT_MAIN}</script>", "</head><body>",
        f"<h1>{html.escape(title)}</h1>",
        f"<p>Written by <code>bench report</code> (tools/report.py) from {inputs}: {len(tables)} table(s), "
        f"{len(images)} image(s). Static: sorting runs in this page, nothing is fetched.</p>",
        '<pre id="js-errors" hidden></pre>', '<output id="selftest"></output>',
    ]
    if skipped:
        page.append(f'<h2>Skipped</h2><ul id="skipped">' + "".join(
            f"<li><code>{html.escape(shown_path(p, out_dir))}</code>: {html.escape(why)}</li>" for p, why in skipped)
            + "</ul>")
    page.extend(g for g in glances if g)
    page += [
        "<h2>Environment</h2><p>What the rows record about the machine, driver and build that measured them.</p>",
        environment_html(tables),
    ]
    if notes:
        page.append("<h2>Notes beside the results</h2>")
        page.extend(notes)
    page.extend(sections)
    page.append("</body></html>\n")
    data = "\n".join(page).encode("utf-8", "replace")  # display() made every name UTF-8 already
    write_page(args.out, data)
    if skipped:  # one line, the same list as the page's
        say(f"skipped {len(skipped)} entr{'y' if len(skipped) == 1 else 'ies'}: " +
            "; ".join(f"{display(p)} ({why})" for p, why in skipped))
    print(f"wrote {display(args.out)} ({len(tables)} table(s), {len(images)} image(s), {len(data) // 1024} KiB)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("inputs", nargs="+", help="folders, CSVs, images, README.md")
    parser.add_argument("--out", default="", help="the page (default: FIRST_FOLDER/report.html)")
    parser.add_argument("--title", default="")
    parser.add_argument("--embed", action="store_true", help="write the images into the page (data: URLs)")
    args = parser.parse_args()
    if not args.out:
        first = args.inputs[0]
        args.out = os.path.join(first if os.path.isdir(first) else os.path.dirname(first) or ".", "report.html")
    build(args)


if __name__ == "__main__":
    main()
