#!/usr/bin/env python3
"""What a traced GL frame does, pass by pass: reads `apitrace dump --color=never TRACE` text and splits
it into frames (at each glFinish, which ends a frame in glmark2's off-screen mode and in bench's
harness, or at a swap) and each frame into passes (a run of draws into one framebuffer with one program). For every
pass it prints the framebuffer, viewport, colour mask, draw buffers, cull and depth state, the clears
before it, its draws (and vertices) and the GL calls between its draws (state churn); for the program it
names the shaders glShaderSource gave it. With --ignore it prints the calls of one pass kind in every
frame as an apitrace call set, for `glretrace --ignore-calls` (results/perf/README.md).

Usage: apitrace dump --color=never T.trace | tools/perf/trace_passes.py [--frame K] [--ignore PASS]
  --frame K       the frame to print in detail (default: the last complete one; negative counts back)
  --ignore PASS   print the call set of pass number PASS (0-based, in frame order) of every frame whose
                  passes have the same layout as the printed frame, plus the clears before it
  --ignore-draws  with --ignore: only the draws, not the clears
Examples:
  apitrace dump --color=never /tmp/glmark2.trace | tools/perf/trace_passes.py
  apitrace dump --color=never /tmp/bench.trace | tools/perf/trace_passes.py --ignore 0
"""
import argparse
import re
import sys

CALL = re.compile(r"^(\d+) (?:@\d+ )?(\w+)\((.*)\)(?: = (.*))?$")
# A frame ends at glFinish (glmark2 off-screen, bench's harness) or at a swap (glmark2 on screen).
FRAME_ENDS = ("glFinish", "glXSwapBuffers", "eglSwapBuffers")
DRAW = re.compile(r"^gl(Multi)?Draw(Arrays|Elements|RangeElements)")


def arg(args, name):
    m = re.search(r"\b" + name + r" = (\{[^}]*\}|[^,]+)", args)
    return m.group(1).strip() if m else None


class Pass:
    def __init__(self, fbo, program, state):
        self.fbo, self.program, self.state = fbo, program, dict(state)
        self.draws, self.vertices, self.between, self.calls, self.clears = 0, 0, 0, [], []
        self.draw_calls = []

    def key(self):
        return (self.fbo, self.program)


SOURCE = re.compile(r"^\d+ (?:@\d+ )?glShaderSource\(shader = (\d+), count = \d+, string = &?\{?\"(.*?)\", length",
                    re.S | re.M)


def shader_sources(text):
    """shader name -> (characters, the body of main condensed to one line): sources span many lines."""
    out = {}
    for m in SOURCE.finditer(text):
        src = m.group(2)
        body = src[src.rfind("void main"):] if "void main" in src else src[-160:]
        out[m.group(1)] = (len(src), re.sub(r"\s+", " ", body)[:200])
    return out


