"""The side-by-side tables of scripts/paper_report.py: the paper's figures
(config/paper_reference.yaml) against what the `tvd` runs of paper_runs.py produced.

Each table is a `Section`: a name (the README marker), Markdown text, and the numbers behind it for
report.json. Nothing here runs `tvd`; every number is read from the runs' JSON and CSV files.
"""
import math

import numpy as np

from paper_runs import (COUPLING_SPEED_KMH, DAMPING_VARIANTS, FRF_SPEEDS_KMH, MOR_SPEEDS_KMH,
                        TRACKED_SPEEDS_KMH)
from plot_common import Table

HULL_MOTIONS = ("longitudinal", "lateral", "bounce", "roll", "pitch", "yaw")
WHEEL = "wheel bounce"
FRF_OUTPUTS = (("hull_vertical_acc", "hull vertical"), ("hull_pitch_acc", "hull pitch"),
               ("front_wheel_acc", "front wheel"), ("rear_wheel_acc", "rear wheel"))
MINUS = "\u2212"


class Section:
    def __init__(self, name, title, markdown, data):
        self.name, self.title, self.markdown, self.data = name, title, markdown, data

    @property
    def summary(self):
        """The paragraph after the table (the counts of what is met), or ''."""
        tail = self.markdown.rsplit("\n\n", 1)
        return tail[1] if len(tail) == 2 and not tail[1].startswith("|") else ""


def signed(x, digits=1):
    """'+2.6 %'-style numbers with a true minus sign, as the README writes them."""
    text = f"{x:+.{digits}f}"
    return text.replace("-", MINUS)


def percent(ours, paper):
    return signed(100.0 * (ours - paper) / paper) + " %"


def markdown_table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


# --- Table 4: mode types ------------------------------------------------------------------------

def kind(label):
    """'wheel', 'hull' or 'track' from a mode label of `tvd modes` (mode_classification.h)."""
    if label.startswith(WHEEL):
        return "wheel"
    return "hull" if label.split("+")[0] in HULL_MOTIONS else "track"


def matches(label, paper_type):
    """vehicle::ModeClass::matches on the label: a hull type matches when its primary motion is
    the mode's strongest component and its secondary, if any, is among the mode's named ones; a
    wheel-bounce type matches any wheel-bounce mode."""
    if paper_type.startswith(WHEEL):
        return kind(label) == "wheel"
    if kind(label) != "hull":
        return False
    primary, _, secondary = paper_type.partition("+")
    components = label.split("+")
    return components[0] == primary and (not secondary or secondary in components)


def match_targets(targets, frequencies, labels, primary_only):
    """The nearest mode of each target's type, each mode used once (the test's matchTargets):
    wheel targets take only the wheel-bounce modes coupled with the hull, as the paper's are.
    targets: [(type, hz)]; returns 0-based mode indices or None."""
    used, found = set(), []
    for paper_type, hz in targets:
        wanted = paper_type.split("+")[0] if primary_only else paper_type
        best = None
        for i, label in enumerate(labels):
            if i in used or not matches(label, wanted):
                continue
            if kind(label) == "wheel" and "+" not in label:
                continue
            if best is None or abs(frequencies[i] - hz) < abs(frequencies[best] - hz):
                best = i
        found.append(best)
        if best is not None:
            used.add(best)
    return found


def mode_targets(modes_json, targets, tolerance):
    """Per target: the matched mode (full type when that is within the tolerance, else the one
    with the paper's main motion), its deviation and a status."""
    f, labels = modes_json["frequencies_hz"], modes_json["mode_types"]
    full = match_targets(targets, f, labels, primary_only=False)
    main = match_targets(targets, f, labels, primary_only=True)
    result = []
    for (paper_type, hz), i_full, i_main in zip(targets, full, main):
        within = lambda i: i is not None and abs(f[i] - hz) <= tolerance * hz  # noqa: E731
        if within(i_full):
            i, status = i_full, "met"
        elif within(i_main):
            i, status = i_main, "met (main motion)"
        else:
            i = i_main if i_main is not None else i_full
            status = "**not met**"
        result.append({"type": paper_type, "paper_hz": hz, "mode": None if i is None else i + 1,
                       "hz": None if i is None else f[i],
                       "label": None if i is None else labels[i], "status": status})
    return result


