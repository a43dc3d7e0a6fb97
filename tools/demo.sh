#!/usr/bin/env bash
# The main job: measures every shadow technique against the ray-traced truth on the corpus's airport apron under
# its low (8 degree) sun, where they differ (on knob every non-naive one scores 0 acne and leak; knob stands in
# when the corpus has no apron), and sets them side by side on labelled sheets (out/contact-sheet.png,
# out/truth-sheet.png: acne, leak, darkening, frame ms, edge p95 both ways), then renders knob with every
# technique, every content scene and every real model of the corpus (tools/corpus.sh) headless into out/ (or
# $1), and writes out/report.md: the accuracy table, then the frame times. Prints a line per step.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}
started=${EPOCHREALTIME/./}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-render gs-corpus gs-shadowbench gs-contactsheet
# A corpus that fails partway (assimp missing) still lets the demo run: the sheets fall back to knob below.
bash tools/corpus.sh || echo "demo: tools/corpus.sh failed; going on with what corpus/ has"
mkdir -p "$out"

# Seconds since microsecond timestamp $1, one decimal.
seconds_since() { local us=$((${EPOCHREALTIME/./} - $1)); printf '%d.%d' $((us / 1000000)) $((us % 1000000 / 100000)); }

# The apron staged by gs-corpus: 300 m of vehicles, poles and wires seen from 8 m under an 8 degree sun, where
# edge placement, darkening, the last pixels of acne and the cost part the techniques; generated, so it needs no
# assimp.
sheet_scene=apron-merged
if [[ ! -s corpus/$sheet_scene.glb ]]; then
    echo "demo: corpus/$sheet_scene.glb is missing (tools/corpus.sh); the sheets fall back to knob"
    sheet_scene=knob
fi
echo "demo: every technique on $sheet_scene against the ray-traced truth (gs-shadowbench, 640x480)"
./build/bin/gs-shadowbench --scene "$sheet_scene" --frames 3 --out "$out/accuracy"
./build/bin/gs-contactsheet "$out/accuracy" --downsample 2 --out "$out"

render=./build/bin/gs-render
mapfile -t techniques < <("$render" --list-techniques)
scenes=(torus bowl thin-shell crease-cube grazing-plane spheres room outdoor)
soft_scenes=(soft-contact soft-overlap soft-fence) # lights with a size, shown with the soft technique
shopt -s nullglob # no corpus (assimp missing): nothing to render
models=(corpus/*.glb)
steps=$((${#techniques[@]} + ${#scenes[@]} + ${#soft_scenes[@]} + ${#models[@]}))
step=0
# render_step LABEL gs-render-options...: one image, its report.json and a progress line; gs-render's own lines go
# to out/render.log.
render_step() {
    local label=$1 begun=${EPOCHREALTIME/./}
    shift
    step=$((step + 1))
    "$render" "$@" >> "$out/render.log"
    echo "[$step/$steps] $label $(seconds_since "$begun") s"
}
echo "demo: frame times ($steps images, gs-render)"
: > "$out/render.log"
for technique in "${techniques[@]}"; do
    render_step "knob $technique" --scene knob --technique "$technique" --out "$out/knob/$technique"
done
for scene in "${scenes[@]}"; do
    render_step "$scene" --scene "$scene" --out "$out/scenes/$scene"
done
for scene in "${soft_scenes[@]}"; do
    render_step "$scene pcss" --scene "$scene" --technique pcss --out "$out/scenes/$scene"
done
for model in "${models[@]}"; do
    name=$(basename "$model" .glb)
    render_step "$name" --scene "$name" --size 640x480 --out "$out/corpus/$name"
done
python3 tools/demo_report.py "$out" > "$out/report.md.tmp" && mv "$out/report.md.tmp" "$out/report.md"
cat "$out/report.md"
echo "demo: wrote $out/report.md, $out/contact-sheet.png and $out/truth-sheet.png in $(seconds_since "$started") s"
