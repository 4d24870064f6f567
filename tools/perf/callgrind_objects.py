#!/usr/bin/env python3
"""Self instructions (Ir) of callgrind dumps, split by where the code lives: the JIT-compiled shaders and
set-up code (callgrind's object "???"), Mesa (swrast_dri.so, libgallium-*.so, libglapi, the Mesa GLX/EGL
vendor libraries), the replayer or application, the system libraries, and the rest. One line per dump,
then the median of the dumps asked for. Used by tools/perf/pass-instructions.sh (results/perf/README.md).

Usage: tools/perf/callgrind_objects.py [--skip N] [--last M] DUMP...
  --skip N   leave out the first N dumps (set-up, warm-up frames) from the median  [0]
  --last M   leave out the last M dumps (the teardown after the last frame)       [0]
Examples:
  tools/perf/callgrind_objects.py --skip 3 --last 1 /tmp/cg/callgrind.out.*
"""
import argparse
import re
import statistics
import sys

CATEGORIES = ("jit", "mesa", "app", "system", "other")


def category(obj):
    base = obj.rsplit("/", 1)[-1]
    if obj in ("???", ""):
        return "jit"
    if re.match(r"(swrast_dri|kms_swrast_dri|libgallium|libglapi|libGLX_mesa|libEGL_mesa|libOSMesa)", base):
        return "mesa"
    if re.match(r"(libc\.so|libc-|ld-linux|libm\.so|libstdc\+\+|libgcc_s|libpthread)", base):
        return "system"
    if re.match(r"(glretrace|eglretrace|glmark2|bench|libwaffle)", base):
        return "app"
    return "other"


def self_ir(path):
    """Self Ir per object of one callgrind dump (event Ir only, or Ir as the first event)."""
    names = {}
    per_obj = {}
    ob = "???"
    skip_next = False
    with open(path, errors="replace") as f:
        for line in f:
            if skip_next:
                skip_next = False
                continue
            c = line[0] if line else ""
            if c.isdigit() or c in "+-*":
                parts = line.split()
                if len(parts) >= 2:
                    per_obj[ob] = per_obj.get(ob, 0) + int(parts[1])
                continue
            if line.startswith("ob="):
                m = re.match(r"ob=\((\d+)\)(?: (.*))?", line.rstrip("\n"))
                if m:
                    if m.group(2) is not None:
                        names[m.group(1)] = m.group(2)
                    ob = names.get(m.group(1), "???")
                else:
                    ob = line[3:].strip()
            elif line.startswith("cob="):
                m = re.match(r"cob=\((\d+)\)(?: (.*))?", line.rstrip("\n"))
                if m and m.group(2) is not None:
                    names[m.group(1)] = m.group(2)
            elif line.startswith("calls="):
                skip_next = True  # the next line is the call's inclusive cost, not self cost
    out = dict.fromkeys(CATEGORIES, 0)
    for obj, ir in per_obj.items():
        out[category(obj)] += ir
    return out, per_obj


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--skip", type=int, default=0)
    ap.add_argument("--last", type=int, default=0)
    ap.add_argument("--objects", action="store_true", help="also print the top objects of each dump")
    ap.add_argument("dumps", nargs="+")
    a = ap.parse_args()

    def order(p):
        m = re.search(r"\.(\d+)(?:-\d+)?$", p)
        return int(m.group(1)) if m else 0

    dumps = sorted(a.dumps, key=order)
    rows = []
    print("%-40s %12s %12s %12s %12s %12s %12s" % (("dump",) + CATEGORIES + ("jit+mesa",)))
    for d in dumps:
        cats, objs = self_ir(d)
        rows.append(cats)
        print("%-40s %12d %12d %12d %12d %12d %12d" % ((d[-40:],) + tuple(cats[c] for c in CATEGORIES) +
                                                       (cats["jit"] + cats["mesa"],)))
        if a.objects:
            for obj, ir in sorted(objs.items(), key=lambda kv: -kv[1])[:6]:
                print("    %14d  %s" % (ir, obj))
    chosen = rows[a.skip:len(rows) - a.last if a.last else None]
    if not chosen:
        sys.exit("callgrind_objects: --skip/--last leave no dump")
    med = {c: statistics.median(r[c] for r in chosen) for c in CATEGORIES}
    jm = statistics.median(r["jit"] + r["mesa"] for r in chosen)
    print("%-40s %12d %12d %12d %12d %12d %12d" % (("median of %d" % len(chosen),) +
                                                   tuple(int(med[c]) for c in CATEGORIES) + (int(jm),)))


if __name__ == "__main__":
    main()
