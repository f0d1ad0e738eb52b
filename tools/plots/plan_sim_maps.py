#!/usr/bin/python3
"""Follow maps of `mhd plan-sim` (thesis Fig. 3.9-3.10), drawn from the CSVs it writes.

    python3 tools/plots/plan_sim_maps.py PLAN_SIM_DIR [--no-single]

reads PLAN_SIM_DIR/maps/planner_<kind>_f<facing>_v<v>_w<w>.csv and writes, beside each,
planner_...png (one map), and PLAN_SIM_DIR/planner_<kind>_f<facing>.png (the maps of one
planner and facing change tiled: linear speed limits down, angular speed limits across).
A map is a top view of the floor in the world frame (x right, z down, metres): the user at
the start and the user's cylinder, the facing before and after the move, the base's start,
the followed cells (user positions whose hand the base brings into the usable workspace
within the horizon) coloured by when, and a 0.5 m scale bar.
Exit status 0 when every PNG was written, 1 on bad input (file:line), 2 on usage errors.
"""

import argparse
import glob
import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calibration_residuals import InputError, read_columns  # noqa: E402  (shared CSV reader)

META_NUMBERS = ("max_linear_speed_mps", "max_angular_speed_degps", "facing_change_deg", "horizon_s", "half_size_m",
                "cell_m", "user_start_x_m", "user_start_z_m", "user_start_heading_deg", "collision_radius_m",
                "base_start_x_m", "base_start_z_m", "followed_area_m2")
SCALE_BAR_M = 0.5


def read_map(path):
    meta = {}
    try:
        with open(path) as f:
            for n, line in enumerate(f, 1):
                if not line.startswith("#") or "=" not in line:
                    continue
                name, value = line[1:].strip().split("=", 1)
                if name in META_NUMBERS:
                    try:
                        meta[name] = float(value)
                    except ValueError:
                        raise InputError(f"{path}:{n}: '{name}' is '{value}', not a number")
                else:
                    meta[name] = value
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}")
    missing = [m for m in META_NUMBERS + ("planner",) if m not in meta]
    if missing:
        raise InputError(f"{path}: missing '# {missing[0]}=' line (is this a plan-sim map?)")
    try:
        cells = read_columns(path, ["x_m", "z_m", "follow_time_s"])
    except InputError as e:
        if "no data rows" not in str(e):
            raise
        cells = {"x_m": [], "z_m": [], "follow_time_s": []}  # nothing followed is a valid map
    return meta, cells


def direction(heading_deg):
    """World (x, z) of a heading (the planner's convention: (cos h, -sin h))."""
    h = math.radians(heading_deg)
    return math.cos(h), -math.sin(h)


