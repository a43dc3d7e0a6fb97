#!/usr/bin/env python3
"""Summarises the report.json files gs-render wrote under a folder as a Markdown table (stdout)."""
import json
import pathlib
import sys

root = pathlib.Path(sys.argv[1])
reports = sorted(root.glob("**/report.json"))
if not reports:
    sys.exit(f"demo_report: no report.json under {root}")
first = json.loads(reports[0].read_text())
print("# Demo report\n")
print(f"Renderer: {first['renderer']} ({first['glVersion']}). Timing: {first['timingMethod']}, "
      f"median of {first['frames']} frames after one warm-up frame.\n")
print("| image | technique | size | triangles drawn (after culling) | frame ms (median) | programs compiled |")
print("| --- | --- | --- | --- | --- | --- |")
for path in reports:
    r = json.loads(path.read_text())
    image = pathlib.Path(r["image"]).relative_to(root) if pathlib.Path(r["image"]).is_relative_to(root) else r["image"]
    print(f"| {image} | {r['shadowTechnique']} | {r['width']}x{r['height']} | {r['triangles']} | "
          f"{r['frameMillisecondsMedian']:.1f} | {r['programsCompiled']} |")
