#!/usr/bin/env python3
"""Strokes across the pole of a uv-sphere (mhd-mesh-gen uv-sphere, pole on +y), and how
well the proxy followed them (docs/benchmarks.md, "A fine mesh's pole").

A uv-sphere's pole is a fan of slivers round one vertex, and the bands next to it are
slivers too: the finer the sphere, the more triangles a sweep there meets. Random
strokes almost never pass there.

    pole_strokes.py path --radius-mm 100 --speed-mps 0.5 --out pole.csv
        12 strokes 2 mm deep, 8 mm long, in 12 directions, the k-th passing k * 20 um from
        the pole: a HIP path for mhd proxy-replay or mhd-proxy-bench --hip-path.
    pole_strokes.py follow --radius-mm 100 TICKS.csv
        from mhd proxy-replay's ticks: the ticks out of work, and the proxy's distance from
        the surface point nearest the HIP (where it would rest on a smooth sphere) while
        the HIP is inside: its maximum, and the ticks where it is over 1 mm.
"""
import argparse
import csv
import math
import sys

RATE_HZ = 1000.0
DEPTH_M = 0.002
ABOVE_M = 0.005
HALF_LENGTH_M = 0.004
STROKES = 12
OFFSET_STEP_M = 20e-6


def write_path(radius_m, speed_mps, out):
    points = []

    def leg(a, b):
        n = max(1, int(math.dist(a, b) / speed_mps * RATE_HZ))
        points.extend(tuple(a[k] + (b[k] - a[k]) * i / n for k in range(3)) for i in range(n))

    y_above, y_in = radius_m + ABOVE_M, radius_m - DEPTH_M
    for k in range(STROKES):
        azimuth = 2.0 * math.pi * k / STROKES + 0.1
        c, s = math.cos(azimuth), math.sin(azimuth)
        ox, oz = -s * k * OFFSET_STEP_M, c * k * OFFSET_STEP_M
        a = (ox + HALF_LENGTH_M * c, y_in, oz + HALF_LENGTH_M * s)
        b = (ox - HALF_LENGTH_M * c, y_in, oz - HALF_LENGTH_M * s)
        leg((a[0], y_above, a[2]), a)
        leg(a, b)
        leg(b, (b[0], y_above, b[2]))
    with open(out, "w") as f:
        f.write("t_s,x_m,y_m,z_m\n")
        for i, p in enumerate(points):
            f.write("%.6f,%.9f,%.9f,%.9f\n" % (i / RATE_HZ, *p))
    print(f"{out}: {len(points)} ticks, {STROKES} strokes")


def follow(radius_m, ticks_csv):
    ticks = out_of_work = over_1mm = 0
    worst_m = 0.0
    with open(ticks_csv) as f:
        for row in csv.DictReader(f):
            ticks += 1
            out_of_work += row["budget_exhausted"] == "1"
            hip = [float(row["hip_" + a + "_m"]) for a in "xyz"]
            proxy = [float(row["proxy_" + a + "_m"]) for a in "xyz"]
            r = math.hypot(*hip)
            if not 0.0 < r < radius_m:
                continue
            error_m = math.dist([c * radius_m / r for c in hip], proxy)
            worst_m = max(worst_m, error_m)
            over_1mm += error_m > 0.001
    print(f"{ticks} ticks: {out_of_work} out of work; proxy from the nearest surface point: "
          f"max {worst_m * 1e3:.3f} mm, over 1 mm on {over_1mm} ticks")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("path")
    p.add_argument("--radius-mm", type=float, required=True)
    p.add_argument("--speed-mps", type=float, required=True)
    p.add_argument("--out", required=True)
    f = sub.add_parser("follow")
    f.add_argument("--radius-mm", type=float, required=True)
    f.add_argument("ticks")
    args = parser.parse_args()
    if args.command == "path":
        if not (args.radius_mm > 0.0 and args.speed_mps > 0.0):
            sys.exit("pole_strokes.py: --radius-mm and --speed-mps must be positive")
        write_path(args.radius_mm / 1000.0, args.speed_mps, args.out)
    else:
        follow(args.radius_mm / 1000.0, args.ticks)


if __name__ == "__main__":
    main()
