#!/usr/bin/python3
"""The road profiles under the pad rows of a vehicle, like Fig. 17 of Dimauro et al. (2024).

A terrain file (what `tvd terrain --out` writes: CSV or YAML, doc in the README) is read along
the four pad rows of the vehicle: p_LO, p_LI, p_RI, p_RO (left/right, outer/inner), at
y = +-(b/2 +- e) + lateral offset, with b the track centre distance and e the pads' lateral offset
(`running_gear.track_centre_distance`, `track_assembly.pad_lateral_offset` of the description),
between the file's lateral lines linearly and held beyond the outermost, as `tvd simulate` reads
it. Left panel: the whole track; right panel: a detail (--detail X0:X1, default 2 m from where
the profiles first leave their starting height).

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD terrain --track oop_waves --out /tmp/oop.csv
    scripts/plot_terrain.py --vehicle $V --out fig17c.png /tmp/oop.csv

--profiles-out FILE.csv also writes the four profiles (station_m, then one column per row). The
built-in tracks are written in the path frame (the OOP track includes the paper's 1 m offset), so
--lateral-offset is 0 for them, as for `tvd simulate`. Bad input exits with status 2 and one line
on stderr naming the file; no figure is written then.
"""
import argparse
import csv
import math
import os

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import OUT_HELP, ArgumentParser, check_outputs, fail, reason, save, to_float
import matplotlib.pyplot as plt
import numpy as np
import yaml

ROW_STYLES = {"LO": ("tab:red", "-"), "LI": ("tab:orange", "--"), "RI": ("tab:cyan", "--"),
              "RO": ("tab:blue", "-")}


def read_terrain(path):
    """(stations [n], lateral lines y [m] or None for a uniform profile, heights [lines x n])."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in (".csv", ".yaml", ".yml"):
        fail(f"{path}: a terrain file is .csv, .yaml or .yml")
    if os.path.isdir(path):
        fail(f"{path}: cannot read the terrain (it is a directory)")
    try:
        if extension == ".csv":
            return read_terrain_csv(path)
        return read_terrain_yaml(path)
    except (OSError, UnicodeDecodeError, csv.Error, yaml.YAMLError) as error:
        fail(f"{path}: cannot read the terrain ({reason(error)})")


def read_terrain_csv(path):
    # utf-8-sig: a byte-order mark is not part of the first cell (as tvd reads it).
    with open(path, newline="", encoding="utf-8-sig") as f:
        rows = [(n, [c.strip() for c in row]) for n, row in enumerate(csv.reader(f), start=1)
                if row and not row[0].lstrip().startswith("#")]
    if not rows:
        fail(f"{path}: no terrain rows")
    header_line, header = rows[0]
    lateral = None
    if not is_number(header[0]):
        cells = header[1:]
        if len(cells) > 1 or (cells and is_number(cells[0])):
            lateral = np.array([number(path, header_line, c, "lateral position") for c in cells])
        rows = rows[1:]
    width = len(lateral) + 1 if lateral is not None else 2
    data = []
    for line, row in rows:
        if len(row) != width:
            fail(f"{path}: row {line}: {len(row)} values, expected {width}")
        data.append([number(path, line, c, "value") for c in row])
    if len(data) < 2:
        fail(f"{path}: a terrain needs at least two stations")
    data = np.array(data)
    return data[:, 0], lateral, data[:, 1:].T


def numbers(path, doc, key, ndim):
    """doc[key] as a float array of `ndim` dimensions, or one error line naming the key."""
    try:
        value = np.array(doc[key], dtype=float)
    except (TypeError, ValueError) as error:
        fail(f"{path}: {key}: not a list of numbers ({reason(error)})")
    if value.ndim != ndim:
        shape = {1: "a list of numbers", 2: "a list of lists of numbers (one per y)"}[ndim]
        fail(f"{path}: {key}: expected {shape}")
    if not np.all(np.isfinite(value)):
        fail(f"{path}: {key}: every value must be a finite number")
    return value


def read_terrain_yaml(path):
    with open(path, encoding="utf-8-sig") as f:
        doc = yaml.safe_load(f)
    if not isinstance(doc, dict) or "heights" not in doc:
        fail(f"{path}: expected a map with 'heights'")
    lateral = numbers(path, doc, "y", 1) if "y" in doc else None
    heights = numbers(path, doc, "heights", 1 if lateral is None else 2)
    if lateral is None:
        heights = heights[np.newaxis, :]
    elif len(heights) != len(lateral):
        fail(f"{path}: heights: {len(heights)} lists for {len(lateral)} lateral lines (y)")
    if ("x" in doc) == ("spacing" in doc):
        fail(f"{path}: give exactly one of 'x' (the stations) and 'spacing'")
    if "x" in doc:
        stations = numbers(path, doc, "x", 1)
    else:
        spacing = numbers(path, doc, "spacing", 0)
        start = numbers(path, doc, "start", 0) if "start" in doc else 0.0
        if not spacing > 0:
            fail(f"{path}: spacing: must be > 0")
        stations = start + spacing * np.arange(heights.shape[1])
    if heights.shape[1] != len(stations):
        fail(f"{path}: heights: {heights.shape[1]} per line for {len(stations)} stations")
    if len(stations) < 2:
        fail(f"{path}: a terrain needs at least two stations")
    return stations, lateral, heights


def is_number(text):
    return not math.isnan(to_float(text))


def number(path, line, text, what):
    value = to_float(text)
    if not math.isfinite(value):
        fail(f"{path}: row {line}: {what} '{text.strip()}' is not a finite number")
    return value


def check_increasing(path, values, what):
    if np.any(np.diff(values) <= 0):
        fail(f"{path}: {what} must be strictly increasing")


def profile(stations, lateral, heights, y):
    """Heights along the line at y: linear between the file's lines, the edge line beyond."""
    if lateral is None or len(lateral) == 1:
        return heights[0].copy()
    return np.array([np.interp(y, lateral, heights[:, i]) for i in range(len(stations))])


