#!/usr/bin/python3
"""MAC of the un-tracked and tracked vehicle modes, like Figs. 9 and 10 of Dimauro et al. (2024).

--out (Fig. 9): the MAC matrix, un-tracked modes on x, tracked modes on y; gray scale below the
threshold, red scale at or above it (blue where one of the two modes is not a global mode, when
mac.mat says which are: a local mode of the chains that happens to share a shape on the common
DOFs, which the reduction's pairing leaves out). --freq-out (Fig. 10): the mode selection, every
pair of global modes whose MAC between eigenspaces (what the pairing uses) is >= threshold, as a
marker at (f_untracked, f_tracked), sized and coloured by MAC, with the iso-frequency line; its
tracked modes are those `tvd reduce` keeps. From a mac.mat without the global flags (older tvd):
every pair with MAC >= threshold.

Input: the directory written by
    build/devel/lib/tracked_vehicle_dynamics/tvd mac --vehicle config/vehicles/paper_vehicle.yaml \\
        --count 40 --out DIR
    scripts/plot_mac.py --mac-dir DIR --out fig9.png --freq-out fig10.png
DIR/mac.csv: header 'untracked_mode' (un-tracked mode number of each row), then one
column per tracked mode named by its number. DIR/mac.mat (needed for --freq-out; used when
present for --out): the vectors untracked_frequencies_hz and tracked_frequencies_hz [Hz], and
optionally untracked_global, tracked_global (1 for a global mode) and eigenspace_mac, indexed by
mode number - 1.

The figure type of --out and --freq-out follows the extension (.png, .pdf, .svg, ...). Bad input
(missing or corrupt file, missing or repeated column or variable, non-numeric value, an option that
is not a finite number in range, an output that cannot be written) exits with status 2 and one line
on stderr naming the file; every input and output is checked before a figure is written, so bad
input writes no figure at all.
"""
import argparse
import os
import re

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (OUT_HELP, ArgumentParser, Table, check_outputs, fail, load_mat,
                         positive_float, save)
import matplotlib
import matplotlib.pyplot as plt
import numpy as np


ROW_COLUMN = "untracked_mode"
# Scales without their near-white ends, so that MAC = threshold is visibly red.
RED = matplotlib.colors.ListedColormap(matplotlib.colormaps["Reds"](np.linspace(0.3, 1, 256)))
GRAY = matplotlib.colors.ListedColormap(matplotlib.colormaps["Greys"](np.linspace(0, 0.85, 256)))
BLUE = matplotlib.colors.ListedColormap(matplotlib.colormaps["Blues"](np.linspace(0.3, 0.8, 256)))
GLOBAL_NAMES = ["untracked_global", "tracked_global", "eigenspace_mac"]


MAX_MODE = 10**6  # far more modes than any MAT vector of frequencies holds


def mode_numbers(path, what, values):
    if np.any(values != np.round(values)) or np.any(values < 1):
        fail(f"{path}: {what} are not mode numbers >= 1")
    if np.any(values > MAX_MODE):
        fail(f"{path}: {what} include a mode number above {MAX_MODE}")
    return values.astype(int)


def load_mac(path):
    """(un-tracked mode numbers, tracked mode numbers, MAC[untracked, tracked]) from mac.csv."""
    table = Table(path)
    untracked = mode_numbers(path, f"the values of '{ROW_COLUMN}'", table.column(ROW_COLUMN))
    names = [name for name in table.header if name != ROW_COLUMN]
    if not names or not all(re.fullmatch("[0-9]+", name) for name in names):
        fail(f"{path}: the columns after '{ROW_COLUMN}' must be named by tracked mode numbers")
    tracked = mode_numbers(path, "the column names",
                           np.array([min(int(name), MAX_MODE + 1) for name in names], dtype=float))
    mac = np.column_stack([table.column(name) for name in names])
    if mac.min() < 0 or mac.max() > 1 + 1e-9:
        fail(f"{path}: MAC values outside [0, 1]")
    return untracked, tracked, mac


def load_frequencies(path, data, name, modes):
    """Natural frequencies [Hz] of the given mode numbers, from variable `name` of mac.mat."""
    if name not in data:
        fail(f"{path}: missing variable '{name}'")
    values = data[name]
    if (not isinstance(values, np.ndarray) or values.dtype.kind not in "iuf"
            or not np.all(np.isfinite(values))):
        fail(f"{path}: variable '{name}' is not a vector of finite numbers")
    values = values.ravel()
    if modes.max() > values.size:
        fail(f"{path}: variable '{name}' has {values.size} entries, mac.csv needs {modes.max()}")
    return values[modes - 1]