def table4_section(name, variant, runs, reference):
    t4 = reference["table4"]
    tolerance = t4[f"{variant}_tolerance"]
    key = "uv_hz" if variant == "untracked" else "tv_hz"
    rows = mode_targets(runs.modes[variant], [(r["type"], r[key]) for r in t4["rows"]], tolerance)
    body = []
    for r in rows:
        ours = "none" if r["mode"] is None else f"{r['hz']:.2f} ({r['mode']})"
        delta = "" if r["mode"] is None else percent(r["hz"], r["paper_hz"])
        body.append([r["type"], f"{r['paper_hz']:.2f}", ours, delta, r["label"] or "", r["status"]])
    met = sum(r["status"] != "**not met**" for r in rows)
    title = f"Table 4, {variant} modes (target \u00b1{tolerance * 100:.0f} %)"
    text = (markdown_table(["Table 4 mode", "paper [Hz]", "ours [Hz] (mode)", "\u0394",
                            "our label", "status"], body)
            + f"\n\n{met} of {len(rows)} within \u00b1{tolerance * 100:.0f} %.")
    return Section(name, title, text, rows)


def pairing_section(runs, reference):
    """Table 4's un-tracked -> tracked pairing against ours by MAC (`tvd mac`)."""
    t4 = reference["table4"]
    uv = runs.modes["untracked"]
    ours_uv = match_targets([(r["type"], r["uv_hz"]) for r in t4["rows"]], uv["frequencies_hz"],
                            uv["mode_types"], primary_only=True)
    correlation = {c["untracked_mode"]: c for c in runs.mac["correlation"]}
    body, data = [], []
    for r, i in zip(t4["rows"], ours_uv):
        c = correlation.get(i + 1) if i is not None else None
        partner = c is not None and c.get("tracked_mode") is not None
        if partner:
            tv_type = c["tracked_type"]
            same = (kind(tv_type) == "wheel" if r["type"].startswith(WHEEL)
                    else tv_type.split("+")[0] == r["type"].split("+")[0])
            ours = (f"{i + 1} ({uv['frequencies_hz'][i]:.2f}) \u2192 {c['tracked_mode']} "
                    f"({c['tracked_hz']:.2f}), {tv_type}, MAC {c['mac']:.2f}")
        else:
            same, tv_type, ours = False, None, "no partner"
        body.append([r["type"], f"{r['uv_mode']} ({r['uv_hz']:.2f}) \u2192 {r['tv_mode']} "
                     f"({r['tv_hz']:.2f})", ours, "yes" if same else "**no**"])
        data.append({"type": r["type"], "untracked_mode": None if i is None else i + 1,
                     "tracked_mode": c["tracked_mode"] if partner else None,
                     "tracked_type": tv_type, "mac": c["mac"] if partner else None,
                     "same_motion_as_paper": same})
    same = sum(d["same_motion_as_paper"] for d in data)
    text = (markdown_table(["Table 4 type", "paper: UV mode (Hz) \u2192 TV mode (Hz)",
                            "ours: UV mode (Hz) \u2192 TV partner by MAC (Hz), its label, MAC",
                            "partner has the paper's motion"], body)
            + f"\n\n{same} of {len(data)} partners have the paper's main motion "
              f"(MAC on the {runs.mac['common_dofs']} translational DOFs both variants share).")
    return Section("mac_pairing", "Table 4, un-tracked \u2192 tracked pairing by MAC", text, data)


# --- Table 5: reduction -------------------------------------------------------------------------

def band_error_percent(reduce_json, band_hz):
    errors = [abs(m["relative_error"]) for m in reduce_json["band_modes"] if m["full_hz"] <= band_hz]
    return 100.0 * max(errors) if errors else math.nan


