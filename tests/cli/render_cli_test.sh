#!/usr/bin/env bash
# End-to-end checks of gs-render: a real render, and each bad input's message and exit status.
set -u
render=$1
out=$2
rm -rf "$out"
source "$(dirname "$0")/expect.sh"


expect renders 0 "wrote .*knob.png" -- "$render" --out "$out" --size 160x120 --frames 2
[[ -s $out/knob.png && -s $out/report.json ]] || { echo "FAIL outputs missing"; failures=$((failures + 1)); }
grep -q '"timingMethod"' "$out/report.json" || { echo "FAIL report lacks timingMethod"; failures=$((failures + 1)); }
ls -a "$out" | grep -q '\.tmp' && { echo "FAIL temporary file left behind"; failures=$((failures + 1)); }

expect noShadowsTakesShadowOptions 0 "wrote .*knob.png" -- "$render" --out "$out/none" --size 16x12 --frames 1 \
    --technique none --shadow-size 512 --depth-format d16 --debug-view visibility
grep -q '"shadowTechnique": "none"' "$out/none/report.json" || { echo "FAIL none rendered shadows"; failures=$((failures + 1)); }
expect noShadowsStillChecksOptions 2 "--shadow-size: '8' is not an integer in \[64, 16384\]" -- \
    "$render" --technique none --shadow-size 8
expect unknownDepthFormat 2 "--depth-format: unknown value 'd8' \(d16, d24, d32f\)" -- "$render" --depth-format d8
expect listsTechniques 0 "^hard$" -- "$render" --list-techniques
[[ $("$render" --list-techniques | wc -l) -ge 14 ]] || { echo "FAIL --list-techniques too short"; failures=$((failures + 1)); }
"$render" --help | grep -q -- "--list-techniques" || { echo "FAIL usage lacks --list-techniques"; failures=$((failures + 1)); }
expect unknownOption 2 "unknown option '--bogus'" -- "$render" --bogus
expect badSize 2 "--size: 'axb' is not WIDTHxHEIGHT|--size: 'a' is not an integer" -- "$render" --size axb
expect zeroSize 2 "--size: '0' is not an integer in \[1, 16384\]" -- "$render" --size 0x10
expect unknownScene 1 "scenes/nope.gltf: file not found" -- "$render" --scene nope
printf '%s' '{"asset":{"version":"2.0"},"meshes":[{"primitives":{"attributes":{"POSITION":0}}}]}' >"$out/wrong-type.gltf"
expect wrongTypeGltf 1 "wrong-type.gltf: meshes\[0\].primitives: expected an array" -- "$render" --scene "$out/wrong-type.gltf" --out "$out/w"
printf '%s' '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"extensions":{"KHR_lights_punctual":{"light":0}}}],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","name":"bulb","range":0}]}}}' >"$out/zero-range.gltf"
expect zeroLightRange 1 "zero-range.gltf: light 0 \('bulb'\): extensions.KHR_lights_punctual.lights\[0\].range must be a finite number > 0" -- \
    "$render" --scene "$out/zero-range.gltf" --out "$out/z"
expect missingValue 2 "--out needs a value" -- "$render" --out
expect missingModule 1 "module 'nothere' not found" -- "$render" --out "$out/m" --module nothere
expect noEglDriver 1 "headless context: .*libegl-mesa0" -- env LIBGL_DRIVERS_PATH=/nonexistent "$render" --out "$out/n"
[[ -e $out/n ]] && { echo "FAIL output written despite failure"; failures=$((failures + 1)); }

exit $((failures > 0))