def load_pair_mac(path, values, untracked, tracked):
    """The eigenspace MAC [untracked, tracked] of the plotted modes, from mac.mat."""
    if (not isinstance(values, np.ndarray) or values.dtype.kind not in "iuf" or values.ndim != 2
            or not np.all(np.isfinite(values))):
        fail(f"{path}: variable 'eigenspace_mac' is not a matrix of finite numbers")
    if untracked.max() > values.shape[0] or tracked.max() > values.shape[1]:
        fail(f"{path}: variable 'eigenspace_mac' is {values.shape[0]} x {values.shape[1]}, "
             f"mac.csv needs {untracked.max()} x {tracked.max()}")
    return values[np.ix_(untracked - 1, tracked - 1)]


def mode_ticks(ax, untracked, tracked):
    """Tick every mode up to 40 modes, every 5th beyond."""
    for axis, modes in ((ax.xaxis, untracked), (ax.yaxis, tracked)):
        step = 1 if modes.size <= 40 else 5
        axis.set_ticks(np.arange(0, modes.size, step))
        axis.set_ticklabels([str(m) for m in modes[::step]], fontsize=6)


def band_edges(ax, f_untracked, f_tracked, f_max):
    """Dashed lines after the last mode at or below f_max [Hz] on each axis: the modes beyond are
    outside the band of interest (the paper ignores them, §3.1.1)."""
    for frequencies, line, place in ((f_untracked, ax.axvline, "x"), (f_tracked, ax.axhline, "y")):
        inside = int(np.count_nonzero(frequencies <= f_max))
        if inside == frequencies.size:
            continue
        line(inside - 0.5, color="tab:green", linestyle="--", linewidth=1)
        if place == "x":  # in the top image row: the y axis counts the tracked modes
            ax.text(inside - 0.3, f_tracked.size - 0.8, f"> {f_max:g} Hz", color="tab:green",
                    fontsize=7, va="top")
        else:
            ax.text(0.2, inside - 0.3, f"> {f_max:g} Hz",
                    color="tab:green", fontsize=7, va="bottom")


def plot_matrix(untracked, tracked, mac, threshold, frequencies=None, f_max=None,
                global_modes=None):
    """Fig. 9; with frequencies = (un-tracked, tracked) [Hz] and f_max, the band edges are drawn;
    with global_modes = (un-tracked, tracked) flags, a pair at or above the threshold with a
    local mode in it is drawn blue, not red."""
    fig, ax = plt.subplots(figsize=(10.5 if global_modes is not None else 9, 7.5))
    shown = mac.T  # rows: tracked modes (y), columns: un-tracked modes (x)
    local = np.zeros(shown.shape, dtype=bool)
    if global_modes is not None:
        local = ~np.outer(global_modes[1], global_modes[0])
    low = ax.imshow(np.ma.masked_where(shown >= threshold, shown), cmap=GRAY, vmin=0,
                    vmax=threshold, origin="lower", aspect="auto")
    high = ax.imshow(np.ma.masked_where((shown < threshold) | local, shown), cmap=RED,
                     vmin=threshold, vmax=1, origin="lower", aspect="auto")
    off = None
    if np.any((shown >= threshold) & local):
        off = ax.imshow(np.ma.masked_where((shown < threshold) | ~local, shown), cmap=BLUE,
                        vmin=threshold, vmax=1, origin="lower", aspect="auto")
    for y, x in np.argwhere(shown >= threshold):
        ax.text(x, y, f"{shown[y, x]:.2f}", ha="center", va="center", fontsize=5, color="w")
    # Each colour bar takes its room from the axes' right side, so the last added sits nearest.
    fig.colorbar(low, ax=ax, pad=0.01, label=f"MAC < {threshold:g}")
    if off is not None:
        fig.colorbar(off, ax=ax, pad=0.01,
                     label=f"MAC $\\geq$ {threshold:g} with a local mode (not paired)")
    fig.colorbar(high, ax=ax, pad=0.02, label=f"MAC $\\geq$ {threshold:g}" +
                 (" (global modes)" if global_modes is not None else ""))
    mode_ticks(ax, untracked, tracked)
    if frequencies is not None and f_max is not None:
        band_edges(ax, *frequencies, f_max)
    ax.set_xlabel("un-tracked (minimal track chain) model mode #")
    ax.set_ylabel("tracked model mode #")
    ax.set_title("MAC between un-tracked and tracked vehicle modes")
    return fig


