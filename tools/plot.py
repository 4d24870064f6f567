#!/usr/bin/python3
"""Plots regenerated from result CSVs only (docs/ARCHITECTURE.md, "Results"). Run with Debian's python3
(/usr/bin/python3, python3-matplotlib, python3-pandas):

  /usr/bin/python3 tools/plot.py pareto results/accuracy/aircraft.csv --out results/accuracy/pareto
      error against median frame time, one series per technique, the Pareto front highlighted; the
      points are numbered (placed so that no two numbers or markers overlap) and listed in a key beside
      the chart (number, time, error, configuration);
  /usr/bin/python3 tools/plot.py lines inst.csv --out inst --x instances [--y wall_ms_median]
      a measure against an axis, one line per technique (median over rounds; bars: min-max over the
      rounds, or p5..p95 of the frames with a single round, as the legend's title says), one panel per
      --facet value;
  /usr/bin/python3 tools/plot.py bottleneck bn_classes.csv --out bn
      the bottleneck classification: each stage's share of the frame, and the evidence (T/T0 for
      every perturbation).
  /usr/bin/python3 tools/plot.py bars vol.csv --out vol [--facet scene] [--strip volume: | --diff-labels]
      one bar per configuration (technique_spec, in the order measured; median over rounds), labelled
      with its speed-up over the first bar of its panel (e.g. every optimisation off); --diff-labels
      names each bar by the properties that differ from the first.
Each writes OUT.png and OUT.svg. `bench figures` calls it for every declared figure.

Every figure says what it shows: a line under the title gives the parameters read from the rows
themselves (size, frames, warm-up, rounds, renderer), so a reduced run (`bench figures --reduced`)
is not titled with the full run's size, and the legend's title says what the error bars are. The
output is byte for byte the same for the same CSV and the same matplotlib (no date, a fixed SVG id
salt), so replotting committed figures leaves git clean.
"""
import argparse
import os
import re
import sys
import textwrap

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
    import numpy as np  # noqa: E402
    import pandas as pd  # noqa: E402
except ImportError as missing:
    # The plots are optional at run time (scripts/install-deps.sh's plot group): say what to install.
    sys.exit(
        f"tools/plot.py: {missing}: the plots need matplotlib and pandas "
        "(apt-get install python3-matplotlib python3-pandas, or bash scripts/install-deps.sh plot)"
    )

# Reproducible output: matplotlib names SVG clip paths and glyphs by hashes salted with a random value
# unless this is set, and stamps the date into the SVG metadata unless save() clears it.
matplotlib.rcParams["svg.hashsalt"] = "shadowbench-plot"
CREATOR = "shadowbench tools/plot.py"

METRIC_LABELS = {
    "acc_wrong_pct": "wrongly classified pixels (%)",
    "acc_wrong_no_edge_pct": "wrongly classified pixels, edges excluded (%)",
    "acc_rmse": "visibility RMSE",
}


def pareto_front(points):
    """Indices of the points no other point beats on both time and error (lower is better)."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def short_label(row, default_props):
    """The properties that differ from the technique's first (base) configuration."""
    props = dict(kv.split("=", 1) for kv in str(row["properties"]).split(":") if "=" in kv)
    base = default_props.get(row["technique"], {})
    diff = [f"{k}={v}" for k, v in props.items() if base.get(k) != v]
    return ",".join(diff) if diff else "default"


def distinct_ints(df, col):
    """The distinct integer values of a column, sorted ([] when it is absent or empty)."""
    if col not in df.columns:
        return []
    return sorted({int(v) for v in pd.to_numeric(df[col], errors="coerce").dropna()})


def distinct_sizes(df):
    """The distinct 'WxH' of the rows, smallest first."""
    if "width" not in df.columns or "height" not in df.columns:
        return []
    pairs = df[["width", "height"]].apply(pd.to_numeric, errors="coerce").dropna().astype(int)
    return [f"{w}x{h}" for w, h in sorted({(int(w), int(h)) for w, h in pairs.itertuples(index=False)})]


def spread(values):
    return "" if not values else str(values[0]) if len(values) == 1 else f"{values[0]}-{values[-1]}"