def table5_section(runs, reference):
    t5 = reference["table5"]
    fields = [("active DOFs", "active_dofs", "full_dofs"),
              ("interface DOFs", "interface_dofs", "interface_dofs"),
              ("input DOFs (hull + wheels)", "input_dofs", "input_dofs"),
              ("MoGeSeC DOFs", "mogesec_dofs", "mogesec_dofs"),
              ("fixed-interface (flexible) modes", "flexible_modes", "flexible_modes"),
              ("reduced DOFs", "reduced_dofs", "reduced_dofs")]
    body, data = [], {}
    for label, paper_key, our_key in fields:
        row = [label]
        for v in ("untracked", "tracked"):
            row += [f"{t5[v][paper_key]:,}", f"{runs.reduce[v][our_key]:,}"]
            data.setdefault(v, {})[our_key] = runs.reduce[v][our_key]
        body.append(row)
    row = ["reduced size"]
    for v in ("untracked", "tracked"):
        row += [f"{t5[v]['reduced_size_percent']:.1f} %",
                f"{runs.reduce[v]['reduced_size_percent']:.3f} %"]
    body.append(row)
    band = t5["band_hz"]
    row = [f"worst frequency error of the modes below {band:g} Hz"]
    for v in ("untracked", "tracked"):
        error = band_error_percent(runs.reduce[v], band)
        data[v]["worst_band_error_percent"] = error
        row += [f"\u2264 {t5['frequency_error_percent']:g} %", f"{error:.2g} %"]
    body.append(row)
    text = markdown_table(["", "paper UV", "ours UV", "paper TV", "ours TV"], body)
    share = runs.reduce["tracked"]["reduced_size_percent"]
    errors = [data[v]["worst_band_error_percent"] for v in ("untracked", "tracked")]
    text += (f"\n\nTracked reduced model {share:.3f} % of the full one (target \u2264 3 %: "
             f"{'met' if share <= 3.0 else '**not met**'}); every mode below {band:g} Hz within "
             f"{max(errors):.2g} % (target {t5['frequency_error_percent']:g} %: "
             f"{'met' if max(errors) <= t5['frequency_error_percent'] else '**not met**'}).")
    return Section("table5", "Table 5, model sizes", text, data)


# --- §4.1: FRFs ---------------------------------------------------------------------------------

def worst_db(hz, full, reduced, band_hz, ratio, window_hz):
    """Largest |20 log10(|reduced| / |full|)| over (0, band], skipping the points where the full
    FRF is below `ratio` of its largest value within +-window_hz (anti-resonances); also the
    fraction of points compared (test_vehicle_frf's worstDb)."""
    step = hz[1] - hz[0]
    w = int(round(window_hz / step))
    worst, compared, in_band = 0.0, 0, 0
    for i in range(1, len(hz)):
        if hz[i] > band_hz + 1e-9:
            break
        in_band += 1
        if full[i] < ratio * full[max(0, i - w):i + w + 1].max():
            continue
        compared += 1
        worst = max(worst, abs(20.0 * math.log10(reduced[i] / full[i])))
    return worst, compared / max(in_band, 1)


def frf_agreement_section(runs, reference):
    f = reference["frf"]
    body, data = [], []
    for v in ("untracked", "tracked"):
        for speed in (0, COUPLING_SPEED_KMH):
            full = Table(runs.frf[(v, "full", speed)]["csv"])
            reduced = Table(runs.frf[(v, "reduced", speed)]["csv"])
            hz = full.column("frequency_hz")
            cells, worst, fraction = [], 0.0, 1.0
            for column, _ in FRF_OUTPUTS:
                db, share = worst_db(hz, full.column(column + "_mag"),
                                     reduced.column(column + "_mag"), f["band_hz"],
                                     f["anti_resonance_ratio"], f["anti_resonance_window_hz"])
                cells.append(f"{db:.2g}")
                worst, fraction = max(worst, db), min(fraction, share)
            excitation = "synchronous" if not speed else f"{speed} km/h"
            status = "met" if worst <= f["tolerance_db"] else "**not met**"
            body.append([v, excitation, *cells, f"{100 * fraction:.0f} %", status])
            data.append({"variant": v, "speed_kmh": speed, "worst_db": worst,
                         "fraction_compared": fraction})
    text = markdown_table(["variant", "excitation", *[f"{n} [dB]" for _, n in FRF_OUTPUTS],
                           "points compared (fewest)", f"within {f['tolerance_db']:g} dB"], body)
    met = sum(d["worst_db"] <= f["tolerance_db"] for d in data)
    text += f"\n\n{met} of {len(data)} within {f['tolerance_db']:g} dB."
    return Section("frf_agreement", "Reduced vs full comfort FRFs up to "
                   f"{f['band_hz']:g} Hz, worst difference away from anti-resonances", text, data)


def peak_in_band(path, column, band_hz):
    t = Table(path)
    hz, mag = t.column("frequency_hz"), t.column(column + "_mag")
    inside = (hz > 0) & (hz <= band_hz + 1e-9)
    return mag[inside].max()


