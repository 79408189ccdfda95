#!/usr/bin/python3
"""Vehicle mode shapes, like Fig. 11 of Dimauro et al. (2024).

Reads what `tvd modes --vehicle ... --out DIR` writes (DIR/modes.csv and DIR/node_shapes.csv:
every node's undeformed position and its translation in each mode, wheel centres and named points
included) and draws each requested mode in a side view (x, z), a top view (x, y) and a front
view (y, z; the hull's roll shows there, in its suspension mounts and named points): the
undeformed vehicle in grey, the deformed one coloured by the displacement magnitude, blue for
none to red for the largest, as the paper does. Each LABEL=DIR:MODE is one row, e.g. a MAC pair
of `tvd mac` (the un-tracked mode and its tracked partner):

    TVD=build/devel/lib/tracked_vehicle_dynamics/tvd; V=config/vehicles/paper_vehicle.yaml
    $TVD modes --vehicle $V --variant untracked --count 20 --out /tmp/mu
    $TVD modes --vehicle $V --variant tracked --count 40 --out /tmp/mt
    scripts/plot_modes.py --out fig11.png "un-tracked=/tmp/mu:5" "tracked=/tmp/mt:15"

--scale sets the drawn largest displacement [m] (default 0.4). With --normalise vehicle the colour
and the drawn scale refer to the largest displacement off the track chain (hull, spider, arms,
wheels, sprockets, idlers, named points), so that a tracked mode whose chain moves most still shows
its hull; chain nodes beyond it are drawn red at the scale. The hull's CoG is a large marker, its
rest position a hollow one. Bad input (a missing directory or
file, a mode the files do not hold, a malformed row) exits with status 2 and one line on stderr
naming it; no figure is written then.
"""
import argparse
import os

# First: plot_common selects the Agg backend before pyplot loads.
from plot_common import (OUT_HELP, ArgumentParser, Table, check_outputs, fail, positive_float,
                         save, vehicle_view)
import matplotlib.pyplot as plt
import numpy as np


def spec(text):
    """'[LABEL=]DIR:MODE' -> (label, dir, mode number)."""
    label, _, rest = text.rpartition("=") if "=" in text and not os.path.isdir(text) else ("", "", text)
    directory, colon, mode = rest.rpartition(":")
    try:
        number = int(mode)
    except ValueError:
        number = 0
    if not colon or number < 1:
        raise argparse.ArgumentTypeError(f"'{text}': expected [LABEL=]DIR:MODE with MODE >= 1")
    return (label or f"{os.path.basename(os.path.normpath(directory))} mode {number}", directory,
            number)


# --normalise: what the colour scale's red and the drawn --scale refer to.
NORMALISE = {"mode": "max |u| of the mode",
             "vehicle": "max |u| off the track chain (chain nodes beyond it: red, at the scale)"}
CHAIN_PART = "track assembly"  # node_shapes.csv `part` of the chain's nodes
HULL_PART = "hull"             # the hull's reference node, its CoG


def reference_magnitude(parts, magnitude, normalise):
    """The displacement drawn at --scale and coloured red: the mode's largest, or with 'vehicle'
    the largest off the track chain (the mode's largest when nothing off the chain moves)."""
    if normalise == "vehicle":
        off_chain = np.array([not part.startswith(CHAIN_PART) for part in parts], dtype=bool)
        if off_chain.any() and magnitude[off_chain].max() > 0:
            return magnitude[off_chain].max()
    return magnitude.max()


def drawn_positions(positions, shape, scale, reference):
    """positions + shape scale / reference, each node's drawn displacement at most `scale`."""
    if reference <= 0:
        return positions.copy()
    drawn = shape * (scale / reference)
    length = np.linalg.norm(drawn, axis=1)
    over = length > scale
    drawn[over] *= (scale / length[over])[:, None]
    return positions + drawn


