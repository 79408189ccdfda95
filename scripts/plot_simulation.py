#!/usr/bin/python3
"""Time response over a track, like Figs. 18-24 of Dimauro et al. (2024).

Panels: hull heave [m], hull vertical acceleration [m/s^2], pitch [deg], roll [deg] (only if a file
has hull_roll_deg), front-left and rear-left road wheel displacement [m], and front-right and
rear-right ones where a run's right wheels move otherwise than its left (by more than 1e-6 m: the
out-of-phase waves, Fig. 22; on a track uniform across its width they are the left ones again);
x is station [m] or time [s]. Each LABEL=FILE becomes one line per panel, e.g. full/reduced
(Figs. 18-19), untracked/tracked (Figs. 20-22) or 5 km/h / 50 km/h (Figs. 23-24). Input is what
`tvd simulate --out` writes, CSV or .mat (one n x 1 variable per column, same names; the char
variables are ignored):

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD simulate --vehicle $V --variant untracked --track long_hill --speed-kmh 30 --out /tmp/u.csv
    $TVD simulate --vehicle $V --variant tracked --track long_hill --speed-kmh 30 --out /tmp/t.csv
    scripts/plot_simulation.py --out fig20.png untracked=/tmp/u.csv tracked=/tmp/t.csv

Columns are found by header name: time_s, station_m, hull_heave_m, hull_vertical_accel_m_s2,
hull_pitch_deg, [hull_roll_deg], road_wheel_left_<k>_m (k = 1 is the front wheel, the largest k the
rear one), [road_wheel_right_<k>_m], and with --point NAME, NAME_accel_z_m_s2 (e.g. --point
crew_seat). Where a file has road_under_road_wheel_<side>_<k>_m, the road under the wheel is drawn
grey and dashed in its panel (the paper's dashed h_F and h_R; once where the runs' roads are the
same, dotted for a second road). One legend, in the first panel, names the runs; a roll panel that
stays below 0.001 deg in every run says so. The figure type follows the extension of --out (.png,
.pdf, .svg, ...).

--layout paper draws the paper's three graphs instead (Figs. 18-24): the displacements (the hull's
m_s black, the front and rear wheels' m_u,F orange and m_u,R cyan, the roads under them h_F red
and h_R blue, dashed), the hull's vertical acceleration, and its roll and pitch; each run keeps
one line style throughout. The right wheels and --point panels are the panel layout's only.

Bad input (missing or corrupt file, missing or repeated column, ragged row, non-numeric value, an
output that cannot be written) exits with status 2 and one line on stderr naming the file; no
figure is written then.
"""
import argparse
import math
import re

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (LABELLED_HELP, OUT_HELP, ArgumentParser, Table, check_outputs,
                         check_unique_labels, fail, labelled, save)
import matplotlib.pyplot as plt
from matplotlib.lines import Line2D
import numpy as np


# The station is that of the vehicle's reference point, the wheelbase centre (the front wheel
# meets a feature 3 axle spacings earlier).
X_AXES = {"station": ("station_m", "station of the wheelbase centre [m]"),
          "time": ("time_s", "time [s]")}
# Smallest y range drawn per panel: a symmetric track leaves roll at round-off (1e-7 deg), which
# an autoscaled axis would blow up into what looks like a signal.
MIN_SPAN = {"hull_roll_deg": 0.02, "hull_pitch_deg": 0.02}
# Panel key -> y label; the wheel panels' columns depend on the wheel count.
PANELS = {
    "hull_heave_m": "hull heave [m]",
    "hull_vertical_accel_m_s2": "hull vertical acceleration [m/s$^2$]",
    "hull_pitch_deg": "hull pitch [deg, nose down +]",
    "hull_roll_deg": "hull roll [deg, left up +]",
    "front_left_wheel": "front-left road wheel [m]",
    "rear_left_wheel": "rear-left road wheel [m]",
    "front_right_wheel": "front-right road wheel [m]",
    "rear_right_wheel": "rear-right road wheel [m]",
}
# Right wheels moving within this of the left ones in every run are not drawn again [m].
SAME_SIDES_M = 1e-6
LINE_STYLES = ["-", "--", "-.", ":"]
# The roads under the wheels, grey: dashed as the paper draws h_F and h_R, then dotted, ...
ROAD_STYLES = ["--", ":", "-."]
# Roll below this in every run is no signal: a track uniform across its width does not excite it.
NEGLIGIBLE_ROLL_DEG = 1e-3
# The paper's colours (§4.2.2: black m_s, orange and cyan m_u,F and m_u,R, red and blue dashed
# h_F and h_R; roll and pitch in the last graph).
PAPER_COLOURS = {"hull_heave_m": "black", "front_left_wheel": "tab:orange",
                 "rear_left_wheel": "tab:cyan", "front_left_wheel/road": "tab:red",
                 "rear_left_wheel/road": "tab:blue", "hull_vertical_accel_m_s2": "black",
                 "hull_roll_deg": "tab:green", "hull_pitch_deg": "tab:purple"}
