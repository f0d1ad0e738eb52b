#!/usr/bin/python3
"""Before/after residual plot of a rig calibration (thesis Fig. 4.8), from the CSV that
`mhd calibrate SAMPLES.csv --rig RIG.xml --residuals RESIDUALS.csv` writes.

    python3 tools/plots/calibration_residuals.py RESIDUALS.csv -o residuals.png

Columns are found by name (others are ignored): before_x_m, before_y_m, before_z_m,
after_x_m, after_y_m, after_z_m (residual = measured - predicted HIP, world frame), and
optionally base_x_m, base_z_m (the base positions, drawn like the thesis's Fig. 4.7).
Exit status 0 when the PNG was written, 1 on bad input (the message names the file and
line), 2 on usage errors.
"""

import argparse
import csv
import math
import os
import sys

AXES = ("x", "y", "z")
COLOURS = {"x": "tab:red", "y": "tab:green", "z": "tab:blue"}


class InputError(Exception):
    pass


def read_columns(path, required, optional=(), nan_allowed=(), with_lines=False):
    """Returns {column: [float, ...]} for the required and present optional columns.

    Columns in nan_allowed may hold 'nan' (the caller decides which rows may); any other
    non-finite value is an error naming file:line. with_lines adds data["line"]: the file
    line of each row, so the caller's own checks can name it too.
    """
    try:
        with open(path, newline="") as f:
            rows = [(n + 1, line) for n, line in enumerate(f) if line.strip() and not line.lstrip().startswith("#")]
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}")
    if not rows:
        raise InputError(f"{path}: no header line")
    header_line, header_text = rows[0]
    header = next(csv.reader([header_text]))
    header = [h.strip() for h in header]
    missing = [c for c in required if c not in header]
    if missing:
        raise InputError(f"{path}:{header_line}: missing column{'s' if len(missing) > 1 else ''} "
                         + ", ".join(f"'{c}'" for c in missing))
    wanted = list(required) + [c for c in optional if c in header]
    index = {c: header.index(c) for c in wanted}
    data = {c: [] for c in wanted}
    lines = []
    for line_number, text in rows[1:]:
        lines.append(line_number)
        fields = next(csv.reader([text]))
        if len(fields) != len(header):
            raise InputError(f"{path}:{line_number}: expected {len(header)} fields, found {len(fields)}")
        for c in wanted:
            text = fields[index[c]].strip()
            try:
                value = float({"true": "1", "false": "0"}.get(text.lower(), text))
            except ValueError:
                raise InputError(f"{path}:{line_number}: column '{c}': '{text}' is not a number")
            if not math.isfinite(value) and not (c in nan_allowed and math.isnan(value)):
                raise InputError(f"{path}:{line_number}: column '{c}' is not finite")
            data[c].append(value)
    if not data[wanted[0]]:
        raise InputError(f"{path}: no data rows")
    if with_lines:
        data["line"] = lines
    return data


def rmse(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def plot(data, out, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = len(data["before_x_m"])
    index = list(range(1, n + 1))
    has_base = "base_x_m" in data and "base_z_m" in data
    fig, grid = plt.subplots(2, 2 if has_base else 1, figsize=(12 if has_base else 8, 7.5), squeeze=False,
                             gridspec_kw={"width_ratios": [2.2, 1]} if has_base else None)
    for row, phase in enumerate(("before", "after")):
        ax = grid[row][0]
        for a in AXES:
            values_mm = [v * 1e3 for v in data[f"{phase}_{a}_m"]]
            ax.plot(index, values_mm, marker=".", linewidth=0.8, color=COLOURS[a],
                    label=f"{a}: RMSE {rmse(values_mm):.2f} mm")
        ax.axhline(0.0, color="black", linewidth=0.6)
        ax.set_title(f"HIP error {phase} calibration (measured - predicted)")
        ax.set_xlabel("sample")
        ax.set_ylabel("error (mm)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize=9, framealpha=0.9)
    if has_base:
        ax = grid[0][1]
        ax.scatter(data["base_x_m"], data["base_z_m"], s=12, color="tab:gray", label="base at a sample")
        ax.set_title("base positions (world x, z)")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("z (m)")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=9)
        ax = grid[1][1]
        for a in AXES:
            ax.hist([v * 1e3 for v in data[f"after_{a}_m"]], bins=15, histtype="step", color=COLOURS[a], label=a)
        ax.set_title("error after calibration")
        ax.set_xlabel("error (mm)")
        ax.set_ylabel("samples")
        ax.legend(fontsize=9)
        ax.grid(True, alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("residuals", help="CSV from mhd calibrate --residuals")
    parser.add_argument("-o", "--out", default="calibration_residuals.png", help="PNG to write")
    parser.add_argument("--title", default="Rig calibration residuals", help="figure title")
    args = parser.parse_args(argv)
    required = [f"{phase}_{a}_m" for phase in ("before", "after") for a in AXES]
    try:
        data = read_columns(args.residuals, required, optional=("base_x_m", "base_z_m"))
    except InputError as e:
        print(f"calibration_residuals.py: error: {e}", file=sys.stderr)
        return 1
    if os.path.dirname(args.out):
        os.makedirs(os.path.dirname(args.out), exist_ok=True)
    plot(data, args.out, args.title)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
