#!/usr/bin/python3
"""Checks that each PNG exists and is a real plot, not an empty canvas (tests/plots).

    check_png.py FILE.png... [--min-colours N]

A plot with axes, text and traces has many distinct colours (anti-aliasing alone gives
dozens); a blank or failed figure has one or two. Exit 0 when every file passes.
"""

import argparse
import os
import sys

sys.dont_write_bytecode = True


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pngs", nargs="+")
    parser.add_argument("--min-colours", type=int, default=32)
    args = parser.parse_args(argv)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.image as mpimg
    import numpy as np

    failed = False
    for path in args.pngs:
        if not os.path.isfile(path):
            print(f"{path}: missing")
            failed = True
            continue
        pixels = mpimg.imread(path)
        height, width = pixels.shape[:2]
        colours = len(np.unique(pixels.reshape(height * width, -1), axis=0))
        ok = width >= 400 and height >= 300 and colours >= args.min_colours
        print(f"{path}: {width}x{height} px, {colours} colours{'' if ok else ' (too plain)'}")
        failed |= not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
