#!/usr/bin/env bash
# The installable package, tested from outside the tree: installs a built tree to a temporary prefix, moves the
# prefix (the package must be relocatable), runs an installed tool by scene name with the shadow plugin loaded by
# name, then configures examples/host-app against the moved prefix alone, builds it, runs it and its CTest
# tests (the shadow module linked and as a plugin, and a gs-scenetest shadow-quality check). docs/INTEGRATING.md.
# usage: tools/package_test.sh [BUILD_DIR]   (default build-ci, already built)
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
build=$(realpath "${1:-build-ci}")
[[ -f $build/CMakeCache.txt ]] || { echo "package_test: $build is not a configured build folder" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unset GS_MODULE_PATH # modules must be found from the installed files alone
cmake --install "$build" --prefix "$work/installed" >/dev/null
mv "$work/installed" "$work/prefix"
prefix=$work/prefix

# Nothing installed may point back into the source or build tree.
if grep -rIl -e "$source_dir" -e "$build" "$prefix/lib/cmake" "$prefix/include"; then
    echo "package_test: FAILED: the files above refer to the source or build tree" >&2
    exit 1
fi

# An installed tool finds the installed content by scene name and the installed plugin by module name.
"$prefix/bin/gs-render" --scene torus --technique none --module shadows --size 160x120 --frames 1 \
    --out "$work/render" >/dev/null
[[ -s $work/render/torus.png ]] || { echo "package_test: FAILED: installed gs-render wrote no image" >&2; exit 1; }
installed_scene=$(realpath "$prefix")/share/GradientShadows/content/scenes/torus.gltf
grep -q "\"scene\": \"$installed_scene\"" "$work/render/report.json" ||
    { echo "package_test: FAILED: installed gs-render did not read $installed_scene" >&2; exit 1; }

# The example host, copied out of the tree and configured against the prefix only: no package registry, no
# path into this tree.
cp -r examples/host-app "$work/host-src"
cmake -S "$work/host-src" -B "$work/host" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
    -DCMAKE_CXX_FLAGS="-Wall -Wextra -Werror" >/dev/null
cmake --build "$work/host" >/dev/null
if grep -q -e "$source_dir/" -e "$build/" "$work/host/CMakeCache.txt" "$work/host/build.ninja"; then
    echo "package_test: FAILED: the host build refers to the source or build tree:" >&2
    grep -h -e "$source_dir/" -e "$build/" "$work/host/CMakeCache.txt" "$work/host/build.ninja" | head -5 >&2
    exit 1
fi
ctest --test-dir "$work/host" --output-on-failure
for image in linked.png plugin.png; do
    [[ -s $work/host/$image ]] || { echo "package_test: FAILED: host-app wrote no $image" >&2; exit 1; }
done
echo "package_test: passed (installed, moved, found by find_package, example host built, run and tested)"
