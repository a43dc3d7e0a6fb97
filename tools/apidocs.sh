#!/usr/bin/env bash
# Generates the API reference of the public headers (docs/Doxyfile) as HTML in OUT/html and fails when a public
# declaration of the shadow module (modules/shadows/include) is undocumented or its comment is malformed. Gaps
# in the engine's and the content library's headers are counted, not fatal. Exit 77 (skipped) without doxygen.
# usage: tools/apidocs.sh [OUT]   (default build-ci/apidocs)
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:-build-ci/apidocs}")

if ! command -v doxygen >/dev/null; then
    echo "apidocs: skipped: doxygen is not installed (Debian: doxygen; bash tools/setup.sh installs it)"
    exit 77
fi
rm -rf "$out"
mkdir -p "$out"
log=$out/warnings.log
{
    cat docs/Doxyfile
    echo "OUTPUT_DIRECTORY = $out"
    echo "WARN_LOGFILE = $log"
} | doxygen -

# One warning per line that names a file; continuation lines (e.g. parameter lists) name none.
shadow_warnings=$(grep -E "modules/shadows/include/[^:]+:[0-9]+: warning:" "$log" || true)
other_count=$(grep -E ": warning:" "$log" | grep -cv "modules/shadows/include/" || true)
echo "apidocs: $out/html/index.html; $other_count warnings outside the shadow module (not fatal)"
if [[ -n $shadow_warnings ]]; then
    echo "apidocs: FAILED: $(wc -l <<<"$shadow_warnings") undocumented or malformed declarations in the shadow module's public API:"
    echo "$shadow_warnings"
    exit 1
fi
echo "apidocs: the shadow module's public API is documented"
