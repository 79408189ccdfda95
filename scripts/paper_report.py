#!/usr/bin/python3
"""Reproduces the paper's results on a vehicle description in one command: every analysis of
Dimauro et al. (2024), Sections 3-4, run with `tvd`, the side-by-side tables of the paper's
figures (config/paper_reference.yaml) against ours, and the paper's Figs. 9-24.

    scripts/paper_report.py [--vehicle FILE] [--out DIR] [--tvd PATH] [--no-figures]
                            [--readme FILE [--readme FILE ...] (--check | --update)]

Writes DIR (default paper_report/): report.md (the tables, with the commands that produced the
numbers), report.json (the same numbers), figures/figNN_*.png, and every run's own output (modes,
MAC, reduced models, FRF and simulation CSVs) in subdirectories. About a minute on the paper vehicle.

--readme FILE --check compares the generated tables of a Markdown file (between the markers
`<!-- paper_report:NAME -->` and `<!-- /paper_report:NAME -->`; the README and
doc/vehicle_model.md have them) with this run's and exits with status 1 naming those that
differ; --update rewrites them. Bad input (a missing `tvd` or
description, a failed run) exits with status 2 and one line naming it.
"""
import argparse
import difflib
import json
import os
import re
import shutil
import sys

import yaml

SCRIPTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(SCRIPTS)
sys.path.insert(0, SCRIPTS)

import paper_figures  # noqa: E402
import paper_tables  # noqa: E402
from paper_runs import RunError, Runs  # noqa: E402

DEFAULT_VEHICLE = os.path.relpath(os.path.join(ROOT, "config", "vehicles", "paper_vehicle.yaml"))
DEFAULT_REFERENCE = os.path.join(ROOT, "config", "paper_reference.yaml")
BLOCK = re.compile(r"<!-- paper_report:(?P<name>[a-z0-9_]+) -->\n(?P<body>.*?)"
                   r"<!-- /paper_report:(?P=name) -->", re.S)


def fail(message, status=2):
    sys.stderr.write(f"paper_report.py: error: {message}\n")
    sys.exit(status)


class ArgumentParser(argparse.ArgumentParser):
    def error(self, message):
        fail(message)


def find_tvd(given):
    if given:
        candidates = [given]
    else:
        candidates = [os.path.join(ROOT, "build", "devel", "lib", "tracked_vehicle_dynamics", "tvd"),
                      shutil.which("tvd") or ""]
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    fail(f"no tvd executable at {given}" if given else
         "no tvd executable found (build with scripts/build.sh, or pass --tvd PATH)")


def load_reference(path):
    try:
        with open(path, encoding="utf-8") as stream:
            reference = yaml.safe_load(stream)
    except (OSError, yaml.YAMLError) as error:
        fail(f"{path}: cannot read the paper's reference values ({error})")
    for key in ("table4", "table5", "frf", "time_domain"):
        if not isinstance(reference, dict) or key not in reference:
            fail(f"{path}: missing key '{key}'")
    return reference


def render_report(sections, runs, vehicle, figures):
    lines = ["# Paper vs ours", "",
             f"Vehicle description `{vehicle}`; paper: Dimauro et al., Defence Technology (2024). "
             "Produced by `scripts/paper_report.py`; every number below comes from the `tvd` "
             "runs listed at the end (their outputs are in this directory).", ""]
    lines += ["## Summary", ""] + [f"* **{s.title}**: {s.summary}" for s in sections if s.summary]
    lines += [""]
    for s in sections:
        lines += [f"## {s.title}", "", f"<!-- paper_report:{s.name} -->", s.markdown,
                  f"<!-- /paper_report:{s.name} -->", ""]
    if figures:
        lines += ["## Figures", "", "Ours, under the paper's caption of the figure they redraw.", ""]
        for f in figures:
            lines += [f"**{paper_figures.caption(f)}**", "", f"![{f}](figures/{f})", ""]
    lines += ["## Runs", "", "```"] + runs.commands + ["```", ""]
    return "\n".join(lines)


def readme_blocks(text):
    return {m.group("name"): m.group("body") for m in BLOCK.finditer(text)}


