#!/usr/bin/python3
"""The tables and figures of results/raytraced/README.md from what scripts/raytraced-study.sh writes. Run
with Debian's python3 (python3-pandas, python3-numpy, python3-matplotlib):

  /usr/bin/python3 tools/raytraced_summary.py results/raytraced

prints Markdown (the script keeps it as tables.md) and writes accuracy.png, soft.png, build.png and
rays.png beside the CSVs. Times are ratios within a round of one process (bench --repeat: the rows of
round k share `repeat` = k), summarised as the median over the rounds with [min, max]; the few absolute
times shown (build times, the ray fit's slope) are labelled as this machine's under its load.
- accuracy_<scene>.csv, soft_<scene>.csv: bench accuracy rows (acc_* columns), every technique per round;
  where raytraced's modes hard and guided are both there, a line of what guided saves against hard
  (unsure share, rays traced, time, and whether its error is hard's).
- build.csv: one raytraced row per process, configurations (instances, tess_factor) in turn.
- rays.csv: none and raytraced:mode=hard per round, per (instances, tess_factor, size).
- order.csv: the same on generated grids of spheres (scenes/order_<side>_<sorted|shuffled>.json), two
  processes per grid and order.
- motion.csv: the same on aircraft_day in motion, per instance count.
A section whose CSV is missing is left out with a line saying so; a row whose status is not ok stops the
summary (exit 1) naming it."""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

RT_HARD = "raytraced hard"
ZERO_FLOOR = 1e-4  # wrong % plotted for 0 on a log axis (below any measured non-zero share)


def fail(message):
    print(f"raytraced_summary: {message}", file=sys.stderr)
    sys.exit(1)


def read(path):
    rows = pd.read_csv(path)
    bad = rows[rows.status != "ok"]
    if len(bad):
        first = bad.iloc[0]
        fail(f"{path}: {first.technique} is {first.status}: {first.get('error', '')}")
    return rows


def prop(properties, name):
    for part in str(properties).split(":"):
        key, _, value = part.partition("=")
        if key == name:
            return value
    return ""


def label(row):
    """A technique as the tables name it: its name, and for raytraced its mode (and rays)."""
    if row.technique != "raytraced":
        return row.technique
    mode = prop(row.properties, "mode")
    rays = prop(row.properties, "rays")
    return f"raytraced {mode}" + (f" rays={rays}" if mode == "soft" and rays else "")


def labelled(rows):
    rows = rows.copy()
    rows["label"] = [label(r) for r in rows.itertuples()]
    rows["round"] = rows["repeat"] if "repeat" in rows else 1
    return rows


def spread(values, digits=2):
    """'median [min, max]' of a list of numbers (only the median for one value)."""
    v = np.asarray(values, dtype=float)
    if len(v) == 1:
        return f"{v[0]:.{digits}f}"
    return f"{np.median(v):.{digits}f} [{v.min():.{digits}f}, {v.max():.{digits}f}]"


def ratios(rows, over):
    """Per label, the list of (its wall median / `over`'s wall median) within each round."""
    base = rows[rows.label == over].set_index("round").wall_ms_median
    out = {}
    for lab, group in rows.groupby("label", sort=False):
        r = [row.wall_ms_median / base[row.round] for row in group.itertuples() if row.round in base]
        out[lab] = r
    return out


def pct(value):
    return "0" if value == 0 else f"{value:.3g}"


