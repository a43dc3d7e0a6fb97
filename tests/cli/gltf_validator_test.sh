#!/usr/bin/env bash
# Every glTF the project writes passes the Khronos glTF-Validator with 0 errors (warnings are listed): the
# content scenes (gs-contentgen), the corpus scenes (gs-corpus) when built, and a fresh GltfWriter round trip of
# scene with extras.subdivision tags (gs-corpus stage of a content scene). Exit 77 (skipped) when Node.js or the validator is
# missing, saying so.
set -u
repo=$1
corpusTool=$2
work=$3
command -v node >/dev/null || { echo "gltf-validate: Node.js is missing (apt-get install nodejs); skipped"; exit 77; }
rm -rf "$work"
mkdir -p "$work"
"$corpusTool" stage "$repo/content/scenes/torus.gltf" "$work/torus-staged.gltf" --subdivide loop:1 >/dev/null || exit 1
shopt -s nullglob
exec node "$repo/tools/gltf-validate/validate.mjs" "$repo"/content/scenes/*.gltf "$repo"/corpus/*.glb \
    "$repo"/corpus/sweep/*.glb "$work/torus-staged.gltf"
