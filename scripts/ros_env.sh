# shellcheck shell=bash
# Shell functions shared by the scripts that run ROS programs (demo.sh, ros_demo.sh,
# bench/ros_node_bench.sh). Source it from a script that has cd'ed to the repository root.

# ros_setup BUILD_DIR [TARGET ...]: builds the targets (unless SKIP_BUILD=1 or none are given) and
# sources BUILD_DIR/devel/setup.bash, so that rosrun, roslaunch and catkin_find see the package.
ros_setup() {
  local build_dir="$1"
  shift
  if [ "$#" -gt 0 ] && [ "${SKIP_BUILD:-0}" != 1 ]; then
    BUILD_DIR="$build_dir" scripts/build.sh "$@"
  fi
  # The ROS setup scripts read unset variables.
  set +u
  # shellcheck disable=SC1091
  source "$build_dir/devel/setup.bash"
  set -u
}

# wait_for_master: returns once the ROS master at $ROS_MASTER_URI answers (up to ~20 s).
wait_for_master() {
  for _ in $(seq 1 100); do
    timeout 2 rosparam list >/dev/null 2>&1 && return 0
    sleep 0.2
  done
  echo "no ROS master answered at ${ROS_MASTER_URI:-http://localhost:11311}" >&2
  return 1
}
