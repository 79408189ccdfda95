#!/usr/bin/python3
"""catkin_lint on the package (CMakeLists.txt against package.xml, install rules, catkin usage).

Run -W2 --strict: every notice is an error, apart from those CMakeLists.txt itself waives with a
`#catkin_lint:` pragma and a reason, and the checkout directory's name (a clone may be called
anything). A copy with a dependency left out of package.xml must fail, so a linter that checks
nothing cannot pass. Run as
    /usr/bin/python3 test/scripts/test_catkin_lint.py [--xml OUTDIR/catkin_lint.xml]
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import junit_runner

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ARGS = ["-W2", "--strict", "--offline", "--ignore", "package_path_name"]


def catkin_lint(path):
    program = shutil.which("catkin_lint", path="/usr/bin:" + os.environ.get("PATH", ""))
    if program is None:
        raise AssertionError("catkin_lint is not installed (Debian package catkin-lint; "
                             "scripts/install_deps.sh installs it)")
    return subprocess.run([program, *ARGS, path], capture_output=True, text=True, timeout=300)


class CatkinLintTest(unittest.TestCase):
    def test_the_package_is_clean(self):
        result = catkin_lint(SOURCE)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("found 0 problems", result.stdout + result.stderr)

    def test_a_dependency_missing_from_package_xml_is_found(self):
        with tempfile.TemporaryDirectory() as work:
            copy = os.path.join(work, "tracked_vehicle_dynamics")
            # The sources only: not the checkout's build trees and generated outputs.
            shutil.copytree(SOURCE, copy, symlinks=True, ignore=lambda d, names: [
                n for n in names if d == SOURCE and (
                    n in (".git", "paper_report") or n.startswith(("build", ".devel-")))])
            with open(os.path.join(copy, "package.xml")) as f:
                manifest = f.read()
            line = "<depend>nav_msgs</depend>"
            self.assertIn(line, manifest)
            with open(os.path.join(copy, "package.xml"), "w") as f:
                f.write(manifest.replace(line, ""))
            result = catkin_lint(copy)
            self.assertNotEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("nav_msgs", result.stdout + result.stderr)


if __name__ == "__main__":
    sys.exit(junit_runner.main(CatkinLintTest, "catkin_lint", __doc__))
