#!/usr/bin/env python3
"""The cost model of docs/RESULTS.md: each technique's lighting-pass overhead over the unshadowed lighting pass,
in fetch-equivalents (one more bilinear read per fragment, as gs-shadowbench --cost-model measures it on the same
scene), next to the map reads it makes, the goal 1.5 x reads + 2, and the instructions of its variants as the driver
compiled them (nir_counts.py).

usage: cost_model.py COST_MODEL_RESULTS.json [NIR_COUNTS.json]   prints the section (Markdown)
"""
import json
import sys


def goal(reads):
    """The issue's bound on a technique's lighting overhead, in fetch-equivalents."""
    return 1.5 * reads + 2.0


def probe_map_line(cost, unit):
    """One comparison read alone, by the map it reads (SceneCost::oneCompareReadByMap), with 2048² D24's;
    None when the run did not measure them."""
    others = cost.get("oneCompareReadByMap")
    reference = cost.get("oneCompareReadOverheadMs")
    if not others or reference is None or not unit > 0:
        return None
    maps = others + [{"size": 2048, "format": "d24", "oneCompareReadOverheadMs": reference}]
    maps.sort(key=lambda m: (m["size"] ** 2 * {"d16": 2, "d24": 4, "d32f": 4}[m["format"]], m["format"]))
    parts = [f"{m['size']}² {m['format'].upper()} {m['oneCompareReadOverheadMs']:.1f} ms "
             f"({m['oneCompareReadOverheadMs'] / unit:.1f})" for m in maps]
    smallest = maps[0]
    ratio = (f" (2048² D24 {reference / smallest['oneCompareReadOverheadMs']:.1f}x {smallest['size']}² "
             f"{smallest['format'].upper()} here)" if smallest["oneCompareReadOverheadMs"] > 0 else "")
    return ("That one comparison read, by the map it reads (ms, fetch-equivalents in brackets): " + ", ".join(parts)
            + ". The shader is the same for every map (D24 and D32F hold 4 bytes a texel, D16 2); what differs is "
            "the memory a fragment's first read brings in, which grows with the map's bytes" + ratio + ".\n")


def section(doc, nir=None):
    """The section's lines from a --cost-model run (and the variants' instruction counts, when given)."""
    variants = (nir or {}).get("variants", {})
    out = ["## Cost model\n",
           f"What the lighting pass costs beyond its fetches. A reference pass (gs-shadowbench --cost-model) makes 1, 2, "
           f"4, 8 and 16 reads per fragment of a 2048² D24 depth map, where the default technique's map lies, and nothing "
           f"else (one read also of 512² and 1024² D24 and 2048² D16 and D32F maps); the least-squares slope of its lighting pass over the count is one read's cost on this renderer "
           f"({doc['renderer']}, {doc['width']}x{doc['height']}, {doc['timingMethod']}, the counts alternated over "
           f"5 rounds, each count's fastest frame of a round). A technique's overhead is its lighting pass minus "
           f"the unshadowed one, the two timed back to back in each of 5 rounds and each a round's fastest frame "
           f"(the machine's noise only adds time; the median difference, its range over the rounds in brackets), "
           f"so that a drift of the machine's speed cancels; in fetch-equivalents, that over one bilinear read. "
           f"Goal: at most 1.5 x its map reads + 2. Instructions: the fragment shader "
           f"of each variant as Mesa's NIR (MESA_GLSL=dump) on "
           f"{(nir or {}).get('scene', 'the knob')}, texture instructions in brackets (a loop's counted once).\n"]
    scenes = {c["scene"]: c for c in doc["scenes"] if c.get("filteredFetchMs")}
    none = variants.get("none", {}).get("lighting")
    if none:
        out.append(f"The unshadowed lighting pass compiles to {none['instructions']} instructions.\n")
    for scene, cost in scenes.items():
        unit = cost["filteredFetchMs"]
        base = cost["unshadowedLightingMs"]["median"]
        out.append(f"**{scene}**: unshadowed lighting pass {base:.1f} ms; one read {unit:.2f} ms bilinear, "
                   f"{cost['compareFetchMs']:.2f} ms with comparison"
                   + (f"; the reference pass with one comparison read and nothing else adds "
                      f"{cost['oneCompareReadOverheadMs']:.1f} ms "
                      f"({cost['oneCompareReadOverheadMs'] / unit:.1f} fetch-equivalents), the least a one-read "
                      f"technique adds here" if cost.get("oneCompareReadOverheadMs") is not None and unit > 0 else "")
                   + ".\n")
        by_map = probe_map_line(cost, unit)
        if by_map:
            out.append(by_map)
        lines = ["| technique | map reads | lighting ms | overhead ms | fetch-equivalents | goal | meets | "
                 "shadow pass ms | lighting instructions | depth instructions |",
                 "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
        for r in doc["results"]:
            if r["scene"] != scene or r["peer"]:
                continue
            paired = r.get("lightingOverheadMs")
            overhead = paired["median"] if paired else r["lightingPassMs"]["median"] - base
            spread = f" [{paired['min']:.1f}, {paired['max']:.1f}]" if paired else ""
            equivalents = overhead / unit if unit > 0 else float("nan")
            v = variants.get(r["settings"]["technique"], {})
            lighting = v.get("lighting")
            depth = v.get("depth")
            lines.append(
                f"| `{r['label']}` | {r['mapReads']} | {r['lightingPassMs']['median']:.1f} | "
                f"{overhead:.1f}{spread} | "
                f"{equivalents:.1f} | {goal(r['mapReads']):.1f} | {'yes' if equivalents <= goal(r['mapReads']) else 'no'} | "
                f"{r['shadowPassMs']['median']:.1f} | "
                + (f"{lighting['instructions']} ({lighting['textures']})" if lighting else "–") + " | "
                + (f"{depth['instructions']}" if depth else "–") + " |")
        out.append("\n".join(lines) + "\n")
        vdsm = next((r for r in doc["results"] if r["scene"] == scene and r["label"] == "osg-vdsm"), None)
        default = next((r for r in doc["results"] if r["scene"] == scene and not r["peer"]
                        and r["settings"]["technique"] == doc.get("defaultTechnique")), None)
        if vdsm and default and vdsm["frameMs"]["median"] > 0:
            peer_base = cost.get("peerUnshadowedFrameMs") or {"median": float("nan")}
            out.append(f"Beside osgShadow's ViewDependentShadowMap on the same view: its frame "
                       f"{vdsm['frameMs']['median']:.1f} ms (unshadowed {peer_base['median']:.1f} ms), the default "
                       f"`{default['label']}` {default['frameMs']['median']:.1f} ms: "
                       f"{default['frameMs']['median'] / vdsm['frameMs']['median']:.2f}x; our shadow pass "
                       f"{default['shadowPassMs']['median']:.1f} ms against its shadow cost (shadowed minus unshadowed "
                       f"frame) {vdsm['frameMs']['median'] - peer_base['median']:.1f} ms.\n")
    return out


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    doc = json.load(open(sys.argv[1]))
    nir = json.load(open(sys.argv[2])) if len(sys.argv) == 3 else None
    print("\n".join(section(doc, nir)))


if __name__ == "__main__":
    main()
