#!/usr/bin/python3
"""The master DOFs of a reduced model, like Fig. 12 of Dimauro et al. (2024).

Reads the reduced model that `tvd reduce --out FILE.mat` writes (master_positions, master_groups,
masters) and draws every master at its node, side view (x, z) and top view (x, y): the road-input
DOFs of the pad soles, the hull's DOFs (at its CoG), the suspension arms and the MoGeSeC picks,
numbered in pick order, circles for vertical DOFs and triangles for lateral ones (the paper's
markers).

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD reduce --vehicle $V --variant untracked --out /tmp/untracked.mat
    $TVD reduce --vehicle $V --variant tracked --out /tmp/tracked.mat
    scripts/plot_masters.py --out fig12.png untracked=/tmp/untracked.mat tracked=/tmp/tracked.mat

Each LABEL=FILE gives one row of the figure. Bad input (a missing, corrupt or foreign file, a
model without master positions) exits with status 2 and one line on stderr naming the file; no
figure is written then.
"""
import argparse

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (OUT_HELP, ArgumentParser, check_outputs, fail, check_unique_labels,
                         labelled, load_mat, save, vehicle_view)
import matplotlib.pyplot as plt
import numpy as np

VARIABLES = ["master_positions", "master_groups", "masters"]
DIRECTIONS = ["ux", "uy", "uz", "rx", "ry", "rz"]
STYLES = {"road input": dict(color="0.6", s=8, label="road input (pad sole)"),
          "hull": dict(color="tab:red", s=90, marker="*", label="hull (CoG)"),
          "wheel arm": dict(color="tab:orange", s=40, marker="s", label="wheel arm")}


def texts(cell):
    """A MAT cell array of strings as a list of str."""
    return [str(np.ravel(item)[0]) if np.size(item) else "" for item in np.ravel(cell)]


def load(path):
    """(positions [m x 3], groups [m], directions [m]) of a reduced model file."""
    data = load_mat(path, VARIABLES)
    missing = [n for n in VARIABLES if n not in data]
    if missing:
        fail(f"{path}: not a reduced model with master positions (no {', '.join(missing)}; "
             f"written by `tvd reduce --out` of this version?)")
    positions = np.asarray(data["master_positions"], dtype=float)
    groups = texts(data["master_groups"])
    masters = np.asarray(data["masters"], dtype=float)
    if positions.ndim != 2 or positions.shape[1] != 3 or len(groups) != len(positions) \
            or masters.shape != (len(positions), 2):
        fail(f"{path}: master_positions {positions.shape}, {len(groups)} master_groups and "
             f"masters {masters.shape} do not match")
    if len(positions) == 0:
        fail(f"{path}: the model has no master DOFs")
    if not np.all(np.isfinite(positions)):
        fail(f"{path}: master_positions holds a non-finite value")
    directions = [DIRECTIONS[int(d)] if 0 <= d < 6 else "?" for d in masters[:, 1]]
    return positions, groups, directions


def draw(ax, positions, groups, directions, vertical_axis):
    """One view: x against `vertical_axis` (1: y, top view; 2: z, side view)."""
    v = vertical_axis
    for group, style in STYLES.items():
        rows = [i for i, g in enumerate(groups) if g == group]
        if rows:
            ax.scatter(positions[rows, 0], positions[rows, v], zorder=2, **style)
    picks = [(i, g) for i, g in enumerate(groups) if g.startswith("MoGeSeC")]
    for marker, direction, label in (("o", "uz", "MoGeSeC, vertical"),
                                     ("^", "uy", "MoGeSeC, lateral")):
        rows = [i for i, _ in picks if directions[i] == direction]
        if rows:
            ax.scatter(positions[rows, 0], positions[rows, v], marker=marker, s=60,
                       facecolors="none", edgecolors="tab:blue", linewidths=1.5, zorder=3,
                       label=label)
    # Picks that coincide in this view (left and right of a symmetric pair, seen from the side)
    # share one label, "1,2", instead of two printed over each other.
    labels = {}  # rounded (x, view coordinate) -> pick numbers
    for i, group in picks:
        key = (round(positions[i, 0], 3), round(positions[i, v], 3))
        labels.setdefault(key, []).append(group.split()[-1])
    for (x, y), numbers in labels.items():
        ax.annotate(",".join(numbers), (x, y), fontsize=8, xytext=(4, 4),
                    textcoords="offset points", color="tab:blue")
    others = [i for i, g in enumerate(groups) if g not in STYLES and not g.startswith("MoGeSeC")]
    if others:
        ax.scatter(positions[others, 0], positions[others, v], color="k", s=10, label="other")
    vehicle_view(ax, v)


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("files", nargs="+", type=labelled, metavar="[LABEL=]FILE.mat",
                        help="reduced models written by `tvd reduce --out`, one row each")
    args = parser.parse_args()
    check_unique_labels(args.files)
    check_outputs(("--out", args.out))

    models = [(label, *load(path)) for label, path in args.files]
    fig, axes = plt.subplots(len(models), 2, figsize=(14, 4.2 * len(models)), squeeze=False)
    for row, (label, positions, groups, directions) in zip(axes, models):
        draw(row[0], positions, groups, directions, 2)
        draw(row[1], positions, groups, directions, 1)
        picks = sum(g.startswith("MoGeSeC") for g in groups)
        row[0].set_title(f"{label}: side view ({len(groups)} masters, {picks} by MoGeSeC)")
        row[1].set_title(f"{label}: top view")
    axes[0][0].legend(fontsize="small", loc="upper right")
    save((fig, args.out))


if __name__ == "__main__":
    main()
