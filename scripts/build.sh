#!/usr/bin/env bash
# Configures and builds the catkin package into build/ (standalone, no workspace needed).
# Afterwards `source build/devel/setup.bash` lets rosrun/roslaunch/rostest find the package.
set -euo pipefail
cd "$(dirname "$0")/.."
# The system Python carries catkin_pkg; a pyenv shim earlier on PATH may not.
export PATH="/usr/bin:$PATH"
BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-$(nproc)}"
cmake -S . -B "$BUILD_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release \
  -DCATKIN_ENABLE_TESTING="${CATKIN_ENABLE_TESTING:-ON}" >"$BUILD_DIR.configure.log" 2>&1 \
  || { cat "$BUILD_DIR.configure.log"; exit 1; }
# Arguments name the targets to build (default: all).
if [ $# -gt 0 ]; then
  cmake --build "$BUILD_DIR" -j"$JOBS" --target "$@"
else
  cmake --build "$BUILD_DIR" -j"$JOBS"
fi