def accuracy_tables(folder, kind):
    """Per scene: each technique's error (identical in every round: checked) and its time ratios."""
    paths = sorted(glob.glob(os.path.join(folder, f"{kind}_*.csv")))
    if not paths:
        print(f"_No {kind}_*.csv: section {kind} was not run._\n")
        return {}
    summary = {}
    for path in paths:
        rows = labelled(read(path))
        scene = os.path.basename(path)[len(kind) + 1:-4]
        baseline = rows.label.iloc[0]
        vs_base = ratios(rows, baseline)
        vs_rt = ratios(rows, RT_HARD) if RT_HARD in set(rows.label) else {}
        first = rows.iloc[0]
        print(f"**{scene}** ({first.scene_triangles:,} triangles, camera {first.camera}, "
              f"{first.width}x{first.height}, light {first.lights}, reference {first.acc_reference}, "
              f"{rows['round'].max()} rounds)\n")
        print(f"| technique | judged | wrong % | off edge % | RMSE | NaN/Inf/OOR | time vs {baseline} | "
              f"time vs {RT_HARD} | rays traced | unsure % |")
        print("|---|---:|---:|---:|---:|---|---:|---:|---:|---:|")
        scene_summary = []
        for lab, group in rows.groupby("label", sort=False):
            r = group.iloc[0]
            for col in ("acc_wrong_pct", "acc_rmse", "acc_evaluated"):
                if group[col].nunique() != 1:
                    fail(f"{path}: {lab}'s {col} differs between rounds: {list(group[col])}")
            bad = int(r.acc_nan + r.acc_inf + r.acc_out_of_range)
            rays = group.get("counter_rays_traced")
            rays_cell = f"{int(rays.iloc[0]):,}" if rays is not None and pd.notna(rays.iloc[0]) else ""
            rt_cell = spread(vs_rt[lab]) if lab in vs_rt else ""
            unsure = group.get("counter_unsure_pct")
            unsure_cell = f"{unsure.iloc[0]:.3g}" if unsure is not None and pd.notna(unsure.iloc[0]) else ""
            print(f"| {lab} | {int(r.acc_evaluated):,} | {pct(r.acc_wrong_pct)} | "
                  f"{pct(r.acc_wrong_no_edge_pct)} | {r.acc_rmse:.4f} | {int(r.acc_nan)}/{int(r.acc_inf)}/"
                  f"{int(r.acc_out_of_range)} | {spread(vs_base[lab])} | {rt_cell} | {rays_cell} | "
                  f"{unsure_cell} |")
            scene_summary.append({"label": lab, "wrong": r.acc_wrong_pct, "rmse": r.acc_rmse, "bad": bad,
                                  "vs_rt": np.median(vs_rt[lab]) if lab in vs_rt else np.nan,
                                  "vs_base": np.median(vs_base[lab])})
        print()
        guided_line(rows, vs_rt)
        summary[scene] = scene_summary
    return summary


def guided_line(rows, vs_rt):
    """What mode=guided saves against mode=hard on this scene: its unsure share, its rays over hard's and
    its time over hard's, and whether its error equals hard's (the time ratio is "at equal error" only
    then)."""
    guided, hard = rows[rows.label == "raytraced guided"], rows[rows.label == RT_HARD]
    if guided.empty or hard.empty or "counter_unsure_pct" not in rows:
        return
    g, h = guided.iloc[0], hard.iloc[0]
    same = g.acc_wrong_pct == h.acc_wrong_pct and g.acc_rmse == h.acc_rmse
    error = "the same error as hard" if same else \
        f"error {pct(g.acc_wrong_pct)}% wrong, RMSE {g.acc_rmse:.4f} against hard's " \
        f"{pct(h.acc_wrong_pct)}%, {h.acc_rmse:.4f}"
    print(f"guided against hard: unsure {g.counter_unsure_pct:.3g}%, rays traced "
          f"{int(g.counter_rays_traced):,} of {int(h.counter_rays_traced):,} "
          f"({g.counter_rays_traced / h.counter_rays_traced:.3f}x), time "
          f"{spread(vs_rt['raytraced guided'])}x hard's, {error}.\n")


# The figures' markers: the other techniques in blue squares, raytraced's modes in colours of their own.
MODE_STYLE = {"hard": ("o", "C3"), "soft": ("^", "C1"), "guided": ("D", "C2")}


def short(lab):
    """A figure's label: rt hard, s1 ... s64 for mode=soft's rays, guided."""
    if lab.startswith("raytraced soft rays="):
        return "s" + lab.rsplit("=", 1)[1]
    return lab.replace("raytraced ", "rt " if lab == RT_HARD else "")