def run_parameters(df, frames_df=None, what=""):
    """The line under a title: the parameters the rows were measured with, e.g. 'measured: 128x128, 2
    frames after 1 warm-up, 2 rounds; llvmpipe (...)'. frames_df holds the frame counts when df does not
    (a bottleneck figure's classes.csv: its data.csv). `what` says what a point or bar is."""
    src = df if frames_df is None else frames_df
    parts = []
    sizes = distinct_sizes(df)
    if sizes:
        parts.append(", ".join(sizes) if len(sizes) <= 3 else f"{sizes[0]} ... {sizes[-1]}")
    frames, warmup, rounds = distinct_ints(src, "frames"), distinct_ints(src, "warmup"), distinct_ints(src, "repeat")
    if frames:
        parts.append(f"{spread(frames)} frames" + (f" after {spread(warmup)} warm-up" if warmup else ""))
    if rounds:
        parts.append(f"{max(rounds)} round{'s' if max(rounds) > 1 else ''}")
    renderer = next((str(v) for v in df.get("renderer", pd.Series(dtype=str)).dropna()), "")
    text = "measured: " + ", ".join(parts) + (f"; {renderer}" if renderer else "")
    return text + (f"\n{what}" if what else "")


def true_title(title, df):
    """The declared title with its size ('1024x1024') and instance count (' x200') replaced by the
    measured ones where the rows hold exactly one and it differs: a reduced run's figure must not carry
    the full run's parameters."""
    sizes = distinct_sizes(df)
    if len(sizes) == 1 and len(re.findall(r"\b\d+x\d+\b", title)) == 1:
        title = re.sub(r"\b\d+x\d+\b", sizes[0], title)
    counts = [n for n in distinct_ints(df, "instances") if n > 0]
    if len(counts) == 1 and len(re.findall(r"(?<= )x\d+\b", title)) == 1:
        title = re.sub(r"(?<= )x\d+\b", f"x{counts[0]}", title)
    return title


