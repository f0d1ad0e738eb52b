#!/usr/bin/python3
"""The force trace of the dolphin demo (docs/haptic_server.md, images/dolphin_run_forces.png),
made with the `mhd` Python module instead of `mhd run` and tools/plots/force_traces.py.

    PYTHONPATH=build/release/python /usr/bin/python3 python/examples/dolphin_force_trace.py \
        [--duration 20] [--out dolphin_run_forces.png] [--recording run.csv] [--show]

Runs the haptic server on scenes/dolphin.xml on its simulated plugins (a simulated user
walks up to the dolphin, the base follows, the hand strokes the dolphin's back) for
--duration seconds, recording every tick; reads the recording back as a NumPy structured
array and draws the force on the hand per axis: rendered (what the device was told) and
commanded (the proxy's force before the safety stage), contact shaded grey, the start-up
rows (before the first tracker sample) hatched. Writes --out; --show also opens a window.
"""

import argparse
import os
import sys
import tempfile

import numpy as np

import mhd

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
AXES = ("x", "y", "z")
COLOURS = {"x": "tab:red", "y": "tab:green", "z": "tab:blue"}


def spans(t_s, mask):
    """[(t0, t1)] of each run of True in mask."""
    edges = np.flatnonzero(np.diff(np.concatenate(([0], mask.astype(np.int8), [0]))))
    return [(t_s[a], t_s[min(b, len(t_s) - 1)]) for a, b in zip(edges[::2], edges[1::2])]


def plot_forces(rec, out, title, show):
    import matplotlib
    if not show:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = rec["t_s"]
    startup = rec["tracker_age_s"] < 0  # no base pose yet: no HIP, no force
    fig, axes = plt.subplots(3, 1, figsize=(12, 7.5), sharex=True)
    for ax, a in zip(axes, AXES):
        for k, (t0, t1) in enumerate(spans(t, startup)):
            ax.axvspan(t0, t1, facecolor="tab:orange", alpha=0.2, hatch="//", edgecolor="tab:orange", linewidth=0,
                       label="start-up: no tracker sample yet" if k == 0 else None)
        for k, (t0, t1) in enumerate(spans(t, rec["contact"] != 0)):
            ax.axvspan(t0, t1, color="0.85", linewidth=0, label="contact" if k == 0 else None)
        ax.plot(t, rec[f"force_{a}_N"], color=COLOURS[a], linewidth=1.0, label="rendered")
        ax.plot(t, rec[f"cmd_force_{a}_N"], color="black", linewidth=0.8, linestyle="--", label="commanded")
        ax.set_ylabel(f"F{a} (N)")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)  # outside: never over a trace
    axes[-1].set_xlabel("time (s)")
    axes[0].set_title(f"{title}: force on the hand per axis (world frame)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    if show:
        plt.show()
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=os.path.join(REPO, "scenes", "dolphin.xml"), help="scene XML")
    parser.add_argument("--duration", type=float, default=20.0, help="seconds to run (default: 20, the demo's)")
    parser.add_argument("--out", default="dolphin_run_forces.png", help="the figure (PNG)")
    parser.add_argument("--recording", default=None, help="keep the recording here (default: a temporary file)")
    parser.add_argument("--show", action="store_true", help="also show the figure in a window")
    args = parser.parse_args(argv)

    scene = mhd.load_scene(args.scene)
    with tempfile.TemporaryDirectory() as tmp:
        recording = args.recording or os.path.join(tmp, "dolphin_run.csv")
        report = mhd.run_server(scene, duration_s=args.duration, recording=recording)
        rec = mhd.read_recording(recording)
    print(f"ran {report.status.elapsed_s:.2f} s: {report.status.ticks} ticks, {report.contact_ticks} in contact, "
          f"{report.clamped_ticks} clamped; recording: {len(rec)} rows")
    plot_forces(rec, args.out, "dolphin_run", args.show)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except mhd.MhdError as e:
        print(f"dolphin_force_trace.py: error: {e}", file=sys.stderr)
        sys.exit(1)
