#!/usr/bin/python3
"""The tables of results/effects/README.md, regenerated from the CSVs scripts/effects.sh writes. Run with
Debian's python3 (/usr/bin/python3, python3-pandas):

  /usr/bin/python3 tools/effects_summary.py results/effects

prints Markdown: per effect, the configuration with it and without it, the median of the per-round wall
medians, the paired ratio (without / with, per round: median [min, max]) and the exact work of one
census frame (vertices, fragments, draws) with which passes ran.
"""
import glob
import os
import sys

import pandas as pd


def spec_value(properties, name):
    for part in str(properties).split(":"):
        key, _, value = part.partition("=")
        if key == name:
            return value
    return ""


def draws(row):
    total = 0
    for column, value in row.items():
        if column.startswith("work_") and column.endswith("_draws") and pd.notna(value):
            total += int(value)
    return total


def exact(row):
    return "%d vertices, %d fragments, %d draws" % (row["load_vertices"], row["load_fragments"], draws(row))


def property_toggle(path, name):
    """Rows of one run with property `name` on and off, measured in interleaved rounds."""
    rows = pd.read_csv(path)
    rows["value"] = rows["properties"].map(lambda p: spec_value(p, name))
    on, off = rows[rows["value"] == "on"], rows[rows["value"] == "off"]
    ratios = off["wall_ms_median"].values / on["wall_ms_median"].values
    print("| %s | %.1f ms | %.1f ms | %.3f [%.3f, %.3f] | %s | %s |" % (
        name, on["wall_ms_median"].median(), off["wall_ms_median"].median(), pd.Series(ratios).median(),
        ratios.min(), ratios.max(), exact(on.iloc[0]), exact(off.iloc[0])))


def fill_light(folder):
    rows = pd.concat([pd.read_csv(p) for p in sorted(glob.glob(os.path.join(folder, "fill_light_*.csv")))])
    rows["without"] = rows["scene"].str.contains("unshadowed")
    print("| technique | with: wall | without: wall | without / with, per round | with: exact work | "
          "without: exact work | passes left out without |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for technique, group in rows.groupby("technique", sort=False):
        with_rows, without_rows = group[~group["without"]], group[group["without"]]
        ratios = without_rows["wall_ms_median"].values / with_rows["wall_ms_median"].values
        skipped = without_rows.iloc[0]["passes_skipped"]
        print("| %s | %.2f ms | %.2f ms | %.3f [%.3f, %.3f] | %s | %s | %s |" % (
            technique, with_rows["wall_ms_median"].median(), without_rows["wall_ms_median"].median(),
            pd.Series(ratios).median(), ratios.min(), ratios.max(), exact(with_rows.iloc[0]),
            exact(without_rows.iloc[0]), skipped if isinstance(skipped, str) else "none"))


def auto(path):
    rows = pd.read_csv(path)
    print("| scene | effects requested | chosen | wall median | why |")
    print("| --- | --- | --- | --- | --- |")
    for _, r in rows.iterrows():
        print("| %s | %s | %s | %.2f ms | %s |" % (r["scene"], r["effects_requested"], r["technique"],
                                                 r["wall_ms_median"], r["auto_choice"]))


def label(row):
    """A technique with the part properties that tell hybrids apart."""
    if row["technique"] == "hybrid":
        return "hybrid self=%s cast=%s" % (spec_value(row["properties"], "self"), spec_value(row["properties"], "cast"))
    return row["technique"]


def hybrids(folder):
    """Every hybrid and pure technique of scripts/effects.sh's hybrid section: wall time in interleaved
    rounds as a ratio to the shadow map of the same round, accuracy against the reference, exact work."""
    time = pd.read_csv(os.path.join(folder, "hybrid_time.csv"))
    accuracy = pd.read_csv(os.path.join(folder, "hybrid_accuracy.csv"))
    time["label"] = time.apply(label, axis=1)
    accuracy["label"] = accuracy.apply(label, axis=1)
    time["round"] = time.groupby("label").cumcount()
    base = time[time["label"] == "shadowmap"].set_index("round")["wall_ms_median"]
    print("| technique | wall median | / shadowmap, per round | wrong % | wrong off edges % | exact work |")
    print("| --- | --- | --- | --- | --- | --- |")
    for name, group in time.groupby("label", sort=False):
        ratios = group["wall_ms_median"].values / base.loc[group["round"]].values
        acc = accuracy[accuracy["label"] == name].iloc[0]
        print("| %s | %.1f ms | %.3f [%.3f, %.3f] | %.3f | %.3f | %s |" % (
            name, group["wall_ms_median"].median(), pd.Series(ratios).median(), ratios.min(), ratios.max(),
            acc["acc_wrong_pct"], acc["acc_wrong_no_edge_pct"], exact(group.iloc[0])))


def motion(folder):
    """aircraft_day moving against frozen at noon, per round (scripts/effects.sh's motion section), and
    accuracy and flicker along the camera path."""
    rows = pd.concat([pd.read_csv(p).assign(round=i) for i, p in
                      enumerate(sorted(glob.glob(os.path.join(folder, "motion_[0-9]*.csv"))))])
    rows["label"] = rows.apply(label, axis=1)
    rows["moving"] = rows["path_time"] == "moving"
    accuracy = pd.read_csv(os.path.join(folder, "motion_accuracy.csv"))
    accuracy["label"] = accuracy.apply(label, axis=1)
    print("| technique | frozen: wall | moving: wall | moving / frozen, per round | motion update (CPU, median) "
          "| wrong % along the path (mean, max) | flicker |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name, group in rows.groupby("label", sort=False):
        frozen = group[~group["moving"]].set_index("round")["wall_ms_median"]
        moving = group[group["moving"]].set_index("round")
        ratios = (moving["wall_ms_median"] / frozen.loc[moving.index]).values
        acc = accuracy[accuracy["label"] == name].iloc[0]
        print("| %s | %.2f ms | %.2f ms | %.3f [%.3f, %.3f] | %.3f ms | %.3f, %.3f | %.4f |" % (
            name, frozen.median(), moving["wall_ms_median"].median(), pd.Series(ratios).median(), ratios.min(),
            ratios.max(), moving["motion_ms_median"].median(), acc["acc_path_wrong_mean_pct"],
            acc["acc_path_wrong_max_pct"], acc["acc_path_flicker"]))


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "results/effects"
    print("| property | on: wall | off: wall | off / on, per round | on: exact work | off: exact work |")
    print("| --- | --- | --- | --- | --- | --- |")
    property_toggle(os.path.join(folder, "bleeding.csv"), "bleeding")
    property_toggle(os.path.join(folder, "modulate.csv"), "modulate")
    print()
    fill_light(folder)
    print()
    if os.path.exists(os.path.join(folder, "auto.csv")):
        auto(os.path.join(folder, "auto.csv"))
        print()
    if os.path.exists(os.path.join(folder, "hybrid_time.csv")):
        hybrids(folder)
        print()
    if os.path.exists(os.path.join(folder, "motion_accuracy.csv")):
        motion(folder)


if __name__ == "__main__":
    main()
