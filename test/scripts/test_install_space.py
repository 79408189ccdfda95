#!/usr/bin/python3
"""The package from its install space, as a deployed simulator stack gets it.

`cmake --install` of the build (staged with DESTDIR, so the configured prefix is not touched)
into a scratch directory that is then made read-only; every check runs in an environment that
holds nothing but that install space's setup.bash (no devel space, no source tree on any path):
rospack finds the installed share directory, `rosrun ... tvd` is this build's and reads the
installed vehicle description, a figure script imports its installed helper module, a catkin
package builds and runs against the install space, and the node started by the installed launch
file reduces its model into $ROS_HOME (the install is read-only) and publishes the hull's frame.
Run as
    /usr/bin/python3 test/scripts/test_install_space.py --build BUILD_DIR [--keep] [--xml OUT.xml]
The stage is a temporary directory outside the package, removed at the end unless --keep.
"""
import json
import os
import re
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
import time
import unittest

import junit_runner

PACKAGE = "tracked_vehicle_dynamics"
HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = None  # set from --build: the configured and built tree
# --keep (taken off the command line below): leave the staged install and logs for a look.
KEEP = "--keep" in sys.argv


def cache_value(build, name):
    """A variable of BUILD/CMakeCache.txt (e.g. CMAKE_INSTALL_PREFIX)."""
    with open(os.path.join(build, "CMakeCache.txt")) as f:
        for line in f:
            match = re.match(rf"{name}:[A-Z]+=(.*)$", line.strip())
            if match:
                return match.group(1)
    raise AssertionError(f"{name} is not in {build}/CMakeCache.txt")


