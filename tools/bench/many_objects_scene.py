#!/usr/bin/env python3
"""Writes a scene of N copies of one mesh on a cubic grid, for timing ticks in scenes of
many objects (docs/benchmarks.md, "Scenes of many objects"):

    python3 tools/bench/many_objects_scene.py --objects 4000 --out many_4000.xml
    mhd-popthrough-stress many_4000.xml --object s0 --strokes 200 --seed 1234

Object s0 sits at the grid's corner; every copy is a separate object (each its own
pose), all sharing the one mesh, which is compiled once."""

import argparse
import math
import os
import sys


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n", maxsplit=1)[0])
    parser.add_argument("--objects", type=int, required=True, help="how many copies (1 to 1000000)")
    parser.add_argument("--mesh", default=None, help="mesh file (default: the repository's assets/dolphin.ply)")
    parser.add_argument("--spacing-mm", type=float, default=2500.0, help="grid spacing (default 2500 mm)")
    parser.add_argument("--out", required=True, help="scene file to write")
    args = parser.parse_args()
    if not 1 <= args.objects <= 1_000_000:
        print(f"many_objects_scene.py: error: --objects must be within [1, 1000000], got {args.objects}",
              file=sys.stderr)
        return 2
    if not (math.isfinite(args.spacing_mm) and args.spacing_mm > 0.0):
        print(f"many_objects_scene.py: error: --spacing-mm must be positive, got {args.spacing_mm}", file=sys.stderr)
        return 2
    here = os.path.dirname(os.path.abspath(__file__))
    mesh = os.path.abspath(args.mesh or os.path.join(here, "..", "..", "assets", "dolphin.ply"))
    if not os.path.isfile(mesh):
        print(f"many_objects_scene.py: error: no mesh file {mesh}", file=sys.stderr)
        return 2
    side = math.ceil(round(args.objects ** (1.0 / 3.0), 9))
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<scene version="1" name="many_{args.objects}" unit="mm">',
        '  <haptics max_force_N="8.5" update_rate_Hz="1000"/>',
        '  <material name="m" stiffness_N_per_m="1000" damping_Ns_per_m="0" static_friction="0"'
        ' dynamic_friction="0" force_shading="false"/>',
    ]
    for n in range(args.objects):
        i, j, k = n // (side * side), (n // side) % side, n % side
        lines += [
            f'  <object name="s{n}" material="m">',
            f'    <mesh file="{mesh}"/>',
            f'    <pose position="{i * args.spacing_mm:g} {j * args.spacing_mm:g} {k * args.spacing_mm:g}"'
            ' rpy_deg="0 0 0"/>',
            "  </object>",
        ]
    lines.append("</scene>")
    with open(args.out, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
