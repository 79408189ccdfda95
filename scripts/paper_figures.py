"""The figures of scripts/paper_report.py: the paper's Figs. 9-24 drawn from the runs of
paper_runs.py by the plot scripts beside this file (plot_mac.py, plot_modes.py, ...), one PNG each
in <report>/figures/, named after the paper's figure."""
import os
import subprocess
import sys

from paper_runs import COUPLING_SPEED_KMH, FRF_SPEEDS_KMH, MOR_SPEEDS_KMH, TRACKED_SPEEDS_KMH, TRACKS, RunError

SCRIPTS = os.path.dirname(os.path.abspath(__file__))
MAC_BAND_HZ = 30  # §3.1.1: the MAC is read in the 0-30 Hz band of vertical dynamics
# The paper's captions, by figure number (its Fig. 11 caption abridged).
CAPTIONS = {
    9: "MAC index applied to vehicle model mode shapes.",
    10: "Mode selection based on MAC index.",
    11: "Vehicle model mode shape comparison: minimal track chain coupling and tracked model.",
    12: "Significant master DOFs identified by MoGeSeC: un-tracked and tracked vehicle models.",
    13: "MOR effect on vehicle model sprung mass FRFs: un-tracked vehicle (a) and tracked "
        "vehicle (b).",
    14: "Track coupling effect on vehicle models: sprung mass FRFs.",
    15: "Wheelbase filter on sprung mass vertical acceleration FRF: un-tracked vehicle (a) and "
        "tracked vehicle (b).",
    16: "Wheelbase filter on unsprung masses vertical acceleration FRFs: un-tracked vehicle and "
        "tracked vehicle.",
    17: "Track vertical road profiles and details: long hill track (a), separated waves track "
        "(b), and OOP waves track with Y+ offset (c).",
    18: "MOR effect on un-tracked vehicle model: long hill track at 5 km/h.",
    19: "MOR effect on un-tracked vehicle model: long hill track at 50 km/h.",
    20: "Track chain coupling effect on tracked vehicle CMS model: long hill track.",
    21: "Track chain coupling effect on tracked vehicle CMS model: separated waves track.",
    22: "Track chain coupling effect on tracked vehicle CMS model: out-of-phase waves + shift "
        "track.",
    23: "Longitudinal speed effect on tracked vehicle CMS model: long hill track.",
    24: "Longitudinal speed effect on tracked vehicle CMS model: separated waves track.",
}


def caption(name):
    """'Fig. 13 (a): <the paper's caption>' for a file name figNN[x]_..."""
    number, letter = int(name[3:5]), name[5] if name[5].isalpha() else ""
    return f"Fig. {number}{f' ({letter})' if letter else ''}: {CAPTIONS.get(number, '')}"


TRACK_NAMES = {"long_hill": "long hill", "separated_waves": "separated waves",
               "oop_waves": "out-of-phase waves"}


def _speed_label(speed):
    return "synchronous" if not speed else f"{speed} km/h"


def _driving_line(terrain_csv, track):
    """' (driven D m left of the track's centre line, ...)' when the lateral lines of a terrain
    file of `tvd terrain` (path frame, y left) are not centred on the path: the built-in
    oop_waves is written 1 m off (terrain/tracks.h, kOopWavesLateralOffset); '' otherwise."""
    with open(terrain_csv, encoding="utf-8") as stream:
        header = next(line for line in stream if not line.startswith("#"))
    lateral = [float(cell) for cell in header.strip().split(",")[1:]]
    offset = -0.5 * (min(lateral) + max(lateral)) if len(lateral) > 1 else 0.0
    if abs(offset) < 1e-9:
        return ""
    return (f" (driven {abs(offset):g} m {'left' if offset > 0 else 'right'} of the track's "
            f"centre line{', as in the paper' if track == 'oop_waves' else ''})")


