#!/usr/bin/env bash
# Builds the real-model corpus into corpus/ (or $1): each model of Debian's assimp-testmodels is converted to
# glTF with assimp-utils, then staged by gs-corpus on a ground plane with a camera and a sun placed from its
# bounds. Third-party models are never committed; third_party_notes/assimp-testmodels.md lists each licence.
# Idempotent: a model whose scene is newer than its source and than gs-corpus is skipped. A model that cannot
# be converted is reported by name and skipped; the script fails only if gs-corpus itself is missing.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:-corpus}
models=${GS_ASSIMP_MODELS:-/usr/share/assimp/models}
corpusTool=${GS_CORPUS_TOOL:-./build/bin/gs-corpus}
[[ -x $corpusTool ]] || { echo "corpus: $corpusTool is not built (cmake --build --preset default --target gs-corpus)" >&2; exit 1; }
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name | source under $models | gs-corpus options
manifest=(
    "suzanne|BLEND/SuzanneSubdiv_252.blend|"
    "human-subdivided|BLEND/HUMAN.blend|--up z --subdivide loop:2"
    "fzk-haus|IFC/AC14-FZK-Haus.ifc|--sun-azimuth 150"
    "at-at|Q3D/E-AT-AT.q3o|--up z"
    "jeep|MS3D/jeep1.ms3d|"
    "duck|Collada/duck.dae|"
    "wuson|PLY/Wuson.ply|"
    "epileptic|X/BCN_Epileptic.X|--up -z"
    "dwarf|COB/dwarf.cob|--up z"
    "cylinder-engine|glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb|"
)

built=0
skipped=0
failed=()
upToDate() { [[ -s $1 && $1 -nt $2 && $1 -nt $corpusTool ]]; }

for entry in "${manifest[@]}"; do
    IFS='|' read -r name source options <<<"$entry"
    scene="$out/$name.glb"
    if [[ ! -r $models/$source ]]; then
        echo "corpus: $name: $models/$source is missing (apt-get install assimp-testmodels); skipped" >&2
        failed+=("$name")
        continue
    fi
    if upToDate "$scene" "$models/$source"; then
        skipped=$((skipped + 1))
        continue
    fi
    converted="$work/$name.gltf"
    if [[ $source == *.glb || $source == *.gltf ]]; then
        converted="$models/$source"
    elif ! command -v assimp >/dev/null; then
        echo "corpus: $name: the assimp command is missing (apt-get install assimp-utils); skipped" >&2
        failed+=("$name")
        continue
    elif ! assimp export "$models/$source" "$converted" >"$work/$name.log" 2>&1; then
        echo "corpus: $name: assimp could not convert $source; skipped:" >&2
        tail -3 "$work/$name.log" >&2
        failed+=("$name")
        continue
    fi
    # shellcheck disable=SC2086 # options are words
    if "$corpusTool" stage "$converted" "$scene" $options; then
        built=$((built + 1))
    else
        failed+=("$name")
    fi
done

# Large ones: the Terragen heightfield (assimp 5.2 stops at its "read limit", so gs-corpus reads the format)
# and a tessellation sweep of generated hills from 10k to 1M triangles.
# The terrain is staged twice: seen from above its near edge, and by a camera 10 m above the ground looking
# across it (a low view: shadows far away fall on few pixels, near ones on many).
terrain=$models/TER/RealisticTerrain_Large.ter
for variant in "terrain|" "terrain-low|--camera-height 10"; do
    IFS='|' read -r name options <<<"$variant"
    if [[ ! -r $terrain ]]; then
        echo "corpus: $name: $terrain is missing; skipped" >&2
        failed+=("$name")
    elif ! upToDate "$out/$name.glb" "$terrain"; then
        # shellcheck disable=SC2086 # options are words
        "$corpusTool" terrain "$terrain" "$out/$name.glb" $options && built=$((built + 1)) || failed+=("$name")
    else
        skipped=$((skipped + 1))
    fi
done
for triangles in 10000 100000 1000000; do
    scene="$out/sweep/hills-$triangles.glb"
    mkdir -p "$out/sweep"
    if [[ -s $scene && $scene -nt $corpusTool ]]; then
        skipped=$((skipped + 1))
    else
        "$corpusTool" tessellation "$triangles" "$scene" && built=$((built + 1)) || failed+=("hills-$triangles")
    fi
done
# A generated airport apron seen from 8 m under a low sun, once with one mesh per object and once merged into
# one mesh whose bounds span the view, as real assets often arrive.
for entry in "apron|" "apron-merged|--merged"; do
    IFS='|' read -r name options <<<"$entry"
    scene="$out/$name.glb"
    if [[ -s $scene && $scene -nt $corpusTool ]]; then
        skipped=$((skipped + 1))
    else
        # shellcheck disable=SC2086 # options are words
        "$corpusTool" apron "$scene" $options && built=$((built + 1)) || failed+=("$name")
    fi
done

echo "corpus: $built built, $skipped up to date, ${#failed[@]} failed${failed[*]:+: ${failed[*]}} (in $out/)"