PAPER_NAMES = {"hull_heave_m": "$m_s$", "front_left_wheel": "$m_{u,F}$",
               "rear_left_wheel": "$m_{u,R}$", "front_left_wheel/road": "$h_F$",
               "rear_left_wheel/road": "$h_R$", "hull_roll_deg": r"$\varphi$ (roll)",
               "hull_pitch_deg": r"$\theta$ (pitch)"}


def load(path, x_column, points=()):
    """x values and {panel key: values} of one simulation file; `points`: named points whose
    vertical acceleration gets a panel (column <point>_accel_z_m_s2)."""
    table = Table(path)
    header = table.header
    wheel = re.compile(r"road_wheel_left_(\d+)_m")
    rear = max((int(m.group(1)) for m in map(wheel.fullmatch, header) if m), default=1)
    columns = {key: key for key in PANELS if key.startswith("hull_")}
    columns["front_left_wheel"] = "road_wheel_left_1_m"
    columns["rear_left_wheel"] = f"road_wheel_left_{rear}_m"
    for end, wheel in (("front", 1), ("rear", rear)):
        if f"road_wheel_right_{wheel}_m" in header:
            columns[f"{end}_right_wheel"] = f"road_wheel_right_{wheel}_m"
    if "hull_roll_deg" not in header:  # older files
        del columns["hull_roll_deg"]
    for point in points:
        columns[point_panel(point)] = f"{point}_accel_z_m_s2"
    # The road under each wheel (newer files), drawn dashed under its wheel like the paper's h_F
    # and h_R.
    for key in [k for k in columns if k.endswith("_wheel")]:
        if f"road_under_{columns[key]}" in header:
            columns[road_panel(key)] = f"road_under_{columns[key]}"
    x = table.column(x_column)
    return x, {key: table.column(name) for key, name in columns.items()}


def drop_right_wheels_like_left(runs):
    """Removes the right-wheel panels (and their roads) from every run when in each run the right
    wheels follow the left ones within SAME_SIDES_M: a track uniform across its width."""
    def same(series):
        return all(np.max(np.abs(series[f"{end}_right_wheel"] - series[f"{end}_left_wheel"]),
                          initial=0.0) <= SAME_SIDES_M
                   for end in ("front", "rear") if f"{end}_right_wheel" in series)
    if all(same(series) for _, _, series in runs):
        for _, _, series in runs:
            for key in [k for k in series if "_right_wheel" in k]:
                del series[key]


def road_panel(key):
    return f"{key}/road"


def point_panel(point):
    return f"{point}_accel_z_m_s2"