def figure_jobs(runs, vehicle, figures_dir, pairs):
    """[(file name, script, arguments)] for every figure. pairs: the MAC pairs of Table 4's rows
    (paper_tables.pairing_section's data), one Fig. 11 panel each, as the paper's (a)-(h)."""
    fig = lambda name: os.path.join(figures_dir, name)  # noqa: E731
    jobs = [
        ("fig09_mac.png", "plot_mac.py", ["--mac-dir", runs.path("mac"), "--out", fig("fig09_mac.png"),
                                         "--freq-out", fig("fig10_mac_frequencies.png"),
                                         "--f-max", str(MAC_BAND_HZ)]),
    ]
    for letter, pair in zip("abcdefghijklmnop", pairs):
        if not (pair["untracked_mode"] and pair["tracked_mode"]):
            continue
        name = f"fig11{letter}_modes_{pair['type'].replace(' ', '_').replace('+', '_')}.png"
        modes_tracked = runs.path("modes_tracked")
        rows = [f"un-tracked ({pair['type']})={runs.path('modes_untracked')}:"
                f"{pair['untracked_mode']}",
                f"tracked, its MAC partner (MAC {pair['mac']:.2f})={modes_tracked}:"
                f"{pair['tracked_mode']}"]
        # A partner other than Table 4's tracked mode of that type (the mode of the paper's
        # motion nearest its frequency): that mode as a third row, whether the partner lacks the
        # paper's motion or only its frequency (11h's 29.1 Hz wheel mode was missing).
        of_type = pair.get("tracked_mode_of_type")
        if of_type and of_type != pair["tracked_mode"]:
            rows.append(f"tracked, the mode of the type nearest the paper's frequency (not the "
                        f"MAC partner)={modes_tracked}:{of_type}")
        jobs.append((name, "plot_modes.py", ["--out", fig(name), "--normalise", "vehicle"] + rows))
    jobs += [
        ("fig12_masters.png", "plot_masters.py",
         ["--out", fig("fig12_masters.png"), f"un-tracked={runs.path('reduced_untracked.mat')}",
          f"tracked={runs.path('reduced_tracked.mat')}"]),
    ]
    for v, letter in (("untracked", "a"), ("tracked", "b")):
        jobs.append((f"fig13{letter}_frf_{v}_full_vs_reduced.png", "plot_frf.py",
                     ["--out", fig(f"fig13{letter}_frf_{v}_full_vs_reduced.png"), "--title",
                      f"{v}: full vs reduced, synchronous",
                      f"full={runs.frf_csv(v, 'full')}", f"reduced={runs.frf_csv(v, 'reduced')}"]))
    jobs.append(("fig14_frf_track_coupling.png", "plot_frf.py",
                 ["--out", fig("fig14_frf_track_coupling.png"), "--title",
                  "track coupling: un-tracked vs tracked (reduced, synchronous)",
                  f"un-tracked={runs.frf_csv('untracked', 'reduced')}",
                  f"tracked={runs.frf_csv('tracked', 'reduced')}"]))
    for number, outputs, what in ((15, "hull_vertical_acc", "hull"),
                                  (16, "front_wheel_acc,rear_wheel_acc", "wheels")):
        for v, letter in (("untracked", "a"), ("tracked", "b")):
            name = f"fig{number}{letter}_frf_{v}_wheelbase_filter_{what}.png"
            jobs.append((name, "plot_frf.py",
                         ["--out", fig(name), "--outputs", outputs, "--title",
                          f"{v}: wheelbase filter (reduced model)"]
                         + [f"{_speed_label(s)}={runs.frf_csv(v, 'reduced', s)}"
                            for s in (0, *FRF_SPEEDS_KMH)]))
    for track, letter in zip(TRACKS, "abc"):
        name = f"fig17{letter}_terrain_{track}.png"
        jobs.append((name, "plot_terrain.py",
                     ["--vehicle", vehicle, "--out", fig(name), "--title",
                      f"{TRACK_NAMES[track]} under the pad rows"
                      + _driving_line(runs.terrain_csv(track), track), runs.terrain_csv(track)]))
    for speed, number in zip(MOR_SPEEDS_KMH, (18, 19)):
        name = f"fig{number}_untracked_long_hill_{speed}kmh_full_vs_reduced.png"
        jobs.append((name, "plot_simulation.py",
                     ["--layout", "paper", "--out", fig(name), "--title",
                      f"un-tracked, long hill, {speed} km/h",
                      f"full={runs.sim_csv('untracked', 'full', 'long_hill', speed)}",
                      f"reduced={runs.sim_csv('untracked', 'reduced', 'long_hill', speed)}"]))
    for track, number in zip(TRACKS, (20, 21, 22)):
        v = COUPLING_SPEED_KMH
        name = f"fig{number}_{track}_{v}kmh_untracked_vs_tracked.png"
        jobs.append((name, "plot_simulation.py",
                     ["--layout", "paper", "--out", fig(name), "--title",
                      f"{TRACK_NAMES[track]}, {v} km/h (reduced models)",
                      f"un-tracked={runs.sim_csv('untracked', 'reduced', track, v)}",
                      f"tracked={runs.sim_csv('tracked', 'reduced', track, v)}"]))
    for track, number in (("long_hill", 23), ("separated_waves", 24)):
        name = f"fig{number}_tracked_{track}_speeds.png"
        jobs.append((name, "plot_simulation.py",
                     ["--layout", "paper", "--out", fig(name), "--title",
                      f"tracked, {TRACK_NAMES[track]} (reduced model)"]
                     + [f"{s} km/h={runs.sim_csv('tracked', 'reduced', track, s)}"
                        for s in TRACKED_SPEEDS_KMH]))
    # Each figure names the paper's figure it stands for, so that a PNG taken out of the report
    # still says which it is.
    for name, _, args in jobs:
        if "--title" in args:
            i = args.index("--title") + 1
            args[i] = f"{caption(name).split(':')[0]}: {args[i]}"
    return jobs


def draw_all(runs, vehicle, figures_dir, pairs, log=print):
    """Draws every figure; returns the files written (Fig. 10 comes with Fig. 9)."""
    os.makedirs(figures_dir, exist_ok=True)
    for old in os.listdir(figures_dir):  # an earlier run's figures, which this one may not redraw
        if old.startswith("fig") and old.endswith(".png"):
            os.remove(os.path.join(figures_dir, old))
    written = []
    for name, script, args in figure_jobs(runs, vehicle, figures_dir, pairs):
        log(f"{script} -> {name}")
        result = subprocess.run([sys.executable, os.path.join(SCRIPTS, script), *args],
                                capture_output=True, text=True, timeout=300)
        if result.returncode != 0:
            last = (result.stderr.strip().splitlines() or ["(no message)"])[-1]
            raise RunError(f"{script} failed for {name}: {last}")
        written.append(name)
        if script == "plot_mac.py":
            written.append("fig10_mac_frequencies.png")
    return written
