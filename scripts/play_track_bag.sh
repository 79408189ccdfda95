#!/usr/bin/env bash
# Plays the rosbag of a track at a constant speed with --clock (1 kHz), writing it first with
# tvd_make_bag when it is not there yet, or was written from another file or version of it.
#   play_track_bag.sh TRACK SPEED BAG_DIR [rosbag play options...]
# TRACK: long_hill | separated_waves | oop_waves | half_round:H | a terrain file (.csv/.yaml, e.g. from
# `tvd terrain --iso8608 C`). SPEED: km/h, or a speed-profile CSV (time_s,speed_kmh). The bag is
# BAG_DIR/NAME_SPEEDkmh.bag for a built-in track at a constant speed, NAME the track; from a
# terrain file NAME_SPEEDkmh.HASH.bag (NAME its stem), with a speed profile NAME_PROFILE.HASH.bag
# (PROFILE its stem): HASH (8 hex) is that of the record of both inputs, each file's absolute path
# and content hash (BAG.source).
# Arguments roslaunch appends (__name:=..., __log:=...) are ignored, so it runs as a launch node;
# remappings (from:=to) are passed to the player.
# With TVD_BAG_MAKE_ONLY=1 the bag is only written (when needed) and its path printed, alone on
# stdout (tvd_make_bag's summary goes to stderr then).
# The options are those of rosbag's play executable (`rosbag play`'s; /usr/lib/rosbag/play --help),
# which runs as this script's child: a SIGINT, SIGTERM or SIGHUP to the script stops it (and
# tvd_make_bag) before the script ends, so no player is left behind.
set -euo pipefail

# roslaunch stops a node with SIGINT to its process group and SIGTERM 15 s later. play ignores
# SIGINT while it waits for subscribers (--wait-for-subscribers), and `rosbag play` (Python) exits
# on SIGINT at once, leaving play running on its own; so play is started directly, and a child that
# has not ended 2 s after SIGINT gets SIGTERM.
child=""
child_command=""
tmp=""
log=""
stty_saved=""
if [ -t 0 ]; then stty_saved=$(stty -g 2>/dev/null || true); fi
stop() {  # stop SIGNAL STATUS: stops the child, exits with STATUS
  trap '' INT TERM HUP
  if [ -n "$child" ]; then
    if [ "$1" = INT ]; then
      kill -s INT "$child" 2>/dev/null || true
      for _ in $(seq 20); do
        kill -0 "$child" 2>/dev/null || break
        sleep 0.1
      done
      if kill -0 "$child" 2>/dev/null; then
        echo "play_track_bag.sh: $(basename "$child_command") still running 2 s after SIGINT:" \
          "SIGTERM" >&2
      fi
    fi
    kill -s TERM "$child" 2>/dev/null || true
    wait "$child" 2>/dev/null || true
    # play's terminal settings (it reads keys) are not restored by SIGTERM.
    if [ -n "$stty_saved" ]; then stty "$stty_saved" 2>/dev/null || true; fi
  fi
  if [ -n "$tmp" ]; then rm -f "$tmp" "$tmp.source"; fi
  if [ -n "$log" ]; then rm -f "$log"; fi
  exit "$2"
}
trap 'stop INT 130' INT
trap 'stop TERM 143' TERM
trap 'stop HUP 129' HUP
run_child() {  # run_child COMMAND...: runs it as the child the traps stop (with this stdin)
  child_command=$1
  # An asynchronous command ignores SIGINT unless it resets it; `wait` lets the traps run at once.
  (trap - INT QUIT; exec "$@") <&0 &
  child=$!
  local status=0
  wait "$child" || status=$?
  child=""
  return "$status"
}

args=()
remaps=()  # a launch file's <remap> (from:=to): the player's, applied to the bag's topics
for a in "$@"; do
  case "$a" in
    __*:=*) ;;
    *:=*) remaps+=("$a") ;;
    *) args+=("$a") ;;
  esac