def wheelbase_section(runs, reference):
    band = reference["frf"]["band_hz"]
    body, data = [], []
    for v in ("untracked", "tracked"):
        for column, name in FRF_OUTPUTS:
            if column == "hull_pitch_acc":
                continue
            sync = peak_in_band(runs.frf[(v, "reduced", 0)]["csv"], column, band)
            ratios = [peak_in_band(runs.frf[(v, "reduced", s)]["csv"], column, band) / sync
                      for s in FRF_SPEEDS_KMH]
            body.append([v, name, *[f"{r:.2f}" for r in ratios]])
            data.append({"variant": v, "output": column, "ratios": dict(zip(FRF_SPEEDS_KMH, ratios))})
    text = markdown_table(["variant", "output", *[f"{s} km/h" for s in FRF_SPEEDS_KMH]], body)
    ratios = {(d["variant"], d["output"]): list(d["ratios"].values()) for d in data}
    hull = [r for v in ("untracked", "tracked") for r in ratios[(v, "hull_vertical_acc")]]
    wheels = ("front_wheel_acc", "rear_wheel_acc")
    untracked = [r for w in wheels for r in ratios[("untracked", w)]]
    falling = [all(b < a for a, b in zip(ratios[("tracked", w)], ratios[("tracked", w)][1:]))
               for w in wheels]
    text += ("\n\nPeak acceleration FRF up to "
             f"{band:g} Hz at each speed (travelled excitation) over the synchronous peak "
             "(reduced model). The paper (\u00a74.1.3): travelled FRFs at most tangent to the "
             f"synchronous one (hull vertical: {sum(r <= 1.0 for r in hull)} of {len(hull)} at "
             "most 1); un-tracked wheels unaffected by speed (within 10 %: "
             f"{sum(abs(r - 1.0) <= 0.1 for r in untracked)} of {len(untracked)}); tracked wheels "
             f"lower at increasing speed ({sum(falling)} of {len(falling)} falling at every step).")
    return Section("wheelbase_filter", "Wheelbase filter (Figs. 15-16)", text, data)


# --- §4.2: time domain --------------------------------------------------------------------------

def sim(runs, variant, track, speed, model="reduced"):
    return runs.sim[(variant, model, track, speed)]["json"]


def crew_seat(sim_json):
    for p in sim_json.get("peaks_at_points", []):
        if p["point"] == "crew_seat":
            return p["peak_vertical_accel_m_s2"]
    return None


def full_vs_reduced_section(runs, reference):
    tolerance = reference["time_domain"]["full_vs_reduced_tolerance"]
    body, data = [], []
    for speed in MOR_SPEEDS_KMH:
        full = Table(runs.sim_csv("untracked", "full", "long_hill", speed))
        reduced = Table(runs.sim_csv("untracked", "reduced", "long_hill", speed))
        wheels = [c for c in full.header if c.startswith("road_wheel_")]
        groups = [("hull heave", ["hull_heave_m"]), ("pitch", ["hull_pitch_deg"]),
                  ("road wheels (worst)", wheels),
                  ("hull vertical acceleration", ["hull_vertical_accel_m_s2"])]
        row = [f"{speed} km/h"]
        for name, columns in groups:
            worst = 0.0
            for c in columns:
                a, b = full.column(c), reduced.column(c)
                a, b = a - a[0], b - b[0]
                worst = max(worst, np.abs(a - b).max() / np.abs(a).max())
            row.append(f"{100 * worst:.2g} %")
            data.append({"speed_kmh": speed, "output": name, "relative_to_peak": worst})
        body.append(row)
    text = markdown_table(["un-tracked, long hill", "hull heave", "pitch", "road wheels (worst)",
                           "hull vertical acceleration"], body)
    judged = [d for d in data if d["output"] != "hull vertical acceleration"]
    met = sum(d["relative_to_peak"] <= tolerance for d in judged)
    text += (f"\n\nLargest |full \u2212 reduced| over the run, relative to the full model's peak; "
             f"{met} of {len(judged)} within {100 * tolerance:g} % (heave, pitch, wheels).")
    return Section("full_vs_reduced", "Reduced vs full model in time (Figs. 18-19)", text, data)


def approx_row(what, paper, ours, unit, tolerance, digits):
    ok = abs(ours - paper) <= tolerance * paper
    return [what, f"\u2248 {paper:g} {unit}", f"{ours:.{digits}f} {unit}", percent(ours, paper),
            "met" if ok else "**not met**"], ok