def pareto(args):
    frames = [pd.read_csv(path, low_memory=False) for path in args.csv]
    df = pd.concat(frames, ignore_index=True)
    for col in ("technique", "properties", "wall_ms_median", args.metric):
        if col not in df.columns:
            sys.exit(f"plot.py: {args.csv}: column '{col}' missing (was this written by `bench accuracy`?)")
    df = df[df.get("status", "ok") == "ok"] if "status" in df.columns else df
    base = {}
    for _, row in df.iterrows():
        base.setdefault(row["technique"], dict(kv.split("=", 1) for kv in str(row["properties"]).split(":") if "=" in kv))

    facets = list(dict.fromkeys(df[args.facet])) if args.facet else [None]
    # Each panel is the chart and, beside it, the key of its numbered points (labels written at the
    # points collide where configurations cost the same); two panels a row.
    cols = min(len(facets), 2)
    rows = (len(facets) + cols - 1) // cols
    fig = plt.figure(figsize=(12.5 * cols, 5.6 * rows + 0.6), dpi=120)
    grid = fig.add_gridspec(rows, 2 * cols, width_ratios=[1.55, 1] * cols)
    panels = []
    for i, facet in enumerate(facets):
        ax = fig.add_subplot(grid[i // cols, 2 * (i % cols)])
        key = fig.add_subplot(grid[i // cols, 2 * (i % cols) + 1])
        part = df if facet is None else df[df[args.facet] == facet]
        panels.append((ax, key, pareto_panel(ax, part, base, args)))
        ax.set_title(f"{args.facet} = {facet}" if facet is not None else "", fontsize=9)
    first = df.iloc[0]
    title = true_title(args.title, df) if args.title else \
        f"Accuracy against time: {first.get('scene', '')}"
    headline(fig, title + "\n" + run_parameters(df, what="each point: one configuration, the median of its "
                                                 "frames' wall time against its error over the judged pixels"))
    layout(fig)
    fronts = 0
    for ax, key, (points, front) in panels:
        fronts += len(front)
        place_numbers(ax, points)
        write_key(key, ax, points, args.metric)
    save(fig, args.out, f"{len(df)} points, {fronts} on the front(s)", relayout=False)


def pareto_panel(ax, df, base, args):
    """One accuracy-against-time scatter with its Pareto front; returns its points (number, x, y,
    colour, technique, label) and the front's indices."""
    points = []
    for tech, group in df.groupby("technique", sort=False):
        dots = ax.scatter(group["wall_ms_median"], group[args.metric], label=tech, s=36, zorder=3)
        colour = dots.get_facecolor()[0]
        for _, row in group.sort_values("wall_ms_median").iterrows():
            points.append((len(points) + 1, float(row["wall_ms_median"]), float(row[args.metric]), colour, tech,
                           short_label(row, base)))
    xy = [(p[1], p[2]) for p in points]
    front = pareto_front(xy)
    ordered = sorted(front, key=lambda i: xy[i])
    ax.plot([xy[i][0] for i in ordered], [xy[i][1] for i in ordered], color="black", lw=1.2, ls="--", zorder=2,
            label="Pareto front")
    ax.set_xlabel("median frame time, wall (ms)")
    ax.set_ylabel(METRIC_LABELS.get(args.metric, args.metric))
    if args.logy:
        positive = df[args.metric][df[args.metric] > 0]
        if (df[args.metric] > 0).all():
            ax.set_yscale("log")
        elif len(positive):
            # The reference (and any exact technique) sits at 0: a symmetric log axis keeps it on the
            # chart, linear below the smallest non-zero error and logarithmic above it.
            ax.set_yscale("symlog", linthresh=float(positive.min()))
    ax.grid(True, alpha=0.3)
    ax.margins(0.08)
    return points, front


# Where a point's number may go, tried in this order: the directions (unit steps) at growing distances
# (points) from the marker; the first place that overlaps no marker, no other number and stays inside
# the axes wins.
LABEL_DIRECTIONS = [(1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1)]
LABEL_DISTANCES = [2, 6, 11, 17, 24, 32, 42]


def place_numbers(ax, points, fontsize=7):
    """Writes each point's number beside it without overlapping another number or marker (greedy, in
    display space, after the layout is final); a number pushed away from its point gets a thin leader."""
    fig = ax.figure
    renderer = fig.canvas.get_renderer()
    scale = fig.dpi / 72.0  # pixels per point
    marker = 3.5 * scale    # scatter s=36: a 6 pt disc, plus a margin
    centres = [ax.transData.transform((x, y)) for _, x, y, *_ in points]
    boxes = [(cx - marker, cy - marker, cx + marker, cy + marker) for cx, cy in centres]
    frame = ax.get_window_extent(renderer)

    def free(box):
        x0, y0, x1, y1 = box
        if x0 < frame.x0 or y0 < frame.y0 or x1 > frame.x1 or y1 > frame.y1:
            return False
        return not any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in boxes)

    for (number, x, y, colour, *_), (cx, cy) in zip(points, centres):
        probe = ax.text(0, 0, str(number), fontsize=fontsize, fontweight="bold")
        extent = probe.get_window_extent(renderer)
        probe.remove()
        w, h = extent.width + 2, extent.height + 1
        chosen = None
        for distance in LABEL_DISTANCES:
            for dx, dy in LABEL_DIRECTIONS:
                ox = dx * (marker + distance * scale + w / 2)
                oy = dy * (marker + distance * scale + h / 2)
                box = (cx + ox - w / 2, cy + oy - h / 2, cx + ox + w / 2, cy + oy + h / 2)
                if free(box):
                    chosen = (ox, oy, box, distance)
                    break
            if chosen:
                break
        if chosen is None:  # crowded beyond every place tried: the farthest north-east one
            ox = oy = marker + LABEL_DISTANCES[-1] * scale + w / 2
            chosen = (ox, oy, (cx + ox - w / 2, cy + oy - h / 2, cx + ox + w / 2, cy + oy + h / 2),
                      LABEL_DISTANCES[-1])
        ox, oy, box, distance = chosen
        boxes.append(box)
        leader = {"arrowstyle": "-", "color": colour, "lw": 0.5, "shrinkA": 0, "shrinkB": 3} \
            if distance > LABEL_DISTANCES[1] else None
        note = ax.annotate(str(number), (x, y), xytext=(ox / scale, oy / scale), textcoords="offset points",
                           ha="center", va="center", fontsize=fontsize, fontweight="bold", color=colour,
                           arrowprops=leader, zorder=4)
        note.set_in_layout(False)


def write_key(key, ax, points, metric):
    """The numbered points' table beside the chart: number, technique, configuration, time, error."""
    key.axis("off")
    handles, labels = ax.get_legend_handles_labels()
    legend = key.legend(handles, labels, fontsize=7, loc="upper left", ncol=2, frameon=False)
    box = legend.get_window_extent(key.figure.canvas.get_renderer()).transformed(key.transAxes.inverted())
    lines = [f"{'#':>3}  {'ms':>6}  {metric_short(metric):>9}  configuration"]
    for number, x, y, colour, tech, label in points:
        lines.append((f"{number:>3}  {x:6.1f}  {y:9.4g}  {tech} {label if label != 'default' else ''}".rstrip(),
                      colour))
    top = box.y0 - 0.04
    size = min(7.0, 300.0 / max(len(lines), 1))
    step = size * 1.35 / (key.get_window_extent().height * 72.0 / key.figure.dpi)
    for i, line in enumerate(lines):
        text, colour = (line, "black") if isinstance(line, str) else line
        key.text(0.0, top - i * step, text, transform=key.transAxes, fontsize=size, family="monospace",
                 color=colour, va="top")


def metric_short(metric):
    return {"acc_wrong_pct": "wrong %", "acc_wrong_no_edge_pct": "no-edge %", "acc_rmse": "RMSE"}.get(metric, metric)


def ok_rows(df):
    return df[df["status"] == "ok"] if "status" in df.columns else df


def series_label(row, columns):
    return " ".join(str(row[c]) for c in columns)


def lines(args):
    df = ok_rows(pd.concat([pd.read_csv(path, low_memory=False) for path in args.csv], ignore_index=True))
    series = args.series.split(",")
    if "technique_spec" in df.columns and series == ["technique"]:
        series = ["technique_spec"]
    for col in [args.x, args.y] + series + ([args.facet] if args.facet else []):
        if col not in df.columns:
            sys.exit(f"plot.py: {args.csv}: column '{col}' missing")
    facets = list(dict.fromkeys(df[args.facet])) if args.facet else [None]
    fits = []
    described = set()
    fig, axes = plt.subplots(1, len(facets), figsize=(6.5 * len(facets), 5.2), dpi=120, squeeze=False)
    for ax, facet in zip(axes[0], facets):
        part = df if facet is None else df[df[args.facet] == facet]
        kinds = []
        for key, group in part.groupby(series if len(series) > 1 else series[0], sort=False):
            key = key if isinstance(key, tuple) else (key,)
            stats = group.groupby(args.x)[args.y].agg(["median", "min", "max", "count"]).sort_index()
            # What a bar is depends on the rows: with several rounds (one row per round and x), the
            # range of the rounds' values; with one round, the frames' p5..p95 (wall time only).
            lo, hi = stats["median"] - stats["min"], stats["max"] - stats["median"]
            rounds = int(stats["count"].max())
            kind = f"min-max over {rounds} rounds" if rounds > 1 else "none (one round)"
            if rounds <= 1 and args.y == "wall_ms_median" and "wall_ms_p5" in group.columns:
                pct = group.groupby(args.x)[["wall_ms_p5", "wall_ms_p95"]].median().sort_index()
                lo, hi = stats["median"] - pct["wall_ms_p5"], pct["wall_ms_p95"] - stats["median"]
                kind = "p5-p95 of the frames (one round)"
            kinds.append(kind)
            described.add(rounds)
            label = " ".join(str(k) for k in key)
            if args.fit and len(stats) >= 2:
                fit = linear_fit(stats.index.to_numpy(float), stats["median"].to_numpy(float))
                fits.append({"facet": "" if facet is None else facet, "series": label, **fit})
                label += f"  (fit {fit['slope']:.4g}/unit, R² {fit['r2']:.3f})"
            line = ax.errorbar(stats.index, stats["median"], yerr=[lo.clip(lower=0), hi.clip(lower=0)], marker="o",
                               ms=4, capsize=3, label=label)
            if args.fit and len(stats) >= 2:
                xs = stats.index.to_numpy(float)
                ax.plot(xs, fit["intercept"] + fit["slope"] * xs, "--", lw=0.8, color=line[0].get_color())
        ax.set_xlabel(args.x)
        ax.set_ylabel(args.ylabel or args.y)
        if args.logx:
            ax.set_xscale("log")
        if args.logy:
            ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
        # The legend says what the error bars are (the same for every line of a panel, as a rule).
        legend = ax.legend(fontsize=8, title="error bars: " + "; ".join(dict.fromkeys(kinds)), title_fontsize=7)
        legend._legend_box.align = "left"
        if facet is not None:
            ax.set_title(f"{args.facet} = {facet}", fontsize=9)
    first = df.iloc[0]
    measure = "median frame time (wall)" if args.y == "wall_ms_median" else args.y
    point = f"median over the rounds of each round's {measure}" if max(described, default=1) > 1 else f"the {measure}"
    title = true_title(args.title, df) if args.title else f"{args.y} against {args.x} ({first.get('renderer', '')})"
    headline(fig, title + "\n" + run_parameters(df, what=f"points: {point}"))
    save(fig, args.out, f"{len(df)} rows")
    if args.fit:
        # The fit of each line, for write-ups: y = intercept + slope * x over the medians.
        pd.DataFrame(fits).to_csv(args.out + "_fit.csv", index=False, float_format="%.6g")
        print(f"plot.py: wrote {args.out}_fit.csv ({len(fits)} fits)")


def linear_fit(x, y):
    """Least squares y = a + b x, with R^2 (1 when the medians lie on the line)."""
    b, a = np.polyfit(x, y, 1)
    residual = y - (a + b * x)
    total = ((y - y.mean()) ** 2).sum()
    r2 = 1.0 - (residual ** 2).sum() / total if total > 0 else 1.0
    return {"intercept": a, "slope": b, "r2": r2, "points": len(x)}


def bottleneck(args):
    df = pd.read_csv(args.csv[0], low_memory=False)
    for col in ("technique_spec", "share_cpu", "share_vertex", "share_fill", "class"):
        if col not in df.columns:
            sys.exit(f"plot.py: {args.csv[0]}: column '{col}' missing (written by bench bottleneck?)")
    def where(r):
        n = r.get("instances")
        return f"{r['scene']}" + (f" x{int(n)}" if pd.notna(n) and n else "")

    labels = [f"{r['technique_spec']} @ {where(r)}" for _, r in df.iterrows()]
    perts = [c[len("time_ratio_"):] for c in df.columns if c.startswith("time_ratio_") and
             c != "time_ratio_baseline"]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 1.9 + 0.55 * len(df)), dpi=120,
                                  gridspec_kw={"width_ratios": [1, 1.3]})
    y = range(len(df))
    left = [0.0] * len(df)
    for col, name, color in (("share_cpu", "cpu", "#4c72b0"), ("share_vertex", "vertex", "#55a868"),
                             ("share_fill", "fill", "#c44e52")):
        ax.barh(y, df[col], left=left, color=color, label=name)
        left = [a + b for a, b in zip(left, df[col])]
    for i, (_, r) in enumerate(df.iterrows()):
        poor = " ?" if str(r.get("poor_fit", False)).lower() == "true" else ""
        ax.text(1.02, i, f"{r['class']}{poor}  ({r['wall_ms_baseline']:.1f} ms)", va="center", fontsize=7.5)
    ax.set_yticks(list(y))
    ax.set_yticklabels(labels, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlim(0, 1.8)  # room for the longest class text ("mixed:fill+vertex ?  (14.6 ms)")
    ax.set_xticks([0, 0.2, 0.4, 0.6, 0.8, 1.0])  # shares: nothing beyond 1
    ax.set_xlabel("share of the baseline frame time (fitted)")
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.35 if len(df) < 4 else -0.12), ncol=3)
    for j, p in enumerate(perts):
        ax2.scatter(df[f"time_ratio_{p}"], [v + (j - len(perts) / 2) * 0.06 for v in y], s=18, label=p, zorder=3)
    ax2.axvline(1.0, color="0.5", lw=0.8)
    ax2.set_xscale("log")
    ax2.set_yticks(list(y))
    ax2.set_yticklabels([])
    ax2.invert_yaxis()
    ax2.set_xlabel("frame time / baseline frame time (evidence)")
    ax2.grid(True, axis="x", alpha=0.3)
    ax2.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.0, 0.5))
    # classes.csv has no frame counts: `bench figures` writes it beside the rows it classifies.
    beside = os.path.join(os.path.dirname(os.path.abspath(args.csv[0])), "data.csv")
    rows = pd.read_csv(beside, low_memory=False) if os.path.abspath(args.csv[0]) != beside and \
        os.path.exists(beside) else None
    title = true_title(args.title, df) if args.title else "Bottleneck classification"
    headline(fig, title + "\n" + run_parameters(df, rows, what="baseline size shown; each perturbation "
                                                 "changes one thing (size, tessellation, submission, scale)"))
    save(fig, args.out, f"{len(df)} classifications")