done
# replay_track.launch records the node's topics by their global names in the namespace its ns:=
# argument names (rosbag record stores a relative name as given, without its namespace), and
# passes that argument here as TVD_RECORD_NS when it records. Included in a namespace without
# ns:= (or with another), the recorder would record none of the node's topics, and say nothing
# (review 165): refused here, where roslaunch's ROS_NAMESPACE tells where the launch runs.
if [ -n "${TVD_RECORD_NS+set}" ]; then
  # The recorder is given ns + "/odom": a relative ns (veh1) makes it veh1/odom, which rosbag
  # record resolves in its own namespace, /veh1/veh1/odom (review 166).
  if [ -n "$TVD_RECORD_NS" ] && [ "${TVD_RECORD_NS#/}" = "$TVD_RECORD_NS" ]; then
    running=${ROS_NAMESPACE:-/}
    running=/${running#/}
    running=${running%/}
    running=${running:-/}
    echo "play_track_bag.sh: replay_track.launch's ns argument '${TVD_RECORD_NS}' must be a" \
      "global name: the recorder would record ${TVD_RECORD_NS%/}/odom ..., which it resolves" \
      "in its namespace; this launch runs in ${running}: give ns:=${running}" >&2
    exit 2
  fi
  here=${ROS_NAMESPACE:-/}
  here=/${here#/}
  here=${here%/}
  wanted=/${TVD_RECORD_NS#/}
  wanted=${wanted%/}
  if [ "$here" != "$wanted" ]; then
    echo "play_track_bag.sh: replay_track.launch runs in the namespace ${here:-/} but its ns" \
      "argument is '${TVD_RECORD_NS}': the recorder would record ${wanted}/odom ..., not" \
      "${here}/odom ...; include it with ns:=${here:-/} (or record:=false)" >&2
    exit 2
  fi
fi
track=${args[0]:-long_hill}
speed=${args[1]:-30}
dir=${args[2]:-/tmp/tvd_bags}
extra=("${args[@]:3}")
name=$(basename "$track")
# A terrain file's stem; a built-in track as named (half_round:0.2 has a '.' of its own).
if [ -f "$track" ]; then name=${name%.*}; fi
if [[ "$speed" == *.csv ]]; then
  profile=$(basename "$speed")
  run="${name}_${profile%.*}"
  speed_args=(--speed-profile "$speed")
else
  run="${name}_${speed}kmh"
  speed_args=(--speed-kmh "$speed")
fi
bag="$dir/$run.bag"
mkdir -p "$dir"
# The devel/install space's executable (rosrun may see several build trees in the source).
make_bag=$(catkin_find --without-underlays --libexec tracked_vehicle_dynamics tvd_make_bag \
  2>/dev/null | head -n 1)
# What the bag is written from: each terrain or profile file's absolute path and content hash,
# else the built-in track or speed as given. A bag from a file carries a hash of this record in
# its name, so another file of the same stem (elsewhere, or edited under its old time stamp, e.g.
# by cp -p) gets a bag of its own, and runs in parallel never share a name for different
# contents; BAG.source keeps the record for a look. A bag older than tvd_make_bag itself (a
# rebuilt track definition or patch layout) is written again.
source_of() {
  if [ -f "$1" ]; then
    local real hash
    real=$(realpath "$1") && hash=$(sha256sum <"$1") ||
      { echo "play_track_bag.sh: cannot read $1" >&2; return 2; }
    printf '%s sha256:%s\n' "$real" "${hash%% *}"
  else
    printf '%s\n' "$1"
  fi
}
source_record=$(source_of "$track")
source_record+=$'\n'$(source_of "$speed")
if [ -f "$track" ] || [ -f "$speed" ]; then
  key=$(printf '%s\n' "$source_record" | sha256sum)
  bag="$dir/$run.${key:0:8}.bag"
fi
fresh() { [ -s "$bag" ] && ! { [ -f "$make_bag" ] && [ "$make_bag" -nt "$bag" ]; }; }
# The node rejects speed messages above its ~max_speed (30 m/s in the parameter file): a bag
# faster than that would replay a vehicle standing at station 0. replay_track.launch names the
# node (TVD_REPLAY_NODE, resolved in the player's namespace); its parameter is on the master
# before any node starts. tvd_make_bag checks the run as it would for the bag (refusing one it
# could not make) and gives its highest speed (a profile's largest sample); without it a
# constant speed is still checked here.
max_speed=""
if [ -n "${TVD_REPLAY_NODE:-}" ]; then
  max_speed=$(rosparam get "$TVD_REPLAY_NODE/max_speed" 2>/dev/null || true)
fi
if [[ "$max_speed" =~ ^[0-9.eE+-]+$ ]]; then
  if [ -x "$make_bag" ]; then
    peak=$("$make_bag" --track "$track" "${speed_args[@]}" --peak-speed) || exit $?
  elif [[ "$speed" != *.csv ]]; then
    peak=$(awk -v v="$speed" 'BEGIN { printf "%.17g", v / 3.6 }')
  else
    echo "play_track_bag.sh: warning: tvd_make_bag not found: the speed profile $speed is not" \
      "checked against $TVD_REPLAY_NODE's ~max_speed" >&2
    peak=0
  fi
  if awk -v v="$peak" -v m="$max_speed" 'BEGIN { exit !(v > m) }'; then
    what="drives at $speed km/h"
    [[ "$speed" == *.csv ]] &&
      what="reaches $(awk -v v="$peak" 'BEGIN { printf "%.4g", v * 3.6 }') km/h (speed profile $speed)"
    echo "play_track_bag.sh: the bag $what, above $TVD_REPLAY_NODE's ~max_speed" \
      "$max_speed m/s ($(awk -v m="$max_speed" 'BEGIN { printf "%.4g", m * 3.6 }') km/h): the node" \
      "would reject the speed messages above it; raise max_speed in the node's parameter file" \
      "(config:=FILE)" >&2
    exit 2
  fi
fi
if ! fresh; then
  tmp="$dir/.$run.$$.bag"
  if [ -z "$make_bag" ] || [ ! -x "$make_bag" ]; then
    echo "play_track_bag.sh: tvd_make_bag not found (build the package and source its setup.bash)" >&2
    exit 2
  fi
  # Its summary (stdout) is kept apart from the bag directory, which tvd_make_bag itself reports
  # on when it cannot write there.
  log=$(mktemp "${TMPDIR:-/tmp}/play_track_bag.XXXXXX")
  status=0
  run_child "$make_bag" --track "$track" "${speed_args[@]}" --out "$tmp" >"$log" || status=$?
  # The summary names the file written, the temporary one: shown with the bag's name.
  summary=$(<"$log")
  summary=${summary//"$tmp"/"$bag"}
  rm -f "$log"
  log=""
  if [ $status -ne 0 ]; then
    [ -z "$summary" ] || printf '%s\n' "$summary" >&2
    rm -f "$tmp"
    exit $status
  fi
  printf '%s\n' "$source_record" >"$tmp.source"
  mv -f "$tmp.source" "$bag.source"
  mv -f "$tmp" "$bag"
  tmp=""
  if [ "${TVD_BAG_MAKE_ONLY:-0}" = 1 ]; then
    printf '%s\n' "$summary" >&2
  else
    printf '%s\n' "$summary"
  fi
fi
# TVD_BAG_MAKE_ONLY=1: the bag is written (or found current) and named, not played (bags made
# ahead of a session; the tests).
if [ "${TVD_BAG_MAKE_ONLY:-0}" = 1 ]; then
  echo "$bag"
  exit 0
fi
play=$(catkin_find --libexec rosbag play 2>/dev/null | head -n 1)
if [ -z "$play" ] || [ ! -x "$play" ]; then
  echo "play_track_bag.sh: rosbag's play executable not found (catkin_find --libexec rosbag play)" >&2
  exit 2
fi
run_child "$play" --clock --hz=1000 "${extra[@]}" "$bag" "${remaps[@]}"
# The player is the launch's required node: its end stops the recorder. The node publishes the
# last /clock tick's sample after play has sent it; linger so the recorder receives it too
# (TVD_REPLAY_LINGER seconds, default 1).
sleep "${TVD_REPLAY_LINGER:-1}"
