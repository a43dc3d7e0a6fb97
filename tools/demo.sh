#!/usr/bin/env bash
# The main job: renders every content scene headless (the default scene, knob, first) and writes images plus a
# report per scene to out/<scene>/ (or $1/<scene>/).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-render
for scene in knob torus bowl thin-shell crease-cube grazing-plane spheres; do
    ./build/bin/gs-render --scene "$scene" --out "$out/$scene"
done
cat "$out/knob/report.json"