def claim_row(what, paper, ours, holds):
    return [what, paper, ours, "", "holds" if holds else "**does not hold**"], holds


def time_domain_section(runs, reference):
    td = reference["time_domain"]
    tol, height = td["approx_tolerance"], td["hill_height_m"]
    slow, fast = sim(runs, "untracked", "long_hill", 5), sim(runs, "untracked", "long_hill", 50)
    rows = [
        approx_row("UV long hill 5 km/h: peak hull vertical acceleration",
                   td["long_hill_5kmh"]["peak_hull_vertical_accel_m_s2"],
                   slow["peak_hull_vertical_accel_m_s2"], "m/s\u00b2", tol, 2),
        approx_row("same: peak pitch", td["long_hill_5kmh"]["peak_pitch_deg"],
                   slow["peak_pitch_deg"], "\u00b0", tol, 2),
        approx_row("UV long hill 50 km/h: peak hull vertical acceleration",
                   td["long_hill_50kmh"]["peak_hull_vertical_accel_m_s2"],
                   fast["peak_hull_vertical_accel_m_s2"], "m/s\u00b2", tol, 1),
        approx_row(f"same: wheel overshoot above the {height:g} m hill",
                   td["long_hill_50kmh"]["wheel_overshoot_m"],
                   fast["peak_wheel_displacement_m"] - height, "m", tol, 3),
    ]
    seat = [crew_seat(slow), crew_seat(fast)]
    if None not in seat:
        rows.append(([f"same runs at the crew seat: peak vertical acceleration, 5 / 50 km/h",
                      "not given", f"{seat[0]:.1f} / {seat[1]:.0f} m/s\u00b2", "", ""], None))
    v = COUPLING_SPEED_KMH
    uv = {t: sim(runs, "untracked", t, v) for t in ("long_hill", "separated_waves", "oop_waves")}
    tv = {t: sim(runs, "tracked", t, v) for t in ("long_hill", "separated_waves", "oop_waves")}
    acc, wheel = "peak_hull_vertical_accel_m_s2", "peak_wheel_displacement_m"
    rows += [
        claim_row(f"long hill {v} km/h: the track raises hull acceleration", "TV > UV",
                  f"TV {tv['long_hill'][acc]:.1f}, UV {uv['long_hill'][acc]:.1f} m/s\u00b2",
                  tv["long_hill"][acc] > uv["long_hill"][acc]),
    ]
    for t, name in (("separated_waves", "separated waves"), ("oop_waves", "OOP waves")):
        rows += [
            claim_row(f"{name} {v} km/h: the track filters wheel displacement", "TV < UV",
                      f"TV {tv[t][wheel]:.3f}, UV {uv[t][wheel]:.3f} m", tv[t][wheel] < uv[t][wheel]),
            claim_row(f"{name} {v} km/h: the track raises hull acceleration", "TV > UV",
                      f"TV {tv[t][acc]:.1f}, UV {uv[t][acc]:.1f} m/s\u00b2", tv[t][acc] > uv[t][acc]),
        ]
    roll = "peak_roll_deg"
    other = max(max(uv[t][roll], tv[t][roll]) for t in ("long_hill", "separated_waves"))
    rows += [
        claim_row(f"OOP waves {v} km/h: larger roll than on the other tracks", "larger",
                  f"UV {uv['oop_waves'][roll]:.2f}\u00b0, TV {tv['oop_waves'][roll]:.2f}\u00b0; "
                  f"other tracks \u2264 {other:.2g}\u00b0",
                  min(uv["oop_waves"][roll], tv["oop_waves"][roll]) > other),
        claim_row(f"OOP waves {v} km/h: roll, read as tracked > un-tracked", "TV > UV (no numbers)",
                  f"TV {tv['oop_waves'][roll]:.2f}\u00b0, UV {uv['oop_waves'][roll]:.2f}\u00b0",
                  tv["oop_waves"][roll] > uv["oop_waves"][roll]),
    ]
    for t, name, quantities in (("long_hill", "long hill", (acc,)),
                                ("separated_waves", "separated waves", ("peak_hull_heave_m", acc))):
        for q in quantities:
            values = [sim(runs, "tracked", t, s)[q] for s in TRACKED_SPEEDS_KMH]
            unit, digits = ("m", 3) if q.endswith("_m") else ("m/s\u00b2", 1)
            what = "hull heave" if q.endswith("_m") else "hull acceleration"
            speeds = " / ".join(f"{s}" for s in TRACKED_SPEEDS_KMH)
            rows.append(claim_row(f"TV {name} {speeds} km/h: {what} grows with speed", "grows",
                                  " / ".join(f"{x:.{digits}f}" for x in values) + f" {unit}",
                                  all(b > a for a, b in zip(values, values[1:]))))
    body = [r for r, _ in rows]
    met = sum(ok is True for _, ok in rows)
    judged = sum(ok is not None for _, ok in rows)
    text = markdown_table(["case", "paper", "ours", "\u0394", "status"], body)
    text += (f"\n\n{met} of {judged} met or holding (approximate values: within "
             f"\u00b1{100 * tol:g} %). Reduced models, modal damping of the description.")
    data = [{"case": r[0], "paper": r[1], "ours": r[2], "ok": ok} for r, ok in rows]
    return Section("time_domain", "Time domain (\u00a74.2, Figs. 18-24)", text, data)


