#!/usr/bin/env bash
# tools/corpus.sh and gs-corpus on bad input: a model that does not convert and models that are missing are
# reported by name and skipped (exit 0); gs-corpus refuses broken files naming them (exit 1) and bad options
# (exit 2).
set -u
repo=$1
tool=$2
work=$3
rm -rf "$work"
mkdir -p "$work/models/BLEND"
failures=0

check() { # check NAME CONDITION_STATUS OUTPUT PATTERN
    if [[ $2 -ne 0 ]] || ! grep -qE -e "$4" <<<"$3"; then
        echo "FAIL $1:"
        echo "$3"
        failures=$((failures + 1))
    else
        echo "ok   $1"
    fi
}

echo "not a blend file" >"$work/models/BLEND/SuzanneSubdiv_252.blend"
output=$(GS_ASSIMP_MODELS="$work/models" GS_CORPUS_TOOL="$tool" bash "$repo/tools/corpus.sh" "$work/corpus" 2>&1)
status=$?
check "unconvertible model named" $status "$output" "corpus: suzanne: assimp could not convert BLEND/SuzanneSubdiv_252.blend; skipped|corpus: suzanne: the assimp command is missing"
check "missing model named" $status "$output" "corpus: duck: .*Collada/duck.dae is missing"
check "missing terrain named" $status "$output" "corpus: terrain: .* is missing; skipped"
check "missing low terrain named" $status "$output" "corpus: terrain-low: .* is missing; skipped"
check "summary" $status "$output" "corpus: 5 built, 0 up to date, 12 failed"
[[ -s $work/corpus/sweep/hills-10000.glb ]] || { echo "FAIL generated sweep missing"; failures=$((failures + 1)); }
for apron in apron apron-merged; do
    [[ -s $work/corpus/$apron.glb ]] || { echo "FAIL generated $apron missing"; failures=$((failures + 1)); }
done

printf 'TERRAGENTERRAIN SIZE' >"$work/broken.ter"
output=$("$tool" terrain "$work/broken.ter" "$work/out.glb" 2>&1)
[[ $? -eq 1 ]]
check "truncated terrain refused" $? "$output" "broken.ter: chunk SIZE is truncated"
output=$("$tool" stage "$work/missing.gltf" "$work/out.glb" 2>&1)
[[ $? -eq 1 ]]
check "missing model refused" $? "$output" "missing.gltf"
output=$("$tool" stage a.gltf b.glb --up w 2>&1)
[[ $? -eq 2 ]]
check "bad option refused" $? "$output" "--up: 'w' is not one of"
output=$("$tool" apron "$work/out.glb" --sun-elevation 0 2>&1)
[[ $? -eq 2 ]]
check "apron sun on the horizon refused" $? "$output" "--sun-elevation: '0' is not a number in"
output=$("$tool" apron "$work/out.glb" --sun-azimuth 2>&1)
[[ $? -eq 2 ]]
check "apron option without a value refused" $? "$output" "option '--sun-azimuth' needs a value"
output=$("$tool" apron "$work/out.glb" --camera-elevation 10 2>&1)
[[ $? -eq 2 ]]
check "apron unknown option refused" $? "$output" "unknown option '--camera-elevation'"
output=$("$tool" tessellation 1000 "$work/out.glb" --camera-height 0 2>&1)
[[ $? -eq 2 ]]
check "camera under the ground refused" $? "$output" "--camera-height: '0' is not a number in"
output=$("$tool" apron 2>&1)
[[ $? -eq 2 ]]
check "apron without an output refused" $? "$output" "'apron' needs an output"
[[ ! -e $work/out.glb ]] || { echo "FAIL output written despite the error"; failures=$((failures + 1)); }

echo "$((failures == 0 ? 1 : 0)) passed, $failures failed"
exit $((failures > 0))
