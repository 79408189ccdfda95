#!/usr/bin/python3
"""Tests of scripts/plot_mac.py, plot_frf.py and plot_simulation.py on small synthetic inputs
(and of the wheel choice of ros_demo_summary.py).

Needs no C++ build: the inputs are written here in the formats of `tvd mac --out`, `tvd frf` and
`tvd simulate --out`. Run as
    /usr/bin/python3 test/scripts/test_plot_scripts.py [--xml OUTDIR/plot_scripts.xml] [TEST ...]
--xml writes a JUnit-style report (one <testcase> per test method); the exit status is 1 on failure.
"""
import importlib
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import scipy.io

import junit_runner

SCRIPTS = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                        "scripts"))
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
PDF_SIGNATURE = b"%PDF-"
MIN_PNG_BYTES = 10_000  # a rendered figure, not an empty canvas
INPUT_ERROR_STATUS = 2
FRF_OUTPUTS = ["hull_vertical_acc", "hull_pitch_acc", "front_wheel_acc", "rear_wheel_acc"]
MAC_ROW_COLUMN = "untracked_mode"


def write_csv(path, columns):
    """columns: {header name: 1-D array}, written in insertion order."""
    names = list(columns)
    np.savetxt(path, np.column_stack([columns[n] for n in names]), delimiter=",", fmt="%.9g",
               header=",".join(names), comments="")
    return path


def script_module(name):
    """Imports scripts/<name>.py as a module (to call its functions or main())."""
    sys.path.insert(0, SCRIPTS)
    try:
        return importlib.import_module(name)
    finally:
        sys.path.remove(SCRIPTS)


def drawn_figure(name, *args):
    """Runs scripts/<name>.py's main() with `args` as its command line and returns the first
    figure it would have saved (save() replaced, nothing written)."""
    module = script_module(name)
    captured = []
    original, argv = module.save, sys.argv
    module.save = lambda *pairs: captured.extend(pairs)
    sys.argv = [f"{name}.py"] + list(args)
    try:
        module.main()
    finally:
        module.save, sys.argv = original, argv
    return captured[0][0]


def write_mat(path, columns, metadata=None):
    """columns in the format of `tvd frf/simulate --out FILE.mat`: one n x 1 variable per column,
    plus char metadata variables."""
    variables = dict(metadata or {"vehicle": "synthetic", "variant": "tracked", "model": "reduced"})
    variables.update({n: np.asarray(v, dtype=float).reshape(-1, 1) for n, v in columns.items()})
    scipy.io.savemat(path, variables)
    return path


def corrupt_mat(path):
    """Flips 8 bytes in the middle of the first data element of a MAT v5 file."""
    with open(path, "rb") as stream:
        data = bytearray(stream.read())
    size = struct.unpack("<I", data[132:136])[0]
    middle = 136 + size // 2
    data[middle:middle + 8] = bytes(b ^ 0x5A for b in data[middle:middle + 8])
    with open(path, "wb") as stream:
        stream.write(data)


def rewrite_lines(path, edit):
    """Applies edit(list of lines) to a text file."""
    with open(path) as stream:
        lines = stream.read().splitlines()
    edit(lines)
    with open(path, "w") as stream:
        stream.write("\n".join(lines) + "\n")
    return path


def frf_columns(outputs=FRF_OUTPUTS, wheelbase_delay_s=0.0):
    """FRF of a 2-DOF sprung/unsprung mass on a tyre spring, excited by the road height h.

    (-w^2 M + i w C + K) z = [0, k_t]^T h; outputs are accelerations -w^2 z / h [(m/s^2)/m].
    """
    m_s, m_u, k_s, c_s, k_t = 400.0, 40.0, 2.0e4, 1.5e3, 2.0e5  # [kg], [N/m], [N s/m]
    frequency = np.linspace(0.1, 50.0, 400)
    columns = {"frequency_hz": frequency}
    responses = {}
    for k, f in enumerate(frequency):
        w = 2 * np.pi * f
        dynamic = np.array([[-w**2 * m_s + 1j * w * c_s + k_s, -1j * w * c_s - k_s],
                            [-1j * w * c_s - k_s, -w**2 * m_u + 1j * w * c_s + k_s + k_t]])
        z = np.linalg.solve(dynamic, np.array([0.0, k_t]))
        delay = np.exp(-1j * w * wheelbase_delay_s)
        responses.setdefault("hull_vertical_acc", []).append(-w**2 * z[0])
        responses.setdefault("hull_pitch_acc", []).append(-w**2 * z[0] * (1.2 - delay) / 3.0)
        responses.setdefault("front_wheel_acc", []).append(-w**2 * z[1])
        responses.setdefault("rear_wheel_acc", []).append(-w**2 * z[1] * delay)
    for name in outputs:
        values = np.array(responses[name])
        columns[name + "_mag"] = np.abs(values)
        columns[name + "_phase_deg"] = np.degrees(np.angle(values))
    return columns


def hill(station):
    """Height [m] of a 0.4 m hill with 1 m ramps between stations 8 and 20 m."""
    return 0.4 * np.clip(np.minimum(station - 8.0, 20.0 - station), 0.0, 1.0)


def simulation_columns(with_roll=True, speed_kmh=30.0):
    """A plausible `tvd simulate` time series over the hill; wheels 1 (front) to 7 (rear)."""
    time_s = np.arange(0.0, 30.0 / (speed_kmh / 3.6), 0.002)
    station = time_s * speed_kmh / 3.6
    heave = hill(station - 2.0) * (1 + 0.05 * np.sin(2 * np.pi * 1.5 * time_s))
    columns = {"time_s": time_s, "station_m": station, "hull_heave_m": heave,
               "hull_vertical_accel_m_s2": np.gradient(np.gradient(heave, time_s), time_s),
               "hull_pitch_deg": 6.0 * (hill(station) - hill(station - 4.0)) / 0.4}
    if with_roll:
        columns["hull_roll_deg"] = 0.5 * np.sin(2 * np.pi * station / 1.8)
    for side in ("left", "right"):
        for wheel in range(1, 8):
            columns[f"road_wheel_{side}_{wheel}_m"] = hill(station - 0.6 * (wheel - 1))
    return columns


def write_mac_dir(directory, n_untracked=6, n_tracked=8, with_mat=True, row_column=MAC_ROW_COLUMN,
                  mat_variables=("untracked_frequencies_hz", "tracked_frequencies_hz"),
                  compress=False):
    """A small directory in the format of `tvd mac --out DIR`: mac.csv and mac.mat."""
    os.makedirs(directory, exist_ok=True)
    rng = np.random.default_rng(7)
    mac = 0.5 * rng.random((n_untracked, n_tracked)) ** 3
    for i in range(n_untracked):
        mac[i, min(i + 1, n_tracked - 1)] = 0.75 + 0.04 * i  # one match per un-tracked mode
    with open(os.path.join(directory, "mac.csv"), "w") as stream:
        stream.write(",".join([row_column] + [str(j + 1) for j in range(n_tracked)]) + "\n")
        for i in range(n_untracked):
            stream.write(",".join([str(i + 1)] + [f"{v:g}" for v in mac[i]]) + "\n")
    if with_mat:
        frequencies = {"untracked_frequencies_hz": np.linspace(2.0, 20.0, n_untracked),
                       "tracked_frequencies_hz": np.linspace(0.7, 30.0, n_tracked)}
        variables = {"mac": mac, "threshold": np.array([[0.7]]),
                     "untracked_mode_types": np.array([["bounce"]] * n_untracked, dtype=object)}
        variables.update({n: frequencies[n].reshape(-1, 1) for n in mat_variables})
        scipy.io.savemat(os.path.join(directory, "mac.mat"), variables, do_compression=compress)
    return directory


class PlotScriptsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="plot_scripts_")
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def run_script(self, script, *args):
        return subprocess.run([sys.executable, os.path.join(SCRIPTS, script), *args],
                              capture_output=True, text=True, timeout=120)

    def assert_png(self, result, *paths):
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        for path in paths:
            self.assertIn(path, result.stdout.splitlines())
            with open(path, "rb") as stream:
                self.assertEqual(stream.read(len(PNG_SIGNATURE)), PNG_SIGNATURE, path)
            self.assertGreater(os.path.getsize(path), MIN_PNG_BYTES, path)

    def assert_input_error(self, result, out, *words):
        """Status 2, exactly one stderr line containing every word, no traceback, no PNG."""
        self.assertEqual(result.returncode, INPUT_ERROR_STATUS, result.stderr)
        lines = result.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, result.stderr)
        for word in words:
            self.assertIn(word, lines[0])
        self.assertFalse(os.path.exists(out), "a PNG was written despite the input error")

    # --help

    def test_help(self):
        for script in ("plot_mac.py", "plot_frf.py", "plot_simulation.py", "plot_terrain.py",
                       "plot_masters.py", "plot_modes.py", "plot_ground_pressure.py",
                       "plot_ride.py"):
            result = self.run_script(script, "--help")
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("--out", result.stdout)

    def test_help_is_current(self):
        # `tvd frf` exists (README); the help gives its real options and the .mat/'=' rules.
        result = self.run_script("plot_frf.py", "--help")
        self.assertNotIn("not written yet", result.stdout)
        for words in ("--speed-kmh", "--model full", ".mat"):
            self.assertIn(words, result.stdout)
        for script in ("plot_frf.py", "plot_simulation.py"):
            result = self.run_script(script, "--help")
            self.assertIn(".mat", result.stdout)
            self.assertIn("contains '='", result.stdout)

    # every script: options, outputs

    def test_options_must_be_finite_and_positive(self):
        mac_dir = write_mac_dir(self.path("mac"))
        frf = write_csv(self.path("frf.csv"), frf_columns())
        out, freq_out = self.path("a.png"), self.path("b.png")
        for value in ("nan", "inf", "-inf", "-3", "0", "x"):
            result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out,
                                     "--freq-out", freq_out, f"--f-max={value}")
            self.assert_input_error(result, out, "--f-max", value)
            self.assertFalse(os.path.exists(freq_out))
            for option in ("--f-max", "--band-hz"):
                result = self.run_script("plot_frf.py", "--out", out, f"{option}={value}",
                                         f"a={frf}")
                self.assert_input_error(result, out, option, value)

    def test_mac_unwritable_freq_out_writes_no_figure(self):
        mac_dir = write_mac_dir(self.path("mac"))
        out = self.path("mac.png")
        for freq_out in (self.path("nowhere/freq.png"), self.dir, self.path("freq.txt"), out):
            result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out,
                                     "--freq-out", freq_out)
            self.assert_input_error(result, out, freq_out)

    def test_output_type_follows_extension(self):
        mac_dir = write_mac_dir(self.path("mac"))
        frf = write_csv(self.path("frf.csv"), frf_columns())
        sim = write_csv(self.path("sim.csv"), simulation_columns())
        runs = {"plot_mac.py": ["--mac-dir", mac_dir, "--out"],
                "plot_frf.py": [f"a={frf}", "--out"],
                "plot_simulation.py": [f"a={sim}", "--out"]}
        for script, args in runs.items():
            pdf, svg = self.path(f"{script}.PDF"), self.path(f"{script}.svg")
            for out, signature in ((pdf, PDF_SIGNATURE), (svg, b"<?xml")):
                result = self.run_script(script, *args, out)
                self.assertEqual(result.returncode, 0, result.stderr)
                self.assertEqual(result.stdout.splitlines(), [out])
                with open(out, "rb") as stream:
                    self.assertEqual(stream.read(len(signature)), signature, out)
            for bad in ("fig.txt", "fig"):
                result = self.run_script(script, *args, self.path(bad))
                self.assert_input_error(result, self.path(bad), "--out", self.path(bad))

    # plot_mac.py

    def test_mac_matrix_and_frequency_map(self):
        mac_dir = write_mac_dir(self.path("mac"))
        out, freq_out = self.path("mac.png"), self.path("freq.png")
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out,
                                 "--freq-out", freq_out, "--threshold", "0.7")
        self.assert_png(result, out, freq_out)

    def test_mac_matrix_marks_the_band_edge_after_the_last_mode_inside(self):
        plot_mac = script_module("plot_mac")
        untracked, tracked = np.arange(1, 7), np.arange(1, 9)
        f_untracked = np.array([2.0, 4.0, 9.0, 10.0, 35.0, 35.0])  # 4 inside 10 Hz (edge included)
        f_tracked = np.array([1.0, 3.0, 5.0, 7.0, 9.5, 12.0, 30.0, 40.0])  # 5 inside
        mac = np.full((6, 8), 0.1)
        fig = plot_mac.plot_matrix(untracked, tracked, mac, 0.7, (f_untracked, f_tracked), 10.0)
        vertical = [line.get_xdata()[0] for line in fig.axes[0].lines
                    if line.get_xdata()[0] == line.get_xdata()[1]]
        horizontal = [line.get_ydata()[0] for line in fig.axes[0].lines
                      if line.get_ydata()[0] == line.get_ydata()[1]]
        self.assertEqual(len(fig.axes[0].lines), 2)
        self.assertEqual(vertical, [3.5])  # between image columns 3 (mode 4) and 4 (mode 5)
        self.assertEqual(horizontal, [4.5])
        # The vertical edge's label hangs from the top image row (8 tracked modes, not 6).
        self.assertEqual(sorted(t.get_position() for t in fig.axes[0].texts),
                         [(0.2, 4.7), (3.7, 7.2)])
        # every mode inside: no edge drawn
        fig = plot_mac.plot_matrix(untracked, tracked, mac, 0.7, (f_untracked, f_tracked), 50.0)
        self.assertEqual(len(fig.axes[0].lines), 0)

    def test_mac_selection_keeps_pairs_of_global_modes(self):
        """With mac.mat's global flags and eigenspace MAC (as tvd mac writes them), Fig. 10 shows
        the pairs the reduction uses, pairs of global modes by eigenspace MAC, and Fig. 9 draws a
        pair with a local mode in it blue, not red (review 126: both showed every raw pair)."""
        plot_mac = script_module("plot_mac")
        mac_dir = write_mac_dir(self.path("mac"))  # pairs (i, i + 1), i = 0..5, MAC >= 0.75
        data = scipy.io.loadmat(os.path.join(mac_dir, "mac.mat"))
        untracked_global = np.array([1, 1, 0, 1, 1, 1])  # un-tracked mode 3 local
        tracked_global = np.array([1, 1, 1, 1, 1, 0, 1, 1])  # tracked mode 6 local
        eigenspace = data["mac"].copy()
        eigenspace[0, 1] = 0.2  # raw MAC 0.75, but not the eigenspaces': not paired
        data.update({"untracked_global": untracked_global.reshape(-1, 1),
                     "tracked_global": tracked_global.reshape(-1, 1),
                     "eigenspace_mac": eigenspace})
        scipy.io.savemat(os.path.join(mac_dir, "mac.mat"),
                         {k: v for k, v in data.items() if not k.startswith("__")})
        out, freq_out = self.path("mac.png"), self.path("freq.png")
        self.assert_png(self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out,
                                        "--freq-out", freq_out), out, freq_out)
        untracked, tracked, mac = plot_mac.load_mac(os.path.join(mac_dir, "mac.csv"))
        f_u, f_t = np.linspace(2.0, 20.0, 6), np.linspace(0.7, 30.0, 8)
        flags = (untracked_global != 0, tracked_global != 0)
        fig = plot_mac.plot_frequencies(untracked, tracked, f_u, f_t, eigenspace, 0.7, None,
                                        flags)
        points = fig.axes[0].collections[0].get_offsets()
        # Pairs (2, 3), (4, 5), (6, 7): (1, 2) by its eigenspace MAC, (3, 4) and (5, 6) by a
        # local mode, are out.
        np.testing.assert_allclose(points, np.column_stack([f_u[[1, 3, 5]], f_t[[2, 4, 6]]]))
        self.assertIn("3 pairs of global modes", fig.axes[0].get_title())
        fig = plot_mac.plot_matrix(untracked, tracked, mac, 0.7, None, None, flags)
        self.assertEqual(len(fig.axes), 4)  # the matrix and three colour bars: red, blue, gray
        blue = fig.axes[0].images[2].get_array()  # the local pairs' layer
        self.assertEqual(sorted(map(tuple, np.argwhere(~np.ma.getmaskarray(blue)))),
                         [(3, 2), (5, 4)])  # (tracked, un-tracked) image indices
        # Without the flags (an older mac.mat): every raw pair, as before.
        fig = plot_mac.plot_frequencies(untracked, tracked, f_u, f_t, mac, 0.7, None)
        self.assertEqual(len(fig.axes[0].collections[0].get_offsets()), 6)

    def test_mac_matrix_needs_no_mat_file(self):
        mac_dir = write_mac_dir(self.path("mac"), with_mat=False)
        out = self.path("mac.png")
        self.assert_png(self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out), out)

    def test_mac_missing_mat_file(self):
        mac_dir = write_mac_dir(self.path("mac"), with_mat=False)
        out = self.path("mac.png")
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out, "--freq-out",
                                 self.path("freq.png"))
        self.assert_input_error(result, out, os.path.join(mac_dir, "mac.mat"))

    def test_mac_missing_csv(self):
        out = self.path("mac.png")
        result = self.run_script("plot_mac.py", "--mac-dir", self.path("nowhere"), "--out", out)
        self.assert_input_error(result, out, os.path.join(self.path("nowhere"), "mac.csv"))

    def test_mac_missing_row_column(self):
        mac_dir = write_mac_dir(self.path("mac"), row_column="mode")
        out = self.path("mac.png")
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out)
        self.assert_input_error(result, out, "mac.csv", MAC_ROW_COLUMN)

    def test_mac_corrupt_mat_file(self):
        mac_dir = write_mac_dir(self.path("mac"), compress=True)
        corrupt_mat(os.path.join(mac_dir, "mac.mat"))  # zlib: incorrect data check
        out, freq_out = self.path("mac.png"), self.path("freq.png")
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out, "--freq-out",
                                 freq_out)
        self.assert_input_error(result, out, os.path.join(mac_dir, "mac.mat"),
                                "cannot read MAT file")
        self.assertFalse(os.path.exists(freq_out))

    def test_mac_truncated_mat_file(self):
        for compress in (False, True):
            mac_dir = write_mac_dir(self.path(f"mac{compress}"), compress=compress)
            mat = os.path.join(mac_dir, "mac.mat")
            with open(mat, "rb") as stream:
                data = stream.read()
            for size in (len(data) // 2, 100):
                with open(mat, "wb") as stream:
                    stream.write(data[:size])
                out = self.path("mac.png")
                result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out,
                                         "--freq-out", self.path("freq.png"))
                self.assert_input_error(result, out, mat, "cannot read MAT file", "truncated")

    def test_mac_duplicate_column_and_huge_mode_number(self):
        mac_dir = write_mac_dir(self.path("mac"))
        path = os.path.join(mac_dir, "mac.csv")
        with open(path) as stream:
            original = stream.read().splitlines()

        def duplicate(lines):
            lines[0] = lines[0].replace(",2,", ",1,")
        rewrite_lines(path, duplicate)
        out = self.path("mac.png")
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out)
        self.assert_input_error(result, out, path, "'1'", "twice")

        def huge(lines):
            lines[:] = original
            lines[2] = "1e300" + lines[2][lines[2].index(","):]
        rewrite_lines(path, huge)  # no numpy overflow warning before the error line
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out)
        self.assert_input_error(result, out, path, MAC_ROW_COLUMN)

    def test_mac_missing_frequency_variable(self):
        mac_dir = write_mac_dir(self.path("mac"), mat_variables=("untracked_frequencies_hz",))
        out = self.path("mac.png")
        result = self.run_script("plot_mac.py", "--mac-dir", mac_dir, "--out", out, "--freq-out",
                                 self.path("freq.png"))
        self.assert_input_error(result, out, "mac.mat", "tracked_frequencies_hz")

    # plot_frf.py

    def test_frf_two_models_all_outputs(self):
        full = write_csv(self.path("full.csv"), frf_columns())
        delayed = write_csv(self.path("delayed.csv"), frf_columns(wheelbase_delay_s=0.2))
        out = self.path("frf.png")
        result = self.run_script("plot_frf.py", "--out", out, "--title", "synthetic 2-DOF",
                                 "--band-hz", "30", f"sync={full}", f"30 km/h={delayed}")
        self.assert_png(result, out)

    def test_frf_shares_one_legend_under_the_panels(self):
        # The files are the same lines in every panel: one legend, in a row of its own under the
        # panels (no panel's curves covered), naming each file once and the band line.
        plot_frf = script_module("plot_frf")  # its OUTPUTS below
        # The rear wheel scaled, so that no two outputs of a file share their magnitudes.
        files = {"sync": frf_columns(), "30 km/h": frf_columns(wheelbase_delay_s=0.2)}
        for columns in files.values():
            columns["rear_wheel_acc_mag"] = 0.8 * columns["rear_wheel_acc_mag"]
        full = write_csv(self.path("full.csv"), files["sync"])
        delayed = write_csv(self.path("delayed.csv"), files["30 km/h"])
        fig = drawn_figure("plot_frf", "--out", self.path("f.png"), f"sync={full}",
                           f"30 km/h={delayed}")
        panels = [ax for ax in fig.axes if ax.get_visible() and ax.axison]
        self.assertEqual(len(panels), 4)
        self.assertTrue(all(ax.get_legend() is None for ax in panels))
        # Each panel draws its output's magnitude column of each file, against frequency: not
        # the phase, not another output.
        by_title = {ax.get_title(): ax for ax in panels}
        for name, (title, _) in plot_frf.OUTPUTS.items():
            lines = {line.get_label(): line for line in by_title[title].get_lines()}
            for label, columns in files.items():
                # (the CSV keeps 8 significant digits)
                np.testing.assert_allclose(lines[label].get_xdata(), columns["frequency_hz"],
                                           rtol=1e-7, err_msg=(name, label))
                np.testing.assert_allclose(lines[label].get_ydata(), columns[name + "_mag"],
                                           rtol=1e-7, err_msg=(name, label))
        self.assertFalse(np.allclose(files["30 km/h"]["hull_pitch_acc_mag"],
                                     files["sync"]["hull_pitch_acc_mag"]))
        legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
        self.assertEqual(len(legends), 1)
        self.assertEqual([t.get_text() for t in legends[0].get_texts()],
                         ["sync", "30 km/h", "30 Hz band"])
        # Laid out as save() does: the legend lies below every panel.
        fig.tight_layout()
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        legend_top = legends[0].get_window_extent(renderer).y1
        self.assertLess(legend_top, min(ax.get_window_extent(renderer).y0 for ax in panels))

    def test_frf_only_hull_outputs(self):
        path = write_csv(self.path("hull.csv"),
                         frf_columns(outputs=["hull_vertical_acc", "hull_pitch_acc"]))
        out = self.path("frf.png")
        self.assert_png(self.run_script("plot_frf.py", "--out", out, f"full={path}"), out)

    def test_frf_selected_outputs(self):
        # Fig. 15 draws the hull only, Fig. 16 the wheels: --outputs picks the panels.
        path = write_csv(self.path("all.csv"), frf_columns())
        out = self.path("frf.png")
        self.assert_png(self.run_script("plot_frf.py", "--out", out, "--outputs",
                                        "front_wheel_acc,rear_wheel_acc", f"full={path}"), out)
        hull = write_csv(self.path("hull.csv"), frf_columns(outputs=["hull_vertical_acc"]))
        bad = self.path("bad.png")
        for outputs, words in (("tyre_acc", ["'tyre_acc' is not an output"]),
                               ("hull_pitch_acc,hull_pitch_acc", ["names an output twice"]),
                               ("rear_wheel_acc", ["none of these is in any file"])):
            result = self.run_script("plot_frf.py", "--out", bad, "--outputs", outputs,
                                     f"full={hull}")
            self.assert_input_error(result, bad, *words)

    def test_frf_point_panels(self):
        # `tvd frf --points crew_seat`: the point's magnitude and its Wk-weighted one.
        columns = frf_columns()
        f = columns["frequency_hz"]
        columns["crew_seat_vertical_acc_mag"] = 1.3 * columns["hull_vertical_acc_mag"]
        columns["crew_seat_vertical_acc_phase_deg"] = columns["hull_vertical_acc_phase_deg"]
        columns["crew_seat_vertical_acc_wk_mag"] = (columns["crew_seat_vertical_acc_mag"]
                                                    * f / np.hypot(f, 2.0))
        path = write_csv(self.path("points.csv"), columns)
        plain = write_csv(self.path("plain.csv"), frf_columns())
        out = self.path("frf.png")
        self.assert_png(self.run_script("plot_frf.py", "--out", out, f"seat={path}",
                                        f"no points={plain}"), out)
        self.assert_png(self.run_script("plot_frf.py", "--out", out, "--outputs",
                                        "crew_seat_vertical_acc", f"seat={path}"), out)
        bad = self.path("bad.png")
        result = self.run_script("plot_frf.py", "--out", bad, "--outputs",
                                 "crew_seat_vertical_acc", f"no points={plain}")
        self.assert_input_error(result, bad, "none of these is in any file")
        columns["crew_seat_vertical_acc_wk_mag"][5] = -1.0
        negative = write_csv(self.path("negative.csv"), columns)
        result = self.run_script("plot_frf.py", "--out", bad, negative)
        self.assert_input_error(result, bad, negative, "'crew_seat_vertical_acc_wk_mag'",
                                "negative")

    def test_a_label_given_twice_is_refused(self):
        # A legend would name one of the two curves only: refused by every LABEL=FILE script,
        # for two LABEL= alike and for two bare files of one base name.
        columns = frf_columns()
        first = write_csv(self.path("frf.csv"), columns)
        os.makedirs(self.path("other"))
        second = write_csv(os.path.join(self.path("other"), "frf.csv"), columns)
        out = self.path("twice.png")
        for args in ([f"a={first}", f"a={second}"], [first, second]):
            result = self.run_script("plot_frf.py", "--out", out, *args)
            label = "a" if args[0].startswith("a=") else "frf"
            self.assert_input_error(result, out, f"label '{label}' is given to both", second)
        self.assert_png(self.run_script("plot_frf.py", "--out", out, f"a={first}",
                                        f"b={second}"), out)

    def test_frf_missing_frequency_column(self):
        columns = frf_columns()
        columns["f"] = columns.pop("frequency_hz")
        path = write_csv(self.path("bad.csv"), columns)
        out = self.path("frf.png")
        result = self.run_script("plot_frf.py", "--out", out, f"full={path}")
        self.assert_input_error(result, out, path, "frequency_hz")

    def test_frf_missing_magnitude_column(self):
        columns = frf_columns()
        del columns["hull_pitch_acc_mag"]
        path = write_csv(self.path("bad.csv"), columns)
        out = self.path("frf.png")
        result = self.run_script("plot_frf.py", "--out", out, f"full={path}")
        self.assert_input_error(result, out, path, "hull_pitch_acc_mag")

    def test_frf_mat_input(self):
        columns = frf_columns()
        csv_path = write_csv(self.path("full.csv"), columns)
        mat_path = write_mat(self.path("reduced.mat"), columns)
        out = self.path("frf.png")
        self.assert_png(self.run_script("plot_frf.py", "--out", out, f"full={csv_path}",
                                        f"reduced={mat_path}"), out)
        # A corrupt or inconsistent .mat file is named as a MAT file.
        corrupt = write_mat(self.path("corrupt.mat"), columns)
        with open(corrupt, "r+b") as stream:
            stream.truncate(os.path.getsize(corrupt) // 2)
        result = self.run_script("plot_frf.py", "--out", out + "2.png", corrupt)
        self.assert_input_error(result, out + "2.png", corrupt, "cannot read MAT file")
        columns["hull_pitch_acc_mag"] = columns["hull_pitch_acc_mag"][:-1]
        short = write_mat(self.path("short.mat"), columns)
        result = self.run_script("plot_frf.py", "--out", out + "3.png", short)
        self.assert_input_error(result, out + "3.png", short, "'hull_pitch_acc_mag'")

    def test_frf_ragged_row(self):
        path = write_csv(self.path("ragged.csv"), frf_columns())
        rewrite_lines(path, lambda lines: lines.__setitem__(3, lines[3] + ",7"))
        out = self.path("frf.png")
        result = self.run_script("plot_frf.py", "--out", out, f"full={path}")
        self.assert_input_error(result, out, path, "line 4")

    def test_frf_output_zero_in_every_file(self):
        columns = frf_columns()
        columns["hull_pitch_acc_mag"][:] = 0.0
        path = write_csv(self.path("zero.csv"), columns)
        out = self.path("frf.png")
        result = self.run_script("plot_frf.py", "--out", out, f"full={path}")
        self.assert_png(result, out)
        self.assertEqual(result.stderr, "")  # no matplotlib warning about the log scale

    def test_frf_path_with_equals_sign(self):
        path = write_csv(self.path("v=30.csv"), frf_columns())
        out = self.path("frf.png")
        # An existing file is a bare FILE; LABEL= in front works too.
        self.assert_png(self.run_script("plot_frf.py", "--out", out, path, f"30 km/h={path}"), out)
        missing = self.path("v=40.csv")  # neither the whole nor the part after '=' exists
        result = self.run_script("plot_frf.py", "--out", self.path("no.png"), missing)
        self.assert_input_error(result, self.path("no.png"), "40.csv", "LABEL=FILE", missing)

    def test_frf_missing_file(self):
        out = self.path("frf.png")
        result = self.run_script("plot_frf.py", "--out", out, f"full={self.path('none.csv')}")
        self.assert_input_error(result, out, self.path("none.csv"))

    # plot_simulation.py

    def test_simulation_two_runs_with_and_without_roll(self):
        slow = write_csv(self.path("slow.csv"), simulation_columns(speed_kmh=5.0))
        fast = write_csv(self.path("fast.csv"), simulation_columns(with_roll=False, speed_kmh=50))
        for x in ("station", "time"):
            out = self.path(f"sim_{x}.png")
            result = self.run_script("plot_simulation.py", "--out", out, "--x", x, "--title",
                                     "long hill", f"5 km/h={slow}", f"50 km/h={fast}")
            self.assert_png(result, out)

    def test_simulation_shares_one_legend_and_draws_a_common_road_once(self):
        # Two runs over the same road: one grey road line per wheel panel (not one per run), one
        # legend, in the first panel, naming both runs and the road; a roll below 0.001 deg in
        # both runs is said to be no signal. A third run on another road adds its own road line.
        columns = simulation_columns()
        columns["hull_roll_deg"] = 1e-5 * np.sin(columns["station_m"])
        for wheel in (1, 7):
            columns[f"road_under_road_wheel_left_{wheel}_m"] = hill(columns["station_m"] + wheel)
        a = write_csv(self.path("a.csv"), columns)
        b = write_csv(self.path("b.csv"), dict(columns, hull_heave_m=1.1 * columns["hull_heave_m"]))
        other = dict(columns, road_under_road_wheel_left_1_m=np.zeros_like(columns["station_m"]))
        c = write_csv(self.path("c.csv"), other)

        def draw(*args):
            return drawn_figure("plot_simulation", "--out", self.path("f.png"), *args)

        fig = draw(f"a={a}", f"b={b}")
        panels = {ax.get_ylabel(): ax for ax in fig.axes if ax.get_visible()}
        front = panels["front-left road wheel [m]"]
        grey = [line for line in front.get_lines() if line.get_color() == "grey"]
        self.assertEqual(len(grey), 1)
        self.assertEqual(grey[0].get_linestyle(), "--")  # dashed, as the paper's h_F and h_R
        legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
        self.assertEqual(len(legends), 1)
        self.assertIs(fig.axes[0].get_legend(), legends[0])
        self.assertEqual([t.get_text() for t in legends[0].get_texts()],
                         ["a", "b", "road under the wheel"])
        roll = panels["hull roll [deg, left up +]"]
        self.assertTrue(any("no lateral excitation" in t.get_text() for t in roll.texts))
        fig = draw(f"a={a}", f"c={c}")
        front = {ax.get_ylabel(): ax for ax in fig.axes}["front-left road wheel [m]"]
        self.assertEqual(len([l for l in front.get_lines() if l.get_color() == "grey"]), 2)
        # A roll that is a signal (0.5 deg) gets no such note.
        fig = draw(f"slow={write_csv(self.path('r.csv'), simulation_columns())}")
        roll = {ax.get_ylabel(): ax for ax in fig.axes}["hull roll [deg, left up +]"]
        self.assertEqual(len(roll.texts), 0)

    def test_simulation_draws_right_wheels_only_where_they_differ(self):
        # Out-of-phase waves (Fig. 22): the right wheels move opposite to the left ones and get
        # their own panels, with the road under them; on a uniform track they would repeat the
        # left ones and are left out (as in every other test here).
        columns = simulation_columns()
        for wheel in (1, 7):
            columns[f"road_wheel_right_{wheel}_m"] = -columns[f"road_wheel_left_{wheel}_m"]
            columns[f"road_under_road_wheel_right_{wheel}_m"] = -hill(columns["station_m"] + wheel)
        oop = write_csv(self.path("oop.csv"), columns)
        uniform = write_csv(self.path("uniform.csv"), simulation_columns())

        def panels(*files):
            fig = drawn_figure("plot_simulation", "--out", self.path("f.png"), *files)
            return {ax.get_ylabel(): ax for ax in fig.axes if ax.get_visible()}

        right = panels(f"oop={oop}")
        self.assertIn("front-right road wheel [m]", right)
        rear = right["rear-right road wheel [m]"]
        drawn = [line for line in rear.get_lines() if line.get_color() != "grey"][0]
        np.testing.assert_allclose(drawn.get_ydata(), -columns["road_wheel_left_7_m"], atol=1e-9)
        self.assertEqual(len([l for l in rear.get_lines() if l.get_color() == "grey"]), 1)
        self.assertEqual(len(right), 8)
        # One run differing is enough for both runs to get the panels.
        self.assertIn("rear-right road wheel [m]", panels(f"a={oop}", f"b={uniform}"))
        left_only = panels(f"u={uniform}")
        self.assertNotIn("front-right road wheel [m]", left_only)
        self.assertEqual(len(left_only), 6)

    def test_simulation_paper_layout(self):
        # --layout paper: the paper's three graphs (Figs. 18-24). The displacements graph holds
        # each run's hull (black), front and rear wheels (orange, cyan) and the roads under them
        # once (red, blue, dashed) when the runs share them; each run keeps its line style.
        columns = simulation_columns()
        for wheel in (1, 7):
            columns[f"road_under_road_wheel_left_{wheel}_m"] = hill(columns["station_m"] + wheel)
        a = write_csv(self.path("a.csv"), columns)
        b = write_csv(self.path("b.csv"), dict(columns, hull_heave_m=1.1 * columns["hull_heave_m"]))
        axes = drawn_figure("plot_simulation", "--layout", "paper", "--out", self.path("p.png"),
                            f"full={a}", f"reduced={b}").axes
        self.assertEqual(len(axes), 3)
        lines = {line.get_label(): line for line in axes[0].get_lines()}
        self.assertEqual(sorted(lines), sorted([
            "$m_s$ (full)", "$m_{u,F}$ (full)", "$m_{u,R}$ (full)", "$m_s$ (reduced)",
            "$m_{u,F}$ (reduced)", "$m_{u,R}$ (reduced)", "$h_F$", "$h_R$"]))
        np.testing.assert_allclose(lines["$m_s$ (reduced)"].get_ydata(),
                                   1.1 * columns["hull_heave_m"], rtol=1e-7, atol=1e-12)
        np.testing.assert_allclose(lines["$m_{u,R}$ (full)"].get_ydata(),
                                   columns["road_wheel_left_7_m"], rtol=1e-7, atol=1e-12)
        np.testing.assert_allclose(lines["$h_F$"].get_ydata(),
                                   columns["road_under_road_wheel_left_1_m"], rtol=1e-7,
                                   atol=1e-12)
        self.assertEqual(lines["$m_s$ (full)"].get_color(), "black")
        self.assertEqual((lines["$h_F$"].get_color(), lines["$h_F$"].get_linestyle()),
                         ("tab:red", "--"))
        self.assertEqual(lines["$m_s$ (full)"].get_linestyle(), "-")
        self.assertEqual(lines["$m_s$ (reduced)"].get_linestyle(), "--")
        accel = axes[1].get_lines()
        self.assertEqual(len(accel), 2)
        np.testing.assert_allclose(accel[0].get_ydata(), columns["hull_vertical_accel_m_s2"],
                                   rtol=1e-7, atol=1e-9)
        angles = {line.get_label(): line for line in axes[2].get_lines()}
        np.testing.assert_allclose(angles[r"$\theta$ (pitch) (full)"].get_ydata(),
                                   columns["hull_pitch_deg"], rtol=1e-7, atol=1e-9)
        self.assertIn(r"$\varphi$ (roll) (reduced)", angles)
        # Its graphs have no place for a named point's panel: refused, naming both options.
        result = self.run_script("plot_simulation.py", "--layout", "paper", "--point",
                                 "crew_seat", "--out", self.path("no.png"), f"full={a}")
        self.assert_input_error(result, self.path("no.png"), "--point", "--layout panels")

    def test_simulation_named_point_panel(self):
        columns = simulation_columns()
        columns["crew_seat_accel_z_m_s2"] = 1.3 * columns["hull_vertical_accel_m_s2"]
        path = write_csv(self.path("seat.csv"), columns)
        out = self.path("seat.png")
        self.assert_png(self.run_script("plot_simulation.py", "--out", out, "--point", "crew_seat",
                                        f"run={path}"), out)
        # A point the file does not have is named with the file.
        result = self.run_script("plot_simulation.py", "--out", self.path("no.png"), "--point",
                                 "turret", f"run={path}")
        self.assert_input_error(result, self.path("no.png"), path, "turret_accel_z_m_s2")

    def test_simulation_missing_column(self):
        columns = simulation_columns()
        del columns["hull_pitch_deg"]
        path = write_csv(self.path("bad.csv"), columns)
        out = self.path("sim.png")
        result = self.run_script("plot_simulation.py", "--out", out, f"full={path}")
        self.assert_input_error(result, out, path, "hull_pitch_deg")

    def test_simulation_non_numeric_value(self):
        path = write_csv(self.path("bad.csv"), simulation_columns())
        with open(path) as stream:
            lines = stream.read().splitlines()
        cells = lines[5].split(",")
        cells[2] = "abc"  # hull_heave_m of data line 5 (file line 6)
        lines[5] = ",".join(cells)
        with open(path, "w") as stream:
            stream.write("\n".join(lines) + "\n")
        out = self.path("sim.png")
        result = self.run_script("plot_simulation.py", "--out", out, f"full={path}")
        self.assert_input_error(result, out, path, "line 6", "hull_heave_m", "abc")

    def test_simulation_mat_input(self):
        columns = simulation_columns()
        columns["crew_seat_accel_z_m_s2"] = 1.3 * columns["hull_vertical_accel_m_s2"]
        path = write_mat(self.path("run.mat"), columns,
                         {"vehicle": "v", "variant": "tracked", "track": "hill", "model": "full"})
        out = self.path("sim.png")
        self.assert_png(self.run_script("plot_simulation.py", "--out", out, "--point", "crew_seat",
                                        f"run={path}"), out)
        del columns["hull_pitch_deg"]
        bad = write_mat(self.path("bad.mat"), columns)
        result = self.run_script("plot_simulation.py", "--out", self.path("no.png"), bad)
        self.assert_input_error(result, self.path("no.png"), bad, "hull_pitch_deg")

    def test_simulation_duplicate_column(self):
        path = write_csv(self.path("dup.csv"), simulation_columns())
        rewrite_lines(path, lambda lines: lines.__setitem__(
            0, lines[0].replace("hull_roll_deg", "hull_pitch_deg")))
        out = self.path("sim.png")
        result = self.run_script("plot_simulation.py", "--out", out, f"full={path}")
        self.assert_input_error(result, out, path, "'hull_pitch_deg'", "twice")

    def test_simulation_missing_file(self):
        out = self.path("sim.png")
        result = self.run_script("plot_simulation.py", "--out", out, self.path("none.csv"))
        self.assert_input_error(result, out, self.path("none.csv"))

    # plot_terrain.py (Fig. 17)

    def write_vehicle(self, track_centre_distance=2.8, pad_lateral_offset=0.155):
        """The two keys plot_terrain.py reads, in the description's {value, unit, source} form."""
        path = self.path("vehicle.yaml")
        with open(path, "w") as f:
            f.write(f"running_gear:\n  track_centre_distance: {{value: {track_centre_distance}, "
                    f"unit: m, source: test}}\ntrack_assembly:\n  pad_lateral_offset: "
                    f"{{value: {pad_lateral_offset}, unit: m, source: test}}\n")
        return path

    def write_twist(self, heights_of=lambda x, y: 0.1 * y * np.sin(x)):
        """A terrain file as `tvd terrain` writes it: lines at y = -2, 0, 2 m."""
        stations, lines = np.linspace(0.0, 10.0, 101), [-2.0, 0.0, 2.0]
        path = self.path("twist.csv")
        with open(path, "w") as f:
            f.write("# tracked_vehicle_dynamics terrain 'twist'\nx," + ",".join(map(str, lines)) + "\n")
            for x in stations:
                f.write(f"{x!r}," + ",".join(repr(heights_of(x, y)) for y in lines) + "\n")
        return path, stations

    def test_terrain_profiles_under_the_pad_rows(self):
        # h = 0.1 y sin x is linear in y, so the profile of a row inside the lines is exact:
        # 0.1 y_row sin x at y_row = +-(1.4 +- 0.155) m; with a 1 m offset the left outer row
        # (2.555 m) lies beyond the last line (2 m) and reads that line.
        terrain, x = self.write_twist()
        vehicle = self.write_vehicle()
        for offset, expected_y in ((0.0, {"LO": 1.555, "LI": 1.245, "RI": -1.245, "RO": -1.555}),
                                   (1.0, {"LO": 2.0, "LI": 2.245, "RI": -0.245, "RO": -0.555})):
            if offset:  # the inner left row 2.245 m is beyond the edge too
                expected_y["LI"] = 2.0
            out, profiles = self.path(f"fig17_{offset}.png"), self.path(f"p_{offset}.csv")
            result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out,
                                     "--lateral-offset", str(offset), "--profiles-out", profiles,
                                     terrain)
            self.assert_png(result, out)
            table = np.genfromtxt(profiles, delimiter=",", names=True)
            np.testing.assert_allclose(table["station_m"], x, atol=1e-12)
            for row, y in expected_y.items():
                np.testing.assert_allclose(table[f"p_{row}_m"], 0.1 * y * np.sin(x), atol=1e-11,
                                           err_msg=f"row {row} at offset {offset}")

    def test_terrain_yaml_uniform_profile(self):
        path = self.path("bump.yaml")
        with open(path, "w") as f:
            f.write("name: bump\nspacing: 0.5\nstart: 1.0\nheights: [0, 0, 0.1, 0.2, 0.1, 0, 0]\n")
        out, profiles = self.path("bump.png"), self.path("bump.csv")
        result = self.run_script("plot_terrain.py", "--vehicle", self.write_vehicle(), "--out",
                                 out, "--profiles-out", profiles, "--detail", "1:4", path)
        self.assert_png(result, out)
        table = np.genfromtxt(profiles, delimiter=",", names=True)
        np.testing.assert_allclose(table["station_m"], 1.0 + 0.5 * np.arange(7))
        for row in ("LO", "LI", "RI", "RO"):
            np.testing.assert_allclose(table[f"p_{row}_m"], [0, 0, 0.1, 0.2, 0.1, 0, 0])

    def test_terrain_bad_input_is_one_line(self):
        out = self.path("t.png")
        vehicle = self.write_vehicle()
        bad, _ = self.write_twist(lambda x, y: math.nan if x > 5 else 0.0)
        result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out, bad)
        self.assert_input_error(result, out, "twist.csv", "row 54", "not a finite number")  # x = 5.1: file line 3 + 51
        terrain, _ = self.write_twist()
        no_keys = self.path("no_keys.yaml")
        with open(no_keys, "w") as f:
            f.write("running_gear: {}\n")
        result = self.run_script("plot_terrain.py", "--vehicle", no_keys, "--out", out, terrain)
        self.assert_input_error(result, out, "no_keys.yaml", "track_centre_distance")
        # Another unit is refused as tvd refuses it, not read as metres (2800 mm: rows at 1400 m).
        in_mm = self.path("in_mm.yaml")
        with open(vehicle) as f, open(in_mm, "w") as g:
            g.write(f.read().replace("{value: 2.8, unit: m", "{value: 2800, unit: mm"))
        result = self.run_script("plot_terrain.py", "--vehicle", in_mm, "--out", out, terrain)
        self.assert_input_error(result, out, "in_mm.yaml",
                                "running_gear.track_centre_distance: unit must be m, got 'mm'")
        result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out,
                                 "--detail", "3:1", terrain)
        self.assert_input_error(result, out, "--detail", "X0 < X1")
        result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out,
                                 "--profiles-out", self.path("p.txt"), terrain)
        self.assert_input_error(result, out, "--profiles-out", ".csv")
        # The input is never overwritten by the profiles.
        with open(terrain) as f:
            before = f.read()
        result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out,
                                 "--profiles-out", terrain, terrain)
        self.assert_input_error(result, out, "would be overwritten")
        with open(terrain) as f:
            self.assertEqual(f.read(), before)
        # Malformed YAML terrains: one line naming the key, never a traceback.
        for text, words in (("heights: 5\nspacing: 1\n", "heights"),
                            ("heights: []\nspacing: 1\n", "at least two stations"),
                            ("y: [0]\nheights: [[]]\nspacing: 1\n", "at least two stations"),
                            ("heights: [[[0, 1]]]\nspacing: 1\n", "heights"),
                            ("y: 0.5\nheights: [[0, 1]]\nspacing: 1\n", "y"),
                            ("heights: [0, 1]\nx: 5\n", "x"),
                            ("heights: [0, 1]\nx: [0, 1]\nspacing: 1\n", "exactly one"),
                            ("heights: [[0, 1], [0, 2]]\nspacing: 1\n", "heights")):
            bad_yaml = self.path("bad.yaml")
            with open(bad_yaml, "w") as f:
                f.write(text)
            result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out, bad_yaml)
            self.assert_input_error(result, out, "bad.yaml", *([words] if words else []))
        result = self.run_script("plot_terrain.py", "--vehicle", vehicle, "--out", out,
                                 self.path("terrain.txt"))
        self.assert_input_error(result, out, ".csv, .yaml or .yml")

    def test_terrain_csv_with_a_byte_order_mark_keeps_its_first_row(self):
        bom = self.path("bom.csv")
        with open(bom, "wb") as f:
            f.write(b"\xef\xbb\xbf0,0\n1,1\n2,2\n")
        out, profiles = self.path("bom.png"), self.path("bom_p.csv")
        result = self.run_script("plot_terrain.py", "--vehicle", self.write_vehicle(), "--out",
                                 out, "--profiles-out", profiles, "--detail", "0:2", bom)
        self.assert_png(result, out)
        table = np.genfromtxt(profiles, delimiter=",", names=True)
        np.testing.assert_allclose(table["station_m"], [0, 1, 2])
        np.testing.assert_allclose(table["p_LO_m"], [0, 1, 2])

    # plot_masters.py (Fig. 12)

    def write_masters(self, name, groups=None, positions=None, masters=None):
        """A reduced model's master variables as `tvd reduce --out` writes them."""
        if groups is None:
            groups = ["road input"] * 4 + ["hull"] + ["wheel arm"] * 2 + ["MoGeSeC 1", "MoGeSeC 2"]
        n = len(groups)
        if positions is None:
            positions = np.column_stack([np.linspace(-2, 2, n), np.zeros(n), np.linspace(0, 1, n)])
        if masters is None:
            masters = np.column_stack([np.arange(1, n + 1), [2] * (n - 1) + [1]])  # last: uy
        path = self.path(name)
        scipy.io.savemat(path, {"master_positions": positions, "masters": masters,
                                "master_groups": np.array(groups, dtype=object).reshape(-1, 1),
                                "M_R": np.eye(n)})
        return path

    def test_masters_two_models(self):
        out = self.path("fig12.png")
        result = self.run_script("plot_masters.py", "--out", out,
                                 f"untracked={self.write_masters('u.mat')}",
                                 f"tracked={self.write_masters('t.mat')}")
        self.assert_png(result, out)

    def test_masters_bad_input_is_one_line(self):
        out = self.path("fig12.png")
        old = self.path("old.mat")
        scipy.io.savemat(old, {"M_R": np.eye(2), "masters": np.ones((2, 2))})
        result = self.run_script("plot_masters.py", "--out", out, old)
        self.assert_input_error(result, out, "old.mat", "no master_positions, master_groups")
        ragged = self.write_masters("ragged.mat", positions=np.zeros((3, 3)))
        result = self.run_script("plot_masters.py", "--out", out, ragged)
        self.assert_input_error(result, out, "ragged.mat", "do not match")
        empty = self.write_masters("empty.mat", groups=[], positions=np.zeros((0, 3)),
                                   masters=np.zeros((0, 2)))
        result = self.run_script("plot_masters.py", "--out", out, empty)
        self.assert_input_error(result, out, "empty.mat", "no master DOFs")
        nan = self.write_masters("nan.mat", positions=np.full((9, 3), np.nan))
        result = self.run_script("plot_masters.py", "--out", out, nan)
        self.assert_input_error(result, out, "nan.mat", "non-finite")

    # plot_ground_pressure.py

    def write_statics(self, name, **changes):
        """A small `tvd statics --json` document: 3 assemblies and 2 wheels per side."""
        doc = {"contact": "unilateral", "nominal_ground_pressure_pa": 9e4,
               "mean_peak_pressure_pa": 2.6e5, "rowland_mean_maximum_pressure_pa": 2.4e5,
               "track_assemblies": [{"side": side, "x_m": x, "pressure_pa": p}
                                    for side in ("left", "right")
                                    for x, p in ((0.5, 2.6e5), (0.0, 1e3), (-0.5, 2.6e5))],
               "road_wheels": [{"name": f"road_wheel_{side}_{k}", "x_m": 0.5 - k + 1}
                               for side in ("left", "right") for k in (1, 2)]}
        doc.update(changes)
        path = self.path(name)
        with open(path, "w") as f:
            f.write(doc if isinstance(doc, str) else json.dumps(doc))
        return path

    def write_ride(self, name, **changes):
        """A small `tvd ride --json` document: two points, three runs, one limit of each kind."""
        limit = {"reached": {"status": "reached", "speed_kmh": 15.0},
                 "not": {"status": "not_reached", "speed_kmh": None, "bracket_kmh": [20.0, 20.0]}}
        doc = {"track": "road_C", "points": ["hull", "crew_seat"], "power_limit_w": 6.0,
               "peak_limit_g": 2.5, "peak_lowpass_hz": 30.0,
               "runs": [{"speed_kmh": v, "in_sweep": v != 15.0,
                         "points": [{"point": p, "absorbed_power_w": w, "peak_up_g": g}
                                    for p in ("hull", "crew_seat")]}
                        for v, w, g in ((10.0, 2.0, 1.0), (15.0, 6.0, 2.0), (20.0, 9.0, 2.4))],
               "limits": [{"point": p, "absorbed_power": limit["reached"],
                           "peak_acceleration": limit["not"]} for p in ("hull", "crew_seat")]}
        doc.update(changes)
        path = self.path(name)
        with open(path, "w") as f:
            json.dump(doc, f)
        return path

    def test_ride_two_files_and_chosen_points(self):
        out = self.path("ride.png")
        result = self.run_script("plot_ride.py", "--out", out, f"C={self.write_ride('c.json')}",
                                 self.write_ride("d.json", peak_lowpass_hz=0.0))
        self.assert_png(result, out)
        out = self.path("seat.png")
        result = self.run_script("plot_ride.py", "--out", out, "--points", "crew_seat",
                                 self.write_ride("c.json"))
        self.assert_png(result, out)

    def write_spectral_ride(self, name, **changes):
        """A small `tvd ride --iso8608 C --json` document: the absorbed power only (no peaks)."""
        doc = {"method": "spectral", "road": {"name": "iso8608_C_psd"},
               "points": ["hull", "crew_seat"], "power_limit_w": 6.0,
               "runs": [{"speed_kmh": v, "in_sweep": True,
                         "points": [{"point": p, "absorbed_power_w": w, "weighted_rms_z_m_s2": 1.0,
                                     "rms_z_m_s2": 1.5} for p in ("hull", "crew_seat")]}
                        for v, w in ((10.0, 2.5), (15.0, 6.0), (20.0, 8.0))],
               "limits": [{"point": p, "absorbed_power": {"status": "reached", "speed_kmh": 15.0}}
                          for p in ("hull", "crew_seat")]}
        doc.update(changes)
        path = self.path(name)
        with open(path, "w") as f:
            json.dump(doc, f)
        return path

    def test_ride_spectral_alone_and_beside_a_time_domain_file(self):
        # Spectral alone: the power panel only; beside a time-domain file: both panels, the
        # spectral curve on the first.
        out = self.path("spectral.png")
        result = self.run_script("plot_ride.py", "--out", out, self.write_spectral_ride("s.json"))
        self.assert_png(result, out)
        out = self.path("both.png")
        result = self.run_script("plot_ride.py", "--out", out, "spectral=" + self.path("s.json"),
                                 f"time={self.write_ride('t.json')}", "--points", "crew_seat")
        self.assert_png(result, out)
        # A spectral document needs what it has: the power limit, a status per point.
        bad = self.write_spectral_ride("nolimit.json")
        with open(bad) as f:
            doc = json.load(f)
        del doc["power_limit_w"]
        with open(bad, "w") as f:
            json.dump(doc, f)
        result = self.run_script("plot_ride.py", "--out", out + ".png", bad)
        self.assert_input_error(result, out + ".png", "nolimit.json", "tvd ride --json", "power_limit_w")
        status = self.write_spectral_ride("sstatus.json", limits=[{"point": "hull", "absorbed_power": {}}])
        result = self.run_script("plot_ride.py", "--out", out + ".png", status)
        self.assert_input_error(result, out + ".png", "sstatus.json", "limits[0].absorbed_power")
        # A time-domain document still needs its peaks.
        nopeak = self.write_ride("nopeak.json", limits=[{"point": "hull", "absorbed_power": {
            "status": "reached", "speed_kmh": 15.0}}])
        result = self.run_script("plot_ride.py", "--out", out + ".png", nopeak)
        self.assert_input_error(result, out + ".png", "nopeak.json", "limits[0].peak_acceleration")

    def test_ride_bad_input_is_one_line(self):
        out = self.path("ride.png")
        statics = self.write_statics("statics.json")
        result = self.run_script("plot_ride.py", "--out", out, statics)
        self.assert_input_error(result, out, "statics.json", "tvd ride --json", "points")
        ride = self.write_ride("r.json")
        result = self.run_script("plot_ride.py", "--out", out, "--points", "moon", ride)
        self.assert_input_error(result, out, "--points", "'moon'")
        runs = self.write_ride("runs.json", runs=[{"speed_kmh": 10, "points": [{"point": "moon"}]}])
        result = self.run_script("plot_ride.py", "--out", out, runs)
        self.assert_input_error(result, out, "runs.json", "runs[0].points[0]")
        nan = self.write_ride("nan.json", runs=[{"speed_kmh": None, "points": []}])
        result = self.run_script("plot_ride.py", "--out", out, nan)
        self.assert_input_error(result, out, "nan.json", "runs[0].speed_kmh", "not a finite number")
        status = self.write_ride("status.json", limits=[{"point": "hull", "absorbed_power": {}}])
        result = self.run_script("plot_ride.py", "--out", out, status)
        self.assert_input_error(result, out, "status.json", "limits[0].absorbed_power")
        for key in ("points", "runs", "limits"):
            scalar = self.write_ride(f"{key}.json", **{key: 5})
            result = self.run_script("plot_ride.py", "--out", out, scalar)
            self.assert_input_error(result, out, f"{key}.json", key)
        result = self.run_script("plot_ride.py", "--out", out, self.path("missing.json"))
        self.assert_input_error(result, out, "missing.json")

    def test_ground_pressure_two_runs(self):
        out = self.path("ground.png")
        result = self.run_script("plot_ground_pressure.py", "--out", out,
                                 f"unilateral={self.write_statics('u.json')}",
                                 self.write_statics("b.json", contact="bilateral"))
        self.assert_png(result, out)

    def test_ground_pressure_bad_input_is_one_line(self):
        out = self.path("ground.png")
        bad = self.path("bad.json")
        with open(bad, "w") as f:
            f.write("{not json")
        result = self.run_script("plot_ground_pressure.py", "--out", out, bad)
        self.assert_input_error(result, out, "bad.json", "not JSON")
        frf = self.write_statics("frf.json")
        with open(frf, "w") as f:
            json.dump({"outputs": []}, f)
        result = self.run_script("plot_ground_pressure.py", "--out", out, frf)
        self.assert_input_error(result, out, "frf.json", "tvd statics --json", "track_assemblies")
        nan = self.write_statics("nan.json", nominal_ground_pressure_pa=None)
        result = self.run_script("plot_ground_pressure.py", "--out", out, nan)
        self.assert_input_error(result, out, "nan.json", "nominal_ground_pressure_pa",
                                "not a finite number")
        side = self.write_statics("side.json", track_assemblies=[{"side": "middle", "x_m": 0,
                                                                   "pressure_pa": 1}])
        result = self.run_script("plot_ground_pressure.py", "--out", out, side)
        self.assert_input_error(result, out, "side.json", "track_assemblies[0]")
        none = self.write_statics("none.json", track_assemblies=[])
        result = self.run_script("plot_ground_pressure.py", "--out", out, none)
        self.assert_input_error(result, out, "none.json", "no track assembly")
        result = self.run_script("plot_ground_pressure.py", "--out", out, self.path("missing.json"))
        self.assert_input_error(result, out, "missing.json")
        # Lists that are not lists, a wheel name that is not a string: one line, not a traceback.
        for key in ("track_assemblies", "road_wheels"):
            scalar = self.write_statics(f"{key}.json", **{key: 5})
            result = self.run_script("plot_ground_pressure.py", "--out", out, scalar)
            self.assert_input_error(result, out, f"{key}.json", f"{key} is not a list")
        name = self.write_statics("name.json", road_wheels=[{"name": 5, "x_m": 0.0}])
        result = self.run_script("plot_ground_pressure.py", "--out", out, name)
        self.assert_input_error(result, out, "name.json", "road_wheels[0]")

    # plot_modes.py (Fig. 11)

    def write_modes_dir(self, name, modes=2):
        """What `tvd modes --vehicle --out DIR` writes, for a 5-node bar: modes.csv and
        node_shapes.csv (mode k bends it with k half waves)."""
        directory = self.path(name)
        os.makedirs(directory)
        with open(os.path.join(directory, "modes.csv"), "w") as f:
            f.write("mode,frequency_hz,eigenvalue_rad2_s2,type\n")
            for k in range(1, modes + 1):
                f.write(f"{k},{2.5 * k},{(2 * np.pi * 2.5 * k) ** 2},bounce\n")
        x = np.linspace(-2, 2, 5)
        with open(os.path.join(directory, "node_shapes.csv"), "w") as f:
            f.write("node,part,x_m,y_m,z_m" + "".join(f",mode_{k}_ux,mode_{k}_uy,mode_{k}_uz"
                                                     for k in range(1, modes + 1)) + "\n")
            for i, xi in enumerate(x):
                values = "".join(f",0,0,{np.sin(k * np.pi * (xi + 2) / 4)}"
                                 for k in range(1, modes + 1))
                f.write(f"{i + 1},track assembly left {i + 1} link,{xi},1.4,0.1{values}\n")
        return directory

    def test_modes_two_rows(self):
        out = self.path("fig11.png")
        u, t = self.write_modes_dir("mu"), self.write_modes_dir("mt")
        result = self.run_script("plot_modes.py", "--out", out, f"un-tracked={u}:1", f"{t}:2")
        self.assert_png(result, out)

    def test_modes_bad_input_is_one_line(self):
        out = self.path("fig11.png")
        u = self.write_modes_dir("mu")
        result = self.run_script("plot_modes.py", "--out", out, f"{u}:3")
        self.assert_input_error(result, out, "no mode 3", "1..2")
        result = self.run_script("plot_modes.py", "--out", out, f"{self.path('none')}:1")
        self.assert_input_error(result, out, "none", "not a directory")
        result = self.run_script("plot_modes.py", "--out", out, u)
        self.assert_input_error(result, out, "DIR:MODE")
        result = self.run_script("plot_modes.py", "--out", out, "--scale", "-1", f"{u}:1")
        self.assert_input_error(result, out, "--scale")
        def not_a_number(lines):
            lines[2] = lines[2].replace(",0.1,", ",nan,", 1)
        rewrite_lines(os.path.join(u, "node_shapes.csv"), not_a_number)
        result = self.run_script("plot_modes.py", "--out", out, f"{u}:1")
        self.assert_input_error(result, out, "node_shapes.csv", "z_m")

    def test_modes_front_view_shows_roll(self):
        """The front view plots y against z (review 126: the side and top views alone could not
        show a roll): two mounts at y = +-1 m moving -+z are drawn where they moved."""
        plot_modes = script_module("plot_modes")
        import matplotlib.pyplot as plt
        parts = ["hull", "spider left", "spider right"]
        positions = np.array([[0.0, 0.0, 1.5], [0.0, 1.0, 0.5], [0.0, -1.0, 0.5]])
        shape = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.1], [0.0, 0.0, -0.1]])  # roll, left up
        fig, ax = plt.subplots()
        plot_modes.draw(ax, positions, shape, parts, 0.4, "mode", 2, horizontal=1)
        moved = ax.collections[1].get_offsets()  # the deformed nodes, smallest first
        np.testing.assert_allclose(sorted(map(tuple, moved)),
                                   [(-1.0, 0.1), (0.0, 1.5), (1.0, 0.9)])
        self.assertEqual((ax.get_xlabel(), ax.get_ylabel()), ("y [m] (left)", "z [m] (up)"))
        plt.close(fig)

    def test_modes_vehicle_normalisation_scales_on_the_hull_and_clips_the_chain(self):
        plot_modes = script_module("plot_modes")
        parts = ["hull", "road_wheel_left_1 centre", "track assembly left 3 link",
                 "track assembly left 4 sole"]
        positions = np.zeros((4, 3))
        shape = np.array([[0.0, 0.0, 0.02], [0.0, 0.0, 0.05], [1.0, 0.0, 0.0], [0.0, 0.0, 0.5]])
        magnitude = np.linalg.norm(shape, axis=1)
        self.assertEqual(plot_modes.reference_magnitude(parts, magnitude, "mode"), 1.0)
        self.assertEqual(plot_modes.reference_magnitude(parts, magnitude, "vehicle"), 0.05)
        # Nothing off the chain moves: the mode's own largest.
        still = shape.copy()
        still[:2] = 0.0
        self.assertEqual(plot_modes.reference_magnitude(parts, np.linalg.norm(still, axis=1),
                                                        "vehicle"), 1.0)
        drawn = plot_modes.drawn_positions(positions, shape, 0.4, 0.05)
        np.testing.assert_allclose(drawn[0], [0.0, 0.0, 0.16])  # 0.02 of 0.05 -> 0.4 * 0.4
        np.testing.assert_allclose(drawn[1], [0.0, 0.0, 0.4])   # the reference, at the scale
        np.testing.assert_allclose(drawn[2], [0.4, 0.0, 0.0])   # 20x the reference, clipped
        np.testing.assert_allclose(drawn[3], [0.0, 0.0, 0.4])
        np.testing.assert_allclose(plot_modes.drawn_positions(positions, shape, 0.4, 0.0), 0.0)
        # The option end to end, and a bad value refused.
        out = self.path("fig11.png")
        u = self.write_modes_dir("mu")
        self.assert_png(self.run_script("plot_modes.py", "--out", out, "--normalise", "vehicle",
                                        f"{u}:1"), out)
        result = self.run_script("plot_modes.py", "--out", out, "--normalise", "hull", f"{u}:1")
        self.assertEqual(result.returncode, INPUT_ERROR_STATUS, result.stderr)
        self.assertIn("--normalise", result.stderr)

    # ros_demo_summary.py (its bag reading needs the node's messages; the wheel choice does not)

    def test_demo_summary_plots_the_front_middle_and_rear_left_wheels(self):
        sys.path.insert(0, SCRIPTS)
        try:
            import ros_demo_summary
        finally:
            sys.path.remove(SCRIPTS)

        def wheels(axles, prefix=""):
            return sorted(f"{prefix}road_wheel_{side}_{k}" for side in ("left", "right")
                          for k in range(1, axles + 1))
        pick = ros_demo_summary.plotted_wheels
        self.assertEqual(pick(wheels(7)),
                         ["road_wheel_left_1", "road_wheel_left_4", "road_wheel_left_7"])
        self.assertEqual(pick(wheels(6)),  # the rear wheel too, not only _1 and _4
                         ["road_wheel_left_1", "road_wheel_left_4", "road_wheel_left_6"])
        self.assertEqual(pick(wheels(10, "tank/")),  # numbers, not text order (_10 after _1)
                         ["tank/road_wheel_left_1", "tank/road_wheel_left_6",
                          "tank/road_wheel_left_10"])
        self.assertEqual(pick(wheels(2)), ["road_wheel_left_1", "road_wheel_left_2"])
        self.assertEqual(pick([]), [])


if __name__ == "__main__":
    sys.exit(junit_runner.main(PlotScriptsTest, "plot_scripts", __doc__))
