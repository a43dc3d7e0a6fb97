#!/usr/bin/env bash
# The main job: renders the default scene (knob) headless with every shadow technique, every content scene and
# every real model of the corpus (tools/corpus.sh) with the default technique, into out/ (or $1), then writes
# out/report.md summarising what was rendered.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-render gs-corpus
render=./build/bin/gs-render
mapfile -t techniques < <("$render" --list-techniques)
for technique in "${techniques[@]}"; do
    "$render" --scene knob --technique "$technique" --out "$out/knob/$technique"
done
for scene in torus bowl thin-shell crease-cube grazing-plane spheres; do
    "$render" --scene "$scene" --out "$out/scenes/$scene"
done
bash tools/corpus.sh
shopt -s nullglob # no corpus (assimp missing): nothing to render
for model in corpus/*.glb; do
    name=$(basename "$model" .glb)
    "$render" --scene "$name" --size 640x480 --out "$out/corpus/$name"
done
python3 tools/demo_report.py "$out" > "$out/report.md.tmp" && mv "$out/report.md.tmp" "$out/report.md"
cat "$out/report.md"
