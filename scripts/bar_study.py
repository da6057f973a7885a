#!/usr/bin/env python3
"""A study (not a test) of issue 31's "no splits of one bar into two": how often `--method shapes`
reports a flat bar as ONE region with its orientation within 10 degrees, over a sweep of places and
angles on the default 60 mm sheet (docs/physics.md, "Contact shapes", "Regions").

The twin (its own mesh, ADC and noise on) presses 24 x 4 and 30 x 3 mm bars of 10 N at centres on a
grid (12, 21, 30, 39, 48 mm in x and y) and at 30, 80 and 135 degrees, every corner 3 mm or more
inside the border (those that do not fit are left out); each frame has its own noise seed. Every
frame is reconstructed on its own (`emit reconstruct --method shapes`) and scored.

  scripts/bar_study.py --emit build-rel/emit [--work /tmp/bar-study] [--compare other/emit] [--fingers]

--compare reconstructs the same frames with a second binary (e.g. a build before a change) and
prints both. The frames are simulated once and kept in --work. --fingers also reconstructs frames
of separate presses (two fingers 12-20 mm apart, three >= 12 mm apart) and counts the frames
reported with as many regions as presses: a merge must not join them.
"""
import argparse
import json
import math
import os
import subprocess
import sys

BARS = [(24.0, 4.0), (30.0, 3.0)]
PLACES = [12.0, 21.0, 30.0, 39.0, 48.0]
ANGLES = [30.0, 80.0, 135.0]
SHEET_MM, MARGIN_MM, FORCE_N = 60.0, 3.0, 10.0


def corners(x, y, length, width, angle_deg):
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    for u, v in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
        du, dv = u * length / 2, v * width / 2
        yield x + du * c - dv * s, y + du * s + dv * c


def cases():
    for length, width in BARS:
        for angle in ANGLES:
            for x in PLACES:
                for y in PLACES:
                    if all(MARGIN_MM <= cx <= SHEET_MM - MARGIN_MM and MARGIN_MM <= cy <= SHEET_MM - MARGIN_MM
                           for cx, cy in corners(x, y, length, width, angle)):
                        yield length, width, angle, x, y


def run(args, **kw):
    return subprocess.run(["nice", *args], check=True, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, **kw)


def simulate(emit, work):
    os.makedirs(work, exist_ok=True)
    frames, truth = os.path.join(work, "bars.csv"), os.path.join(work, "bars.json")
    todo = list(cases())
    if os.path.exists(frames) and os.path.exists(truth):
        with open(truth) as f:
            if json.load(f) == [list(c) for c in todo]:
                return frames, todo
    run([emit, "simulate", "--script", "none", "--frames", "10", "--seed", "1000", "--out", os.path.join(work, "ref.csv")])
    lines = []
    for i, (length, width, angle, x, y) in enumerate(todo):
        one = os.path.join(work, "one.csv")
        run([emit, "simulate", "--press", f"bar:{x},{y},{length},{width},{angle},{FORCE_N}", "--seed", str(1 + i),
             "--out", one])
        with open(one) as f:
            lines.append(f.read().strip())
        print(f"\rsimulated {i + 1}/{len(todo)}", end="", file=sys.stderr)
    print(file=sys.stderr)
    with open(frames, "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(truth, "w") as f:
        json.dump([list(c) for c in todo], f)
    return frames, todo


def angle_error_deg(a, b):
    d = (a - b) % 180.0
    return min(d, 180.0 - d)


def score(emit, work, frames, todo):
    out = run([emit, "reconstruct", "--reference", os.path.join(work, "ref.csv"), "--frames", frames, "--method",
               "shapes", "--contacts", "-"]).stdout
    rows = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    assert len(rows) == len(todo), f"{len(rows)} frames reconstructed of {len(todo)}"
    result = []
    for (length, width, angle, x, y), row in zip(todo, rows):
        contacts = row["contacts"]
        one = len(contacts) == 1
        error = angle_error_deg(contacts[0]["orientation_deg"], angle) if one else float("nan")
        result.append(dict(bar=f"{length:g}x{width:g}", angle=angle, x=x, y=y, regions=len(contacts), error=error,
                           good=one and error <= 10, orientations=[round(c["orientation_deg"], 1) for c in contacts]))
    return result


def summary(name, result):
    print(f"{name}:")
    for bar in sorted({r["bar"] for r in result}):
        for angle in ANGLES:
            sel = [r for r in result if r["bar"] == bar and r["angle"] == angle]
            good = sum(r["good"] for r in sel)
            print(f"  bar {bar} at {angle:g} deg: {good}/{len(sel)} one region within 10 deg")
    good = sum(r["good"] for r in result)
    errors = sorted(r["error"] for r in result if r["regions"] == 1)
    print(f"  all: {good}/{len(result)} = {100 * good / len(result):.1f} % one region within 10 deg; "
          f"{sum(r['regions'] == 1 for r in result)} one region; median / worst angle error of those "
          f"{errors[len(errors) // 2]:.1f} / {errors[-1]:.1f} deg")
    for r in result:
        if not r["good"]:
            print(f"    missed: bar {r['bar']} at ({r['x']:g}, {r['y']:g}) {r['angle']:g} deg -> {r['regions']} "
                  f"regions {r['orientations']}")


def fingers(emit, work):
    """Frames of separate presses the merge must leave apart: two fingers 12-20 mm apart, three >= 12 mm."""
    made = []
    for script, frames, separation in (("two-finger", 30, "12,20"), ("three-finger", 10, "12")):
        out = os.path.join(work, f"{script}.csv")
        if not os.path.exists(out):
            run([emit, "simulate", "--script", script, "--frames", str(frames), "--separation-mm", separation,
                 "--force-N", "4,16", "--seed", "7", "--out", out])
        made.append((script, out))
    return made


def score_fingers(name, emit, work, made):
    for script, frames in made:
        out = run([emit, "reconstruct", "--reference", os.path.join(work, "ref.csv"), "--frames", frames, "--method",
                   "shapes", "--contacts", "-"]).stdout
        rows = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
        counts = {}
        with open(frames[:-4] + "_presses.csv") as f:
            next(f)
            for line in f:
                counts[int(line.split(",")[0])] = counts.get(int(line.split(",")[0]), 0) + 1
        same = sum(len(r["contacts"]) == counts[r["frame"]] for r in rows)
        fewer = sum(len(r["contacts"]) < counts[r["frame"]] for r in rows)
        print(f"{name}: {script}: {same}/{len(rows)} frames with as many regions as presses, {fewer} with fewer")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--emit", default="build-rel/emit")
    parser.add_argument("--compare", help="a second emit binary to reconstruct the same frames with")
    parser.add_argument("--work", default="/tmp/bar-study")
    parser.add_argument("--fingers", action="store_true", help="also separate presses that must stay apart")
    a = parser.parse_args()
    frames, todo = simulate(a.emit, a.work)
    if a.fingers:
        made = fingers(a.emit, a.work)
        for binary in filter(None, (a.compare, a.emit)):
            score_fingers(binary, binary, a.work, made)
    if a.compare:
        summary(a.compare, score(a.compare, a.work, frames, todo))
    summary(a.emit, score(a.emit, a.work, frames, todo))


if __name__ == "__main__":
    main()
