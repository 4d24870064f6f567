#!/usr/bin/python3
"""The tables of results/drivers/README.md from what scripts/driver-study.sh writes: one driver (the base,
the system's Mesa) against another (the head) for every configuration of results/drivers/suite.json.
Run with Debian's python3 (python3-pandas, python3-numpy, python3-pil):

  /usr/bin/python3 tools/driver_study.py results/drivers

prints Markdown and writes diff-<config>.png beside the CSVs for the largest image differences.
- work.csv: one census frame per configuration and driver, in the suite's order, base first. Its counts
  are split into the application's work (GL calls, draws, triangles and primitives submitted, the
  technique's own counters: what the harness asked for, so equal on every driver) and the driver's
  (vertex and fragment shader invocations, primitives out of the clipper, samples a query counted:
  how the driver chose to do it). A rate (a counter per second) or a time (a counter ending in _ms) is
  time, and is left out.
- ci-instructions/ and ci-wall/: bench ci with the two drivers as its sides, layer B (instructions per
  frame under callgrind: report.json, instructions.json) and layer C (wall time in interleaved rounds:
  report.json, wall.csv).
- images/<driver>/<config>.png and .vis.png: the census frame's colour and visibility.
Exits 1 with one line when a row is missing or the two drivers' rows ran on different backends."""
import json
import os
import re
import sys

import numpy as np
import pandas as pd
from PIL import Image

DRIVER_SUFFIXES = ("_clipped_primitives", "_vertices", "_fragments")  # before "_primitives"
APPLICATION_SUFFIXES = ("_gl_calls", "_draws", "_triangles", "_primitives")
DRIVER_COUNTERS = ("counter_stencil_samples_passed",)  # an occlusion query: what the driver rasterised
PIXEL_STEP = 2  # the golden matrix's tolerance (bench/golden/MatrixCheck.h): a channel may differ by 2/255
PIXEL_SHARE = 0.005  # ... on at most 0.5% of the pixels
DIFF_IMAGES = 3  # the configurations whose colour differs most get a picture


def fail(message):
    print(f"driver_study: {message}", file=sys.stderr)
    sys.exit(1)


def kind(column):
    """'application', 'driver', 'rate' (a time) or None (not a count) for a column of a result row."""
    if column.startswith("counter_"):
        if "_per_second" in column or column.endswith("_ms"):
            return "rate"
        return "driver" if column in DRIVER_COUNTERS else "application"
    if not column.startswith(("work_", "load_")):
        return None
    if column.endswith(DRIVER_SUFFIXES):
        return "driver"
    return "application" if column.endswith(APPLICATION_SUFFIXES) else None


def version(row):
    """The driver's version as the row reports it: GL_VERSION on GL, the device's driver on Vulkan."""
    return row.gl_version if row.api == "gl" else f"{row.gl_vendor} (Vulkan {row.api_version})"


def load_pairs(folder, suite):
    """[(config, base row, head row)] in the suite's order; checks that each pair ran one configuration."""
    path = os.path.join(folder, "work.csv")
    if not os.path.exists(path):
        fail(f"no {path} (bash scripts/driver-study.sh writes it)")
    rows = pd.read_csv(path)
    configs = suite["configs"]
    if len(rows) != 2 * len(configs):
        fail(f"work.csv has {len(rows)} rows for {len(configs)} configurations on two drivers")
    pairs = []
    for i, config in enumerate(configs):
        base, head = rows.iloc[2 * i], rows.iloc[2 * i + 1]
        args = config["args"]
        api = args[args.index("--api") + 1] if "--api" in args else "gl"
        technique = args[args.index("-t") + 1].split(":")[0]
        for row in (base, head):
            if row.status != "ok" or row.api != api or row.technique != technique:
                fail(f"work.csv row for {config['name']} is {row.api} {row.technique} ({row.status})")
        if base.backend != head.backend:
            fail(f"{config['name']}: the drivers ran on different backends ({base.backend}, {head.backend})")
        if version(base) == version(head):
            fail(f"{config['name']}: both rows ran on {version(base)}: the second driver did not load")
        pairs.append((config["name"], base, head))
    return pairs


def counts(row, wanted):
    return {c: row[c] for c in row.index if kind(c) == wanted and pd.notna(row[c])}


def fmt(value):
    return f"{int(value):,}" if float(value).is_integer() else f"{value:g}"


def drivers_table(pairs):
    print("| API | base driver | head driver | renderer |\n|---|---|---|---|")
    seen = set()
    for _, base, head in pairs:
        if base.api in seen:
            continue
        seen.add(base.api)
        print(f"| {base.api} | {version(base)} | {version(head)} | {base.renderer} |")


