#!/usr/bin/python3
"""Force traces and HIP/proxy paths from a haptic server recording (thesis Fig. 6.3-6.7).

    python3 tools/plots/force_traces.py RECORDING.csv [--out-dir DIR] [--t-start S] [--t-end S]

writes DIR/<recording>_forces.png (force per axis over time: rendered force_{x,y,z}_N, and
commanded cmd_force_{x,y,z}_N when the recording has them; contact ticks shaded) and
DIR/<recording>_paths.png (HIP and proxy paths seen from above (x, z) and from the front
(x, y)). Columns are found by name; others are ignored. Needed: t_s, hip_{x,y,z}_m,
proxy_{x,y,z}_m, force_{x,y,z}_N; used when present: cmd_force_{x,y,z}_N, contact.
Exit status 0 when both PNGs were written, 1 on bad input, 2 on usage errors.
"""

import argparse
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


def window(data, t_start, t_end):
    keep = [i for i, t in enumerate(data["t_s"])
            if (t_start is None or t >= t_start) and (t_end is None or t <= t_end)]
    return {c: [v[i] for i in keep] for c, v in data.items()}


def plot_forces(data, out, title):
    import matplotlib.pyplot as plt

    t = data["t_s"]
    has_cmd = all(f"cmd_force_{a}_N" in data for a in AXES)
    spans = contact_spans(t, data["contact"]) if "contact" in data else []
    fig, axes = plt.subplots(3, 1, figsize=(10, 7.5), sharex=True)
    for ax, a in zip(axes, AXES):
        for t0, t1 in spans:
            ax.axvspan(t0, t1, color="0.9", linewidth=0)
        ax.plot(t, data[f"force_{a}_N"], color=COLOURS[a], linewidth=1.0, label="rendered")
        if has_cmd:
            ax.plot(t, data[f"cmd_force_{a}_N"], color="black", linewidth=0.8, linestyle="--", label="commanded")
        ax.set_ylabel(f"F{a} (N)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("time (s)")
    axes[0].set_title(title + ("  (grey: contact)" if spans else ""))
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_paths(data, out, title):
    import matplotlib.pyplot as plt

    mm = lambda values: [v * 1e3 for v in values]  # noqa: E731
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5))
    for ax, (u, v), name in ((axes[0], ("x", "z"), "from above"), (axes[1], ("x", "y"), "from the front")):
        ax.plot(mm(data[f"hip_{u}_m"]), mm(data[f"hip_{v}_m"]), color="tab:orange", linewidth=1.0, label="HIP")
        ax.plot(mm(data[f"proxy_{u}_m"]), mm(data[f"proxy_{v}_m"]), color="tab:blue", linewidth=1.0,
                linestyle="--", label="proxy")
        ax.set_xlabel(f"{u} (mm)")
        ax.set_ylabel(f"{v} (mm)")
        ax.set_title(f"{title}: HIP and proxy {name}")
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
    optional = [f"cmd_force_{a}_N" for a in AXES] + ["contact"]
    try:
        data = window(read_columns(args.recording, required, optional), args.t_start, args.t_end)
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