def sync_readme(path, sections, update):
    """Returns the names of the README blocks that differ from `sections` (after rewriting them
    when `update`)."""
    try:
        with open(path, encoding="utf-8") as stream:
            text = stream.read()
    except OSError as error:
        fail(f"{path}: cannot read ({error.strerror})")
    generated = {s.name: s.markdown + "\n" for s in sections}
    blocks = readme_blocks(text)
    if not blocks:
        fail(f"{path}: no <!-- paper_report:NAME --> blocks")
    unknown = sorted(set(blocks) - set(generated))
    if unknown:
        fail(f"{path}: unknown block(s) {', '.join(unknown)}; known: {', '.join(sorted(generated))}")
    differ = [n for n, body in blocks.items() if body != generated[n]]
    for n in differ:
        sys.stdout.writelines(difflib.unified_diff(blocks[n].splitlines(True),
                                                   generated[n].splitlines(True),
                                                   f"{path} ({n})", f"generated ({n})"))
    if update and differ:
        text = BLOCK.sub(lambda m: f"<!-- paper_report:{m.group('name')} -->\n"
                         f"{generated[m.group('name')]}<!-- /paper_report:{m.group('name')} -->",
                         text)
        with open(path, "w", encoding="utf-8") as stream:
            stream.write(text)
    return differ


def main():
    parser = ArgumentParser(description=__doc__.split("\n\n")[0],
                            formatter_class=argparse.RawDescriptionHelpFormatter,
                            epilog="\n\n".join(__doc__.split("\n\n")[1:]))
    parser.add_argument("--vehicle", default=DEFAULT_VEHICLE,
                        help=f"vehicle description (default {DEFAULT_VEHICLE})")
    parser.add_argument("--out", default="paper_report", help="report directory (default paper_report)")
    parser.add_argument("--tvd", help="the tvd executable (default: build/devel/lib/... or PATH)")
    parser.add_argument("--reference", default=DEFAULT_REFERENCE,
                        help="the paper's values (default config/paper_reference.yaml)")
    parser.add_argument("--no-figures", action="store_true", help="tables only")
    parser.add_argument("--readme", action="append", metavar="FILE",
                        help="a Markdown file with <!-- paper_report:NAME --> blocks (repeatable)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="with --readme: exit 1 if a block differs")
    mode.add_argument("--update", action="store_true", help="with --readme: rewrite the blocks")
    args = parser.parse_args()
    if (args.check or args.update) and not args.readme:
        fail("--check and --update need --readme FILE")
    if args.readme and not (args.check or args.update):
        fail("--readme needs --check or --update")
    if not os.path.isfile(args.vehicle):
        fail(f"{args.vehicle}: no such vehicle description")
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        fail(f"{args.out}: exists and is not a directory")
    tvd = find_tvd(args.tvd)
    reference = load_reference(args.reference)
    os.makedirs(args.out, exist_ok=True)

    runs = Runs(tvd, args.vehicle, args.out, log=lambda line: print(line, flush=True))
    try:
        runs.run_all()
        sections = paper_tables.all_sections(runs, reference)
        pairs = next(s for s in sections if s.name == "mac_pairing").data
        figures = [] if args.no_figures else paper_figures.draw_all(
            runs, args.vehicle, os.path.join(args.out, "figures"), pairs,
            log=lambda line: print(line, flush=True))
    except RunError as error:
        fail(str(error))
    with open(os.path.join(args.out, "report.md"), "w", encoding="utf-8") as stream:
        stream.write(render_report(sections, runs, args.vehicle, figures))
    with open(os.path.join(args.out, "report.json"), "w", encoding="utf-8") as stream:
        json.dump({"vehicle": args.vehicle, "sections": {s.name: s.data for s in sections},
                   "figures": figures, "runs": runs.commands}, stream, indent=1)
    print(f"report: {os.path.join(args.out, 'report.md')} ({len(sections)} tables, "
          f"{len(figures)} figures)")
    stale = []
    for readme in args.readme or []:
        differ = sync_readme(readme, sections, args.update)
        print(f"{readme}: {('rewrote ' if args.update else 'differs: ') + ', '.join(differ) if differ else 'up to date'}")
        stale += [f"{readme} ({', '.join(differ)})"] if differ else []
    if stale and args.check:
        fail(f"generated tables differ in {'; '.join(stale)} (rerun with --update to rewrite them)",
             status=1)


if __name__ == "__main__":
    main()
