#!/usr/bin/python3
"""Plots regenerated from result CSVs only (docs/ARCHITECTURE.md, "Results"). Run with Debian's python3
(/usr/bin/python3, python3-matplotlib, python3-pandas):

  /usr/bin/python3 tools/plot.py pareto results/accuracy/aircraft.csv --out results/accuracy/pareto
      error against median frame time, one series per technique, the Pareto front highlighted;
  /usr/bin/python3 tools/plot.py lines inst.csv --out inst --x instances [--y wall_ms_median]
      a measure against an axis, one line per technique (median over rounds; bars: the spread over
      rounds, or p5..p95 of the frames with a single round), one panel per --facet value;
  /usr/bin/python3 tools/plot.py bottleneck bn_classes.csv --out bn
      the bottleneck classification: each stage's share of the frame, and the evidence (T/T0 for
      every perturbation).
  /usr/bin/python3 tools/plot.py bars vol.csv --out vol [--facet scene] [--strip volume: | --diff-labels]
      one bar per configuration (technique_spec, in the order measured; median over rounds), labelled
      with its speed-up over the first bar of its panel (e.g. every optimisation off); --diff-labels
      names each bar by the properties that differ from the first.
Each writes OUT.png and OUT.svg. `bench figures` calls it for every declared figure.
"""
import argparse
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

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


def pareto(args):
    frames = [pd.read_csv(path) for path in args.csv]
    df = pd.concat(frames, ignore_index=True)
    for col in ("technique", "properties", "wall_ms_median", args.metric):
        if col not in df.columns:
            sys.exit(f"plot.py: {args.csv}: column '{col}' missing (was this written by `bench accuracy`?)")
    df = df[df.get("status", "ok") == "ok"] if "status" in df.columns else df
    base = {}
    for _, row in df.iterrows():
        base.setdefault(row["technique"], dict(kv.split("=", 1) for kv in str(row["properties"]).split(":") if "=" in kv))

    facets = list(dict.fromkeys(df[args.facet])) if args.facet else [None]
    fig, axes = plt.subplots(1, len(facets), figsize=(8 * len(facets), 5.5), dpi=120, squeeze=False)
    fronts = 0
    for ax, facet in zip(axes[0], facets):
        part = df if facet is None else df[df[args.facet] == facet]
        fronts += pareto_panel(ax, part, base, args)
        first = part.iloc[0]
        default = (f"Accuracy against time: {first.get('scene', '')}, {first.get('width', '')}x"
                   f"{first.get('height', '')}, {first.get('renderer', '')}")
        ax.set_title(f"{args.facet} = {facet}" if facet is not None else (args.title or default), fontsize=9)
    if args.facet and args.title:
        fig.suptitle(args.title, fontsize=10)
    save(fig, args.out, f"{len(df)} points, {fronts} on the front(s)")


