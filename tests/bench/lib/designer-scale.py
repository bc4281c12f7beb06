#!/usr/bin/env python3
"""The Python side of tests/bench/designer-scale.sh (standard library only).

  scene OUT N            writes a floor of N spheres ("ball 0" ... "ball N-1"), the camera
                         framed on "ball 0": a bright green sphere of radius 1 at the origin
                         with no other sphere within 5 units, so it looks the same at any N
  locate MASK W H        the largest green blob of one mask frame (W x H bytes): "X Y PIXELS"
                         in mask pixels, or nothing
  analyse DIR            one JSON line from a scene size's recordings in DIR (see the script)
  report FILE [--json]   the table (or one JSON object) of the JSON lines in FILE
"""
import json
import math
import os
import random
import statistics
import sys

from sphere_floor import side_for, sphere_floor

MASK_SCALE = 4      # The mask is the recorded region shrunk 4x (area average).
MASK_LEVEL = 128    # A mask pixel at least this green is the ball's.
MOVED_PX = 2.0      # The ball moved when its centre moved this far (screen pixels).
ARRIVED_PX = 5.0    # The ball is back where it was when its centre is this close.

TARGETS = [  # key, label, unit, comparison, target
    ("position_updates_per_s", "ball position updates on screen", "/s", ">=", 30),
    ("distinct_frames_per_s", "distinct frames on screen while moving", "/s", ">=", 30),
    ("undo_ms", "undo: key to the ball back where it was, on screen", "ms", "<=", 50),
    ("redo_ms", "redo: key to the ball moved again, on screen", "ms", "<=", 50),
    ("memory_ratio", "memory after the edits / before them", "x", "<=", 1.5),
    ("open_first_frame_ms", "open: launch to the first frame with the ball", "ms", "<=", 3000),
    ("open_longest_stall_ms", "open: longest stall (ping), window to first frame + 2 s", "ms",
     "<=", 100),
]


def scene(out, n):
    # "ball 0" is the marker: bright green at the origin, the others kept 5 units away.
    doc = sphere_floor(range(1, n), random.Random(7), side_for(max(n, 10)),
                       camera={"position": [0, 9, 18], "target": [0, 1, 0]},
                       light=[6, 30, 20], ambient=0.15, clear=5.0)
    doc["materials"].append({"name": "marker", "color": [0.02, 1.0, 0.02], "diffuse": 1.0})
    doc["objects"].insert(1, {"name": "ball 0", "type": "sphere", "center": [0, 1, 0],
                              "radius": 1.0, "material": "marker"})
    with open(out, "w") as f:
        json.dump(doc, f)


