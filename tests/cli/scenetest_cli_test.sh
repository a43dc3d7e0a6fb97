#!/usr/bin/env bash
# gs-scenetest: passes a good scene, fails a bad one naming the bound (naive hard shadows: acne; an edge bound of
# 0 px), reports the texel density, checks a golden
# image both ways, and refuses bad options (exit 2) and missing scenes (exit 1).
set -u
tool=$1
out=$2
rm -rf "$out"
source "$(dirname "$0")/expect.sh"


small=(--size 160x120)
expect good 0 "PASSED" -- "$tool" torus --technique gsm "${small[@]}" --out "$out/good"
for file in report.txt classes.png error.png shaded.png; do
    [[ -s $out/good/$file ]] || { echo "FAIL $file missing"; failures=$((failures + 1)); }
done
expect badNamesTheBound 1 "FAILED: acne [0-9.]+ % > 0.05 %;" -- "$tool" torus --technique hard "${small[@]}" --out "$out/bad"
grep -q "acne .* EXCEEDED" "$out/bad/report.txt" || { echo "FAIL report lacks the exceeded bound"; failures=$((failures + 1)); }
expect edgeBoundNamed 1 "FAILED: .*edge true->rendered mean [0-9.]+ px > 0.000000 px;" -- "$tool" torus --technique gsm \
    --max-edge-mean 0 "${small[@]}" --out "$out/edges"
grep -q "texel density: .* of lit receivers at m <= 1" "$out/edges/report.txt" ||
    { echo "FAIL report lacks the texel density"; failures=$((failures + 1)); }
expect goldenSame 0 "golden 0 % of pixels differ" -- "$tool" torus --technique gsm "${small[@]}" \
    --golden "$out/good/shaded.png" --out "$out/same"
expect goldenDifferent 1 "FAILED: .*golden" -- "$tool" torus --technique pcf-gsm-average --max-acne 100 \
    --max-leak 100 --max-darkening 100 "${small[@]}" --golden "$out/bad/shaded.png" --out "$out/different"
[[ -s $out/different/diff.png ]] || { echo "FAIL diff.png missing"; failures=$((failures + 1)); }
expect goldenWrongSize 1 "golden image is 160x120" -- "$tool" torus --size 80x60 --golden "$out/good/shaded.png" --out "$out/size"
expect noScene 2 "no scene given" -- "$tool"
expect unknownTechnique 2 "--technique: unknown technique 'nope'" -- "$tool" torus --technique nope
expect badBound 2 "--max-acne: '-1' is not a number" -- "$tool" torus --max-acne -1
expect badEdgeBound 2 "--max-edge-p95: '-1' is not a number" -- "$tool" torus --max-edge-p95 -1
expect missingScene 1 "nowhere.gltf" -- "$tool" /nowhere.gltf --out "$out/missing"

echo "$((failures == 0 ? 1 : 0)) passed, $failures failed"
exit $((failures > 0))
