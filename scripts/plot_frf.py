#!/usr/bin/python3
"""Comfort FRF magnitudes, like Figs. 13-16 of Dimauro et al. (2024).

Fig. 13: full vs CMS-reduced model; Fig. 14: un-tracked vs tracked; Figs. 15-16: synchronous vs
wheelbase-delayed excitation at several speeds. Each LABEL=FILE becomes one line per panel.

Input: files written by `tvd frf --out FILE.csv` (header by name, any column order) or
`--out FILE.mat` (one n x 1 variable per column, same names; the char variables are ignored):
    frequency_hz, then for N in hull_vertical_acc, hull_pitch_acc, front_wheel_acc, rear_wheel_acc
    the columns N_mag [(m/s^2)/m; pitch (rad/s^2)/m] and N_phase_deg (not plotted); with
    `tvd frf --points P`, also P_vertical_acc_mag, _phase_deg and _wk_mag (ISO 2631-1
    Wk-weighted), drawn in a panel of their own after the others, the weighted one thinner.
One legend, in a row under the panels, names the files (and the band line). Outputs absent from
every file get no panel; an output that is zero in every file is drawn on a
linear scale (log scale otherwise, down to 3 decades below its peak) and its panel says so. For
example

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD frf --vehicle $V --variant tracked --model full --out /tmp/full.csv
    $TVD frf --vehicle $V --variant tracked --out /tmp/reduced.csv
    scripts/plot_frf.py --out fig13.png full=/tmp/full.csv reduced=/tmp/reduced.csv
    $TVD frf --vehicle $V --variant untracked --out /tmp/uv.csv
    scripts/plot_frf.py --out fig14.png untracked=/tmp/uv.csv tracked=/tmp/reduced.csv
    $TVD frf --vehicle $V --variant tracked --speed-kmh 30 --out /tmp/v30.mat
    scripts/plot_frf.py --out fig15.pdf synchronous=/tmp/reduced.csv "30 km/h=/tmp/v30.mat"

The figure type follows the extension of --out (.png, .pdf, .svg, ...). Bad input (missing or
corrupt file, missing or repeated column, ragged row, non-numeric value or negative magnitude, an
option that is not a finite number > 0, an output that cannot be written) exits with status 2 and
one line on stderr naming the file; no figure is written then.
"""
import argparse
import math

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (LABELLED_HELP, OUT_HELP, ArgumentParser, Table, check_outputs, fail,
                         check_unique_labels, labelled, positive_float, save)
import matplotlib.pyplot as plt
import numpy as np


# Output name -> (panel title, y label).
OUTPUTS = {
    "hull_vertical_acc": ("hull vertical acceleration", r"$|\ddot z_s / h|$ [(m/s$^2$)/m]"),
    "hull_pitch_acc": ("hull pitch acceleration", r"$|\ddot\theta_s / h|$ [(rad/s$^2$)/m]"),
    "front_wheel_acc": ("front-left road wheel acceleration",
                        r"$|\ddot z_{u,F} / h|$ [(m/s$^2$)/m]"),
    "rear_wheel_acc": ("rear-left road wheel acceleration",
                       r"$|\ddot z_{u,R} / h|$ [(m/s$^2$)/m]"),
}
# Decades of magnitude drawn below the largest value of a panel (log scale).
DECADES_SHOWN = 3
# The legend row under the panels: its height [in] and at most this many entries side by side.
LEGEND_ROW_INCHES = 0.6
LEGEND_COLUMNS = 5
LINE_STYLES = ["-", "--", ":", (0, (5, 1, 1, 1))]  # "-." is the band line
POINT_SUFFIX = "_vertical_acc"  # `tvd frf --points`: <point>_vertical_acc_mag, ..._wk_mag


def is_point(name):
    return name not in OUTPUTS and name.endswith(POINT_SUFFIX) and len(name) > len(POINT_SUFFIX)


def panel(name):
    """(title, y label) of an output's panel."""
    if name in OUTPUTS:
        return OUTPUTS[name]
    return (f"{name[:-len(POINT_SUFFIX)]} vertical acceleration (thin: Wk-weighted)",
            r"$|\ddot z_p / h|$ [(m/s$^2$)/m]")


def load(path):
    """frequency_hz, {output: magnitude} and {point output: Wk-weighted magnitude} of one FRF
    file."""
    table = Table(path)
    frequency = table.column("frequency_hz")
    present = [n for n in OUTPUTS if n + "_mag" in table.header or n + "_phase_deg" in table.header]
    present += [c[:-len("_mag")] for c in table.header
                if c.endswith("_mag") and not c.endswith("_wk_mag") and is_point(c[:-len("_mag")])]
    if not present:
        fail(f"{path}: no FRF column (expected e.g. 'hull_vertical_acc_mag')")
    magnitudes, weighted = {}, {}
    for name in present:
        for suffix, into in (("_mag", magnitudes), ("_wk_mag", weighted)):
            if suffix == "_wk_mag" and name + suffix not in table.header:
                continue
            values = table.column(name + suffix)
            if np.any(values < 0):
                k = int(np.argmax(values < 0))
                fail(f"{path}: {table.where(k)}, column '{name}{suffix}': {values[k]:g} is "
                     f"negative (a magnitude)")
            into[name] = values
    return frequency, magnitudes, weighted