def parse(lines, sources):
    frames, frame, cur, pending_clears = [], [], None, []
    state = {"fbo": "0", "program": "0", "viewport": "?", "colormask": "all", "drawbuffers": "default",
             "cull": "off", "cullface": "GL_BACK", "depthtest": "off", "polygonoffset": "off"}
    shaders, programs, attached = {}, {}, {}
    since_draw = 0
    for line in lines:
        m = CALL.match(line.rstrip("\n"))
        if not m:
            continue
        no, fn, args = int(m.group(1)), re.sub(r"(EXT|ARB)$", "", m.group(2)), m.group(3)
        ret = m.group(4)
        if fn in ("glCreateShader",) and ret:
            shaders[ret] = (arg(args, "type"),) + sources.get(ret, (0, ""))
        elif fn == "glAttachShader":
            attached.setdefault(arg(args, "program"), []).append(arg(args, "shader"))
        elif fn == "glBindFramebuffer" and arg(args, "target") in ("GL_FRAMEBUFFER", "GL_DRAW_FRAMEBUFFER"):
            state["fbo"] = arg(args, "framebuffer")
        elif fn == "glUseProgram":
            state["program"] = arg(args, "program")
        elif fn == "glViewport":
            state["viewport"] = "%sx%s" % (arg(args, "width"), arg(args, "height"))
        elif fn == "glColorMask":
            vals = [arg(args, c) for c in ("red", "green", "blue", "alpha")]
            state["colormask"] = "all" if all(v == "GL_TRUE" for v in vals) else (
                "none" if all(v == "GL_FALSE" for v in vals) else ",".join(vals))
        elif fn in ("glDrawBuffers", "glDrawBuffer"):
            state["drawbuffers"] = arg(args, "bufs") or arg(args, "buf") or arg(args, "mode")
        elif fn in ("glEnable", "glDisable"):
            cap = arg(args, "cap")
            on = "on" if fn == "glEnable" else "off"
            if cap == "GL_CULL_FACE":
                state["cull"] = on
            elif cap == "GL_DEPTH_TEST":
                state["depthtest"] = on
            elif cap == "GL_POLYGON_OFFSET_FILL":
                state["polygonoffset"] = on
        elif fn == "glCullFace":
            state["cullface"] = arg(args, "mode")
        if fn in ("glClear", "glClearBufferfv", "glClearBufferfi", "glClearBufferiv", "glClearTexImage"):
            pending_clears.append((no, fn, args[:80], state["fbo"], state["viewport"]))
            since_draw += 1
            continue
        if DRAW.match(fn):
            key = (state["fbo"], state["program"])
            if cur is None or cur.key() != key or pending_clears:
                cur = Pass(state["fbo"], state["program"], state)
                cur.clears, pending_clears = pending_clears, []
                frame.append(cur)
            else:
                cur.between += since_draw
            cur.draws += 1
            cur.draw_calls.append(no)
            count = arg(args, "count")
            if count and count.isdigit():
                cur.vertices += int(count)
            cur.calls.append(no)
            since_draw = 0
            continue
        since_draw += 1
        if cur is not None and fn not in FRAME_ENDS:
            cur.calls.append(no)
        if fn in FRAME_ENDS:
            if frame:
                frame.append(("finish", no, pending_clears))
                frames.append(frame)
            frame, cur, pending_clears = [], None, []
    return frames, shaders, attached


def layout(frame):
    return tuple(p.key() for p in frame if isinstance(p, Pass))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frame", type=int, default=-1)
    ap.add_argument("--ignore", type=int)
    ap.add_argument("--ignore-draws", action="store_true")
    a = ap.parse_args()
    text = sys.stdin.read()
    frames, shaders, attached = parse(text.splitlines(), shader_sources(text))
    if not frames:
        sys.exit("trace_passes: no frame (no draw followed by glFinish) in the dump on stdin")
    frame = frames[a.frame]
    passes = [p for p in frame if isinstance(p, Pass)]
    if a.ignore is not None:
        if not 0 <= a.ignore < len(passes):
            print("trace_passes: --ignore %d: the frame has passes 0-%d" % (a.ignore, len(passes) - 1),
                  file=sys.stderr)
            sys.exit(2)
        calls = []
        for f in frames:
            ps = [p for p in f if isinstance(p, Pass)]
            if layout(f) != layout(frame):
                continue
            p = ps[a.ignore]
            calls += p.draw_calls if a.ignore_draws else [c[0] for c in p.clears] + p.draw_calls
        print(",".join(str(c) for c in sorted(calls)))
        return
    same = sum(1 for f in frames if layout(f) == layout(frame))
    print("%d frames (ended by glFinish or a swap), %d with the layout of the printed one" % (len(frames), same))
    for i, p in enumerate(passes):
        progs = attached.get(p.program, [])
        print("pass %d: fbo %s, program %s" % (i, p.fbo, p.program))
        for sh in progs:
            if isinstance(shaders.get(sh), tuple):
                kind, chars, body = shaders[sh]
                print("  shader  %s, %d chars: %s" % (kind.replace("GL_", "").lower(), chars, body))
        for no, fn, args, fbo, vp in p.clears:
            print("  clear   call %d %s(%s) fbo %s viewport %s" % (no, fn, args, fbo, vp))
        s = p.state
        print("  state   viewport %s, colour mask %s, draw buffers %s, cull %s (%s), depth test %s, "
              "polygon offset %s" % (s["viewport"], s["colormask"], s["drawbuffers"], s["cull"],
                                     s["cullface"], s["depthtest"], s["polygonoffset"]))
        print("  draws   %d (calls %s), %d vertices, %d GL calls between its draws" % (
            p.draws, ",".join(map(str, p.draw_calls)), p.vertices, p.between))
    tail = frame[-1]
    for no, fn, args, fbo, vp in tail[2]:
        print("clear after the last pass: call %d %s(%s) fbo %s" % (no, fn, args, fbo))
    print("frame ends: call %d" % tail[1])


if __name__ == "__main__":
    main()