def draw_map(ax, meta, cells, show_legend=True):
    import matplotlib.patches as mpatches
    import numpy as np
    from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

    half, cell = meta["half_size_m"], meta["cell_m"]
    n = int(round(2 * half / cell))
    grid = np.full((n, n), np.nan)
    for x, z, t in zip(cells["x_m"], cells["z_m"], cells["follow_time_s"]):
        ix, iz = int((x + half) // cell), int((z + half) // cell)
        if 0 <= ix < n and 0 <= iz < n:
            grid[iz, ix] = t
    # Row 0 is the smallest z; z grows downward, as the thesis draws it.
    image = ax.imshow(grid, extent=(-half, half, half, -half), origin="upper", cmap="viridis",
                      vmin=0.0, vmax=meta["horizon_s"], interpolation="nearest")
    ux, uz = meta["user_start_x_m"], meta["user_start_z_m"]
    ax.add_patch(mpatches.Circle((ux, uz), meta["collision_radius_m"], fill=False, color="black", linewidth=1.0,
                                 label=f"user's cylinder at the start (r {meta['collision_radius_m']:.3f} m)"))
    ax.plot([ux], [uz], "o", color="black", markersize=5, label="user at the start")
    arrow = 0.4
    for heading, colour, text in ((meta["user_start_heading_deg"], "0.45", "facing at the start"),
                                  (meta["user_start_heading_deg"] + meta["facing_change_deg"], "tab:orange",
                                   f"facing after the move ({meta['facing_change_deg']:+.0f}°)")):
        dx, dz = direction(heading)
        ax.annotate("", xy=(ux + arrow * dx, uz + arrow * dz), xytext=(ux, uz),
                    arrowprops={"arrowstyle": "-|>", "color": colour, "linewidth": 1.8})
        ax.plot([], [], color=colour, linewidth=1.8, label=text)  # legend entry for the arrow
    ax.plot([meta["base_start_x_m"]], [meta["base_start_z_m"]], "s", color="tab:red", markersize=6,
            label="base at the start")
    ax.add_artist(AnchoredSizeBar(ax.transData, SCALE_BAR_M, f"{SCALE_BAR_M:g} m", "lower left", pad=0.4,
                                  frameon=True, size_vertical=0.015))
    ax.set_xlim(-half, half)
    ax.set_ylim(half, -half)
    ax.set_aspect("equal")
    ax.set_xlabel("world x (m)")
    ax.set_ylabel("world z (m)")
    if show_legend:
        followed = mpatches.Patch(color=image.cmap(0.6), label=f"followed within {meta['horizon_s']:g} s "
                                  f"({meta['followed_area_m2']:.3f} m²)")
        handles, _ = ax.get_legend_handles_labels()
        ax.legend(handles=[followed] + handles, loc="upper right", fontsize=7, framealpha=0.9)
    return image


def title_of(meta):
    return (f"{meta['planner']} planner, v_max {meta['max_linear_speed_mps']:g} m/s, "
            f"ω_max {meta['max_angular_speed_degps']:g}°/s, facing change {meta['facing_change_deg']:+.0f}°")


def plot_single(meta, cells, out):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.2, 6.4))
    image = draw_map(ax, meta, cells)
    fig.colorbar(image, ax=ax, label="time until the hand is in the workspace (s)")
    ax.set_title(title_of(meta), fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def plot_tiled(maps, out):
    import matplotlib.pyplot as plt

    speeds = sorted({m["max_linear_speed_mps"] for m, _ in maps})
    omegas = sorted({m["max_angular_speed_degps"] for m, _ in maps})
    fig, axes = plt.subplots(len(speeds), len(omegas), figsize=(3.2 * len(omegas) + 1.5, 3.1 * len(speeds) + 1.2),
                             squeeze=False)
    for ax in axes.flat:
        ax.set_visible(False)
    image = None
    for meta, cells in maps:
        ax = axes[speeds.index(meta["max_linear_speed_mps"])][omegas.index(meta["max_angular_speed_degps"])]
        ax.set_visible(True)
        image = draw_map(ax, meta, cells, show_legend=False)
        ax.set_title(f"v_max {meta['max_linear_speed_mps']:g} m/s, ω_max {meta['max_angular_speed_degps']:g}°/s: "
                     f"{meta['followed_area_m2']:.2f} m²", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.xaxis.label.set_size(8)
        ax.yaxis.label.set_size(8)
    meta = maps[0][0]
    handles, labels = axes.flat[0].get_legend_handles_labels() if axes.flat[0].get_visible() else ([], [])
    if not handles:
        handles, labels = next(a for a in axes.flat if a.get_visible()).get_legend_handles_labels()
    import matplotlib.patches as mpatches
    handles = [mpatches.Patch(color=image.cmap(0.6), label=f"followed within {meta['horizon_s']:g} s")] + handles
    fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=8)
    fig.suptitle(f"Follow maps, {meta['planner']} planner, user's facing change {meta['facing_change_deg']:+.0f}° "
                 "(top view, world frame)")
    fig.tight_layout(rect=(0, 0.07, 0.86, 0.97))
    cax = fig.add_axes((0.88, 0.15, 0.015, 0.7))
    fig.colorbar(image, cax=cax, label="time until the hand is in the workspace (s)")
    fig.savefig(out, dpi=90)
    plt.close(fig)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("plan_sim_dir", help="the --out folder of mhd plan-sim")
    parser.add_argument("--no-single", action="store_true", help="only the tiled PNGs, not one per map")
    args = parser.parse_args(argv)

    files = sorted(glob.glob(os.path.join(args.plan_sim_dir, "maps", "planner_*.csv")))
    try:
        if not files:
            raise InputError(f"{args.plan_sim_dir}: no maps/planner_*.csv (run mhd plan-sim --out "
                             f"{args.plan_sim_dir} without --no-maps)")
        maps = [(path, *read_map(path)) for path in files]
    except InputError as e:
        print(f"plan_sim_maps.py: error: {e}", file=sys.stderr)
        return 1

    import matplotlib
    matplotlib.use("Agg")
    groups = {}
    written = 0
    for path, meta, cells in maps:
        groups.setdefault((meta["planner"], meta["facing_change_deg"]), []).append((meta, cells))
        if not args.no_single:
            plot_single(meta, cells, os.path.splitext(path)[0] + ".png")
            written += 1
    for (planner, facing), group in sorted(groups.items()):
        out = os.path.join(args.plan_sim_dir, f"planner_{planner}_f{facing:.0f}.png")
        plot_tiled(group, out)
        print(f"wrote {out}")
        written += 1
    print(f"wrote {written} PNGs from {len(maps)} maps")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
