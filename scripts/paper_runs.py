"""The `tvd` runs behind scripts/paper_report.py: every analysis of the paper's Sections 3-4 on one
vehicle description, each written to its own file in the report directory and its JSON kept.

One concern: running `tvd` and knowing where each result lies. The tables (paper_tables.py) and
the figures (paper_figures.py) only read what these runs wrote.
"""
import json
import os
import subprocess

import yaml

VARIANTS = ("untracked", "tracked")
TRACKS = ("long_hill", "separated_waves", "oop_waves")
FRF_SPEEDS_KMH = (10, 30, 50)  # Figs. 15-16
TRACKED_SPEEDS_KMH = (10, 30, 50)  # Figs. 23-24
COUPLING_SPEED_KMH = 30  # §4.2.3, Figs. 20-22
MOR_SPEEDS_KMH = (5, 50)  # §4.2.2, Figs. 18-19
MODE_COUNT = {"untracked": 20, "tracked": 40}  # Table 4 lists UV modes up to 20, TV up to 40
MAC_COUNT = 40
# How far damping (which the paper does not give) moves the §4.2.2 magnitudes: the description's
# `damping` replaced by each of these, un-tracked long hill at MOR_SPEEDS_KMH.
DAMPING_VARIANTS = (("modal_2", {"model": "modal", "modal_ratio": 0.02}),
                    ("modal_1", {"model": "modal", "modal_ratio": 0.01}),
                    ("rayleigh_0.002", {"model": "rayleigh", "rayleigh_alpha": 0.0,
                                        "rayleigh_beta": 0.002}),
                    ("rayleigh_0.005", {"model": "rayleigh", "rayleigh_alpha": 0.0,
                                        "rayleigh_beta": 0.005}))


class RunError(Exception):
    """A `tvd` run failed: the command and the last line it printed on stderr."""


def _speed_name(speed_kmh):
    return "sync" if not speed_kmh else f"{speed_kmh:g}kmh"


