#!/usr/bin/python3
"""Comfort FRF magnitudes, like Figs. 13-16 of Dimauro et al. (2024).

Fig. 13: full vs CMS-reduced model; Fig. 14: un-tracked vs tracked; Figs. 15-16: synchronous vs
wheelbase-delayed excitation at several speeds. Each LABEL=FILE.csv becomes one line per panel.

Input: CSV files written by `tvd frf` (header by name, any column order):
    frequency_hz, then for N in hull_vertical_acc, hull_pitch_acc, front_wheel_acc, rear_wheel_acc
    the columns N_mag [(m/s^2)/m; pitch (rad/s^2)/m] and N_phase_deg (not plotted).
Outputs absent from every file get no panel. `tvd frf` is not written yet; its options below are
assumed to mirror `tvd simulate`:

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD frf --vehicle $V --variant untracked --out /tmp/uv.csv
    $TVD frf --vehicle $V --variant tracked --out /tmp/tv.csv
    scripts/plot_frf.py --out fig14.png untracked=/tmp/uv.csv tracked=/tmp/tv.csv

Bad input (missing file, missing column, non-numeric value) exits with status 2 and one line on
stderr naming the file.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# Output name -> (panel title, y label).
OUTPUTS = {
    "hull_vertical_acc": ("hull vertical acceleration", r"$|\ddot z_s / h|$ [(m/s$^2$)/m]"),
    "hull_pitch_acc": ("hull pitch acceleration", r"$|\ddot\theta_s / h|$ [(rad/s$^2$)/m]"),
    "front_wheel_acc": ("front road wheel acceleration", r"$|\ddot z_{u,F} / h|$ [(m/s$^2$)/m]"),
    "rear_wheel_acc": ("rear road wheel acceleration", r"$|\ddot z_{u,R} / h|$ [(m/s$^2$)/m]"),
}
LINE_STYLES = ["-", "--", ":", (0, (5, 1, 1, 1))]  # "-." is the band line


def fail(message):
    """One error line on stderr, exit status 2 (bad input)."""
    sys.stderr.write(f"{os.path.basename(sys.argv[0])}: error: {message}\n")
    sys.exit(2)


def read_csv(path):
    """Header and data rows of a CSV file; fails on a missing, unreadable or empty file."""
    try:
        with open(path, newline="") as stream:
            rows = [row for row in csv.reader(stream) if row]
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        fail(f"{path}: cannot read CSV ({getattr(error, 'strerror', None) or error})")
    if len(rows) < 2:
        fail(f"{path}: no data rows")
    return [name.strip() for name in rows[0]], rows[1:]


def column(path, header, rows, name):
    """The column called `name` as a float array; fails if it is missing or not finite numbers."""
    if name not in header:
        fail(f"{path}: missing column '{name}'")
    j = header.index(name)
    values = []
    for line, row in enumerate(rows, start=2):
        text = row[j].strip() if j < len(row) else ""
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            fail(f"{path}: line {line}, column '{name}': '{text}' is not a finite number")
        values.append(value)
    return np.array(values)


def load(path):
    """frequency_hz and {output: magnitude} of one FRF file."""
    header, rows = read_csv(path)
    frequency = column(path, header, rows, "frequency_hz")
    present = [n for n in OUTPUTS if n + "_mag" in header or n + "_phase_deg" in header]
    if not present:
        fail(f"{path}: no FRF column (expected e.g. 'hull_vertical_acc_mag')")
    return frequency, {n: column(path, header, rows, n + "_mag") for n in present}


def labelled(text):
    label, sep, path = text.partition("=")
    return (label, path) if sep else (os.path.splitext(os.path.basename(text))[0], text)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="PNG file to write")
    parser.add_argument("--title", default="", help="figure title")
    parser.add_argument("--band-hz", type=float, default=30.0,
                        help="CMS truncation band, drawn dash-dot [Hz] (default 30)")
    parser.add_argument("--f-max", type=float, default=50.0, help="x axis limit [Hz] (default 50)")
    parser.add_argument("files", nargs="+", type=labelled, metavar="LABEL=FILE.csv",
                        help="one line per file, named LABEL in the legend")
    args = parser.parse_args()

    curves = [(label, *load(path)) for label, path in args.files]
    present = [n for n in OUTPUTS if any(n in outputs for _, _, outputs in curves)]
    ncols = 1 if len(present) == 1 else 2
    nrows = math.ceil(len(present) / ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(6 * ncols, 4 * nrows), squeeze=False)
    for ax in axes.flat[len(present):]:
        ax.set_visible(False)
    for ax, name in zip(axes.flat, present):
        for k, (label, frequency, outputs) in enumerate(curves):
            if name in outputs:
                ax.plot(frequency, outputs[name], linestyle=LINE_STYLES[k % len(LINE_STYLES)],
                        label=label)
        ax.axvline(args.band_hz, color="k", linestyle="-.", linewidth=1,
                   label=f"{args.band_hz:g} Hz band")
        ax.set_yscale("log")
        # Wheelbase-filter notches reach ~0: show 6 decades below the peak, not down to 1e-13.
        peak = max(outputs[name].max() for _, _, outputs in curves if name in outputs)
        ax.set_ylim(bottom=max(ax.get_ylim()[0], 1e-6 * peak))
        ax.set_xlim(0, args.f_max)
        ax.set_title(OUTPUTS[name][0])
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylabel(OUTPUTS[name][1])
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    try:
        fig.savefig(args.out, dpi=150, format="png")
    except OSError as error:
        fail(f"{args.out}: cannot write PNG ({error.strerror or error})")
    print(args.out)


if __name__ == "__main__":
    main()