def spec_properties(spec):
    """'volume:mode=zfail:scissor=true' -> ('volume', {'mode': 'zfail', 'scissor': 'true'})."""
    name, _, rest = spec.partition(":")
    props = dict(p.split("=", 1) for p in rest.split(":") if "=" in p)
    return name, props


def diff_labels(specs):
    """Each configuration named by what differs from the first (the baseline): 'scissor' for a switch
    turned on, 'no scissor' for one turned off, 'mode=auto' otherwise."""
    baseName, base = spec_properties(specs[0])
    labels = []
    for i, spec in enumerate(specs):
        name, props = spec_properties(spec)
        parts = []
        for key, value in props.items():
            if base.get(key) == value:
                continue
            parts.append(key if value == "true" else f"no {key}" if value == "false" else f"{key}={value}")
        label = ", ".join(parts)
        if name != baseName:
            label = f"{name}: {label}" if label else name
        labels.append(f"baseline ({name})" if i == 0 else label or name)
    # Long lists wrap so the axis stays readable.
    return ["\n".join(textwrap.wrap(label, 60)) for label in labels]


def bars(args):
    every = pd.concat([pd.read_csv(path, low_memory=False) for path in args.csv], ignore_index=True)
    if "technique_spec" not in every.columns and "technique" in every.columns:
        # A plain run's rows (no sweep): the technique and its properties name the configuration.
        spec = every["technique"].astype(str)
        # The properties only where a technique was measured with several sets of them.
        if "properties" in every.columns and (every.groupby("technique")["properties"].nunique() > 1).any():
            props = every["properties"].fillna("").astype(str)
            spec = spec + (":" + props).where(props != "", "")
        every["technique_spec"] = spec
    df = ok_rows(every)
    for col in ["technique_spec", args.y] + ([args.facet] if args.facet else []):
        if col not in every.columns:
            sys.exit(f"plot.py: {args.csv}: column '{col}' missing")
    facets = list(dict.fromkeys(every[args.facet])) if args.facet else [None]
    specs = list(dict.fromkeys(every["technique_spec"]))
    names = dict(zip(specs, diff_labels(specs))) if args.diff_labels else \
        {spec: spec.replace(args.strip, "", 1) if args.strip else spec for spec in specs}
    height = 0.45 * len(specs) * len(facets) + 2.1
    fig, axes = plt.subplots(len(facets), 1, figsize=(9, height), dpi=120, squeeze=False)
    for ax, facet in zip(axes[:, 0], facets):
        part = df if facet is None else df[df[args.facet] == facet]
        everyPart = every if facet is None else every[every[args.facet] == facet]
        # Every configuration keeps its row, measured or not: a skipped one (unsupported here) is a
        # labelled gap, not a silently missing bar.
        order = list(dict.fromkeys(everyPart["technique_spec"]))
        med = part.groupby("technique_spec")[args.y].median().reindex(order)
        ax.barh(range(len(order)), med.fillna(0).values, color="#4c72b0")
        ax.set_yticks(range(len(order)))
        ax.set_yticklabels([names[spec] for spec in order], fontsize=7)
        ax.invert_yaxis()
        base = med.values[0]
        for i, (spec, v) in enumerate(med.items()):
            if pd.isna(v):
                status = everyPart[everyPart["technique_spec"] == spec]["status"].iloc[0] \
                    if "status" in everyPart.columns else "no data"
                ax.text(0, i, f"  {status} (not measured)", va="center", fontsize=7, color="#a33")
            else:
                if args.y.startswith(("wall_ms", "cpu_ms", "gpu_ms")):
                    ax.text(v, i, f"  {v:.1f} ms  ({base / v:.2f}x)", va="center", fontsize=7)
                else:  # an error or a count: the value and its share of the baseline's
                    ax.text(v, i, f"  {v:.4g}  ({v / base:.2f} of baseline)" if base else f"  {v:.4g}",
                            va="center", fontsize=7)
        ax.set_xlim(0, med.max() * 1.35)
        ax.set_xlabel(args.ylabel or args.y)
        ax.grid(True, axis="x", alpha=0.3)
        if facet is not None:
            ax.set_title(f"{args.facet} = {facet}", fontsize=9)
    first = df.iloc[0]
    rounds = distinct_ints(df, "repeat")
    measure = "median frame time (wall)" if args.y == "wall_ms_median" else args.y
    ratio = ("the first bar's time divided by it (speed-up)" if args.y.startswith(("wall_ms", "cpu_ms", "gpu_ms"))
             else "it divided by the first bar's")
    what = (f"each bar: the median over {max(rounds)} rounds of each round's {measure}" if rounds and max(rounds) > 1
            else f"each bar: the {measure} of one round") + f"; the label: its value and {ratio}"
    title = true_title(args.title, df) if args.title else f"{args.y} per configuration ({first.get('renderer', '')})"
    headline(fig, title + "\n" + run_parameters(df, what=what))
    save(fig, args.out, f"{len(df)} rows")