def damping_name(values):
    """'modal 2 %' or 'Rayleigh β = 0.002 s (ζ = 3 % at 5 Hz, 11 % at 18 Hz)'."""
    if values["model"] == "modal":
        return f"modal {100 * values['modal_ratio']:g} %"
    alpha, beta = values.get("rayleigh_alpha", 0.0), values["rayleigh_beta"]
    zeta = lambda hz: 100 * (alpha / (4 * math.pi * hz) + beta * math.pi * hz)  # noqa: E731
    head = f"Rayleigh \u03b1 = {alpha:g} 1/s, \u03b2 = {beta:g} s" if alpha else f"Rayleigh \u03b2 = {beta:g} s"
    return f"{head} (\u03b6 = {zeta(5):.0f} % at 5 Hz, {zeta(18):.0f} % at 18 Hz)"


def damping_section(runs, reference):
    """The §4.2.2 magnitudes under other damping (the paper gives none)."""
    td = reference["time_domain"]
    height = td["hill_height_m"]
    slow, fast = MOR_SPEEDS_KMH
    description = runs.description_damping()
    cases = [(damping_name(description) + " (the description's)",
              sim(runs, "untracked", "long_hill", slow), sim(runs, "untracked", "long_hill", fast))]
    cases += [(damping_name(values), runs.damping[(name, slow)], runs.damping[(name, fast)])
              for name, values in DAMPING_VARIANTS]
    body, data = [], []
    for name, a, b in cases:
        seat = [crew_seat(a), crew_seat(b)]
        body.append([name, f"{a['peak_hull_vertical_accel_m_s2']:.2f} m/s\u00b2, "
                           f"{a['peak_pitch_deg']:.2f}\u00b0",
                     f"{b['peak_hull_vertical_accel_m_s2']:.1f} m/s\u00b2, "
                     f"{b['peak_wheel_displacement_m'] - height:.3f} m",
                     "\u2013" if None in seat else f"{seat[0]:.1f} / {seat[1]:.0f} m/s\u00b2"])
        data.append({"damping": name, "slow": a["peak_hull_vertical_accel_m_s2"],
                     "fast": b["peak_hull_vertical_accel_m_s2"]})
    p5, p50 = td["long_hill_5kmh"], td["long_hill_50kmh"]
    body.append(["paper", f"\u2248 {p5['peak_hull_vertical_accel_m_s2']:g} m/s\u00b2, "
                          f"\u2248 {p5['peak_pitch_deg']:g}\u00b0",
                 f"\u2248 {p50['peak_hull_vertical_accel_m_s2']:g} m/s\u00b2, "
                 f"\u2248 {p50['wheel_overshoot_m']:g} m", "\u2013"])
    text = markdown_table(["damping", f"{slow} km/h: peak hull acceleration, pitch",
                           f"{fast} km/h: peak hull acceleration, wheel overshoot",
                           f"crew seat, {slow} / {fast} km/h"], body)
    return Section("damping_sweep", "Damping (not given by the paper), un-tracked long hill", text,
                   data)


def all_sections(runs, reference):
    return [table4_section("table4_untracked", "untracked", runs, reference),
            table4_section("table4_tracked", "tracked", runs, reference),
            pairing_section(runs, reference),
            table5_section(runs, reference),
            frf_agreement_section(runs, reference),
            wheelbase_section(runs, reference),
            full_vs_reduced_section(runs, reference),
            time_domain_section(runs, reference),
            damping_section(runs, reference)]