def blob(frame, w, h):
    """The largest 4-connected set of green mask pixels: (x, y, pixels) or None."""
    seen = bytearray(w * h)
    best = None
    for start in range(w * h):
        if seen[start] or frame[start] < MASK_LEVEL:
            continue
        stack, cells = [start], []
        seen[start] = 1
        while stack:
            p = stack.pop()
            cells.append(p)
            x, y = p % w, p // w
            for q, ok in ((p - 1, x > 0), (p + 1, x < w - 1), (p - w, y > 0), (p + w, y < h - 1)):
                if ok and not seen[q] and frame[q] >= MASK_LEVEL:
                    seen[q] = 1
                    stack.append(q)
        if best is None or len(cells) > len(best):
            best = cells
    if not best:
        return None
    wsum = sum(frame[p] for p in best)
    return (sum((p % w) * frame[p] for p in best) / wsum,
            sum((p // w) * frame[p] for p in best) / wsum, len(best))


def read_floats(path):
    try:
        return [[float(v) for v in line.split()] for line in open(path) if line.strip()]
    except FileNotFoundError:
        return []


def kept_frames(d, info):
    """(time, centre in screen pixels of the region or None, mask pixels) of every distinct
    frame."""
    times = []
    for line in open(os.path.join(d, "record.log"), errors="replace"):
        i = line.find(" pts:")
        if "showinfo" in line and i >= 0:
            times.append(int(line[i + 5:].split()[0]) / 1e6)
    w, h = info["mask_w"], info["mask_h"]
    data = open(os.path.join(d, "mask.raw"), "rb").read()
    frames = []
    for k, t in enumerate(times[:len(data) // (w * h)]):
        b = blob(data[k * w * h:(k + 1) * w * h], w, h)
        frames.append((t, None if b is None or b[2] < 3 else
                       (b[0] * MASK_SCALE + MASK_SCALE / 2, b[1] * MASK_SCALE + MASK_SCALE / 2),
                       0 if b is None else b[2]))
    return frames


def dist(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def centre_before(frames, t):
    c = None
    for ft, fc, _ in frames:
        if ft > t:
            break
        c = fc or c
    return c


def first_moved(frames, t, ref):
    """The first distinct frame after t whose ball is MOVED_PX from ref: (time, centre)."""
    for ft, fc, _ in frames:
        if ft > t and fc and ref and dist(fc, ref) >= MOVED_PX:
            return ft, fc
    return None, None


def first_near(frames, t, target):
    """The first distinct frame after t whose ball is within ARRIVED_PX of target."""
    for ft, fc, _ in frames:
        if ft > t and fc and target and dist(fc, target) <= ARRIVED_PX:
            return ft, fc
    return None, None


def longest_stall(pings, a, b):
    answers = [p[1] - p[0] for p in pings if a <= p[0] <= b]
    return round(1000 * max(answers), 1) if answers else None


def ms(x):
    return None if x is None else round(1000 * x, 1)


def analyse(d):
    info = json.load(open(os.path.join(d, "info.json")))
    ev = {k: float(v) for k, v in (l.split() for l in open(os.path.join(d, "events")))}
    frames = kept_frames(d, info)
    pings = read_floats(os.path.join(d, "pings"))
    r = {"spheres": info["spheres"], "screen": info["screen"], "region": info["region"],
         "moves": info["moves"], "edits": info["edits"]}
    # Opening: the first recorded frame that shows the ball.
    shown = next((t for t, c, _ in frames if t > ev["launch"] and c), None)
    r["open_window_ms"] = ms(ev["window"] - ev["launch"]) if "window" in ev else None
    r["open_first_frame_ms"] = ms(shown - ev["launch"]) if shown else None
    r["open_longest_stall_ms"] = longest_stall(
        pings, ev.get("window", ev["launch"]), (shown or ev.get("opened", ev["launch"])) + 2.0)
    r["open_settled"] = "opened" in ev
    # The G move: its moves' span, from the first move to the last.
    a, b = ev["drag_start"] + 0.5, ev["drag_end"]
    during = [f for f in frames if a <= f[0] <= b]
    span = max(b - a, 1e-3)
    # A position update: a frame whose ball is whole and 2 px or more from the last whole one.
    # Whole: its blob at least 3/4 of the largest of the last 12 (a pass cut short shows part
    # of the ball at its new place and part at its old, the blob smaller; a coarse pass shows
    # it blocky and larger, so the largest recent one is the yardstick).
    updates, last, sizes = 0, None, []
    for t, c, px in [f for f in frames if f[0] < a][-1:] + during:
        if not c:
            continue
        sizes = (sizes + [px])[-12:]
        if px >= 0.75 * max(sizes):
            if last and dist(c, last) >= MOVED_PX and t >= a:
                updates += 1
            last = c
    gaps = [y[0] - x[0] for x, y in zip(during, during[1:])]
    r["distinct_frames_per_s"] = round(len(during) / span, 1)
    r["position_updates_per_s"] = round(updates / span, 1)
    r["median_gap_ms"] = ms(statistics.median(gaps)) if gaps else None
    r["longest_gap_ms"] = ms(max(gaps)) if gaps else None
    start = centre_before(frames, a)
    moved_at, _ = first_moved(frames, a, start)
    r["input_to_screen_ms"] = ms(moved_at - a) if moved_at else None
    r["drag_longest_stall_ms"] = longest_stall(pings, a, b)
    r["ball_start"] = [round(v) for v in start] if start else None
    # Undo and redo: the key to the first frame with the ball where the undo (redo) puts it:
    # where it was before the move (after the move). The first changed frame is given too.
    targets = {"undo": start, "redo": centre_before(frames, ev.get("undo", 0))}
    for kind in ("undo", "redo"):
        r[kind + "_ms"] = r[kind + "_first_change_ms"] = r[kind + "_moved_px"] = None
        if kind not in ev:
            continue
        before = centre_before(frames, ev[kind])
        t, c = first_near(frames, ev[kind], targets[kind])
        if t and before and dist(before, targets[kind]) > 4 * ARRIVED_PX:
            r[kind + "_ms"] = ms(t - ev[kind])
            r[kind + "_moved_px"] = round(dist(c, before), 1)
        changed = next((f[0] for f in frames if f[0] > ev[kind]), None)
        r[kind + "_first_change_ms"] = ms(changed - ev[kind]) if changed else None
    for k in ("rss_open_kib", "rss_before_kib", "rss_after_kib"):
        r[k.replace("_kib", "_mib")] = round(ev[k] / 1024, 1) if k in ev else None
    r["memory_ratio"] = (round(ev["rss_after_kib"] / ev["rss_before_kib"], 2)
                         if "rss_after_kib" in ev and "rss_before_kib" in ev else None)
    r["edits_seconds"] = round(ev["edits_end"] - ev["edits_start"], 1) if "edits_end" in ev else None
    # How far the designer fell behind the edits: their last click to its last frame or CPU use.
    r["edits_behind_s"] = (round(max(0.0, ev["edits_settled"] - ev["edits_end"]), 1)
                           if "edits_settled" in ev else None)
    r["edits_longest_stall_ms"] = longest_stall(pings, ev.get("edits_start", 0), ev.get("edits_end", 0))
    r["not_settled"] = info.get("not_settled", [])
    try:
        r["designer_own"] = json.load(open(os.path.join(d, "self.json")))
    except (OSError, ValueError):
        r["designer_own"] = None
    print(json.dumps(r))


def met(v, op, target):
    if v is None:
        return "no (not measured)"
    return "yes" if (v >= target if op == ">=" else v <= target) else "no"


def report(path, as_json):
    runs = [json.loads(l) for l in open(path) if l.startswith("{")]
    for r in runs:
        r["targets"] = {k: met(r.get(k), op, t) == "yes" for k, _, _, op, t in TARGETS}
    if as_json:
        print(json.dumps({"runs": runs}))
        return
    for r in runs:
        own = r.get("designer_own") or {}
        print(f"\n{r['spheres']:,} spheres (screen {r['screen']}, region {r['region']}, "
              f"{r['moves']} moves, {r['edits']} edits)")
        print(f"  {'measure':58} {'value':>10}  target   met")
        for k, label, unit, op, t in TARGETS:
            v = r.get(k)
            print(f"  {label:58} {('-' if v is None else v):>10} {unit:<3} {op} {t:<6} {met(v, op, t)}")
        extra = [("the designer's own updates/s (--measure-drag generations_per_s)", own.get("generations_per_s"), "/s"),
                 ("the designer's own distinct frames/s (--measure-drag)", own.get("frames_per_s"), "/s"),
                 ("the designer's own whole frames/s (--measure-drag)", own.get("whole_frames_per_s"), "/s"),
                 ("input to the ball moved on screen", r.get("input_to_screen_ms"), "ms"),
                 ("undo / redo: key to the first changed frame",
                  f"{r.get('undo_first_change_ms')} / {r.get('redo_first_change_ms')}", "ms"),
                 ("undo / redo: how far the ball went", f"{r.get('undo_moved_px')} / {r.get('redo_moved_px')}", "px"),
                 ("median / longest gap between distinct frames while moving",
                  f"{r.get('median_gap_ms')} / {r.get('longest_gap_ms')}", "ms"),
                 ("longest stall (ping) while moving", r.get("drag_longest_stall_ms"), "ms"),
                 ("longest stall (ping) during the edits", r.get("edits_longest_stall_ms"), "ms"),
                 ("memory after opening / before / after the edits",
                  f"{r.get('rss_open_mib')} / {r.get('rss_before_mib')} / {r.get('rss_after_mib')}", "MiB"),
                 ("the edits: sending them / their last click to the designer idle",
                  f"{r.get('edits_seconds')} / {r.get('edits_behind_s')}", "s"),
                 ("open: launch to the window mapped", r.get("open_window_ms"), "ms")]
        for label, v, unit in extra:
            if isinstance(v, float):
                v = round(v, 1)
            print(f"  {label:58} {('-' if v is None else v):>10} {unit}")
        if r.get("not_settled"):
            print("  did not settle in time: " + ", ".join(r["not_settled"]))


def main(argv):
    if len(argv) >= 4 and argv[1] == "scene":
        scene(argv[2], int(argv[3]))
    elif len(argv) >= 5 and argv[1] == "locate":
        w, h = int(argv[3]), int(argv[4])
        data = open(argv[2], "rb").read()
        b = blob(data[-w * h:], w, h) if len(data) >= w * h else None
        if b:
            print("%.1f %.1f %d" % b)
    elif len(argv) >= 3 and argv[1] == "analyse":
        analyse(argv[2])
    elif len(argv) >= 3 and argv[1] == "report":
        report(argv[2], "--json" in argv[3:])
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
