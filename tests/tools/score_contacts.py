#!/usr/bin/env python3
"""Scores emit's contacts (JSON Lines) against the presses that made them (the presses CSV).

Frames of one press: the strongest contact's position error (mean, p95, max), the force's
relative error, and the frames with a contact more. Frames of several presses: how often every
press has a contact within 2 mm (each contact matched once), and how many contacts were found.

    python3 tests/tools/score_contacts.py contacts.jsonl presses.csv
"""
import csv
import json
import math
import sys


def main(contacts_path, presses_path):
    contacts = {}
    with open(contacts_path) as f:
        for line in f:
            record = json.loads(line)
            contacts[record["frame"]] = record["contacts"]
    truth = {}
    with open(presses_path) as f:
        for row in csv.reader(f):
            if not row or row[0].startswith("frame"):
                continue
            truth.setdefault(int(row[0]), []).append((float(row[1]), float(row[2]), float(row[4])))
    single, forces, extra = [], [], 0
    several, found_all = 0, 0
    for frame, presses in sorted(truth.items()):
        found = contacts.get(frame, [])
        if len(presses) == 1:
            x, y, force = presses[0]
            if not found:
                single.append(math.inf)
                continue
            single.append(math.hypot(found[0]["x_mm"] - x, found[0]["y_mm"] - y))
            forces.append(abs(found[0]["force_N"] - force) / force)
            extra += len(found) > 1
        else:
            several += 1
            used, ok = set(), True
            for x, y, _ in presses:
                best = min(((math.hypot(c["x_mm"] - x, c["y_mm"] - y), i) for i, c in enumerate(found) if i not in used),
                           default=None)
                if best is None or best[0] > 2:
                    ok = False
                else:
                    used.add(best[1])
            found_all += ok
    if single:
        single.sort()
        n = len(single)
        print("single presses: %d; position error mean %.3f mm, p95 %.3f, max %.3f; force error mean %.1f %%; "
              "frames with a contact more: %d" % (n, sum(single) / n, single[int(0.95 * (n - 1))], single[-1],
                                                  100 * sum(forces) / max(1, len(forces)), extra))
    if several:
        print("frames of several presses: %d; every press found within 2 mm: %.0f %%" % (several, 100 * found_all / several))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: score_contacts.py CONTACTS.jsonl PRESSES.csv")
    main(sys.argv[1], sys.argv[2])
