#!/usr/bin/python3
"""Ride-limiting speeds from `tvd ride --json`: absorbed power and peak upward acceleration
against speed.

Two panels: the vertical absorbed power [W] (log scale) and the peak upward acceleration [g]
(low-passed as the run says) at each chosen point against speed, every run of the sweep and of
the bisection; the limits (6 W, 2.5 g by default) as horizontal lines and each limit speed the
command found as a marker on its curve. Several files are drawn together, e.g. one per ISO 8608
road class:

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    for c in C D; do
      $TVD terrain --iso8608 $c --length 300 --independent-sides --out /tmp/road_$c.csv
      $TVD ride --vehicle $V --track /tmp/road_$c.csv --points crew_seat --json > /tmp/ride_$c.json
    done
    scripts/plot_ride.py --out ride.png C=/tmp/ride_C.json D=/tmp/ride_D.json

A spectral document (`tvd ride --iso8608 CLASS --json`, "method": "spectral") has the absorbed
power only: its curves are drawn dashed on the power panel, beside any time-domain file's (e.g.
C=/tmp/ride_C.json "C spectral"=/tmp/spectral_C.json); with spectral files alone the figure has
the power panel only.

Bad input (a missing or malformed file, a JSON document that is not `tvd ride --json`, a --points
name no file has) exits with status 2 and one line on stderr naming the file; no figure is
written then.
"""
import argparse

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (OUT_HELP, ArgumentParser, check_outputs, fail, json_number,
                         check_unique_labels, labelled, read_json, save)
import matplotlib.pyplot as plt

KEYS = ("points", "runs", "limits", "power_limit_w", "peak_limit_g", "peak_lowpass_hz")
# The spectral method computes no peak (a PSD gives variances): its documents lack these.
PEAK_KEYS = ("peak_limit_g", "peak_lowpass_hz")
METRICS = (("absorbed_power", "absorbed_power_w", "power_limit_w", "absorbed power [W]", "W"),
           ("peak_acceleration", "peak_up_g", "peak_limit_g", "peak upward acceleration [g]", "g"))


def load(path):
    """The ride document: (points, {point: {key: [(speed, value)]}}, {point: limits}, figures);
    a spectral document's curves and limits hold the absorbed power only."""
    doc = read_json(path)
    spectral = isinstance(doc, dict) and doc.get("method") == "spectral"
    keys = [k for k in KEYS if not (spectral and k in PEAK_KEYS)]
    metrics = METRICS[:1] if spectral else METRICS
    missing = [k for k in keys if not isinstance(doc, dict) or k not in doc]
    if missing:
        fail(f"{path}: not the output of `tvd ride --json` (no {', '.join(missing)})")
    for key in KEYS[:3]:
        if not isinstance(doc[key], list):
            fail(f"{path}: {key} is not a list")
    points = [p for p in doc["points"] if isinstance(p, str)]
    if len(points) != len(doc["points"]) or not points:
        fail(f"{path}: points is not a list of names")
    curves = {p: {m[1]: [] for m in metrics} for p in points}
    for i, run in enumerate(doc["runs"]):
        if not isinstance(run, dict) or not isinstance(run.get("points"), list):
            fail(f"{path}: runs[{i}] has no list of points")
        speed = json_number(path, f"runs[{i}].speed_kmh", run.get("speed_kmh"))
        for j, p in enumerate(run["points"]):
            name = p.get("point") if isinstance(p, dict) else None
            if name not in curves:
                fail(f"{path}: runs[{i}].points[{j}] is not one of the points")
            for _, key, *_ in metrics:
                curves[name][key].append((speed, json_number(path, f"runs[{i}].points[{j}].{key}", p.get(key))))
    limits = {}
    for i, entry in enumerate(doc["limits"]):
        name = entry.get("point") if isinstance(entry, dict) else None
        if name not in curves:
            fail(f"{path}: limits[{i}] is not one of the points")
        limits[name] = {}
        for kind, *_ in metrics:
            limit = entry.get(kind)
            if not isinstance(limit, dict) or limit.get("status") not in (
                    "reached", "at_lowest_speed", "not_reached"):
                fail(f"{path}: limits[{i}].{kind} has no status")
            # A speed only where the limit is crossed (null for at_lowest_speed, not_reached).
            limits[name][kind] = (limit["status"], json_number(
                path, f"limits[{i}].{kind}.speed_kmh", limit.get("speed_kmh"))
                if limit["status"] == "reached" else None)
    figures = {k: json_number(path, k, doc[k]) for k in keys[3:]}
    road = doc.get("road")
    figures["track"] = str(doc.get("track", road.get("name", "") if isinstance(road, dict) else ""))
    figures["spectral"] = spectral
    return points, curves, limits, figures


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("--points", help="comma-separated points to draw (default: every point "
                                         "of every file)")
    parser.add_argument("files", nargs="+", type=labelled, metavar="[LABEL=]FILE.json",
                        help="outputs of `tvd ride --json`, drawn together")
    args = parser.parse_args()
    check_unique_labels(args.files)
    check_outputs(("--out", args.out))
    wanted = None if args.points is None else args.points.split(",")

    runs = [(label, *load(path)) for label, path in args.files]
    if wanted is not None:
        for name in wanted:
            if not any(name in points for _, points, *_ in runs):
                fail(f"--points: no file has the point '{name}'")

    # The peak panel only when a time-domain file has peaks to draw.
    timed = [figures for *_, figures in runs if not figures["spectral"]]
    panels = METRICS if timed else METRICS[:1]
    fig, axes = plt.subplots(len(panels), 1, figsize=(11, 4 + 4 * (len(panels) - 1)), sharex=True,
                             squeeze=False)
    axes = axes[:, 0]
    k = 0
    for label, points, curves, limits, figures in runs:
        style = "--" if figures["spectral"] else "-"
        for point in points:
            if wanted is not None and point not in wanted:
                continue
            color = f"C{k % 10}"
            k += 1
            for ax, (kind, key, limit_key, _, unit) in zip(axes, panels):
                if key not in curves[point]:
                    continue  # a spectral file on the peak panel
                curve = sorted(curves[point][key])
                ax.plot([c[0] for c in curve], [c[1] for c in curve], "." + style, ms=4, lw=1,
                        color=color, label=f"{label}: {point}")
                status, speed = limits[point][kind]
                if status == "reached":
                    ax.plot([speed], [figures[limit_key]], "o", ms=9, mfc="none", mew=2, color=color,
                            label=f"{label}: {point}, {figures[limit_key]:g} {unit} at {speed:.1f} km/h")
    first = runs[0][4]
    for ax, (_, _, limit_key, ylabel, unit) in zip(axes, panels):
        source = first if limit_key in first else timed[0]
        ax.axhline(source[limit_key], color="k", ls="--", lw=1, label=f"limit {source[limit_key]:g} {unit}")
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    axes[0].set_yscale("log")
    # Every file's road, once each, in the order given (a track and a spectral road drawn
    # together are both named).
    tracks = list(dict.fromkeys(r[4]["track"] for r in runs if r[4]["track"]))
    axes[0].set_title("ride limits: vertical absorbed power" + (f" on {' and '.join(tracks)}" if tracks else ""))
    if timed:
        axes[1].set_title(f"peak upward acceleration ({timed[0]['peak_lowpass_hz']:g} Hz low-pass)"
                          if timed[0]["peak_lowpass_hz"] > 0 else "peak upward acceleration (unfiltered)")
    axes[-1].set_xlabel("speed [km/h]")
    save((fig, args.out))


if __name__ == "__main__":
    main()