def application_table(pairs):
    print("| configuration | passes | application counts compared | differences |\n|---|---|---|---|")
    for name, base, head in pairs:
        b, h = counts(base, "application"), counts(head, "application")
        passes = sorted({c[5:-6] for c in b if c.startswith("work_") and c.endswith("_draws")})
        differ = [f"{c} {fmt(b.get(c, float('nan')))} -> {fmt(h.get(c, float('nan')))}"
                  for c in sorted(set(b) | set(h)) if b.get(c) != h.get(c)]
        if differ:
            print(f"driver_study: {name}: the application's work differs: {'; '.join(differ)}", file=sys.stderr)
        print(f"| {name} | {', '.join(passes)} | {len(set(b) | set(h))} | "
              f"{'; '.join(differ) if differ else 'none: identical'} |")


def ratio(b, h):
    if b == h:
        return "1"
    return f"{h / b:.3f}" if b else "new"


def labels(pairs):
    """Short names of the two drivers ("22.3.6", "25.0.7") for the tables' headers."""
    _, base, head = pairs[0]
    return tuple(re.search(r"Mesa ([0-9.]+)", version(row)).group(1) for row in (base, head))


def driver_table(pairs):
    b, h = labels(pairs)
    print(f"| configuration | pass | vertex invocations | clipped primitives | fragments {b} | "
          f"fragments {h} | fragments {h}/{b} |\n|---|---|---|---|---|---|---|")
    for name, base, head in pairs:
        passes = [c[5:-len("_fragments")] for c in base.index
                  if c.startswith("work_") and c.endswith("_fragments") and pd.notna(base[c])]
        for p in passes:
            cells = []
            for what in ("vertices", "clipped_primitives"):
                b, h = base[f"work_{p}_{what}"], head[f"work_{p}_{what}"]
                cells.append(fmt(b) if b == h else f"{fmt(b)} -> {fmt(h)} ({ratio(b, h)})")
            b, h = base[f"work_{p}_fragments"], head[f"work_{p}_fragments"]
            print(f"| {name} | {p} | {cells[0]} | {cells[1]} | {fmt(b)} | {fmt(h)} | {ratio(b, h)} |")
        for c in DRIVER_COUNTERS:
            if pd.notna(base.get(c)):
                print(f"| {name} | ({c[8:]}) | | | {fmt(base[c])} | {fmt(head[c])} | {ratio(base[c], head[c])} |")


def layer(report, prefix):
    for entry in report["layers"]:
        if entry["name"].startswith(prefix):
            return entry
    return None


def parse_changes(text):
    """'shader_jit -3007800, mesa +2097005' -> {'shader_jit': -3007800.0, ...}; 'none' -> {}."""
    return {k: float(v) for k, v in re.findall(r"([a-z_]+) ([+-][0-9.e+]+)", text)}


def where_text(base, head):
    """'shader_jit 24.9 M -> 22.3 M (-10.4%); mesa ...' over the categories either side counted."""
    parts = []
    for k in head:
        if max(base[k], head[k]) >= 1e4:  # below that a category holds no code of this frame
            change = f" ({100 * (head[k] / base[k] - 1):+.1f}%)" if base[k] else ""
            parts.append(f"{k} {base[k] / 1e6:.2f} M -> {head[k] / 1e6:.2f} M{change}")
    return "; ".join(parts)


def instructions_table(folder, pairs):
    path = os.path.join(folder, "ci-instructions", "report.json")
    if not os.path.exists(path):
        print("(layer B not run)")
        return
    b_layer = layer(json.load(open(path)), "B:")
    record = json.load(open(os.path.join(folder, "ci-instructions", "instructions.json")))["configs"]
    b, h = labels(pairs)
    print(f"| configuration | Ir/frame {b} | Ir/frame {h} | {h}/{b} | by where the code lives (Ir/frame) | "
          "top functions by change (Ir/frame) |\n|---|---|---|---|---|---|")
    for line in b_layer["details"]:
        m = re.match(r"([a-z0-9_]+): ([+-][0-9.]+)% Ir per frame; by where \(Ir/frame\): (.*); top functions: (.*)$",
                     line)
        if not m:
            continue
        name, change, top = m.group(1), float(m.group(2)) / 100, m.group(4)
        backend_check(folder, name)
        head = record[name]["ir_per_frame"]
        frames = record[name]["frames"]
        head_where = {k: v / frames for k, v in record[name]["categories"].items()}
        delta = parse_changes(m.group(3))
        base_where = {k: v - delta.get(k, 0.0) for k, v in head_where.items()}
        print(f"| {name} | {head / (1 + change):.4g} | {head:.4g} | {1 + change:.3f} | "
              f"{where_text(base_where, head_where)} | {top} |")
    for line in b_layer["details"]:
        if line.startswith(("A/A", "no verdict")):
            print(f"\n{line}")


