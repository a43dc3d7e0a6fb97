#!/usr/bin/env bash
# End-to-end checks of gs-osgshadow (the OpenSceneGraph peer): real vdsm, sm, pssm and two-map vdsm renders
# whose outputs must parse and show both shadow and light, and each bad input's message and exit status.
# usage: osgpeer_cli_test.sh GS_OSGSHADOW CONTENT_DIR OUT_DIR [MALLOPT_TAKES]
# MALLOPT_TAKES: 1 (the default) where glibc's allocator serves the peer, 0 under the sanitizers' allocator.
# Needs an X display: without DISPLAY it reruns itself under xvfb-run, or exits 77 (skipped) saying so.
set -u
if [[ -z ${DISPLAY:-} ]]; then
    command -v xvfb-run >/dev/null || { echo "osgpeer: no X display and xvfb-run is missing (apt-get install xvfb); skipped"; exit 77; }
    exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$@"
fi
peer=$1
content=$2
out=$3
mallopt_takes=${4:-1}
rm -rf "$out"
mkdir -p "$out"
source "$(dirname "$0")/expect.sh"
python=/usr/bin/python3


# Checks PREFIX.json's fields, that PREFIX.visibility.pfm is a WxH single-channel PFM with valid values in
# [0, 1] (or -1 for no lit surface), and that the frame is fairly shaded, as white diffuse without ambient
# gives: umbra pixels (<= 0.02) exist and at least half the lit surface reads 1 (the rest is the technique's
# own acne and penumbra).
check_outputs() { # check_outputs NAME PREFIX TECHNIQUE [SHADOW_MAPS [MAP_SIZE [ALLOCATOR]]]
    local name=$1 prefix=$2 technique=$3 maps=${4:-1} mapSize=${5:-512} allocator=${6:-tuned}
    if ! "$python" - "$prefix" "$technique" "$maps" "$mapSize" "$allocator" "$mallopt_takes" <<'PY'; then
import json, struct, sys
prefix, technique, maps, map_size = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
report = json.load(open(prefix + ".json"))
for key in ("technique", "osgClass", "renderer", "timingMethod", "size", "mapSize", "shadowMaps", "camera",
            "frames", "unshadowedMs", "shadowedMs", "triangles", "drawables", "osgSettings", "allocatorTuned"):
    assert key in report, "JSON lacks " + key
# Tuned as our renderer is: on a CPU rasteriser only, unless --allocator default or mallopt cannot take.
software = any(name in report["renderer"] for name in ("llvmpipe", "softpipe", "swrast"))
expected = software and sys.argv[5] == "tuned" and sys.argv[6] == "1"
assert report["allocatorTuned"] == expected, "allocatorTuned " + str(report)
assert report["shadowMaps"] == maps, "shadowMaps %d, wanted %d" % (report["shadowMaps"], maps)
assert report["camera"]["projection"] == "perspective" and 0 < report["camera"]["near"] < report["camera"]["far"]
settings = report["osgSettings"]
if technique == "pssm":
    assert settings["splits"] == maps and settings["ambientBias"] == [0.0, 1.0], str(settings)
if technique == "vdsm":
    assert settings["numShadowMapsPerLight"] == maps, str(settings)
for key in ("unshadowedMs", "shadowedMs"):
    times = report[key]
    assert 0 < times["min"] <= times["median"] <= times["max"], key + " not ordered: " + str(times)
assert report["technique"] == technique and report["size"] == [160, 120] and report["mapSize"] == map_size
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
umbra = sum(v <= 0.02 for v in valid)
full = sum(v >= 0.99 for v in valid)
assert umbra > 20, "only %d umbra pixels (<= 0.02): shadow is not black" % umbra
assert full > 0.5 * len(valid), "only %d of %d lit pixels read 1" % (full, len(valid))
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
# PSSM's only depth bias is a constant 2^-9 of each split's depth range, so 512² maps show acne on the
# ground at this size; 1024² keep it to a few per cent.
expect render-pssm 0 "pssm \(osgShadow::ParallelSplitShadowMap\) .* x2: .*wrote" -- \
    "$peer" --scene "$scene" --technique pssm --splits 2 --size 160x120 --map-size 1024 --frames 2 --warmup 1 \
    --out "$out/torus-pssm2"
check_outputs render-pssm "$out/torus-pssm2" pssm 2 1024
expect render-vdsm-csm2 0 "vdsm \(osgShadow::ViewDependentShadowMap\) .* x2: .*wrote" -- \
    "$peer" --scene "$scene" --technique vdsm --cascades 2 --size 160x120 --map-size 512 --frames 2 --warmup 1 \
    --out "$out/torus-vdsm-csm2"
check_outputs render-vdsm-csm2 "$out/torus-vdsm-csm2" vdsm 2

# Hand-written scenes without normals (the peer computes flat ones): a ground quad and a triangle above it lit
# from 45 degrees, so its shadow falls beside it; and one-triangle scenes without a directional light (only a
# spot) and without a camera.
"$python" - "$out" <<'PY'
import base64, json, struct, sys
folder = sys.argv[1]
def scene(nodes, lights, corners=((-1, 0, -1), (1, 0, -1), (0, 0, 1)),
          lens={"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}):
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
        "cameras": [lens],
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
orthographic = {"type": "orthographic", "orthographic": {"xmag": 3, "ymag": 3, "znear": 0.1, "zfar": 100}}
json.dump(scene([above, sun], [{"type": "directional"}], ground + occluder, orthographic),
          open(folder + "/orthographic.gltf", "w"))
PY

# ShadowMap draws only back faces into its map, so this one-sided occluder casts no shadow with sm: use vdsm.
expect render-flat 0 "vdsm \(osgShadow::.*wrote" -- \
    "$peer" --scene "$out/flat.gltf" --technique vdsm --size 160x120 --map-size 512 --frames 2 --warmup 1 \
    --out "$out/flat-vdsm"
check_outputs render-flat "$out/flat-vdsm" vdsm
expect render-default-allocator 0 "vdsm \(osgShadow::.*wrote" -- \
    "$peer" --scene "$out/flat.gltf" --technique vdsm --size 160x120 --map-size 512 --frames 2 --warmup 1 \
    --allocator default --out "$out/flat-vdsm-default-allocator"
check_outputs render-default-allocator "$out/flat-vdsm-default-allocator" vdsm 1 512 default
ls -a "$out" | grep -q '\.tmp' && { echo "FAIL temporary file left behind"; failures=$((failures + 1)); }

expect missingFile 1 "nope\.gltf: file not found" -- "$peer" --scene "$out/nope.gltf" --out "$out/x"
expect unknownTechnique 2 "--technique: unknown technique 'pcss'" -- \
    "$peer" --scene "$scene" --technique pcss --out "$out/x"
expect tooManyCascades 2 "--cascades: OpenSceneGraph 3.6's ViewDependentShadowMap renders at most 2 maps" -- \
    "$peer" --scene "$scene" --technique vdsm --cascades 3 --out "$out/x"
expect badSplits 2 "--splits: '5' is not an integer in \[1, 4\]" -- \
    "$peer" --scene "$scene" --technique pssm --splits 5 --out "$out/x"
expect splitsWithoutPssm 2 "--splits applies to --technique pssm only" -- \
    "$peer" --scene "$scene" --technique sm --splits 2 --out "$out/x"
expect cascadesWithoutVdsm 2 "--cascades applies to --technique vdsm only" -- \
    "$peer" --scene "$scene" --technique pssm --cascades 2 --out "$out/x"
expect pssmOrthographic 1 "orthographic\.gltf: --technique pssm needs a perspective camera" -- \
    "$peer" --scene "$out/orthographic.gltf" --technique pssm --out "$out/x"
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
expect badAllocator 2 "--allocator: 'fast' is not tuned or default" -- \
    "$peer" --scene "$scene" --allocator fast --out "$out/x"
expect missingOut 2 "--out is required" -- "$peer" --scene "$scene"
expect unknownOption 2 "unknown option '--bogus'" -- "$peer" --bogus
expect noDisplay 1 "no X display: DISPLAY is not set" -- env -u DISPLAY "$peer" --scene "$scene" --out "$out/x"
compgen -G "$out/x*" >/dev/null && { echo "FAIL output written despite failure"; failures=$((failures + 1)); }

exit $((failures > 0))
