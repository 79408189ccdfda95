#!/usr/bin/env bash
# Installs the Debian 12 packages this package needs, only those that are missing.
# Run as root or with sudo available. Used by scripts/demo.sh and scripts/test.sh.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  # ROS 1 as packaged by Debian
  ros-core-dev catkin libroscpp-dev librosbag-dev libtf2-ros-dev libtf2-geometry-msgs-dev
  ros-message-generation libstd-msgs-dev libgeometry-msgs-dev libstd-srvs-dev
  libnav-msgs-dev libsensor-msgs-dev
  libdiagnostic-updater-dev libdiagnostic-msgs-dev libtf2-msgs-dev libros-rosgraph-msgs-dev python3-rostest librostest-dev tf2-tools python3-rosbag python3-roslaunch python3-rostopic
  catkin-lint  # ctest catkin_lint: CMakeLists.txt checked against package.xml
  clang-format  # ctest format: every C++ file as .clang-format says
  faketime  # rostest node_clock_step: the system clock stepped under a running node
  rosbash  # rosrun (a Recommends of ros-core-dev, which --no-install-recommends leaves out)
  # the command-line tools load the Python bindings of the types they handle: rosservice call
  # ~reset (std_srvs/Empty), rostopic echo /diagnostics, odom and imu/<point>
  python3-rosservice python3-std-srvs python3-diagnostic-msgs python3-nav-msgs python3-sensor-msgs
  # numerics and I/O
  libeigen3-dev libspectra-dev libsuitesparse-dev libyaml-cpp-dev libmatio-dev libhdf5-dev libcli11-dev
  zlib1g-dev  # compressed MAT elements are inflated to check their headers before matio reads them
  # an optimised BLAS for CHOLMOD's supernodal factorisations and dense products (serial: the
  # solvers are single-threaded and the machines have 2 cores)
  libopenblas0-serial
  googletest
  locales  # test_locale_independence compiles de_DE (a comma locale) with localedef from its sources
  # plots and side-by-side benchmarks
  python3-numpy python3-scipy python3-matplotlib python3-yaml
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
