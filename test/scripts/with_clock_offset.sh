#!/bin/bash
# Runs a command whose system clock (CLOCK_REALTIME, so ROS time on real time) is offset by the
# seconds written in OFFSET_FILE ("+0", "-10", "+0.5"), read at every clock reading, while its
# monotonic clock stays true: a test steps the clock under a running node by rewriting the file,
# as NTP would step the machine's. Uses libfaketime (Debian package faketime).
#   with_clock_offset.sh OFFSET_FILE COMMAND [ARG...]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 OFFSET_FILE COMMAND [ARG...]" >&2
  exit 2
fi
offset_file=$1
shift
library=$(ls /usr/lib/*/faketime/libfaketimeMT.so.1 2>/dev/null | head -n 1 || true)
if [ -z "$library" ]; then
  echo "$0: libfaketimeMT.so.1 not found: install the Debian package faketime (scripts/install_deps.sh does)" >&2
  exit 1
fi
mkdir -p "$(dirname "$offset_file")"
echo "+0" > "$offset_file.tmp.$$"
mv -f "$offset_file.tmp.$$" "$offset_file"
# FAKETIME_NO_CACHE: the file is read at every clock reading, so a step takes effect at once.
export LD_PRELOAD="$library${LD_PRELOAD:+:$LD_PRELOAD}" FAKETIME_TIMESTAMP_FILE="$offset_file" \
  FAKETIME_NO_CACHE=1 FAKETIME_DONT_FAKE_MONOTONIC=1
exec "$@"
