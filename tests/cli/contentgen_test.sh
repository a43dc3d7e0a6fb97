#!/usr/bin/env bash
# The committed content/ must be exactly what tools/contentgen writes: regenerate and compare.
set -u
generator=$1
content=$2
scratch=$3
rm -rf "$scratch"
"$generator" "$scratch" >/dev/null || { echo "FAIL generator exited $?"; exit 1; }
if ! diff -r "$content/cages" "$scratch/cages" || ! diff -r "$content/scenes" "$scratch/scenes"; then
    echo "FAIL content/ differs from the generator's output: run gs-contentgen content and commit"
    exit 1
fi
echo "ok content matches the generator"
