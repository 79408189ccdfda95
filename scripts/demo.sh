#!/usr/bin/env bash
# The main job on the bundled default: installs what is missing, builds into build/, then runs
# the modal analysis of the bundled example model and writes its results to demo_output/.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="/usr/bin:$PATH"

scripts/install_deps.sh
scripts/build.sh tvd
# shellcheck disable=SC1091
source build/devel/setup.bash

OUT=demo_output
mkdir -p "$OUT"
echo
echo "== Modal analysis of the bundled cantilever (config/models/cantilever_beam.yaml) =="
rosrun tracked_vehicle_dynamics tvd modes --model config/models/cantilever_beam.yaml --count 6 \
  --out "$OUT/cantilever_modes"
echo
echo "Results in $OUT/. Next: source build/devel/setup.bash; rosrun tracked_vehicle_dynamics tvd --help"
