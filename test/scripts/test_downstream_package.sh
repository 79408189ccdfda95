#!/bin/bash
# A catkin package that depends on tracked_vehicle_dynamics (test/downstream) configured, built
# and run against the devel space, as a simulator stack would: it must find the messages, the
# public headers and what they include (Eigen), and link both libraries, through
# find_package(catkin COMPONENTS tracked_vehicle_dynamics) alone.
#   test/scripts/test_downstream_package.sh DEVEL_SPACE WORK_DIR [REPORT.xml]
# Exit status 0 when it builds and runs; REPORT.xml (JUnit, one case) for scripts/test.sh's count.
# WORK_DIR/downstream_check is replaced on every run (and nothing else in WORK_DIR is touched);
# the output also goes to WORK_DIR/downstream_check.log as it comes.
set -uo pipefail
if [ $# -lt 2 ] || [ ! -f "$1/setup.bash" ]; then
  echo "usage: $0 DEVEL_SPACE WORK_DIR [REPORT.xml] (DEVEL_SPACE holds setup.bash)" >&2
  exit 2
fi
devel="$1"
work="$2/downstream_check"
log="$2/downstream_check.log"
report="${3:-}"
here="$(cd "$(dirname "$0")/../.." && pwd)"

check() {
  rm -rf "$work" && mkdir -p "$work" || return 1
  # The ROS setup scripts read unset variables.
  set +u
  # shellcheck disable=SC1091
  source "$devel/setup.bash"
  set -u
  # catkin's CMake runs the system Python (a pyenv python3 shim may lack catkin_pkg).
  export PATH="/usr/bin:$PATH"
  if ! cmake -S "$here/test/downstream" -B "$work/build" -DPYTHON_EXECUTABLE=/usr/bin/python3 \
      -DCATKIN_DEVEL_PREFIX="$work/devel" >"$work/configure.log" 2>&1; then
    tail -20 "$work/configure.log"
    echo "the downstream package does not configure against $devel"
    return 1
  fi
  if ! cmake --build "$work/build" -j2 >"$work/build.log" 2>&1; then
    grep -m5 -E "error|Error" "$work/build.log" || tail -20 "$work/build.log"
    echo "the downstream package does not build against $devel"
    return 1
  fi
  # The package's own vehicle: the source tree's for a devel space, the installed one else.
  if ! "$work/devel/lib/tvd_downstream_check/downstream_check" \
      "$(rospack find tracked_vehicle_dynamics)/config/vehicles/paper_vehicle.yaml"; then
    echo "the downstream package's program failed"
    return 1
  fi
  echo "downstream package: configured, built and ran against $devel"
}

mkdir -p "$2"
check 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
if [ -n "$report" ]; then
  mkdir -p "$(dirname "$report")"
  # XML text: no control characters (compiler colours), the markup characters escaped.
  escaped="$(tr -d '\000-\010\013\014\016-\037' <"$log" |
    iconv -c -f UTF-8 -t UTF-8 |
    sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g')"
  {
    echo '<?xml version="1.0" encoding="UTF-8"?>'
    echo "<testsuite name=\"downstream_package\" tests=\"1\" failures=\"$((status != 0))\">"
    echo '  <testcase classname="downstream_package" name="builds_and_runs_against_the_devel_space">'
    [ $status -ne 0 ] && echo "    <failure message=\"see system-out\"/>"
    echo "    <system-out>$escaped</system-out>"
    echo '  </testcase>'
    echo '</testsuite>'
  } >"$report"
fi
exit $status
