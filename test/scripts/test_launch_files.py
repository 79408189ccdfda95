#!/usr/bin/python3
"""Tests of launch/vehicle_dynamics.launch and launch/replay_track.launch without a master.

`roslaunch --dump-params` resolves a launch file's parameters and `roslaunch --args NODE` a node's
command line, both offline. What they must show: the node's parameter file (config:=FILE) is in
force unless an argument is given on the command line, the arguments then win, replay_track passes
its arguments through, and its recorder keeps /tf_static (the named points' frames). Run as
    /usr/bin/python3 test/scripts/test_launch_files.py --env-sh DEVEL/env.sh [--xml OUTDIR/launch_files.xml]
"""
import os
import re
import shlex
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import unittest

import yaml

import junit_runner

PACKAGE = "tracked_vehicle_dynamics"
NODE = "/vehicle_dynamics"
# replay_track.launch's player (run from the source tree, as rosrun runs it from the devel space)
PLAY_TRACK_BAG = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), "scripts", "play_track_bag.sh")
ENV_SH = None  # set from --env-sh: the devel space's env.sh, which finds the package


def roslaunch(*args):
    result = subprocess.run([ENV_SH, "roslaunch", *args], capture_output=True, text=True,
                            timeout=120)
    if result.returncode != 0:
        raise AssertionError(f"roslaunch {' '.join(args)} failed:\n{result.stdout}\n{result.stderr}")
    return result.stdout


def params(launch_file, *args):
    """The node's private parameters as roslaunch would set them: {name: value}."""
    dumped = yaml.safe_load(roslaunch("--dump-params", PACKAGE, launch_file, *args))
    return {key[len(NODE) + 1:]: value for key, value in dumped.items() if key.startswith(NODE + "/")}


def make_track_bag(track, speed, bag_dir, env=None):
    """play_track_bag.sh TRACK SPEED BAG_DIR with TVD_BAG_MAKE_ONLY=1 (the bag written when needed,
    its path printed, nothing played), in `env` (default: this process's) plus that variable."""
    return subprocess.run([ENV_SH, PLAY_TRACK_BAG, track, speed, bag_dir],
                          env=dict(env if env is not None else os.environ, TVD_BAG_MAKE_ONLY="1"),
                          capture_output=True, text=True, timeout=120)


def private_master(ros_home):
    """A free local port for a master of this test alone (parallel tests must not share one) and
    the environment that points ROS at it, with its own ROS_HOME: (port, env)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    return port, dict(os.environ, ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_IP="127.0.0.1",
                      ROS_HOME=ros_home)


def cleared_namespaces(launch_file):
    """The namespaces roslaunch deletes from the master before setting the launch's parameters."""
    code = ("import sys, rospkg, roslaunch.config\n"
            "path = rospkg.RosPack().get_path(sys.argv[1]) + '/launch/' + sys.argv[2]\n"
            "print('\\n'.join(roslaunch.config.load_config_default([path], None).clear_params))\n")
    result = subprocess.run([ENV_SH, "/usr/bin/python3", "-c", code, PACKAGE, launch_file],
                            capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        raise AssertionError(f"loading {launch_file} failed:\n{result.stdout}\n{result.stderr}")
    return result.stdout.split()


def launch_nodes(launch_path, *args):
    """The nodes of a launch file (a path) as roslaunch would start them, with these args:
    {resolved name: roslaunch.core.Node}."""
    code = ("import sys, roslaunch.config\n"
            "c = roslaunch.config.load_config_default([(sys.argv[1], sys.argv[2:])], None)\n"
            "for n in c.nodes:\n"
            "    print(repr((n.namespace + n.name, n.required, n.respawn, n.respawn_delay,\n"
            "                n.remap_args, n.launch_prefix, n.env_args)))\n")
    result = subprocess.run([ENV_SH, "/usr/bin/python3", "-c", code, launch_path, *args],
                            capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        raise AssertionError(f"loading {launch_path} failed:\n{result.stdout}\n{result.stderr}")
    import ast
    return {n[0]: n[1:] for n in map(ast.literal_eval, result.stdout.splitlines())}


def launch_path(launch_file):
    return os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__)))), "launch", launch_file)


class LaunchFilesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp(prefix="tvd_launch_")
        # A user's edited copy of the parameter file: other values than the defaults.
        cls.config = os.path.join(cls.work, "my_vehicle_dynamics.yaml")
        with open(cls.config, "w") as f:
            yaml.safe_dump({"variant": "untracked", "rate": 500.0, "lateral_offset": 0.75,
                            "max_speed": 12.0, "comfort_point": "sensor_mount",
                            "points": ["crew_seat"]}, f)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_defaults_come_from_the_bundled_parameter_file(self):
        p = params("vehicle_dynamics.launch")
        self.assertEqual(p["variant"], "tracked")
        self.assertEqual(p["rate"], 1000.0)
        self.assertEqual(p["lateral_offset"], 0.0)
        self.assertTrue(p["vehicle"].endswith("config/vehicles/paper_vehicle.yaml"))
        self.assertNotIn("cache_dir", p)  # the node's own default
        # The node's default: crew_seat when the vehicle names one, else hull (any vehicle starts).
        self.assertNotIn("comfort_point", p)
        self.assertNotIn("points", p)  # the node's default: every named point
        # Derived rates: the node's defaults, capped at ~rate (a slow ~rate must not trip on them).
        self.assertNotIn("comfort_rate", p)
        self.assertNotIn("ground_contact_rate", p)

    def test_speed_timeout_argument(self):
        self.assertEqual(params("vehicle_dynamics.launch")["speed_timeout"], 0.0)  # the file's
        p = params("vehicle_dynamics.launch", "speed_timeout:=0.5")
        self.assertEqual(p["speed_timeout"], 0.5)
        self.assertIsInstance(p["speed_timeout"], float)

    def test_an_edited_parameter_file_is_not_overridden_by_argument_defaults(self):
        p = params("vehicle_dynamics.launch", f"config:={self.config}")
        self.assertEqual((p["variant"], p["rate"], p["lateral_offset"], p["max_speed"]),
                         ("untracked", 500.0, 0.75, 12.0))
        self.assertEqual((p["comfort_point"], p["points"]), ("sensor_mount", ["crew_seat"]))

    def test_arguments_given_win_over_the_parameter_file(self):
        p = params("vehicle_dynamics.launch", f"config:={self.config}", "variant:=tracked",
                   "rate:=200", "lateral_offset:=-1", "cache_dir:=/tmp/tvd_cache")
        self.assertEqual((p["variant"], p["rate"], p["lateral_offset"], p["cache_dir"]),
                         ("tracked", 200.0, -1.0, "/tmp/tvd_cache"))
        self.assertIsInstance(p["rate"], float)  # the node reads a double
        self.assertEqual(p["max_speed"], 12.0)   # the rest of the file still applies

    def test_publish_rate_and_use_sim_time_arguments(self):
        dumped = yaml.safe_load(roslaunch("--dump-params", PACKAGE, "vehicle_dynamics.launch"))
        self.assertNotIn("/use_sim_time", dumped)  # left as it is on the master
        self.assertNotIn(NODE + "/publish_rate", dumped)  # the file's (commented out: ~rate)
        dumped = yaml.safe_load(roslaunch("--dump-params", PACKAGE, "vehicle_dynamics.launch",
                                          "publish_rate:=100", "use_sim_time:=true"))
        self.assertIs(dumped["/use_sim_time"], True)
        self.assertEqual(dumped[NODE + "/publish_rate"], 100.0)
        self.assertIsInstance(dumped[NODE + "/publish_rate"], float)  # the node reads a double
        self.assertIs(yaml.safe_load(roslaunch("--dump-params", PACKAGE, "vehicle_dynamics.launch",
                                               "use_sim_time:=false"))["/use_sim_time"], False)
        # replay_track passes it through.
        p = params("replay_track.launch", "publish_rate:=250")
        self.assertEqual(p["publish_rate"], 250.0)

    def test_comfort_point_and_points_given_win_over_the_parameter_file(self):
        p = params("vehicle_dynamics.launch", "comfort_point:=hull")
        self.assertEqual(p["comfort_point"], "hull")
        p = params("vehicle_dynamics.launch", f"config:={self.config}", "comfort_point:=crew_seat",
                   "points:=[sensor_mount, crew_seat]")
        self.assertEqual((p["comfort_point"], p["points"]),
                         ("crew_seat", ["sensor_mount", "crew_seat"]))
        p = params("vehicle_dynamics.launch", f"config:={self.config}", "points:=[]")
        self.assertEqual(p["points"], [])  # no named point as a frame
        self.assertEqual(p["comfort_point"], "sensor_mount")
        # A point named like a number stays a string (the node reads a string).
        self.assertEqual(params("vehicle_dynamics.launch", "comfort_point:=1")["comfort_point"],
                         "1")

    def test_replay_track_passes_its_arguments_and_config_through(self):
        p = params("replay_track.launch", f"config:={self.config}")
        self.assertEqual((p["variant"], p["rate"], p["lateral_offset"]), ("untracked", 500.0, 0.75))
        self.assertEqual((p["comfort_point"], p["points"]), ("sensor_mount", ["crew_seat"]))
        p = params("replay_track.launch", f"config:={self.config}", "rate:=250",
                   "comfort_point:=hull", "points:=[sensor_mount]")
        self.assertEqual((p["rate"], p["comfort_point"], p["points"]),
                         (250.0, "hull", ["sensor_mount"]))
        p = params("replay_track.launch")
        self.assertNotIn("comfort_point", p)
        self.assertNotIn("points", p)
        # A shipped reduced model, the frames of a multi-vehicle stack and the driver timeout.
        p = params("replay_track.launch", "reduced_model:=/tmp/m.mat", "frame_prefix:=veh1/",
                   "footprint_frame:=base_footprint", "publish_odom_tf:=false", "speed_timeout:=0.5")
        self.assertEqual((p["reduced_model"], p["frame_prefix"], p["footprint_frame"],
                          p["publish_odom_tf"], p["speed_timeout"]),
                         ("/tmp/m.mat", "veh1/", "base_footprint", False, 0.5))

    def test_replay_track_loops_on_request(self):
        # loop:=true hands --loop on to rosbag play (through play_track_bag.sh); not by default.
        player = shlex.split(roslaunch("--args", "track_player", PACKAGE, "replay_track.launch"))
        self.assertNotIn("--loop", player)
        self.assertIn("--wait-for-subscribers", player)
        player = shlex.split(roslaunch("--args", "track_player", PACKAGE, "replay_track.launch",
                                       "loop:=true"))
        self.assertIn("--loop", player)

    def test_respawn_makes_the_node_not_required(self):
        # roslaunch refuses a node both required and respawning: respawn:=true drops required.
        path = launch_path("vehicle_dynamics.launch")
        for args, flags in (((), (True, False, 1.0)), (("respawn:=true",), (False, True, 1.0)),
                            (("respawn:=true", "respawn_delay:=3"), (False, True, 3.0)),
                            (("required:=false",), (False, False, 1.0))):
            self.assertEqual(launch_nodes(path, *args)[NODE][:3], flags, args)

    def test_launch_prefix_runs_the_node_under_a_command(self):
        # launch_prefix:=COMMAND reaches the node's launch-prefix (chrt, taskset, gdb); none by
        # default (roslaunch reads the empty attribute as none).
        path = launch_path("vehicle_dynamics.launch")
        self.assertFalse(launch_nodes(path)[NODE][4])
        self.assertEqual(launch_nodes(path, "launch_prefix:=taskset -c 1")[NODE][4], "taskset -c 1")

    def test_replay_track_in_a_namespace(self):
        # Included under <group ns="veh1">: /use_sim_time stays global, the player plays the bag's
        # absolute topics into the namespace, the recorder records the namespace's topics.
        wrapper = os.path.join(self.work, "replay_in_ns.launch")
        with open(wrapper, "w") as f:
            f.write('<launch><group ns="veh1"><include file="' + launch_path("replay_track.launch")
                    + '"><arg name="frame_prefix" value="veh1/"/><arg name="ns" value="/veh1"/>'
                    '<arg name="imu_points" value="[sensor_mount]"/></include></group></launch>')
        dumped = yaml.safe_load(roslaunch("--dump-params", wrapper))
        self.assertIs(dumped.get("/use_sim_time"), True)
        self.assertNotIn("/veh1/use_sim_time", dumped)
        self.assertEqual(dumped["/veh1/vehicle_dynamics/frame_prefix"], "veh1/")
        nodes = launch_nodes(wrapper)
        self.assertEqual(sorted(nodes), ["/veh1/output_recorder", "/veh1/track_player",
                                         "/veh1/vehicle_dynamics"])
        remaps = dict(nodes["/veh1/track_player"][3])
        # (resolved by the player in its namespace, /veh1/terrain_profile)
        # and its relative "clock" to the master's /clock.
        self.assertEqual({k: remaps[k] for k in ("/terrain_profile", "/speed_stamped", "/speed",
                                                 "clock")},
                         {"/terrain_profile": "terrain_profile", "/speed_stamped": "speed_stamped",
                          "/speed": "speed",
                          "clock": "/clock"})
        recorder = shlex.split(roslaunch("--args", "/veh1/output_recorder", wrapper))
        for topic in ("/tf", "/tf_static", "/diagnostics", "/veh1/odom", "/veh1/road_wheels",
                      "/veh1/comfort", "/veh1/imu/sensor_mount"):
            self.assertIn(topic, recorder)
        self.assertNotIn("/odom", recorder)
        # The player is told where the recorder records (and refuses another namespace, below);
        # not when nothing is recorded.
        self.assertEqual(dict(nodes["/veh1/track_player"][5])["TVD_RECORD_NS"], "/veh1")
        replay = launch_path("replay_track.launch")
        self.assertEqual(dict(launch_nodes(replay)["/track_player"][5])["TVD_RECORD_NS"], "")
        self.assertNotIn("TVD_RECORD_NS",
                         dict(launch_nodes(replay, "record:=false")["/track_player"][5]))

    def test_player_refuses_a_namespace_the_recorder_does_not_record(self):
        # replay_track.launch included in /veh1 without ns:= would record /odom ..., none of its
        # node's topics, without a word (review 165): the player stops it before any bag is
        # made. ROS_NAMESPACE as roslaunch sets it (with or without the trailing slash).
        # A relative ns is refused too: the recorder would resolve veh1/odom in /veh1, as
        # /veh1/veh1/odom.
        bag_dir = os.path.join(self.work, "ns_bags")
        for ns, recorded, said in (
                ("/veh1/", "", ["runs in the namespace /veh1 but its ns argument is ''",
                                "include it with ns:=/veh1"]),
                ("/veh1", "veh1", ["ns argument 'veh1' must be a global name",
                                   "this launch runs in /veh1: give ns:=/veh1"])):
            result = make_track_bag("long_hill", "30", bag_dir,
                                    dict(os.environ, ROS_NAMESPACE=ns, TVD_RECORD_NS=recorded))
            self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
            for words in said:
                self.assertIn(words, result.stderr)
            self.assertFalse(os.path.exists(bag_dir))
        for ns, recorded in (("/veh1", "/veh1/"), ("/", ""), ("/", "/"), ("/a/b", "/a/b")):
            result = make_track_bag("long_hill", "30", bag_dir,
                                    dict(os.environ, ROS_NAMESPACE=ns, TVD_RECORD_NS=recorded))
            self.assertEqual(result.returncode, 0, (ns, recorded, result.stderr))

    def test_parameters_of_an_earlier_launch_are_cleared(self):
        # Without clear_params a parameter the launch does not set (reduced_model, cache_dir,
        # points: not in the parameter file) would keep an earlier launch's value on the master.
        for launch_file in ("vehicle_dynamics.launch", "replay_track.launch"):
            self.assertEqual(cleared_namespaces(launch_file), [NODE + "/"], launch_file)

    def test_replay_track_records_the_static_frames(self):
        recorder = shlex.split(roslaunch("--args", "output_recorder", PACKAGE, "replay_track.launch"))
        # Global names: rosbag record stores a relative name as given, without its namespace.
        topics = ["/tf", "/tf_static", "/odom", "/hull/accel", "/hull/twist", "/road_wheels",
                  "/comfort", "/diagnostics"]
        for topic in topics:
            self.assertIn(topic, recorder)
        # Listed, not matched by a regex (found on a ROS-time timer: late on simulated time).
        self.assertNotIn("--regex", recorder)
        self.assertNotIn("-e", recorder)
        self.assertFalse([t for t in recorder if "imu/" in t])
        recorder = shlex.split(roslaunch("--args", "output_recorder", PACKAGE, "replay_track.launch",
                                         "imu_points:=[sensor_mount, 'crew_seat']"))
        self.assertEqual([t for t in recorder if t.startswith("/imu/")],
                         ["/imu/sensor_mount", "/imu/crew_seat"])
        self.assertEqual(recorder[recorder.index("-O") + 1].rsplit("/", 1)[-1],
                         "long_hill_30kmh_output.bag")
        # A terrain or speed-profile file is named by its stem (a path would name a directory).
        for args, name in ((["track:=/tmp/road_c.csv"], "road_c_30kmh_output.bag"),
                           (["speed_kmh:=/tmp/profiles/braking.csv"], "long_hill_braking_output.bag"),
                           (["track:=half_round:0.2", "speed_kmh:=12.5"], "half_round:0.2_12.5kmh_output.bag")):
            recorder = shlex.split(roslaunch("--args", "output_recorder", PACKAGE, "replay_track.launch",
                                             "bag_dir:=/tmp/bags", *args))
            self.assertEqual(recorder[recorder.index("-O") + 1], "/tmp/bags/" + name, args)

    def test_each_terrain_file_gets_a_track_bag_of_its_own(self):
        # replay_track.launch's player names a terrain file's bag by the file's stem.
        bag_dir = os.path.join(self.work, "bags")
        roads = {}
        for sub, rows in (("bump", "0,0\n10,0\n10.5,0.2\n11,0\n30,0\n"), ("flat", "0,0\n30,0\n")):
            os.makedirs(os.path.join(self.work, sub), exist_ok=True)
            roads[sub] = os.path.join(self.work, sub, "road.csv")
            with open(roads[sub], "w") as f:
                f.write("x,h\n" + rows)
            os.utime(roads[sub], (1e9, 1e9))  # both older than any bag written below

        def make(track, writes=True):
            result = make_track_bag(track, "20", bag_dir)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            # The path alone on stdout (bag=$(...)); tvd_make_bag's summary, when it wrote the
            # bag, on stderr, naming the bag rather than the temporary file it wrote first.
            self.assertEqual(len(result.stdout.splitlines()), 1, result.stdout)
            bag = result.stdout.strip()
            if writes:
                self.assertIn(bag + ": ", result.stderr)
                self.assertIn("terrain patches", result.stderr)
                self.assertNotIn(os.path.join(bag_dir, "."), result.stderr)  # the temporary file
            else:
                self.assertNotIn("terrain patches", result.stderr)
            # NAME_SPEEDkmh.HASH.bag: the hash names the file's path and content.
            self.assertRegex(bag, "^" + re.escape(os.path.join(bag_dir, "road_20kmh.")) +
                             "[0-9a-f]{8}[.]bag$")
            with open(bag + ".source") as f:
                return bag, f.read(), os.stat(bag).st_mtime_ns

        flat, flat_source, _ = make(roads["flat"])
        self.assertIn(os.path.realpath(roads["flat"]) + " sha256:", flat_source)
        bump, bump_source, written = make(roads["bump"])  # same stem, older file
        self.assertIn(os.path.realpath(roads["bump"]) + " sha256:", bump_source)
        self.assertNotEqual(bump, flat)
        with open(bump, "rb") as f, open(flat, "rb") as g:
            self.assertNotEqual(f.read(), g.read())
        self.assertEqual(make(roads["bump"], writes=False),
                         (bump, bump_source, written))  # not rewritten
        with open(roads["bump"], "a") as f:  # edited, its old time stamp kept (cp -p, a checkout)
            f.write("31,0\n")
        os.utime(roads["bump"], (1e9, 1e9))
        edited, edited_source, _ = make(roads["bump"])
        self.assertNotEqual(edited, bump)
        self.assertNotEqual(edited_source, bump_source)
        # A built-in track keeps its plain name.
        result = make_track_bag("half_round:0.1", "20", bag_dir)
        self.assertEqual(result.stdout, os.path.join(bag_dir, "half_round:0.1_20kmh.bag") + "\n",
                         result.stderr)

    def test_a_bag_that_cannot_be_made_leaves_nothing_behind(self):
        # tvd_make_bag's own message and status; no temporary bag, record or summary left.
        bag_dir = os.path.join(self.work, "failed_bags")
        road = os.path.join(self.work, "broken.csv")
        with open(road, "w") as f:
            f.write("x,h\n0,0\n10,nan\n30,0\n")
        tmp = os.path.join(self.work, "failed_tmp")
        os.makedirs(tmp)
        result = make_track_bag(road, "20", bag_dir, dict(os.environ, TMPDIR=tmp))
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        self.assertEqual(result.stdout, "")
        self.assertIn("tvd_make_bag: error: ", result.stderr)
        self.assertIn("broken.csv", result.stderr)
        self.assertEqual((os.listdir(bag_dir), os.listdir(tmp)), ([], []))

    def test_the_player_refuses_a_bag_faster_than_the_nodes_max_speed(self):
        # Else the node rejects every speed message and the replay records a vehicle at rest.
        port, env = private_master(os.path.join(self.work, "ros_home"))
        master = subprocess.Popen([ENV_SH, "rosmaster", "--core", "-p", str(port)], env=env,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                  start_new_session=True)
        try:
            deadline = time.monotonic() + 30
            while subprocess.run([ENV_SH, "rosparam", "set", "/ns/vehicle_dynamics/max_speed",
                                  "20.0"], env=env, capture_output=True).returncode != 0:
                self.assertLess(time.monotonic(), deadline, "no master")
                time.sleep(0.3)

            def play(speed):
                return make_track_bag("half_round:0.1", speed, os.path.join(self.work, "fast_bags"),
                                      dict(env, ROS_NAMESPACE="/ns",
                                           TVD_REPLAY_NODE="vehicle_dynamics"))

            fast = play("80")  # 22.2 m/s
            self.assertEqual(fast.returncode, 2, fast.stdout + fast.stderr)
            self.assertIn("the bag drives at 80 km/h, above vehicle_dynamics's ~max_speed 20.0 "
                          "m/s (72 km/h)", fast.stderr)
            self.assertTrue(play("72").returncode == 0)  # at the limit
            # A profile is judged by its fastest sample, read as tvd_make_bag reads it.
            profile = os.path.join(self.work, "surge.csv")
            with open(profile, "w") as f:
                f.write("# speed up, then brake\ntime_s,speed_kmh\n0,30\n2,75\n4,30\n")
            fast = play(profile)
            self.assertEqual(fast.returncode, 2, fast.stdout + fast.stderr)
            self.assertIn(f"the bag reaches 75 km/h (speed profile {profile}), above "
                          "vehicle_dynamics's ~max_speed 20.0 m/s (72 km/h)", fast.stderr)
            with open(profile, "w") as f:
                f.write("time_s,speed_kmh\n0,30\n2,72\n4,30\n")
            slow = play(profile)
            self.assertEqual(slow.returncode, 0, slow.stdout + slow.stderr)
        finally:
            os.killpg(master.pid, 15)
            master.wait(timeout=30)

    def test_replay_ends_when_the_node_dies_at_start_up(self):
        # The node is required: a FATAL parameter ends the whole launch (player and recorder
        # included), at once, instead of a player waiting on a node that never comes.
        port, env = private_master(os.path.join(self.work, "ros_home_required"))
        start = time.monotonic()
        launch = subprocess.Popen([ENV_SH, "roslaunch", "-p", str(port), PACKAGE,
                                   "replay_track.launch", "comfort_point:=nowhere", "record:=false",
                                   "bag_dir:=" + os.path.join(self.work, "required_bags")],
                                  env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  text=True, start_new_session=True)
        try:
            output, _ = launch.communicate(timeout=120)
        finally:
            # The launch's whole process group (master, player): left running, they would
            # outlive a failure of this test.
            try:
                os.killpg(launch.pid, 15)
            except ProcessLookupError:
                pass
            launch.wait(timeout=30)
        elapsed = time.monotonic() - start
        self.assertIn("unknown point 'nowhere'", output)
        self.assertIn("REQUIRED process [vehicle_dynamics", output)
        self.assertIn("[track_player", output)  # started, then ended with the launch
        self.assertLess(elapsed, 60.0, output)

    def test_tvd_make_bag_command_line(self):
        # Errors: status 2 and one line naming the option; --peak-speed: the run's fastest speed
        # in m/s, nothing written.
        def make_bag(*args):
            return subprocess.run([ENV_SH, "rosrun", PACKAGE, "tvd_make_bag", *args],
                                  capture_output=True, text=True, timeout=120, cwd=self.work)

        for args, expected in [(["--speed-kmh", "500", "--out", "x.bag"],
                                "tvd_make_bag: error: --speed-kmh must be in (0, 200], got 500"),
                               (["--speed-kmh", "abc", "--out", "x.bag"],
                                "tvd_make_bag: error: --speed-kmh: 'abc' is not a number"),
                               (["--trak", "long_hill", "--out", "x.bag"],
                                "tvd_make_bag: error: unknown option --trak (did you mean --track?)"),
                               (["--speed-message", "twist", "--out", "x.bag"],
                                "tvd_make_bag: error: --speed-message: twist not in "
                                "{stamped,float64}"),
                               (["--out"], "tvd_make_bag: error: --out needs a value after it"),
                               (["---"], "tvd_make_bag: error: unknown option --- ("),
                               (["-=1"], "tvd_make_bag: error: unknown option - ("),
                               (["--speed-kmh", "30"], "tvd_make_bag: error: --out is required"),
                               (["--lookahead", "", "--out", "x.bag"],
                                "tvd_make_bag: error: --lookahead: '' is not a number"),
                               (["--out", "x.txt"], "'x.txt' must end in .bag"),
                               (["--start-time", "1e-308", "--out", "x.bag"],
                                "start_time = 1e-308 must be in [1e-9, 4e9) s")]:
            result = make_bag(*args)
            self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
            self.assertIn(expected, result.stderr)
            self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
        for ns in ("veh1", "/", "/veh 1"):
            result = make_bag("--namespace", ns, "--out", "x.bag")
            self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
            self.assertIn("tvd_make_bag: error: --namespace must be a global namespace such as "
                          "/veh1", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.work, "x.bag")))
        # A bag over its own terrain file or speed profile is refused, and the input left as it
        # was: by its extension, or (an input named .bag) as the same file however spelt.
        track = os.path.join(self.work, "own_track.csv")
        with open(track, "w") as f:
            f.write("x,h\n0,0\n10,0.1\n20,0\n")
        profile = os.path.join(self.work, "own_profile.bag")
        with open(profile, "w") as f:
            f.write("time_s,speed_kmh\n0,30\n5,30\n")
        for args, path, expected in (
                (["--track", track, "--out", track], track, f"--out: '{track}' must end in .bag"),
                (["--track", profile, "--out", "./own_profile.bag"], profile,
                 "--out ./own_profile.bag is the --track file: writing it would destroy the input"),
                (["--speed-profile", profile, "--out", profile], profile,
                 f"--out {profile} is the --speed-profile file: writing it would destroy the "
                 "input")):
            with open(path) as f:
                before = f.read()
            result = make_bag(*args)
            self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
            self.assertIn("tvd_make_bag: error: " + expected, result.stderr)
            with open(path) as f:
                self.assertEqual(f.read(), before)
        # --namespace: the topics of a vehicle in it, for one player of several vehicles' bags.
        # The speed as geometry_msgs/TwistStamped on speed_stamped, or with --speed-message
        # float64 as std_msgs/Float64 on speed.
        for extra, speed in (([], ("/veh1/speed_stamped", "geometry_msgs/TwistStamped")),
                             (["--speed-message", "float64"], ("/veh1/speed", "std_msgs/Float64"))):
            result = make_bag("--namespace", "/veh1/", "--out", "ns.bag", *extra)
            self.assertEqual(result.returncode, 0, result.stderr)
            info = subprocess.run([ENV_SH, "rosbag", "info", "--yaml", "--key", "topics",
                                   os.path.join(self.work, "ns.bag")], capture_output=True,
                                  text=True, timeout=120)
            self.assertEqual(sorted((t["topic"], t["type"]) for t in yaml.safe_load(info.stdout)),
                             sorted([speed, ("/veh1/terrain_profile",
                                             "tracked_vehicle_dynamics/TerrainProfile")]),
                             info.stderr)
        result = make_bag("--speed-kmh", "90", "--peak-speed")
        self.assertEqual((result.returncode, float(result.stdout)), (0, 25.0), result.stderr)
        profile = os.path.join(self.work, "peak.csv")
        with open(profile, "w") as f:
            f.write("time_s,speed_m_s\n0,5\n3,17.5\n6,2\n")
        result = make_bag("--speed-profile", profile, "--peak-speed")
        self.assertEqual((result.returncode, float(result.stdout)), (0, 17.5), result.stderr)
        # The run is checked as for writing: a profile above 200 km/h could not be made.
        with open(profile, "w") as f:
            f.write("time_s,speed_kmh\n0,30\n3,250\n")
        result = make_bag("--speed-profile", profile, "--peak-speed")
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        self.assertIn(f"tvd_make_bag: error: {profile}: the speed profile reaches 250 km/h; at "
                      "most 200 km/h", result.stderr)
        # It writes nothing, so it takes no file to write.
        result = make_bag("--speed-kmh", "30", "--peak-speed", "--out", "x.bag")
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        self.assertIn("tvd_make_bag: error: ", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.work, "x.bag")))

    def test_footprint_frame_and_publish_odom_tf(self):
        p = params("vehicle_dynamics.launch")
        self.assertEqual((p["footprint_frame"], p["publish_odom_tf"]), ("", True))  # the file's
        p = params("vehicle_dynamics.launch",
                   "footprint_frame:=base_footprint", "publish_odom_tf:=false")
        self.assertEqual((p["footprint_frame"], p["publish_odom_tf"]), ("base_footprint", False))
        self.assertIsInstance(p["publish_odom_tf"], bool)  # the node reads a boolean

    def test_imu_points_are_passed_through(self):
        self.assertEqual(params("vehicle_dynamics.launch")["imu_points"], [])  # the file's: none
        self.assertEqual(params("vehicle_dynamics.launch", "imu_points:=[sensor_mount]")["imu_points"],
                         ["sensor_mount"])
        self.assertEqual(params("replay_track.launch", "imu_points:=[crew_seat, sensor_mount]")
                         ["imu_points"], ["crew_seat", "sensor_mount"])

    def test_speed_slew_rates_are_passed_through(self):
        p = params("vehicle_dynamics.launch")
        self.assertEqual((p["max_acceleration"], p["max_deceleration"]), (0.0, 0.0))  # the file's
        p = params("vehicle_dynamics.launch", "max_acceleration:=1.5", "max_deceleration:=3")
        self.assertEqual((p["max_acceleration"], p["max_deceleration"]), (1.5, 3.0))
        self.assertIsInstance(p["max_deceleration"], float)  # the node reads a number
        p = params("replay_track.launch", "max_acceleration:=1", "max_deceleration:=2.5")
        self.assertEqual((p["max_acceleration"], p["max_deceleration"]), (1.0, 2.5))

    def test_initial_speed_is_passed_through_in_its_units(self):
        self.assertEqual(params("vehicle_dynamics.launch")["initial_speed"], 0.0)  # the file's
        p = params("vehicle_dynamics.launch", "initial_speed:=5")
        self.assertEqual(p["initial_speed"], 5.0)
        self.assertIsInstance(p["initial_speed"], float)
        # The replay takes km/h, as its speed_kmh: 50 km/h is 50 / 3.6 m/s.
        p = params("replay_track.launch", "initial_speed_kmh:=50")
        self.assertAlmostEqual(p["initial_speed"], 50 / 3.6, places=12)
        p = params("replay_track.launch", "initial_speed_kmh:=12.6")
        self.assertAlmostEqual(p["initial_speed"], 3.5, places=12)
        self.assertEqual(params("replay_track.launch")["initial_speed"], 0.0)


if __name__ == "__main__":
    sys.exit(junit_runner.main(LaunchFilesTest, "launch_files", __doc__,
                               paths={"--env-sh": "the devel space's env.sh"}))
