#!/usr/bin/env bash
# gs-contactsheet on a tiny gs-shadowbench run: both sheets written at the size the layout gives (three label
# lines: name; acne, leak, darkening; frame ms and edge p95), and bad input (no bench folder, a row without its
# frame time or edges, a missing font, bad options) refused with the right status and message.
set -u
bench=$1
sheet=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
source "$(dirname "$0")/expect.sh"

"$bench" --scene knob --techniques hard,pcf --size 64x48 --frames 1 --resolutions 256 --out "$out/bench" \
    > "$out/bench.log" 2>&1 || { echo "FAIL bench: $(cat "$out/bench.log")"; exit 1; }
expect writesBothSheets 0 "wrote $out/sheets/contact-sheet.png and $out/sheets/truth-sheet.png \(2 configurations of knob\)" -- \
    "$sheet" "$out/bench" --columns 2 --downsample 2 --out "$out/sheets"

# PNG width and height (IHDR, bytes 16..23, big endian).
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8}'; }
# Two 32x24 tiles side by side with 8 px padding: 8 + 2 * (32 + 8) = 88 wide; one row under a title line in
# DejaVu Sans' 14 px lines, three label lines: 8 + 14 + 8 + 24 + (3 * 14 + 4) + 8 = 108 high (a label without
# its frame-time-and-edges line makes it 94). The truth sheet has the truth as a third tile, so a second row.
size=$(png_size "$out/sheets/contact-sheet.png")
[[ $size == 88x108 ]] || { echo "FAIL contact sheet is $size, expected 88x108"; failures=$((failures + 1)); }
contact_height=${size#*x}
size=$(png_size "$out/sheets/truth-sheet.png")
truth_height=${size#*x}
[[ $size == 88x* && $truth_height -gt $((contact_height + 24)) ]] ||
    { echo "FAIL truth sheet is $size (contact sheet height $contact_height)"; failures=$((failures + 1)); }

expect noBenchFolder 1 "$out/none/results.json: cannot read" -- "$sheet" "$out/none"
# The labels need each row's frame time and edge p95; a results.json without them is refused, naming the key.
for key in frameMs edges; do
    mkdir -p "$out/no-$key"
    python3 -c 'import json, sys
results = json.load(open(sys.argv[1]))
for row in results["results"]:
    del row[sys.argv[2]]
json.dump(results, open(sys.argv[3], "w"))' "$out/bench/results.json" "$key" "$out/no-$key/results.json"
    expect "no-$key" 1 "no-$key/results.json: .*'$key' not found" -- "$sheet" "$out/no-$key" --out "$out/x"
done
expect missingFont 1 "/nonexistent/DejaVuSans.ttf: cannot read the font" -- \
    "$sheet" "$out/bench" --font /nonexistent/DejaVuSans.ttf --out "$out/x"
expect unknownScene 1 "no rows of scene 'torus'" -- "$sheet" "$out/bench" --scene torus --out "$out/x"
expect badDownsample 2 "--downsample: '0' is not an integer in \[1, 16\]" -- "$sheet" "$out/bench" --downsample 0
expect noArguments 2 "no BENCH_DIR given" -- "$sheet"
[[ ! -e $out/x ]] || { echo "FAIL output written despite the errors"; failures=$((failures + 1)); }

[[ $failures -eq 0 ]] && echo "ok contactsheet end to end"
exit $((failures > 0))