def accuracy_figure(summary, metric, path, ylabel):
    if not summary:
        return
    scenes = list(summary)
    fig, axes = plt.subplots(1, len(scenes), figsize=(3.6 * len(scenes), 3.6), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        pts = [p for p in summary[scene] if np.isfinite(p["vs_rt"])]
        for p in pts:
            y = max(p[metric], ZERO_FLOOR) if metric == "wrong" else p[metric]
            mode = p["label"].split(" ")[1] if p["label"].startswith("raytraced ") else ""
            marker, colour = MODE_STYLE.get(mode, ("s", "C0"))
            ax.plot(p["vs_rt"], y, marker, color=colour, alpha=0.8)
            ax.annotate(short(p["label"]), (p["vs_rt"], y), fontsize=6, xytext=(2, 3),
                        textcoords="offset points", rotation=45 if mode == "soft" else 0)
        ax.set_xscale("log")
        ax.set_xticks([0.1, 0.2, 0.3, 0.5, 0.7, 1, 1.5, 2, 3, 5, 7, 10, 20, 30, 50, 100])
        ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        xs = [p["vs_rt"] for p in pts]
        ax.set_xlim(min(xs) / 1.3, max(xs) * 1.6)
        ax.set_yscale("log")  # RMSE too: stratified rays' error falls as a power of their count
        if metric != "wrong":  # a decade or two of RMSE: label 1, 2 and 5 of each
            ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
            ax.yaxis.set_minor_formatter(NullFormatter())
        ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        if metric == "wrong":
            ax.axhline(ZERO_FLOOR, color="grey", lw=0.5, ls=":")
        ax.set_title(scene, fontsize=9)
        ax.set_xlabel(f"frame time / {RT_HARD} (same round, median)", fontsize=7)
        ax.tick_params(labelsize=7)
    axes[0][0].set_ylabel(ylabel, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def section_csv(folder, section):
    """The path of `section`'s CSV in `folder`, or None (with a line saying so) where it was not run."""
    path = os.path.join(folder, f"{section}.csv")
    if os.path.exists(path):
        return path
    print(f"_No {section}.csv: section {section} was not run._\n")
    return None


def fit(x_columns, y):
    """Least squares y ~ [1, x...]: coefficients, R^2 and the largest residual relative to y."""
    a = np.column_stack([np.ones(len(y))] + list(x_columns))
    coef, *_ = np.linalg.lstsq(a, y, rcond=None)
    pred = a @ coef
    ss_res = float(((y - pred) ** 2).sum())
    ss_tot = float(((y - y.mean()) ** 2).sum())
    r2 = 1.0 - ss_res / ss_tot if ss_tot > 0 else float("nan")
    rel = np.abs(y - pred) / np.maximum(np.abs(y), 1e-12)
    return coef, r2, float(rel.max()), pred


def fit_row(name, model, x_columns, y):
    """Fits the delta (ms) to `x_columns` and prints the fit's row of the rays table: the constant a in ms,
    the slopes b, c ... per ray (ns). Returns the coefficients and R^2."""
    c, r2, largest, _ = fit(x_columns, y)
    slopes = [f"{chr(ord('b') + i)} {value * 1e6:.3g} ns" for i, value in enumerate(c[1:])]
    coefficients = ", ".join([f"a {c[0]:.3g} ms"] + slopes)
    print(f"| {name} | {model} | {coefficients} | {r2:.3f} | {largest:.0%} |")
    return c, r2


def build_section(folder):
    path = section_csv(folder, "build")
    if path is None:
        return
    rows = read(path)
    keys = ["instances", "tess_factor"]
    rounds = rows.groupby(keys).size().max()
    print(f"Each configuration in its own process, {rounds} rounds round-robin. Build "
          "times are this machine's under its load (machine.txt): median [min, max] over the rounds; a "
          "scheduling delay only adds, so the minimum is the build's own time and the fits use it.\n")
    print("| instances | tess factor | triangles | structure bytes | bytes / triangle | bottom levels "
          "build ms | min, us per triangle | top level build ms | min, us per instance | setup ms |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    table = []
    for (n, t), g in rows.groupby(keys):
        r = g.iloc[0]
        if g.counter_structure_bytes.nunique() != 1:
            fail(f"{path}: structure_bytes differs between rounds at {n} x {t}")
        tris = int(r.scene_triangles)
        bottom, top = g.counter_bottom_levels_build_ms.min(), g.counter_top_level_build_ms.min()
        per_tri = f"{bottom * 1e3 / tris:.3f}" if n == 1 else ""
        per_instance = f"{top * 1e3 / n:.3f}" if n >= 100 else ""
        print(f"| {n} | {t:g} | {tris:,} | {int(r.counter_structure_bytes):,} | "
              f"{r.counter_structure_bytes / tris:.0f} | {spread(g.counter_bottom_levels_build_ms)} | "
              f"{per_tri} | {spread(g.counter_top_level_build_ms, 3)} | {per_instance} | "
              f"{spread(g.setup_ms, 0)} |")
        table.append({"instances": n, "tess": t, "triangles": tris, "bottom": bottom, "top": top,
                      "bytes": r.counter_structure_bytes})
    t = pd.DataFrame(table)
    print("\n(The ground casts no shadow: the top level holds the aircraft only.)\n")
    one = t[t.instances == 1].sort_values("triangles")  # the bottom levels: one aircraft and the ground
    many = t[t.tess == 0.5].sort_values("instances")  # the top level: instances of one coarse aircraft
    lines = []
    big = one[one.bottom >= 1.0]  # below a millisecond the submission's own cost and the clock's grain show
    if len(big) >= 3:
        tri = big.triangles.to_numpy(float)
        per = big.bottom.to_numpy(float) / tri * 1e6  # ns per triangle
        per_level = per / np.log2(tri)
        linear, nlogn = per.max() / per.min(), per_level.max() / per_level.min()
        if min(linear, nlogn) > 1.3:
            verdict = "neither is constant within 30%"
        else:
            verdict = f"{'T log2 T' if nlogn < linear else 'T'} describes the growth (within " \
                      f"{(min(linear, nlogn) - 1):.0%})"
        lines.append(f"- Bottom levels, builds of 1 ms and more ({int(tri.min()):,} to {int(tri.max()):,} "
                     f"triangles): {per.min():.0f} to {per.max():.0f} ns per triangle (x{linear:.2f} "
                     f"over x{tri.max() / tri.min():.0f} triangles), {per_level.min():.1f} to "
                     f"{per_level.max():.1f} ns per triangle and log2(triangles) (x{nlogn:.2f}): {verdict}.")
    bpt = one.bytes.to_numpy(float) / one.triangles.to_numpy(float)
    lines.append(f"- Storage of one mesh: {bpt.min():.0f}-{bpt.max():.0f} bytes per triangle.")
    if len(many) >= 3:
        n = many.instances.to_numpy(float)
        y = many.top.to_numpy(float)
        c, r, e, _ = fit([n], y)
        lines.append(f"- Top level ({int(n.min())} to {int(n.max())} instances, the minimum over rounds): "
                     f"build ms = {c[0]:.3g} + {c[1] * 1e3:.3g} us per instance, R^2 {r:.3f} (largest "
                     f"residual {e:.0%}).")
    print("\n".join(lines) + "\n")
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for ax, part, x, xl, yl in ((axes[0], one, "triangles", "triangles (one aircraft + ground)", "bottom"),
                                (axes[1], many, "instances", "instances (aircraft, tess factor 0.5)", "top")):
        g = rows.merge(part[["instances", "tess"]].rename(columns={"tess": "tess_factor"}), on=keys)
        xs = g.scene_triangles if x == "triangles" else g.instances
        col = "counter_bottom_levels_build_ms" if yl == "bottom" else "counter_top_level_build_ms"
        ax.plot(xs, g[col], "o", alpha=0.35, color="C0", label="each round")
        ax.plot(part[x], part[yl], "-", color="C3", label="minimum over rounds")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.yaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel(xl, fontsize=8)
        ax.set_ylabel(("bottom levels" if yl == "bottom" else "top level") + " build, ms (this machine)",
                      fontsize=8)
        ax.legend(fontsize=7)
        ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "build.png"), dpi=110)
    plt.close(fig)


def paired(rows, keys):
    """Per configuration and round: none's and raytraced's wall, rays traced and triangles."""
    out = []
    for key, g in rows.groupby(keys + ["round"]):
        none = g[g.technique == "none"]
        rt = g[g.technique == "raytraced"]
        if len(none) != 1 or len(rt) != 1:
            fail(f"{dict(zip(keys + ['round'], key))}: expected one none and one raytraced row")
        n, r = none.iloc[0], rt.iloc[0]
        out.append(dict(zip(keys + ["round"], key), none_ms=n.wall_ms_median, rt_ms=r.wall_ms_median,
                        rays=r.counter_rays_traced, triangles=r.scene_triangles,
                        top_ms=r.get("counter_top_level_build_ms", np.nan),
                        built=r.get("counter_structures_built", np.nan),
                        cpu_structures=r.get("cpu_structures_ms_median", np.nan),
                        motion_ms=r.get("motion_ms_median", np.nan)))
    return pd.DataFrame(out)


def rays_section(folder):
    path = section_csv(folder, "rays")
    if path is None:
        return
    rows = labelled(read(path))
    keys = ["instances", "tess_factor", "width"]
    p = paired(rows, keys)
    p["delta"] = p.rt_ms - p.none_ms
    p["ratio"] = p.rt_ms / p.none_ms
    print("none and raytraced:mode=hard in one process per configuration, "
          f"{p['round'].max()} rounds; delta = raytraced's wall median minus none's in the same round "
          "(ms, this machine under its load), median [min, max].\n")
    print("| instances | tess factor | size | triangles | rays traced | raytraced / none | delta ms | "
          "ns per ray |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|")
    med = []
    for (n, t, w), g in p.groupby(keys):
        if g.rays.nunique() != 1:
            fail(f"{path}: rays_traced differs between rounds at {n} x {t}, {w}")
        r = g.iloc[0]
        print(f"| {n} | {t:g} | {w}x{w} | {int(r.triangles):,} | {int(r.rays):,} | {spread(g.ratio)} | "
              f"{spread(g.delta, 1)} | {g.delta.median() / r.rays * 1e6:.0f} |")
        med.append({"instances": n, "tess": t, "width": w, "triangles": r.triangles, "rays": r.rays,
                    "delta": g.delta.median(), "none": g.none_ms.median()})
    m = pd.DataFrame(med)
    print()
    if len(m) < 4:
        return
    print("Fits of the median delta (least squares; R^2, largest residual relative to the delta), over every "
          "configuration and over those with one instance (one bottom level under a trivial top level):\n")
    print("| configurations | model | coefficients | R^2 | largest residual |\n|---|---|---|---:|---:|")
    fits = {}
    for name, part in (("all", m), ("one instance", m[m.instances == 1])):
        if len(part) < 4:
            continue
        rays = part.rays.to_numpy(float)
        work = rays * np.log2(part.triangles.to_numpy(float))
        y = part.delta.to_numpy(float)
        fits[name] = fit_row(name, "delta = a + b R log2 T", [work], y)
        fit_row(name, "delta = a + b R", [rays], y)
        fit_row(name, "delta = a + b R + c R log2 T", [rays, work], y)
    print("\n(R: rays traced, T: scene triangles; b and c per ray and per ray and tree level.)\n")
    if "all" not in fits:
        return
    (c1, r1), work = fits["all"], m.rays.to_numpy(float) * np.log2(m.triangles.to_numpy(float))
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for i, ((n, t), g) in enumerate(m.groupby(["instances", "tess"])):
        g = g.sort_values("rays")
        ax.plot(g.rays * np.log2(g.triangles), g.delta.clip(lower=0.1), "o-", color=f"C{i}",
                label=f"{n} x aircraft, tess {t:g} ({int(g.triangles.iloc[0]):,} tri)")
    xs = np.geomspace(work.min() * 0.9, work.max() * 1.05, 50)
    ys = c1[0] + c1[1] * xs
    ax.plot(xs[ys > 0], ys[ys > 0], "k--", lw=0.8, label=f"best a + b R log2 T, all (R^2 {r1:.2f})")
    ax.set_xlabel("rays traced x log2(scene triangles)", fontsize=8)
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_ylabel("raytraced - none, ms per frame (same round; 0.1 = at most)", fontsize=8)
    ax.legend(fontsize=6)
    ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "rays.png"), dpi=110)
    plt.close(fig)


