#!/usr/bin/env python3
"""The floor every non-naive technique is held to at its defaults, and the rule that recommends the default
technique from the Defaults views and the real corpus's frame times (docs/RESULTS.md, "Defaults").

usage: default_rule.py DEFAULTS.json [DEFAULTS.json...] CORPUS.json
prints the recommendation line results.py writes, computed from those shadowbench results files.
"""
import json
import sys

# The floor for every non-naive technique at its defaults, and the fewest pixels a rate is scored over
# (under a light 1° above the horizon a view may see only a handful of receivers).
FLOOR = {"acneRate": 5e-4, "leakRate": 5e-4, "darkening": 5e-3}
MIN_PIXELS = 1000
# Edge distances count only where the truth has at least this many edge pixels: a view with a handful of true edge
# pixels and no rendered edge would otherwise weigh in at the image diagonal.
MIN_EDGE_PIXELS = 100
# The floor's edge placement, both ways (true→rendered, rendered→true), in screen pixels.
EDGE_FLOOR = {"mean": 0.5, "p95": 2.0}
# Shadow memory of one 2048² map a default may hold (a D24 depth map's): more only where it buys views.
MEMORY_BUDGET_MIB = 16.0


def scored(r):
    """The metrics of a row that have enough pixels behind them, as {key: value}."""
    counts = {"acneRate": r["pixels"]["lit"], "leakRate": r["pixels"]["shadowed"], "darkening": r["pixels"]["lit"]}
    return {k: r[k] for k in FLOOR if counts[k] >= MIN_PIXELS}


def edges_scored(r):
    return r["edges"]["trueToRendered"]["pixels"] >= MIN_EDGE_PIXELS


def edges_meet_floor(r):
    return not edges_scored(r) or all(r["edges"][d][k] <= EDGE_FLOOR[k]
                                      for d in ("trueToRendered", "renderedToTrue") for k in EDGE_FLOOR)


def meets_floor(r):
    return all(v < FLOOR[k] for k, v in scored(r).items()) and edges_meet_floor(r)


def map_mib(r):
    """Shadow memory per map of a row, scaled to a 2048² map."""
    maps = max(r["shadowMaps"], 1)
    side = r.get("mapResolution") or r["settings"]["resolution"]  # the map drawn (sized to the view)
    return r["shadowBytes"] / maps / 2**20 * (2048 / side) ** 2


def frame_ms(r):
    return r["frameMs"]["median"]


def candidates(defaults_rows, corpus_rows):
    """Per non-naive technique: views meeting the floor, views, mean error, median corpus frame and memory."""
    corpus_ms = {}
    for r in corpus_rows:
        if not r["peer"] and frame_ms(r) > 0:
            corpus_ms.setdefault(r["settings"]["technique"], []).append(frame_ms(r))
    out = []
    for technique in dict.fromkeys(r["settings"]["technique"] for r in defaults_rows if not r["peer"]):
        mine = [r for r in defaults_rows if not r["peer"] and r["settings"]["technique"] == technique]
        if mine[0]["naive"] or technique not in corpus_ms:
            continue
        times = sorted(corpus_ms[technique])
        with_maps = [map_mib(r) for r in mine if r["shadowMaps"] > 0]
        out.append({"technique": technique, "met": sum(meets_floor(r) for r in mine), "views": len(mine),
                    "error": sum(sum(scored(r).values()) for r in mine) / len(mine), "ms": times[len(times) // 2],
                    "mib": max(with_maps) if with_maps else 0.0})
    return out


def recommend(defaults_rows, corpus_rows):
    """The recommended technique and the line that says why.

    The floor comes first: the technique meeting it in the most views. Memory next: a technique above
    MEMORY_BUDGET_MIB per map takes part only where it meets the floor in more views than every technique within
    it. Among the techniques left with the most views, the lowest mean error x median corpus frame."""
    rows = candidates(defaults_rows, corpus_rows)
    if not rows:
        raise ValueError("no non-naive technique with Defaults views and corpus frame times")
    within = [c for c in rows if c["mib"] <= MEMORY_BUDGET_MIB]
    best_within = max((c["met"] for c in within), default=-1)
    eligible = within + [c for c in rows if c["mib"] > MEMORY_BUDGET_MIB and c["met"] > best_within]
    most = max(c["met"] for c in eligible)
    ranked = sorted((c for c in eligible if c["met"] == most), key=lambda c: (c["error"] * c["ms"], c["technique"]))
    best = ranked[0]
    over = sorted((c for c in rows if c not in eligible), key=lambda c: -c["met"])

    def figures(c):
        return (f"`{c['technique']}` {c['met']} / {c['views']} views, {c['error']:.2e} x {c['ms']:.1f} ms = "
                f"{c['error'] * c['ms']:.2e}, {c['mib']:.0f} MiB")

    line = (f"**Recommended default: `{best['technique']}`**: it meets the floor in {best['met']} of {best['views']} "
            f"Defaults views, the most of any technique within {MEMORY_BUDGET_MIB:g} MiB per 2048² map or above it, "
            "and among those has the lowest (mean over views of acne + leak + darkening) x (median frame on the real "
            f"corpus): {figures(best)} per map. Next: " + "; ".join(figures(c) for c in ranked[1:4]) + ". ")
    if over:
        line += ("Left out for memory (more than the budget without more views): "
                 + "; ".join(figures(c) for c in over[:3]) + ". ")
    return best["technique"], line


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    documents = [json.load(open(path)) for path in sys.argv[1:]]
    defaults_rows = [r for d in documents[:-1] for r in d["results"]]
    print(recommend(defaults_rows, documents[-1]["results"])[1])


if __name__ == "__main__":
    main()
