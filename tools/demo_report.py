#!/usr/bin/env python3
"""Writes the demo's report (Markdown, stdout) for a folder tools/demo.sh filled: the accuracy of every technique
against the ray-traced truth from the gs-shadowbench run in accuracy/results.json (with the sheets beside it), then
the frame times of every report.json gs-render wrote. The table carries what the sheets' labels do: acne, leak,
darkening, edge p95 both ways and frame time."""
import json
import math
import pathlib
import sys


def percent(fraction):
    """As gs-contactsheet's labels: two decimals from 1 % up, two significant digits below (at most four
    decimals), so a near-perfect view's few pixels of acne read apart from none."""
    value = 100.0 * fraction
    if value == 0.0:
        return "0"
    if abs(value) < 0.00005:
        return "<0.0001"
    decimals = 2 if abs(value) >= 1.0 else min(max(1 - math.floor(math.log10(abs(value))), 2), 4)
    return f"{value:.{decimals}f}"


def accuracy_table(results):
    """Markdown table of a gs-shadowbench results.json document: one row per configuration of our techniques,
    in the order the bench ran them (peer rows are left out)."""
    rows = [r for r in results["results"] if r.get("peer") is None]
    if not rows:
        raise ValueError("results.json has no rows of our techniques")
    scenes = sorted({r["scene"] for r in rows})
    lines = [
        f"Scene {', '.join(scenes)} at {results['width']}x{results['height']}, against {results['groundTruth']} "
        "ray-traced truth (Embree). Acne: lit receivers drawn shadowed; leak: shadowed receivers drawn lit (both "
        "outside the band around true shadow edges); darkening: mean visibility lost over lit receivers; MAE: "
        "mean absolute visibility error; edge p95: 95th percentile distance in pixels from true shadow edges to "
        "the nearest drawn one / from drawn edges to the nearest true one. Frame: whole frame, median, "
        f"{results['timingMethod']}.",
        "",
        "| technique | acne % | leak % | darkening % | MAE | edge p95 px | frame ms |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        name = r["label"] if len(scenes) == 1 else f"{r['scene']} {r['label']}"
        edges = r["edges"]
        lines.append(f"| {name} | {percent(r['acneRate'])} | {percent(r['leakRate'])} | {percent(r['darkening'])} "
                     f"| {r['mae']:.4f} | {edges['trueToRendered']['p95']:.1f} / "
                     f"{edges['renderedToTrue']['p95']:.1f} | {r['frameMs']['median']:.1f} |")
    return "\n".join(lines) + "\n"


def frame_table(root, reports):
    """Markdown table of gs-render's report.json files."""
    first = json.loads(reports[0].read_text())
    lines = [
        f"Renderer: {first['renderer']} ({first['glVersion']}). Timing: {first['timingMethod']}, "
        f"median of {first['frames']} frames after one warm-up frame, of a still view: frames that keep their shadow "
        "maps (ShadowSettings::reuseUnchangedMaps) count them in the last column.",
        "",
        "| image | technique | size | triangles drawn (after culling) | frame ms (median) | programs compiled | "
        "frames keeping their maps |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for path in reports:
        r = json.loads(path.read_text())
        image = pathlib.Path(r["image"])
        image = image.relative_to(root) if image.is_relative_to(root) else image
        lines.append(f"| {image} | {r['shadowTechnique']} | {r['width']}x{r['height']} | {r['triangles']} | "
                     f"{r['frameMillisecondsMedian']:.1f} | {r['programsCompiled']} | "
                     f"{r.get('framesReusingShadowMaps', 0)} / {r['frames']} |")
    return "\n".join(lines) + "\n"


def report(root):
    root = pathlib.Path(root)
    reports = sorted(root.glob("**/report.json"))
    if not reports:
        raise ValueError(f"no report.json under {root}")
    out = ["# Demo report\n"]
    accuracy = root / "accuracy" / "results.json"
    if accuracy.exists():
        out.append("## Accuracy\n")
        out.append("![every technique, labelled](contact-sheet.png)\n")
        out.append("![the truth's classes and each technique's errors](truth-sheet.png)\n")
        out.append(accuracy_table(json.loads(accuracy.read_text())))
    out.append("## Frames\n")
    out.append(frame_table(root, reports))
    return "\n".join(out)


if __name__ == "__main__":
    try:
        print(report(sys.argv[1]), end="")
    except (ValueError, KeyError, OSError) as error:
        sys.exit(f"demo_report: {error}")
