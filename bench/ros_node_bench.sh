#!/usr/bin/env bash
# Performance of vehicle_dynamics_node against its targets (issue 6): at 1 kHz <= 10 % of one
# core, step time p99 <= 100 us, latency message -> tf <= 2 ms.
#
#   bench/ros_node_bench.sh            # environment: BUILD_DIR (build), VARIANT (tracked),
#                                      # TRACK (long_hill), SPEED_KMH (30), PUBLISH_RATE (1000),
#                                      # LAPS (3), SKIP_BUILD=1
# 1. offline: OnlineVehicle::step() on the track without ROS (ros_node_bench offline).
# 2. node: a private ROS master, the node on real time at 1 kHz, and the load driver
#    (ros_node_bench node) publishing the track's terrain patches at the vehicle's pace and the
#    speed at 50 Hz, LAPS times over the track (the node reset between laps); it measures the
#    node's CPU use (/proc, per thread too), the latency from a speed message to the first
#    published sample stepped with it, and reads the node's step-time diagnostics.
# 3. the floor: the same driver against `ros_node_bench bare`, a stand-in with the node's topics
#    and tick that computes nothing: what roscpp and the kernel take at this rate.
# 4. the same stand-in ticking in a thread of its own: what the network-thread tick saves.
# Timings depend on the machine's load: run it on a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="/usr/bin:$PATH"
BUILD_DIR="${BUILD_DIR:-build}"
VARIANT="${VARIANT:-tracked}"
TRACK="${TRACK:-long_hill}"
SPEED_KMH="${SPEED_KMH:-30}"
PUBLISH_RATE="${PUBLISH_RATE:-1000}"
LAPS="${LAPS:-3}"
VEHICLE="$(pwd)/config/vehicles/paper_vehicle.yaml"
CACHE="${CACHE:-/tmp/tvd_bench_cache}"

# shellcheck source=scripts/ros_env.sh
source scripts/ros_env.sh
ros_setup "$BUILD_DIR" vehicle_dynamics_node ros_node_bench
bench="$(catkin_find --without-underlays --libexec tracked_vehicle_dynamics ros_node_bench | head -n 1)"
node="$(catkin_find --without-underlays --libexec tracked_vehicle_dynamics vehicle_dynamics_node | head -n 1)"

echo "== 1. OnlineVehicle::step, no ROS ($VARIANT, $TRACK at $SPEED_KMH km/h, 1 kHz)"
"$bench" offline --vehicle "$VEHICLE" --variant "$VARIANT" --cache-dir "$CACHE" \
  --track "$TRACK" --speed-kmh "$SPEED_KMH"

echo
echo "== 2. The node on real time at 1 kHz with a load driver"
port=$((20000 + RANDOM % 10000))
export ROS_MASTER_URI="http://localhost:$port"
log_dir="$(mktemp -d /tmp/tvd_bench.XXXXXX)"
roscore -p "$port" >"$log_dir/roscore.log" 2>&1 &
roscore_pid=$!
node_pid=""
cleanup() {
  [ -n "$node_pid" ] && kill -INT "$node_pid" 2>/dev/null || true
  [ -n "$node_pid" ] && wait "$node_pid" 2>/dev/null || true
  kill -INT "$roscore_pid" 2>/dev/null || true
  wait "$roscore_pid" 2>/dev/null || true
}
trap cleanup EXIT
wait_for_master
rosparam set /vehicle_dynamics/vehicle "$VEHICLE"
rosparam set /vehicle_dynamics/variant "$VARIANT"
rosparam set /vehicle_dynamics/cache_dir "$CACHE"
rosparam set /vehicle_dynamics/publish_rate "$PUBLISH_RATE"
# Runs a node-like process in the background (its log: $log_dir/$1.log) under the load driver,
# then stops it.
drive() {
  local log="$1"
  shift
  "$@" __name:=vehicle_dynamics >"$log_dir/$log.log" 2>&1 &
  node_pid=$!
  "$bench" node --pid "$node_pid" --track "$TRACK" --speed-kmh "$SPEED_KMH" --laps "$LAPS"
  kill -INT "$node_pid" 2>/dev/null || true
  wait "$node_pid" 2>/dev/null || true
  node_pid=""
}

echo "(node: $VARIANT, rate 1000 Hz, publish_rate $PUBLISH_RATE Hz; the driver subscribes road_wheels)"
drive node "$node"

echo
echo "== 3. The floor: a bare stand-in with the node's topics and tick, computing nothing"
echo "(ros_node_bench bare: a timerfd in roscpp's network thread takes the messages and publishes"
echo " a 14-wheel sample at $PUBLISH_RATE Hz; the same driver. The node's CPU above this is the model's.)"
drive bare "$bench" bare --rate "$PUBLISH_RATE"

echo
echo "== 4. The same stand-in ticking in a thread of its own (clock_nanosleep), the other design"
drive bare_thread "$bench" bare --own-thread --rate "$PUBLISH_RATE"
echo "(logs in $log_dir)"
