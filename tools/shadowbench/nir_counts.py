#!/usr/bin/env python3
"""Counts the instructions of each technique's shader variants as the driver compiled them: Mesa prints every
linked program's NIR under MESA_GLSL=dump (the shader cache off, so every program compiles). Renderer-independent
beside the timings: NIR is what every Mesa driver (llvmpipe, radeonsi, iris) starts its own compiler from.

Usage: nir_counts.py GS_RENDER OUT.json [SCENE]
Writes {technique: {"lighting": {...}, "depth": {...}}}, each with the fragment shader's instruction count
(ALU, intrinsics and texture instructions; constants, derefs, phis and undefs left out), its texture
instructions and its branches (if) and loops, on SCENE (default knob: one directional light, one map)."""
import json
import os
import re
import subprocess
import sys
import tempfile

NOT_COUNTED = re.compile(r"= (load_const|deref_\w+|phi|undefined)\b")
DEFINITION = re.compile(r"^\s+(vec\d+ \d+ ssa_\d+ = |intrinsic )")
TEXTURE = re.compile(r"= \(\w+\)(tex|txl|txb|txd|txf|txf_ms|tg4|txs|lod|query_levels)\b")


def programs(dump):
    """(stage, declarations, body lines) of every shader in a MESA_GLSL=dump log."""
    shaders = []
    current = None
    for line in dump.splitlines():
        if line.startswith("shader: MESA_SHADER_"):
            current = {"stage": line.split("_")[-1].lower(), "declarations": [], "body": []}
            shaders.append(current)
        elif current is not None:
            (current["declarations"] if line.startswith("decl_var") else current["body"]).append(line)
    return shaders


def counts(shader):
    body = [line for line in shader["body"] if DEFINITION.match(line) and not NOT_COUNTED.search(line)]
    return {
        "instructions": len(body),
        "textures": sum(1 for line in body if TEXTURE.search(line)),
        "branches": sum(1 for line in shader["body"] if line.strip().startswith("if ")),
        "loops": sum(1 for line in shader["body"] if line.strip() == "loop {"),
    }


def measure(render, technique, scene):
    environment = dict(os.environ, MESA_GLSL="dump", MESA_SHADER_CACHE_DISABLE="true")
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([render, "--scene", scene, "--technique", technique, "--size", "64x48", "--frames",
                              "1", "--out", out], env=environment, capture_output=True, text=True, check=True)
    shaders = programs(run.stdout + run.stderr)
    result = {}
    for index, shader in enumerate(shaders):
        names = " ".join(shader["declarations"])
        if shader["stage"] == "fragment" and "uBaseColor" in names:
            result["lighting"] = counts(shader)
        # The depth pass's fragment shader follows its vertex shader, the one projecting with uLightViewProjection.
        if (shader["stage"] == "fragment" and index > 0 and shaders[index - 1]["stage"] == "vertex"
                and "uLightViewProjection" in " ".join(shaders[index - 1]["declarations"])):
            result["depth"] = counts(shader)
    if "lighting" not in result:
        raise SystemExit(f"nir_counts.py: no lighting program in the {technique} run's dump (MESA_GLSL=dump "
                         "prints nothing on this driver?)")
    return result


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    render, out = sys.argv[1], sys.argv[2]
    scene = sys.argv[3] if len(sys.argv) == 4 else "knob"
    techniques = ["none"] + subprocess.run([render, "--list-techniques"], capture_output=True, text=True,
                                           check=True).stdout.split()
    table = {technique: measure(render, technique, scene) for technique in techniques}
    folder = os.path.dirname(os.path.abspath(out))
    os.makedirs(folder, exist_ok=True)
    with tempfile.NamedTemporaryFile("w", dir=folder, delete=False, suffix=".tmp") as temporary:
        json.dump({"scene": scene, "variants": table}, temporary, indent=2)
    os.replace(temporary.name, out)
    for technique, row in table.items():
        lighting = row["lighting"]
        print(f"{technique}: lighting {lighting['instructions']} instructions ({lighting['textures']} texture), "
              f"depth {row.get('depth', {}).get('instructions', '-')}")


if __name__ == "__main__":
    main()
