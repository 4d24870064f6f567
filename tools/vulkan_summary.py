#!/usr/bin/env python3
"""The tables of results/vulkan/README.md from the CSVs scripts/vulkan.sh writes: per configuration and
technique, GL against Vulkan. Wall and CPU record/submit medians are the median over the runs of each
run's median; the Vulkan/GL ratio is taken per round (the runs next to each other) and given as median
[min, max]. "app thread" is the share of the frame's wall time spent before the frame is handed to the
driver (GL: the draw calls, in which llvmpipe runs the vertex stage; Vulkan: recording and vkQueueSubmit,
after which lavapipe runs everything on its own threads). The exact work (vertices, fragments) comes
from the census frame's pipeline statistics on both APIs and must agree.
The `every` configuration adds each family's bottleneck class on either API (every_bottleneck_<api>_classes.csv).
Usage: /usr/bin/python3 tools/vulkan_summary.py results/vulkan"""
import glob
import os
import statistics
import sys

import pandas as pd


def fmt(x, digits=2):
    return "" if x is None or pd.isna(x) else f"{x:.{digits}f}"


def summarize(path):
    d = pd.read_csv(path)
    name = os.path.splitext(os.path.basename(path))[0]
    rows = []
    for (tech, submit), g in d.groupby(["technique", "submit"], sort=False):
        gl, vk = g[g.api == "gl"], g[g.api == "vulkan"]
        def med(x, col):
            return statistics.median(x[col]) if len(x) else None
        ratios = [v / w for v, w in zip(vk.wall_ms_median, gl.wall_ms_median)]
        ratio = f"{statistics.median(ratios):.2f} [{min(ratios):.2f}, {max(ratios):.2f}]" if ratios else ""
        share = lambda x: med(x, "cpu_submit_ms_median") / med(x, "wall_ms_median") if len(x) else None
        frag = lambda x: int(x.load_fragments.iloc[0]) if len(x) and not pd.isna(x.load_fragments.iloc[0]) else None
        rows.append([tech, submit, fmt(med(gl, "wall_ms_median")), fmt(med(vk, "wall_ms_median")), ratio,
                     fmt(med(gl, "cpu_submit_ms_median")), fmt(med(vk, "cpu_submit_ms_median")),
                     fmt(share(gl)), fmt(share(vk)),
                     str(frag(gl) or ""), str(frag(vk) or "")])
    print(f"\n### {name}\n")
    head = ["technique", "submit", "GL wall ms", "Vulkan wall ms", "Vulkan/GL", "GL cpu ms", "Vulkan cpu ms",
            "GL app thread", "Vulkan app thread", "GL fragments", "Vulkan fragments"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        print("| " + " | ".join(r) + " |")


def bottleneck_classes(folder):
    """Each technique's bottleneck class on GL and on Vulkan (bench bottleneck --api), side by side."""
    tables = {}
    for api in ("gl", "vulkan"):
        path = os.path.join(folder, f"every_bottleneck_{api}_classes.csv")
        if os.path.exists(path):
            tables[api] = pd.read_csv(path).set_index("technique_spec")
    if len(tables) < 2:
        return
    print("\n### every: bottleneck class\n")
    head = ["technique", "GL class", "GL cpu/vertex/fill", "GL fit residual", "Vulkan class",
            "Vulkan cpu/vertex/fill", "Vulkan fit residual"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for tech in tables["gl"].index:
        cells = [tech]
        for api in ("gl", "vulkan"):
            if tech not in tables[api].index:
                cells += ["", "", ""]
                continue
            r = tables[api].loc[tech]
            cells += [str(r["class"]), f"{r.share_cpu:.2f} / {r.share_vertex:.2f} / {r.share_fill:.2f}",
                      f"{r.rms_rel_residual:.2f}"]
        print("| " + " | ".join(cells) + " |")


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "results/vulkan"
    for path in sorted(glob.glob(os.path.join(folder, "*.csv"))):
        if "bottleneck" not in os.path.basename(path):
            summarize(path)
    bottleneck_classes(folder)


if __name__ == "__main__":
    main()