def load(directory, mode):
    """(positions [n x 3], displacements [n x 3], parts [n], title) of one mode of a modes
    directory."""
    if not os.path.isdir(directory):
        fail(f"{directory}: not a directory (the --out of `tvd modes --vehicle`)")
    modes = Table(os.path.join(directory, "modes.csv"))
    numbers = modes.column("mode")
    if mode not in numbers:
        fail(f"{directory}: no mode {mode} (modes {int(numbers.min())}..{int(numbers.max())})")
    row = int(np.flatnonzero(numbers == mode)[0])
    frequency = modes.column("frequency_hz")[row]
    nodes = Table(os.path.join(directory, "node_shapes.csv"))
    positions = np.column_stack([nodes.column(c) for c in ("x_m", "y_m", "z_m")])
    shape = np.column_stack([nodes.column(f"mode_{mode}_{c}") for c in ("ux", "uy", "uz")])
    if not (np.all(np.isfinite(positions)) and np.all(np.isfinite(shape))):
        fail(f"{directory}/node_shapes.csv: a non-finite value")
    kind = modes.text("type")[row] if "type" in modes.header else ""
    parts = list(nodes.text("part")) if "part" in nodes.header else [""] * len(positions)
    title = f"mode {mode}, {frequency:.2f} Hz" + (f" ({kind})" if kind else "")
    return positions, shape, parts, title


def draw(ax, positions, shape, parts, scale, normalise, axis, horizontal=0):
    """One view: `horizontal` against `axis` (x against 1: y, top view; x against 2: z, side
    view; y against z: front view)."""
    magnitude = np.linalg.norm(shape, axis=1)
    reference = reference_magnitude(parts, magnitude, normalise)
    moved = drawn_positions(positions, shape, scale, reference)
    colour = np.minimum(magnitude / reference, 1.0) if reference > 0 else magnitude
    h = horizontal
    ax.scatter(positions[:, h], positions[:, axis], s=3, color="0.8", zorder=1)
    order = np.argsort(magnitude)  # the largest on top
    ax.scatter(moved[order, h], moved[order, axis], s=6, zorder=2, cmap="jet", c=colour[order],
               vmin=0.0, vmax=1.0)
    hull = [i for i, part in enumerate(parts) if part == HULL_PART]
    ax.scatter(positions[hull, h], positions[hull, axis], s=140, facecolor="none", edgecolor="k",
               zorder=3)
    ax.scatter(moved[hull, h], moved[hull, axis], s=140, c=colour[hull], cmap="jet", vmin=0.0,
               vmax=1.0, edgecolor="k", zorder=4)
    vehicle_view(ax, axis, horizontal)


def main():
    parser = ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help=f"figure file to write; {OUT_HELP}")
    parser.add_argument("--scale", type=positive_float, default=0.4,
                        help="largest displacement as drawn [m] (default 0.4)")
    parser.add_argument("--normalise", choices=NORMALISE, default="mode",
                        help="what the colour and --scale refer to: the mode's largest "
                             "displacement (mode, the default) or the largest off the track chain "
                             "(vehicle)")
    parser.add_argument("modes", nargs="+", type=spec, metavar="[LABEL=]DIR:MODE",
                        help="a `tvd modes --vehicle --out` directory and a mode number, one row each")
    args = parser.parse_args()
    check_outputs(("--out", args.out))

    rows = [(label, *load(directory, mode)) for label, directory, mode in args.modes]
    fig, axes = plt.subplots(len(rows), 3, figsize=(18, 3.8 * len(rows) + 0.8), squeeze=False,
                             gridspec_kw={"width_ratios": [1, 1, 0.5]})
    for (label, positions, shape, parts, title), (side, top, front) in zip(rows, axes):
        draw(side, positions, shape, parts, args.scale, args.normalise, 2)
        draw(top, positions, shape, parts, args.scale, args.normalise, 1)
        draw(front, positions, shape, parts, args.scale, args.normalise, 2, horizontal=1)
        side.set_title(f"{label}:\n{title}, side view")
        top.set_title("\ntop view")
        front.set_title("\nfront view (from ahead)")
    fig.suptitle(f"grey: undeformed; colour: displacement |u| / {NORMALISE[args.normalise]},\n"
                 f"blue 0 to red 1, drawn {args.scale:g} m at red; large marker: the hull's CoG "
                 f"(hollow: at rest)")
    # Room for the two-line title above the first row's titles (they touched).
    fig.tvd_rect = (0, 0, 1, 1 - 0.55 / fig.get_figheight())
    save((fig, args.out))


if __name__ == "__main__":
    main()