def plot_frequencies(untracked, tracked, f_untracked, f_tracked, mac, threshold, f_max,
                     global_modes=None):
    """Fig. 10; pairs with either frequency above f_max [Hz] (if given) are left out; with
    global_modes = (un-tracked, tracked) flags, so are pairs with a local mode in them (the
    selection), and `mac` should then be the eigenspace MAC the pairing uses."""
    fig, ax = plt.subplots(figsize=(7.5, 6.5))
    paired = mac >= threshold
    if global_modes is not None:
        paired &= np.outer(global_modes[0], global_modes[1])
    pairs = np.argwhere(paired)
    if f_max is not None:
        pairs = pairs[(f_untracked[pairs[:, 0]] <= f_max) & (f_tracked[pairs[:, 1]] <= f_max)]
    i, j = pairs[:, 0], pairs[:, 1]
    limit = f_max or 1.05 * max([1.0, *f_untracked[i], *f_tracked[j]])
    ax.plot([0, limit], [0, limit], "k--", linewidth=1, label="iso-frequency")
    markers = ax.scatter(f_untracked[i], f_tracked[j], s=300 * mac[i, j] ** 2, c=mac[i, j],
                         cmap=RED, vmin=threshold, vmax=1, edgecolors="k", linewidths=0.5,
                         label=f"MAC $\\geq$ {threshold:g}", zorder=3)
    # A label is about 6 % of the axis wide: neighbours share one, written right of the
    # rightmost marker of the group and clear of its disc (the marker area is s = 300 MAC² pt²).
    labels = []  # [x, y, names, largest marker radius in pt]
    for a, b in zip(i, j):
        x, y, name = f_untracked[a], f_tracked[b], f"{untracked[a]}/{tracked[b]}"
        radius = np.sqrt(300 / np.pi) * mac[a, b]
        near = [g for g in labels if abs(g[0] - x) < 0.06 * limit and abs(g[1] - y) < 0.03 * limit]
        if near:
            near[0][2].append(name)
            near[0][3] = max(near[0][3], radius)
            if x > near[0][0]:
                near[0][0], near[0][1] = x, y
        else:
            labels.append([x, y, [name], radius])
    for x, y, names, radius in labels:
        # On a white ground: the iso-frequency line runs through the pairs' labels.
        ax.annotate(", ".join(names), (x, y), xytext=(radius + 3, -2), textcoords="offset points",
                    fontsize=6, zorder=4,
                    bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 0.5})
    fig.colorbar(markers, ax=ax, label="MAC")
    ax.set_xlim(0, limit)
    ax.set_ylim(0, limit)
    ax.set_xlabel("un-tracked (minimal track chain) model frequency [Hz]")
    ax.set_ylabel("tracked model frequency [Hz]")
    if global_modes is None:
        ax.set_title(f"{len(pairs)} mode pairs with MAC $\\geq$ {threshold:g} "
                     "(un-tracked/tracked #)")
    else:
        ax.set_title(f"Mode selection: {len(pairs)} pairs of global modes with MAC $\\geq$ "
                     f"{threshold:g},\n{len(set(j))} tracked modes kept (un-tracked/tracked #)")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left")
    return fig


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mac-dir", required=True, help="directory written by `tvd mac --out`")
    parser.add_argument("--out", required=True,
                        help=f"figure file of the MAC matrix (Fig. 9); {OUT_HELP}")
    parser.add_argument("--freq-out",
                        help="figure file of the frequency map (Fig. 10), same types as --out")
    parser.add_argument("--threshold", type=float, default=0.7,
                        help="MAC of a match, in [0, 1] (default 0.7, as in the paper)")
    parser.add_argument("--f-max", type=positive_float,
                        help="Fig. 10: leave out pairs above this frequency [Hz]; Fig. 9 (with "
                             "--freq-out): mark where the modes pass it. > 0 (default: none)")
    args = parser.parse_args()
    if not 0 <= args.threshold <= 1:
        parser.error("--threshold must be in [0, 1]")

    # Every output and input is checked before plotting, so that bad input writes no figure.
    check_outputs(("--out", args.out), ("--freq-out", args.freq_out))
    csv_path = os.path.join(args.mac_dir, "mac.csv")
    untracked, tracked, mac = load_mac(csv_path)
    figures = []
    mat_path = os.path.join(args.mac_dir, "mac.mat")
    global_modes, pair_mac = None, mac
    if args.freq_out:
        names = ["untracked_frequencies_hz", "tracked_frequencies_hz"]
        data = load_mat(mat_path, names + GLOBAL_NAMES)
        f_untracked = load_frequencies(mat_path, data, names[0], untracked)
        f_tracked = load_frequencies(mat_path, data, names[1], tracked)
    elif os.path.isfile(mat_path):
        data = load_mat(mat_path, GLOBAL_NAMES)
    else:
        data = {}
    if all(name in data for name in GLOBAL_NAMES):
        global_modes = (load_frequencies(mat_path, data, GLOBAL_NAMES[0], untracked) != 0,
                        load_frequencies(mat_path, data, GLOBAL_NAMES[1], tracked) != 0)
        pair_mac = load_pair_mac(mat_path, data[GLOBAL_NAMES[2]], untracked, tracked)
    band = (f_untracked, f_tracked) if args.freq_out else None
    figures.append((plot_matrix(untracked, tracked, mac, args.threshold, band, args.f_max,
                                global_modes), args.out))
    if args.freq_out:
        figures.append((plot_frequencies(untracked, tracked, f_untracked, f_tracked, pair_mac,
                                         args.threshold, args.f_max, global_modes),
                        args.freq_out))
    save(*figures)


if __name__ == "__main__":
    main()
