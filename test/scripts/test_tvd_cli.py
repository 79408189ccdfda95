#!/usr/bin/python3
"""End-to-end tests of the `tvd` command line on the bundled vehicle (un-tracked variant: fast).

What an engineer scripts against: the JSON fields and files each subcommand promises, their
consistency with each other (CSV vs JSON, .mat vs JSON), closed-form checks (weight = m g, ground
reactions = weight, the hill's height), and one clear error with exit status 2 for bad input.
Run as
    /usr/bin/python3 test/scripts/test_tvd_cli.py --tvd PATH/TO/tvd [--xml OUTDIR/tvd_cli.xml]
"""
import csv
import glob
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np
import scipy.io
import scipy.linalg
import yaml
from scipy.signal import bilinear, lfilter

import junit_runner

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
VEHICLE = os.path.join(ROOT, "config", "vehicles", "paper_vehicle.yaml")
# A vehicle of our own (5 axles, no crew_seat point): nothing may assume the bundled one.
OWN_VEHICLE = os.path.join(ROOT, "test", "data", "light_5_axle.yaml")
GRAVITY = 9.80665  # [m/s^2], the description's gravity
INPUT_ERROR_STATUS = 2
TVD = None  # set from --tvd


RANGE_WARNING = "beyond the linear model's range"


def input_warnings(warnings):
    """The warnings about the input: all but the bonded ground contact's range (which most runs
    over the paper's tracks reach, and test_simulate_says_when_the_linear_model_leaves_its_range
    checks)."""
    return [w for w in warnings if not w.startswith(RANGE_WARNING)]


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], np.array(rows[1:], dtype=float)
    return header, body


def iso2631_transition_weighting(f, corner_hz):
    """|W(j 2 pi f)|^2 of ISO 2631-1's Wd (corner 2 Hz) or We (1 Hz): the 0.4 Hz high-pass and
    100 Hz low-pass (Butterworth) and the a-v transition (1 + s/w) / (1 + s/(0.63 w) + s^2/w^2),
    with no upward step."""
    s = 2j * np.pi * np.asarray(f)
    w1, w2, w = 2 * np.pi * 0.4, 2 * np.pi * 100.0, 2 * np.pi * corner_hz
    q1 = 1 / np.sqrt(2)
    h = (s ** 2 / (s ** 2 + w1 * s / q1 + w1 ** 2) * w2 ** 2 / (s ** 2 + w2 * s / q1 + w2 ** 2)
         * (1 + s / w) / (1 + s / (0.63 * w) + s ** 2 / w ** 2))
    return np.abs(h) ** 2


def read_terrain_csv(path):
    """A terrain CSV as `tvd terrain` writes it (comment lines, the header x,y_1,...,y_m, then
    the station and the heights per row): (lateral positions, stations, heights)."""
    with open(path) as f:
        lines = [line.strip().split(",") for line in f if line.strip() and not line.startswith("#")]
    rows = np.array(lines[1:], dtype=float)
    return np.array(lines[0][1:], dtype=float), rows[:, 0], rows[:, 1:]


def documented_checksum(path):
    """FNV-1a 64 over each variable before `checksum`, in file order, as
    doc/reduced_model_file.md defines it: name, kind (0 matrix, 1 text, 2 list of texts), then
    rows, columns and column-major doubles, or the text, or the count and each text; counts and
    lengths 8 bytes little-endian, before the bytes they count."""
    h = 14695981039346656037

    def add(data):
        nonlocal h
        for b in data:
            h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF

    def count(n):
        add(struct.pack("<Q", n))

    def text(t):
        data = t.encode("utf-8")
        count(len(data))
        add(data)
    m = scipy.io.loadmat(path)
    for name, _, kind in scipy.io.whosmat(path):
        if name == "checksum":
            break
        value = m[name]
        text(name)
        if kind == "cell":
            count(2)
            cells = [str(np.ravel(c)[0]) if np.size(c) else "" for c in np.ravel(value, order="F")]
            count(len(cells))
            for c in cells:
                text(c)
        elif kind == "char":
            count(1)
            text(str(value[0]) if value.size else "")
        else:
            count(0)
            count(value.shape[0])
            count(value.shape[1])
            add(np.asfortranarray(value, dtype="<f8").tobytes(order="F"))
    return f"{h:016x}"


class TvdCliTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="tvd_cli_")
        cls.cache = os.path.join(cls.work, "cache")
        cls.vehicle_name = "paper_vehicle"  # the bundled description's `name`

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.work, name)

    def vehicle_with(self, name, old, new):
        """A copy of the bundled vehicle description with its one occurrence of `old` replaced
        by `new`, written as `name` in the work directory; its path."""
        with open(VEHICLE) as f:
            text = f.read()
        self.assertEqual(text.count(old), 1, old)
        path = self.path(name)
        with open(path, "w") as f:
            f.write(text.replace(old, new))
        return path

    def tvd(self, *args, status=0):
        result = subprocess.run([TVD, *args], capture_output=True, text=True, timeout=240)
        self.assertEqual(result.returncode, status,
                         f"tvd {' '.join(args)}\nstdout: {result.stdout[-2000:]}\n"
                         f"stderr: {result.stderr[-2000:]}")
        return result

    def tvd_json(self, *args):
        return json.loads(self.tvd(*args, "--json").stdout)

    def test_default_cache_directory_follows_xdg(self):
        """Without --cache-dir the reduced model is cached under $XDG_CACHE_HOME/tracked_vehicle_dynamics,
        else ~/.cache/tracked_vehicle_dynamics (README), one <variant>_<hash>.mat; the second run
        reads it instead of reducing again. A relative XDG_CACHE_HOME is ignored, as the XDG
        specification says: the cache does not follow the working directory."""
        args = ("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--max-hz", "5", "--json")
        work = self.path("work")
        os.makedirs(work)
        for name, env in (("xdg", {"XDG_CACHE_HOME": self.path("xdg_cache")}),
                          ("home", {"HOME": self.path("home")}),
                          ("relative xdg", {"XDG_CACHE_HOME": "relcache",
                                            "HOME": self.path("home2")})):
            environment = {k: v for k, v in os.environ.items() if k != "XDG_CACHE_HOME"}
            environment.update(env)
            expected = (os.path.join(env["XDG_CACHE_HOME"], "tracked_vehicle_dynamics")
                        if os.path.isabs(env.get("XDG_CACHE_HOME", ""))
                        else os.path.join(env["HOME"], ".cache", "tracked_vehicle_dynamics"))
            runs = []
            for _ in range(2):
                result = subprocess.run([TVD, *args], capture_output=True, text=True, timeout=240,
                                        env=environment, cwd=work)
                self.assertEqual(result.returncode, 0, result.stderr)
                runs.append(json.loads(result.stdout))
            files = os.listdir(expected)
            self.assertEqual(len(files), 1, (name, files))
            self.assertRegex(files[0], r"^untracked_[0-9a-f]+\.mat$", name)
            self.assertEqual([r["reduction"]["source"] for r in runs], ["computed", "cache"], name)
            for r in runs:
                self.assertEqual(r["reduction"]["file"], os.path.join(expected, files[0]), name)
            self.assertEqual(runs[0]["outputs"], runs[1]["outputs"], name)
        # --cache-dir=~/x: bash leaves the "~" after "=" (it made a directory "~" in the working
        # directory); tvd expands it as a shell would.
        result = subprocess.run([TVD, *args, "--cache-dir=~/tilde_cache"], capture_output=True,
                                text=True, timeout=240, env=dict(os.environ, HOME=self.path("home3")),
                                cwd=work)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(os.path.dirname(json.loads(result.stdout)["reduction"]["file"]),
                         os.path.join(self.path("home3"), "tilde_cache"))
        self.assertEqual(os.listdir(work), [])

    def test_modes_matrices_reproduce_the_modes_and_statics(self):
        """--matrices writes the assembled model (matrices.mat): with SciPy alone, its sparse
        (K, M) give the modes tvd reports, K q = f_g the static sag, and the identities of a
        rigid lift hold: K r_z = K_u 1 (every spring to ground at rest), r_z' M r_z = the mass,
        r_z' f_g = -m g, r_x' f_a = -m."""
        import scipy.sparse
        import scipy.sparse.linalg
        out = self.path("matrices")
        d = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "untracked", "--count", "12",
                          "--out", out, "--matrices")
        m = scipy.io.loadmat(os.path.join(out, "matrices.mat"))
        modes = scipy.io.loadmat(os.path.join(out, "modes.mat"))
        K, M, C, K_u = (scipy.sparse.csc_matrix(m[k]) for k in ("K", "M", "C", "K_u"))
        self.assertTrue(scipy.sparse.issparse(m["K"]))
        n = d["active_dofs"]
        self.assertEqual(K.shape, (n, n))
        self.assertEqual((M.shape, C.shape), ((n, n), (n, n)))
        self.assertEqual(abs(K - K.T).max(), 0.0)
        self.assertEqual(abs(M - M.T).max(), 0.0)
        np.testing.assert_array_equal(m["dof_node"], modes["dof_node"])
        np.testing.assert_array_equal(m["dof_direction"], modes["dof_direction"])
        # The lowest modes by shift-invert Lanczos on the exported matrices.
        values = np.sort(scipy.sparse.linalg.eigsh(K, 12, M, sigma=-1.0, which="LM")[0])
        np.testing.assert_allclose(values, modes["eigenvalues"].ravel(), rtol=1e-7)
        # Statics (every contact bonded: the linear model's, as tvd modes reports it).
        q = scipy.sparse.linalg.spsolve(K, m["gravity_load"].ravel())
        direction, node = m["dof_direction"].ravel(), m["dof_node"].ravel()
        hull_uz = np.flatnonzero((node == 1) & (direction == 2))
        self.assertEqual(len(hull_uz), 1)
        self.assertAlmostEqual(q[hull_uz[0]] / d["static"]["hull_sag_m"], 1.0, delta=1e-9)
        r_z, r_x = (direction == 2).astype(float), (direction == 0).astype(float)
        lift = K_u @ np.ones(K_u.shape[1])
        self.assertLess(np.linalg.norm(K @ r_z - lift), 1e-9 * np.linalg.norm(lift))
        self.assertAlmostEqual(r_z @ (M @ r_z) / d["mass_kg"], 1.0, delta=1e-12)
        self.assertAlmostEqual(-(r_z @ m["gravity_load"].ravel()) / (9.81 * d["mass_kg"]), 1.0,
                               delta=1e-3)  # g as the description gives it, ~9.81
        self.assertAlmostEqual(-(r_x @ m["travel_load"].ravel()) / d["mass_kg"], 1.0, delta=1e-12)
        inputs = K_u.shape[1]
        self.assertEqual(m["input_node"].shape, (inputs, 1))
        self.assertEqual(m["input_station"].shape, (inputs, 1))
        self.assertEqual(m["node_position"].shape, (m["node_id"].size, 3))
        # Each input samples the road at its station: an un-tracked wheel's three contact springs
        # (0.07 m apart) all at the wheel centre's, the middle one's x.
        x = dict(zip(m["node_id"].ravel(), m["node_position"][:, 0]))
        node_x = np.array([x[i] for i in m["input_node"].ravel()])
        station = m["input_station"].ravel()
        self.assertLessEqual(np.abs(station - node_x).max(), 0.07 + 1e-12)
        np.testing.assert_array_equal(station[1::3], node_x[1::3])
        self.assertEqual((str(m["damping_model"][0]), float(m["modal_damping_ratio"][0, 0])),
                         ("modal", 0.05))
        self.assertEqual(str(m["variant"][0]), "untracked")
        # Without --out there is nowhere to write it.
        self.assertIn("--matrices requires --out",
                      self.tvd("modes", "--vehicle", VEHICLE, "--matrices", status=2).stderr)

    def test_modes_json_and_statics(self):
        count = 12
        d = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "untracked",
                          "--count", str(count), "--out", self.path("modes"))
        self.assertEqual((d["vehicle"], d["vehicle_file"]), (self.vehicle_name, VEHICLE))
        for key in ("frequencies_hz", "mode_types", "active_dofs", "mass_kg", "solve_seconds",
                    "static"):
            self.assertIn(key, d)
        f = np.array(d["frequencies_hz"])
        self.assertEqual(len(f), count)
        self.assertEqual(len(d["mode_types"]), count)
        self.assertGreater(f[0], 0.0)  # on its ground springs: no rigid-body mode
        self.assertTrue(np.all(np.diff(f) >= 0.0))
        s = d["static"]
        # Weight = m g; the ground carries all of it; the hull sinks.
        self.assertAlmostEqual(s["weight_n"] / (d["mass_kg"] * GRAVITY), 1.0, delta=1e-9)
        self.assertLess(abs(s["ground_reaction_sum_n"] - s["weight_n"]) / s["weight_n"], 1e-6)
        self.assertLess(s["relative_balance_error"], 1e-6)
        self.assertLess(s["hull_sag_m"], 0.0)
        # Symmetric left and right: no static roll; the trailing arms pitch it a little.
        self.assertLess(abs(s["hull_roll_deg"]), 1e-6)
        self.assertGreater(abs(s["hull_pitch_deg"]), 1e-6)
        wheels = np.array(s["road_wheel_loads_n"])
        self.assertEqual(len(wheels), 14)
        self.assertTrue(np.all(wheels > 0.0))
        self.assertLess(wheels.sum(), s["weight_n"])  # the wheels carry the hull, not themselves
        # --out: the same frequencies in the .mat file.
        mats = [n for n in os.listdir(self.path("modes")) if n.endswith(".mat")]
        self.assertTrue(mats, os.listdir(self.path("modes")))
        m = scipy.io.loadmat(os.path.join(self.path("modes"), mats[0]))
        stored = [k for k in m if "freq" in k]
        self.assertTrue(stored, sorted(m))
        np.testing.assert_allclose(np.ravel(m[stored[0]])[:count], f, rtol=1e-9)
        # The kinetic-energy shares that name each type: hull (with what rides on it), wheels
        # and track add up to the mode's energy; the hull's own components are m phi^2 of its
        # node (the first six DOFs, at its CoG: Table 1's mass and inertias) of the mass-
        # normalised shapes; the types follow them; the JSON, modes.csv and modes.mat agree.
        e = d["energy_shares"]
        total = np.array(e["hull"]) + np.array(e["wheels"]) + np.array(e["track"])
        np.testing.assert_allclose(total, 1.0, atol=1e-9)
        hull_mass = np.array([30300.0] * 3 + [3.9e4, 1.4e5, 1.6e5])
        components = np.array([e["hull_" + c] for c in ("longitudinal", "lateral", "bounce",
                                                         "roll", "pitch", "yaw")]).T
        np.testing.assert_allclose(components, hull_mass * m["shapes"][:6, :count].T ** 2,
                                   rtol=0, atol=1e-9)
        self.assertTrue(np.all(components.sum(axis=1) <= np.array(e["hull"]) + 1e-12))
        for j, label in enumerate(d["mode_types"]):
            shares = (e["hull"][j], e["wheels"][j], e["track"][j])
            if label.startswith("wheel bounce"):
                self.assertGreater(e["wheels"][j], 0.9, label)
            elif not label.startswith("track"):
                self.assertEqual(max(shares), e["hull"][j], label)
                # The named (strongest) component is the largest of the hull's.
                strongest = ("longitudinal", "lateral", "bounce", "roll", "pitch", "yaw")[
                    int(np.argmax(components[j]))]
                self.assertTrue(label.startswith(strongest), (label, components[j]))
        np.testing.assert_allclose(m["energy_shares"],
                                   np.array([e["hull"], e["wheels"], e["track"]]).T, atol=1e-10)
        np.testing.assert_allclose(m["hull_component_energy_shares"], components, atol=1e-10)
        with open(os.path.join(self.path("modes"), "modes.csv")) as stream:
            rows = list(csv.DictReader(stream))
        np.testing.assert_allclose([float(r["hull_pitch_energy_share"]) for r in rows],
                                   e["hull_pitch"], atol=1e-10)
        self.assertEqual([r["type"] for r in rows], d["mode_types"])

    def test_hand_estimate_beside_the_model_and_its_warnings(self):
        """modes and statics give the hull on its torsion bars alone (wheel rate k_t / (a cos b)^2
        in series with the pads' k_z, n wheels, the hull and what is rigid with it) in the closed
        form recomputed here from the description, and warn when the model is far stiffer: never
        on the bundled vehicle, on the light fixture (the paper's chain and locked wheels on a
        10 t vehicle) both ways, and no longer for its rolling wheels guided laterally."""
        with open(VEHICLE) as f:
            v = yaml.safe_load(f)
        value = lambda section, key: float(v[section][key]["value"])
        lever = value("suspension", "arm_length") * np.cos(np.radians(value("suspension", "arm_angle")))
        rate = value("suspension", "torsion_bar_stiffness") / lever ** 2
        kz = value("track_assembly", "compression_stiffness")
        series = rate * kz / (rate + kz)
        wheels = 2 * int(value("running_gear", "axle_count"))
        for variant, mass in (("untracked", value("hull", "mass")),
                              ("tracked", value("hull", "mass") + 2 * (
                                  value("sprocket", "mass") + value("idler", "mass")))):
            modes = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", variant, "--count", "6")
            statics = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", variant)
            for e in (modes["wheel_rate_estimate"], statics["wheel_rate_estimate"]):
                self.assertAlmostEqual(e["wheel_rate_n_m"] / rate, 1.0, delta=1e-9)  # JSON: 10 digits
                self.assertAlmostEqual(e["series_rate_n_m"] / series, 1.0, delta=1e-9)
                self.assertEqual((e["road_wheels"], e["sprung_mass_kg"]), (wheels, mass))
                self.assertAlmostEqual(e["sag_m"] / (mass * GRAVITY / (wheels * series)), 1.0,
                                       delta=1e-9)
                self.assertAlmostEqual(
                    e["bounce_hz"] / (np.sqrt(wheels * series / mass) / (2 * np.pi)), 1.0,
                    delta=1e-9)
                # The attitude m g x_G / (k_s sum x_i^2), axles about the wheelbase's middle;
                # un-tracked x_G is the hull's CoG.
                axles = wheels // 2
                spacing = value("running_gear", "axle_spacing")
                second = 2 * sum(((axles - 1) / 2 - j) ** 2 for j in range(axles)) * spacing ** 2
                if variant == "untracked":
                    self.assertAlmostEqual(e["cog_x_m"], value("hull", "cog_x"), delta=1e-12)
                self.assertAlmostEqual(
                    np.radians(e["pitch_deg"]) * series * second / (mass * GRAVITY * e["cog_x_m"]),
                    1.0, delta=1e-9)
            self.assertFalse([w for w in statics["warnings"] if "torsion bars" in w], statics)
            e = modes["wheel_rate_estimate"]
            # The whole line, in both commands' text.
            line = (f"torsion bars and pads alone (hand estimate): sag {e['sag_m'] * 1e3:.1f} "
                    f"mm, bounce {e['bounce_hz']:.2f} Hz (wheel rate {rate:.6g} N/m, {wheels} "
                    f"road wheels, {mass:g} kg), pitch {e['pitch_deg']:.2f} deg (positive nose "
                    f"down; its CoG x {e['cog_x_m']:.3f} m)")
            for command in ("modes", "statics"):
                text = self.tvd(command, "--vehicle", VEHICLE, "--variant", variant,
                                *(["--count", "6"] if command == "modes" else []))
                self.assertIn(line, text.stdout, command)
                self.assertNotIn("torsion bars", text.stderr, command)
            # The sag is down (z < 0), printed as a positive sag beside its z.
            sag = statics["hull_sag_m"]
            self.assertLess(sag, 0.0)
            self.assertIn(f"hull at rest: sag {-sag * 1e3:.3f} mm (z {sag * 1e3:.3f} mm)",
                          text.stdout)
        self.assertAlmostEqual(modes["wheel_rate_estimate"]["sag_m"], 0.0162, delta=5e-5)

        light = self.tvd_json("statics", "--vehicle", OWN_VEHICLE, "--variant", "tracked")
        carried = [w for w in light["warnings"] if "less than a fifth" in w]
        self.assertEqual(len(carried), 1, light["warnings"])
        self.assertIn("track_assembly.link_member_bending_inertia", carried[0])
        # modes says it too, of the tracked variant's own estimate (the chain wheels' mass).
        r = self.tvd("modes", "--vehicle", OWN_VEHICLE, "--variant", "tracked", "--count", "8")
        self.assertIn("tvd: warning: the hull sags 1.19 mm under its weight, less than a fifth of "
                      "the 39.5 mm of the hull with its chain wheels (10200 kg)", r.stderr)
        # ... and in its JSON, as statics does; mac names the variant.
        sag = ("the hull sags 1.19 mm under its weight, less than a fifth of the 39.5 mm of the "
               "hull with its chain wheels (10200 kg)")
        modes = self.tvd_json("modes", "--vehicle", OWN_VEHICLE, "--variant", "tracked",
                              "--count", "8")
        self.assertEqual(len([w for w in modes["warnings"] if w.startswith(sag)]), 1,
                         modes["warnings"])
        mac = self.tvd_json("mac", "--vehicle", OWN_VEHICLE, "--count", "8")
        self.assertEqual(len([w for w in mac["warnings"] if w.startswith("tracked: " + sag)]), 1,
                         mac["warnings"])
        self.assertEqual(self.tvd_json("modes", "--vehicle", VEHICLE, "--count", "6")["warnings"],
                         [])
        # Under braking the statics are another load case: no verdict on the sag there.
        braking = self.tvd_json("statics", "--vehicle", OWN_VEHICLE, "--variant", "tracked",
                                "--accel", "-1")
        self.assertLess(-braking["hull_sag_m"], 0.2 * light["wheel_rate_estimate"]["sag_m"])
        self.assertFalse([w for w in braking["warnings"] if "less than a fifth" in w],
                         braking["warnings"])
        # A hull its bonded chain holds nose up where its torsion bars would hold it nose down
        # (a front-drive carrier): statics --contact bilateral and modes (the linear model) say
        # so; statics' default contacts, which cannot pull, sit as the estimate does.
        carrier = os.path.join(ROOT, "test", "data", "front_drive_carrier.yaml")
        bonded = self.tvd_json("statics", "--vehicle", carrier, "--variant", "tracked",
                               "--contact", "bilateral")
        tilted = [w for w in bonded["warnings"] if w.startswith("the hull sits ")]
        self.assertEqual(len(tilted), 1, bonded["warnings"])
        self.assertIn(f"the hull sits {-bonded['hull_pitch_deg']:.2f} deg nose up at rest, where",
                      tilted[0])
        self.assertIn(f"would sit {bonded['wheel_rate_estimate']['pitch_deg']:.2f} deg nose down",
                      tilted[0])
        pushing = self.tvd_json("statics", "--vehicle", carrier, "--variant", "tracked")
        self.assertFalse([w for w in pushing["warnings"] if w.startswith("the hull sits ")],
                         pushing["warnings"])
        r = self.tvd("modes", "--vehicle", carrier, "--variant", "tracked", "--count", "6")
        self.assertIn("tvd: warning: " + tilted[0], r.stderr)
        r = self.tvd("modes", "--vehicle", OWN_VEHICLE, "--variant", "untracked", "--count", "8")
        self.assertIn("tvd: warning: the hull's bounce (mode ", r.stderr)
        self.assertIn("suspension.contact_shear_stiffness 2e+10 N/m", r.stderr)
        with open(OWN_VEHICLE) as f:
            text = f.read()
        start = text.index("  contact_shear_stiffness:")
        end = text.index("  guide_contact_height:")
        rolling = self.path("light_rolling.yaml")
        with open(rolling, "w") as f:
            f.write(text[:start] +
                    '  contact_shear_stiffness: {value: 1e4, unit: N/m, source: "rolling"}\n'
                    '  guide_stiffness: {value: 2e10, unit: N/m, source: "guide horns"}\n' +
                    text[end:])
        r = self.tvd("modes", "--vehicle", rolling, "--variant", "untracked", "--count", "8",
                     "--json")
        self.assertNotIn("torsion bars", r.stderr)
        d = json.loads(r.stdout)
        bounce = d["frequencies_hz"][d["mode_types"].index("bounce")]
        self.assertAlmostEqual(bounce / d["wheel_rate_estimate"]["bounce_hz"], 1.0, delta=0.1)

    def test_static_track_tension_is_reported_and_stiffens_the_top_run(self):
        """track_assembly.static_tension: the tracked model carries it (JSON track_tension_n, a
        text line in modes and statics), its free top run's first mode rises as a taut string
        (f_T^2 - f_0^2 = T / (4 mu L^2), within the 1.0-1.2 the core test measures); the
        un-tracked variant says it is not used; a negative tension is refused by key."""
        anchor = 'track_assembly:\n'
        tension = 20000.0
        tensioned = self.vehicle_with(
            "tensioned.yaml", anchor,
            anchor + f'  static_tension: {{value: {tension}, unit: N, source: "tensioner"}}\n')
        bare = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "tracked", "--count", "2")
        tight = self.tvd_json("modes", "--vehicle", tensioned, "--variant", "tracked", "--count", "2")
        self.assertEqual((bare["track_tension_n"], tight["track_tension_n"]), (0.0, tension))
        mu, span = 27.0 / 0.1615, 6.32  # the bundled chain's mass per metre; its top run [m]
        for f0, f in zip(bare["frequencies_hz"], tight["frequencies_hz"]):
            rise = (f * f - f0 * f0) / (tension / (4 * mu * span * span))
            self.assertTrue(1.0 < rise < 1.2, (f0, f, rise))
        for command, extra in (("modes", ("--count", "1")), ("statics", ())):
            out = self.tvd(command, "--vehicle", tensioned, "--variant", "tracked", *extra).stdout
            self.assertIn("track tension 20000 N per chain, a pre-stress", out)
            out = self.tvd(command, "--vehicle", tensioned, "--variant", "untracked", *extra).stdout
            self.assertIn("track tension (track_assembly.static_tension 20000 N) not used: the "
                          "un-tracked variant has no chain loop", out)
        self.assertEqual(self.tvd_json("statics", "--vehicle", tensioned,
                                       "--variant", "untracked")["track_tension_n"], 0.0)
        reduced = self.tvd_json("reduce", "--vehicle", tensioned, "--variant", "tracked")
        self.assertEqual(reduced["track_tension_n"], tension)
        # The reduced model keeps the tensioned top run (the CMS error of the full model's modes).
        self.assertAlmostEqual(reduced["band_modes"][0]["full_hz"] / tight["frequencies_hz"][0],
                               1.0, delta=1e-6)
        pushed = self.vehicle_with(
            "pushed.yaml", anchor,
            anchor + '  static_tension: {value: -1000, unit: N, source: "typo"}\n')
        r = self.tvd("modes", "--vehicle", pushed, "--variant", "tracked", status=2)
        self.assertIn("track_assembly.static_tension", r.stderr)

    def test_statics_loads_match_modes_and_files(self):
        """tvd statics: the same equilibrium as `modes`, wheel and ground loads that balance the
        weight, the per-assembly CSV/.mat equal to the JSON, and the closed-form NGP."""
        modes = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "tracked", "--count", "1")
        csv_file, mat_file = self.path("statics.csv"), self.path("statics.mat")
        d = self.tvd_json("statics", "--vehicle", VEHICLE, "--contact", "bilateral",
                          "--out", csv_file)  # tracked by default
        self.assertEqual(d["variant"], "tracked")
        self.assertEqual(d["contact"], "bilateral")
        # The mass breakdown: the same in both commands, its parts summing to the model's mass,
        # 14 road wheels of 1,200 kg and 184 links of 27 kg (Table 1, the description).
        parts = d["mass_breakdown_kg"]
        self.assertEqual(parts, modes["mass_breakdown_kg"])
        self.assertAlmostEqual(sum(parts.values()) / d["mass_kg"], 1.0, delta=1e-12)
        self.assertEqual((parts["road_wheels"], parts["track_assemblies"]), (16800.0, 184 * 27.0))
        text = self.tvd("statics", "--vehicle", VEHICLE, "--contact", "bilateral").stdout
        self.assertIn(f"mass breakdown: hull {parts['hull']:.1f} kg, road wheels 16800.0 kg, track "
                      f"assemblies 4968.0 kg", text)
        self.assertIn(f"(total {d['mass_kg']:.1f} kg)", text)
        s = modes["static"]
        self.assertAlmostEqual(d["hull_sag_m"], s["hull_sag_m"], delta=1e-12)
        self.assertAlmostEqual(d["weight_n"] / (d["mass_kg"] * GRAVITY), 1.0, delta=1e-9)
        np.testing.assert_allclose([w["load_n"] for w in d["road_wheels"]], s["road_wheel_loads_n"],
                                   rtol=1e-12)
        self.assertEqual([w["name"] for w in d["road_wheels"]][:2],
                         ["road_wheel_left_1", "road_wheel_left_2"])
        loads = np.array([a["load_n"] for a in d["track_assemblies"]])
        self.assertEqual(len(loads), 60)  # 30 per side on the ground (paper §2)
        self.assertLess(abs(loads.sum() - d["weight_n"]) / d["weight_n"], 1e-6)
        np.testing.assert_allclose(d["side_loads_n"], [d["weight_n"] / 2] * 2, rtol=1e-6)
        self.assertEqual(d["lifting_assemblies"], int((loads < 0).sum()))
        np.testing.assert_allclose(np.mean([w["peak_pressure_pa"] for w in d["road_wheels"]]),
                                   d["mean_peak_pressure_pa"], rtol=1e-9)
        peak = max(a["pressure_pa"] for a in d["track_assemblies"])
        self.assertEqual(d["peak_assembly_pressure"]["pressure_pa"], peak)
        # NGP = W / (2 b L): Table 1's track width 0.62 m, the 4,845 mm ground run.
        self.assertAlmostEqual(d["nominal_ground_pressure_pa"] / (d["weight_n"] / (2 * 0.62 * 4.845)),
                               1.0, delta=1e-9)
        # Rowland's MMP = 1.26 W / (2 n b sqrt(t D)) under a name of its own: the text's "mean
        # maximum pressure" is the FE figure, mean_peak_pressure_pa.
        rowland = 1.26 * d["weight_n"] / (2 * 7 * 0.62 * (0.1615 * 0.68) ** 0.5)
        self.assertAlmostEqual(d["rowland_mean_maximum_pressure_pa"] / rowland, 1.0, delta=1e-9)
        self.assertNotIn("mean_maximum_pressure_pa", d)
        header, rows = read_csv(csv_file)
        self.assertEqual(header, ["side", "assembly", "x_m", "load_n", "inner_pad_n", "outer_pad_n",
                                  "pressure_pa"])
        np.testing.assert_allclose(rows[:, 3], loads, rtol=1e-9)
        np.testing.assert_allclose(rows[:, 4] + rows[:, 5], rows[:, 3], rtol=1e-9, atol=1e-6)
        self.assertEqual(list(rows[:, 0]), [0.0] * 30 + [1.0] * 30)
        self.tvd("statics", "--vehicle", VEHICLE, "--variant", "untracked", "--out", mat_file)
        m = scipy.io.loadmat(mat_file)
        self.assertEqual(str(m["variant"][0]), "untracked")
        self.assertEqual(m["load_n"].shape, (14, 1))
        # Unilateral contacts (the default): nothing pulls, the weight is still carried. The
        # rearmost wheels pull on the chain in the bonded model, but once the sprocket's lowest
        # links may leave it (they pull on it too) they stay down.
        u = self.tvd_json("statics", "--vehicle", VEHICLE)
        self.assertEqual(u["contact"], "unilateral")
        pads = np.array([a["load_n"] for a in u["track_assemblies"]])
        wheels = np.array([w["load_n"] for w in u["road_wheels"]])
        self.assertGreaterEqual(pads.min(), -1e-6 * u["weight_n"])
        self.assertGreaterEqual(wheels.min(), -1e-6 * u["weight_n"])
        self.assertLess(abs(pads.sum() - u["weight_n"]) / u["weight_n"], 1e-6)
        self.assertEqual(u["lifting_assemblies"], 0)
        lifted = [w["name"] for w in u["road_wheels"] if w["lifted"]]
        self.assertEqual(u["lifted_wheels"], len(lifted))
        self.assertTrue(all(wheels[[w["lifted"] for w in u["road_wheels"]]] == 0.0))
        bonded = [w["name"] for w in d["road_wheels"] if w["load_n"] < 0]
        self.assertEqual(sorted(bonded), ["road_wheel_left_7", "road_wheel_right_7"])
        self.assertEqual(lifted, [])
        text = self.tvd("statics", "--vehicle", VEHICLE, "--contact", "bilateral").stdout
        self.assertIn(f"mean maximum pressure: {d['mean_peak_pressure_pa'] / 1e3:.1f} kPa", text)
        # Bonded, the sprocket links pull the chain down: said with the force's own direction.
        self.assertLess(d["chain_wheel_vertical_force_n"], 0.0)
        self.assertIn(f"rollers pull it down with {-d['chain_wheel_vertical_force_n'] / 1e3:.2f} kN,"
                      " with which it pulls the hull up", text)
        self.assertIn(f"rollers push it up with {u['chain_wheel_vertical_force_n'] / 1e3:.2f} kN",
                      self.tvd("statics", "--vehicle", VEHICLE).stdout)
        # A tensioned loop, every contact pressing, can press them down: not "pull", not "bonded".
        tensioned = os.path.join(ROOT, "test", "data", "six_axle_tensioned.yaml")
        t = self.tvd_json("statics", "--vehicle", tensioned)
        self.assertLess(t["chain_wheel_vertical_force_n"], 0.0)
        self.assertGreaterEqual(min(c["load_n"] for c in t["chain_wheel_contacts"]), 0.0)
        self.assertIn(f"rollers press it down with {-t['chain_wheel_vertical_force_n'] / 1e3:.2f} kN,"
                      " with which it lifts the hull (the tensioned loop wrapped round them)",
                      self.tvd("statics", "--vehicle", tensioned).stdout)
        self.assertIn(f"Rowland's empirical estimate {rowland / 1e3:.1f} kPa", text)
        text = self.tvd("statics", "--vehicle", VEHICLE, "--variant", "untracked").stdout
        self.assertIn("nominal ground pressure", text)
        self.assertIn("road_wheel_right_7", text)
        self.assert_input_error(["statics", "--vehicle", VEHICLE, "--out", self.path("s.json")],
                                "must end in .csv or .mat")
        self.assert_input_error(["statics", "--vehicle", VEHICLE, "--contact", "sticky"],
                                "--contact", "sticky")

    def test_our_eigen_code_beside_a_library_built_for_another_simd_level(self):
        """Debian's liborocos-kdl (libtf2-geometry-msgs-dev depends on it) exports Eigen's
        JacobiSVD and Matrix functions built for SSE2; loaded before libtvd_core, whose Eigen
        is built for AVX here, it used to take over libtvd_core's calls (a segfault freeing
        their memory: rc 139). The libraries bind their calls to their own code."""
        kdl = sorted(glob.glob("/usr/lib/x86_64-linux-gnu/liborocos-kdl.so.*")
                     + glob.glob("/lib/x86_64-linux-gnu/liborocos-kdl.so.*"))
        self.assertTrue(kdl, "liborocos-kdl not installed (a dependency of libtf2-geometry-msgs-dev)")
        env = dict(os.environ, LD_PRELOAD=kdl[0])
        plain = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "untracked",
                              "--count", "6")
        result = subprocess.run([TVD, "modes", "--vehicle", VEHICLE, "--variant", "untracked",
                                 "--count", "6", "--json"], capture_output=True, text=True,
                                env=env, timeout=240)
        self.assertEqual(result.returncode, 0, result.stderr[-2000:])
        np.testing.assert_allclose(json.loads(result.stdout)["frequencies_hz"],
                                   plain["frequencies_hz"], rtol=1e-9)
        result = subprocess.run([TVD, "mac", "--vehicle", VEHICLE, "--count", "10", "--json"],
                                capture_output=True, text=True, env=env, timeout=240)
        self.assertEqual(result.returncode, 0, result.stderr[-2000:])

    def test_mat_files_carry_their_run_and_non_ascii_text(self):
        """Result .mat files: texts as UTF-16 code units, as MATLAB writes them, so an accented
        path or name reads back whole (a UTF-8 element counted in bytes was unreadable in Octave
        and read with trailing garbage by SciPy); the settings that change the results are
        variables, numbers as numbers."""
        folder = self.path("d\u00edr_\u00fc")
        os.makedirs(folder, exist_ok=True)
        with open(VEHICLE, encoding="utf-8") as f:
            text = f.read()
        text = text.replace(f"name: {self.vehicle_name}", "name: v\u00e9hicule_\u00fc", 1)
        vehicle = os.path.join(folder, "v\u00e9hicule.yaml")
        with open(vehicle, "w", encoding="utf-8") as f:
            f.write(text)
        statics, frf = self.path("statics_utf.mat"), self.path("frf_utf.mat")
        self.tvd("statics", "--vehicle", vehicle, "--variant", "untracked", "--accel", "-1.5",
                 "--out", statics)
        m = scipy.io.loadmat(statics, uint16_codec="utf-16-le")
        self.assertEqual(str(m["vehicle_file"][0]), vehicle)
        self.assertEqual(str(m["vehicle"][0]), "v\u00e9hicule_\u00fc")
        self.assertEqual(m["forward_acceleration_m_s2"].dtype, np.float64)
        self.assertEqual(float(m["forward_acceleration_m_s2"][0, 0]), -1.5)
        # ASCII text reads the same with SciPy's default codec.
        self.assertEqual(str(scipy.io.loadmat(statics)["variant"][0]), "untracked")
        self.tvd("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--speed-kmh", "30",
                 "--max-hz", "5", "--out", frf)
        m = scipy.io.loadmat(frf)
        self.assertEqual(str(m["excitation"][0]), "travelled")
        self.assertEqual(float(m["speed_kmh"][0, 0]), 30.0)

    def test_statics_under_steady_braking(self):
        """tvd statics --accel: the road holds the vehicle back with m a and still carries its
        weight, the load moves forward by the inertia moment, the nose goes down."""
        a = -0.3 * GRAVITY
        csv_file = self.path("braking.csv")
        rest = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "untracked",
                             "--contact", "bilateral")
        d = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "untracked",
                          "--contact", "bilateral", "--accel", repr(a), "--out", csv_file)
        self.assertEqual(rest["forward_acceleration_m_s2"], 0)
        self.assertAlmostEqual(d["forward_acceleration_m_s2"], a, delta=1e-9)
        self.assertAlmostEqual(rest["longitudinal_ground_reaction_sum_n"], 0.0,
                               delta=1e-9 * rest["weight_n"])
        self.assertAlmostEqual(d["longitudinal_ground_reaction_sum_n"] / (d["mass_kg"] * a), 1.0,
                               delta=1e-6)
        self.assertAlmostEqual(d["ground_reaction_sum_n"] / d["weight_n"], 1.0, delta=1e-6)
        self.assertGreater(d["hull_pitch_deg"], rest["hull_pitch_deg"])  # nose down is +ry
        # The moment of the vertical reactions about the ground moves by -m a h over the masses'
        # heights h above the road (the ground springs' x forces act at the road, no moment).
        x = np.array([p["x_m"] for p in d["track_assemblies"]])
        moved = x @ (np.array([p["load_n"] for p in d["track_assemblies"]])
                     - np.array([p["load_n"] for p in rest["track_assemblies"]]))
        self.assertGreater(moved, 0.0)
        # Hull (30.3 t at 1.57 m) and wheels (16.8 t at their centres, 0.34 m + the link): the
        # inertia moment lies between m a x 0.5 m and m a x 1.57 m.
        self.assertGreater(moved, -d["mass_kg"] * a * 0.5)
        self.assertLess(moved, -d["mass_kg"] * a * 1.57)
        header, rows = read_csv(csv_file)
        np.testing.assert_allclose(rows[:, 3], [p["load_n"] for p in d["track_assemblies"]],
                                   rtol=1e-9)
        # Bonded, the response is linear in a.
        twice = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "untracked",
                              "--contact", "bilateral", "--accel", repr(2 * a))
        self.assertAlmostEqual((twice["hull_pitch_deg"] - rest["hull_pitch_deg"])
                               / (d["hull_pitch_deg"] - rest["hull_pitch_deg"]), 2.0, delta=1e-6)
        text = self.tvd("statics", "--vehicle", VEHICLE, "--accel", "-2.94").stdout
        self.assertIn("steady forward acceleration -2.940 m/s^2 (0.300 g, braking)", text)
        self.assertIn("hull: sag", text)
        self.assertNotIn("hull at rest", text)
        for bad in ("nan", "-20", "abc"):
            self.assert_input_error(["statics", "--vehicle", VEHICLE, "--accel", bad],
                                    "--accel", bad)
        # Beyond the un-tracked pads' tipping limit (doc/vehicle_model.md): one line naming the
        # pads and the way out, a solver error (status 3), and the bonded model solves it.
        err = self.tvd("statics", "--vehicle", VEHICLE, "--variant", "untracked", "--accel",
                       "-9", status=3).stderr
        self.assertEqual(len(err.strip().splitlines()), 1, err)
        self.assertIn("every pad on the road has lifted but for one column of soles (14 track "
                      "assemblies: track_left_0 at x = 2.34 m (front column)", err)
        self.assertTrue(err.strip().endswith(
            "; --contact bilateral solves the bonded model at this load"), err)
        self.tvd("statics", "--vehicle", VEHICLE, "--variant", "untracked", "--accel", "-9",
                 "--contact", "bilateral")
        # A centre of gravity 2.3 m aft: the front wheels lift at rest (the active set's
        # all-at-once change first left two pads free: retaken one contact at a time), and wheels
        # lifted at rest are a warning, not only a count.
        aft = self.vehicle_with("aft.yaml", "cog_x: {value: 0.12", "cog_x: {value: -2.3")
        d = self.tvd_json("statics", "--vehicle", aft, "--variant", "untracked")
        self.assertEqual(d["lifted_wheels"], 2)
        self.assertIn("2 of 14 road wheels lift off their track assemblies at rest "
                      "(road_wheel_left_1, "
                      "road_wheel_right_1): the hull rests on the others; check hull.cog_x",
                      d["warnings"])
        self.assertAlmostEqual(d["ground_reaction_sum_n"] / d["weight_n"], 1.0, delta=1e-9)
        self.assertEqual(self.tvd_json("statics", "--vehicle", VEHICLE)["warnings"], [])

    def test_statics_chain_wheel_contacts(self):
        """tvd statics lists the links' contacts with the sprockets, idlers and return rollers:
        unilateral, none pulls, a released one carries nothing, the rollers carry the top run;
        the per-side counts agree with the list and mirror; bilateral releases none; un-tracked
        has none."""
        kinds = ["sprocket", "idler", "return_roller"]
        # The bundled vehicle has a free return run; here three rollers per side under it.
        rollers = self.vehicle_with("return_rollers.yaml", "x: {value: [], unit: m",
                                    "x: {value: [-1.17, 0.39, 1.95], unit: m")
        u = self.tvd_json("statics", "--vehicle", rollers)
        contacts = u["chain_wheel_contacts"]
        self.assertEqual(sorted({c["wheel"] for c in contacts}), sorted(kinds))
        self.assertEqual(sorted({c["side"] for c in contacts}), ["left", "right"])
        for c in contacts:
            self.assertGreaterEqual(c["load_n"], -1e-6 * u["weight_n"], c["name"])
            if c["released"]:
                self.assertEqual(c["load_n"], 0.0, c["name"])
            if c["wheel"] == "return_roller":
                self.assertFalse(c["released"], c["name"])
                self.assertGreater(c["load_n"], 0.0, c["name"])
        by_side = u["released_chain_wheel_contacts_by_side"]
        for side in ("left", "right"):
            for kind in kinds:
                self.assertEqual(by_side[side][kind],
                                 sum(c["released"] for c in contacts
                                     if c["side"] == side and c["wheel"] == kind), (side, kind))
        self.assertEqual(by_side["left"], by_side["right"])
        self.assertEqual(u["released_chain_wheel_contacts"], sum(c["released"] for c in contacts))
        pads = np.array([a["load_n"] for a in u["track_assemblies"]])
        self.assertLess(abs(pads.sum() - u["weight_n"]) / u["weight_n"], 1e-6)
        text = self.tvd("statics", "--vehicle", rollers).stdout
        total = {k: sum(c["side"] == "left" and c["wheel"] == k for c in contacts) for k in kinds}
        self.assertIn("chain wheel contacts released (the link has left the wheel): left "
                      + ", ".join(f"{k} {by_side['left'][k]} of {total[k]}" for k in kinds), text)
        # The bundled vehicle: the bonded model pulls on the sprocket's lowest links, which let
        # go; the same on both sides.
        p = self.tvd_json("statics", "--vehicle", VEHICLE)
        self.assertGreater(p["released_chain_wheel_contacts_by_side"]["left"]["sprocket"], 0)
        # Without return rollers the text leaves them out rather than print "0 of 0".
        text = self.tvd("statics", "--vehicle", VEHICLE).stdout
        self.assertIn("chain wheel contacts released (the link has left the wheel): left "
                      "sprocket ", text)
        self.assertNotIn("return_roller", text)
        self.assertEqual(p["released_chain_wheel_contacts_by_side"]["left"],
                         p["released_chain_wheel_contacts_by_side"]["right"])
        b = self.tvd_json("statics", "--vehicle", rollers, "--contact", "bilateral")
        self.assertEqual(b["released_chain_wheel_contacts"], 0)
        self.assertFalse(any(c["released"] for c in b["chain_wheel_contacts"]))
        self.assertEqual([c["name"] for c in b["chain_wheel_contacts"]],
                         [c["name"] for c in contacts])
        text = self.tvd("statics", "--vehicle", rollers, "--contact", "bilateral").stdout
        # "pulling": the bilateral contacts whose load is negative, counted per side and wheel.
        btotal = {k: sum(c["side"] == "left" and c["wheel"] == k for c in b["chain_wheel_contacts"])
                  for k in kinds}
        pulling = {k: sum(c["side"] == "left" and c["wheel"] == k and c["load_n"] < 0.0
                          for c in b["chain_wheel_contacts"]) for k in kinds}
        self.assertGreater(pulling["sprocket"], 0, b["chain_wheel_contacts"])
        self.assertIn("chain wheel contacts pulling (would leave the wheel): left "
                      + ", ".join(f"{k} {pulling[k]} of {btotal[k]}" for k in kinds), text)
        t = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "untracked")
        self.assertEqual(t["chain_wheel_contacts"], [])
        self.assertEqual(t["released_chain_wheel_contacts"], 0)
        self.assertEqual(t["released_chain_wheel_contacts_by_side"]["right"],
                         {k: 0 for k in kinds})
        text = self.tvd("statics", "--vehicle", VEHICLE, "--variant", "untracked").stdout
        self.assertNotIn("chain wheel contacts", text)

    def test_node_shapes_recover_the_rigid_hull(self):
        # node_shapes.csv holds every node, slaves included: the crew seat, rigid with the hull,
        # must move as u_G + theta x (p - p_G) with the hull node's six DOFs from shapes.csv.
        out = self.path("modes_nodes")
        self.tvd("modes", "--vehicle", VEHICLE, "--variant", "untracked", "--count", "8",
                 "--out", out)
        with open(os.path.join(out, "shapes.csv")) as f:
            hull = {r[1]: np.array(r[2:], dtype=float) for r in csv.reader(f) if r[0] == "1"}
        with open(os.path.join(out, "node_shapes.csv")) as f:
            table = list(csv.reader(f))
        names = table[0]
        self.assertEqual(names[:5], ["node", "part", "x_m", "y_m", "z_m"])
        self.assertEqual(len(names), 5 + 3 * 8)
        by_part = {row[1]: row for row in table[1:]}
        self.assertEqual(len({row[0] for row in table[1:]}), len(table) - 1)  # one row per node
        for part in ("hull", "crew_seat", "road_wheel_left_1 centre", "road_wheel_right_7 arm"):
            self.assertIn(part, by_part)
        p_g = np.array(by_part["hull"][2:5], dtype=float)
        seat = by_part["crew_seat"]
        p = np.array(seat[2:5], dtype=float)
        for k in range(8):
            u_g = np.array([hull[d][k] for d in ("ux", "uy", "uz")])
            theta = np.array([hull[d][k] for d in ("rx", "ry", "rz")])
            expected = u_g + np.cross(theta, p - p_g)
            got = np.array(seat[5 + 3 * k:8 + 3 * k], dtype=float)
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-9 * np.abs(expected).max() + 1e-15)
            np.testing.assert_allclose(np.array(by_part["hull"][5 + 3 * k:8 + 3 * k], dtype=float),
                                       u_g, rtol=0, atol=1e-12)

    def test_reduce_band_rule_mode_count_beyond_the_solved_modes_is_named(self):
        """With --rule band, --modes N also selects the lowest N global modes (help and README
        say so): more than --global-modes solved is refused naming both options, not as the
        selection's 'count 60 is not in 1..40'."""
        r = self.tvd("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--rule", "band",
                     "--modes", "60", "--out", self.path("band_modes_60.mat"), status=2)
        self.assertIn("mode_count 60 (tvd --modes, ~reduction/mode_count) with rule band also "
                      "selects the lowest 60 global modes, but only 40 were solved (tvd "
                      "--global-modes", r.stderr)
        # The bound itself: one mode more than were solved.
        r = self.tvd("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--rule", "band",
                     "--modes", "41", "--out", self.path("band_modes_41.mat"), status=2)
        self.assertIn("mode_count 41 (tvd --modes, ~reduction/mode_count) with rule band also "
                      "selects the lowest 41 global modes, but only 40 were solved", r.stderr)
        self.assertIn("with --rule band a positive N also selects the lowest N global modes",
                      " ".join(self.tvd("reduce", "--help").stdout.split()))

    def test_reduce_json_and_mat(self):
        out = self.path("untracked.mat")
        d = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--out", out)
        for key in ("full_dofs", "interface_dofs", "mogesec_dofs", "flexible_modes",
                    "reduced_dofs", "reduce_seconds"):
            self.assertIn(key, d)
        self.assertLess(d["reduced_dofs"], d["full_dofs"])
        self.assertEqual(d["mogesec_dofs"], 9)  # paper Table 5
        self.assertLess(d["max_relative_frequency_error"], 0.02)  # paper: 2 % at worst
        m = scipy.io.loadmat(out)
        self.assertEqual(str(np.ravel(m["description_hash"])[0]), d["description_hash"])
        n = d["reduced_dofs"]
        for name in ("M_R", "K_R", "C_R"):
            self.assertEqual(m[name].shape, (n, n), name)
            np.testing.assert_allclose(m[name], m[name].T, rtol=0, atol=1e-9 * abs(m[name]).max())
        self.assertGreater(np.linalg.eigvalsh(m["M_R"]).min(), 0.0)
        # Where the masters are and why (paper Fig. 12): the 84 pad soles' uz on the ground, the
        # hull's 6 DOFs at its CoG (1.57 m up), 14 arms, then the 9 MoGeSeC picks in order.
        groups = [str(np.ravel(g)[0]) for g in np.ravel(m["master_groups"])]
        positions = m["master_positions"]
        self.assertEqual(positions.shape, (len(groups), 3))
        self.assertEqual(groups[:84], ["road input"] * 84)
        self.assertEqual(groups[84:90], ["hull"] * 6)
        self.assertEqual(groups[90:104], ["wheel arm"] * 14)
        self.assertEqual(groups[104:], [f"MoGeSeC {k}" for k in range(1, 10)])
        np.testing.assert_allclose(positions[:84, 2], 0.0, atol=1e-12)
        np.testing.assert_allclose(positions[84:90], [[0.12, 0.0, 1.57]] * 6, atol=1e-12)
        picks = d["mogesec_masters"]
        self.assertEqual([p["pick"] for p in picks], list(range(1, 10)))
        self.assertEqual(len({p["dof"] for p in picks}), 9)  # none repeated
        labels = [str(np.ravel(x)[0]) for x in np.ravel(m["dof_labels"])]
        for k, p in enumerate(picks):
            self.assertEqual(p["dof"], labels[104 + k])
            np.testing.assert_allclose(p["position_m"], positions[104 + k], atol=1e-12)
            self.assertTrue(p["part"].startswith(("track assembly", "road_wheel")), p["part"])
            self.assertAlmostEqual(p["weight"], p["modal_weight"] * p["geometric_weight"], places=9)
            self.assertLessEqual(p["weight"], 1.0)

    def test_a_vehicle_of_our_own_reduces_within_two_percent(self):
        """A light 5-axle vehicle (test/data/light_5_axle.yaml): its MAC keeps 1 global mode, and
        twice as many fixed-interface modes (2) leave a mode below 30 Hz 20 % too stiff. The
        default adds modes until every full-model mode below the band is within 2 % and says so; a
        --modes N that misses it is warned about, naming the mode and its two frequencies."""
        own = OWN_VEHICLE
        d = self.tvd_json("reduce", "--vehicle", own, "--variant", "tracked")
        selected = len(d["selected_modes"])
        self.assertEqual(d["initial_flexible_modes"], 2 * selected)
        # Additions of max(selected, 4) modes, each needed (the count before misses 2 %), the last
        # enough.
        step = max(selected, 4)
        added = d["flexible_modes"] - d["initial_flexible_modes"]
        self.assertGreater(added, 0)
        self.assertEqual(added % step, 0, added)
        self.assertLessEqual(d["max_relative_frequency_error"], 0.02)
        before = self.tvd_json("reduce", "--vehicle", own, "--modes",
                               str(d["flexible_modes"] - step))
        self.assertGreater(before["max_relative_frequency_error"], 0.02)
        # The MAC compares with the un-tracked global modes only: the assemblies' modes at 136 Hz
        # (0.02-0.07 % of their energy in the vehicle) paired tracked modes at 6.8-19.8 Hz before.
        mac = self.tvd_json("mac", "--vehicle", own, "--count", "40")
        self.assertEqual(d["mac_reference_modes"], sum(mac["untracked_global"]))
        self.assertFalse(all(mac["untracked_global"]))
        for m in d["selected_modes"]:
            named = [int(k) for k in re.findall(r"mode (\d+)", m["reason"])]
            self.assertTrue(named, m)
            self.assertTrue(all(mac["untracked_global"][k - 1] for k in named), m)
        errors = [m["relative_error"] for m in d["band_modes"]]
        self.assertAlmostEqual(max(errors), d["max_relative_frequency_error"], places=12)
        self.assertFalse([w for w in d["reduction"]["warnings"] if "off the full model" in w])
        text = self.tvd("reduce", "--vehicle", own, "--variant", "tracked").stdout
        self.assertIn(f"flexible modes {d['flexible_modes']} (raised from "
                      f"{d['initial_flexible_modes']}, twice the selected global modes, until the "
                      "modes up to 30 Hz are within 2 %)", text)
        # --modes N is the user's: kept, and warned about (stderr, JSON, the saved model).
        out = self.path("light_5_axle_modes6.mat")
        r = self.tvd("reduce", "--vehicle", own, "--modes", "6", "--json", "--out", out)
        d6 = json.loads(r.stdout)
        self.assertEqual(d6["flexible_modes"], 6)
        worst = max(d6["band_modes"], key=lambda m: m["relative_error"])
        self.assertGreater(worst["relative_error"], 0.02)
        warning = (f"the reduced model's mode {worst['mode']} is "
                   f"{100 * worst['relative_error']:.2f} % off the full model's "
                   f"({worst['full_hz']:.2f} -> {worst['reduced_hz']:.2f} Hz), beyond the 2 % the "
                   "reduction aims at below 30 Hz, with 6 fixed-interface modes (--modes / "
                   "~reduction/mode_count 6;")
        self.assertIn(warning, r.stderr)
        self.assertTrue([w for w in d6["reduction"]["warnings"] if w.startswith(warning)])
        saved = [str(np.ravel(w)[0]) for w in np.ravel(scipy.io.loadmat(out)["reduction_warnings"])]
        self.assertTrue([w for w in saved if w.startswith(warning)], saved)
        # The bundled vehicle's default needs no more than twice its selected modes.
        p = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "untracked")
        self.assertEqual(p["flexible_modes"], p["initial_flexible_modes"])
        # The r-th modes are paired wherever the reduced one lies: the paper's count (as many
        # fixed-interface modes as selected) pushes tracked modes from 22.9 Hz up above the band
        # (the worst, mode 34, 27.00 -> 46.83 Hz), and the report's worst error is that pair's,
        # as the warning says.
        paper = len(self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant",
                                  "tracked")["selected_modes"])
        t = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "tracked", "--modes",
                          str(paper))
        worst = max(t["band_modes"], key=lambda m: m["relative_error"])
        self.assertGreater(worst["reduced_hz"], 30.0)
        self.assertAlmostEqual(worst["relative_error"], t["max_relative_frequency_error"], places=12)
        self.assertTrue([w for w in t["reduction"]["warnings"]
                         if w.startswith(f"the reduced model's mode {worst['mode']} is ")])

    def test_a_vehicle_of_our_own_runs_every_step(self):
        """Nothing assumes the bundled vehicle's 7 axles: the light 5-axle fixture's statics carry
        its weight, and its simulation has 5 wheels a side, at rest before the hill."""
        own = OWN_VEHICLE
        s = self.tvd_json("statics", "--vehicle", own, "--variant", "tracked")
        self.assertLess(abs(s["ground_reaction_sum_n"] - s["weight_n"]) / s["weight_n"], 1e-6)
        # The wheels' total, and what the chain passes to the sprocket, idler and rollers.
        self.assertAlmostEqual(s["road_wheel_load_sum_n"] / sum(w["load_n"] for w in s["road_wheels"]),
                               1.0, delta=1e-9)
        self.assertGreater(abs(s["chain_wheel_vertical_force_n"]), 0.001 * s["weight_n"])
        out = self.path("light_5_axle_long_hill.csv")
        d = self.tvd_json("simulate", "--vehicle", own, "--track", "long_hill", "--speed-kmh",
                          "20", "--out", out)
        header, rows = read_csv(out)
        for side in ("left", "right"):
            wheels = [h for h in header if re.fullmatch(f"road_wheel_{side}_\\d+_m", h)]
            self.assertEqual(wheels, [f"road_wheel_{side}_{k}_m" for k in range(1, 6)], header)
        self.assertEqual(sorted(p["point"] for p in d["peaks_at_points"]),
                         ["commander_hatch", "driver_seat"])
        accel = rows[:, header.index("hull_vertical_accel_m_s2")]
        self.assertLess(np.abs(accel[:100]).max(), 1e-6)  # flat entry: at rest
        self.assertGreater(d["peak_hull_vertical_accel_m_s2"], 1.0)  # the hill is felt

    def test_reduce_basis_projects_the_exported_full_model(self):
        """--basis writes T_CMS (paper eq. 8) over the rows `tvd modes --matrices` exports: with
        them alone, T' M T and T' K T are M_R and K_R (eq. 9), T' K_u, T' f_g and T' f_a the
        reduced inputs and loads, T is the identity on the master rows, and H's rows are T's rows
        of the output DOFs. The same with a count given (--modes: no projection kept, the
        eigen-solve made again) and with the band rule."""
        import scipy.sparse
        work = self.path("basis")
        os.makedirs(work)
        self.tvd("modes", "--vehicle", VEHICLE, "--variant", "untracked", "--count", "1", "--out",
                 work, "--matrices")
        m = scipy.io.loadmat(os.path.join(work, "matrices.mat"))
        M, K = scipy.sparse.csc_matrix(m["M"]), scipy.sparse.csc_matrix(m["K"])
        row = {(int(n), int(k)): i for i, (n, k) in
               enumerate(zip(m["dof_node"].ravel(), m["dof_direction"].ravel()))}

        def close(projected, stored, rtol):
            self.assertLessEqual(abs(projected - stored).max(), rtol * abs(stored).max())

        reduced, basis = os.path.join(work, "reduced.mat"), os.path.join(work, "basis.mat")
        for extra in ((), ("--modes", "9"), ("--rule", "band")):
            d = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--out",
                              reduced, "--basis", basis, *extra)
            self.assertEqual(d["basis"], basis)
            r, b = scipy.io.loadmat(reduced), scipy.io.loadmat(basis)
            T = b["T"]
            self.assertEqual(T.shape, (d["full_dofs"], d["reduced_dofs"]), extra)
            if extra[:1] == ("--modes",):
                self.assertEqual(d["flexible_modes"], 9)
            np.testing.assert_array_equal(b["dof_node"], m["dof_node"])
            np.testing.assert_array_equal(b["dof_direction"], m["dof_direction"])
            self.assertEqual([str(np.ravel(x)[0]) for x in np.ravel(b["reduced_dof_labels"])],
                             [str(np.ravel(x)[0]) for x in np.ravel(r["dof_labels"])])
            self.assertEqual(str(b["description_hash"][0]), d["description_hash"])
            close(T.T @ (M @ T), r["M_R"], 1e-12)
            close(T.T @ (K @ T), r["K_R"], 1e-11)
            close(T.T @ scipy.sparse.csc_matrix(m["K_u"]).toarray(), r["K_u"], 1e-12)
            close(T.T @ m["gravity_load"], r["gravity_load"], 1e-12)
            close(T.T @ m["travel_load"], r["travel_load"], 1e-12)
            masters = [row[(int(n), int(k))] for n, k in r["masters"]]
            np.testing.assert_array_equal(T[masters, :len(masters)], np.eye(len(masters)))
            np.testing.assert_array_equal(T[masters, len(masters):], 0.0)
            names = [str(np.ravel(x)[0]) for x in np.ravel(r["output_names"])]
            close(T[row[(1, 2)]], r["H"][names.index("hull uz")], 1e-15)
        # One file cannot be both.
        # However spelt: through a link to the directory, or relative to it (review 166: both
        # were written and the basis replaced the model, status 0).
        link = self.path("basis_link")
        os.symlink(work, link)
        for other in (reduced, os.path.join(link, "reduced.mat"),
                      os.path.join(work, ".", "sub", "..", "reduced.mat")):
            os.makedirs(os.path.join(work, "sub"), exist_ok=True)
            self.assert_input_error(["reduce", "--vehicle", VEHICLE, "--out", reduced, "--basis",
                                     other], "--basis and --out name the same file")
        fresh = os.path.join(work, "fresh.mat")  # a file that does not exist yet too
        self.assert_input_error(["reduce", "--vehicle", VEHICLE, "--out", fresh, "--basis",
                                 os.path.join(link, "fresh.mat")],
                                "--basis and --out name the same file")
        self.assertFalse(os.path.exists(fresh))

    def test_reduced_model_file_doc_is_current_and_its_example_runs(self):
        # doc/reduced_model_file.md: its table lists exactly the file's variables, and its SciPy
        # example, run on a fresh file, gives the full model's frequencies and static sag.
        with open(os.path.join(ROOT, "doc", "reduced_model_file.md")) as f:
            doc = f.read()
        documented = set()
        for row in re.findall(r"^\| (`[^|]+`) \|", doc, re.M):
            documented.update(re.findall(r"`([A-Za-z_]+)`", row))
        work = self.path("doc_example")
        os.makedirs(work)
        reduced = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "tracked", "--out",
                                os.path.join(work, "tracked.mat"))
        stored = {k for k in scipy.io.loadmat(os.path.join(work, "tracked.mat")) if not k.startswith("__")}
        self.assertEqual(documented, stored)
        code = re.search(r"```python\n(.*?)```", doc, re.S).group(1)
        namespace = {}
        cwd = os.getcwd()
        try:
            os.chdir(work)
            exec(compile(code, "reduced_model_file.md", "exec"), namespace)  # noqa: S102
        finally:
            os.chdir(cwd)
        full = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "tracked", "--count", "6")
        np.testing.assert_allclose(namespace["frequencies_hz"][:6], full["frequencies_hz"], rtol=1e-3)
        self.assertAlmostEqual(namespace["hull_sag_m"] / full["static"]["hull_sag_m"], 1.0, delta=1e-6)
        self.assertEqual(namespace["A"].shape, (2 * reduced["reduced_dofs"],) * 2)
        # The full FE model's static pitch under 0.3 g braking, bonded as the reduced model is
        # (tvd statics --accel; the reduced model's equals it to 1e-11, test_travel_inertia).
        braking = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "tracked",
                                "--contact", "bilateral", "--accel", repr(-0.3 * 9.80665))
        at_rest = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "tracked",
                                "--contact", "bilateral")
        full_pitch_mrad = np.radians(braking["hull_pitch_deg"] - at_rest["hull_pitch_deg"]) * 1e3
        self.assertAlmostEqual(namespace["brake_pitch_mrad"] / full_pitch_mrad, 1.0, delta=1e-6)
        # The checksum, recomputed from the loaded values as the doc defines it.
        self.assertEqual(documented_checksum(os.path.join(work, "tracked.mat")),
                         str(scipy.io.loadmat(os.path.join(work, "tracked.mat"))["checksum"][0]))
        # It covers the values, not the encoding: the file loaded and saved again by SciPy loads
        # and gives the same FRF.
        original = scipy.io.loadmat(os.path.join(work, "tracked.mat"))
        resaved = os.path.join(work, "resaved.mat")
        scipy.io.savemat(resaved, {k: v for k, v in original.items() if not k.startswith("__")})
        self.assertNotEqual(open(resaved, "rb").read(), open(os.path.join(work, "tracked.mat"), "rb").read())
        frf = [self.tvd_json("frf", "--vehicle", VEHICLE, "--reduced", f, "--max-hz", "20")
               for f in (os.path.join(work, "tracked.mat"), resaved)]
        self.assertEqual(frf[0]["outputs"], frf[1]["outputs"])

    def test_simulate_json_and_csv_agree(self):
        speed_kmh = 50.0
        out = self.path("hill.csv")
        d = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          "long_hill", "--speed-kmh", str(speed_kmh), "--cache-dir", self.cache,
                          "--out", out)
        for key in ("peak_hull_heave_m", "peak_hull_vertical_accel_m_s2", "peak_pitch_deg",
                    "peak_roll_deg", "peak_wheel_displacement_m", "comfort", "simulated_seconds",
                    "wall_seconds"):
            self.assertIn(key, d)
        # As every command: the description's name and the file given.
        self.assertEqual((d["vehicle"], d["vehicle_file"]), (self.vehicle_name, VEHICLE))
        header, rows = read_csv(out)
        self.assertEqual(header[:6], ["time_s", "station_m", "hull_heave_m",
                                      "hull_vertical_accel_m_s2", "hull_pitch_deg", "hull_roll_deg"])
        # 7 more hull rates and accelerations, the hull's surge, sway, yaw, yaw rate and yaw
        # acceleration, 14 wheels, 4 columns for each of 2 named points, the road under each of
        # the 14 wheels, the travel acceleration, the ground force per side and the contacts in
        # tension.
        self.assertEqual(len(header), 6 + 12 + 14 + 2 * 4 + 14 + 1 + 3)
        self.assertEqual(header[6 + 7:6 + 12], ["hull_surge_m", "hull_sway_m", "hull_yaw_deg",
                                                "hull_yaw_rate_deg_s", "hull_yaw_accel_deg_s2"])
        self.assertEqual(header[-4:], ["travel_accel_m_s2", "ground_force_left_n",
                                       "ground_force_right_n", "contacts_in_tension"])
        self.assertEqual(d["peak_travel_accel_m_s2"], 0.0)
        # 30 m at 50 km/h in 1 ms steps, plus the initial sample.
        self.assertEqual(len(rows), round(30.0 / (speed_kmh / 3.6) / 1e-3) + 1)
        self.assertAlmostEqual(rows[-1, 0], d["simulated_seconds"], places=9)
        column = {name: rows[:, i] for i, name in enumerate(header)}
        self.assertAlmostEqual(np.abs(column["hull_heave_m"]).max(), d["peak_hull_heave_m"], places=7)
        self.assertAlmostEqual(np.abs(column["hull_pitch_deg"]).max(), d["peak_pitch_deg"], places=6)
        # The hull climbs the 0.4 m hill (with some overshoot at 50 km/h); no roll on a hill
        # that spans the whole width.
        self.assertGreater(d["peak_hull_heave_m"], 0.35)
        self.assertLess(d["peak_hull_heave_m"], 0.6)
        self.assertLess(d["peak_roll_deg"], 1e-3)
        self.assertGreater(d["comfort"]["weighted_rms_m_s2"], 0.0)
        # Absorbed power at the hull against Project Chrono's own difference equation
        # (ChAbsorbed_Power_Vertical: Tustin form, input in ft/s^2) run on the CSV's acceleration:
        # an independent implementation of the same public filter. Ours is magnitude-matched,
        # theirs bilinear; at 1 kHz they differ by far less than the tolerance in the body band.
        t = 1e-3
        b = np.array([29 * t * (22 * t + 1), 29 * t * (22 * t - 1), -29 * t * (22 * t + 1),
                      -29 * t * (22 * t - 1)])
        a = np.array([(63 * t + 2) * (375 * t * t + 24 * t + 2),
                      (63 * t - 2) * (375 * t * t + 24 * t + 2) + (63 * t + 2) * (750 * t * t - 4),
                      (63 * t + 2) * (375 * t * t - 24 * t + 2) + (63 * t - 2) * (750 * t * t - 4),
                      (63 * t - 2) * (375 * t * t - 24 * t + 2)])
        z = lfilter(b / a[0], a / a[0], column["hull_vertical_accel_m_s2"] / 0.3048)
        hull = d["comfort"]
        self.assertEqual(hull["point"], "hull")
        self.assertGreater(hull["absorbed_power_w"], 0.0)
        self.assertAlmostEqual(hull["absorbed_power_w"] / np.mean(z ** 2), 1.0, delta=0.02)
        # Every named point of the description, with a total value above its vertical part.
        points = {p["point"]: p for p in d["comfort_at_points"]}
        self.assertEqual(sorted(points), ["crew_seat", "sensor_mount"])
        for p in [hull] + list(points.values()):
            self.assertGreaterEqual(p["vibration_total_value_m_s2"], p["weighted_rms_m_s2"])
            self.assertGreater(p["weighted_rms_x_m_s2"], 0.0)  # the hill pitches the hull

    def test_simulate_ground_contact_says_where_the_linear_model_leaves_its_range(self):
        """Every road input's ground spring force F = k (u - q) (compression positive): at rest
        the contacts carry the weight (statics' weight_n, 1e-6); over a 1 cm half-round at
        5 km/h every contact stays in compression, over the out-of-phase waves at 30 km/h the
        model pulls on contacts and on a whole side; the JSON's figures are the CSV columns'; the
        monitor changes no other column (--ground-contact off: the same CSV less its three
        columns); --model full says it is not monitored."""
        weight = self.tvd_json("statics", "--vehicle", VEHICLE, "--variant", "untracked",
                               "--contact", "bilateral")["weight_n"]
        common = ("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", self.cache)
        runs = {}
        for name, track, speed in (("gentle", "half_round:0.01", "5"), ("harsh", "oop_waves", "30")):
            out = self.path(f"contact_{name}.csv")
            d = self.tvd_json(*common, "--track", track, "--speed-kmh", speed, "--out", out)
            header, rows = read_csv(out)
            self.assertEqual(header[-3:], ["ground_force_left_n", "ground_force_right_n",
                                           "contacts_in_tension"])
            c = {h: rows[:, i] for i, h in enumerate(header)}
            g = d["ground_contact"]
            runs[name] = (g, c, out)
            self.assertEqual(g["contacts"], 84)  # 14 wheels, a pad of 6 soles each
            self.assertEqual(g["contacts_in_tension_at_rest"], 0)
            total = c["ground_force_left_n"] + c["ground_force_right_n"]
            self.assertAlmostEqual(total[0] / weight, 1.0, delta=1e-6)
            self.assertAlmostEqual(g["static_ground_force_n"] / weight, 1.0, delta=1e-6)
            # Symmetric vehicle, left and right alike at rest.
            self.assertAlmostEqual(c["ground_force_left_n"][0] / c["ground_force_right_n"][0], 1.0, delta=1e-9)
            tension = c["contacts_in_tension"]
            self.assertEqual(g["max_contacts_in_tension"], tension.max())
            self.assertAlmostEqual(g["tension_sample_fraction"], np.mean(tension > 0), places=9)
            self.assertEqual(g["in_range"], tension.max() == 0)  # nothing pulls at rest here
            self.assertTrue(g["in_range_at_rest"])
            for side in ("left", "right"):
                column = c[f"ground_force_{side}_n"]
                self.assertAlmostEqual(g[f"peak_ground_force_{side}_n"] / column.max(), 1.0, delta=1e-8)
                self.assertAlmostEqual(g[f"min_ground_force_{side}_n"] / column.min(), 1.0, delta=1e-8)
            if tension.max() > 0:
                first = np.argmax(tension > 0)
                self.assertAlmostEqual(g["first_tension_time_s"], c["time_s"][first], places=9)
                self.assertAlmostEqual(g["first_tension_station_m"], c["station_m"][first], places=6)
                self.assertEqual(g["first_new_tension_time_s"], g["first_tension_time_s"])
                self.assertLess(g["min_contact_force_n"], 0.0)
                self.assertIn(g["min_contact"]["side"], ("left", "right"))
                self.assertTrue(g["min_contact"]["input"].startswith("node "))
            else:
                self.assertIsNone(g["first_tension_time_s"])
                self.assertIsNone(g["first_tension_contact"])
                self.assertGreater(g["min_contact_force_n"], 0.0)
        gentle, harsh = runs["gentle"][0], runs["harsh"][0]
        self.assertTrue(gentle["in_range"])
        self.assertFalse(harsh["in_range"])
        # Pads (a wheel's track assembly, 6 soles): each pad's total, the same way.
        for g in (gentle, harsh):
            self.assertEqual((g["pads"]["count"], g["pads"]["in_tension_at_rest"]), (14, 0))
        self.assertGreater(gentle["pads"]["min_force_n"], 0.0)
        self.assertIsNone(gentle["pads"]["first_new_tension_time_s"])
        self.assertLess(harsh["pads"]["min_force_n"], 0.0)
        self.assertGreaterEqual(harsh["pads"]["first_new_tension_time_s"], harsh["first_tension_time_s"])
        self.assertGreater(harsh["max_contacts_in_tension"], 10)
        # The 1.2 m waves at 30 km/h throw a whole side off the road (its total pulls).
        self.assertLess(min(harsh["min_ground_force_left_n"], harsh["min_ground_force_right_n"]), 0.0)
        # The text says so.
        text = self.tvd(*common, "--track", "oop_waves", "--speed-kmh", "30").stdout
        self.assertRegex(text, r"ground contact: the linear model pulls on \d+ of 84 contacts .* from t = "
                               r"[0-9.]+ s \(x = [0-9.]+ m, .*beyond its range")
        text = self.tvd(*common, "--track", "half_round:0.01", "--speed-kmh", "5").stdout
        self.assertIn("ground contact: all 84 contacts stay in compression", text)
        # The bonded tracked model pulls on 84 soles already at rest: those do not put a run out of
        # range, a sole pressed at rest that pulls does (1 mm obstacle: none; 3 mm: some).
        tracked = ("simulate", "--vehicle", VEHICLE, "--variant", "tracked", "--cache-dir", self.cache,
                   "--speed-kmh", "5", "--track")
        g = self.tvd_json(*tracked, "half_round:0.001")["ground_contact"]
        self.assertEqual((g["contacts_in_tension_at_rest"], g["max_contacts_in_tension"]), (84, 84))
        self.assertEqual((g["in_range"], g["in_range_at_rest"]), (True, False))
        self.assertIsNone(g["first_new_tension_time_s"])
        g = self.tvd_json(*tracked, "half_round:0.003")["ground_contact"]
        self.assertEqual((g["in_range"], g["in_range_at_rest"]), (False, False))
        self.assertGreater(g["first_new_tension_time_s"], 0.0)
        # Off: every other column byte for byte, and no ground_contact figures.
        off = self.path("contact_off.csv")
        d = self.tvd_json(*common, "--track", "oop_waves", "--speed-kmh", "30", "--out", off,
                          "--ground-contact", "off")
        self.assertEqual(d["ground_contact"], {"monitored": False, "reason": "--ground-contact off"})
        with open(runs["harsh"][2]) as f:
            on_lines = [",".join(line.rstrip("\n").split(",")[:-3]) for line in f]
        with open(off) as f:
            off_lines = [line.rstrip("\n") for line in f]
        self.assertEqual(on_lines, off_lines)
        d = self.tvd_json(*common[:-2], "--track", "long_hill", "--speed-kmh", "30", "--model",
                          "full", "--max-mode-hz", "40")  # common[:-2]: without --cache-dir
        self.assertFalse(d["ground_contact"]["monitored"])
        self.assertIn("reduced model only", d["ground_contact"]["reason"])

    def test_simulate_says_when_damped_ground_ties_fill_the_contact_forces(self):
        """The 2e10 N/m ground ties' modes (9.1 kHz and up) under 5 % modal damping: quasi-static
        by default (no warning), dynamic with --max-mode-hz 0 or --method exact, whose contact
        forces then carry a damping force to the inertial frame (the un-tracked long hill at
        30 km/h: a side's peak 22 % higher) while the hull's motion barely changes (< 1 %). Both
        all-dynamic runs say so, and agree with each other."""
        common = ("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                  self.cache, "--track", "long_hill", "--speed-kmh", "30")
        runs = {name: self.tvd_json(*common, *extra) for name, extra in
                (("default", ()), ("all", ("--max-mode-hz", "0")), ("exact", ("--method", "exact")))}
        self.assertFalse([w for w in runs["default"]["warnings"] if "ground-tie" in w])
        for name, how in (("all", "--max-mode-hz 0 keeps every mode dynamic"),
                          ("exact", "--method exact integrates every mode")):
            tie = [w for w in runs[name]["warnings"] if "ground-tie" in w]
            self.assertEqual(len(tie), 1, runs[name]["warnings"])
            self.assertIn("the ground-tie modes (9139 to 58125 Hz", tie[0])
            self.assertIn(f"({how})", tie[0])
            self.assertIn("up to 4.9 % of a tie's critical damping", tie[0])
        # A step fine enough to resolve the ties makes them dynamic under the default cut-off
        # (its Nyquist frequency), part of them here: said all the same.
        fine = self.tvd_json(*common, "--dt", "1e-5")
        tie = [w for w in fine["warnings"] if "ground-tie" in w]
        self.assertEqual(len(tie), 1, fine["warnings"])
        self.assertIn("from 9139 Hz up to the cut-off 50000 Hz (of 9139 to 58125 Hz", tie[0])
        base = runs["default"]
        for name in ("all", "exact"):
            d = runs[name]
            peak = d["ground_contact"]["peak_ground_force_left_n"]
            self.assertGreater(peak / base["ground_contact"]["peak_ground_force_left_n"], 1.1)
            self.assertAlmostEqual(d["peak_hull_vertical_accel_m_s2"] /
                                   base["peak_hull_vertical_accel_m_s2"], 1.0, delta=0.01)
            self.assertAlmostEqual(peak / runs["exact"]["ground_contact"]["peak_ground_force_left_n"],
                                   1.0, delta=1e-6)

    def test_simulate_rates_and_named_points_are_consistent(self):
        """The CSV's rates are the time derivatives of its displacements (yaw included), and a
        named point moves with the hull as a rigid body: u_z(P) = u_z(G) + roll (y_P - y_G) -
        pitch (x_P - x_G) for the small rotations of the linear model, the same for the vertical
        accelerations, and a_P = a_G + alpha x r along and across. Out-of-phase
        waves (built in with the 1 m lateral offset of paper §4.2.1), so that the hull rolls as
        well."""
        out = self.path("oop.csv")
        dt = 1e-3
        d = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          "oop_waves", "--speed-kmh", "10", "--dt",
                          str(dt), "--cache-dir", self.cache, "--out", out)
        header, rows = read_csv(out)
        c = {name: rows[:, i] for i, name in enumerate(header)}
        deg = np.pi / 180.0

        def assert_derivative(value, rate, scale=1.0):
            # Central differences: O(dt^2 f^2) off for the few-Hz hull motion.
            numeric = np.gradient(c[value], dt)[1:-1]
            err = np.abs(numeric - scale * c[rate][1:-1]).max()
            self.assertLess(err, 0.01 * np.abs(c[rate]).max(), f"d/dt {value} vs {rate}")

        assert_derivative("hull_heave_m", "hull_heave_rate_m_s")
        assert_derivative("hull_pitch_deg", "hull_pitch_rate_deg_s")
        assert_derivative("hull_roll_deg", "hull_roll_rate_deg_s")
        assert_derivative("hull_heave_rate_m_s", "hull_vertical_accel_m_s2")
        assert_derivative("hull_pitch_rate_deg_s", "hull_pitch_accel_deg_s2")
        assert_derivative("hull_roll_rate_deg_s", "hull_roll_accel_deg_s2")
        assert_derivative("hull_yaw_deg", "hull_yaw_rate_deg_s")
        assert_derivative("hull_yaw_rate_deg_s", "hull_yaw_accel_deg_s2")
        for quantity in ("yaw_deg", "yaw_rate_deg_s", "yaw_accel_deg_s2"):
            self.assertAlmostEqual(d["peak_" + quantity], np.abs(c["hull_" + quantity]).max(),
                                   places=5)
        self.assertGreater(d["peak_roll_deg"], 0.5)
        self.assertAlmostEqual(d["peak_roll_rate_deg_s"], np.abs(c["hull_roll_rate_deg_s"]).max(),
                               places=5)

        with open(VEHICLE) as f:
            description = yaml.safe_load(f)
        cog = np.array([description["hull"]["cog_x"]["value"], 0.0,
                        description["hull"]["cog_height"]["value"]])
        peaks = {p["point"]: p for p in d["peaks_at_points"]}
        self.assertEqual(sorted(peaks), ["crew_seat", "sensor_mount"])
        for name, peak in peaks.items():
            r = np.array(description["named_points"][name]["value"]) - cog
            for value, heave, roll, pitch in (
                    ("_vertical_m", "hull_heave_m", "hull_roll_deg", "hull_pitch_deg"),
                    ("_accel_z_m_s2", "hull_vertical_accel_m_s2", "hull_roll_accel_deg_s2",
                     "hull_pitch_accel_deg_s2")):
                rigid = c[heave] + deg * (c[roll] * r[1] - c[pitch] * r[0])
                np.testing.assert_allclose(c[name + value], rigid, rtol=0,
                                           atol=1e-6 * np.abs(rigid).max(), err_msg=name + value)
            # Across and along: a_P = a_G + alpha x r with alpha = (roll'', pitch'', yaw''); the
            # yaw term is what the hull's yaw columns give (without them the lateral
            # acceleration of a point off the CoG could not be had from the CSV).
            alpha = [deg * c["hull_" + a + "_accel_deg_s2"] for a in ("roll", "pitch", "yaw")]
            rigid_x = c["hull_longitudinal_accel_m_s2"] + alpha[1] * r[2] - alpha[2] * r[1]
            rigid_y = c["hull_lateral_accel_m_s2"] + alpha[2] * r[0] - alpha[0] * r[2]
            for column, rigid in (("_accel_x_m_s2", rigid_x), ("_accel_y_m_s2", rigid_y)):
                np.testing.assert_allclose(c[name + column], rigid, rtol=0,
                                           atol=1e-6 * np.abs(rigid).max(), err_msg=name + column)
            yaw_term = np.abs(alpha[2] * r[0]).max()
            self.assertGreater(yaw_term, 1e-3 * np.abs(rigid_y).max(), name)
            self.assertAlmostEqual(peak["peak_vertical_displacement_m"],
                                   np.abs(c[name + "_vertical_m"]).max(), places=7)
            self.assertAlmostEqual(peak["peak_vertical_accel_m_s2"],
                                   np.abs(c[name + "_accel_z_m_s2"]).max(), places=5)

    def test_vibration_total_values_sum_the_axes(self):
        """ISO 2631-1 eq. (9) with k = 1 on every axis: a_v = sqrt(a_wx^2 + a_wy^2 + a_wz^2),
        at the hull and at every named point, on the out-of-phase waves, which roll the hull
        (a_wy > 0). The rotations: a_w (We) of the hull's roll, pitch and yaw accelerations in
        the CSV, weighted here by SciPy from the standard's analogue We (bilinear at the run's
        rate), within 0.2 % (1e-4 seen; Wd's transition at 2 Hz instead of 1 Hz reads half);
        a_r with the seat surface's factors 0.63, 0.40, 0.20 m/rad, and the six-axis total
        sqrt(a_v^2 + a_r^2)."""
        series = self.path("oop.csv")
        d = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          "oop_waves", "--speed-kmh", "10", "--cache-dir", self.cache,
                          "--out", series)
        header, rows = read_csv(series)
        fs = 1.0 / d["time_step_s"]
        # ISO 2631-1 We: band limits 0.4 and 100 Hz (Butterworth), a-v transition f3 = f4 = 1 Hz,
        # Q4 = 0.63, no upward step.
        w1, w2, w4 = 2 * np.pi * 0.4, 2 * np.pi * 100.0, 2 * np.pi * 1.0
        q1 = 1 / np.sqrt(2)
        num = np.polymul(np.polymul([1, 0, 0], [w2 * w2]), [1 / w4, 1])
        den = np.polymul(np.polymul([1, w1 / q1, w1 * w1], [1, w2 / q1, w2 * w2]),
                         [1 / w4 ** 2, 1 / (0.63 * w4), 1])
        b, a = bilinear(num, den, fs)
        expected = {}
        for axis, column in (("roll", "hull_roll_accel_deg_s2"),
                             ("pitch", "hull_pitch_accel_deg_s2"),
                             ("yaw", "hull_yaw_accel_deg_s2")):
            weighted = lfilter(b, a, np.radians(rows[:, header.index(column)]))
            expected[axis] = np.sqrt(np.mean(weighted ** 2))
        self.assertGreater(min(expected.values()), 1e-2, expected)
        for p in [d["comfort"]] + d["comfort_at_points"]:
            total = np.sqrt(p["weighted_rms_x_m_s2"] ** 2 + p["weighted_rms_y_m_s2"] ** 2
                            + p["weighted_rms_m_s2"] ** 2)
            self.assertAlmostEqual(p["vibration_total_value_m_s2"] / total, 1.0, delta=1e-8, msg=p)
            self.assertGreater(p["weighted_rms_y_m_s2"], 1e-3, p)
            for axis, value in expected.items():
                self.assertAlmostEqual(p[f"weighted_rms_{axis}_rad_s2"] / value, 1.0, delta=2e-3,
                                       msg=f"{p['point']} {axis}")
            rotational = np.sqrt((0.63 * p["weighted_rms_roll_rad_s2"]) ** 2
                                 + (0.40 * p["weighted_rms_pitch_rad_s2"]) ** 2
                                 + (0.20 * p["weighted_rms_yaw_rad_s2"]) ** 2)
            self.assertAlmostEqual(p["rotational_total_value_m_s2"] / rotational, 1.0, delta=1e-8)
            self.assertAlmostEqual(p["seat_surface_total_value_m_s2"] / np.hypot(total, rotational),
                                   1.0, delta=1e-8)

    def test_simulate_text_gives_the_basic_methods_verdict_of_the_json(self):
        """ISO 2631-1 6.2.1 and 6.3.3 in the text output: per point, in the JSON's order (the
        hull, then the named points), 'a_wz suffices' where the JSON's basic_method_sufficient
        is true, else the limits and 'report the VDV and MTVV beside a_wz'; on a class C road
        (where the points differ) and over an obstacle."""
        road = self.path("verdict_road_C.csv")
        self.tvd("terrain", "--iso8608", "C", "--length", "300", "--seed", "2", "--out", road)
        seen = set()
        for track, speed in ((road, "40"), ("half_round:0.1", "10")):
            args = ("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", track,
                    "--speed-kmh", speed, "--cache-dir", self.cache)
            d = self.tvd_json(*args)
            text = self.tvd(*args).stdout
            verdicts = [line for line in text.splitlines()
                        if "a_wz suffices" in line or "beside a_wz" in line]
            expected = [p["basic_method_sufficient"]
                        for p in [d["comfort"]] + d["comfort_at_points"]]
            self.assertEqual(["a_wz suffices (ISO 2631-1 6.2.1, 6.3.3)" in line
                              for line in verdicts], expected, text)
            for line in verdicts:
                if "beside a_wz" in line:
                    self.assertIn("over ISO 2631-1's limits (9, 1.5, 1.75; 6.2.1, 6.3.3)", line)
            seen.update(expected)
        self.assertEqual(seen, {True, False})  # both verdicts checked

    def test_simulate_braking_travel_inertia(self):
        """A braking profile loads the model with the travel inertia a(t) f_a: on a flat track at
        a constant rate the hull pitch settles to a H K_R^-1 travel_load (the reduced-model
        file's own static response, 1 %), nose down; travel_accel_m_s2 is the profile's exact
        derivative and the x accelerations are absolute (relative + a); at constant speed the
        travel column is 0 and the x accelerations are the model's."""
        model = self.path("untracked.mat")
        self.tvd("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--out", model)
        m = scipy.io.loadmat(model)
        names = [str(c[0]) for c in m["output_names"].ravel()]
        per_a = m["H"] @ np.linalg.solve(m["K_R"], m["travel_load"].ravel())
        flat = self.path("flat.csv")
        with open(flat, "w") as f:
            f.write("x,h\n-10,0\n400,0\n")
        # 60 km/h for 1 s, then -0.5 m/s^2 for 25 s (to 15 km/h): 5 % modal damping lets the
        # lowest modes' transient die out well within 25 s.
        accel = -0.5
        profile = self.path("brake.csv")
        with open(profile, "w") as f:
            f.write(f"time_s,speed_m_s\n0,{60 / 3.6!r}\n1,{60 / 3.6!r}\n26,{60 / 3.6 + 25 * accel!r}\n")
        common = ("simulate", "--vehicle", VEHICLE, "--reduced", model, "--track", flat)
        out = self.path("brake_run.csv")
        d = self.tvd_json(*common, "--speed-profile", profile, "--out", out)
        header, rows = read_csv(out)
        c = {name: rows[:, i] for i, name in enumerate(header)}
        t = c["time_s"]
        self.assertEqual(header[-4], "travel_accel_m_s2")
        np.testing.assert_allclose(c["travel_accel_m_s2"],
                                   np.where((t >= 1 - 1e-9) & (t < 26 - 1e-9), accel, 0.0),
                                   rtol=0, atol=1e-9)
        self.assertAlmostEqual(d["peak_travel_accel_m_s2"], -accel, places=9)
        end = t > 25.5
        pitch = accel * per_a[names.index("hull ry")]
        surge = accel * per_a[names.index("hull ux")]
        self.assertGreater(pitch, 0.0)  # braking: nose down (+ry, REP-103)
        self.assertGreater(surge, 0.0)  # and the hull surges forward
        np.testing.assert_allclose(c["hull_pitch_deg"][end], np.degrees(pitch), rtol=1e-2)
        np.testing.assert_allclose(c["hull_surge_m"][end], surge, rtol=1e-2)
        # Settled, the hull moves with the path frame: an accelerometer reads a itself.
        np.testing.assert_allclose(c["hull_longitudinal_accel_m_s2"][end], accel, rtol=1e-2)
        points = [name for name in header if name.endswith("_accel_x_m_s2")]
        self.assertIn("crew_seat_accel_x_m_s2", points)
        for name in points:
            np.testing.assert_allclose(c[name][end], accel, rtol=2e-2, err_msg=name)
        # The travel inertia acts along x: settled, the road carries the weight again, half on
        # each side (the vertical accelerations have died out).
        total = c["ground_force_left_n"] + c["ground_force_right_n"]
        np.testing.assert_allclose(total[end], total[0], rtol=1e-3)
        np.testing.assert_allclose(c["ground_force_left_n"], c["ground_force_right_n"], rtol=1e-6)
        # Before the braking nothing moves on the flat track (round-off of the modal engine's
        # equilibrium: 3e-9 deg, against the braking's 0.02 deg).
        self.assertLess(np.abs(c["hull_pitch_deg"][t < 1]).max(), 1e-6)
        self.assertLess(np.abs(c["hull_longitudinal_accel_m_s2"][t < 1]).max(), 1e-6)
        braking = d

        steady = self.path("steady.csv")
        d = self.tvd_json(*common, "--speed-kmh", "60", "--out", steady)
        # The braking is in ISO 2631's horizontal a_wx (Wd passes its onset and end; on the flat
        # track at constant speed there is nothing).
        self.assertLess(d["comfort"]["weighted_rms_x_m_s2"], 1e-6)
        # Braking straight ahead is fore and aft only: a_wx, no lateral a_wy, at every point.
        for p in [braking["comfort"]] + braking["comfort_at_points"]:
            self.assertGreater(p["weighted_rms_x_m_s2"], 1e-3, p)
            self.assertLess(p["weighted_rms_y_m_s2"], 1e-6, p)
        header, rows = read_csv(steady)
        self.assertEqual(header[-4], "travel_accel_m_s2")
        self.assertEqual(np.abs(rows[:, -4]).max(), 0.0)
        self.assertEqual(d["peak_travel_accel_m_s2"], 0.0)
        self.assertLess(np.abs(rows[:, header.index("hull_longitudinal_accel_m_s2")]).max(), 1e-6)

    def test_simulate_speed_profile(self):
        """--speed-profile: a constant profile is the --speed-kmh run; a braking profile's
        stations are the closed-form integral of its speed; a profile that ends first ends the
        run; bad profiles are named."""
        common = ("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                  "long_hill", "--cache-dir", self.cache)
        constant = self.path("constant.csv")
        with open(constant, "w") as f:
            f.write("time_s,speed_kmh\n0,30\n10,30\n")
        self.tvd(*common, "--speed-kmh", "30", "--out", self.path("v30.csv"))
        d = self.tvd_json(*common, "--speed-profile", constant, "--out", self.path("p30.csv"))
        self.assertEqual(d["speed_profile"], constant)
        self.assertAlmostEqual(d["mean_speed_kmh"], 30.0, places=6)
        self.assertAlmostEqual(d["travelled_m"], 30.0, places=6)
        h1, a = read_csv(self.path("v30.csv"))
        h2, b = read_csv(self.path("p30.csv"))
        self.assertEqual(h1, h2)
        self.assertEqual(a.shape, b.shape)
        # Dense vs held input paths, stations computed two ways: displacements and accelerations
        # agree to round-off; the rates carry the slope input u' = v dh/dx, which jumps at the
        # terrain's grid nodes, where a sample lands every 6 steps at 30 km/h and round-off
        # picks the side (1.7e-5 of the peak heave rate; on this symmetric hill the roll rate is
        # round-off, below 1e-3 deg/s, and so are its jumps).
        # The ground forces (~2e5 N, written to 9 digits: 1e-3 N) agree to their last digit; a
        # sole at the threshold may then count in tension on one path only.
        for i, name in enumerate(h1):
            rate = "_rate_" in name
            if name == "contacts_in_tension":
                self.assertLessEqual(np.abs(b[:, i] - a[:, i]).max(), 1.0)
                continue
            digits = 1e-8 * np.abs(a[:, i]).max() if name.startswith("ground_force_") else 0.0
            np.testing.assert_allclose(
                b[:, i], a[:, i], rtol=0, err_msg=name,
                atol=(1e-4 if rate else 1e-9) * np.abs(a[:, i]).max() + (1e-3 if rate else 1e-8) + digits)

        # 50 km/h for 1 s, then braking at a constant rate to 10 km/h at 3 s, then held.
        braking = self.path("braking.csv")
        with open(braking, "w") as f:
            f.write("# brake before the hill\ntime_s,speed_kmh\n0,50\n1,50\n3,10\n20,10\n")
        out = self.path("braking_run.csv")
        d = self.tvd_json(*common, "--speed-profile", braking, "--out", out)
        header, rows = read_csv(out)
        c = {name: rows[:, i] for i, name in enumerate(header)}
        t = c["time_s"]
        v0, v1 = 50 / 3.6, 10 / 3.6
        accel = (v1 - v0) / 2.0
        s = np.where(t <= 1, v0 * t,
                     np.where(t <= 3, v0 + v0 * (t - 1) + accel * (t - 1) ** 2 / 2,
                              v0 + (v0 + v1) + v1 * (t - 3)))
        # (the CSV has 9 significant digits)
        np.testing.assert_allclose(c["station_m"] - c["station_m"][0], s, rtol=0, atol=1e-7)
        self.assertGreaterEqual(s[-1], 30.0)  # ends when the track is covered ...
        self.assertLess(s[-2], 30.0)          # ... and not a step later
        self.assertAlmostEqual(d["travelled_m"], s[-1], places=6)
        self.assertAlmostEqual(d["max_speed_kmh"], 50.0, places=9)
        self.assertGreater(d["peak_hull_heave_m"], 0.35)  # it still climbs the hill

        short = self.path("short.csv")
        with open(short, "w") as f:
            f.write("time_s,speed_m_s\n0,5\n1,5\n")
        d = self.tvd_json(*common, "--speed-profile", short)
        self.assertAlmostEqual(d["simulated_seconds"], 1.0, places=9)
        self.assertAlmostEqual(d["travelled_m"], 5.0, places=9)

        bad = self.path("bad_profile.csv")
        with open(bad, "w") as f:
            f.write("time_s,speed_kmh\n0,30\n2,30\n1,20\n")
        r = self.tvd(*common, "--speed-profile", bad, status=INPUT_ERROR_STATUS)
        self.assertIn("bad_profile.csv: row 4, column 1: time 1 s is not after", r.stderr)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1)
        r = self.tvd(*common, "--speed-profile", constant, "--speed-kmh", "30",
                     status=INPUT_ERROR_STATUS)
        self.assertIn("excludes", r.stderr)
        endless = self.path("endless.csv")
        with open(endless, "w") as f:
            f.write("time_s,speed_kmh\n0,10\n1e300,10\n")
        # The step limit applies to the steps run: a profile far longer than the track runs to
        # the track's end (30 m at 10 km/h: 10.8 s) ...
        d = self.tvd_json(*common, "--speed-profile", endless)
        self.assertAlmostEqual(d["travelled_m"], 30.0, places=2)
        self.assertAlmostEqual(d["simulated_seconds"], 10.8, places=2)
        # ... and one that would not reach it within the limit is refused.
        stalled = self.path("stalled.csv")
        with open(stalled, "w") as f:
            f.write("time_s,speed_kmh\n0,0.001\n1e300,0.001\n")
        r = self.tvd(*common, "--speed-profile", stalled, status=INPUT_ERROR_STATUS)
        self.assertIn("stalled.csv: the profile lasts 1e+300 s", r.stderr)
        self.assertIn("does not reach the track's end", r.stderr)
        self.assertIn("at most 1e+07", r.stderr)
        # Plausible inputs warn of nothing (the braking above is 0.56 g) ...
        d = self.tvd_json(*common, "--speed-profile", braking)
        self.assertFalse([w for w in d["warnings"] if "m/s^2" in w or "slopes" in w], d["warnings"])
        # ... a profile in ms read as s (30 km/h within 1 ms), and a 10 m bump over 5 m (metres
        # where millimetres were meant), run but are said, on stderr and in the JSON.
        jolt = self.path("jolt.csv")
        with open(jolt, "w") as f:
            f.write("time_s,speed_kmh\n0,0\n0.001,30\n20,30\n")
        bump = self.path("tall_bump.csv")
        x = np.arange(0.0, 30.0001, 0.05)
        h = 10.0 * np.sin(np.pi * np.clip(x - 10.0, 0.0, 5.0) / 5.0)
        with open(bump, "w") as f:
            f.write("x,-3,3\n")
            for xi, hi in zip(x, h):
                f.write(f"{xi:.2f},{hi:.6f},{hi:.6f}\n")
        r = self.tvd("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", bump,
                     "--speed-profile", jolt, "--cache-dir", self.cache, "--json")
        d = json.loads(r.stdout)
        jolts = [w for w in d["warnings"] if w.startswith(jolt + ": the speed changes at up to 8333")]
        slopes = [w for w in d["warnings"] if w.startswith(bump + ": slopes up to 6.2")]
        self.assertEqual((len(jolts), len(slopes)), (1, 1), d["warnings"])
        self.assertIn("times in ms read as s?", jolts[0])
        self.assertIn("heights in mm read as m?", slopes[0])
        self.assertIn("tvd: warning: " + slopes[0], r.stderr)
        # Stations in mm read as m: a gentle profile sampled every 2 m (median) is said too.
        coarse = self.path("coarse.csv")
        with open(coarse, "w") as f:
            f.write("x,h\n")
            for xi in np.arange(0.0, 200.0001, 2.0):
                f.write(f"{xi:.1f},{0.2 * np.sin(xi / 20.0):.6f}\n")
        d = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          coarse, "--speed-kmh", "60", "--cache-dir", self.cache)
        self.assertEqual([w for w in d["warnings"] if "sampled every" in w],
                         [coarse + ": sampled every 2 m (median spacing), coarser than 1 m: the "
                          "road wheels (0.5-1 m apart) and the track pads see no feature shorter "
                          "than 4 m; stations in mm read as m?"], d["warnings"])

    def test_terrain_iso8608_waviness(self):
        """tvd terrain --waviness w (as ride --iso8608's): the road's spectrum falls as n^-w. Over
        one period, untapered, its variance in each band of the periodogram is the closed form
        G_d(n0) n0^w (n_a^(1-w) - n_b^(1-w)) / (w - 1), which falls by 2^(w-1) per octave: 4
        for w = 3, 2 for ISO 8608's w = 2."""
        length, n0, n_low, n_high, spacing = 400.0, 0.1, 0.011, 2.83, 0.05
        road = self.path("wavy.csv")
        d = self.tvd_json("terrain", "--iso8608", "C", "--waviness", "3", "--length",
                          str(length), "--taper", "0", "--seed", "3", "--out", road)
        self.assertEqual(d["waviness"], 3)

        def band(a, b, w=3.0):
            return 256e-6 * n0 ** w * (a ** (1 - w) - b ** (1 - w)) / (w - 1)

        self.assertAlmostEqual(d["band_rms_height_m"] / np.sqrt(band(n_low, n_high)), 1.0, places=8)
        self.assertAlmostEqual(d["rms_height_m"] / d["band_rms_height_m"], 1.0, places=9)
        _, stations, heights = read_terrain_csv(road)
        profile = heights[:-1, 0]  # one period: the last station repeats the first
        self.assertEqual(len(profile), round(length / spacing))
        spectrum = np.abs(np.fft.rfft(profile)) ** 2 * 2 / len(profile) ** 2  # one-sided variance
        n = np.fft.rfftfreq(len(profile), spacing)
        for a in (0.05, 0.1, 0.2, 0.4, 0.8):
            # Octaves [a, 2a) hold whole bins (a multiple of 1/L): each is the closed form
            # within the discrete band's share at its edges (bins of width 1/L = 2.5e-3).
            inside = (n >= a - 1.25e-3) & (n < 2 * a - 1.25e-3)
            self.assertAlmostEqual(spectrum[inside].sum() / band(a - 1.25e-3, 2 * a - 1.25e-3),
                                   1.0, delta=0.01, msg=f"octave from {a} cycles/m")
        r = self.tvd("terrain", "--iso8608", "C", "--waviness", "9", "--out", self.path("w9.csv"),
                     status=2)
        self.assertIn("--waviness", r.stderr)
        r = self.tvd("terrain", "--track", "long_hill", "--waviness", "3",
                     "--out", self.path("w3.csv"), status=2)
        self.assertIn("--waviness requires --iso8608", r.stderr)

    def test_terrain_iso8608_road_and_ride_on_it(self):
        """tvd terrain --iso8608: the road's r.m.s. height is the PSD's over the generated band
        (closed form); simulated on it, a class-D road (4x the PSD of C, same seed, so every height
        exactly doubles) doubles every response of the linear model, a_w and VDV, and quadruples
        the absorbed power."""
        length, n0, n_low, n_high = 80.0, 0.1, 0.011, 2.83
        runs = {}
        for road_class, reference_psd in (("C", 256e-6), ("D", 1024e-6)):
            road = self.path(f"road_{road_class}.csv")
            d = self.tvd_json("terrain", "--iso8608", road_class, "--length", str(length),
                              "--taper", "0", "--seed", "7", "--out", road)
            band = reference_psd * n0 ** 2 * (1 / n_low - 1 / n_high)  # integral of G_d(n0)(n/n0)^-2
            self.assertAlmostEqual(d["band_rms_height_m"] / np.sqrt(band), 1.0, places=8)
            self.assertAlmostEqual(d["rms_height_m"] / d["band_rms_height_m"], 1.0, places=9)
            self.assertEqual(d["stations"], round(length / 0.05) + 1)
            self.assertEqual(d["end_station_m"], length)
            if road_class == "C":
                # "The same seed gives the same road on every machine": the phases come from
                # std::mt19937_64 (its sequence fixed by the C++ standard) through the top 53
                # bits, not from a library's distribution. Heights of seed 7 as first generated
                # (2026-12-05); only libm's cos may move their last digits.
                _, stations, heights = read_terrain_csv(road)
                for x, height in ((0.0, 0.028042333836760594), (20.0, 0.0009948818003772976),
                                  (60.0, -0.015191744029391458)):
                    np.testing.assert_allclose(heights[np.argmin(np.abs(stations - x))], height,
                                               rtol=1e-9, err_msg=f"x = {x} m")
            out = self.path(f"ride_{road_class}.csv")
            runs[road_class] = (self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant",
                                              "untracked", "--track", road, "--speed-kmh", "40",
                                              "--cache-dir", self.cache, "--out", out),
                                *read_csv(out))
        (c, header, c_rows), (d, _, d_rows) = runs["C"], runs["D"]
        self.assertGreater(c["comfort"]["weighted_rms_m_s2"], 0.1)
        for i, name in enumerate(header[2:], start=2):
            if (any(k in name for k in ("roll", "lateral", "accel_y", "sway", "yaw"))
                    or name == "contacts_in_tension"):
                continue  # round-off on this road, uniform across the width; a sign count
            d_col, c_col = d_rows[:, i], c_rows[:, i]
            digits = 0.0
            if name.startswith("ground_force_"):
                # Affine: the static load (the same on both roads) plus the road's part; written
                # to 9 digits (1e-3 N of 2e5 N).
                d_col, c_col, digits = d_col - d_col[0], c_col - c_col[0], 3e-3
            np.testing.assert_allclose(d_col, 2 * c_col, rtol=0,
                                       atol=1e-7 * np.abs(d_col).max() + 1e-12 + digits,
                                       err_msg=name)
        for key in ("weighted_rms_m_s2", "vdv_m_s1_75", "mtvv_m_s2", "mtvv_linear_m_s2"):
            self.assertAlmostEqual(d["comfort"][key] / c["comfort"][key], 2.0, places=7, msg=key)
        self.assertAlmostEqual(d["comfort"]["absorbed_power_w"] / c["comfort"]["absorbed_power_w"],
                               4.0, places=6)
        # ISO 2631-1's ratios (6.2.1, 6.3.3) are the metrics' and do not scale with the road.
        for point in [c["comfort"]] + c["comfort_at_points"]:
            rms, duration = point["weighted_rms_m_s2"], c["simulated_seconds"]
            self.assertAlmostEqual(point["crest_factor"] * rms / point["peak_weighted_m_s2"], 1.0,
                                   places=8)
            self.assertAlmostEqual(point["mtvv_ratio"] * rms / point["mtvv_m_s2"], 1.0, places=8)
            self.assertAlmostEqual(point["mtvv_linear_ratio"] * rms / point["mtvv_linear_m_s2"],
                                   1.0, places=8)
            # T = samples / fs: one sample more than the steps simulated.
            self.assertAlmostEqual(point["vdv_ratio"] * rms * duration ** 0.25
                                   / point["vdv_m_s1_75"], 1.0, delta=1e-4)
            self.assertEqual(point["basic_method_sufficient"],
                             point["crest_factor"] <= 9 and point["mtvv_ratio"] <= 1.5
                             and point["mtvv_linear_ratio"] <= 1.5 and point["vdv_ratio"] <= 1.75)
            self.assertGreater(point["crest_factor"], np.sqrt(2))  # a random road, not a sinusoid
        for key in ("crest_factor", "mtvv_ratio", "mtvv_linear_ratio", "vdv_ratio",
                    "basic_method_sufficient"):
            self.assertAlmostEqual(d["comfort"][key], c["comfort"][key], places=7, msg=key)
        self.assertAlmostEqual(d["comfort"]["peak_weighted_m_s2"]
                               / c["comfort"]["peak_weighted_m_s2"], 2.0, places=7)

        # A road too short for the default band's longest waves starts its band higher, said
        # with what that costs; at 46 m (1/(2 L) < 0.011) nothing is said.
        r = self.tvd("terrain", "--iso8608", "C", "--length", "10", "--out", self.path("short.csv"),
                     "--json")
        short = json.loads(r.stdout)
        self.assertEqual(short["band_cycles_per_m"], [0.05, 2.83])
        self.assertIn("tvd: note: a road of 10 m holds no wavelength longer than 20 m, so its band "
                      "starts at 0.05 cycles/m, not the default 0.011: r.m.s. height 7.09 mm "
                      "against the class's 15.2 mm over the default band (--length 46 or more "
                      "keeps it)", r.stderr)
        self.assertAlmostEqual(short["band_rms_height_m"] * 1e3, 7.09, delta=0.005)
        r = self.tvd("terrain", "--iso8608", "C", "--length", "46", "--out", self.path("46.csv"))
        self.assertNotIn("note", r.stderr)

        # A length that is not a whole number of steps is raised to the next one (the road is
        # L-periodic, its last station repeating the first), said; it once came out 599.93 m.
        # And a spacing whose linear interpolation passes less than 80 % of the PSD at the
        # band's top, sinc^4(n dx), is said with the spacing that keeps 80 %.
        r = self.tvd("terrain", "--iso8608", "C", "--length", "600", "--spacing", "0.17",
                     "--taper", "0", "--out", self.path("coarse.csv"), "--json")
        coarse = json.loads(r.stdout)
        self.assertAlmostEqual(coarse["end_station_m"], 600.1, places=9)
        self.assertEqual(coarse["stations"], 3531)
        self.assertAlmostEqual(coarse["rms_height_m"] / coarse["band_rms_height_m"], 1.0,
                               places=9)  # periodic over its raised length, exactly
        a = np.pi * n_high * 0.17
        self.assertAlmostEqual(coarse["interpolated_psd_share_at_band_top"],
                               (np.sin(a) / a) ** 4, places=9)
        self.assertIn("tvd: note: --length 600 m is not a whole number of --spacing 0.17 m "
                      "steps: the road is 600.1 m long", r.stderr)
        self.assertIn("at --spacing 0.17 m only 19 % at the band's top (2.83 cycles/m), so the "
                      "vehicle rides a smoother road than class C; --spacing 0.0647 m or less "
                      "keeps 80 %", r.stderr)
        r = self.tvd("terrain", "--iso8608", "C", "--length", "600", "--spacing", "0.0647",
                     "--out", self.path("fine.csv"))
        self.assertNotIn("smoother road", r.stderr)
        r = self.tvd("terrain", "--iso8608", "C", "--length", "600", "--spacing", "0.0648",
                     "--out", self.path("fine.csv"))
        self.assertIn("at --spacing 0.0648 m only 79 %", r.stderr)
        # At the finest spacing (1 um) no finer one can keep 80 %: the band's top is named
        # instead (sinc^4 depends on n dx alone: 0.1831 / 1e-6 m).
        r = self.tvd("terrain", "--iso8608", "C", "--length", "0.01", "--spacing", "1e-6",
                     "--min-frequency", "1000", "--max-frequency", "5e5", "--taper", "0",
                     "--out", self.path("micro.csv"))
        self.assertIn("at --spacing 1e-06 m only 16 % at the band's top (500000 cycles/m), so "
                      "the vehicle rides a smoother road than class C; --max-frequency 183000 "
                      "cycles/m or less keeps 80 % (--spacing cannot be finer than 1e-06 m)",
                      r.stderr)

        # A band reaching below 1/(2 L) is generated from 1/(2 L) up, and said so.
        r = self.tvd("terrain", "--iso8608", "C", "--length", str(length), "--min-frequency",
                     "1e-5", "--out", self.path("long_waves.csv"), "--json")
        d = json.loads(r.stdout)
        self.assertEqual(d["band_cycles_per_m"], [0.5 / length, n_high])
        band = 256e-6 * n0 ** 2 * (2 * length - 1 / n_high)
        self.assertAlmostEqual(d["band_rms_height_m"] / np.sqrt(band), 1.0, places=8)
        self.assertIn("--min-frequency 1e-05 cycles/m is below 1/(2 --length) = 0.00625", r.stderr)
        r = self.tvd("terrain", "--out", self.path("x.csv"), status=INPUT_ERROR_STATUS)
        self.assertIn("give --track NAME or --iso8608 CLASS", r.stderr)
        r = self.tvd("terrain", "--iso8608", "Q", "--out", self.path("x.csv"),
                     status=INPUT_ERROR_STATUS)
        self.assertIn("road class A..H, got 'Q'", r.stderr)
        r = self.tvd("terrain", "--track", "long_hill", "--length", "50", "--out",
                     self.path("x.csv"), status=INPUT_ERROR_STATUS)
        self.assertIn("--length requires --iso8608", r.stderr)
        # A road narrower than the vehicle is accepted with one warning naming both spans.
        narrow = self.path("narrow.csv")
        self.tvd("terrain", "--iso8608", "C", "--width", "1", "--length", "20", "--out", narrow)
        r = self.tvd("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", narrow,
                     "--speed-kmh", "30", "--cache-dir", self.cache, "--json")
        self.assertEqual(len(input_warnings(json.loads(r.stdout)["warnings"])), 1)
        self.assertEqual(r.stderr.count("tvd: warning: the contacts span y = -1.555 .. 1.555 m but "
                                        "the terrain's lines only -0.5 .. 0.5 m"), 1, r.stderr)
        # A built-in track written out and read back simulates like the built-in itself.
        hill = self.path("hill.yaml")
        self.tvd("terrain", "--track", "long_hill", "--out", hill)
        a = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          hill, "--speed-kmh", "30", "--cache-dir", self.cache)
        b = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          "long_hill", "--speed-kmh", "30", "--cache-dir", self.cache)
        for key in ("peak_hull_heave_m", "peak_hull_vertical_accel_m_s2", "peak_pitch_deg"):
            self.assertAlmostEqual(a[key], b[key], places=9, msg=key)
        self.assertEqual(input_warnings(a["warnings"]), [])

    def ride_road(self):
        """An 80 m class-C road (seed 7, no taper) shared by the ride tests; its path."""
        road = self.path("ride_road_C.csv")
        if not os.path.exists(road):
            self.tvd("terrain", "--iso8608", "C", "--length", "80", "--taper", "0", "--seed", "7",
                     "--out", road)
        return road

    def test_ride_sweep_is_simulate_and_finds_each_limit(self):
        """tvd ride: every run's metrics are those tvd simulate reports at that speed (the peak
        independently, as SciPy's 4th-order Butterworth at 30 Hz of simulate's acceleration);
        each limit is bracketed within the tolerance by runs on either side of it, and at the
        interpolated speed simulate absorbs the limit; the three outcomes (reached, already at
        the lowest speed, not reached) are told apart; CSV rows = JSON runs."""
        from scipy.signal import butter, sosfilt
        road, out = self.ride_road(), self.path("ride.csv")
        power_limit, peak_limit, tolerance = 2.0, 0.5, 0.1
        d = self.tvd_json("ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track", road,
                          "--speeds", "10:40:10", "--power-limit-w", str(power_limit),
                          "--peak-limit-g", str(peak_limit), "--cache-dir", self.cache,
                          "--out", out)
        self.assertEqual(d["points"], ["hull", "crew_seat", "sensor_mount"])
        self.assertEqual(d["speeds_kmh"], [10, 20, 30, 40])
        speeds = [r["speed_kmh"] for r in d["runs"]]
        self.assertEqual(speeds, sorted(speeds))
        self.assertEqual([v for v, r in zip(speeds, d["runs"]) if r["in_sweep"]], [10, 20, 30, 40])
        self.assertEqual(d["simulations"], len(d["runs"]))
        header, rows = read_csv(out)
        self.assertEqual(rows.shape[0], len(d["runs"]))
        np.testing.assert_allclose(rows[:, 0], speeds, rtol=1e-9)
        for i, point in enumerate(d["points"]):
            for key in ("absorbed_power_w", "peak_up_g", "vdv_z_m_s1_75", "seat_surface_total_value_m_s2"):
                column = rows[:, header.index(f"{point}_{key}")]
                np.testing.assert_allclose(column, [r["points"][i][key] for r in d["runs"]],
                                           rtol=1e-8, err_msg=f"{point} {key}")

        # One sweep speed against tvd simulate.
        by_speed = {r["speed_kmh"]: {p["point"]: p for p in r["points"]} for r in d["runs"]}
        series = self.path("ride_20.csv")
        s = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          road, "--speed-kmh", "20", "--cache-dir", self.cache, "--out", series)
        comfort = {c["point"]: c for c in [s["comfort"]] + s["comfort_at_points"]}
        sim_header, sim_rows = read_csv(series)
        sos = butter(4, 30.0, fs=1.0 / s["time_step_s"], output="sos")
        for point, column in (("hull", "hull_vertical_accel_m_s2"),
                              ("crew_seat", "crew_seat_accel_z_m_s2"),
                              ("sensor_mount", "sensor_mount_accel_z_m_s2")):
            r = by_speed[20][point]
            for ride_key, sim_key in (("absorbed_power_w", "absorbed_power_w"),
                                      ("weighted_rms_z_m_s2", "weighted_rms_z_m_s2"),
                                      ("weighted_rms_z_m_s2", "weighted_rms_m_s2"),
                                      ("vdv_z_m_s1_75", "vdv_z_m_s1_75"),
                                      ("vdv_z_m_s1_75", "vdv_m_s1_75"),
                                      ("vibration_total_value_m_s2", "vibration_total_value_m_s2"),
                                      ("weighted_rms_x_m_s2", "weighted_rms_x_m_s2"),
                                      ("weighted_rms_y_m_s2", "weighted_rms_y_m_s2"),
                                      ("seat_surface_total_value_m_s2", "seat_surface_total_value_m_s2")):
                self.assertAlmostEqual(r[ride_key] / comfort[point][sim_key], 1.0, places=9,
                                       msg=f"{point} {ride_key}")
            filtered = sosfilt(sos, sim_rows[:, sim_header.index(column)]) / GRAVITY
            self.assertAlmostEqual(r["peak_up_g"] / filtered.max(), 1.0, places=6, msg=point)
            self.assertAlmostEqual(r["peak_abs_g"] / np.abs(filtered).max(), 1.0, places=6,
                                   msg=point)

        outcomes = set()
        limits = {l["point"]: l for l in d["limits"]}
        for point in d["points"]:
            for name, key, limit in (("absorbed_power", "absorbed_power_w", power_limit),
                                     ("peak_acceleration", "peak_up_g", peak_limit)):
                l = limits[point][name]
                outcomes.add(l["status"])
                sweep_values = [by_speed[v][point][key] for v in d["speeds_kmh"]]
                # No crossing, no speed: the bracket holds the speed run.
                if l["status"] == "at_lowest_speed":
                    self.assertGreaterEqual(sweep_values[0], limit)
                    self.assertIsNone(l["speed_kmh"])
                    self.assertEqual(l["bracket_kmh"], [10, 10])
                    continue
                if l["status"] == "not_reached":
                    self.assertLess(max(sweep_values), limit)
                    self.assertIsNone(l["speed_kmh"])
                    self.assertEqual(l["bracket_kmh"], [40, 40])
                    continue
                self.assertEqual(l["status"], "reached")
                lo, hi = l["bracket_kmh"]
                self.assertLessEqual(hi - lo, tolerance + 1e-12)
                self.assertTrue(lo <= l["speed_kmh"] <= hi)
                self.assertLess(by_speed[lo][point][key], limit)
                self.assertGreaterEqual(by_speed[hi][point][key], limit)
                # The lowest crossing: every run below the bracket (the sweep's and every
                # bisection's, of any point and limit) is under the limit.
                self.assertTrue(all(by_speed[v][point][key] < limit for v in by_speed if v <= lo))
                if name == "absorbed_power":
                    at = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                                       "--track", road, "--speed-kmh", repr(l["speed_kmh"]),
                                       "--cache-dir", self.cache)
                    got = {c["point"]: c for c in [at["comfort"]] + at["comfort_at_points"]}
                    self.assertAlmostEqual(got[point]["absorbed_power_w"] / limit, 1.0, delta=0.01,
                                           msg=point)
        self.assertEqual(outcomes, {"reached", "at_lowest_speed", "not_reached"})

    def test_ride_limit_is_the_lowest_over_every_run(self):
        """A bisection of one point adds runs the other points see: over the 15 cm half-round
        obstacle (un-tracked) the crew seat's bisection ran 7.5 km/h, where the hull already
        exceeds 2.5 g, below the hull's first sweep bracket (10..15 km/h); the hull's limit must
        come from that run, not from the sweep alone."""
        d = self.tvd_json("ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          "half_round:0.15", "--points", "crew_seat,hull", "--cache-dir",
                          self.cache)
        runs = {r["speed_kmh"]: {p["point"]: p for p in r["points"]} for r in d["runs"]}
        for l in d["limits"]:
            c = l["peak_acceleration"]
            self.assertEqual(c["status"], "reached", l["point"])
            lo, hi = c["bracket_kmh"]
            self.assertLessEqual(hi - lo, d["tolerance_kmh"] + 1e-12)
            below = [v for v in runs if v <= lo]
            self.assertTrue(all(runs[v][l["point"]]["peak_up_g"] < 2.5 for v in below),
                            (l["point"], c, [(v, runs[v][l["point"]]["peak_up_g"]) for v in below]))
            self.assertGreaterEqual(runs[hi][l["point"]]["peak_up_g"], 2.5)

    def test_ride_unfiltered_peaks(self):
        """ride --lowpass-hz 0: the peaks are the unfiltered acceleration's, simulate's peak
        |a| of the same run; no filter order is reported; no bisection, no footnote for it."""
        ride = ("ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track", "half_round:0.1",
                "--speeds", "10", "--points", "hull", "--lowpass-hz", "0", "--cache-dir",
                self.cache)
        d = self.tvd_json(*ride)
        self.assertEqual(d["peak_lowpass_hz"], 0.0)
        self.assertEqual(d["peak_lowpass_order"], 0)
        s = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                          "half_round:0.1", "--speed-kmh", "10", "--cache-dir", self.cache,
                          "--out", self.path("unfiltered.csv"))
        hull = d["runs"][0]["points"][0]
        self.assertAlmostEqual(hull["peak_abs_g"] * 9.80665 / s["peak_hull_vertical_accel_m_s2"],
                               1.0, delta=1e-8)
        text = self.tvd(*ride).stdout
        self.assertIn("unfiltered", text)
        self.assertNotIn("bisection added", text)

    def test_ride_bad_options_are_named_before_any_work(self):
        ride = ["ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track", self.ride_road(),
                "--cache-dir", self.cache]
        for speeds, words in (("40:10:10", ["LAST must not be below FIRST"]),
                              ("10,x", ["'x' is not a number"]),
                              ("0,10", ["speed 0 km/h is outside (0, 200]"]),
                              ("10,10", ["strictly increasing"]),
                              ("10:20", ["three fields"]),
                              ("1:200:0.5", ["more than 200 speeds"]),
                              ("", ["no speeds"])):
            self.assert_input_error(ride + ["--speeds", speeds], "--speeds", *words)
        self.assert_input_error(ride + ["--points", "moon"], "--points", "unknown point 'moon'",
                                "(the vehicle has: hull, crew_seat, sensor_mount)")
        self.assert_input_error(ride + ["--points", "hull,hull"], "'hull' is listed twice")
        # Repeated, as frf's: every one is read (the second one judged too).
        self.assert_input_error(ride + ["--points", "hull", "--points", "hull"],
                                "'hull' is listed twice")
        self.assert_input_error(ride + ["--points", "hull", "--points", "moon"],
                                "unknown point 'moon'")
        self.assert_input_error(ride + ["--points", "hull,"], "an empty name")
        self.assert_input_error(ride + ["--dt", "0.005"], "--dt", "[0.0001, 0.002] s")
        self.assert_input_error(ride + ["--dt", "0.002", "--lowpass-hz", "300"], "--lowpass-hz 300",
                                "Nyquist frequency 1/(2 dt) = 250 Hz")
        # 1e-308 Hz once failed as "weighting filter section 0: numerator is zero".
        for value in ("1e-308", "0.099"):
            self.assert_input_error(ride + ["--lowpass-hz", value], "ride: --lowpass-hz " + value +
                                    " must be 0 (unfiltered) or at least 0.1 Hz")
        self.assert_input_error(ride + ["--tolerance-kmh", "0"], "--tolerance-kmh")
        self.assert_input_error(ride + ["--power-limit-w", "-1"], "--power-limit-w", "positive")
        self.assert_input_error(ride + ["--peak-limit-g", "nan"], "--peak-limit-g", "positive")
        self.assert_input_error(ride + ["--out", self.path("r.json")], "must end in .csv or .mat")
        self.assert_input_error(["ride", "--vehicle", VEHICLE], "--track is required")
        self.assert_input_error(ride + ["--model", "full"], "--model")

    # --- tvd ride --iso8608: the spectral method ------------------------------------------
    # On a road of harmonics with fixed amplitudes (tvd terrain: a_k^2/2 = the PSD's integral over
    # bin k), a linear model's mean square over one period is sum_k |H(v n_k)|^2 a_k^2/2 whatever
    # the phases: on a uniform road one realisation is the spectral integral up to the bins, the
    # terrain's linear interpolation (power sinc^4(n dx), -0.3 % at 15 km/h for dx = 2 cm), the
    # start from rest and the ends (-3 to -4 % at 40 km/h on 300 m; on 600 m under 0.5 % with the
    # interpolation) and the digital filters. Independent sides add cross terms 2 Re(H_L H_R* e^{j(phi_L - phi_R)}) that scatter
    # by 5-7 % per realisation of 600 m (16 seeds, README); a road with one side flat has none,
    # and the left-only and right-only runs add up to the spectral independent-sides power as
    # the uniform road's matches the uniform PSD.
    SPECTRAL_SPEEDS = "15,40"
    SPECTRAL_POWER_TOLERANCE = 0.015  # measured: 0.57 % (P), 0.27 % (a_wz) on 600 m at 2 cm
    SPECTRAL_AWZ_TOLERANCE = 0.008

    def spectral_ride(self, *args, points="crew_seat,hull"):
        return self.tvd_json("ride", "--vehicle", VEHICLE, "--variant", "untracked",
                             "--points", points, "--cache-dir", self.cache, *args)

    def simulated_ride(self, road):
        """tvd ride's time-domain metrics on `road` at SPECTRAL_SPEEDS: {(speed, point): metrics}
        and {speed: run} (limits out of reach: the sweep only, no bisection)."""
        d = self.tvd_json("ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track", road,
                          "--speeds", self.SPECTRAL_SPEEDS, "--points", "crew_seat,hull",
                          "--power-limit-w", "1e9", "--peak-limit-g", "1e9",
                          "--cache-dir", self.cache)
        return ({(r["speed_kmh"], p["point"]): p for r in d["runs"] for p in r["points"]},
                {r["speed_kmh"]: r for r in d["runs"]})

    def test_ride_spectral_agrees_with_the_time_domain(self):
        """tvd ride --iso8608 C against tvd ride --track on a 600 m class-C road of tvd terrain
        (2 cm spacing, untapered): uniform, and independent sides as the sum of the road with
        only its left and only its right half (the rest flat)."""
        road = self.path("spectral_road_C.csv")
        self.tvd("terrain", "--iso8608", "C", "--length", "600", "--spacing", "0.02", "--taper",
                 "0", "--seed", "3", "--out", road)
        lateral, x, heights = read_terrain_csv(road)
        self.assertEqual(list(lateral), [-2.5, 2.5])  # one profile across the width
        h = heights[:, 0]
        sides = {}
        for side in ("left", "right"):
            path = sides[side] = self.path(f"spectral_road_{side}.csv")
            left, right = (h, 0 * h) if side == "left" else (0 * h, h)
            np.savetxt(path, np.column_stack([x, right, right, left, left]), delimiter=",",
                       header="x,-2.5,-0.05,0.05,2.5", comments="", fmt="%.17g")
        spectral, spectral_runs = {}, {}
        for name, extra in (("uniform", ()), ("sides", ("--independent-sides",))):
            d = self.spectral_ride("--iso8608", "C", "--speeds", self.SPECTRAL_SPEEDS,
                                   "--power-limit-w", "1e9", *extra)
            spectral[name] = {(r["speed_kmh"], p["point"]): p for r in d["runs"]
                              for p in r["points"]}
            spectral_runs[name] = {r["speed_kmh"]: r for r in d["runs"]}
        uniform, uniform_runs = self.simulated_ride(road)
        left, left_runs = self.simulated_ride(sides["left"])
        right, right_runs = self.simulated_ride(sides["right"])
        # The hull's rotations (We), per run: pitch on the uniform road, roll too with the sides
        # apart (a mean square adds over the sides).
        for speed in (15, 40):
            s, i = spectral_runs["uniform"][speed], spectral_runs["sides"][speed]
            u, l, r = (runs[speed] for runs in (uniform_runs, left_runs, right_runs))
            for axis in ("roll", "pitch", "yaw", "rotational_total_value"):
                key = (f"weighted_rms_{axis}_rad_s2" if axis != "rotational_total_value"
                       else "rotational_total_value_m_s2")
                both = np.hypot(l[key], r[key])
                self.assertAlmostEqual(both / i[key], 1.0, delta=self.SPECTRAL_AWZ_TOLERANCE,
                                       msg=f"{speed} {key} sides")
                if axis == "pitch":
                    self.assertAlmostEqual(u[key] / s[key], 1.0,
                                           delta=self.SPECTRAL_AWZ_TOLERANCE, msg=f"{speed} {key}")
            self.assertGreater(i["weighted_rms_roll_rad_s2"], 0.5 * i["weighted_rms_pitch_rad_s2"])
            self.assertLess(s["weighted_rms_roll_rad_s2"], 1e-4 * s["weighted_rms_pitch_rad_s2"])
        for key, s in spectral["uniform"].items():
            i = spectral["sides"][key]
            self.assertAlmostEqual(uniform[key]["absorbed_power_w"] / s["absorbed_power_w"], 1.0,
                                   delta=self.SPECTRAL_POWER_TOLERANCE, msg=key)
            self.assertAlmostEqual(uniform[key]["weighted_rms_z_m_s2"] / s["weighted_rms_z_m_s2"],
                                   1.0, delta=self.SPECTRAL_AWZ_TOLERANCE, msg=key)
            power = left[key]["absorbed_power_w"] + right[key]["absorbed_power_w"]
            self.assertAlmostEqual(power / i["absorbed_power_w"], 1.0,
                                   delta=self.SPECTRAL_POWER_TOLERANCE, msg=key)
            awz = np.hypot(left[key]["weighted_rms_z_m_s2"], right[key]["weighted_rms_z_m_s2"])
            self.assertAlmostEqual(awz / i["weighted_rms_z_m_s2"], 1.0,
                                   delta=self.SPECTRAL_AWZ_TOLERANCE, msg=key)
            # The totals over the seat's axes (Wd of x and y, We of the hull's rotations): each
            # axis's mean square adds over the sides, so the totals do too.
            for total in ("vibration_total_value_m_s2", "seat_surface_total_value_m_s2"):
                self.assertAlmostEqual(uniform[key][total] / s[total], 1.0,
                                       delta=self.SPECTRAL_AWZ_TOLERANCE, msg=f"{key} {total}")
                both = np.hypot(left[key][total], right[key][total])
                self.assertAlmostEqual(both / i[total], 1.0, delta=self.SPECTRAL_AWZ_TOLERANCE,
                                       msg=f"{key} {total} sides")
                self.assertGreater(i[total], i["weighted_rms_z_m_s2"], key)
            # The sides differ: independent profiles are not the uniform road's.
            self.assertGreater(abs(i["absorbed_power_w"] / s["absorbed_power_w"] - 1.0), 0.05)

    def test_ride_spectral_sweep_limits_and_scale_law(self):
        """tvd ride --iso8608: the JSON's road and runs; the 6 W speed is where a spectral run at
        it absorbs 6 W; class D is 4x the power of class C and 2x its r.m.s. values, exactly; the
        CSV rows are the JSON's runs; 4000 points per decade change nothing that matters."""
        out = self.path("spectral.csv")
        psd_out = self.path("spectral_psd.csv")
        c = self.spectral_ride("--iso8608", "C", "--speeds", "5:40:5", "--out", out,
                               "--psd-out", psd_out)
        self.assertEqual(c["method"], "spectral")
        self.assertEqual(c["psd_out"], psd_out)
        # Both files or neither: a --psd-out that cannot be written leaves --out as it was.
        with open(out, "rb") as f:
            before = f.read()
        # (the run's table, 8 rows, fits under the file-size limit; its PSDs do not)
        blocked = self.path("spectral_psd_too_large.csv")
        r = self.run_limited(["ride", "--vehicle", VEHICLE, "--variant", "untracked", "--points",
                              "crew_seat,hull", "--cache-dir", self.cache, "--iso8608", "D",
                              "--speeds", "5:40:5", "--out", out, "--psd-out", blocked], 20000)
        self.assertEqual(r.returncode, INPUT_ERROR_STATUS, r.stderr)
        self.assertIn(blocked + ":", r.stderr)
        self.assertFalse(os.path.exists(blocked))
        with open(out, "rb") as f:
            self.assertEqual(f.read(), before)
        self.assertEqual([n for n in os.listdir(self.work) if "~" in n], [])  # no staged file
        self.assertEqual(c["road"]["iso8608_class"], "C")
        self.assertEqual(c["road"]["lateral_correlation"], "uniform")
        self.assertEqual(c["road"]["band_cycles_per_m"], [0.011, 2.83])
        band = 256e-6 * 0.1 ** 2 * (1 / 0.011 - 1 / 2.83)  # closed form, waviness 2
        self.assertAlmostEqual(c["road"]["band_rms_height_m"] / np.sqrt(band), 1.0, places=9)
        for key in ("peak_acceleration", "peak_up_g", "vdv_z_m_s1_75"):
            self.assertIn(key, c["not_computed"])
        self.assertNotIn("peak_limit_g", c)
        speeds = [r["speed_kmh"] for r in c["runs"]]
        self.assertEqual(speeds, sorted(speeds))
        self.assertEqual(c["evaluations"], len(speeds))
        for r in c["runs"]:
            v = r["speed_kmh"] / 3.6
            np.testing.assert_allclose(r["frequency_band_hz"], [0.011 * v, 2.83 * v], rtol=1e-9)
            self.assertEqual(r["frequencies"], int(np.ceil(400 * np.log10(2.83 / 0.011))) + 1)
            self.assertEqual([p["point"] for p in r["points"]], ["crew_seat", "hull"])
            self.assertNotIn("peak_up_g", r["points"][0])
        header, rows = read_csv(out)
        self.assertEqual(header[:5], ["speed_kmh", "in_sweep", "crew_seat_absorbed_power_w",
                                      "crew_seat_weighted_rms_z_m_s2", "crew_seat_rms_z_m_s2"])
        np.testing.assert_allclose(rows[:, 0], speeds, rtol=1e-9)
        np.testing.assert_allclose(rows[:, header.index("hull_absorbed_power_w")],
                                   [r["points"][1]["absorbed_power_w"] for r in c["runs"]],
                                   rtol=1e-8)
        # --psd-out: at each speed of --speeds, the grid the JSON describes, the road PSD
        # G_d(f/v)/v (closed form), and per point S_a, |W_k|^2 S_a, K S_a whose trapezoid is the
        # run's a_rms^2, a_wz^2, P (to the CSV's 12 digits against the JSON's 10); its raw x and
        # y PSDs, and the hull's roll, pitch and yaw PSDs, which weighted here by the analogue
        # Wd and We integrate to the JSON's a_wx^2, a_wy^2 and the rotations' a_w^2.
        psd_header, psd = read_csv(psd_out)
        self.assertEqual(psd_header[:6], ["speed_kmh", "frequency_hz", "road_psd_m2_hz",
                                          "crew_seat_psd_z_m2_s4_hz", "crew_seat_wk_psd_z_m2_s4_hz",
                                          "crew_seat_power_density_z_w_hz"])
        np.testing.assert_array_equal(np.unique(psd[:, 0]), np.arange(5.0, 40.5, 5.0))
        for speed in np.unique(psd[:, 0]):
            rows_v = psd[psd[:, 0] == speed]
            f = rows_v[:, 1]
            run = next(r for r in c["runs"] if r["speed_kmh"] == speed)
            self.assertEqual(len(f), run["frequencies"])
            np.testing.assert_allclose([f[0], f[-1]], run["frequency_band_hz"], rtol=1e-9)
            self.assertTrue(np.all(np.diff(f) > 0))
            v = speed / 3.6
            np.testing.assert_allclose(rows_v[:, 2], 256e-6 * (f / (0.1 * v)) ** -2 / v, rtol=1e-9)
            self.assertAlmostEqual(np.trapz(rows_v[:, 2], f) / band, 1.0, delta=1e-4)
            wd, we = iso2631_transition_weighting(f, 2.0), iso2631_transition_weighting(f, 1.0)
            for p in run["points"]:
                name = p["point"]
                for column, weight, value in (
                        ("_psd_z_m2_s4_hz", 1.0, p["rms_z_m_s2"] ** 2),
                        ("_wk_psd_z_m2_s4_hz", 1.0, p["weighted_rms_z_m_s2"] ** 2),
                        ("_power_density_z_w_hz", 1.0, p["absorbed_power_w"]),
                        ("_psd_x_m2_s4_hz", wd, p["weighted_rms_x_m_s2"] ** 2),
                        ("_psd_y_m2_s4_hz", wd, p["weighted_rms_y_m_s2"] ** 2)):
                    density = rows_v[:, psd_header.index(name + column)]
                    self.assertTrue(np.all(density >= 0))
                    self.assertAlmostEqual(np.trapz(weight * density, f) / value, 1.0,
                                           delta=1e-8, msg=(speed, name, column))
            for axis in ("roll", "pitch", "yaw"):
                density = rows_v[:, psd_header.index(f"hull_psd_{axis}_rad2_s4_hz")]
                self.assertAlmostEqual(np.trapz(we * density, f)
                                       / run[f"weighted_rms_{axis}_rad_s2"] ** 2, 1.0,
                                       delta=1e-8, msg=(speed, axis))
        limits = {l["point"]: l for l in c["limits"]}
        self.assertEqual(set(limits["crew_seat"]), {"point", "absorbed_power"})
        for point, l in limits.items():
            l = l["absorbed_power"]
            self.assertEqual(l["status"], "reached", point)
            lo, hi = l["bracket_kmh"]
            self.assertLessEqual(hi - lo, 0.1 + 1e-12)
            at = self.spectral_ride("--iso8608", "C", "--speeds", repr(l["speed_kmh"]),
                                    points=point)
            self.assertAlmostEqual(at["runs"][0]["points"][0]["absorbed_power_w"] / 6.0, 1.0,
                                   delta=0.01, msg=point)

        d = self.spectral_ride("--iso8608", "D", "--speeds", "5:40:5", "--power-limit-w", "24")
        by_speed = {r["speed_kmh"]: r for r in c["runs"]}
        for r in d["runs"]:
            for p, q in zip(r["points"], by_speed[r["speed_kmh"]]["points"]):
                # To the JSON's 10 digits (in the core, x4 is a power of two: bit for bit).
                self.assertAlmostEqual(p["absorbed_power_w"] / q["absorbed_power_w"], 4.0, places=8)
                for key in ("weighted_rms_z_m_s2", "rms_z_m_s2"):
                    self.assertAlmostEqual(p[key] / q[key], 2.0, places=8)
        # A limit 4x as high on a road 4x as rough: the same speed, to the bisection.
        for p, q in zip(d["limits"], c["limits"]):
            self.assertEqual(p["absorbed_power"]["bracket_kmh"], q["absorbed_power"]["bracket_kmh"])

        fine = self.spectral_ride("--iso8608", "C", "--speeds", "5:40:5", "--power-limit-w", "1e9",
                                  "--points-per-decade", "4000")
        for r in fine["runs"]:
            for p, q in zip(r["points"], by_speed[r["speed_kmh"]]["points"]):
                # 400 per decade: within 5e-4 of a 100x finer grid (README), 4000: 100x closer.
                self.assertAlmostEqual(q["absorbed_power_w"] / p["absorbed_power_w"], 1.0,
                                       delta=5e-4)

    def test_ride_spectral_warns_of_the_band_cut_and_of_sides_crossed(self):
        """The default band (ISO 8608's 0.011-2.83 cycles/m) stops exciting at 3.9 Hz at 5 km/h:
        the warning's figures are a --max-frequency 10 run's, and it names the fastest speed of
        the sweep where that adds over 10 %; a band the user sets is not questioned. An offset
        that carries a track across the centre line of independent sides is named."""
        speeds = "5,10,20,40"
        c = self.spectral_ride("--iso8608", "C", "--speeds", speeds)
        wide = self.spectral_ride("--iso8608", "C", "--speeds", speeds, "--max-frequency", "10")
        self.assertEqual(wide["warnings"], [])
        cut = [w for w in c["warnings"] if w.startswith("the road's band ends at 2.83 cycles/m")]
        self.assertEqual(len(cut), 1, c["warnings"])
        m = re.search(r"which at 5 km/h is ([0-9.]+) Hz: .* \(waves of 0.1 m\), (\w+) would "
                      r"absorb ([0-9.e+-]+) W at 5 km/h, not ([0-9.e+-]+) W; over 10 % more power "
                      r"at the sweep's speeds up to ([0-9.]+) km/h", cut[0])
        self.assertIsNotNone(m, cut[0])
        self.assertAlmostEqual(float(m.group(1)) / (2.83 * 5 / 3.6), 1.0, delta=2e-3)
        power = {(r["speed_kmh"], p["point"]): p["absorbed_power_w"]
                 for d, key in ((c, "cut"), (wide, "wide")) for r in d["runs"]
                 for p in [dict(q, point=(key, q["point"])) for q in r["points"]]}
        sweep = [float(v) for v in speeds.split(",")]
        over = {(v, pt) for v in sweep for pt in ("crew_seat", "hull")
                if power[(v, ("wide", pt))] > 1.1 * power[(v, ("cut", pt))]}
        self.assertEqual(float(m.group(5)), max(v for v, _ in over))
        worst = max((pt for v, pt in over if v == 5.0),
                    key=lambda pt: power[(5.0, ("wide", pt))] / power[(5.0, ("cut", pt))])
        self.assertEqual(m.group(2), worst)
        # Three significant digits of the two runs' figures.
        self.assertAlmostEqual(float(m.group(3)) / power[(5.0, ("wide", worst))], 1.0, delta=5e-3)
        self.assertAlmostEqual(float(m.group(4)) / power[(5.0, ("cut", worst))], 1.0, delta=5e-3)
        # Fast enough that the shorter waves add little: nothing to say.
        fast = self.spectral_ride("--iso8608", "C", "--speeds", "40,50")
        self.assertEqual(fast["warnings"], [])
        # The chosen band, even ISO's own, is the user's.
        self.assertEqual(self.spectral_ride("--iso8608", "C", "--speeds", speeds,
                                            "--max-frequency", "2.83")["warnings"], [])

        crossed = self.spectral_ride("--iso8608", "C", "--independent-sides", "--speeds", "40,50",
                                     "--lateral-offset", "100")
        self.assertEqual([w for w in crossed["warnings"] if "centre line" in w],
                         ["--lateral-offset 100 m carries 42 of 84 road inputs across the road's "
                          "centre line, where --independent-sides joins its left and right "
                          "profiles: they ride the other side's profile"])
        for args in (("--lateral-offset", "0.5"), ()):
            self.assertEqual(self.spectral_ride("--iso8608", "C", "--independent-sides", "--speeds",
                                                "40,50", *args)["warnings"], [])

    def test_ride_spectral_resolves_lightly_damped_modes(self):
        """A resonance whose half-power band is narrower than two steps of the log grid (zeta
        below ln(10) / points per decade) gets frequencies of its own: at 0.2 % modal damping
        the default 400 points per decade give every point's power, a_wz and seat-surface total
        at 10 and 11 km/h within 0.5 % of a 20,000 per decade grid (0.03 % seen; the log grid
        alone erred by +18 % and -19 %). Undamped
        modes in the band have no finite integral: refused before the sweep, naming them."""
        light = self.vehicle_with("light.yaml", "modal_ratio: {value: 0.05,",
                                  "modal_ratio: {value: 0.002,")
        def ride(vehicle, *extra):
            return self.tvd_json("ride", "--vehicle", vehicle, "--variant", "untracked",
                                 "--iso8608", "C", "--speeds", "10,11", "--cache-dir", self.cache,
                                 *extra)
        default, finest = ride(light), ride(light, "--points-per-decade", "20000")
        for i in range(2):
            for k, point in enumerate(default["runs"][i]["points"]):
                exact = finest["runs"][i]["points"][k]
                for key in ("absorbed_power_w", "weighted_rms_z_m_s2",
                            "seat_surface_total_value_m_s2"):
                    self.assertAlmostEqual(point[key] / exact[key], 1.0, delta=5e-3,
                                           msg=(i, point["point"], key))
        # More frequencies than the log grid's 965 at 10 km/h: some 125 around each of the modes
        # below 7.9 Hz.
        self.assertGreater(default["runs"][0]["frequencies"], 965 + 500)
        self.assertEqual(ride(VEHICLE)["runs"][0]["frequencies"],
                         int(np.ceil(400 * np.log10(2.83 / 0.011))) + 1)
        undamped = self.vehicle_with("undamped.yaml", "modal_ratio: {value: 0.05,",
                                     "modal_ratio: {value: 0,")
        self.assert_input_error(["ride", "--vehicle", undamped, "--variant", "untracked",
                                 "--iso8608", "C", "--speeds", "10,30", "--cache-dir", self.cache],
                                "mode(s) without damping lie in the band", "2.14 Hz (0)",
                                "no finite integral", "give the vehicle damping")
        # Repeated modes are listed once and counted: the 14 road wheels hop at one frequency.
        self.assert_input_error(["ride", "--vehicle", undamped, "--variant", "untracked",
                                 "--iso8608", "C", "--speeds", "40", "--min-frequency", "0.9",
                                 "--cache-dir", self.cache],
                                "14 mode(s) without damping", ": 18.6 Hz (0) x14. Across")
        # At 1 and 2 km/h the band holds none, the band-top check's wider band does: not
        # estimated, said so.
        low = self.tvd_json("ride", "--vehicle", undamped, "--variant", "untracked", "--iso8608",
                            "C", "--speeds", "1,2", "--cache-dir", self.cache)
        self.assertTrue(any("would add is not estimated: a mode without damping (2.14 Hz)" in w
                            for w in low["warnings"]), low["warnings"])

    def test_ride_spectral_takes_every_iso_class_a_to_h(self):
        """ISO 8608's eight classes, A to H, either case: each is G_d(n0) = 16e-6 * 4^i m^3
        (i = 0 for A), so on the same band its absorbed power is 4^i / 4^2 times class C's and
        its r.m.s. values 2^i / 2^2 times, exactly (the scale law, at the JSON's 10 digits)."""
        c = self.spectral_ride("--iso8608", "C", "--speeds", "20", "--power-limit-w", "1e9")
        for given, index in (("A", 0), ("h", 7), ("H", 7)):
            d = self.spectral_ride("--iso8608", given, "--speeds", "20", "--power-limit-w", "1e9")
            self.assertEqual(d["road"]["iso8608_class"], given.upper())
            self.assertAlmostEqual(d["road"]["psd_at_n0_m3"] / (16e-6 * 4 ** index), 1.0, places=9)
            for p, q in zip(d["runs"][0]["points"], c["runs"][0]["points"]):
                self.assertAlmostEqual(p["absorbed_power_w"] / q["absorbed_power_w"]
                                       / 4.0 ** (index - 2), 1.0, places=8)
                self.assertAlmostEqual(p["weighted_rms_z_m_s2"] / q["weighted_rms_z_m_s2"]
                                       / 2.0 ** (index - 2), 1.0, places=8)
        self.assert_input_error(["ride", "--vehicle", VEHICLE, "--variant", "untracked",
                                 "--cache-dir", self.cache, "--iso8608", "I"],
                                "--iso8608 must be one road class A..H, got 'I'")

    def test_ride_spectral_bad_options_are_named_before_any_work(self):
        cache = self.path("cache_spectral_refused")
        ride = ["ride", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", cache]
        for args, words in (
                (["--iso8608", "C", "--track", "long_hill"], ["--track and --iso8608 exclude each other"]),
                (["--iso8608", "Q"], ["--iso8608 must be one road class A..H, got 'Q'"]),
                (["--iso8608", "CD"], ["got 'CD'"]),
                (["--iso8608", ""], ["got ''"]),
                (["--iso8608", "C", "--dt", "0.001"], ["--dt applies to a --track simulation"]),
                (["--iso8608", "C", "--peak-limit-g", "2"], ["--peak-limit-g applies to a --track"]),
                (["--iso8608", "C", "--lowpass-hz", "10"], ["--lowpass-hz applies to a --track"]),
                (["--track", "long_hill", "--waviness", "3"],
                 ["--waviness applies to --iso8608 (the spectral method) only"]),
                (["--track", "long_hill", "--independent-sides"], ["--independent-sides applies to --iso8608"]),
                (["--track", "long_hill", "--points-per-decade", "100"], ["--points-per-decade applies"]),
                (["--track", "long_hill", "--psd-out", self.path("psd.csv")], ["--psd-out applies to --iso8608"]),
                (["--iso8608", "C", "--psd-out", self.path("psd.txt")], ["--psd-out", ".csv", ".mat"]),
                (["--iso8608", "C", "--psd-out", self.path("same.csv"), "--out",
                  self.path("same.csv")], ["--psd-out and --out name the same file"]),
                (["--iso8608", "C", "--min-frequency", "3"],
                 ["--min-frequency 3 must be below --max-frequency 2.83 cycles/m"]),
                (["--iso8608", "C", "--points-per-decade", "5"], ["--points-per-decade", "[10, 100000]"]),
                (["--iso8608", "C", "--waviness", "0"], ["--waviness", "[0.5, 5], got 0"]),
                (["--iso8608", "C", "--waviness", "1e300"], ["--waviness", "[0.5, 5], got 1e300"]),
                (["--iso8608", "C", "--min-frequency", "1e-300"],
                 ["--min-frequency", "[0.001, 100] cycles/m, got 1e-300"]),
                (["--iso8608", "C", "--max-frequency", "1e10"],
                 ["--max-frequency", "[0.001, 100] cycles/m, got 1e10"]),
                (["--iso8608", "C", "--points", "moon"], ["unknown point 'moon'"]),
                (["--iso8608", "C", "--speeds", "0,10"], ["speed 0 km/h is outside (0, 200]"]),
                ([], ["--track is required", "or --iso8608 CLASS for the spectral method"])):
            self.assert_input_error(ride + args, *words)
        self.assertFalse(os.path.exists(cache))  # refused before any reduction

    def test_mat_outputs_hold_the_csv_columns(self):
        """--out FILE.mat (simulate, frf): one n x 1 variable per CSV column, the same values
        (to the CSV's digits), and the run's vehicle/variant/model as strings."""
        # The run's settings as variables beside the columns (non-default ones where they have
        # a default: a setting that is not passed through would read as the default).
        settings = {
            "simulate": {"track": "separated_waves", "track_argument": "separated_waves",
                         "model": "reduced", "method": "modal", "dt_s": 0.002,
                         "max_mode_hz": 250.0, "lateral_offset_m": 0.5, "speed_kmh": 20.0},
            "frf": {"model": "reduced", "excitation": "travelled", "speed_kmh": 30.0},
        }
        for command, extra, digits in (("simulate", ("--track", "separated_waves", "--speed-kmh", "20",
                                                     "--dt", "0.002", "--lateral-offset", "0.5"), 9),
                                       ("frf", ("--speed-kmh", "30"), 10)):
            args = (command, "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                    self.cache, *extra)
            csv_file, mat_file = self.path(command + ".csv"), self.path(command + ".mat")
            summary = self.tvd_json(*args, "--out", csv_file)
            self.tvd(*args, "--out", mat_file)
            # The JSON summary names the same settings (review 137: the track's file, the
            # offset and the modal cut-off were in the .mat only).
            for name in ("track_argument", "lateral_offset_m", "max_mode_hz"):
                if name in settings[command]:
                    self.assertEqual(summary[name], settings[command][name], name)
            header, rows = read_csv(csv_file)
            m = scipy.io.loadmat(mat_file)
            self.assertEqual(str(m["variant"][0]), "untracked")
            self.assertEqual(str(m["vehicle"][0]), self.vehicle_name)  # as the JSON's
            self.assertEqual(str(m["vehicle_file"][0]), VEHICLE)
            for name, value in settings[command].items():
                if isinstance(value, str):
                    self.assertEqual(str(m[name][0]), value, name)
                else:
                    self.assertEqual(m[name].shape, (1, 1), name)
                    self.assertEqual(float(m[name][0, 0]), value, name)
            for i, name in enumerate(header):
                self.assertEqual(m[name].shape, (len(rows), 1), name)
                np.testing.assert_allclose(m[name][:, 0], rows[:, i], rtol=10.0 ** (1 - digits),
                                           atol=1e-300, err_msg=f"{command} {name}")

    def test_mac_correlation_between_eigenspaces(self):
        """tvd mac: the correlation table compares eigenspaces (one row per repeated frequency,
        the un-tracked wheels bouncing alone); the eigenspace MAC is at least the plain MAC of
        eq. (11) everywhere and equal to it between single modes; each row's partner is its
        row's maximum."""
        d = self.tvd_json("mac", "--vehicle", VEHICLE, "--count", "40")
        plain, space = np.array(d["mac"]), np.array(d["eigenspace_mac"])
        self.assertEqual(plain.shape, (40, 40))
        self.assertTrue(np.all(space >= plain - 1e-12))
        f_uv, f_tv = np.array(d["untracked_frequencies_hz"]), np.array(d["tracked_frequencies_hz"])

        def single(f, i):
            return all(abs(f[j] - f[i]) > 1e-6 * f[i] for j in (i - 1, i + 1) if 0 <= j < len(f))

        for i in range(40):
            for j in range(40):
                if single(f_uv, i) and single(f_tv, j):
                    self.assertAlmostEqual(space[i, j], plain[i, j], places=9)
        rows = d["correlation"]
        wheels = [r for r in rows if r["multiplicity"] > 1]
        self.assertEqual(len(wheels), 1)  # the 11 wheels bouncing alone at one frequency
        self.assertEqual(wheels[0]["multiplicity"], 11)
        first = wheels[0]["untracked_mode"] - 1
        np.testing.assert_array_equal(space[first:first + 11], np.tile(space[first], (11, 1)))
        # Partners are global modes (1 % or more of their kinetic energy in the hull and running
        # gear), as the reduction pairs them: the un-tracked hull and wheel modes; the tracked
        # chain mode at 1.88 Hz (0.01 %, MAC 0.61 with the un-tracked pitch) is none.
        tv_global = np.array(d["tracked_global"])
        self.assertEqual(list(d["untracked_global"][:20]), [True] * 20)
        self.assertFalse(any(d["untracked_global"][20:]))
        self.assertFalse(tv_global[2])
        for r in rows:
            i, j = r["untracked_mode"] - 1, r["tracked_mode"] - 1
            self.assertTrue(tv_global[j], r)
            best = space[i][tv_global].max()
            self.assertAlmostEqual(r["mac"], best, places=9)
            self.assertAlmostEqual(space[i, j], best, places=12)
            for m in r["other_matches"]:
                self.assertTrue(tv_global[m["tracked_mode"] - 1], m)
            # "best tracked match, then (other matches ...)": the best is not among the others.
            self.assertNotIn(r["tracked_mode"], [m["tracked_mode"] for m in r["other_matches"]])
            # matched: the best MAC reaches the threshold (0.7), else it is shown, not a match.
            self.assertEqual(r["matched"], r["mac"] >= d["threshold"], r)
        pitch = next(r for r in rows if r["type"] == "pitch")
        self.assertFalse(pitch["matched"])
        self.assertLess(space[pitch["untracked_mode"] - 1].max(), 0.7)
        self.assertNotEqual(pitch["tracked_mode"], 3)
        # The roll mode pairs with the tracked roll (Table 4: 6.73 -> 13.7 Hz).
        roll = next(r for r in rows if r["type"] == "roll")
        self.assertEqual(roll["tracked_type"], "roll")
        self.assertGreater(roll["mac"], 0.9)
        # A MAC equal to the threshold matches ("reaches the threshold"): the roll row's MAC, at
        # full precision from mac.mat, given as the threshold.
        self.tvd("mac", "--vehicle", VEHICLE, "--count", "40", "--out", self.path("mac_full"))
        mac_file = scipy.io.loadmat(os.path.join(self.path("mac_full"), "mac.mat"))
        exact = mac_file["eigenspace_mac"]
        # The MAC recomputed from the shapes on the common DOFs mac.mat holds (eq. 11), shapes
        # that do not move there (below 1e-8 of their set's largest norm) giving 0.
        a, b = mac_file["untracked_common_shapes"], mac_file["tracked_common_shapes"]
        self.assertEqual(a.shape, (d["common_dofs"], 40))
        self.assertEqual(mac_file["common_dof_node"].shape, (d["common_dofs"], 1))
        self.assertTrue(set(mac_file["common_dof_direction"].ravel()) <= {0.0, 1.0, 2.0})
        na, nb = np.linalg.norm(a, axis=0), np.linalg.norm(b, axis=0)
        with np.errstate(divide="ignore", invalid="ignore"):
            recomputed = (a.T @ b) ** 2 / np.outer(na**2, nb**2)
        recomputed[na <= 1e-8 * na.max(), :] = 0.0
        recomputed[:, nb <= 1e-8 * nb.max()] = 0.0
        np.testing.assert_allclose(recomputed, mac_file["mac"], atol=1e-10)
        edge = repr(float(exact[roll["untracked_mode"] - 1, roll["tracked_mode"] - 1]))
        at_edge = self.tvd_json("mac", "--vehicle", VEHICLE, "--count", "40", "--mac-threshold",
                                edge)
        edge_roll = next(r for r in at_edge["correlation"] if r["type"] == "roll")
        self.assertTrue(edge_roll["matched"], (edge, edge_roll))
        # The text gives a repeated frequency's modes as one row "a-b", b - a + 1 of them.
        text = self.tvd("mac", "--vehicle", VEHICLE, "--count", "40").stdout
        a = wheels[0]["untracked_mode"]
        self.assertRegex(text, rf"\n\s*{a}-{a + 10}\s+[0-9.]+\s+wheel bounce x11\s")
        # reduce's name of the threshold is taken too, and moves the matches with it.
        strict = self.tvd_json("mac", "--vehicle", VEHICLE, "--count", "40", "--mac-threshold",
                               "0.95")
        self.assertEqual(strict["threshold"], 0.95)
        for r in strict["correlation"]:
            self.assertEqual(r["matched"], r["mac"] >= 0.95, r)
        self.assertLess(sum(r["matched"] for r in strict["correlation"]),
                        sum(r["matched"] for r in rows))

    def test_frf_csv_columns_and_grid(self):
        out = self.path("frf.csv")
        d = self.tvd_json("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                          self.cache, "--speed-kmh", "30", "--out", out)
        header, rows = read_csv(out)
        expected = ["frequency_hz"]
        for name in ("hull_vertical_acc", "hull_pitch_acc", "front_wheel_acc", "rear_wheel_acc"):
            expected += [name + "_mag", name + "_phase_deg"]
        self.assertEqual(header, expected)
        np.testing.assert_allclose(rows[:, 0], np.arange(len(rows)) * 0.05, atol=1e-9)
        self.assertAlmostEqual(rows[-1, 0], 50.0, places=9)
        self.assertEqual(len(d["outputs"]), 4)
        self.assertTrue(np.all(rows[:, 1::2] >= 0.0))  # magnitudes
        self.assertTrue(np.all(np.abs(rows[:, 2::2]) <= 180.0 + 1e-9))  # phases [deg]
        # The hull's vertical-acceleration peak in the JSON is the CSV's.
        self.assertAlmostEqual(rows[:, 1].max() / d["outputs"][0]["peak_magnitude"], 1.0, places=6)
        # A peak at the last frequency is flagged as the band's edge, not taken for a resonance.
        for k, o in enumerate(d["outputs"]):
            at_edge = int(np.argmax(rows[:, 1 + 2 * k])) == len(rows) - 1
            self.assertEqual(o["peak_at_band_edge"], at_edge, o["column"])
        low = self.tvd_json("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                            self.cache, "--max-hz", "3")
        self.assertTrue(low["outputs"][0]["peak_at_band_edge"])  # still rising towards 5 Hz bounce

    # --- frf --points: the description's named points ---------------------------------------
    # ISO 2631-1:1997 one-third-octave table (comfort.h): |Wk| at 1 and 6.3 Hz, to its 3 digits.
    WK_TABLE = {1.0: 0.482, 6.3: 1.054}
    WK_TABLE_TOLERANCE = 1e-3
    # The CSV's 10 significant digits of magnitude and phase rebuild a complex FRF to about 1e-9
    # of its largest value; a point misplaced by 1 mm along x would err by 1e-3 |H_pitch|.
    RIGID_POINT_TOLERANCE = 1e-7
    # The reduced model is not exactly left-right symmetric (MoGeSeC's masters are not mirrored:
    # their y sum to -1.4 m), so under the same road on both sides the hull rolls a little
    # (un-tracked: 0.09 (rad/s^2)/m against a pitch of 2100) and a point off the centre line
    # (the crew seat, y = 0.55 m) moves by theta_x y_p more: 5.3e-6 of its peak synchronous,
    # 1.3e-5 at 30 km/h. A point misplaced by 1 mm along x would still err by 2e-4, the opposite
    # pitch sign by 0.1 and more.
    REDUCED_OFF_CENTRE_TOLERANCE = 3e-5
    # test_vehicle_frf's reduced-vs-full criterion: 1 dB up to 30 Hz, away from anti-resonances
    # (the full FRF 12 dB below its largest value within +-1 Hz), over at least 45 % of the band.
    FRF_TOLERANCE_DB, ANTI_RESONANCE_RATIO, ANTI_RESONANCE_WINDOW_HZ = 1.0, 0.25, 1.0
    BAND_HZ = 30.0

    def worst_db(self, hz, full, reduced):
        """paper_tables.worst_db with test_vehicle_frf's criterion: (worst dB, share compared)."""
        if os.path.join(ROOT, "scripts") not in sys.path:
            sys.path.insert(0, os.path.join(ROOT, "scripts"))
        import paper_tables  # noqa: E402
        return paper_tables.worst_db(hz, full, reduced, self.BAND_HZ, self.ANTI_RESONANCE_RATIO,
                                     self.ANTI_RESONANCE_WINDOW_HZ)

    def frf_columns(self, name, *args):
        """`tvd frf --variant untracked --max-hz 30 ARGS --out NAME --json`: the JSON, the CSV's
        columns by name and its text."""
        out = self.path(name)
        d = self.tvd_json("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--max-hz",
                          str(self.BAND_HZ), *args, "--out", out)
        header, rows = read_csv(out)
        with open(out) as f:
            text = f.read()
        return d, {n: rows[:, i] for i, n in enumerate(header)}, text

    @staticmethod
    def complex_frf(columns, name):
        return columns[name + "_mag"] * np.exp(1j * np.radians(columns[name + "_phase_deg"]))

    def assert_rigid_with_the_hull(self, columns, point, what, tolerance):
        """The point's vertical acceleration is the hull's rigid motion there (the point is a
        slave of the hull's node, at its CoG):  H_p = H_z - (x_p - x_G) H_pitch, from small-angle
        kinematics u = u_G + theta x (p - G) with REP-103 axes (x forward, z up; a positive pitch
        about +y lowers the nose): u_z(p) = u_zG + theta_x (y_p - y_G) - theta_y (x_p - x_G).
        Both tracks read the same road, so the symmetric vehicle does not roll and y_p drops out
        (up to `tolerance`, relative to the point's peak)."""
        with open(VEHICLE) as f:
            d = yaml.safe_load(f)
        arm = d["named_points"][point]["value"][0] - d["hull"]["cog_x"]["value"]
        h_z = self.complex_frf(columns, "hull_vertical_acc")
        h_pitch = self.complex_frf(columns, "hull_pitch_acc")
        h_p = self.complex_frf(columns, point + "_vertical_acc")
        scale = np.abs(h_p).max()
        error = np.abs(h_p - (h_z - arm * h_pitch)).max() / scale
        self.assertLess(error, tolerance, f"{point}, {what}")
        # Not true of any point: the pitch term is 2 % of the response or more (sensor mount,
        # 0.18 m ahead of the CoG: 5 %; crew seat: 50 %), and the opposite sign (nose up) is off.
        self.assertGreater(np.abs(arm * h_pitch).max() / scale, 0.02, f"{point}, {what}")
        self.assertGreater(np.abs(h_p - (h_z + arm * h_pitch)).max() / scale, 0.04,
                           f"{point}, {what}")

    def test_frf_points_are_rigid_with_the_hull_and_wk_weighted(self):
        points = ["crew_seat", "sensor_mount"]
        for speed in ("0", "30"):
            plain, plain_columns, plain_text = self.frf_columns(
                f"frf_plain_{speed}.csv", "--cache-dir", self.cache, "--speed-kmh", speed)
            # Comma-separated or repeated: the same list.
            listed = (["--points", ",".join(points)] if speed == "0" else
                      ["--points", points[0], "--points", points[1]])
            d, c, text = self.frf_columns(f"frf_points_{speed}.csv", "--cache-dir", self.cache,
                                          "--speed-kmh", speed, *listed)
            extra = [p + "_vertical_acc" + s for p in points for s in ("_mag", "_phase_deg",
                                                                       "_wk_mag")]
            self.assertEqual(list(c), list(plain_columns) + extra)
            # The points add columns and outputs and change nothing else, to the byte.
            plain_lines, lines = plain_text.splitlines(), text.splitlines()
            self.assertEqual(len(lines), len(plain_lines))
            for a, b in zip(plain_lines, lines):
                self.assertTrue(b.startswith(a + ","), (a, b))
            self.assertEqual(d["outputs"][:4], plain["outputs"])
            # The rest alike too, but for where the model came from (the first run of a fresh
            # cache reduces, the second reads the file).
            rest = [json.loads(json.dumps(j)) for j in (d, plain)]
            for j in rest:
                del j["outputs"], j["out"], j["model_description"], j["reduction"]["source"]
            self.assertEqual(rest[0], rest[1])
            # (a) Rigid with the hull.
            for point, tolerance in zip(points, (self.REDUCED_OFF_CENTRE_TOLERANCE,
                                                 self.RIGID_POINT_TOLERANCE)):
                self.assert_rigid_with_the_hull(c, point, f"{speed} km/h", tolerance)
            # (b) The weighting: |H| |Wk(f)|, the same factor at both points, the standard's
            # table at 1 and 6.3 Hz, 0 at 0 Hz (Wk's high-pass).
            f = c["frequency_hz"]
            ratio = {}
            for point in points:
                mag, wk = c[point + "_vertical_acc_mag"], c[point + "_vertical_acc_wk_mag"]
                self.assertEqual(wk[0], 0.0)
                self.assertTrue(np.all(mag[1:] > 0.0))
                ratio[point] = wk[1:] / mag[1:]
                for hz, table in self.WK_TABLE.items():
                    i = int(np.argmin(np.abs(f - hz)))
                    self.assertAlmostEqual(f[i], hz, places=9)
                    self.assertAlmostEqual(wk[i] / mag[i], table, delta=self.WK_TABLE_TOLERANCE,
                                           msg=f"{point}, |Wk({hz:g} Hz)|")
            np.testing.assert_allclose(ratio[points[0]], ratio[points[1]], rtol=1e-8)
            # The JSON: each point's peak and Wk-weighted peak are the CSV's.
            for o, point in zip(d["outputs"][4:], points):
                self.assertEqual((o["column"], o["output"], o["unit"]),
                                 (point + "_vertical_acc", point + " uz", "(m/s^2)/m"))
                for prefix, column in (("", "_mag"), ("wk_", "_wk_mag")):
                    values = c[point + "_vertical_acc" + column]
                    k = int(np.argmax(values))
                    self.assertAlmostEqual(o[prefix + "peak_magnitude"] / values[k], 1.0, places=8)
                    self.assertAlmostEqual(o[prefix + "peak_hz"], f[k], places=9)
                    self.assertEqual(o[prefix + "peak_at_band_edge"], k == len(f) - 1)
                # The resonances: every interior local maximum (rising into it, not falling out
                # of it) at or above 10 % of the peak, and every one of the displacement
                # |H| / omega^2 at or above 10 % of its largest, from the CSV's magnitudes.
                mag = c[point + "_vertical_acc_mag"]
                disp = np.zeros_like(mag)
                disp[f > 0] = mag[f > 0] / (2 * np.pi * f[f > 0]) ** 2

                def maximum(v, i, share=0.1):
                    return v[i] > v[i - 1] and v[i] >= v[i + 1] and v[i] >= share * v.max()

                def climb(i):  # to the acceleration's maximum just above (one resonance)
                    k = i
                    while k + 2 < len(mag) and mag[k + 1] > mag[k]:
                        k += 1
                    return k if f[k] <= 1.25 * f[i] and maximum(mag, k, 0.0) else i
                # The displacement's first value after 0 Hz (where it is 0 / 0) is its
                # quasi-static limit, no maximum: a travelled road's falls from there.
                expected = sorted({i for i in range(1, len(f) - 1) if maximum(mag, i)} |
                                  {climb(i) for i in range(1, len(f) - 1)
                                   if f[i - 1] > 0 and maximum(disp, i)})
                expected = [f[i] for i in expected]
                self.assertTrue(expected)
                np.testing.assert_allclose(o["resonances_hz"], expected, rtol=0, atol=1e-9)
            # No output lists the grid's first frequency (0.05 Hz) as a resonance: it once did
            # for every travelled heave FRF, whose quasi-static limit falls from there.
            for o in d["outputs"]:
                self.assertGreater(min(o["resonances_hz"]), f[1], (speed, o["column"]))
        # The text report names the points and their Wk-weighted peaks.
        text = self.tvd("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                        self.cache, "--max-hz", "5", "--points", "crew_seat").stdout
        self.assertIn("crew_seat_vertical_acc peak", text)
        self.assertIn("Wk-weighted peak", text)

    def test_frf_anti_phase_roads_roll_and_points_stay_rigid(self):
        """--sides anti_phase (left +h, right -h): the hull's lateral, roll and yaw columns and
        each point's lateral one are added; the un-tracked roll FRF peaks at the roll mode (the
        README's Table 4: 7.13 Hz); heave and pitch stay ~0 on the symmetric vehicle; each point
        moves with the rigid hull, the roll now included: H_z(P) = H_z + y_P H_roll - (x_P - x_G)
        H_pitch and H_y(P) = H_y + (x_P - x_G) H_yaw - (z_P - z_G) H_roll. The default is
        in_phase, unchanged to the byte."""
        points = ["crew_seat", "sensor_mount"]
        d, c, _ = self.frf_columns("frf_anti.csv", "--cache-dir", self.cache, "--sides",
                                   "anti_phase", "--points", ",".join(points))
        self.assertEqual(d["sides"], "anti_phase")
        self.assertEqual([o["column"] for o in d["outputs"]],
                         ["hull_vertical_acc", "hull_pitch_acc", "front_wheel_acc",
                          "rear_wheel_acc", "hull_lateral_acc", "hull_roll_acc", "hull_yaw_acc",
                          "crew_seat_vertical_acc", "crew_seat_lateral_acc",
                          "sensor_mount_vertical_acc", "sensor_mount_lateral_acc"])
        outputs = {o["column"]: o for o in d["outputs"]}
        self.assertAlmostEqual(outputs["hull_roll_acc"]["peak_hz"], 7.13, delta=0.1)
        # Left up, right down: positive roll (REP-103: about +x, lifting the left side), so at
        # 0.05 Hz the roll acceleration -omega^2 theta is in opposition to the road.
        self.assertAlmostEqual(abs(c["hull_roll_acc_phase_deg"][1]), 180.0, delta=1.0)
        self.assertEqual(outputs["hull_roll_acc"]["unit"], "(rad/s^2)/m")
        plain, plain_columns, plain_text = self.frf_columns("frf_in_phase.csv", "--cache-dir",
                                                            self.cache)
        self.assertEqual(plain["sides"], "in_phase")
        for name in ("hull_vertical_acc", "hull_pitch_acc"):
            self.assertLess(c[name + "_mag"].max(), 1e-3 * plain_columns[name + "_mag"].max(),
                            name)
        _, default_columns, default_text = self.frf_columns("frf_default.csv", "--cache-dir",
                                                            self.cache, "--sides", "in_phase")
        self.assertEqual(default_text, plain_text.replace("frf_in_phase", "frf_default"))
        with open(VEHICLE) as f:
            description = yaml.safe_load(f)
        cog = np.array([description["hull"]["cog_x"]["value"], 0.0,
                        description["hull"]["cog_height"]["value"]])
        h = {n: self.complex_frf(c, "hull_" + n + "_acc")
             for n in ("vertical", "pitch", "lateral", "roll", "yaw")}
        for point in points:
            r = np.array(description["named_points"][point]["value"]) - cog
            rigid_z = h["vertical"] + r[1] * h["roll"] - r[0] * h["pitch"]
            rigid_y = h["lateral"] + r[0] * h["yaw"] - r[2] * h["roll"]
            for column, rigid in (("_vertical_acc", rigid_z), ("_lateral_acc", rigid_y)):
                got = self.complex_frf(c, point + column)
                scale = np.abs(got).max()
                self.assertGreater(scale, 0.0, point + column)
                self.assertLess(np.abs(got - rigid).max() / scale,
                                self.REDUCED_OFF_CENTRE_TOLERANCE, point + column)
        # The crew seat (0.55 m left) now rolls: its vertical FRF is mostly the roll term.
        self.assertGreater(np.abs(0.55 * h["roll"]).max(),
                           0.5 * c["crew_seat_vertical_acc_mag"].max())
        bad = self.tvd("frf", "--vehicle", VEHICLE, "--sides", "opposite", status=2)
        self.assertIn("--sides", bad.stderr)

    def test_frf_points_of_the_full_model_match_the_reduced(self):
        _, reduced, _ = self.frf_columns("frf_points_reduced.csv", "--cache-dir", self.cache,
                                         "--points", "crew_seat")
        full_json, full, _ = self.frf_columns("frf_points_full.csv", "--model", "full",
                                              "--points", "crew_seat")
        self.assertEqual(full_json["model"], "full")  # as simulate's
        self.assertTrue(full_json["model_description"].startswith("full ("), full_json)
        np.testing.assert_array_equal(full["frequency_hz"], reduced["frequency_hz"])
        # The full model is symmetric: its crew seat is rigid with the hull to rounding.
        self.assert_rigid_with_the_hull(full, "crew_seat", "full model", self.RIGID_POINT_TOLERANCE)
        for column in ("crew_seat_vertical_acc_mag", "crew_seat_vertical_acc_wk_mag"):
            db, share = self.worst_db(full["frequency_hz"], full[column], reduced[column])
            self.assertLess(db, self.FRF_TOLERANCE_DB, column)
            self.assertGreater(share, 0.45, column)

    def test_frf_of_coupled_damping_is_the_direct_solution(self):
        """Arm dampers couple the modes: tvd frf then solves eq. 18 directly, and its FRF is that
        of the file's M_R, C_R, K_R (SciPy, dense solve); eq. 20's modal damping is off by a
        factor of two at the front wheel. The full model is solved exactly too, and the reduced
        model lies within 1 dB of it. simulate's modal method and the spectral ride keep the
        whole damping too, and none of them warns."""
        damped = self.vehicle_with("arm_damped.yaml", "arm_damping: {value: 0,",
                                   "arm_damping: {value: 20000,")
        with open(damped) as f:
            text = f.read()
        with open(damped, "w") as f:
            f.write(text.replace('damped_stations: {value: [],', 'damped_stations: {value: [1, 7],'))
        mat = self.path("arm_damped.mat")
        self.tvd("reduce", "--vehicle", damped, "--variant", "untracked", "--out", mat)
        out = self.path("arm_damped_frf.csv")
        d = self.tvd_json("frf", "--vehicle", damped, "--reduced", mat, "--out", out)
        self.assertEqual(d["solution"], "direct")
        self.assertGreater(d["damping_coupling"], 0.1)
        header, rows = read_csv(out)
        m = scipy.io.loadmat(mat)
        names = [str(np.ravel(n)[0]) for n in np.ravel(m["output_names"])]
        M, C, K, Ku, Cu, H = (m[k] for k in ("M_R", "C_R", "K_R", "K_u", "C_u", "H"))
        picks = [(header.index("hull_vertical_acc_mag"), names.index("hull uz")),
                 (header.index("front_wheel_acc_mag"), names.index("road_wheel_left_1 uz"))]
        for i in range(0, len(rows), 40):
            f = rows[i, 0]
            w = 2 * np.pi * f
            x = np.linalg.solve(K - w * w * M + 1j * w * C, (Ku + 1j * w * Cu).sum(axis=1))
            for col, row in picks:
                exact = abs(-w * w * (H[row] @ x))
                self.assertAlmostEqual(rows[i, col], exact, delta=1e-6 * rows[:, col].max() + 1e-9,
                                       msg=(f, header[col]))
        # What eq. 20 would give: modal damping ratios from the diagonal of Phi^T C Phi.
        lam, phi = scipy.linalg.eigh(K, M)
        c = np.diag(phi.T @ C @ phi)
        front = picks[1][0]
        peak = rows[:, front].argmax()
        w = 2 * np.pi * rows[peak, 0]
        eta = (phi.T @ (Ku + 1j * w * Cu).sum(axis=1)) / (lam - w * w + 1j * w * c)
        modal_front = abs(-w * w * (H[names.index("road_wheel_left_1 uz")] @ (phi @ eta)))
        self.assertGreater(abs(modal_front / rows[peak, front] - 1), 0.3)
        # The bundled vehicle's modal damping is diagonal: modal superposition, as the paper.
        self.assertEqual(self.tvd_json("frf", "--vehicle", VEHICLE, "--variant", "untracked",
                                       "--cache-dir", self.cache, "--max-hz", "5")["solution"],
                         "modal")
        # The full model solves eq. 18 in its modal coordinates likewise, silently, and the
        # reduced model's exact FRF lies within the 1 dB of issue 4 of it, both speeds.
        for speed in ("0", "30"):
            full_out = self.path(f"arm_damped_full_{speed}.csv")
            r = self.tvd("frf", "--vehicle", damped, "--variant", "untracked", "--model", "full",
                         "--speed-kmh", speed, "--out", full_out, "--json")
            self.assertEqual(json.loads(r.stdout)["solution"], "direct")
            self.assertGreater(json.loads(r.stdout)["damping_coupling"], 0.1)
            self.assertEqual(r.stderr, "")
            reduced_out = self.path(f"arm_damped_reduced_{speed}.csv")
            self.tvd("frf", "--vehicle", damped, "--reduced", mat, "--speed-kmh", speed,
                     "--out", reduced_out)
            full_header, full_rows = read_csv(full_out)
            reduced_header, reduced_rows = read_csv(reduced_out)
            self.assertEqual(full_header, reduced_header)
            for column in ("hull_vertical_acc_mag", "hull_pitch_acc_mag", "front_wheel_acc_mag",
                           "rear_wheel_acc_mag"):
                c = full_header.index(column)
                db, share = self.worst_db(full_rows[:, 0], full_rows[:, c], reduced_rows[:, c])
                self.assertLess(db, self.FRF_TOLERANCE_DB, (speed, column))
                self.assertGreater(share, 0.45, (speed, column))
        # SciPy's squeeze_me round trip writes the column vectors as rows: refused, saying why.
        squeezed = self.path("arm_damped_squeezed.mat")
        scipy.io.savemat(squeezed, scipy.io.loadmat(mat, squeeze_me=True))
        r = self.tvd("frf", "--vehicle", damped, "--reduced", squeezed, "--out",
                     self.path("x.csv"), status=INPUT_ERROR_STATUS)
        self.assertIn("a row saved for a column: SciPy's savemat writes 1-D arrays as rows unless "
                      "given oned_as='column'", r.stderr)
        columns = self.path("arm_damped_columns.mat")
        scipy.io.savemat(columns, scipy.io.loadmat(mat, squeeze_me=True), oned_as="column")
        self.tvd("frf", "--vehicle", damped, "--reduced", columns, "--max-hz", "2", "--out",
                 self.path("x.mat"))
        # The result file names the model file it is of, as simulate's do; so does its JSON.
        self.assertEqual(str(scipy.io.loadmat(self.path("x.mat"))["reduced_model_file"][0]),
                         columns)
        self.assertEqual(self.tvd_json("frf", "--vehicle", damped, "--reduced", columns,
                                       "--max-hz", "2")["reduced_model_file"], columns)
        # simulate: the modal method steps the coupled modes together (the whole C, as the
        # exact method) and says nothing; reduced modal and exact, and the full model (the
        # reference) by either method, agree within 2 % of each peak (issue 5; 0.2 % here).
        # Keeping each mode's own damping, until 2026-12-06, gave half the hull's acceleration.
        runs = {}
        for name, args in (("modal", ["--reduced", mat, "--ground-contact", "off", "--out",
                                      self.path("arm_damped.csv")]),
                           ("exact", ["--reduced", mat, "--ground-contact", "off", "--method",
                                      "exact"]),
                           ("full", ["--variant", "untracked", "--model", "full"]),
                           ("full exact", ["--variant", "untracked", "--model", "full",
                                           "--method", "exact"])):
            r = self.tvd("simulate", "--vehicle", damped, "--track", "long_hill", "--speed-kmh",
                         "30", *args, "--json")
            self.assertEqual(r.stderr, "", name)
            runs[name] = json.loads(r.stdout)
            self.assertEqual(runs[name]["warnings"], [], name)
            self.assertEqual(runs[name]["method"], "exact" if "exact" in name else "modal")
        for key in ("peak_hull_heave_m", "peak_hull_vertical_accel_m_s2", "peak_pitch_deg",
                    "peak_wheel_displacement_m"):
            for name in ("modal", "exact", "full exact"):
                self.assertAlmostEqual(runs[name][key], runs["full"][key],
                                       delta=0.02 * abs(runs["full"][key]), msg=(name, key))
        # The spectral ride takes the whole damping by complex modes, silently; the bundled
        # vehicle's diagonal damping keeps the real modes.
        ride = self.tvd("ride", "--vehicle", damped, "--reduced", mat, "--iso8608", "C",
                        "--speeds", "20,40", "--json")
        self.assertEqual(json.loads(ride.stdout)["solution"], "complex_modes")
        self.assertGreater(json.loads(ride.stdout)["damping_coupling"], 0.1)
        self.assertEqual(json.loads(ride.stdout)["warnings"], [])
        self.assertEqual(ride.stderr, "")
        text = self.tvd("ride", "--vehicle", damped, "--reduced", mat, "--iso8608", "C",
                        "--speeds", "20").stdout
        self.assertIn("solved by complex modes: the damping couples the modes", text)
        # The band-cut sensitivity is the same model's on the wider band: its figure is the
        # run with --max-frequency 10 (eq. 20 on the wider band, until 2026-12-06, warned of
        # nothing here).
        low = self.tvd_json("ride", "--vehicle", damped, "--reduced", mat, "--iso8608", "C",
                            "--speeds", "10")
        wide = self.tvd_json("ride", "--vehicle", damped, "--reduced", mat, "--iso8608", "C",
                             "--speeds", "10", "--max-frequency", "10")
        seat = [p["absorbed_power_w"] for p in wide["runs"][0]["points"]
                if p["point"] == "crew_seat"][0]
        band = [w for w in low["warnings"] if w.startswith("the road's band ends at 2.83")]
        self.assertEqual(len(band), 1, low["warnings"])
        self.assertIn(f"crew_seat would absorb {seat:.3g} W at 10 km/h", band[0])
        self.assertEqual(self.tvd_json("ride", "--vehicle", VEHICLE, "--variant", "untracked",
                                       "--cache-dir", self.cache, "--iso8608", "C", "--speeds",
                                       "20")["solution"], "modal")
        # The time-domain ride steps the coupled modes likewise.
        self.assertEqual(self.tvd_json("ride", "--vehicle", damped, "--reduced", mat, "--track",
                                       "long_hill", "--speeds", "10,20")["warnings"], [])

    def test_frf_points_bad_names_are_refused(self):
        renamed = self.vehicle_with("renamed_seat.yaml", "\n  crew_seat:", "\n  driver_seat:")
        cache = self.path("cache_points_refused")
        frf = ["frf", "--variant", "untracked"]
        cases = [
            ([VEHICLE, "--points", "crew_seat,turret"],
             "unknown point 'turret' (the vehicle has: crew_seat, sensor_mount)"),
            ([VEHICLE, "--points", "crew_seat", "--points", "crew_seat"],
             "point 'crew_seat' is listed twice"),
            ([VEHICLE, "--points", "sensor_mount,crew_seat,sensor_mount"],
             "point 'sensor_mount' is listed twice"),
            ([VEHICLE, "--model", "full", "--points", "Crew_Seat"],
             "unknown point 'Crew_Seat' (the vehicle has: crew_seat, sensor_mount)"),
            # The names are the description's, not a built-in list.
            ([renamed, "--points", "crew_seat"],
             "unknown point 'crew_seat' (the vehicle has: driver_seat, sensor_mount)"),
        ]
        for args, message in cases:
            # --cache-dir is refused with --model full.
            cached = [] if "--model" in args else ["--cache-dir", cache]
            result = self.tvd(*frf, *cached, "--vehicle", *args, status=INPUT_ERROR_STATUS)
            self.assertEqual(result.stdout, "")
            lines = result.stderr.strip().splitlines()
            self.assertEqual(len(lines), 1, result.stderr)
            self.assertEqual(lines[0], "tvd: error: frf: --points: " + message)
        self.assertFalse(os.path.exists(cache))  # refused before any reduction

    # --- Reduction options and reduced-model files of frf and simulate ----------------------
    # The un-tracked variant with the band rule: no tracked modes to solve, so each reduction
    # takes a fraction of a second; the options still differ from the defaults in every way the
    # cache keys on (rule and band).
    BAND = ("--rule", "band", "--band", "40")

    def band_model(self):
        """`tvd reduce --rule band --band 40 --out m.mat` (once) and its JSON."""
        cls = type(self)
        if not hasattr(cls, "_band_model"):
            out = self.path("band40.mat")
            d = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "untracked", *self.BAND,
                              "--out", out)
            cls._band_model = (out, d)
        return cls._band_model

    def frf_mat(self, name, *args):
        out = self.path(name)
        d = self.tvd_json("frf", "--vehicle", VEHICLE, *args, "--max-hz", "30", "--out", out)
        m = scipy.io.loadmat(out)
        return d, {k: np.ravel(v) for k, v in m.items() if k.endswith(("_mag", "_phase_deg"))}

    def test_frf_of_a_reduced_file_is_that_of_its_options(self):
        mat, reduced = self.band_model()
        self.assertEqual(reduced["reduction"]["rule"], "band")
        self.assertEqual(reduced["reduction"]["band_hz"], 40.0)
        cache = self.path("cache_band_frf")
        from_file, h_file = self.frf_mat("frf_file.mat", "--reduced", mat)
        computed, h_computed = self.frf_mat("frf_band.mat", "--variant", "untracked", *self.BAND,
                                            "--cache-dir", cache)
        r = from_file["reduction"]
        self.assertEqual(r["source"], "file")
        self.assertEqual(r["file"], mat)
        self.assertEqual(from_file["variant"], "untracked")  # the file's, --variant not given
        self.assertEqual((r["rule"], r["band_hz"], r["variant"]), ("band", 40.0, "untracked"))
        self.assertEqual(r["reduced_dofs"], reduced["reduced_dofs"])
        self.assertEqual(from_file["dofs"], reduced["reduced_dofs"])
        self.assertEqual(r["fixed_interface_modes"], reduced["flexible_modes"])
        self.assertEqual(r["mogesec_masters"], 9)
        self.assertEqual(r["master_dofs"] + r["fixed_interface_modes"], r["reduced_dofs"])
        self.assertEqual(computed["reduction"]["source"], "computed")
        for key in ("rule", "band_hz", "global_modes", "mac_threshold", "mogesec_masters",
                    "mode_count", "selected_global_modes", "fixed_interface_modes",
                    "master_dofs", "reduced_dofs"):
            self.assertEqual(computed["reduction"][key], r[key], key)
        self.assertEqual(sorted(h_file), sorted(h_computed))
        self.assertEqual(len(h_file), 8)
        for name in h_file:
            if name.endswith("_mag"):
                np.testing.assert_allclose(h_file[name], h_computed[name], rtol=1e-9, atol=0,
                                           err_msg=name)
        # The text output says where the model came from.
        text = self.tvd("frf", "--vehicle", VEHICLE, "--reduced", mat, "--max-hz", "5").stdout
        self.assertIn("reduction: rule band, 0-40 Hz", text)
        self.assertIn("from " + mat, text)

    def test_cache_keeps_each_reduction_apart(self):
        # A band-40 FRF, then one with the default options in the same cache: the default model,
        # computed (not the band-40 file), then both again from their own cache files.
        cache = self.path("cache_apart")
        _, band = self.band_model()
        default = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "untracked")
        self.assertNotEqual(default["reduced_dofs"], band["reduced_dofs"])
        args = ("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--max-hz", "5",
                "--cache-dir", cache)
        runs = [("band", self.tvd_json(*args, *self.BAND), "computed", band),
                ("default", self.tvd_json(*args), "computed", default),
                ("band", self.tvd_json(*args, *self.BAND), "cache", band),
                ("default", self.tvd_json(*args), "cache", default)]
        for name, d, source, expected in runs:
            r = d["reduction"]
            self.assertEqual(r["source"], source, name)
            self.assertEqual(r["rule"], "band" if name == "band" else "mac", name)
            self.assertEqual(r["reduced_dofs"], expected["reduced_dofs"], name)
            self.assertEqual(d["dofs"], expected["reduced_dofs"], name)
            self.assertTrue(r["file"].startswith(cache), r["file"])
        self.assertNotEqual(runs[0][1]["reduction"]["file"], runs[1][1]["reduction"]["file"])
        self.assertEqual(len([n for n in os.listdir(cache) if n.endswith(".mat")]), 2)

    def test_reduced_file_of_another_description_or_damaged_is_refused(self):
        mat, _ = self.band_model()
        heavier = self.vehicle_with("heavier_hull.yaml", "mass: {value: 30300, unit: kg",
                                    "mass: {value: 31300, unit: kg")
        cut = self.path("band40_cut.mat")
        with open(mat, "rb") as f, open(cut, "wb") as g:
            data = f.read()
            g.write(data[:len(data) // 2])
        for command in (["frf", "--vehicle", heavier, "--reduced", mat],
                        ["simulate", "--vehicle", heavier, "--reduced", mat],
                        ["frf", "--vehicle", VEHICLE, "--reduced", cut]):
            result = self.tvd(*command, status=INPUT_ERROR_STATUS)
            self.assertEqual(result.stdout, "")
            lines = result.stderr.strip().splitlines()
            self.assertEqual(len(lines), 1, result.stderr)
            file = command[-1]
            self.assertTrue(lines[0].startswith(f"tvd: error: {file}: "), lines[0])
            self.assertIn("run tvd reduce again", lines[0])
            if file == mat:
                self.assertIn("reduced from another description", lines[0])
            else:
                self.assertIn("truncated", lines[0])
        # A file whose checksum holds but whose K_R is not positive definite (edited and signed
        # again): refused by the file's own check, its advice given once.
        edited = self.path("band40_edited.mat")
        values = {k: v for k, v in scipy.io.loadmat(mat).items() if not k.startswith("__")}
        values["K_R"][0, 0] = -values["K_R"][0, 0]
        scipy.io.savemat(edited, values)
        values["checksum"] = documented_checksum(edited)
        scipy.io.savemat(edited, values)
        result = self.tvd("frf", "--vehicle", VEHICLE, "--reduced", edited,
                          status=INPUT_ERROR_STATUS)
        self.assertIn("K_R is not positive definite", result.stderr)
        self.assertEqual(result.stderr.count("tvd reduce"), 1, result.stderr)
        # Outputs renamed and the file signed again: refused naming the file, not as "frf: the
        # model has no output 'hull uz'" once the run had started.
        renamed = self.path("band40_renamed.mat")
        values = {k: v for k, v in scipy.io.loadmat(mat).items() if not k.startswith("__")}
        names = values["output_names"]
        for i in range(names.shape[0]):
            names[i, 0] = np.array([str(names[i, 0][0]).replace("hull", "body")])
        scipy.io.savemat(renamed, values)
        values["checksum"] = documented_checksum(renamed)
        scipy.io.savemat(renamed, values)
        for command in ("frf", "simulate"):
            result = self.tvd(command, "--vehicle", VEHICLE, "--reduced", renamed,
                              *(["--track", "long_hill", "--speed-kmh", "10"]
                                if command == "simulate" else []),
                              status=INPUT_ERROR_STATUS)
            self.assertEqual(result.stderr.strip(),
                             f"tvd: error: {renamed}: the model has no output 'hull ux', which "
                             "the vehicle's reduced model has (output_names edited?); run tvd "
                             "reduce again")

    def test_reduced_file_conflicts_are_named(self):
        mat, _ = self.band_model()
        frf = ["frf", "--vehicle", VEHICLE, "--cache-dir", self.cache]
        sim = ["simulate", "--vehicle", VEHICLE, "--cache-dir", self.cache]
        for cmd in (frf, sim):
            name = cmd[0]
            self.assert_input_error(cmd + ["--reduced", mat, "--model", "full"],
                                    f"{name}: --reduced {mat} is a reduced model; it cannot be "
                                    "used with --model full")
            self.assert_input_error(cmd + ["--reduced", mat, "--band", "30"],
                                    f"{name}: --band is a reduction option; --reduced {mat}")
            self.assert_input_error(cmd + ["--reduced", mat, "--rule", "mac"], "--rule is a reduction")
            self.assert_input_error(cmd + ["--model", "full", "--masters", "4"],
                                    f"{name}: --masters applies to --model reduced only")
            # (without --cache-dir, which --reduced refuses)
            self.assert_input_error(cmd[:3] + ["--reduced", mat, "--variant", "tracked"],
                                    f"{name}: --reduced {mat} is the untracked variant, --variant "
                                    "is tracked")
            self.assert_input_error(cmd + ["--reduced", self.path("none.mat")], "--reduced",
                                    "none.mat")
        # The reduction options: the same flags, ranges and messages as tvd reduce.
        for cmd in (["reduce", "--vehicle", VEHICLE], frf, sim):
            name = cmd[0]
            self.assert_input_error(cmd + ["--rule", "band", "--mac-threshold", "0.8"],
                                    f"{name}: --mac-threshold applies to --rule mac only")
            for value in ("0", "1.5", "nan"):
                self.assert_input_error(cmd + ["--mac-threshold", value], "--mac-threshold",
                                        f"must be a number in (0, 1], got {value}")
            self.assert_input_error(cmd + ["--band", "-1"], "--band",
                                    "must be a positive number, got -1")
            self.assert_input_error(cmd + ["--rule", "all"], "--rule", "all")
            self.assert_input_error(cmd + ["--global-modes", "0"], "--global-modes")
        for command in ("reduce", "frf", "simulate"):
            text = self.tvd(command, "--help").stdout
            for flag in ("--rule", "--band", "--global-modes", "--masters", "--modes",
                         "--mac-threshold"):
                self.assertIn(flag, text, command)
            if command != "reduce":
                self.assertIn("--reduced", text)

    def test_simulate_runs_a_reduced_file(self):
        mat, reduced = self.band_model()
        args = ("simulate", "--vehicle", VEHICLE, "--track", "long_hill", "--speed-kmh", "30")
        d = self.tvd_json(*args, "--reduced", mat)
        r = d["reduction"]
        self.assertEqual((r["source"], r["file"], r["rule"], r["band_hz"]), ("file", mat, "band", 40.0))
        self.assertEqual(d["variant"], "untracked")
        self.assertEqual(d["reduced_dofs"], reduced["reduced_dofs"])
        self.assertFalse(d["model_from_cache"])
        # The same run with the options themselves (through the cache) gives the same response.
        again = self.tvd_json(*args, "--variant", "untracked", *self.BAND, "--cache-dir",
                              self.path("cache_band_sim"))
        self.assertEqual(again["reduction"]["source"], "computed")
        for key in ("peak_hull_heave_m", "peak_hull_vertical_accel_m_s2", "peak_pitch_deg"):
            self.assertAlmostEqual(again[key] / d[key], 1.0, delta=1e-9, msg=key)

    def assert_input_error(self, args, *words):
        result = self.tvd(*args, status=INPUT_ERROR_STATUS)
        message = result.stderr + result.stdout
        for word in words:
            self.assertIn(word, message)
        self.assertNotIn("Traceback", message)
        self.assertNotIn("terminate called", message)

    def test_a_failed_write_of_the_printed_results_is_an_error(self):
        """Text or JSON results that cannot be written (a full disk: /dev/full) fail the run
        (status 2, one line naming standard output) instead of passing for success."""
        for extra in ((), ("--json",)):
            with open("/dev/full", "w") as full:
                result = subprocess.run([TVD, "statics", "--vehicle", VEHICLE, "--variant",
                                         "untracked", *extra], stdout=full,
                                        stderr=subprocess.PIPE, text=True, timeout=120)
            self.assertEqual(result.returncode, INPUT_ERROR_STATUS, result.stderr)
            self.assertEqual(result.stderr.count("tvd: error: cannot write standard output"), 1,
                             result.stderr)

    def test_an_empty_number_is_refused_not_read_as_zero(self):
        """An empty value of a number option (an unset shell variable) is no 0: frf took
        --speed-kmh '' for synchronous excitation without a word."""
        for args in (["frf", "--vehicle", VEHICLE, "--speed-kmh", ""],
                     ["simulate", "--vehicle", VEHICLE, "--speed-kmh", ""]):
            self.assert_input_error(args, "--speed-kmh: '' is not a number")

    def test_integers_are_read_in_decimal(self):
        """CLI11 reads an integer with a leading 0 as octal and 0x as hex: --seed 010 gave seed
        8's road and --count 010 eight modes. A leading zero is dropped; a base prefix refused."""
        model = os.path.join(ROOT, "config", "models", "spring_mass_chain.yaml")
        counts = []
        for count in ("010", "10", "+0010"):
            result = self.tvd("modes", "--model", model, "--count", count, "--json")
            counts.append(len(json.loads(result.stdout)["frequencies_hz"]))
        self.assertEqual(counts, [10, 10, 10])
        roads = []
        for seed in ("010", "10"):
            out = self.path(f"seed_{seed}.csv")
            self.tvd("terrain", "--iso8608", "C", "--length", "20", "--seed", seed, "--out", out)
            with open(out) as f:
                roads.append(f.read())
        self.assertEqual(roads[0], roads[1])
        # The whole message, as describeParseError words it (checkNumberTexts' own refusal is
        # bare; its old text, "must be a decimal integer", was never shown).
        for args, message in (
                (["modes", "--model", model, "--count", "0x10"],
                 "tvd: error: modes: --count: '0x10' is not an integer"),
                (["terrain", "--iso8608", "C", "--seed", "0b11", "--out", self.path("b.csv")],
                 "tvd: error: terrain: --seed: '0b11' is not a non-negative integer"),
                (["modes", "--model", model, "--count", "-0x10"],
                 "tvd: error: modes: --count: '-0x10' is not an integer")):
            result = self.tvd(*args, status=INPUT_ERROR_STATUS)
            self.assertEqual(result.stderr.strip(), message)
        self.assertFalse(os.path.exists(self.path("b.csv")))

    def test_ride_mat_output_with_a_long_point_name_is_refused_before_the_sweep(self):
        """A 40-character point name (the description's limit) loads, but ride's longest MAT
        variable from it would have 67 characters: refused before any run, not after the sweep."""
        name = "abcdefghij" * 4
        vehicle = self.vehicle_with("long_point.yaml", "crew_seat:", name + ":")
        self.assert_input_error(["ride", "--vehicle", vehicle, "--variant", "untracked", "--track",
                                 "half_round:0.2", "--out", self.path("long.mat")],
                                f"'{name}_vibration_total_value_m_s2' (67 characters)",
                                "write .csv")
        self.assertFalse(os.path.exists(self.path("long.mat")))
        # The spectral method's table has the same column, refused before its sweep too.
        self.assert_input_error(["ride", "--vehicle", vehicle, "--variant", "untracked",
                                 "--iso8608", "C", "--out", self.path("long.mat")],
                                f"--out {self.path('long.mat')}: the column "
                                f"'{name}_vibration_total_value_m_s2' (67 characters)")
        self.assertFalse(os.path.exists(self.path("long.mat")))

    def test_an_output_over_an_input_file_is_refused(self):
        """--out naming an input file (however spelt) is refused before any work, and the input
        is left as it was: the terrain of simulate and ride, the reduced model of frf."""
        track = self.path("own_track.csv")
        with open(os.path.join(ROOT, "config", "tracks", "step_profile.csv")) as f:
            terrain = f.read()
        with open(track, "w") as f:
            f.write(terrain)
        spelt = os.path.join(os.path.dirname(track), ".", os.path.basename(track))
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                                 "--track", track, "--out", spelt],
                                f"--out {spelt} is the --track file", "write elsewhere")
        self.assert_input_error(["ride", "--vehicle", VEHICLE, "--variant", "untracked",
                                 "--track", track, "--speeds", "10", "--out", track],
                                "ride: --out", "is the --track file")
        with open(track) as f:
            self.assertEqual(f.read(), terrain)
        mat, _ = self.band_model()
        with open(mat, "rb") as f:
            model = f.read()
        self.assert_input_error(["frf", "--vehicle", VEHICLE, "--reduced", mat, "--out", mat],
                                "is the --reduced file")
        with open(mat, "rb") as f:
            self.assertEqual(f.read(), model)
        # The speed profile of simulate: a CSV like the output, the easiest one to overwrite.
        profile = self.path("own_profile.csv")
        with open(profile, "w") as f:
            f.write("t,v\n0,5\n10,5\n")
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                                 "--track", "long_hill", "--speed-profile", profile,
                                 "--out", profile],
                                f"--out {profile} is the --speed-profile file", "write elsewhere")
        with open(profile) as f:
            self.assertEqual(f.read(), "t,v\n0,5\n10,5\n")
        # statics' table over its description (its name may end in .csv: the kind is read from
        # the content), and modes' directory holding a model named as one of its output files.
        with open(VEHICLE) as f:
            description = f.read()
        own = self.path("own_vehicle.csv")
        with open(own, "w") as f:
            f.write(description)
        self.assert_input_error(["statics", "--vehicle", own, "--out", own],
                                f"statics: --out {own} is the --vehicle file", "write elsewhere")
        with open(own) as f:
            self.assertEqual(f.read(), description)
        directory = self.path("modes_over_input")
        os.makedirs(directory, exist_ok=True)
        model = os.path.join(directory, "shapes.csv")
        with open(os.path.join(ROOT, "config", "models", "spring_mass_chain.yaml")) as f:
            chain = f.read()
        with open(model, "w") as f:
            f.write(chain)
        self.assert_input_error(["modes", "--model", model, "--count", "2", "--out", directory],
                                f"modes: --out {model} is the --model file")
        with open(model) as f:
            self.assertEqual(f.read(), chain)
        self.assertFalse(os.path.exists(os.path.join(directory, "modes.csv")))

    def test_random_road_and_reduction_errors_name_the_options(self):
        """tvd terrain --iso8608 names --taper and --length, --max-frequency and --spacing (its
        suggested spacing is accepted as printed), --max-frequency and --width beyond their finite
        bounds; a MoGeSeC count beyond the candidates and a
        MAC selection that pairs nothing name the options that set them."""
        road = self.path("named_road.csv")
        iso = ["terrain", "--iso8608", "C", "--out", road]
        self.assert_input_error(iso + ["--length", "100", "--taper", "60"],
                                "--taper 60 m must be at most half of --length (100 m: at most "
                                "50 m)")
        self.assert_input_error(iso + ["--min-frequency", "3"],
                                "--min-frequency 3 cycles/m must be below --max-frequency 2.83")
        r = self.tvd(*iso, "--max-frequency", "3", "--spacing", "0.2", status=INPUT_ERROR_STATUS)
        self.assertIn("--max-frequency 3 cycles/m is above what --spacing 0.2 m can hold, "
                      "1 / (2 spacing) = 2.5 cycles/m: give --spacing at most 0.166666 m", r.stderr)
        self.tvd(*iso, "--max-frequency", "3", "--spacing", "0.166666", "--length", "20")
        self.assertTrue(os.path.exists(road))
        # Finite bounds named by their option: 1e308 once suggested "--spacing at most nan m",
        # and --width 1e20 was refused naming the terrain's lateral line.
        for value in ("1e308", "5.1e5"):
            self.assert_input_error(iso + ["--max-frequency", value],
                                    "terrain: --max-frequency: must be positive and at most "
                                    "5e+05 cycles/m (1 / (2 x 1e-06 m), the finest --spacing), "
                                    "got " + value)
        for value in ("1e20", "1000.5"):
            self.assert_input_error(iso + ["--width", value],
                                    "terrain: --width: must be positive and at most 1000 m (a "
                                    "road's width), got " + value)
        reduce = ["reduce", "--vehicle", VEHICLE, "--variant", "untracked"]
        self.assert_input_error(reduce + ["--masters", "1000"],
                                "MoGeSeC masters of the untracked variant, mogesec_masters 1000 "
                                "(tvd --masters, ~reduction/mogesec_masters)",
                                "only 364 candidates")
        self.assert_input_error(reduce + ["--global-modes", "5"],
                                "no global mode selected below 30 Hz (MAC threshold 0.7 among the "
                                "global modes of each variant's lowest 5",
                                "--global-modes", "--mac-threshold")

    def test_a_run_that_cannot_be_driven_is_refused_before_the_model_is_built(self):
        """A track of one station, or a speed too slow to finish within the step limit, is
        refused at once: no reduction is run (the cache directory stays empty) and the refusal
        comes in well under the tracked reduction's seconds."""
        cache = self.path("untouched_cache")
        one = self.path("one_station.csv")
        with open(one, "w") as f:
            f.write("x,h\n0,0.1\n")
        sim = ["simulate", "--vehicle", VEHICLE, "--variant", "tracked", "--cache-dir", cache,
               "--out", self.path("never.csv")]
        for args, words in (((*sim, "--track", one), ("one_station.csv", "single station")),
                            ((*sim, "--track", "long_hill", "--speed-kmh", "0.001"),
                             ("take 1.08e+08 time steps", "at most 1e+07"))):
            start = time.monotonic()
            self.assert_input_error(list(args), *words)
            self.assertLess(time.monotonic() - start, 1.0)
            written = os.listdir(cache) if os.path.exists(cache) else []
            self.assertEqual(written, [])
        self.assertFalse(os.path.exists(self.path("never.csv")))

    def test_bad_input_is_named(self):
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                                 "--track", "long_hill", "--speed-kmh", "-5"], "--speed-kmh", "-5")
        self.assert_input_error(["modes", "--vehicle", self.path("none.yaml")], "none.yaml")
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--method", "exact",
                                 "--max-mode-hz", "50", "--cache-dir", self.cache],
                                "--max-mode-hz applies to --method modal only")
        self.assert_input_error(["frf", "--vehicle", VEHICLE, "--max-mode-hz", "50",
                                 "--cache-dir", self.cache], "--max-mode-hz applies to --model full")
        for command in (["frf"], ["simulate", "--track", "long_hill", "--speed-kmh", "10"]):
            self.assert_input_error([*command, "--vehicle", VEHICLE, "--model", "full",
                                     "--cache-dir", self.cache],
                                    "--cache-dir applies to --model reduced only")
        self.assert_input_error(["reduce", "--vehicle", VEHICLE, "--rule", "band",
                                 "--mac-threshold", "0.8"], "--mac-threshold applies to --rule mac")
        self.assert_input_error(["modes", "--vehicle", VEHICLE, "--count", "0"], "--count")
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--track", "moon_craters",
                                 "--speed-kmh", "10", "--cache-dir", self.cache], "moon_craters",
                                "neither a built-in track (long_hill")
        truncated = self.path("truncated.yaml")
        with open(VEHICLE) as f, open(truncated, "w") as g:
            g.writelines(f.readlines()[:30])
        self.assert_input_error(["modes", "--vehicle", truncated], "required key is missing")

    def test_options_are_checked_before_any_work(self):
        # Each of these once ran the whole job first, or wrote a file of another type, or let
        # NaN through (CLI11's Range does).
        sim = ["simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", self.cache]
        self.assert_input_error(sim + ["--out", self.path("no_dir/x.csv")], "does not exist")
        self.assert_input_error(sim + ["--out", self.path("x.json")], "must end in .csv or .mat")
        # A directory where access(W_OK) says yes to root but no file can be made (sysfs): it
        # once ran the whole job and lost the results at the end.
        if os.path.isdir("/sys/kernel"):
            why = ("a file cannot be created in the directory /sys/kernel" if os.geteuid() == 0
                   else "the directory /sys/kernel is not writable")
            self.assert_input_error(sim + ["--out", "/sys/kernel/x.csv"], why)
            self.assert_input_error(["modes", "--vehicle", VEHICLE, "--out", "/sys/kernel/new"], why)
        self.assert_input_error(sim + ["--dt", "nan"], "--dt", "[1e-05, 0.01] s")
        self.assert_input_error(sim + ["--dt", "0.05"], "--dt")
        self.assert_input_error(sim + ["--lateral-offset", "nan"], "--lateral-offset", "finite")
        self.assert_input_error(["reduce", "--vehicle", VEHICLE, "--out", self.path("r.csv")],
                                "must end in .mat")
        self.assert_input_error(["frf", "--vehicle", VEHICLE, "--model", "full",
                                 "--max-mode-hz", "1e5"], "--max-mode-hz", "(0, 100] Hz")
        self.assert_input_error(["modes", "--vehicle", VEHICLE, "--count", "100000"], "--count")
        # Output directories of modes and mac: checked before the solve, not after it.
        a_file = self.path("a_file")
        with open(a_file, "w") as f:
            f.write("x")
        self.assert_input_error(["modes", "--vehicle", VEHICLE, "--out", a_file], "--out",
                                "is not a directory")
        self.assert_input_error(["mac", "--vehicle", VEHICLE, "--out",
                                 os.path.join(a_file, "mac")], "--out", "is not a directory")
        os.symlink(self.path("nowhere"), self.path("dangling"))
        self.assert_input_error(["modes", "--vehicle", VEHICLE, "--out", self.path("dangling")],
                                "--out", "link to nothing")
        # A directory where a file is expected, and a file where a directory is.
        os.makedirs(self.path("m.mat"))
        self.assert_input_error(["reduce", "--vehicle", VEHICLE, "--out", self.path("m.mat")],
                                "--out", "is a directory")
        self.assert_input_error(["terrain", "--track", "long_hill", "--out",
                                 os.path.join(a_file, "t.csv")], "--out", "is not a directory")
        self.tvd("modes", "--vehicle", VEHICLE, "--count", "2", "--out", self.path("new/modes"))
        self.assertTrue(os.path.isfile(self.path("new/modes/modes.csv")))
        # Terrain files: the directory is checked, the extension in any case.
        self.assert_input_error(["terrain", "--track", "long_hill", "--out",
                                 self.path("no_dir/t.csv")], "does not exist")
        self.assert_input_error(["terrain", "--track", "long_hill", "--out", self.path("t.txt")],
                                "must end in .csv or .yaml or .yml")
        self.tvd("terrain", "--track", "long_hill", "--out", self.path("HILL.YAML"))
        with open(self.path("HILL.YAML")) as f:
            self.assertEqual(yaml.safe_load(f)["name"], "long_hill")
        self.assert_input_error(["modes", "--vehicle", VEHICLE, "--max-frequency", "5"],
                                "--max-frequency requires --model")
        self.assert_input_error(["terrain", "--iso8608", "C", "--seed", "-1", "--out",
                                 self.path("t.csv")], "--seed", "[0, 9007199254740992]")
        # 2^53 + 1 is one above the bound, though as a double it rounds down to 2^53.
        self.assert_input_error(["terrain", "--iso8608", "C", "--seed", "9007199254740993",
                                 "--out", self.path("t.csv")], "--seed", "[0, 9007199254740992]")
        self.tvd("terrain", "--iso8608", "C", "--seed", "9007199254740992", "--length", "20",
                 "--out", self.path("t.csv"))
        self.assert_input_error(["terrain", "--iso8608", "", "--out", self.path("t.csv")],
                                "--iso8608 must be one road class A..H")
        self.assert_input_error(["frf", "--vehicle", VEHICLE, "--variant", "untracked", "--model",
                                 "full", "--max-mode-hz", "0.001"], "no mode lies below 0.001 Hz",
                                "--max-mode-hz")
        # A terrain of one station covers no length.
        one = self.path("one.csv")
        with open(one, "w") as f:
            f.write("x,h\n0,0.1\n")
        self.assert_input_error(sim + ["--track", one], "one.csv", "single station")
        # Upper-case extensions are terrain files too; .MAT is a MAT file.
        flat = self.path("FLAT.CSV")
        with open(flat, "w") as f:
            f.write("x,h\n0,0\n20,0\n")
        out = self.path("flat.MAT")
        self.tvd(*sim, "--track", flat, "--speed-kmh", "60", "--out", out)
        with open(out, "rb") as f:
            self.assertTrue(f.read(10).startswith(b"MATLAB 5.0"))

    def test_speed_profile_ending_early_is_a_warning_in_the_json(self):
        profile = self.path("short_profile.csv")
        with open(profile, "w") as f:
            f.write("time_s,speed_kmh\n0,36\n2,36\n")  # 20 m of the 30 m long hill
        result = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                               "--track", "long_hill", "--speed-profile", profile,
                               "--cache-dir", self.cache)
        self.assertAlmostEqual(result["travelled_m"], 20.0, delta=1e-6)
        self.assertEqual(len(input_warnings(result["warnings"])), 1, result["warnings"])
        self.assertIn("ends after 20", result["warnings"][0])

    def test_simulate_says_when_the_linear_model_leaves_its_range(self):
        """A whole pad pressed at rest that pulls on the road (the node's criterion) is a warning,
        with the time and station the JSON's ground_contact block gives; a gentle road is not."""
        common = ("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                  self.cache, "--json")
        r = self.tvd(*common, "--track", "long_hill", "--speed-kmh", "50")
        d = json.loads(r.stdout)
        pads = d["ground_contact"]["pads"]
        ranged = [w for w in d["warnings"] if w.startswith(RANGE_WARNING)]
        self.assertEqual(len(ranged), 1, d["warnings"])
        self.assertIn(f"from t = {pads['first_new_tension_time_s']:.3f} s "
                      f"(x = {pads['first_new_tension_station_m']:.3f} m)", ranged[0])
        self.assertIn(f"(up to {pads['max_in_tension']} of {pads['count']} at once)", ranged[0])
        self.assertIn("tvd: warning: " + ranged[0], r.stderr)
        self.assertFalse(d["ground_contact"]["in_range"])
        # A 2 cm bump at walking pace: single soles may rock into tension, whole pads keep
        # pressing, and that is no warning.
        bump = self.path("bump.csv")
        with open(bump, "w") as f:
            f.write("x,h\n0,0\n10,0\n12,0.02\n14,0\n30,0\n")
        gentle = json.loads(self.tvd(*common, "--track", bump, "--speed-kmh", "5").stdout)
        self.assertEqual(gentle["ground_contact"]["pads"]["max_in_tension"], 0,
                         gentle["ground_contact"])
        self.assertEqual([w for w in gentle["warnings"] if w.startswith(RANGE_WARNING)], [])

    def test_built_in_oop_track_runs_without_an_edge_warning(self):
        result = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                               "--track", "oop_waves", "--speed-kmh", "30", "--cache-dir", self.cache)
        self.assertEqual(input_warnings(result["warnings"]), [])
        # The same track as a file is user data: the 5.5 cm overhang is reported.
        track = self.path("oop.csv")
        self.tvd("terrain", "--track", "oop_waves", "--out", track)
        result = self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                               "--track", track, "--speed-kmh", "30", "--cache-dir", self.cache)
        self.assertEqual(len(input_warnings(result["warnings"])), 1)
        self.assertIn("edge line", result["warnings"][0])

    def test_half_round_obstacle_track(self):
        """--track half_round:H, the NRMM half-round obstacle: `tvd terrain` writes it (uniform
        across the width, flat before and after, the half-disc's area, the crest of the 0.2 m
        moving average of the semicircle: closed forms), the file reads back and simulates like
        the built-in; the vehicle rides over it from rest and settles; bad specs are named."""
        height, window, centre, dx = 0.15, 0.2, 10.0, 0.01
        track = self.path("half_round.csv")
        d = self.tvd_json("terrain", "--track", f"half_round:{height}", "--out", track)
        self.assertEqual(d["name"], "half_round:0.15")
        self.assertEqual((d["stations"], d["start_station_m"], d["end_station_m"]), (3001, 0, 30))
        self.assertEqual(d["min_height_m"], 0.0)
        y_lines, stations, heights = read_terrain_csv(track)
        self.assertEqual((y_lines[0], y_lines[-1]), (-2.5, 2.5))
        for j in range(1, heights.shape[1]):
            np.testing.assert_array_equal(heights[:, j], heights[:, 0])  # uniform across the width
        h = heights[:, 0]
        # Crest: the mean of sqrt(H^2 - u^2) over |u| <= W/2 (a circular segment), at x = 10 m,
        # to the chords' sag between 1 cm samples (tracks.h); lower than H.
        a = window / 2
        crest = (a * np.sqrt(height ** 2 - a ** 2) + height ** 2 * np.arcsin(a / height)) / window
        self.assertAlmostEqual(stations[np.argmax(h)], centre, places=9)
        self.assertAlmostEqual(h.max(), crest, delta=2e-4)
        self.assertAlmostEqual(d["max_height_m"], h.max(), places=9)
        self.assertLess(h.max(), height - 0.01)
        # Area: the moving average keeps the sampled half-disc's, pi H^2 / 2 to the sampling error
        # at the vertical feet (0.23 mm^2 of 35 mm^2 here).
        self.assertAlmostEqual(h.sum() * dx / (np.pi * height ** 2 / 2), 1.0, delta=0.01)
        # Flat (exactly) from W/2 beyond the feet, a station more for round-off; raised within.
        distance = np.abs(stations - centre)
        self.assertTrue(np.all(h[distance > height + a + dx / 2] == 0.0))
        self.assertTrue(np.all(h[distance < height + a - dx / 2] > 0.0))

        # The file reads back and simulates like the built-in track (the same grid, exactly).
        out = self.path("half_round_10kmh.csv")
        common = ("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir",
                  self.cache)
        built_in = self.tvd_json(*common, "--track", "half_round:0.15", "--speed-kmh", "10",
                                 "--out", out)
        from_file = self.tvd_json(*common, "--track", track, "--speed-kmh", "10")
        for key in ("peak_hull_heave_m", "peak_hull_vertical_accel_m_s2", "peak_pitch_deg"):
            self.assertAlmostEqual(from_file[key] / built_in[key], 1.0, places=9, msg=key)
        self.assertEqual(input_warnings(built_in["warnings"]), [])
        self.assertEqual(built_in["track"], "half_round:0.15")
        # At rest on the flat until the front wheel (2.34 m ahead of the reference point) meets
        # the obstacle's foot; the peak while the wheels cross it; then it rings down on the 17 m
        # of flat after it, to a small fraction of the peak.
        header, rows = read_csv(out)
        c = {name: rows[:, i] for i, name in enumerate(header)}
        station, heave = c["station_m"], c["hull_heave_m"]
        accel = c["hull_vertical_accel_m_s2"]
        before = station + 2.34 < centre - height - a
        self.assertLess(np.abs(heave[before]).max(), 1e-6)
        self.assertLess(np.abs(accel[before]).max(), 1e-3)
        self.assertGreater(built_in["peak_hull_heave_m"], 0.01)
        self.assertGreater(heave.max(), 0.01)  # lifted, not only shaken
        peak_station = station[np.argmax(np.abs(accel))]
        self.assertTrue(centre - height - a - 2.34 <= peak_station <= centre + height + a + 2.34,
                        peak_station)
        end = station > station[-1] - 2.0
        self.assertLess(np.abs(heave[end]).max(), 0.02 * np.abs(heave).max())
        self.assertLess(np.abs(accel[end]).max(), 0.02 * np.abs(accel).max())
        # A fixed obstacle taken faster shakes the hull harder: peak hull acceleration at 5 and
        # 20 km/h (un-tracked 14 -> 25 m/s^2, tracked 7 -> 147 m/s^2).
        for variant in ("untracked", "tracked"):
            slow, fast = (self.tvd_json("simulate", "--vehicle", VEHICLE, "--variant", variant,
                                        "--track", "half_round:0.15", "--speed-kmh", speed,
                                        "--cache-dir", self.cache)
                          for speed in ("5", "20"))
            self.assertGreater(fast["peak_hull_vertical_accel_m_s2"],
                               1.5 * slow["peak_hull_vertical_accel_m_s2"], variant)

        # Bad specs: one message naming the spec, from terrain (its --track check) and simulate.
        for spec, fault in (("half_round:", "the obstacle height is missing"),
                            ("half_round:abc", "'abc' is not a number"),
                            ("half_round:0.2x", "'0.2x' is not a number"),
                            ("half_round:0", "must be in (0, 1] m, got 0"),
                            ("half_round:-0.1", "got -0.1"),
                            ("half_round:nan", "got nan"),
                            ("half_round:15", "got 15 (more than any vehicle's ground clearance")):
            self.assert_input_error(["terrain", "--track", spec, "--out", self.path("x.csv")],
                                    f"track '{spec}': ", fault)
            self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--variant", "untracked",
                                     "--track", spec, "--cache-dir", self.cache],
                                    f"simulate: --track: track '{spec}': ", fault)
        self.assert_input_error(["terrain", "--track", "moon", "--out", self.path("x.csv")],
                                "unknown track 'moon'", "long_hill", "half_round:H")
        # simulate's and ride's name the command and option too, for a missing file as well.
        for command in ("simulate", "ride"):
            self.assert_input_error([command, "--vehicle", VEHICLE, "--track", "half_round:15",
                                     "--cache-dir", self.cache],
                                    f"{command}: --track: track 'half_round:15': ")
            self.assert_input_error([command, "--vehicle", VEHICLE, "--track",
                                     self.path("missing.csv"), "--cache-dir", self.cache],
                                    f"{command}: --track: {self.path('missing.csv')}: file not found")

    def test_road_under_each_wheel_is_the_terrain_at_the_wheel(self):
        # The out-of-phase waves differ left and right and along the track: each column must be
        # the terrain file's height at its own wheel's (station + x_w, y_w), bilinear between the
        # file's samples, from its value at the start (0 on the flat entry). The CSV's 9
        # significant digits of station (up to 5e-8 m) times the waves' slope (up to 1.6) bound
        # the difference to 1e-7 m; a wheel misplaced by 1 mm would differ by up to 1.6 mm.
        track, out = self.path("oop_road.csv"), self.path("oop_run.csv")
        self.tvd("terrain", "--track", "oop_waves", "--out", track)
        y_lines, stations, heights = read_terrain_csv(track)
        self.tvd("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", track,
                 "--speed-kmh", "30", "--cache-dir", self.cache, "--out", out)
        header, rows = read_csv(out)
        column = {name: rows[:, i] for i, name in enumerate(header)}
        with open(VEHICLE) as f:
            gear = yaml.safe_load(f)["running_gear"]
        n, spacing = gear["axle_count"]["value"], gear["axle_spacing"]["value"]
        half_track = 0.5 * gear["track_centre_distance"]["value"]
        for side, y in (("left", half_track), ("right", -half_track)):
            # Between the file's two lines around y, then along the stations (held at the ends).
            j = np.searchsorted(y_lines, y) - 1
            w = (y - y_lines[j]) / (y_lines[j + 1] - y_lines[j])
            profile = (1 - w) * heights[:, j] + w * heights[:, j + 1]
            for k in range(1, n + 1):
                x = (0.5 * (n - 1) - (k - 1)) * spacing  # axle k, front first, centred on 0
                expected = np.interp(column["station_m"] + x, stations, profile) - profile[0]
                name = f"road_under_road_wheel_{side}_{k}_m"
                np.testing.assert_allclose(column[name], expected, rtol=0, atol=1e-7, err_msg=name)
        # Heights are taken from the start's: a level track 0.3 m up reads 0 under every wheel.
        raised, raised_out = self.path("raised_road.csv"), self.path("raised_run.csv")
        with open(raised, "w") as f:
            f.write("x,h\n-10,0.3\n400,0.3\n")
        self.tvd("simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", raised,
                 "--speed-kmh", "30", "--cache-dir", self.cache, "--out", raised_out)
        raised_header, raised_rows = read_csv(raised_out)
        under = [i for i, name in enumerate(raised_header) if name.startswith("road_under_")]
        self.assertEqual(len(under), 14)
        self.assertEqual(np.abs(raised_rows[:, under]).max(), 0.0)
        # The track is not the same left and right, so the test above is not one line twice.
        self.assertGreater(np.abs(column["road_under_road_wheel_left_1_m"]
                                  - column["road_under_road_wheel_right_1_m"]).max(), 0.1)
        # The wheel stands on its road: at 30 km/h the un-tracked front wheel follows the road
        # under it to within its pad's compliance and the waves' curvature, not a wave height.
        self.assertLess(np.abs(column["road_wheel_left_1_m"]
                               - column["road_under_road_wheel_left_1_m"]).max(), 0.15)

    def test_model_statics_under_gravity_match_the_closed_form(self):
        # config/models/cantilever_beam.yaml: m_t g L^3/(3 EI) + rho A g L^4/(8 EI) = 2.54214 mm
        # at the tip (node 21, down); the gravity key is what loads it.
        model = os.path.join(ROOT, "config", "models", "cantilever_beam.yaml")
        result = self.tvd_json("modes", "--model", model, "--count", "2")
        self.assertTrue(result["static"]["solved"])
        self.assertEqual(result["static"]["at"], "node 21 uz")
        self.assertAlmostEqual(result["static"]["max_translation_m"] * 1e3, 2.54214, delta=2e-5)
        # The same beam along y bends about x: its tip rotation rx (3.58e-3 rad) is larger than
        # its deflection in m and must not be taken for the largest translation.
        along_y = self.path("cantilever_along_y.yaml")
        with open(model) as f, open(along_y, "w") as g:
            g.write(re.sub(r"x: \[([0-9.e+-]+), 0, 0\]", r"x: [0, \1, 0]", f.read()))
        with open(along_y) as f:
            self.assertIn("{id: 21, x: [0, 1, 0]}", f.read())
        turned = self.tvd_json("modes", "--model", along_y, "--count", "2")
        self.assertEqual(turned["static"]["at"], "node 21 uz")
        self.assertAlmostEqual(turned["static"]["max_translation_m"],
                               result["static"]["max_translation_m"], delta=1e-12)
        # The text gives the same number in mm.
        text = self.tvd("modes", "--model", model, "--count", "2").stdout
        self.assertIn(f"largest translation {result['static']['max_translation_m'] * 1e3:.6f} mm "
                      f"at node 21 uz", text)
        # Without gravity there is nothing to solve, and the report says so.
        weightless = self.path("weightless.yaml")
        with open(model) as f, open(weightless, "w") as g:
            g.write(f.read().replace("gravity: [0, 0, -9.80665]", "gravity: [0, 0, 0]"))
        result = self.tvd_json("modes", "--model", weightless, "--count", "2")
        self.assertFalse(result["static"]["solved"])
        self.assertEqual(result["static"]["note"], "no gravity load")

    def test_massless_motion_through_an_offset_mass_is_named(self):
        # Every diagonal of M is positive, yet M is singular: a point mass on an offset without
        # rotary inertia leaves a rotation without inertia. It used to print modes at 11 and
        # 16 Hz that do not exist, and NaN shapes, with exit 0.
        # A skewed offset leaves a pivot that is not exactly 0 but rounding (1e-12 of the
        # largest): refused too, not 6 modes that do not exist.
        for name, mass, offset, parts in (
                ("offset_mass", "1", "[0.1, 0.1, 0]",
                 ("the mass matrix is singular", "has no mass or inertia")),
                ("skewed_offset_mass", "1.7", "[0.3, -0.7, 0.11]", ("the mass matrix is singular",))):
            model = self.path(name + ".yaml")
            with open(model, "w") as f:
                f.write("nodes:\n  - {id: 1, x: [0, 0, 0]}\n"
                        f"masses:\n  - {{node: 1, mass: {mass}, offset: {offset}}}\n"
                        "springs:\n  - {nodes: [1, ground], k: [100, 100, 100, 0, 0, 0]}\n")
            self.assert_input_error(["modes", "--model", model], name + ".yaml", *parts)

    def test_free_dof_without_mass_is_named(self):
        model = self.path("no_mass.yaml")
        with open(model, "w") as f:
            f.write("nodes:\n  - {id: 1, x: [0, 0, 0]}\nsprings:\n  - {nodes: [1, ground], kz: 1e4}\n")
        self.assert_input_error(["modes", "--model", model], "no_mass.yaml", "node 1 uz",
                                "is free but has no mass or inertia")

    def test_eigenvalues_beyond_double_range_are_a_solver_error_with_a_hint(self):
        # A pad of 1e-300 kg passes the description's checks (positive) but puts eigenvalues
        # beyond double range: Spectra's "TridiagEigen" failure, once status 1 with no context.
        vehicle = self.vehicle_with("tiny_pad.yaml", "pad_mass: {value: 1.5,",
                                    "pad_mass: {value: 1e-300,")
        result = self.tvd("modes", "--vehicle", vehicle, "--count", "5", status=3)
        self.assertEqual(result.stdout, "")
        self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
        self.assertIn("tvd: solver error: modal solver (shift-invert Lanczos): ", result.stderr)
        self.assertIn("orders of magnitude", result.stderr)

    # --- acceptance findings (findings.md #2-#12) ---

    def run_limited(self, args, max_bytes):
        """tvd with a file-size limit of `max_bytes` (a full disk: writes past it fail with EFBIG,
        SIGXFSZ ignored)."""
        import resource
        import signal

        def limit():
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (max_bytes, max_bytes))
        return subprocess.run([TVD, *args], capture_output=True, text=True, timeout=240,
                              preexec_fn=limit)

    def test_modes_max_frequency_returns_every_mode_below(self):
        """modes --model --max-frequency F: every mode below F (not the default --count's 20);
        a --count given caps them, with a warning naming the Sylvester count below F."""
        model = os.path.join(ROOT, "config", "models", "cantilever_beam.yaml")
        limit = 20000.0
        everything = self.tvd_json("modes", "--model", model, "--count", "500")["frequencies_hz"]
        below = [f for f in everything if f < limit]
        self.assertGreater(len(below), 20)
        self.assertLess(len(below), len(everything))
        d = self.tvd_json("modes", "--model", model, "--max-frequency", repr(limit))
        self.assertEqual(len(d["frequencies_hz"]), len(below))
        for f, g in zip(d["frequencies_hz"], below):
            self.assertAlmostEqual(f / g, 1.0, delta=1e-9)
        self.assertEqual(d["warnings"], [])
        capped = self.tvd_json("modes", "--model", model, "--max-frequency", repr(limit),
                               "--count", "5")
        self.assertEqual(len(capped["frequencies_hz"]), 5)
        self.assertEqual(capped["warnings"],
                         [f"{len(below)} modes lie below 20000 Hz: the lowest 5 are returned "
                          "(--count 5; raise it, at most 500)"])

    def test_output_files_are_written_whole_or_not_at_all(self):
        """#2: a CSV through a symlink to /dev/full is replaced by the whole file (as a .mat);
        a write that fails exits non-zero naming the file and leaves none of the command's
        files, nor a temporary one."""
        model = os.path.join(ROOT, "config", "models", "cantilever_beam.yaml")
        d = self.path("full_disk")
        os.makedirs(d)
        for name in ("modes.csv", "shapes.csv"):
            os.symlink("/dev/full", os.path.join(d, name))
        self.tvd("modes", "--model", model, "--out", d)
        for name in ("modes.csv", "shapes.csv"):
            path = os.path.join(d, name)
            self.assertFalse(os.path.islink(path))
            with open(path) as f:
                self.assertGreater(len(f.read().splitlines()), 1, name)
        # modes.csv (< 2 kB) fits under the limit, shapes.csv does not.
        d = self.path("limited")
        os.makedirs(d)
        r = self.run_limited(["modes", "--model", model, "--out", d], 2000)
        self.assertEqual(r.returncode, INPUT_ERROR_STATUS, r.stderr)
        self.assertIn("shapes.csv", r.stderr)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        self.assertEqual(os.listdir(d), [])
        # Into the directory of a good earlier run: a failed write leaves its files as they were
        # (not deleted, not a mix of old and new).
        self.tvd("modes", "--model", model, "--out", d)
        before = {}
        for name in sorted(os.listdir(d)):
            with open(os.path.join(d, name), "rb") as f:
                before[name] = f.read()
        self.assertEqual(sorted(before), ["modes.csv", "modes.mat", "shapes.csv"])
        r = self.run_limited(["modes", "--model", model, "--count", "3", "--out", d], 2000)
        self.assertEqual(r.returncode, INPUT_ERROR_STATUS, r.stderr)
        self.assertIn(os.path.join(d, "shapes.csv") + ":", r.stderr)
        self.assertNotIn("~", r.stderr)  # the staged name, "shapes~Ab3xYz.csv", is not shown
        after = {}
        for name in sorted(os.listdir(d)):
            with open(os.path.join(d, name), "rb") as f:
                after[name] = f.read()
        self.assertEqual(after, before)
        # mac --out: mac.mat is written first; when mac.csv cannot be, mac.mat goes too.
        d = self.path("mac_fails")
        os.makedirs(os.path.join(d, "mac.csv"))  # a directory: the rename onto it fails
        r = self.tvd("mac", "--vehicle", VEHICLE, "--out", d, status=INPUT_ERROR_STATUS)
        self.assertIn("mac.csv", r.stderr)
        self.assertEqual(os.listdir(d), ["mac.csv"])
        # writeTable's CSV (simulate --out): nothing under the name when it fails.
        out = self.path("limited_sim.csv")
        r = self.run_limited(["simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                              "long_hill", "--cache-dir", self.cache, "--out", out], 1 << 20)
        self.assertEqual(r.returncode, INPUT_ERROR_STATUS, r.stderr)
        self.assertIn("limited_sim.csv", r.stderr)
        self.assertEqual([f for f in os.listdir(self.work) if f.startswith("limited_sim")], [])

    def test_global_modes_limit_is_named(self):
        """#3: --global-modes above 200 takes minutes; refused with the limit and why."""
        for command in ("reduce", "frf", "simulate"):
            args = [command, "--vehicle", VEHICLE, "--global-modes", "201"]
            if command == "simulate":
                args += ["--track", "long_hill"]
            r = self.tvd(*args, status=INPUT_ERROR_STATUS)
            self.assertIn("[1, 200], got 201", r.stderr)
            self.assertIn("minutes", r.stderr)
            self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)

    def test_options_without_effect_are_refused(self):
        """#4: README: an option that would be ignored is refused."""
        model = self.path("ignored.mat")
        self.tvd("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--rule", "band",
                 "--out", model)
        sim = ["simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", "long_hill"]
        self.assert_input_error(sim + ["--reduced", model, "--cache-dir", self.cache],
                                "--cache-dir is not used with --reduced")
        self.assert_input_error(sim + ["--model", "full", "--ground-contact", "on"],
                                "--ground-contact applies to --model reduced only")
        self.assert_input_error(["modes", "--vehicle", VEHICLE, "--out", ""],
                                "--out", "must name a directory")
        # An empty --cache-dir is no directory (it silently meant the default cache).
        self.assert_input_error(sim + ["--cache-dir", ""], "--cache-dir", "must name a directory")
        chain = os.path.join(ROOT, "config", "models", "spring_mass_chain.yaml")
        self.assert_input_error(["modes", "--model", chain, "--max-frequency", "0"],
                                "--max-frequency", "must be a positive number")
        ride = ["ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track", "half_round:0.1",
                "--cache-dir", self.cache]
        frf = ["frf", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", self.cache]
        for command in (ride, frf):
            for points in ("", "crew_seat,", ",crew_seat", "crew_seat,,sensor_mount"):
                self.assert_input_error(command + ["--points", points],
                                        "--points: an empty name in '" + points + "'")

    def test_frf_grid_has_two_frequencies_and_ends_at_max(self):
        """#5: step > max is refused; a max that is not a multiple of the step is the last point."""
        frf = ["frf", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", self.cache]
        self.assert_input_error(frf + ["--step-hz", "100"],
                                "--step-hz 100 is larger than --max-hz 50", "at least 2 frequencies")
        out = self.path("grid.csv")
        self.tvd(*frf, "--max-hz", "1", "--step-hz", "0.07", "--out", out)
        header, body = read_csv(out)
        hz = body[:, header.index("frequency_hz")]
        self.assertEqual(len(hz), 16)
        self.assertAlmostEqual(hz[-2], 0.98, places=12)
        self.assertEqual(hz[-1], 1.0)
        # A last multiple a hair below max is max itself, not a second point beside it.
        self.tvd(*frf, "--max-hz", "1", "--step-hz", "0.3333333", "--out", out)
        header, body = read_csv(out)
        hz = body[:, header.index("frequency_hz")]
        self.assertEqual(len(hz), 4)
        self.assertEqual(hz[-1], 1.0)
        self.assertAlmostEqual(hz[-2], 0.6666666, places=12)

    def test_lateral_offset_off_a_built_in_track(self):
        """#6: an offset that puts contacts beyond a built-in track's edge is warned about (how
        many, how far); one that puts every contact off it is refused."""
        sim = ["simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", self.cache,
               "--track"]
        r = self.tvd(*sim, "long_hill", "--lateral-offset", "2", "--json")
        warnings = input_warnings(json.loads(r.stdout)["warnings"])
        self.assertEqual(len(warnings), 1, warnings)
        self.assertRegex(warnings[0], r"\d+ of \d+ contacts lie outside, up to [0-9.]+ m beyond")
        self.assertIn("--lateral-offset 2 m", warnings[0])
        self.assertIn("tvd: warning: " + warnings[0], r.stderr)
        # oop_waves' own driving line leaves 5.5 cm of the left outer row beyond its edge (as in
        # the paper): not warned about, nor an offset that reduces it; one that adds to it is.
        for offset, warned in (("0", False), ("-0.01", False), ("0.01", True)):
            d = self.tvd_json(*sim, "oop_waves", "--speed-kmh", "30", "--lateral-offset", offset)
            self.assertEqual(len(input_warnings(d["warnings"])), 1 if warned else 0,
                             (offset, d["warnings"]))
        self.assert_input_error(sim + ["oop_waves", "--lateral-offset", "10"],
                                "oop_waves: every contact", "lies off the terrain",
                                "--lateral-offset 10 m")
        self.assert_input_error(sim + ["long_hill", "--lateral-offset", "1e6"],
                                "long_hill: every contact")
        # Refused from the description's pad rows before the model is obtained: nothing is
        # reduced into an empty cache, by simulate or by ride, for either variant.
        empty = self.path("cache_never_filled")
        for command, variant in (("simulate", "tracked"), ("ride", "untracked")):
            self.assert_input_error(
                [command, "--vehicle", VEHICLE, "--variant", variant, "--cache-dir", empty,
                 "--track", "long_hill", "--lateral-offset", "-4.1"],
                "long_hill: every contact (the 4 pad rows) lies off the terrain",
                "y = -5.655 .. -2.545 m", "only -2.5 .. 2.5 m")
        self.assertFalse(os.path.exists(empty) and os.listdir(empty), "a model was reduced")

    def test_unusable_cache_is_reported(self):
        """#9: a --cache-dir that is a file gives one warning; a corrupt cache file is rebuilt
        with a note."""
        bad = self.path("cache_is_a_file")
        with open(bad, "w") as f:
            f.write("not a directory\n")
        base = ["frf", "--vehicle", VEHICLE, "--variant", "untracked", "--rule", "band",
                "--max-hz", "5", "--json"]
        r = self.tvd(*base, "--cache-dir", bad)
        reduction = json.loads(r.stdout)["reduction"]
        self.assertEqual(len(reduction["warnings"]), 1, reduction)
        self.assertIn("the reduced-model cache is not used", reduction["warnings"][0])
        # Named by the option, not as "filesystem error: cannot create directories".
        self.assertIn("--cache-dir " + bad + " is a file, not a directory",
                      reduction["warnings"][0])
        self.assertNotIn("filesystem error", r.stderr)
        self.assertEqual(r.stderr.count("tvd: warning: the reduced-model cache is not used"), 1)
        cache = self.path("corrupt_cache")
        first = json.loads(self.tvd(*base, "--cache-dir", cache).stdout)["reduction"]
        self.assertEqual(first["notes"], [])
        with open(first["file"], "r+b") as f:
            f.seek(200)
            f.write(b"\x00" * 64)
        r = self.tvd(*base, "--cache-dir", cache)
        again = json.loads(r.stdout)["reduction"]
        self.assertEqual(again["source"], "computed")
        self.assertEqual(len(again["notes"]), 1, again)
        self.assertIn("rebuilt", again["notes"][0])
        self.assertIn("tvd: note: rebuilt", r.stderr)

    def test_messages_name_what_is_wrong(self):
        """#10: unknown subcommand, a .mat that is not a reduced model, ranges as accepted, one
        line with the tvd: error: prefix for option checks."""
        # With --help or --version after it too (CLI11 answers those first): not the program's
        # help and status 0 for a misspelt command.
        for extra in ((), ("--help",), ("--version",)):
            r = self.tvd("foo", *extra, status=INPUT_ERROR_STATUS)
            self.assertIn("tvd: error: unknown subcommand 'foo' (one of: modes,", r.stderr)
            self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
            self.assertEqual(r.stdout, "")
        self.assertIn("Usage:", self.tvd("reduce", "--help").stdout)
        self.assertIn("Usage:", self.tvd("--help").stdout)
        r = self.tvd("simulate", "--vehicle", VEHICLE, "--track", "long_hill", "--dt", "0",
                     status=INPUT_ERROR_STATUS)
        self.assertTrue(r.stderr.startswith("tvd: error: "), r.stderr)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        # CLI11's own errors, in the user's words: a misspelt option is named (not "--vehicle
        # is required", which CLI11 checks first), with the nearest spelling.
        for args, expected in (
                (["simulate", "--trak", "long_hill"],
                 "tvd: error: simulate: unknown option --trak (did you mean --track?)"),
                # Two edits away (two letters swapped): still named.
                (["simulate", "--tarck", "long_hill"],
                 "tvd: error: simulate: unknown option --tarck (did you mean --track?)"),
                (["simulate", "--vehicle", VEHICLE, "--track=long_hill", "--speed", "5"],
                 "tvd: error: simulate: unknown option --speed (did you mean --speed-kmh?)"),
                (["modes", "--vehicle", VEHICLE, "--frobnicate"],
                 "tvd: error: modes: unknown option --frobnicate (tvd modes --help lists"),
                (["simulate", "--vehicle", VEHICLE, "--track", "long_hill", "--speed-kmh", "abc"],
                 "tvd: error: simulate: --speed-kmh: 'abc' is not a number"),
                (["modes", "--vehicle", VEHICLE, "--count"],
                 "tvd: error: modes: --count needs an integer after it"),
                (["modes", "--vehicle", VEHICLE, "--count", "1.5"],
                 "tvd: error: modes: --count: '1.5' is not an integer"),
                (["modes", "--vehicle", VEHICLE, "--count=0"],
                 "tvd: error: modes: --count: Value 0 not in range 1 to 500"),
                (["--frob"], "tvd: error: unknown option --frob: a subcommand is required (one "
                             "of: modes, statics,"),
                # Dashes only: nothing to compare with the options (it aborted the program).
                (["modes", "---"], "tvd: error: modes: unknown option --- (tvd modes --help"),
                (["modes", "-=3"], "tvd: error: modes: unknown option - (tvd modes --help"),
                (["simulate", "--vehicle", VEHICLE, "--track", "long_hill", "--speed-kmh", "5",
                  "--speed-kmh", "6"],
                 "tvd: error: simulate: --speed-kmh is given 2 times: give it once"),
                (["simulate", "--vehicle", VEHICLE, "--track", "long_hill", "stray"],
                 "tvd: error: simulate: unexpected argument 'stray': every value follows its"),
                # Several, named as given and each whole (CLI11 lists them reversed, joined).
                (["simulate", "--vehicle", VEHICLE, "--track", "long_hill", "[--model", "full]",
                  "two words"],
                 "tvd: error: simulate: unexpected arguments '[--model', 'full]', 'two words': ")):
            r = self.tvd(*args, status=INPUT_ERROR_STATUS)
            self.assertTrue(r.stderr.startswith(expected), (args, r.stderr))
            self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        # A negative number is a value, not an unknown option.
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--track", "long_hill",
                                 "--speed-kmh", "-5"], "--speed-kmh")
        r = self.tvd("simulate", "--vehicle", VEHICLE, "--track", "long_hill", "--speed-kmh",
                     "-5", status=INPUT_ERROR_STATUS)
        self.assertNotIn("unknown option", r.stderr)
        frf_mat = self.path("not_reduced.mat")
        self.tvd("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--cache-dir", self.cache,
                 "--max-hz", "2", "--out", frf_mat)
        self.assert_input_error(["simulate", "--vehicle", VEHICLE, "--track", "long_hill",
                                 "--reduced", frf_mat], "not a reduced model file")
        for threshold in ("0", "1.1"):
            self.assert_input_error(["mac", "--vehicle", VEHICLE, "--threshold", threshold],
                                    "--threshold", "must be a number in (0, 1]")
        self.assertIn("in (0, 1]", self.tvd("mac", "--help").stdout)
        for hz in ("0", "200"):
            self.assert_input_error(["frf", "--vehicle", VEHICLE, "--model", "full",
                                     "--max-mode-hz", hz], "must be a number in (0, 100] Hz")
        r = self.tvd("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--rule", "band",
                     "--band", "0.1", status=INPUT_ERROR_STATUS)
        self.assertIn("no global mode selected below 0.1 Hz", r.stderr)
        self.assertNotIn("MAC threshold", r.stderr)

    def test_cut_eigenspace_is_warned(self):
        """#1: a --global-modes count that cuts an eigenspace the MAC selection uses is warned
        about, with the counts that would not cut it; one of track-local modes is not."""
        # The default 40 cut the un-tracked 12-fold eigenspace at 107.72 Hz after 6 modes: modes
        # of the assemblies alone, with no energy in the hull and running gear, so no MAC
        # reference: no warning, and the tracked selection is the one at 46 (whose own warning
        # is below) and names no such mode.
        default = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "tracked")
        self.assertEqual(default["reduction"]["warnings"], [])
        self.assertEqual(default["mac_reference_modes"], 20)  # the 6 hull and 14 wheel modes
        for m in default["selected_modes"]:
            self.assertNotIn("(108 Hz)", m["reason"])
        wider = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", "tracked",
                              "--global-modes", "46")
        self.assertEqual([m["mode"] for m in wider["selected_modes"]],
                         [m["mode"] for m in default["selected_modes"]])
        # At 46 one Lanczos run returned 11 of the 12 (and the next mode), which was warned
        # about; the solver's Sylvester count now finds the 12th, and 46 ends the group: nothing
        # to say, and the 46 un-tracked modes hold all 12.
        self.assertEqual(wider["reduction"]["warnings"], [])
        modes46 = self.tvd_json("modes", "--vehicle", VEHICLE, "--variant", "untracked",
                                "--count", "46")["frequencies_hz"]
        self.assertEqual(sum(abs(f - modes46[-1]) < 1e-6 * f for f in modes46), 12)
        # 10 cut the un-tracked wheels' 11-fold bounce eigenspace at 18.56 Hz after 4: the
        # un-tracked reduction selects from it (in the band) and the tracked one compares with it.
        for variant in ("tracked", "untracked"):  # the un-tracked warnings are kept below
            d = self.tvd_json("reduce", "--vehicle", VEHICLE, "--variant", variant,
                              "--global-modes", "10")
            warnings = d["reduction"]["warnings"]
            self.assertIn("global_modes 10: cuts a repeated eigenvalue of the untracked variant: "
                          "4 of its 11 modes at 18.5568 Hz", warnings[0])
            self.assertIn("6 global modes end below it, 17 above it if the solver returns all 11",
                          warnings[0])
        # Saved with the model: a --reduced file and a cached model warn again, as the run that
        # reduced them did (the cache's second run loads the model the first one built).
        mat = self.path("cut_eigenspace.mat")
        self.tvd("reduce", "--vehicle", VEHICLE, "--variant", "untracked", "--global-modes", "10",
                 "--out", mat)
        cache = self.path("cut_eigenspace_cache")
        cached = ("--cache-dir", cache, "--global-modes", "10")
        for args, source in ((("--reduced", mat), "file"), (cached, "computed"),
                             (cached, "cache")):
            r = self.tvd("frf", "--vehicle", VEHICLE, "--variant", "untracked", "--max-hz", "5",
                         *args, "--json")
            reduction = json.loads(r.stdout)["reduction"]
            self.assertEqual(reduction["source"], source)
            self.assertEqual(reduction["warnings"], warnings, source)
            self.assertIn("tvd: warning: global_modes 10: cuts a repeated eigenvalue", r.stderr)

    def test_poisson_ratio_and_speed_range_are_checked(self):
        """#12: a Poisson ratio outside (-1, 0.5] is refused naming the key; a --speeds range
        whose step does not land on LAST is refused."""
        nu = self.vehicle_with("nu.yaml", "steel_poisson_ratio: {value: 0.29",
                               "steel_poisson_ratio: {value: 0.6")
        self.assert_input_error(["modes", "--vehicle", nu], "steel_poisson_ratio",
                                "(-1, 0.5], got 0.6")
        self.assert_input_error(["ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                                 "half_round:0.1", "--speeds", "5:7:3"],
                                "--speeds '5:7:3'", "does not land on LAST 7")

    def test_documented_ranges_are_refused_at_their_bounds(self):
        """The ranges the help texts give, refused just outside each bound and named: simulate's
        speed in (0, 200] km/h (0 would never leave the start), frf's 0 (synchronous) or in
        [0.01, 200], mac's count in 1 .. 200, ride's step in [1e-4, 2e-3] s."""
        sim = ["simulate", "--vehicle", VEHICLE, "--variant", "untracked", "--track", "long_hill"]
        for value in ("0", "200.1"):
            self.assert_input_error(sim + ["--speed-kmh", value],
                                    "simulate: --speed-kmh must be in (0, 200], got " + value)
        # Above 0 and below 0.01 km/h: 1e-308 once read as an infinite delay ("an undamped mode
        # lies on the grid"), 1e-300 as another FRF.
        for value in ("-0.1", "200.1", "1e-308", "1e-300", "0.0099"):
            self.assert_input_error(["frf", "--vehicle", VEHICLE, "--variant", "untracked",
                                     "--speed-kmh", value],
                                    "frf: --speed-kmh must be 0 (synchronous) or in [0.01, 200], "
                                    "got " + value)
        for value in ("0", "201"):
            self.assert_input_error(["mac", "--vehicle", VEHICLE, "--count", value],
                                    "mac: --count", value + " not in range 1 to 200")
        for value in ("9e-05", "0.0021"):
            self.assert_input_error(["ride", "--vehicle", VEHICLE, "--variant", "untracked",
                                     "--track", "long_hill", "--speeds", "10", "--dt", value],
                                    "ride: --dt: must be a number in [0.0001, 0.002] s, got " + value)

    def test_text_output_fits_the_run(self):
        """#11: the un-tracked statics do not mention chain links; one ride run is '1 run'."""
        text = self.tvd("statics", "--vehicle", VEHICLE, "--variant", "untracked").stdout
        self.assertIn("contacts: unilateral (pads on the road push but cannot pull)", text)
        self.assertNotIn("sprockets", text)
        text = self.tvd("ride", "--vehicle", VEHICLE, "--variant", "untracked", "--track",
                        "half_round:0.1", "--speeds", "10", "--cache-dir", self.cache).stdout
        self.assertIn("  1 run, ", text)


if __name__ == "__main__":
    sys.exit(junit_runner.main(TvdCliTest, "tvd_cli", __doc__,
                               paths={"--tvd": "path of the built tvd executable"}))
