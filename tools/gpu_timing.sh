#!/usr/bin/env bash
# The side-by-side timing and the cost model on a machine with a GPU, through EGL (NVIDIA's EGL is headless
# too): every technique at its defaults on the real models and the generated apron, timed per pass with
# GL_TIMESTAMP queries (the bench picks them on a hardware renderer), the reference pass's one-fetch cost
# per scene, and osgShadow's ViewDependentShadowMap beside them where an X display with a hardware GLX
# renderer is there (the peer needs GLX; under Xvfb it would run on llvmpipe, so it is left out, saying so).
# Writes the cost-model and Real-models tables to DIR/tables.md. Not run by the tests.
# Usage: bash tools/gpu_timing.sh [DIR, default out/gpu]
set -euo pipefail
cd "$(dirname "$0")/.."
work=${1:-out/gpu}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-shadowbench gs-render gs-corpus gs-osgshadow
bash tools/corpus.sh
mkdir -p "$work"

renderer=$(./build/bin/gs-render --scene knob --technique none --size 64x48 --frames 1 --out "$work/probe" |
    sed -n 's/.*(\(.*\), median frame.*/\1/p')
case "$renderer" in
    *llvmpipe* | *softpipe* | *lavapipe* | *SWR* | "")
        echo "gpu_timing.sh: EGL renders with '${renderer:-nothing}', not a GPU; docs/RESULTS.md holds the" \
            "llvmpipe figures (tools/results.sh)" >&2
        exit 1
        ;;
esac
echo "gpu_timing.sh: renderer $renderer"

scenes=(cylinder-engine jeep duck terrain apron-merged apron)
peer=()
if [ -n "${DISPLAY:-}" ] && glxinfo -B 2>/dev/null | grep -q "OpenGL renderer" &&
    ! glxinfo -B 2>/dev/null | grep -q "llvmpipe"; then
    for scene in "${scenes[@]}"; do
        ./build/bin/gs-osgshadow --scene "corpus/$scene.glb" --technique vdsm --size 640x480 --map-size 2048 \
            --frames 30 --warmup 5 --out "$work/osg/$scene/vdsm"
    done
    peer=(--peer "$work/osg")
else
    echo "gpu_timing.sh: no X display with a hardware GLX renderer: osgShadow's rows are left out" >&2
fi
./build/bin/gs-shadowbench $(printf -- '--scene %s ' "${scenes[@]}") --defaults --cost-model --frames 30 \
    --config "slope-scaled-d16:technique=slope-scaled,depthFormat=d16" \
    --config "slope-scaled-d32f:technique=slope-scaled,depthFormat=d32f" \
    "${peer[@]}" --out "$work/cost-model"
/usr/bin/python3 tools/shadowbench/nir_counts.py ./build/bin/gs-render "$work/cost-model/nir-counts.json"
/usr/bin/python3 tools/shadowbench/cost_model.py "$work/cost-model/results.json" \
    "$work/cost-model/nir-counts.json" >"$work/tables.md.tmp"
mv "$work/tables.md.tmp" "$work/tables.md"
echo "wrote $work/tables.md"
