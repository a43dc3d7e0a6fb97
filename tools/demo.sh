#!/usr/bin/env bash
# The main job: renders the default scene headless and writes images plus a report to out/ (or $1).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out}
bash tools/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target gs-render
./build/bin/gs-render --scene default --out "$out"
echo "report: $out/report.json"
cat "$out/report.json"