def backend_check(folder, name):
    """Both sides' rows under valgrind must have run on one backend (else they are not one workload)."""
    backends = []
    for side in (name + "_base", name):
        rows = json.load(open(os.path.join(folder, "ci-instructions", "callgrind", side, "stdout.json")))["rows"]
        backends.append(rows[0]["backend"])
    if backends[0] != backends[1]:
        fail(f"{name} under valgrind ran on {backends[0]} (base) and {backends[1]} (head)")


def wall_table(folder, pairs):
    path = os.path.join(folder, "ci-wall", "report.json")
    if not os.path.exists(path):
        print("(layer C not run)")
        return
    report = json.load(open(path))
    c_layer = layer(report, "C:")
    runs = pd.read_csv(os.path.join(folder, "ci-wall", "wall.csv"))
    for config, g in runs.groupby("ci_config"):
        if g.backend.nunique() != 1:
            fail(f"{config}: wall-time runs on several backends ({', '.join(g.backend.unique())})")
    b, h = labels(pairs)
    print(f"| configuration | wall ratio {h}/{b}, median [95% interval] | Wilcoxon p | gate's verdict | "
          "rounds |\n|---|---|---|---|---|")
    for row in report["configs"]:
        if not row.get("wall"):
            continue
        m = re.match(r"([0-9.]+) \[([0-9.]+), ([0-9.]+)\] p=(\S+)", row["wall"]["summary"])
        rounds = runs[(runs.ci_config == row["config"]) & (runs.ci_role == "head")].ci_round.nunique()
        print(f"| {row['config']} | {m.group(1)} [{m.group(2)}, {m.group(3)}] | {m.group(4)} | "
              f"{row['wall']['verdict']} | {rounds} |")
    print()
    for line in c_layer["details"][:2]:
        print(f"- {line}")


def pixels(path):
    return np.asarray(Image.open(path), dtype=np.int16)


def image_table(folder, pairs, base_name, head_name):
    print("| configuration | colour: max diff /255 | colour: pixels over 2/255 | visibility: max diff /255 | "
          "visibility: pixels over 2/255 | within the matrix tolerance |\n|---|---|---|---|---|---|")
    largest = []
    for name, _, _ in pairs:
        cells, within = [], True
        for suffix in (".png", ".vis.png"):
            a = pixels(os.path.join(folder, "images", base_name, name + suffix))
            b = pixels(os.path.join(folder, "images", head_name, name + suffix))
            if a.shape != b.shape:
                fail(f"{name}{suffix}: sizes differ ({a.shape}, {b.shape})")
            diff = np.abs(a - b)
            per_pixel = diff.max(axis=-1) if diff.ndim == 3 else diff
            over = int((per_pixel > PIXEL_STEP).sum())
            share = over / per_pixel.size
            within &= share <= PIXEL_SHARE
            cells += [str(int(per_pixel.max())), f"{over} ({100 * share:.2f}%)"]
            if suffix == ".png":
                largest.append((share, name, a, b, per_pixel))
        print(f"| {name} | {' | '.join(cells)} | {'yes' if within else 'no'} |")
    for share, name, a, b, per_pixel in sorted(largest, key=lambda t: -t[0])[:DIFF_IMAGES]:
        if share == 0:
            continue
        amplified = np.clip(per_pixel * 16, 0, 255).astype(np.uint8)
        strip = np.concatenate([a.astype(np.uint8), b.astype(np.uint8),
                                np.stack([amplified] * 3, axis=-1)], axis=1)
        Image.fromarray(strip).save(os.path.join(folder, f"diff-{name}.png"), optimize=True)
        print(f"\n![{name}: 22.3.6, 25.0.7, difference x16](diff-{name}.png)")


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "results/drivers"
    suite = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "results", "drivers",
                                        "suite.json")))
    pairs = load_pairs(folder, suite)
    drivers = sorted(os.listdir(os.path.join(folder, "images")), key=lambda d: d != "system")
    sections = [("Drivers", lambda: drivers_table(pairs)),
                ("Application's work (must be identical)", lambda: application_table(pairs)),
                ("Driver's work per pass", lambda: driver_table(pairs)),
                ("Instructions per frame (layer B, callgrind)", lambda: instructions_table(folder, pairs)),
                ("Wall time (layer C, interleaved)", lambda: wall_table(folder, pairs)),
                ("Image differences (census frame, pixel by pixel)",
                 lambda: image_table(folder, pairs, drivers[0], drivers[1]))]
    for title, section in sections:
        print(f"\n### {title}\n")
        section()


if __name__ == "__main__":
    main()
