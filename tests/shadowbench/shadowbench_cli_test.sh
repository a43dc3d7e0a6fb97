#!/usr/bin/env bash
# A tiny shadowbench sweep end to end: one CSV row per configuration, JSON and images written, bad input refused.
set -u
bench=$1
out=$2
rm -rf "$out"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

"$bench" --scene knob --techniques hard,pcf-gsm-average --taps 2,3 --resolutions 256,512 --size 96x72 --frames 1 \
    --rounds 2 --config "rpb-d16-floor:technique=receiver-plane,depthFormat=d16,floorReceiverDepth=true,constantBiasTexels=0" \
    --out "$out" > "$out.log" 2>&1 || fail "sweep exited $?: $(cat "$out.log")"
# hard: 2 resolutions; pcf-gsm-average: 2 taps x 2 resolutions; plus one --config = 7 rows.
rows=$(($(wc -l < "$out/results.csv") - 1))
[[ $rows -eq 7 ]] || fail "results.csv has $rows rows, expected 7"
head -1 "$out/results.csv" | grep -q '^scene,label,technique' || fail "results.csv header"
grep -q '"timingMethod"' "$out/results.json" || fail "results.json lacks the timing method"
grep -q '"rounds": 2' "$out/results.json" || fail "results.json lacks the rounds"
[[ $(grep -c '"samples": 2' "$out/results.json") -eq 7 ]] || fail "a frame time is not of 1 frame x 2 rounds"
grep -q '^\[7/7\]' "$out.log" || fail "no progress lines"
[[ -s $out/knob/side-by-side.png && -s $out/knob/rpb-d16-floor-classes.png && -s $out/knob/rpb-d16-floor-error.png ]] ||
    fail "images missing"

# Each technique at its defaults under a light sweep: 2 techniques x 2 x 1 directions, edge columns written.
"$bench" --scene knob --techniques gsm,pcf --defaults --accuracy-only --light-sweep 30,210:5 --size 96x72 \
    --out "$out/sweep" > "$out.sweep.log" 2>&1 || fail "light sweep exited $?: $(cat "$out.sweep.log")"
[[ $(($(wc -l < "$out/sweep/results.csv") - 1)) -eq 4 ]] || fail "light sweep: expected 4 rows"
head -1 "$out/sweep/results.csv" | grep -q 'edge_true_to_rendered_mean' || fail "results.csv lacks the edge columns"
grep -q '^knob-az210-el5,gsm,' "$out/sweep/results.csv" || fail "light sweep rows are not named after the view"
grep -q '"renderedToTrue"' "$out/sweep/results.json" || fail "results.json lacks the edge distances"
"$bench" --light-sweep 30 --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 2 ]] && grep -q "light-sweep" "$out.bad" || fail "malformed --light-sweep not refused"
"$bench" --light-sweep 30:95 --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 2 ]] && grep -q "elevation" "$out.bad" || fail "elevation above 90° not refused"

# "default" names the module's default technique: one row, under that technique's own name.
"$bench" --scene knob --techniques default --defaults --accuracy-only --size 48x36 --out "$out/default" \
    > "$out.default.log" 2>&1 || fail "--techniques default exited $?: $(cat "$out.default.log")"
[[ $(($(wc -l < "$out/default/results.csv") - 1)) -eq 1 ]] || fail "--techniques default: expected 1 row"
grep -Eq '^knob,([a-z-]+),\1,' "$out/default/results.csv" && ! grep -q ',default,' "$out/default/results.csv" ||
    fail "--techniques default did not run a named technique"

# Shimmer along a camera path: a path_shimmer column at the end, measured (not -1); a path of no frames refused.
"$bench" --scene knob --techniques normal-offset --defaults --accuracy-only --shimmer-path 2 --size 48x36 \
    --out "$out/path" > "$out.path.log" 2>&1 || fail "--shimmer-path exited $?: $(cat "$out.path.log")"
head -1 "$out/path/results.csv" | grep -q ',path_shimmer$' || fail "results.csv lacks the path_shimmer column"
awk -F, 'NR == 2 { found = 1; measured = ($NF >= 0) } END { exit !(found && measured) }' "$out/path/results.csv" ||
    fail "--shimmer-path wrote no path shimmer"
grep -q '"pathFrames": 2' "$out/path/results.json" || fail "results.json lacks pathFrames"
grep -q 'path shimmer' "$out.path.log" || fail "the progress line lacks the path shimmer"
"$bench" --shimmer-path 0 --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 2 ]] && grep -q -- "--shimmer-path: '0'" "$out.bad" || fail "--shimmer-path 0 not refused"
"$bench" --rounds 0 --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 2 ]] && grep -q -- "--rounds: '0'" "$out.bad" || fail "--rounds 0 not refused"

"$bench" --techniques nonsense --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 2 ]] && grep -q "unknown technique 'nonsense'" "$out.bad" || fail "unknown technique not refused"
"$bench" --config "x:pcfTaps=99" --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 2 ]] && grep -q "pcfTaps" "$out.bad" || fail "bad --config not refused"
"$bench" --scene /nonexistent.gltf --techniques hard --out "$out/x" > "$out.bad" 2>&1
[[ $? -eq 1 ]] && grep -q "/nonexistent.gltf: file not found" "$out.bad" || fail "missing scene not refused"

[[ $failures -eq 0 ]] && echo "ok shadowbench end to end"
exit $((failures > 0))