def pad_rows(vehicle):
    """{row name: y [m]} of the four pad rows of a vehicle description."""
    try:
        with open(vehicle) as f:
            d = yaml.safe_load(f)
        if not isinstance(d, dict):
            fail(f"{vehicle}: not a vehicle description (a YAML map of sections, e.g. "
                 f"config/vehicles/paper_vehicle.yaml)")
        entries = {"running_gear.track_centre_distance":
                   d["running_gear"]["track_centre_distance"],
                   "track_assembly.pad_lateral_offset": d["track_assembly"]["pad_lateral_offset"]}
        b, e = (float(entry["value"]) for entry in entries.values())
    except (OSError, UnicodeDecodeError, yaml.YAMLError, KeyError, TypeError,
            ValueError) as error:
        fail(f"{vehicle}: cannot read running_gear.track_centre_distance and "
             f"track_assembly.pad_lateral_offset ({reason(error)})")
    # The description's loader takes each quantity in one unit only (tvd refuses another).
    for key, entry in entries.items():
        if entry.get("unit") != "m":
            fail(f"{vehicle}: {key}: unit must be m, got {entry.get('unit')!r}")
    if not (math.isfinite(b) and math.isfinite(e) and b > 0 and e > 0):
        fail(f"{vehicle}: running_gear.track_centre_distance and "
             f"track_assembly.pad_lateral_offset must be finite and > 0")
    return {"LO": b / 2 + e, "LI": b / 2 - e, "RI": -b / 2 + e, "RO": -b / 2 - e}


