#!/usr/bin/python3
"""Force traces and HIP/proxy paths from a haptic server recording (thesis Fig. 6.3-6.7).

    python3 tools/plots/force_traces.py RECORDING.csv [--out-dir DIR] [--t-start S] [--t-end S]

writes DIR/<recording>_forces.png (force per axis over time: rendered force_{x,y,z}_N, and
commanded cmd_force_{x,y,z}_N when the recording has them; contact ticks shaded) and
DIR/<recording>_paths.png (HIP and proxy paths seen from above (x, z) and from the front
(x, y)). Columns are found by name; others are ignored. Needed: t_s, hip_{x,y,z}_m,
proxy_{x,y,z}_m, force_{x,y,z}_N; used when present: cmd_force_{x,y,z}_N, contact,
tracker_age_s.

Start-up rows are the first rows of a recording, written before the first base pose
(tracker sample): `mhd run` writes their HIP and proxy as nan and tracker_age_s as -1
(docs/haptic_server.md). They are shaded as "start-up" in the force plot and left out of
the paths; a nan HIP or proxy after the first finite one is bad input (file:line).
Exit status 0 when both PNGs were written, 1 on bad input, 2 on usage errors.
"""

import argparse
import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calibration_residuals import InputError, read_columns  # noqa: E402  (shared CSV reader)

AXES = ("x", "y", "z")
COLOURS = {"x": "tab:red", "y": "tab:green", "z": "tab:blue"}


def contact_spans(t, contact):
    """[(t0, t1)] intervals where contact is non-zero."""
    spans, start = [], None
    for ti, ci in zip(t, contact):
        if ci and start is None:
            start = ti
        elif not ci and start is not None:
            spans.append((start, ti))
            start = None
    if start is not None:
        spans.append((start, t[-1]))
    return spans


PATH_COLUMNS = [f"{p}_{a}_m" for p in ("hip", "proxy") for a in AXES]


def startup_rows(data, path):
    """How many leading rows come before the first base pose; raises InputError on a nan
    HIP or proxy anywhere else, or a start-up row that claims a tracker sample."""
    n = len(data["t_s"])
    first = next((i for i in range(n) if not any(math.isnan(data[c][i]) for c in PATH_COLUMNS)), n)
    for i in range(n):
        nan_columns = [c for c in PATH_COLUMNS if math.isnan(data[c][i])]
        if i < first and len(nan_columns) != len(PATH_COLUMNS):
            raise InputError(f"{path}:{data['line'][i]}: start-up row with a partial HIP/proxy "
                             f"(column '{nan_columns[0]}' is nan, others are not)")
        if i < first and "tracker_age_s" in data and data["tracker_age_s"][i] >= 0:
            raise InputError(f"{path}:{data['line'][i]}: column '{nan_columns[0]}' is nan but "
                             f"tracker_age_s is {data['tracker_age_s'][i]:g} (start-up rows have -1)")
        if i >= first and nan_columns:
            raise InputError(f"{path}:{data['line'][i]}: column '{nan_columns[0]}' is not finite "
                             f"after the first base pose (line {data['line'][first]})")
    return first


def window(data, t_start, t_end):
    keep = [i for i, t in enumerate(data["t_s"])
            if (t_start is None or t >= t_start) and (t_end is None or t <= t_end)]
    return {c: [v[i] for i in keep] for c, v in data.items()}


def plot_forces(data, out, title):
    import matplotlib.pyplot as plt

    t = data["t_s"]
    has_cmd = all(f"cmd_force_{a}_N" in data for a in AXES)
    spans = contact_spans(t, data["contact"]) if "contact" in data else []
    startup = contact_spans(t, data["startup"])
    fig, axes = plt.subplots(3, 1, figsize=(12, 7.5), sharex=True)
    for ax, a in zip(axes, AXES):
        for k, (t0, t1) in enumerate(startup):
            ax.axvspan(t0, t1, facecolor="tab:orange", alpha=0.2, hatch="//", edgecolor="tab:orange", linewidth=0,
                       label="start-up: no tracker sample yet" if k == 0 else None)
        for k, (t0, t1) in enumerate(spans):
            ax.axvspan(t0, t1, color="0.85", linewidth=0, label="contact" if k == 0 else None)
        ax.plot(t, data[f"force_{a}_N"], color=COLOURS[a], linewidth=1.0, label="rendered")
        if has_cmd:
            ax.plot(t, data[f"cmd_force_{a}_N"], color="black", linewidth=0.8, linestyle="--", label="commanded")
        ax.set_ylabel(f"F{a} (N)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)  # outside: never over a trace
    axes[-1].set_xlabel("time (s)")
    axes[0].set_title(f"{title}: force on the hand per axis (world frame)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_paths(data, out, title):
    import matplotlib.pyplot as plt

    tracked = [i for i, s in enumerate(data["startup"]) if not s]
    mm = lambda values: [values[i] * 1e3 for i in tracked]  # noqa: E731
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    for ax, (u, v), name in ((axes[0], ("x", "z"), "from above"), (axes[1], ("x", "y"), "from the front")):
        ax.plot(mm(data[f"hip_{u}_m"]), mm(data[f"hip_{v}_m"]), color="tab:orange", linewidth=1.0, label="HIP")
        ax.plot(mm(data[f"proxy_{u}_m"]), mm(data[f"proxy_{v}_m"]), color="tab:blue", linewidth=1.0,
                linestyle="--", label="proxy")
        ax.set_xlabel(f"world {u} (mm)")
        ax.set_ylabel(f"world {v} (mm)")
        ax.set_title(f"{title}: HIP and proxy {name}")
        if not tracked:
            ax.text(0.5, 0.5, "no HIP: the rows end before the first tracker sample",
                    transform=ax.transAxes, ha="center", va="center")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("recording", help="haptic server recording CSV")
    parser.add_argument("--out-dir", default=".", help="where the PNGs go (default: .)")
    parser.add_argument("--t-start", type=float, default=None, help="first time to plot (s)")
    parser.add_argument("--t-end", type=float, default=None, help="last time to plot (s)")
    parser.add_argument("--title", default=None, help="title (default: the recording's name)")
    args = parser.parse_args(argv)

    required = ["t_s"] + [f"{p}_{a}_m" for p in ("hip", "proxy") for a in AXES] + [f"force_{a}_N" for a in AXES]
    optional = [f"cmd_force_{a}_N" for a in AXES] + ["contact", "tracker_age_s"]
    try:
        data = read_columns(args.recording, required, optional, nan_allowed=PATH_COLUMNS, with_lines=True)
        first_tracked = startup_rows(data, args.recording)
        data["startup"] = [i < first_tracked for i in range(len(data["t_s"]))]
        data = window(data, args.t_start, args.t_end)
        if not data["t_s"]:
            raise InputError(f"{args.recording}: no rows between --t-start and --t-end")
    except InputError as e:
        print(f"force_traces.py: error: {e}", file=sys.stderr)
        return 1

    import matplotlib
    matplotlib.use("Agg")
    stem = os.path.splitext(os.path.basename(args.recording))[0]
    title = args.title or stem
    os.makedirs(args.out_dir, exist_ok=True)
    forces = os.path.join(args.out_dir, f"{stem}_forces.png")
    paths = os.path.join(args.out_dir, f"{stem}_paths.png")
    plot_forces(data, forces, title)
    plot_paths(data, paths, title)
    print(f"wrote {forces}\nwrote {paths}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
