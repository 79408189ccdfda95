#!/usr/bin/python3
"""catkin_lint on the package (CMakeLists.txt against package.xml, install rules, catkin usage).

Run -W2 --strict: every notice is an error, apart from those CMakeLists.txt waives with a
`#catkin_lint:` pragma and a reason. The waived messages are checked too (--show-ignored): the
scripts left uninstalled must be exactly the developer tools, so a script the launch files need
cannot lose its install rule unnoticed. A copy with a dependency left out of package.xml must
fail, so a linter that checks nothing cannot pass. Offline, catkin_lint has no rosdep database and
does not check that dependency keys exist (it says so on stderr). Run as
    /usr/bin/python3 test/scripts/test_catkin_lint.py [--xml OUTDIR/catkin_lint.xml]
"""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

import junit_runner

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PACKAGE = "tracked_vehicle_dynamics"
ARGS = ["-W2", "--strict", "--offline"]
# Executables run from the source tree, never installed (README: build, test, demos, paper
# report, benchmark); everything else executable must have an install rule.
DEVELOPER_TOOLS = {"scripts/build.sh", "scripts/demo.sh", "scripts/install_deps.sh",
                   "scripts/paper_report.py", "scripts/ros_demo.sh",
                   "scripts/ros_demo_summary.py", "bench/ros_node_bench.sh"}
# What CMakeLists.txt waives, each with its reason there: (catkin_lint id, text it contains).
WAIVED = {("MISSING_FILE", "generated/software_version.cpp"),
          ("EXTERNAL_INTERFACE_PATH", "${catkin_INCLUDE_DIRS}"),
          ("GLOBAL_VAR_COLLISION", "'PYTHON_EXECUTABLE'"),
          ("GLOBAL_VAR_COLLISION", "'TVD_SIMD'")}


def catkin_lint(path, *extra):
    program = shutil.which("catkin_lint", path="/usr/bin:" + os.environ.get("PATH", ""))
    if program is None:
        raise AssertionError("catkin_lint is not installed (Debian package catkin-lint; "
                             "scripts/install_deps.sh installs it)")
    return subprocess.run([program, *ARGS, *extra, path], capture_output=True, text=True,
                          timeout=300)


def package_copy(work):
    """The package's tracked files under WORK/tracked_vehicle_dynamics (no build trees or
    outputs; the directory named as the package)."""
    files = subprocess.run(["git", "-C", SOURCE, "ls-files", "-z"], capture_output=True,
                           check=True, timeout=60).stdout.decode().split("\0")
    copy = os.path.join(work, PACKAGE)
    for name in filter(None, files):
        source = os.path.join(SOURCE, name)
        if os.path.isfile(source):
            os.makedirs(os.path.dirname(os.path.join(copy, name)), exist_ok=True)
            shutil.copy2(source, os.path.join(copy, name))
    return copy


class CatkinLintTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="tvd_catkin_lint_")
        cls.copy = package_copy(cls.work)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_the_package_is_clean(self):
        result = catkin_lint(self.copy)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("found 0 problems", result.stdout + result.stderr)

    def test_only_the_reasoned_waivers_and_developer_tools_are_ignored(self):
        result = catkin_lint(self.copy, "--show-ignored", "--xml")
        report = ET.fromstring(result.stdout)
        ignored = [(m.findtext("id"), m.findtext("text")) for m in report]
        scripts = {text.split("'")[1] for id_, text in ignored if id_ == "UNINSTALLED_SCRIPT"}
        self.assertEqual(scripts, DEVELOPER_TOOLS)
        others = [(id_, text) for id_, text in ignored if id_ != "UNINSTALLED_SCRIPT"]
        for id_, part in WAIVED:
            self.assertTrue(any(i == id_ and part in t for i, t in others), (id_, part, others))
        self.assertEqual(len(others), len(WAIVED), others)

    def test_a_dependency_missing_from_package_xml_is_found(self):
        with tempfile.TemporaryDirectory() as work:
            copy = shutil.copytree(self.copy, os.path.join(work, PACKAGE))
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
