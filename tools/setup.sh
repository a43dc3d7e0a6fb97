#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds, tests and runs with. Idempotent: installs only what is
# missing, so a machine that has everything does no network work.
set -euo pipefail

packages=(
    cmake ninja-build g++ pkg-config
    libepoxy-dev libegl1 libegl-mesa0 libgl1-mesa-dri
    libglfw3-dev libglm-dev libstb-dev
    fonts-dejavu-core # the labels of the demo's sheets (gs-contactsheet)
    libosd-dev libopenmesh-dev libtinygltf-dev libembree-dev
    libgtest-dev libbenchmark-dev libimgui-dev xvfb python3 python3-matplotlib nlohmann-json3-dev
    doxygen # the API reference and its check of the shadow module (tools/apidocs.sh)
    libopenscenegraph-dev # optional: gs-osgshadow, the osgShadow peer (tools/osgpeer)
    assimp-utils assimp-testmodels # the real-model corpus (tools/corpus.sh)
    nodejs # the Khronos glTF-Validator (tools/gltf-validate), run on every glTF we write; npm below
    clang libclang-rt-14-dev llvm # sanitizer build and libFuzzer targets; llvm gives llvm-symbolizer
)

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done

# Debian's npm, unless npm is already there (a Node.js build that bundles it conflicts with Debian's package).
command -v npm >/dev/null || missing+=(npm)

if ((${#missing[@]} > 0)); then
    echo "setup: installing ${missing[*]}"
    sudo=""
    if [[ $(id -u) -ne 0 ]]; then
        command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
        sudo="sudo"
    fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The glTF-Validator from the npm registry, at the version package-lock.json pins.
validator="$(dirname "$0")/gltf-validate"
if [[ ! -d $validator/node_modules/gltf-validator ]]; then
    echo "setup: installing the glTF-Validator (npm ci in $validator)"
    (cd "$validator" && npm ci --no-audit --no-fund --loglevel=error) ||
        echo "setup: warning: the glTF-Validator could not be installed; its test will say it is skipped" >&2
fi