def headline(fig, text, fontsize=10):
    """The figure's title block (several lines) above the panels; layout() keeps the panels below it."""
    fig.suptitle(text, fontsize=fontsize, y=0.995, va="top")


def layout(fig):
    """tight_layout below the title block (matplotlib 3.6 makes room for the suptitle)."""
    fig.tight_layout()


def save(fig, out, what, relayout=True):
    if relayout:
        layout(fig)
    # No date and a fixed creator: the same rows give the same bytes (the module's docstring).
    fig.savefig(f"{out}.png", bbox_inches="tight", metadata={"Software": CREATOR})
    fig.savefig(f"{out}.svg", bbox_inches="tight", metadata={"Date": None, "Creator": CREATOR})
    print(f"wrote {out}.png and {out}.svg ({what})")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="kind", required=True)
    p = sub.add_parser("pareto", help="error against median frame time")
    p.add_argument("csv", nargs="+", help="CSV files written by `bench accuracy`")
    p.add_argument("--out", required=True, help="output path without extension")
    p.add_argument("--metric", default="acc_wrong_pct", help="error column (default acc_wrong_pct)")
    p.add_argument("--title", default="")
    p.add_argument("--logy", action="store_true", help="logarithmic error axis")
    p.add_argument("--facet", default="", help="one panel (and front) per value of this column")
    q = sub.add_parser("lines", help="a measure against an axis, one line per series")
    q.add_argument("csv", nargs="+")
    q.add_argument("--out", required=True)
    q.add_argument("--x", required=True, help="axis column (instances, scale, width ...)")
    q.add_argument("--y", default="wall_ms_median")
    q.add_argument("--ylabel", default="")
    q.add_argument("--series", default="technique", help="comma-separated columns naming a line")
    q.add_argument("--facet", default="", help="one panel per value of this column")
    q.add_argument("--title", default="")
    q.add_argument("--logx", action="store_true")
    q.add_argument("--logy", action="store_true")
    q.add_argument("--fit", action="store_true",
                   help="least-squares line per series (dashed), slope and R² in the legend, written to OUT_fit.csv")
    b = sub.add_parser("bottleneck", help="bottleneck classification (the _classes.csv of bench bottleneck)")
    b.add_argument("csv", nargs=1)
    b.add_argument("--out", required=True)
    b.add_argument("--title", default="")
    c = sub.add_parser("bars", help="one bar per configuration, speed-up over the first")
    c.add_argument("csv", nargs="+")
    c.add_argument("--out", required=True)
    c.add_argument("--y", default="wall_ms_median")
    c.add_argument("--ylabel", default="")
    c.add_argument("--facet", default="", help="one panel per value of this column")
    c.add_argument("--strip", default="", help="prefix removed from the labels (e.g. volume:)")
    c.add_argument("--diff-labels", action="store_true",
                   help="label each bar by the properties that differ from the first (the baseline)")
    c.add_argument("--title", default="")
    args = parser.parse_args()
    {"pareto": pareto, "lines": lines, "bottleneck": bottleneck, "bars": bars}[args.kind](args)


if __name__ == "__main__":
    main()