def pareto_panel(ax, df, base, args):
    """One accuracy-against-time scatter with its Pareto front; returns the front's size."""
    for tech, group in df.groupby("technique", sort=False):
        ax.scatter(group["wall_ms_median"], group[args.metric], label=tech, s=36, zorder=3)
        for _, row in group.iterrows():
            ax.annotate(short_label(row, base), (row["wall_ms_median"], row[args.metric]), fontsize=6,
                        xytext=(4, 3), textcoords="offset points", color="0.3")
    points = list(zip(df["wall_ms_median"], df[args.metric]))
    front = [points[i] for i in pareto_front(points)]
    ax.plot([p[0] for p in front], [p[1] for p in front], color="black", lw=1.2, ls="--", zorder=2,
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
    ax.legend(fontsize=8)
    return len(front)


def ok_rows(df):
    return df[df["status"] == "ok"] if "status" in df.columns else df


def series_label(row, columns):
    return " ".join(str(row[c]) for c in columns)


def lines(args):
    df = ok_rows(pd.concat([pd.read_csv(path) for path in args.csv], ignore_index=True))
    series = args.series.split(",")
    if "technique_spec" in df.columns and series == ["technique"]:
        series = ["technique_spec"]
    for col in [args.x, args.y] + series + ([args.facet] if args.facet else []):
        if col not in df.columns:
            sys.exit(f"plot.py: {args.csv}: column '{col}' missing")
    facets = list(dict.fromkeys(df[args.facet])) if args.facet else [None]
    fits = []
    fig, axes = plt.subplots(1, len(facets), figsize=(6.5 * len(facets), 4.8), dpi=120, squeeze=False)
    for ax, facet in zip(axes[0], facets):
        part = df if facet is None else df[df[args.facet] == facet]
        for key, group in part.groupby(series if len(series) > 1 else series[0], sort=False):
            key = key if isinstance(key, tuple) else (key,)
            stats = group.groupby(args.x)[args.y].agg(["median", "min", "max", "count"]).sort_index()
            lo, hi = stats["median"] - stats["min"], stats["max"] - stats["median"]
            if stats["count"].max() <= 1 and args.y == "wall_ms_median" and "wall_ms_p5" in group.columns:
                pct = group.groupby(args.x)[["wall_ms_p5", "wall_ms_p95"]].median().sort_index()
                lo, hi = stats["median"] - pct["wall_ms_p5"], pct["wall_ms_p95"] - stats["median"]
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
        ax.legend(fontsize=8)
        if facet is not None:
            ax.set_title(f"{args.facet} = {facet}", fontsize=9)
    first = df.iloc[0]
    fig.suptitle(args.title or f"{args.y} against {args.x} ({first.get('renderer', '')})", fontsize=10)
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
    df = pd.read_csv(args.csv[0])
    for col in ("technique_spec", "share_cpu", "share_vertex", "share_fill", "class"):
        if col not in df.columns:
            sys.exit(f"plot.py: {args.csv[0]}: column '{col}' missing (written by bench bottleneck?)")
    def where(r):
        n = r.get("instances")
        return f"{r['scene']}" + (f" x{int(n)}" if pd.notna(n) and n else "")

    labels = [f"{r['technique_spec']} @ {where(r)}" for _, r in df.iterrows()]
    perts = [c[len("time_ratio_"):] for c in df.columns if c.startswith("time_ratio_") and
             c != "time_ratio_baseline"]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 1.2 + 0.55 * len(df)), dpi=120,
                                  gridspec_kw={"width_ratios": [1, 1.3]})
    y = range(len(df))
    left = [0.0] * len(df)
    for col, name, color in (("share_cpu", "cpu", "#4c72b0"), ("share_vertex", "vertex", "#55a868"),
                             ("share_fill", "fill", "#c44e52")):
        ax.barh(y, df[col], left=left, color=color, label=name)
        left = [a + b for a, b in zip(left, df[col])]
    for i, (_, r) in enumerate(df.iterrows()):
        poor = " ?" if str(r.get("poor_fit", False)).lower() == "true" else ""
        ax.text(1.02, i, f"{r['class']}{poor}  ({r['wall_ms_baseline']:.1f} ms)", va="center", fontsize=8)
    ax.set_yticks(list(y))
    ax.set_yticklabels(labels, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlim(0, 1.45)
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
    fig.suptitle(args.title or "Bottleneck classification", fontsize=10)
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
    every = pd.concat([pd.read_csv(path) for path in args.csv], ignore_index=True)
    df = ok_rows(every)
    for col in ["technique_spec", args.y] + ([args.facet] if args.facet else []):
        if col not in every.columns:
            sys.exit(f"plot.py: {args.csv}: column '{col}' missing")
    facets = list(dict.fromkeys(every[args.facet])) if args.facet else [None]
    specs = list(dict.fromkeys(every["technique_spec"]))
    names = dict(zip(specs, diff_labels(specs))) if args.diff_labels else \
        {spec: spec.replace(args.strip, "", 1) if args.strip else spec for spec in specs}
    height = 0.45 * len(specs) * len(facets) + 1.5
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
    # Above the first panel's title (tight_layout does not make room for a suptitle; bbox "tight"
    # saving keeps what lies above 1.0).
    fig.suptitle(args.title or f"{args.y} per configuration ({first.get('renderer', '')})", fontsize=10,
                 y=1.0 + 0.3 / height)
    save(fig, args.out, f"{len(df)} rows")


def save(fig, out, what):
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(f"{out}.{ext}", bbox_inches="tight")
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