class Runs:
    """Runs `tvd` into `out_dir` and remembers each run's JSON. `tvd reduce` writes the reduced
    models of the report (Table 5, Fig. 12); the FRF and simulation runs share a cache in
    out_dir/cache, where each description (a damping variant is one) is reduced once."""

    def __init__(self, tvd, vehicle, out_dir, log=print):
        self.tvd = tvd
        self.vehicle = vehicle
        self.out = out_dir
        self.cache = os.path.join(out_dir, "cache")
        self.log = log
        self.modes = {}
        self.reduce = {}
        self.mac = None
        self.frf = {}  # (variant, model, speed_kmh or 0) -> {"json": ..., "csv": path}
        self.sim = {}  # (variant, model, track, speed_kmh) -> {"json": ..., "csv": path}
        self.damping = {}  # (variant name, speed_kmh) -> simulate JSON
        self.commands = []  # every command run, as typed

    def path(self, *parts):
        return os.path.join(self.out, *parts)

    def _run(self, command, *args, vehicle=None):
        """`tvd COMMAND --vehicle V ARGS --json`; vehicle None: the report's, False: none."""
        vehicle = self.vehicle if vehicle is None else vehicle
        argv = [self.tvd, command, *(["--vehicle", vehicle] if vehicle else []),
                *map(str, args), "--json"]
        self.commands.append("tvd " + " ".join(argv[1:]))
        self.log(self.commands[-1])
        try:
            result = subprocess.run(argv, capture_output=True, text=True, timeout=600)
        except OSError as error:
            raise RunError(f"cannot run {self.tvd}: {error.strerror}") from None
        if result.returncode != 0:
            last = (result.stderr.strip().splitlines() or ["(no message)"])[-1]
            raise RunError(f"`tvd {' '.join(argv[1:])}` failed (status {result.returncode}): {last}")
        try:
            return json.loads(result.stdout)
        except json.JSONDecodeError:
            raise RunError(f"`tvd {' '.join(argv[1:])}` did not print JSON") from None

    def run_modes(self):
        for v in VARIANTS:
            self.modes[v] = self._run("modes", "--variant", v, "--count", MODE_COUNT[v],
                                      "--out", self.path(f"modes_{v}"))

    def run_mac(self):
        self.mac = self._run("mac", "--count", MAC_COUNT, "--out", self.path("mac"))

    def run_reduce(self):
        for v in VARIANTS:
            self.reduce[v] = self._run("reduce", "--variant", v, "--out",
                                       self.path(f"reduced_{v}.mat"))

    def frf_csv(self, variant, model, speed_kmh=0):
        return self.path("frf", f"{variant}_{model}_{_speed_name(speed_kmh)}.csv")

    def run_frf(self):
        os.makedirs(self.path("frf"), exist_ok=True)
        for v in VARIANTS:
            cases = [("full", 0), ("full", COUPLING_SPEED_KMH), ("reduced", 0)]
            cases += [("reduced", s) for s in FRF_SPEEDS_KMH]
            for model, speed in cases:
                csv = self.frf_csv(v, model, speed)
                args = ["--variant", v, "--model", model, "--out", csv]
                if model == "reduced":  # tvd refuses --cache-dir with --model full
                    args += ["--cache-dir", self.cache]
                if speed:
                    args += ["--speed-kmh", speed]
                self.frf[(v, model, speed)] = {"json": self._run("frf", *args), "csv": csv}

    def sim_csv(self, variant, model, track, speed_kmh):
        return self.path("simulate", f"{variant}_{model}_{track}_{speed_kmh:g}kmh.csv")

    def simulation_cases(self):
        cases = {("untracked", m, "long_hill", s) for m in ("full", "reduced") for s in MOR_SPEEDS_KMH}
        cases |= {(v, "reduced", t, COUPLING_SPEED_KMH) for v in VARIANTS for t in TRACKS}
        cases |= {("tracked", "reduced", t, s) for t in ("long_hill", "separated_waves")
                  for s in TRACKED_SPEEDS_KMH}
        return sorted(cases)

    def run_simulations(self):
        os.makedirs(self.path("simulate"), exist_ok=True)
        for case in self.simulation_cases():
            v, model, track, speed = case
            csv = self.sim_csv(*case)
            cache = ["--cache-dir", self.cache] if model == "reduced" else []
            self.sim[case] = {"json": self._run("simulate", "--variant", v, "--model", model,
                                                "--track", track, "--speed-kmh", speed,
                                                *cache, "--out", csv),
                              "csv": csv}

    def terrain_csv(self, track):
        return self.path("terrain", f"{track}.csv")

    def run_terrains(self):
        os.makedirs(self.path("terrain"), exist_ok=True)
        for track in TRACKS:
            self._run("terrain", "--track", track, "--out", self.terrain_csv(track), vehicle=False)

    def _description(self):
        """The description as YAML data."""
        try:
            with open(self.vehicle, encoding="utf-8") as stream:
                return yaml.safe_load(stream)
        except (OSError, yaml.YAMLError) as error:
            raise RunError(f"{self.vehicle}: cannot read it ({error})") from None

    def damping_description(self, name, values):
        """A copy of the description with its `damping` values replaced, in out/damping/."""
        description = self._description()
        try:
            for key, value in values.items():
                description["damping"][key]["value"] = value
        except (KeyError, TypeError) as error:
            raise RunError(f"{self.vehicle}: cannot vary its damping ({error})") from None
        path = self.path("damping", f"{name}.yaml")
        with open(path, "w", encoding="utf-8") as stream:
            yaml.safe_dump(description, stream, sort_keys=False, allow_unicode=True)
        return path

    def description_damping(self):
        """The description's own damping values {key: value}."""
        try:
            return {key: item["value"] for key, item in self._description()["damping"].items()}
        except (KeyError, TypeError, AttributeError) as error:
            raise RunError(f"{self.vehicle}: cannot read its damping ({error})") from None

    def run_damping(self):
        os.makedirs(self.path("damping"), exist_ok=True)
        for name, values in DAMPING_VARIANTS:
            vehicle = self.damping_description(name, values)
            for speed in MOR_SPEEDS_KMH:
                self.damping[(name, speed)] = self._run(
                    "simulate", "--variant", "untracked", "--track", "long_hill", "--speed-kmh",
                    speed, "--cache-dir", self.cache,
                    "--out", self.path("damping", f"{name}_long_hill_{speed}kmh.csv"),
                    vehicle=vehicle)

    def run_all(self):
        self.run_modes()
        self.run_terrains()
        self.run_mac()
        self.run_reduce()
        self.run_frf()
        self.run_simulations()
        self.run_damping()
        return self
