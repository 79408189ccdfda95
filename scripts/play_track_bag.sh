#!/usr/bin/env bash
# Plays the rosbag of a track at a constant speed with --clock (1 kHz), writing it first with
# tvd_make_bag when it is not there yet (or, for a terrain file, older than the file).
#   play_track_bag.sh TRACK SPEED BAG_DIR [rosbag play options...]
# TRACK: long_hill | separated_waves | oop_waves | a terrain file (.csv/.yaml, e.g. from
# `tvd terrain --iso8608 C`). SPEED: km/h, or a speed-profile CSV (time_s,speed_kmh). The bag is
# BAG_DIR/NAME_SPEEDkmh.bag (NAME_PROFILE.bag for a profile), NAME the track or file stem.
# Arguments roslaunch appends (__name:=..., __log:=...) are ignored, so it runs as a launch node.
set -euo pipefail
args=()
for a in "$@"; do
  case "$a" in
    __*:=*) ;;
    *) args+=("$a") ;;
  esac
done
track=${args[0]:-long_hill}
speed=${args[1]:-30}
dir=${args[2]:-/tmp/tvd_bags}
extra=("${args[@]:3}")
name=$(basename "$track")
name=${name%.*}
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
stale() { [ -f "$1" ] && [ "$1" -nt "$bag" ]; }
if [ ! -s "$bag" ] || stale "$track" || stale "$speed"; then
  tmp="$dir/.$run.$$.bag"
  # The devel/install space's executable (rosrun may see several build trees in the source).
  make_bag=$(catkin_find --without-underlays --libexec tracked_vehicle_dynamics tvd_make_bag \
    2>/dev/null | head -n 1)
  if [ -z "$make_bag" ] || [ ! -x "$make_bag" ]; then
    echo "play_track_bag.sh: tvd_make_bag not found (build the package and source its setup.bash)" >&2
    exit 2
  fi
  "$make_bag" --track "$track" "${speed_args[@]}" --out "$tmp"
  mv -f "$tmp" "$bag"
fi
exec rosbag play --clock --hz=1000 "${extra[@]}" "$bag"