def paper_figure(runs, x_label):
    """The paper's three graphs: displacements with the roads, vertical acceleration, roll and
    pitch. A road common to every run is drawn once."""
    fig, axes = plt.subplots(3, 1, figsize=(10, 10), sharex=True)
    several = len(runs) > 1

    def name(key, label):
        return PAPER_NAMES.get(key, "") + (f" ({label})" if several else "")

    for k, (label, x, series) in enumerate(runs):
        style = LINE_STYLES[k % len(LINE_STYLES)]
        for key in ("hull_heave_m", "front_left_wheel", "rear_left_wheel"):
            axes[0].plot(x, series[key], color=PAPER_COLOURS[key], linestyle=style,
                         label=name(key, label))
        axes[1].plot(x, series["hull_vertical_accel_m_s2"], color="black", linestyle=style,
                     label=label if several else None)
        for key in ("hull_roll_deg", "hull_pitch_deg"):
            if key in series:
                axes[2].plot(x, series[key], color=PAPER_COLOURS[key], linestyle=style,
                             label=name(key, label))
    for key in ("front_left_wheel/road", "rear_left_wheel/road"):
        drawn = []
        for label, x, series in runs:
            road = series.get(key)
            if road is None or any(np.array_equal(x, dx) and np.array_equal(road, d)
                                   for dx, d in drawn):
                continue
            drawn.append((x, road))
            common = all(np.array_equal(road, other.get(key, road)) for _, _, other in runs)
            axes[0].plot(x, road, color=PAPER_COLOURS[key], linestyle="--", linewidth=0.9,
                         label=PAPER_NAMES[key] + ("" if common or not several else f" ({label})"))
    axes[0].set_ylabel("vertical displacement [m]")
    axes[1].set_ylabel("hull vertical acceleration [m/s$^2$]")
    axes[2].set_ylabel("angle [deg; pitch nose down +, roll left up +]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize="small", ncol=2 if several else 1)
    axes[2].set_xlabel(x_label)
    return fig


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("--title", default="", help="figure title")
    parser.add_argument("--x", choices=X_AXES, default="station", help="x axis (default station)")
    parser.add_argument("--layout", choices=("panels", "paper"), default="panels",
                        help="panels: one quantity a panel (default); paper: the paper's three "
                             "graphs of Figs. 18-24")
    parser.add_argument("--point", action="append", default=[], metavar="NAME",
                        help="add a panel of this named point's vertical acceleration (column "
                             "NAME_accel_z_m_s2, e.g. crew_seat); repeatable")
    parser.add_argument("files", nargs="+", type=labelled, metavar="[LABEL=]FILE",
                        help=LABELLED_HELP)
    args = parser.parse_args()
    check_unique_labels(args.files)

    if args.layout == "paper" and args.point:
        fail("--point applies to --layout panels; the paper's layout has no point panels")
    check_outputs(("--out", args.out))  # before reading: bad input writes no figure

    x_column, x_label = X_AXES[args.x]
    runs = [(label, *load(path, x_column, args.point)) for label, path in args.files]
    drop_right_wheels_like_left(runs)
    if args.layout == "paper":
        fig = paper_figure(runs, x_label)
        if args.title:
            fig.suptitle(args.title)
        save((fig, args.out))
        return
    labels = dict(PANELS)
    for point in args.point:
        labels[point_panel(point)] = f"{point} vertical acceleration [m/s$^2$]"
    present = [key for key in labels if any(key in series for _, _, series in runs)]
    nrows = math.ceil(len(present) / 2)
    fig, axes = plt.subplots(nrows, 2, figsize=(12, 3.2 * nrows), sharex=True, squeeze=False)
    for ax in axes.flat[len(present):]:
        ax.set_visible(False)
    road_drawn = False
    for ax, key in zip(axes.flat, present):
        roads = []  # the road lines drawn in this panel: the same road of several runs once
        for k, (label, x, series) in enumerate(runs):
            if key in series:
                ax.plot(x, series[key], linestyle=LINE_STYLES[k % len(LINE_STYLES)], label=label)
            road = series.get(road_panel(key))
            if road is not None and not any(np.array_equal(x, rx) and np.array_equal(road, r)
                                            for rx, r in roads):
                roads.append((x, road))
                ax.plot(x, road, color="grey", linewidth=0.9,
                        linestyle=ROAD_STYLES[(len(roads) - 1) % len(ROAD_STYLES)])
                road_drawn = True
        ax.set_ylabel(labels[key])
        low, high = ax.get_ylim()
        if key in MIN_SPAN and high - low < MIN_SPAN[key]:
            centre = 0.5 * (low + high)
            ax.set_ylim(centre - 0.5 * MIN_SPAN[key], centre + 0.5 * MIN_SPAN[key])
        if key == "hull_roll_deg" and all(
                np.max(np.abs(series[key])) < NEGLIGIBLE_ROLL_DEG for _, _, series in runs
                if key in series):
            ax.text(0.5, 0.5, f"|roll| < {NEGLIGIBLE_ROLL_DEG:g}° in every run:\n"
                    "no lateral excitation", transform=ax.transAxes, ha="center", va="center",
                    color="0.3", bbox={"facecolor": "white", "edgecolor": "none"})
            # The line high in the panel, the note clear of it.
            ax.set_ylim(-1.5 * MIN_SPAN[key], 0.5 * MIN_SPAN[key])
        ax.set_xlabel(x_label)
        ax.xaxis.set_tick_params(labelbottom=True)
        ax.grid(True, alpha=0.3)
    # One legend, in the first panel (the runs' line styles are the same in every panel), so
    # that none covers the wheel panels' peaks; the road under the wheels is grey.
    handles, names = axes.flat[0].get_legend_handles_labels()
    if road_drawn:
        handles.append(Line2D([], [], color="grey", linewidth=0.9, linestyle=ROAD_STYLES[0]))
        names.append("road under the wheel")
    if handles:
        axes.flat[0].legend(handles, names, fontsize="small")
    if args.title:
        fig.suptitle(args.title)
    save((fig, args.out))


if __name__ == "__main__":
    main()
