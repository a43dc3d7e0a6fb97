#!/usr/bin/env bash
# Regenerates docs/RESULTS.md (and docs/results/*.png) from a fresh shadowbench sweep on this machine.
# Usage: bash tools/results.sh [work folder, default out/results]
set -euo pipefail
cd "$(dirname "$0")/.."
work=${1:-out/results}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-shadowbench
bench=./build/bin/gs-shadowbench
rm -rf "$work"

# 1. Trade-off sweep on the default scene: every technique, tap counts and map sizes.
"$bench" --scene knob --taps 2,4,6 --resolutions 512,1024,2048 --frames 7 --out "$work/knob-sweep"

# 2. Every stress scene at one map size (spheres: a spot light), plus the reproductions of the references' claims.
"$bench" --scene torus --scene bowl --scene thin-shell --scene crease-cube --scene grazing-plane --scene spheres \
    --taps 4 --resolutions 1024 --frames 5 --out "$work/scenes"
"$bench" --scene knob --techniques pcf,pcf-gsm-naive,pcf-gsm-point,pcf-gsm-average,pcf-gsm-quadratic \
    --taps 5 --radius 2 --resolutions 1024 --frames 15 \
    --config "rpb-d16-round:technique=receiver-plane,depthFormat=d16,constantBias=0" \
    --config "rpb-d16-floor:technique=receiver-plane,depthFormat=d16,constantBias=0,floorReceiverDepth=true" \
    --config "rpb-d24-round:technique=receiver-plane,depthFormat=d24,constantBias=0" \
    --config "rpb-d24-floor:technique=receiver-plane,depthFormat=d24,constantBias=0,floorReceiverDepth=true" \
    --config "average-circular8:technique=pcf-gsm-average,averageGradientForm=circular8,pcfRadius=1" \
    --config "average-circular8-vec4:technique=pcf-gsm-average,averageGradientForm=circular8-vec4,pcfRadius=1" \
    --config "naive-circular8:technique=pcf-gsm-naive,pcfLayout=circular8,pcfRadius=1" \
    --out "$work/reproduction"

# 3. Filtered families: VSM, EVSM and MSM light leaking, and early-out speed versus the same jittered kernel.
"$bench" --scene knob --scene thin-shell --scene spheres --techniques vsm,evsm,msm --resolutions 1024 --frames 7 \
    --config "msm-16bit:technique=msm,msmQuantize16=true,resolution=1024" \
    --config "vsm-no-reduction:technique=vsm,lightBleedingReduction=0,resolution=1024" \
    --config "jittered32-full:technique=pcf-jittered,jitterTaps=32,earlyOutTestTaps=0,constantBias=0.12,resolution=1024" \
    --config "jittered32-early8:technique=pcf-jittered,jitterTaps=32,earlyOutTestTaps=8,constantBias=0.12,resolution=1024" \
    --config "jittered64-full:technique=pcf-jittered,jitterTaps=64,earlyOutTestTaps=0,constantBias=0.12,resolution=1024" \
    --config "jittered64-early16:technique=pcf-jittered,jitterTaps=64,earlyOutTestTaps=16,constantBias=0.12,resolution=1024" \
    --out "$work/filtered"

# Debian's interpreter: python3-matplotlib installs there (a python3 earlier on PATH may lack it).
/usr/bin/python3 tools/shadowbench/results.py "$work" docs/RESULTS.md docs/results
echo "wrote docs/RESULTS.md"
