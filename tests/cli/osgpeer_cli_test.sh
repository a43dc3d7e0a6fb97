#!/usr/bin/env bash
# End-to-end checks of gs-osgshadow (the OpenSceneGraph peer): real vdsm and sm renders whose outputs must
# parse and show both shadow and light, and each bad input's message and exit status.
# usage: osgpeer_cli_test.sh GS_OSGSHADOW CONTENT_DIR OUT_DIR   (needs an X display: run under xvfb-run)
set -u
peer=$1
content=$2
out=$3
rm -rf "$out"
mkdir -p "$out"
source "$(dirname "$0")/expect.sh"
python=/usr/bin/python3


# Checks PREFIX.json's fields, that PREFIX.visibility.pfm is a WxH single-channel PFM with valid values in
# [0, 1] (or -1 for no lit surface), and that the frame has both shadowed (< 0.5) and lit (> 0.9) pixels.
check_outputs() { # check_outputs NAME PREFIX TECHNIQUE
    local name=$1 prefix=$2 technique=$3
    if ! "$python" - "$prefix" "$technique" <<'PY'; then
import json, struct, sys
prefix, technique = sys.argv[1], sys.argv[2]
report = json.load(open(prefix + ".json"))
for key in ("technique", "osgClass", "renderer", "timingMethod", "size", "mapSize", "frames", "unshadowedMs",
            "shadowedMs", "triangles", "drawables"):
    assert key in report, "JSON lacks " + key
for key in ("unshadowedMs", "shadowedMs"):
    times = report[key]
    assert 0 < times["min"] <= times["median"] <= times["max"], key + " not ordered: " + str(times)
assert report["technique"] == technique and report["size"] == [160, 120] and report["mapSize"] == 512
assert report["frames"] == 2 and report["triangles"] > 0 and report["drawables"] > 0
assert report["timingMethod"] == "glFinish + steady clock"
data = open(prefix + ".visibility.pfm", "rb").read()
magic, dims, scale, pixels = data.split(b"\n", 3)
width, height = map(int, dims.split())
assert magic == b"Pf" and (width, height) == (160, 120) and float(scale) < 0, "bad PFM header"
assert len(pixels) == 4 * width * height, "PFM has %d bytes of pixels" % len(pixels)
values = struct.unpack("<%df" % (width * height), pixels)
valid = [v for v in values if v != -1.0]
assert valid, "no valid pixel"
assert all(0.0 <= v <= 1.0 for v in valid), "valid visibility outside [0, 1]"
shadowed = sum(v < 0.5 for v in valid)
lit = sum(v > 0.9 for v in valid)
assert shadowed > 50 and lit > 1000, "shadowed %d, lit %d pixels" % (shadowed, lit)
assert open(prefix + ".png", "rb").read(8) == b"\x89PNG\r\n\x1a\n", "PNG signature"
PY
        echo "FAIL $name: outputs"
        failures=$((failures + 1))
    else
        echo "ok   $name outputs"
    fi
}

scene=$content/scenes/torus.gltf
for technique in vdsm sm; do
    expect "render-$technique" 0 "$technique \(osgShadow::.*wrote" -- \
        "$peer" --scene "$scene" --technique "$technique" --size 160x120 --map-size 512 --frames 2 --warmup 1 \
        --out "$out/torus-$technique"
    check_outputs "render-$technique" "$out/torus-$technique" "$technique"
done

# Hand-written scenes without normals (the peer computes flat ones): a ground quad and a triangle above it lit
# from 45 degrees, so its shadow falls beside it; and one-triangle scenes without a directional light (only a
# spot) and without a camera.
"$python" - "$out" <<'PY'
import base64, json, struct, sys
folder = sys.argv[1]
def scene(nodes, lights, corners=((-1, 0, -1), (1, 0, -1), (0, 0, 1))):
    triangle = b"".join(struct.pack("<3f", *corner) for corner in corners)
    return {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "buffers": [{"byteLength": len(triangle),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(triangle).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": len(triangle)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(corners), "type": "VEC3",
                       "min": [min(c[i] for c in corners) for i in range(3)],
                       "max": [max(c[i] for c in corners) for i in range(3)]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
        "nodes": [{"mesh": 0}] + nodes,
        "scenes": [{"nodes": list(range(1 + len(nodes)))}],
        "scene": 0,
    }
camera = {"camera": 0, "translation": [0, 1, 4]}
ground = ((-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, 3), (3, 0, -3), (-3, 0, -3))
occluder = ((-0.7, 1.5, 0.7), (0.7, 1.5, 0.7), (0, 1.5, -0.7))
above = {"camera": 0, "translation": [0, 3, 5], "rotation": [-0.2672, 0, 0, 0.9636]}  # 31 degrees down
# Shines along (1, -1, 0).
sun = {"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [-0.5, -0.5, 0, 0.7071068]}
json.dump(scene([above, sun], [{"type": "directional"}], ground + occluder),
          open(folder + "/flat.gltf", "w"))
spot = {"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 3, 0]}
json.dump(scene([camera, spot], [{"type": "spot", "spot": {}}]), open(folder + "/no-sun.gltf", "w"))
json.dump(scene([spot], [{"type": "directional"}]), open(folder + "/no-camera.gltf", "w"))
PY

# ShadowMap draws only back faces into its map, so this one-sided occluder casts no shadow with sm: use vdsm.
expect render-flat 0 "vdsm \(osgShadow::.*wrote" -- \
    "$peer" --scene "$out/flat.gltf" --technique vdsm --size 160x120 --map-size 512 --frames 2 --warmup 1 \
    --out "$out/flat-vdsm"
check_outputs render-flat "$out/flat-vdsm" vdsm
ls -a "$out" | grep -q '\.tmp' && { echo "FAIL temporary file left behind"; failures=$((failures + 1)); }

expect missingFile 1 "nope\.gltf: file not found" -- "$peer" --scene "$out/nope.gltf" --out "$out/x"
expect unknownTechnique 2 "--technique: unknown technique 'pcss'" -- \
    "$peer" --scene "$scene" --technique pcss --out "$out/x"
expect noDirectionalLight 1 "no-sun\.gltf: the scene has no directional light" -- \
    "$peer" --scene "$out/no-sun.gltf" --out "$out/x"
# The room content scene is lit by point lights only: the peer (which needs a sun) refuses it by name.
expect pointLightsOnly 1 "room\.gltf: the scene has no directional light" -- \
    "$peer" --scene "$content/scenes/room.gltf" --out "$out/x"
expect noCamera 1 "no-camera\.gltf: the scene has no camera" -- \
    "$peer" --scene "$out/no-camera.gltf" --out "$out/x"
expect badMapSize 2 "--map-size: '0' is not an integer in \[16, 16384\]" -- \
    "$peer" --scene "$scene" --map-size 0 --out "$out/x"
expect badSize 2 "--size: 'axb' is not WIDTHxHEIGHT|--size: 'a' is not an integer" -- \
    "$peer" --scene "$scene" --size axb --out "$out/x"
expect missingOut 2 "--out is required" -- "$peer" --scene "$scene"
expect unknownOption 2 "unknown option '--bogus'" -- "$peer" --bogus
expect noDisplay 1 "no X display: DISPLAY is not set" -- env -u DISPLAY "$peer" --scene "$scene" --out "$out/x"
compgen -G "$out/x*" >/dev/null && { echo "FAIL output written despite failure"; failures=$((failures + 1)); }

exit $((failures > 0))