def parse_detail(text):
    try:
        x0, x1 = (float(v) for v in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not X0:X1")
    if not (math.isfinite(x0) and math.isfinite(x1) and x1 > x0):
        raise argparse.ArgumentTypeError(f"'{text}': needs finite X0 < X1")
    return x0, x1


def default_detail(stations, profiles):
    """2 m from just before the profiles first leave their starting height."""
    moved = np.zeros(len(stations), dtype=bool)
    for p in profiles.values():
        moved |= np.abs(p - p[0]) > 1e-9
    start = stations[np.argmax(moved)] - 0.5 if moved.any() else stations[0]
    return start, start + 2.0


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("--vehicle", required=True, help="vehicle description YAML (pad rows)")
    parser.add_argument("--lateral-offset", type=float, default=0.0,
                        help="the vehicle centre line on the terrain's y [m] (default 0)")
    parser.add_argument("--detail", type=parse_detail, metavar="X0:X1",
                        help="stations of the detail panel [m]")
    parser.add_argument("--profiles-out", metavar="FILE.csv",
                        help="also write the four profiles as CSV")
    parser.add_argument("--title", default="", help="figure title")
    parser.add_argument("terrain", help="terrain file (.csv, .yaml, .yml)")
    args = parser.parse_args()

    check_outputs(("--out", args.out))
    if not math.isfinite(args.lateral_offset):
        fail(f"--lateral-offset {args.lateral_offset} is not finite")
    if args.profiles_out is not None:
        out = args.profiles_out
        directory = os.path.dirname(out) or "."
        if not os.path.splitext(out)[1].lower() == ".csv":
            fail(f"--profiles-out {out}: must end in .csv")
        if os.path.isdir(out):
            fail(f"--profiles-out {out}: it is a directory")
        if not os.path.isdir(directory) or not os.access(directory, os.W_OK):
            fail(f"--profiles-out {out}: directory {directory} is not writable")
        for other, what in ((args.terrain, "the terrain file"), (args.out, "--out")):
            if os.path.realpath(out) == os.path.realpath(other):
                fail(f"--profiles-out {out} is {what}: it would be overwritten")

    stations, lateral, heights = read_terrain(args.terrain)
    check_increasing(args.terrain, stations, "stations")
    if lateral is not None:
        check_increasing(args.terrain, lateral, "lateral positions")
    if not np.all(np.isfinite(heights)):
        fail(f"{args.terrain}: heights must be finite")
    rows = pad_rows(args.vehicle)
    profiles = {name: profile(stations, lateral, heights, y + args.lateral_offset)
                for name, y in rows.items()}

    detail = args.detail or default_detail(stations, profiles)
    fig, (whole, zoom) = plt.subplots(1, 2, figsize=(13, 3.8), gridspec_kw={"width_ratios": [2, 1]})
    for name, p in profiles.items():
        color, style = ROW_STYLES[name]
        label = f"$p_{{{name}}}$ (y = {rows[name] + args.lateral_offset:+.3f} m)"
        for ax in (whole, zoom):
            ax.plot(stations, p, color=color, linestyle=style, label=label)
    whole.axvspan(*detail, color="grey", alpha=0.15)
    zoom.set_xlim(*detail)
    for ax in (whole, zoom):
        ax.set_xlabel("station [m]")
        ax.set_ylabel("road height [m]")
        ax.grid(True, alpha=0.3)
    values = list(profiles.values())
    coincide = all(np.array_equal(values[0], v) for v in values[1:])
    # A track uniform across its width gives four equal lines, drawn over one another.
    whole.legend(fontsize="small", title="the four lines coincide" if coincide else None,
                 title_fontsize="small")
    fig.suptitle(args.title or os.path.basename(args.terrain))

    if args.profiles_out is not None:
        names = list(profiles)
        np.savetxt(args.profiles_out, np.column_stack([stations] + [profiles[n] for n in names]),
                   delimiter=",", fmt="%.12g", comments="",
                   header=",".join(["station_m"] + [f"p_{n}_m" for n in names]))
    save((fig, args.out))


if __name__ == "__main__":
    main()