def order_section(folder):
    path = section_csv(folder, "order")
    if path is None:
        return
    rows = labelled(read(path))
    rows["side"] = [int(str(sc).split("_")[1]) for sc in rows.scene]
    rows["kind"] = [str(sc).split("_")[2] for sc in rows.scene]
    # A process is a run of its own: number them so that paired() keeps their rounds apart.
    rows["process"] = (rows["round"] == 1) & (rows.technique == "none")
    rows["process"] = rows.process.cumsum()
    p = paired(rows, ["side", "kind", "process"])
    p["ratio"] = p.rt_ms / p.none_ms
    p["per_ray"] = (p.rt_ms - p.none_ms) / p.rays * 1e6  # ns
    print("Two processes per grid and order, alternating (sorted, shuffled, shuffled, sorted ...), none and "
          "raytraced:mode=hard side by side in each; median [min, max] over every round of both processes. "
          "Per ray: (raytraced - none) / rays traced, this machine under its load.\n")
    print("| grid | spheres | triangles | rays traced | raytraced / none, sorted | shuffled | ns per ray, "
          "sorted | shuffled | shuffled / sorted, per ray |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    med = []
    for side, g in p.groupby("side"):
        a, b = g[g.kind == "sorted"], g[g.kind == "shuffled"]
        if set(a.rays) != set(b.rays) or a.rays.nunique() != 1:
            fail(f"{path}: the {side}x{side} grid's rays differ between orders or rounds")
        r = a.iloc[0]
        print(f"| {side}x{side} | {side * side:,} | {int(r.triangles):,} | {int(r.rays):,} | "
              f"{spread(a.ratio)} | {spread(b.ratio)} | {spread(a.per_ray, 0)} | {spread(b.per_ray, 0)} | "
              f"{b.per_ray.median() / a.per_ray.median():.1f} |")
        med.append({"n": side * side, "sorted": a.per_ray.median(), "shuffled": b.per_ray.median()})
    print()
    m = pd.DataFrame(med).sort_values("n")
    if len(m) >= 3:
        n = m.n.to_numpy(float)
        lines = []
        for kind in ("sorted", "shuffled"):
            y = m[kind].to_numpy(float)
            steps = ", ".join(f"x{b / a:.1f}" for a, b in zip(y[:-1], y[1:]))
            (_, k), r2, _, _ = fit([np.log(n)], np.log(y))
            lines.append(f"- {kind}: the cost per ray grows {steps} from one grid to the next "
                         f"(x{n[1] / n[0]:.0f} instances each); as a power of the instance count n^{k:.2f} "
                         f"(fit of the logarithms, R^2 {r2:.3f}).")
        lines.append("- A tree that prunes adds a constant amount per x4 instances (log n); a traversal that "
                     "visits every instance multiplies by 4 (n^1).")
        print("\n".join(lines) + "\n")


def motion_section(folder):
    path = section_csv(folder, "motion")
    if path is None:
        return
    rows = labelled(read(path))
    p = paired(rows, ["instances"])
    p["ratio"] = p.rt_ms / p.none_ms
    p["share"] = p.top_ms / p.rt_ms
    print(f"aircraft_day moving, none and raytraced:mode=hard side by side, {p['round'].max()} rounds "
          "(median [min, max]); the top level's build time is the counter measured before the first frame "
          "in the same process, its share that over raytraced's frame in the same round.\n")
    print("| instances | triangles | structures built per frame | rays traced | raytraced / none | "
          "top level build ms | its share of the frame | structures pass CPU ms | motion CPU ms |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for n, g in p.groupby("instances"):
        r = g.iloc[0]
        print(f"| {n} | {int(r.triangles):,} | {int(r.built)} | {int(g.rays.median()):,} | "
              f"{spread(g.ratio)} | {spread(g.top_ms, 3)} | {spread(g.share * 100, 3)}% | "
              f"{spread(g.cpu_structures, 4)} | {spread(g.motion_ms, 3)} |")
    print()


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        fail("usage: tools/raytraced_summary.py FOLDER (the output folder of scripts/raytraced-study.sh)")
    folder = sys.argv[1]
    machine = os.path.join(folder, "machine.txt")
    if os.path.exists(machine):
        print("```text\n" + open(machine).read().rstrip() + "\n```\n")
    print("## Hard lights: accuracy against time\n")
    summary = accuracy_tables(folder, "accuracy")
    accuracy_figure(summary, "wrong", os.path.join(folder, "accuracy.png"),
                    f"wrong % of judged samples ({ZERO_FLOOR:g} = none)")
    print("## Area lights: RMSE against time\n")
    soft = accuracy_tables(folder, "soft")
    accuracy_figure(soft, "rmse", os.path.join(folder, "soft.png"), "visibility RMSE")
    print("## Structure builds\n")
    build_section(folder)
    print("## Frame time against rays x log2(triangles)\n")
    rays_section(folder)
    print("## The top level's traversal against the order of its instances\n")
    order_section(folder)
    print("## In motion: the top level rebuilt every frame\n")
    motion_section(folder)


if __name__ == "__main__":
    main()
