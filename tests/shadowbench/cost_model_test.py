#!/usr/bin/env python3
"""CostModelTest: the cost model's line on one comparison read by the map it reads (tools/shadowbench/
cost_model.py, probe_map_line) from a small results file: maps in order of their bytes, the default's 2048² D24
among them, fetch-equivalents over the scene's bilinear read, and no line where the run measured none."""
import pathlib
import sys

TOOL = pathlib.Path(sys.argv[1])
sys.path.insert(0, str(TOOL.parent))
from cost_model import probe_map_line, section  # noqa: E402


def cost(by_map):
    return {"scene": "model", "filteredFetchMs": 2.0, "compareFetchMs": 2.0,
            "unshadowedLightingMs": {"median": 20.0}, "oneCompareReadOverheadMs": 8.0,
            "oneCompareReadByMap": by_map}


MAPS = [{"size": 2048, "format": "d32f", "oneCompareReadOverheadMs": 9.0},
        {"size": 512, "format": "d24", "oneCompareReadOverheadMs": 3.0},
        {"size": 2048, "format": "d16", "oneCompareReadOverheadMs": 6.0},
        {"size": 1024, "format": "d24", "oneCompareReadOverheadMs": 4.0}]

failures = []
line = probe_map_line(cost(MAPS), 2.0)
expected = ["512² D24 3.0 ms (1.5)", "1024² D24 4.0 ms (2.0)", "2048² D16 6.0 ms (3.0)", "2048² D24 8.0 ms (4.0)",
            "2048² D32F 9.0 ms (4.5)"]
positions = [line.find(part) if line else -1 for part in expected]
if -1 in positions or positions != sorted(positions):
    failures.append(f"maps by their bytes: expected {expected} in order, got {line!r}")
if probe_map_line(cost(None), 2.0) is not None or probe_map_line(cost([]), 2.0) is not None:
    failures.append("a run without other maps gives no line")
if probe_map_line(cost(MAPS), 0.0) is not None:
    failures.append("no fetch-equivalents without a measured read")
doc = {"renderer": "test", "width": 64, "height": 48, "timingMethod": "test", "scenes": [cost(MAPS)],
       "results": []}
if not any("2048² D16 6.0 ms" in part for part in section(doc)):
    failures.append("the section carries the line")

for failure in failures:
    print("FAIL:", failure)
print(f"{4 - len(failures)} of 4 cases pass")
sys.exit(1 if failures else 0)
