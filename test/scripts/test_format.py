#!/usr/bin/python3
"""Every C++ source and header of the package is formatted as the repository's .clang-format says
(STYLE: "Format with the repository's .clang-format").

Checks each *.cpp and *.h git knows or would add (tracked, and untracked but not ignored; outside
a git work tree, every such file under include/, src/, test/ and bench/) with `clang-format --dry-run -Werror --style=file`, and names
the files that would change with the first lines clang-format reports. A badly formatted copy of a
file must fail, so a formatter that checks nothing cannot pass. Fix a failure with
    git ls-files '*.cpp' '*.h' | xargs clang-format -i
Run as
    /usr/bin/python3 test/scripts/test_format.py [--xml OUTDIR/format.xml]
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import junit_runner

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FOLDERS = ("include", "src", "test", "bench")


def clang_format():
    program = shutil.which("clang-format", path="/usr/bin:" + os.environ.get("PATH", ""))
    if program is None:
        raise AssertionError("clang-format is not installed (Debian package clang-format; "
                             "scripts/install_deps.sh installs it)")
    return program


def sources():
    """The package's C++ files, relative to SOURCE."""
    inside = subprocess.run(["git", "-C", SOURCE, "rev-parse", "--is-inside-work-tree"],
                            capture_output=True, text=True, timeout=60)
    if inside.returncode == 0 and inside.stdout.strip() == "true":
        listed = subprocess.run(["git", "-C", SOURCE, "ls-files", "-z", "--cached", "--others",
                                 "--exclude-standard", "*.cpp", "*.h"],
                                capture_output=True, check=True, timeout=60).stdout.decode()
        return sorted(set(name for name in listed.split("\0")
                          if name and os.path.isfile(os.path.join(SOURCE, name))))
    found = []
    for folder in FOLDERS:
        for root, _, files in os.walk(os.path.join(SOURCE, folder)):
            found += [os.path.relpath(os.path.join(root, f), SOURCE) for f in files
                      if f.endswith((".cpp", ".h"))]
    return sorted(found)


def unformatted(program, paths, cwd):
    """{path: first complaint} for each path clang-format would change (checked in batches: one
    process per file costs half a minute)."""
    bad = {}
    for start in range(0, len(paths), 64):
        batch = paths[start:start + 64]
        result = subprocess.run([program, "--dry-run", "-Werror", "--style=file", *batch],
                                cwd=cwd, capture_output=True, text=True, timeout=300)
        if result.returncode == 0:
            continue
        lines = result.stderr.splitlines()
        for i, line in enumerate(lines):
            path = line.split(":", 1)[0]
            if path in batch and ": error: " in line and path not in bad:
                bad[path] = "\n".join(lines[i:i + 3])
        if not bad.keys() & set(batch):  # failed without naming a file: say what it said
            bad[" ".join(batch[:3]) + " ..."] = result.stderr[:2000]
    return bad


class FormatTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.program = clang_format()
        cls.paths = sources()

    def test_every_source_is_formatted(self):
        self.assertGreater(len(self.paths), 100, "no sources found")
        bad = unformatted(self.program, self.paths, SOURCE)
        version = subprocess.run([self.program, "--version"], capture_output=True, text=True,
                                 timeout=60).stdout.strip()
        if bad:
            self.fail("%d file(s) not formatted as .clang-format says to %s (the "
                      "files follow Debian 12's clang-format 14; fix: git ls-files '*.cpp' "
                      "'*.h' | xargs clang-format -i):\n%s"
                      % (len(bad), version, "\n".join("%s:\n%s" % b for b in sorted(bad.items()))))

    def test_a_badly_formatted_file_is_caught(self):
        # The check must see a change: the same .clang-format, a header with its braces and
        # spacing broken.
        with tempfile.TemporaryDirectory() as work:
            shutil.copy(os.path.join(SOURCE, ".clang-format"), work)
            with open(os.path.join(work, "bad.h"), "w") as f:
                f.write("#pragma once\nnamespace a{int  f( int x ){return x;}}\n")
            with open(os.path.join(work, "good.h"), "w") as f:
                f.write("#pragma once\nnamespace a {\ninline int f(int x) {\n  return x;\n}\n"
                        "}  // namespace a\n")
            self.assertEqual(sorted(unformatted(self.program, ["bad.h", "good.h"], work)),
                             ["bad.h"])


if __name__ == "__main__":
    sys.exit(junit_runner.main(FormatTest, "format", __doc__))
