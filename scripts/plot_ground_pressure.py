#!/usr/bin/python3
"""Ground pressure under the track of a vehicle at rest, from `tvd statics --json`.

One panel per side: the pressure under each track assembly on the road (its vertical reaction
over width x pitch) along x, the road wheels' stations, the nominal ground pressure NGP and the
mean maximum pressure (mean of the peaks under the wheels) with Rowland's estimate of it. Several
files are drawn over each other, e.g. unilateral against bonded contacts:

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD statics --vehicle $V --json > /tmp/unilateral.json
    $TVD statics --vehicle $V --contact bilateral --json > /tmp/bilateral.json
    scripts/plot_ground_pressure.py --out ground.png unilateral=/tmp/unilateral.json \\
        bilateral=/tmp/bilateral.json

Bad input (a missing or malformed file, a JSON document that is not `tvd statics --json`) exits
with status 2 and one line on stderr naming the file; no figure is written then.
"""
import argparse

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (OUT_HELP, ArgumentParser, check_outputs, fail, json_number,
                         check_unique_labels, labelled, read_json, save)
import matplotlib.pyplot as plt

SIDES = ("left", "right")
KEYS = ("track_assemblies", "road_wheels", "nominal_ground_pressure_pa", "mean_peak_pressure_pa",
        "rowland_mean_maximum_pressure_pa")


def load(path):
    """The statics document: (assemblies per side [(x, kPa)], wheel stations per side, figures)."""
    doc = read_json(path)
    if not isinstance(doc, dict) or any(k not in doc for k in KEYS):
        missing = [k for k in KEYS if not isinstance(doc, dict) or k not in doc]
        fail(f"{path}: not the output of `tvd statics --json` (no {', '.join(missing)})")
    for key in KEYS[:2]:
        if not isinstance(doc[key], list):
            fail(f"{path}: {key} is not a list")
    assemblies = {side: [] for side in SIDES}
    for i, a in enumerate(doc["track_assemblies"]):
        if not isinstance(a, dict) or a.get("side") not in SIDES:
            fail(f"{path}: track_assemblies[{i}] has no side 'left' or 'right'")
        assemblies[a["side"]].append((json_number(path, f"track_assemblies[{i}].x_m", a.get("x_m")),
                                      json_number(path, f"track_assemblies[{i}].pressure_pa",
                                             a.get("pressure_pa")) / 1e3))
    if not any(assemblies.values()):
        fail(f"{path}: no track assembly on the ground")
    wheels = {side: [] for side in SIDES}
    for i, w in enumerate(doc["road_wheels"]):
        name = w.get("name") if isinstance(w, dict) else None
        name = name if isinstance(name, str) else ""
        side = "left" if "_left_" in name else "right" if "_right_" in name else None
        if side is None:
            fail(f"{path}: road_wheels[{i}] is not named road_wheel_<left|right>_<k>")
        wheels[side].append(json_number(path, f"road_wheels[{i}].x_m", w.get("x_m")))
    figures = {k: json_number(path, k, doc[k]) / 1e3 for k in KEYS[2:]}
    figures["contact"] = str(doc.get("contact", ""))
    return assemblies, wheels, figures


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("files", nargs="+", type=labelled, metavar="[LABEL=]FILE.json",
                        help="outputs of `tvd statics --json`, drawn over each other")
    args = parser.parse_args()
    check_unique_labels(args.files)
    check_outputs(("--out", args.out))

    runs = [(label, *load(path)) for label, path in args.files]
    fig, axes = plt.subplots(2, 1, figsize=(15, 7.5), sharex=True, sharey=True)
    for ax, side in zip(axes, SIDES):
        for k, (label, assemblies, wheels, figures) in enumerate(runs):
            color = f"C{k}"
            points = sorted(assemblies[side])
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], "o-", ms=3, lw=1,
                        color=color, label=f"{label}: per assembly")
            ax.axhline(figures["mean_peak_pressure_pa"], color=color, ls="--", lw=1,
                       label=f"{label}: mean maximum pressure "
                             f"{figures['mean_peak_pressure_pa']:.0f} kPa")
            if k == 0:
                ax.axhline(figures["nominal_ground_pressure_pa"], color="0.4", ls=":", lw=1,
                           label=f"nominal ground pressure {figures['nominal_ground_pressure_pa']:.0f} kPa")
                ax.axhline(figures["rowland_mean_maximum_pressure_pa"], color="0.4", ls="-.", lw=1,
                           label=f"Rowland's MMP {figures['rowland_mean_maximum_pressure_pa']:.0f} kPa")
                for x in wheels[side]:
                    ax.axvline(x, color="0.85", lw=3, zorder=0)
        ax.axhline(0.0, color="k", lw=0.5)
        ax.set_ylabel("pressure [kPa]")
        ax.set_title(f"{side} track (grey bars: road wheel stations)")
        ax.grid(True, alpha=0.3)
    axes[1].set_xlabel("x [m] (forward)")
    axes[0].legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    save((fig, args.out))


if __name__ == "__main__":
    main()