def make_read_only(root, writable):
    for directory, dirs, files in os.walk(root):
        for name in dirs + files:
            path = os.path.join(directory, name)
            if not os.path.islink(path):
                mode = os.stat(path).st_mode
                os.chmod(path, mode | stat.S_IWUSR if writable else mode & ~0o222)
    mode = os.stat(root).st_mode
    os.chmod(root, mode | stat.S_IWUSR if writable else mode & ~0o222)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class InstallSpaceTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # Outside the package and removed afterwards: a copy of the launch files anywhere under
        # the package directory (build/ included) makes `roslaunch PACKAGE FILE` ambiguous.
        cls.work = tempfile.mkdtemp(prefix="tvd_install_space_")
        stage = os.path.join(cls.work, "stage")
        os.makedirs(stage)
        env = dict(os.environ, DESTDIR=stage)
        result = subprocess.run(["cmake", "--install", BUILD], env=env, capture_output=True,
                                text=True, timeout=120)
        if result.returncode != 0:
            raise AssertionError(f"cmake --install {BUILD} failed:\n{result.stdout}\n"
                                 f"{result.stderr}")
        cls.prefix = stage + cache_value(BUILD, "CMAKE_INSTALL_PREFIX")
        cls.share = os.path.join(cls.prefix, "share", PACKAGE)
        make_read_only(stage, writable=False)
        cls.stage = stage
        cls.home = os.path.join(cls.work, "home")
        cls.ros_home = os.path.join(cls.work, "ros_home")
        os.makedirs(cls.home)
        # Nothing of the calling environment (ctest's, the devel space's): the install space only.
        cls.env = {"HOME": cls.home, "PATH": "/usr/bin:/bin", "LANG": "C.UTF-8",
                   "ROS_HOME": cls.ros_home, "MPLBACKEND": "Agg"}

    @staticmethod
    def listing(root):
        """{path: (size, mtime)} of every file under root: what a run wrote there shows."""
        files = {}
        for directory, _, names in os.walk(root):
            for name in names:
                path = os.path.join(directory, name)
                info = os.lstat(path)
                files[path] = (info.st_size, info.st_mtime_ns)
        return files

    @classmethod
    def tearDownClass(cls):
        make_read_only(cls.work, writable=True)
        if KEEP:
            print(f"install space test: kept {cls.work}")
        else:
            shutil.rmtree(cls.work, ignore_errors=True)

    def installed_command(self, *args):
        """bash running ARGS after sourcing the install space's setup.bash. The positional
        parameters are cleared first: setup.bash hands its own to _setup_util.py."""
        script = ('prefix=$0; command=("$@"); set --; set +u; '
                  'source "$prefix/setup.bash" || exit 97; exec "${command[@]}"')
        return ["/bin/bash", "-c", script, self.prefix, *args]

    def run_installed(self, *args, timeout=300, check=True, env=None):
        """A command after `source PREFIX/setup.bash`, in the bare environment."""
        result = subprocess.run(self.installed_command(*args), env=env or self.env,
                                capture_output=True, text=True, timeout=timeout)
        if check and result.returncode != 0:
            raise AssertionError(f"{' '.join(args)} failed ({result.returncode}):\n"
                                 f"{result.stdout}\n{result.stderr}")
        return result

    def test_rospack_finds_the_installed_package_only(self):
        found = self.run_installed("rospack", "find", PACKAGE).stdout.strip()
        self.assertEqual(found, self.share)
        for name in ("package.xml", "launch/vehicle_dynamics.launch",
                     "launch/replay_track.launch", "config/vehicle_dynamics.yaml",
                     "config/vehicles/paper_vehicle.yaml"):
            self.assertTrue(os.path.isfile(os.path.join(found, name)), name)
        # Every search path is the install space's or the system's: no source or devel tree.
        paths = self.run_installed("bash", "-c",
                                   "echo $ROS_PACKAGE_PATH:$CMAKE_PREFIX_PATH:$LD_LIBRARY_PATH:"
                                   "$PYTHONPATH:$PATH").stdout.strip().split(":")
        for path in filter(None, paths):
            self.assertTrue(path.startswith((self.prefix, "/usr/", "/bin", "/opt/")), path)

    def test_installed_tvd_is_this_build_and_reads_the_installed_vehicle(self):
        built = subprocess.run([os.path.join(cache_value(BUILD, "CATKIN_DEVEL_PREFIX"), "lib",
                                             PACKAGE, "tvd"), "--version"],
                               capture_output=True, text=True, timeout=60, check=True)
        installed = self.run_installed("rosrun", PACKAGE, "tvd", "--version")
        self.assertEqual(installed.stdout, built.stdout)
        vehicle = os.path.join(self.share, "config/vehicles/paper_vehicle.yaml")
        out = self.run_installed("rosrun", PACKAGE, "tvd", "modes", "--vehicle", vehicle,
                                 "--variant", "untracked", "--count", "12", "--json")
        report = json.loads(out.stdout)
        self.assertEqual(len(report["frequencies_hz"]), 12)
        # Table 1: 5.6e4 kg with the chains; the un-tracked model carries its minimal chain.
        self.assertGreater(report["mass_kg"], 3.0e4)
        static = report["static"]
        self.assertAlmostEqual(static["ground_reaction_sum_n"] / static["weight_n"], 1.0,
                               delta=1e-6)

    def test_installed_figure_script_finds_its_helper_module(self):
        out = self.run_installed("rosrun", PACKAGE, "plot_frf.py", "--help")
        self.assertIn("usage", out.stdout.lower())

    def test_a_downstream_package_builds_against_the_install_space(self):
        # The same package and checks as against the devel space (test_downstream_package.sh),
        # here with the install space's exported CMake configuration.
        result = subprocess.run([os.path.join(HERE, "test_downstream_package.sh"), self.prefix,
                                 self.work], env=self.env, capture_output=True, text=True,
                                timeout=300)
        self.assertEqual(result.returncode, 0, f"{result.stdout}\n{result.stderr}")
        self.assertIn(f"against {self.prefix}", result.stdout)
        found = cache_value(os.path.join(self.work, "downstream_check", "build"),
                            f"{PACKAGE}_DIR")
        self.assertEqual(found, os.path.join(self.share, "cmake"))
        # ... and runs on the installed libraries (a stale copy under the configured prefix, e.g.
        # /usr/local/lib, must not be what it loads).
        program = os.path.join(self.work, "downstream_check", "devel", "lib",
                               "tvd_downstream_check", "downstream_check")
        libraries = self.run_installed("ldd", program).stdout
        for library in ("libtvd_core.so", "libtvd_ros.so"):
            line = next((l for l in libraries.splitlines() if library in l), "")
            self.assertIn(os.path.join(self.prefix, "lib", library), line, libraries)

    def test_a_program_built_from_the_pkg_config_file_shares_eigen_objects(self):
        # A make-based user takes Cflags and Libs from the installed .pc. Debian's own
        # rosbag_storage.pc names a pluginlib.pc that Debian does not ship, so `pkg-config` fails
        # on any package requiring rosbag; the fields are read from the file, as pkg-config would.
        pc_file = os.path.join(self.prefix, "lib", "pkgconfig", f"{PACKAGE}.pc")
        fields, variables = {}, {}
        with open(pc_file) as f:
            for line in f:
                line = line.strip().replace("\\$", "$")
                for name, value in variables.items():
                    line = line.replace("${" + name + "}", value)
                if re.match(r"^\w+=", line):
                    name, value = line.split("=", 1)
                    # The prefix written is the configured one: the staged copy is under stage.
                    variables[name] = self.stage + value if name == "prefix" else value
                elif re.match(r"^[A-Za-z.]+:", line):
                    name, value = line.split(":", 1)
                    fields[name] = value.split()
        # The SIMD flag is the one the CMake configuration exports (extras file): Eigen's
        # allocation and layout must match tvd_core's on both sides.
        with open(os.path.join(self.share, "cmake", f"{PACKAGE}-extras.cmake")) as f:
            flag = re.search(r'SIMD_FLAG "([^"]*)"', f.read()).group(1)
        if flag:
            self.assertIn(flag, fields["Cflags"], pc_file)
        program = os.path.join(self.work, "pkg_config_check")
        source = program + ".cpp"
        with open(source, "w") as f:
            f.write("""
#include <cstdio>
#include <tracked_vehicle_dynamics/fem/system.h>
#include <tracked_vehicle_dynamics/vehicle/vehicle_description.h>
#include <tracked_vehicle_dynamics/vehicle/vehicle_model.h>
namespace tvd = tracked_vehicle_dynamics;
int main(int, char** argv) {
  const auto d = tvd::vehicle::loadVehicleDescription(argv[1]);
  const auto model = tvd::vehicle::buildVehicleModel(d, tvd::vehicle::Variant::Untracked);
  tvd::fem::System system = tvd::fem::assemble(model.model);  // made in tvd_core, freed here
  tvd::SparseMatrix k = system.stiffness;
  k.makeCompressed();
  std::printf("%ld %.0f\\n", static_cast<long>(system.size()), model.model.totalMass());
}
""")
        compile_command = ["g++", "-std=c++17", *fields["Cflags"], source, "-o", program,
                           *fields["Libs"], "-Wl,-rpath-link=/usr/lib/x86_64-linux-gnu"]
        result = subprocess.run(compile_command, capture_output=True, text=True, timeout=300)
        self.assertEqual(result.returncode, 0, f"{' '.join(compile_command)}\n{result.stderr}")
        vehicle = os.path.join(self.share, "config/vehicles/paper_vehicle.yaml")
        out = self.run_installed(program, vehicle).stdout.split()
        self.assertGreater(int(out[0]), 6)
        self.assertGreater(float(out[1]), 3.0e4)
        # Built for another level, the same program does not link, and the error says why
        # (types.h): it used to link and abort at its first call ("double free or corruption").
        other = ([c for c in fields["Cflags"] if not c.startswith("-march=")] if flag
                 else fields["Cflags"] + ["-march=x86-64-v3"])
        mismatched = ["g++", "-std=c++17", *other, source, "-o", program + "_other",
                      *fields["Libs"], "-Wl,-rpath-link=/usr/lib/x86_64-linux-gnu"]
        result = subprocess.run(mismatched, capture_output=True, text=True, timeout=300)
        self.assertNotEqual(result.returncode, 0, " ".join(mismatched))
        self.assertRegex(result.stderr,
                         r"undefined reference to .*tracked_vehicle_dynamics::abi::"
                         r"eigen_max_align_bytes_\d+_compile_with_tvd_core_simd_flag")

    def test_the_installed_launch_file_starts_the_node_from_a_read_only_install(self):
        before = self.listing(self.stage)
        port = free_port()
        env = dict(self.env, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_IP="127.0.0.1")
        launch = subprocess.Popen(
            self.installed_command("roslaunch", "-p", str(port), PACKAGE,
                                   "vehicle_dynamics.launch"), env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            start_new_session=True)
        try:
            # roslaunch starts the master; rostopic gives up at once without one.
            deadline = time.monotonic() + 60
            while (self.run_installed("rostopic", "list", check=False, env=env).returncode != 0
                   and launch.poll() is None and time.monotonic() < deadline):
                time.sleep(0.5)
            # The first start reduces the tracked model (seconds) and caches it under $ROS_HOME.
            echo = self.run_installed("rostopic", "echo", "-n", "1", "/tf", timeout=120,
                                      check=False, env=env)
            alive = launch.poll() is None
        finally:
            os.killpg(launch.pid, 2)  # SIGINT: roslaunch shuts its nodes and master down
            try:
                log, _ = launch.communicate(timeout=60)
            except subprocess.TimeoutExpired:
                # roslaunch starts the master and nodes in sessions of their own: end them by
                # what they run.
                os.killpg(launch.pid, 9)
                subprocess.run(["pkill", "-9", "-f", f"-p {port}|{self.prefix}"], check=False)
                log, _ = launch.communicate()
        self.assertTrue(alive, f"roslaunch stopped:\n{log}")
        self.assertEqual(echo.returncode, 0, f"{echo.stdout}\n{echo.stderr}\n{log}")
        self.assertIn('child_frame_id: "base_link"', echo.stdout, echo.stdout)
        # Nothing was written into the install (as root the read-only mode does not stop a
        # write: the listing does).
        self.assertEqual(self.listing(self.stage), before)
        cache = os.path.join(self.ros_home, PACKAGE)
        self.assertTrue(os.path.isdir(cache) and any(f.endswith(".mat") for f in os.listdir(cache)),
                        f"no reduced model cached under {cache}:\n{log}")


if __name__ == "__main__":
    raise SystemExit(junit_runner.main(InstallSpaceTest, "install_space", __doc__,
                                       argv=[a for a in sys.argv[1:] if a != "--keep"],
                                       paths={"--build": "the configured and built tree"}))
