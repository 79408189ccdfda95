#!/usr/bin/env bash
# The ROS demo: builds the node, starts a ROS master if none is running, launches
# vehicle_dynamics_node on the default vehicle (config/vehicles/paper_vehicle.yaml) on simulated
# time, replays the long-hill track at 30 km/h from a rosbag, records the node's outputs, and
# prints a short summary (peaks, comfort, real-time figures) with a PNG plot.
#
#   scripts/ros_demo.sh            # environment: TRACK, SPEED_KMH, VARIANT, OUT, BUILD_DIR,
#                                  # IMU_POINTS (default [sensor_mount]: a simulated IMU there),
#                                  # SKIP_BUILD=1 to use an existing build
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="/usr/bin:$PATH"
BUILD_DIR="${BUILD_DIR:-build}"
TRACK="${TRACK:-long_hill}"
SPEED_KMH="${SPEED_KMH:-30}"
VARIANT="${VARIANT:-tracked}"
IMU_POINTS="${IMU_POINTS:-[sensor_mount]}"
OUT="${OUT:-demo_output/ros}"

# shellcheck source=scripts/ros_env.sh
source scripts/ros_env.sh
ros_setup "$BUILD_DIR" vehicle_dynamics_node tvd_make_bag
mkdir -p "$OUT"
OUT="$(cd "$OUT" && pwd)"

roscore_pid=""
had_sim_time=""
cleanup() {
  if [ -n "$roscore_pid" ]; then
    kill -INT "$roscore_pid" 2>/dev/null || true
    wait "$roscore_pid" 2>/dev/null || true
  elif [ "$had_sim_time" = "none" ]; then
    rosparam delete /use_sim_time >/dev/null 2>&1 || true
  elif [ -n "$had_sim_time" ]; then
    rosparam set /use_sim_time "$had_sim_time" >/dev/null 2>&1 || true
  fi
}
trap cleanup EXIT

if timeout 5 rosparam list >/dev/null 2>&1; then
  echo "== Using the running ROS master at ${ROS_MASTER_URI:-http://localhost:11311}"
  had_sim_time="$(rosparam get /use_sim_time 2>/dev/null || echo none)"
else
  echo "== Starting a ROS master (log: $OUT/roscore.log)"
  port="$(echo "${ROS_MASTER_URI:-http://localhost:11311}" | sed -E 's#.*:([0-9]+)/?$#\1#')"
  roscore -p "$port" >"$OUT/roscore.log" 2>&1 &
  roscore_pid=$!
  wait_for_master
fi

output_bag="$OUT/${TRACK}_${SPEED_KMH}kmh_output.bag"
rm -f "$output_bag"
echo "== Replaying $TRACK at $SPEED_KMH km/h through vehicle_dynamics_node ($VARIANT)"
start=$(date +%s.%N)
roslaunch tracked_vehicle_dynamics replay_track.launch track:="$TRACK" speed_kmh:="$SPEED_KMH" \
  variant:="$VARIANT" imu_points:="$IMU_POINTS" bag_dir:="$OUT" output:="$output_bag" >"$OUT/roslaunch.log" 2>&1 || {
  echo "roslaunch failed; the last lines of $OUT/roslaunch.log:"
  tail -n 30 "$OUT/roslaunch.log"
  exit 1
}
end=$(date +%s.%N)
grep -h "/vehicle_dynamics:" "$OUT/roslaunch.log" | sed 's/\x1b\[[0-9;]*m//g' | head -n 3 || true
# rosbag record finishes writing after SIGINT; wait for the final file.
for _ in $(seq 1 50); do
  [ -s "$output_bag" ] && [ ! -e "$output_bag.active" ] && break
  sleep 0.2
done
# roslaunch exits 0 even when a required node dies at start-up (a FATAL parameter, a bad track):
# no output bag means the replay did not run.
if [ ! -s "$output_bag" ] || [ -e "$output_bag.active" ]; then
  echo "the replay wrote no output bag ($output_bag); the last lines of $OUT/roslaunch.log:"
  grep -E "FATAL|ERROR" "$OUT/roslaunch.log" | sed 's/\x1b\[[0-9;]*m//g' | tail -n 5 || true
  tail -n 30 "$OUT/roslaunch.log"
  exit 1
fi

echo
echo "== Summary"
/usr/bin/python3 scripts/ros_demo_summary.py "$output_bag" --png "$OUT/${TRACK}_${SPEED_KMH}kmh.png" \
  --wall-seconds "$(/usr/bin/python3 -c "print($end - $start)")" \
  --title "$TRACK at $SPEED_KMH km/h, paper vehicle ($VARIANT)"
echo
echo "Outputs in $OUT/ (track bag, output bag, plot, logs)."