def output_list(text):
    """argparse type: comma-separated output names, each one of OUTPUTS or a point's
    <point>_vertical_acc, none twice."""
    names = [n.strip() for n in text.split(",")]
    for n in names:
        if n not in OUTPUTS and not is_point(n):
            raise argparse.ArgumentTypeError(f"'{n}' is not an output ({', '.join(OUTPUTS)}, "
                                             f"<point>{POINT_SUFFIX})")
    if len(set(names)) != len(names):
        raise argparse.ArgumentTypeError(f"'{text}' names an output twice")
    return names


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("--title", default="", help="figure title")
    parser.add_argument("--band-hz", type=positive_float, default=30.0,
                        help="CMS truncation band, drawn dash-dot [Hz], > 0 (default 30)")
    parser.add_argument("--f-max", type=positive_float, default=50.0,
                        help="x axis limit [Hz], > 0 (default 50)")
    parser.add_argument("--outputs", type=output_list, default=None,
                        metavar="NAME[,NAME...]",
                        help="panels to draw, in this order (default: every output present): "
                             + ", ".join(OUTPUTS) + ", <point>" + POINT_SUFFIX + " (tvd frf "
                             "--points); e.g. hull_vertical_acc for Fig. 15, "
                             "front_wheel_acc,rear_wheel_acc for Fig. 16")
    parser.add_argument("files", nargs="+", type=labelled, metavar="[LABEL=]FILE",
                        help=LABELLED_HELP)
    args = parser.parse_args()
    check_unique_labels(args.files)

    check_outputs(("--out", args.out))  # before reading: bad input writes no figure
    curves = [(label, *load(path)) for label, path in args.files]
    if args.outputs is None:  # every output of any file: the paper's, then the points
        points = [n for _, _, outputs, _ in curves for n in outputs if is_point(n)]
        args.outputs = list(OUTPUTS) + list(dict.fromkeys(points))
    present = [n for n in args.outputs if any(n in outputs for _, _, outputs, _ in curves)]
    if not present:
        fail(f"--outputs {','.join(args.outputs)}: none of these is in any file")
    ncols = 1 if len(present) == 1 else 2
    nrows = math.ceil(len(present) / ncols)
    # One legend for every panel, in a row of its own under them: the lines are the same files
    # in every panel, and a legend inside a panel covers part of its curves (the notches of the
    # wheelbase filter reach every corner).
    fig = plt.figure(figsize=(6 * ncols, 4 * nrows + LEGEND_ROW_INCHES))
    grid = fig.add_gridspec(nrows + 1, ncols, height_ratios=[4.0] * nrows + [LEGEND_ROW_INCHES])
    axes = np.array([[fig.add_subplot(grid[r, c]) for c in range(ncols)] for r in range(nrows)])
    for ax in axes.flat[len(present):]:
        ax.set_visible(False)
    for ax, name in zip(axes.flat, present):
        for k, (label, frequency, outputs, weighted) in enumerate(curves):
            style = LINE_STYLES[k % len(LINE_STYLES)]
            if name in outputs:
                line, = ax.plot(frequency, outputs[name], linestyle=style, label=label)
            if name in weighted:
                ax.plot(frequency, weighted[name], linestyle=style, color=line.get_color(),
                        linewidth=0.8, label=label + ", Wk")
        ax.axvline(args.band_hz, color="k", linestyle="-.", linewidth=1,
                   label=f"{args.band_hz:g} Hz band")
        peak = max(outputs[name].max() for _, _, outputs, _ in curves if name in outputs)
        if peak > 0:
            ax.set_yscale("log")
            # An acceleration FRF falls as f^2 towards 0 Hz and the wheelbase filter's notches
            # reach ~0: DECADES_SHOWN below the peak keep the resonances readable.
            ax.set_ylim(bottom=max(ax.get_ylim()[0], 10.0 ** -DECADES_SHOWN * peak))
        else:  # nothing to draw on a log scale
            ax.set_ylim(-0.05, 1)
        ax.set_xlim(0, args.f_max)
        ax.set_title(panel(name)[0] + ("" if peak > 0 else " (zero in every file)"))
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylabel(panel(name)[1])
        ax.grid(True, which="both", alpha=0.3)
    entries = {}  # label -> handle, in the order the panels first draw them
    for ax in axes.flat[:len(present)]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            entries.setdefault(label, handle)
    legend_row = fig.add_subplot(grid[nrows, :])
    legend_row.axis("off")
    legend_row.legend(entries.values(), entries.keys(), loc="center", fontsize="small",
                      ncol=min(len(entries), LEGEND_COLUMNS), frameon=False)
    if args.title:
        fig.suptitle(args.title)
    save((fig, args.out))


if __name__ == "__main__":
    main()
