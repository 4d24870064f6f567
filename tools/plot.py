#!/usr/bin/python3
"""Plots regenerated from result CSVs only (DESIGN.md section 7). Run with Debian's python3
(/usr/bin/python3, python3-matplotlib, python3-pandas):

  /usr/bin/python3 tools/plot.py pareto results/accuracy/aircraft.csv --out results/accuracy/pareto
      error against median frame time, one series per technique, the Pareto front highlighted;
      writes OUT.png and OUT.svg.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
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

    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=120)
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
    first = df.iloc[0]
    ax.set_title(args.title or f"Accuracy against time: {first.get('scene', '')}, "
                 f"{first.get('width', '')}x{first.get('height', '')}, {first.get('renderer', '')}", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig(f"{args.out}.{ext}")
    print(f"wrote {args.out}.png and {args.out}.svg ({len(df)} points, {len(front)} on the front)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="kind", required=True)
    p = sub.add_parser("pareto", help="error against median frame time")
    p.add_argument("csv", nargs="+", help="CSV files written by `bench accuracy`")
    p.add_argument("--out", required=True, help="output path without extension")
    p.add_argument("--metric", default="acc_wrong_pct", help="error column (default acc_wrong_pct)")
    p.add_argument("--title", default="")
    p.add_argument("--logy", action="store_true", help="logarithmic error axis")
    args = parser.parse_args()
    if args.kind == "pareto":
        pareto(args)


if __name__ == "__main__":
    main()
