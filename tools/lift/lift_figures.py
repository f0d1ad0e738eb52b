#!/usr/bin/env python3
"""The lift's figures from an `mhd run --record` recording of a rig with a lift
(scenes/tall_column.xml; docs/planner.md, "The lift's planner"):

  - the share of contact ticks whose tool lies inside the arm's workspace (2 mm inside
    every face of the PHANToM Premium 1.5's 381 x 267 x 191 mm box, centred at
    (0, 130, -10) mm in its frame): the simulated arm holds its tool on a face while the
    hand is beyond it, so a tool inside is a hand the arm still follows;
  - the lift's tracking error: the HIP's height above the middle of the arm's usable
    reach (130 mm above the arm's frame, which pomhi.xml puts 0.87 m up at lift 0), over
    the contact ticks: median, p95 and max of its magnitude;
  - the heights touched and the lift's range.

    /usr/bin/python3 tools/lift/lift_figures.py RECORDING.csv
"""
import csv
import math
import sys

BOX_MIN = (-0.1905, -0.0035, -0.1055)
BOX_MAX = (0.1905, 0.2635, 0.0855)
INSIDE_BY_M = 0.002
PHANTOM_Y_AT_0_M = 0.87
REACH_CENTRE_ABOVE_PHANTOM_M = 0.13


def percentile(values, q):
    s = sorted(values)
    return s[min(len(s) - 1, int(q * (len(s) - 1) + 0.5))] if s else math.nan


def main(path):
    contact = inside = 0
    errors, heights, lifts = [], [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            lift = float(row.get("lift_m", "0") or "0")
            if math.isfinite(lift):
                lifts.append(lift)
            if row["contact"] != "1":
                continue
            contact += 1
            tool = [float(row["tool_D_%s_m" % a]) for a in "xyz"]
            if all(lo + INSIDE_BY_M <= v <= hi - INSIDE_BY_M for v, lo, hi in zip(tool, BOX_MIN, BOX_MAX)):
                inside += 1
            hip_y = float(row["hip_y_m"])
            heights.append(hip_y)
            errors.append(abs(hip_y - (PHANTOM_Y_AT_0_M + lift + REACH_CENTRE_ABOVE_PHANTOM_M)))
    if contact == 0:
        print("no contact ticks in %s" % path)
        return 1
    print("contact ticks: %d, tool inside the arm's workspace on %.1f %%" % (contact, 100.0 * inside / contact))
    print("HIP touched from %.2f to %.2f m; lift from %.2f to %.2f m" % (min(heights), max(heights), min(lifts),
                                                                       max(lifts)))
    print("HIP from the reach's middle: median %.1f mm, p95 %.1f mm, max %.1f mm" %
          (1e3 * percentile(errors, 0.5), 1e3 * percentile(errors, 0.95), 1e3 * max(errors)))
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
