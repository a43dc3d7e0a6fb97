#!/usr/bin/env python3
"""Writes docs/RESULTS.md and its plots from the results.json files of tools/results.sh's shadowbench runs.

usage: results.py WORK_FOLDER RESULTS_MD PLOT_FOLDER [--only real|defaults|filtered|lights|virtual|soft|cost|sizing|
still]

With --only real (filtered, lights, virtual, soft, cost, sizing, still), only steps 4-6's (3's, 8's, 11's, 12's,
10's, 13's, 14's) section, "Real models" ("Filtered families: ...", "Every light: ...", "Virtual maps", "Soft
shadows", "Cost model", "Maps sized to the view", "A still view keeps its maps") up to the next "## " section, is
regenerated from WORK_FOLDER and replaces its own in RESULTS_MD, which says so; every other section stays as the last
full run wrote it. --only defaults regenerates steps 4-7's three: "Real models", "Defaults" and "PCF over GSM
against single-tap GSM".
"""
import itertools
import json
import pathlib
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from default_rule import EDGE_FLOOR, FLOOR, MEMORY_BUDGET_MIB, MIN_EDGE_PIXELS, MIN_PIXELS  # noqa: E402
from default_rule import edges_scored, map_mib, meets_floor, recommend, scored  # noqa: E402
import cost_model  # noqa: E402
from peer_rounds import bracketed, median_ratio  # noqa: E402

# The sections --only regenerates alone, by its option.
PARTIAL_SECTIONS = {"real": "## Real models", "defaults": "## Defaults", "virtual": "## Virtual maps",
                    "filtered": "## Filtered families: VSM, EVSM, MSM and jittered PCF with early-out",
                    "lights": "## Every light: cascades and point lights",
                    "soft": "## Soft shadows", "cost": "## Cost model",
                    "sizing": "## Maps sized to the view", "still": "## A still view keeps its maps"}

work, results_md, plot_folder = (pathlib.Path(a) for a in sys.argv[1:4])
if sys.argv[4:] != [] and not (len(sys.argv) == 6 and sys.argv[4] == "--only" and sys.argv[5] in PARTIAL_SECTIONS):
    sys.exit(f"results.py: unknown options {' '.join(sys.argv[4:])} (usage: see its docstring)")
partial = sys.argv[5] if len(sys.argv) > 5 else None
plot_folder.mkdir(parents=True, exist_ok=True)


def load(name):
    path = work / name / "results.json"
    if not path.exists():
        sys.exit(f"results.py: {path} is missing (run tools/results.sh)")
    return json.loads(path.read_text())


if not partial:
    sweep, scenes, repro, filtered = load("knob-sweep"), load("scenes"), load("reproduction"), load("filtered")
    meta = sweep


def band_description(meta):
    """What the band of a run's metadata is, in words (runs before the pixel band name texels)."""
    band = meta.get("band", {"width": meta.get("bandTexels", 2), "unit": "texels"})
    if band["unit"] == "pixels":
        return (f"a receiver within {band['width']:g} screen pixels of a receiver of the other truth, or whose other "
                "side lies within that reach off the image, hidden from the camera")
    return (f"within {band['width']:g} shadow texels of a receiver of the other truth, measured across the light's "
            "rays as the map sees them, or next to one")


def total_ms(r):
    return r["shadowPassMs"]["median"] + r["lightingPassMs"]["median"]


def pareto(rows):
    """Rows not dominated in (total time, MAE)."""
    front = []
    for r in sorted(rows, key=lambda r: (total_ms(r), r["mae"])):
        if not front or r["mae"] < front[-1]["mae"]:
            front.append(r)
    return front


def plot(rows, scene, path):
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
    families = sorted({r["settings"]["technique"] for r in rows})
    markers = "os^vD<>P*Xh"
    for n, family in enumerate(families):
        pts = [r for r in rows if r["settings"]["technique"] == family]
        # Colour and marker both vary: more families than the palette has colours.
        ax.scatter([total_ms(r) for r in pts], [r["mae"] for r in pts], label=family, s=20,
                   marker=markers[n % len(markers)], color=plt.cm.tab20(n % 20))
    front = pareto(rows)
    ax.plot([total_ms(r) for r in front], [r["mae"] for r in front], "k--", linewidth=0.8, label="Pareto front")
    ax.set_xlabel(f"shadow + lighting pass, ms (median; {meta['timingMethod']})")
    ax.set_ylabel("mean absolute visibility error vs ray-traced truth")
    ax.set_yscale("symlog", linthresh=1e-3)
    ax.set_title(f"{scene}: time versus error ({meta['width']}x{meta['height']}, {meta['renderer']})", fontsize=8)
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def edges(r):
    """Edge placement, pixels: true->rendered and rendered->true, mean / 95th percentile; then texel density: the
    fraction of lit receivers at m <= 1 / the 99th percentile of m (– for the peer, whose maps we do not know)."""
    e = r["edges"]
    d = r.get("density")
    density = f"{100 * d['atMostOnePixel']:.0f} % / {d['p99']:.1f}" if d else "–"
    return (f"{e['trueToRendered']['mean']:.2f} / {e['trueToRendered']['p95']:.1f} | "
            f"{e['renderedToTrue']['mean']:.2f} / {e['renderedToTrue']['p95']:.1f} | {density}")


def table(rows):
    lines = ["| configuration | acne | leak | darkening | MAE | edges true→rendered px | edges rendered→true px | m ≤ 1 / m p99 "
             "| shadow ms | lighting ms | memory |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    front = {id(r) for r in pareto(rows)}
    for r in sorted(rows, key=total_ms):
        star = " ★" if id(r) in front else ""
        lines.append(f"| {r['label']}{star} | {100 * r['acneRate']:.2f} % | {100 * r['leakRate']:.2f} % | "
                     f"{r['darkening']:.4f} | {r['mae']:.4f} | {edges(r)} | {r['shadowPassMs']['median']:.2f} | "
                     f"{r['lightingPassMs']['median']:.2f} | {r['shadowBytes'] / 2**20:.1f} MiB |")
    return "\n".join(lines)


def by_label(doc, label, scene="knob"):
    for r in doc["results"]:
        if r["label"] == label and r["scene"] == scene:
            return r
    sys.exit(f"results.py: no result '{label}' for {scene}")


out = []


def filtered_section(filtered, moments16, moments16_lights):
    """The filtered families on three scenes, then the moments' precision over the Defaults views."""
    out.append("## Filtered families: VSM, EVSM, MSM and jittered PCF with early-out\n")
    out.append("| scene | configuration | acne | leak | MAE | edges true→rendered px | edges rendered→true px | m ≤ 1 / m p99 | lighting ms "
               "| memory | full-kernel pixels |")
    out.append("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in filtered["results"]:
        full = f"{100 * r['fullKernelFraction']:.1f} %" if r["fullKernelFraction"] >= 0 else "—"
        out.append(f"| {r['scene']} | {r['label']} | {100 * r['acneRate']:.2f} % | {100 * r['leakRate']:.2f} % | "
                   f"{r['mae']:.4f} | {edges(r)} | {r['lightingPassMs']['median']:.2f} | {r['shadowBytes'] / 2**20:.1f} MiB | "
                   f"{full} |")
    out.append("")
    for scene in sorted({r["scene"] for r in filtered["results"]}):
        full32, early32 = by_label(filtered, "jittered32-full", scene), by_label(filtered, "jittered32-early8", scene)
        full64, early64 = by_label(filtered, "jittered64-full", scene), by_label(filtered, "jittered64-early16", scene)
        vsm, msm = by_label(filtered, "vsm-1024-d24", scene), by_label(filtered, "msm-1024-d24", scene)
        evsm = by_label(filtered, "evsm-1024-d24", scene)
        out.append(f"- **{scene}**: early-out speed-up {full32['lightingPassMs']['median'] / early32['lightingPassMs']['median']:.2f}x "
                   f"(32 taps, 8 test) and {full64['lightingPassMs']['median'] / early64['lightingPassMs']['median']:.2f}x "
                   f"(64 taps, 16 test) on the lighting pass (the soft shadows reference measured 1.5x and 3.0x on its "
                   f"scenes); MAE cost {early32['mae'] - full32['mae']:+.4f} / {early64['mae'] - full64['mae']:+.4f}; "
                   f"{100 * early32['fullKernelFraction']:.1f} % of pixels took the full kernel. Light leaking: VSM "
                   f"{100 * vsm['leakRate']:.2f} %, EVSM {100 * evsm['leakRate']:.2f} %, MSM {100 * msm['leakRate']:.2f} %.")
    out.append("")

    moments_precision(moments16, moments16_lights)


def moments_precision(views, lights):
    """vsm and msm with 16-bit moments (the default) against 32-bit floats over the Defaults views: the floor, the
    rates and the memory each precision holds."""
    rows = [r for r in views["results"] if not r["peer"]]
    per_label = {}
    for r in rows:
        per_label.setdefault(r["label"], {})[r["scene"]] = r
    out.append(f"16-bit moments (`moments16`, the default: vsm's in RG16, msm's in RGBA16 through the optimised basis) "
               f"against 32-bit floats over the {len(next(iter(per_label.values())))} Defaults views "
               f"({views['width']}x{views['height']}, accuracy only, the floor of \"Defaults\"): views meeting the "
               "floor, the mean over views of acne + leak + darkening (the default rule's error), the worst view's "
               "rates, the mean MAE and edge placement (mean over views of the per-view mean, both ways), the views "
               "each precision meets the floor in and the other does not, and the memory of one 2048² map.\n")
    lines = ["| technique | moments | views meeting the floor | mean error | worst acne / leak / darkening | mean MAE | "
             "edges true→rendered / rendered→true px | views only this precision meets | memory per 2048² map |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for technique in ("vsm", "msm"):
        sixteen, thirty_two = per_label[technique], per_label[f"{technique}-32bit"]
        for label, mine, other in (("16-bit", sixteen, thirty_two), ("32-bit float", thirty_two, sixteen)):
            scored_edges = [r for r in mine.values() if edges_scored(r)]
            only_here = [s for s, r in mine.items() if meets_floor(r) and not meets_floor(other[s])]
            lines.append(
                f"| `{technique}` | {label} | {sum(meets_floor(r) for r in mine.values())} / {len(mine)} | "
                f"{sum(sum(scored(r).values()) for r in mine.values()) / len(mine):.2e} | "
                + " / ".join(f"{100 * max(r[k] for r in mine.values()):.3f} %" for k in RATES)
                + f" | {sum(r['mae'] for r in mine.values()) / len(mine):.5f} | "
                + " / ".join(f"{sum(r['edges'][d]['mean'] for r in scored_edges) / len(scored_edges):.3f}"
                             for d in ("trueToRendered", "renderedToTrue"))
                + f" | {', '.join(only_here) or 'none'} | "
                f"{max(map_mib(r) for r in mine.values() if r['shadowMaps'] > 0):.0f} MiB |")
    out.append("\n".join(lines) + "\n")
    out.append(f"The same on the 4 km outdoor scene (its sun's automatic cascades) and in the room (two point lights' "
               f"cube faces), {lights['width']}x{lights['height']}: acne / leak / darkening and edges (mean both ways), "
               "16-bit against 32-bit float; a long depth range quantises coarser in 16 bits.\n")
    rows = [r for r in lights["results"] if not r["peer"]]
    lines = ["| scene | technique | 16-bit: acne / leak / darkening | 16-bit: edges px | 32-bit: acne / leak / darkening "
             "| 32-bit: edges px |", "| --- | --- | --- | --- | --- | --- |"]
    for scene in dict.fromkeys(r["scene"] for r in rows):
        for technique in ("vsm", "msm"):
            cells = []
            for label in (technique, f"{technique}-32bit"):
                r = next(r for r in rows if r["scene"] == scene and r["label"] == label)
                cells.append(" / ".join(f"{100 * r[k]:.3f}" for k in RATES) + " % | "
                             f"{r['edges']['trueToRendered']['mean']:.2f} / {r['edges']['renderedToTrue']['mean']:.2f}")
            lines.append(f"| {scene} | `{technique}` | " + " | ".join(cells) + " |")
    out.append("\n".join(lines) + "\n")


def reference_sections():
    """The header, the references' reproductions, the filtered families and the content scenes' sweeps."""
    out.append("# Results: speed versus accuracy\n")
    out.append("Generated by `bash tools/results.sh` (shadowbench sweeps, then `tools/shadowbench/results.py`); "
               "every figure below comes from that command. Do not edit by hand.\n")
    out.append(f"- Renderer: {meta['renderer']} ({meta['glVersion']})")
    out.append(f"- Timing: {meta['timingMethod']}; median over timed frames after one warm-up frame "
               "(`shadow` = the module's pre-pass, `lighting` = the forward pass)")
    out.append(f"- Ground truth: {meta['groundTruth']} visibility ray-traced with Embree 3 from a G-buffer of the same "
               "refined geometry")
    out.append(f"- Images {meta['width']}x{meta['height']}; receivers = pixels facing the light by both their smoothed "
               "normal and their facet (where the two disagree, at a smoothed mesh's terminator, the facets shadow "
               "themselves); acne = truly lit receivers with visibility < 0.5, "
               "leak = truly shadowed receivers with visibility > 0.5, both outside a band around true shadow edges: "
               f"{band_description(meta)} (surfaces facing away from the light count as dark: a lit face meeting one is "
               "at an edge of the light); darkening = mean (1 - V) over truly lit "
               "receivers; MAE over every receiver; edges: distances in pixels from each true shadow-edge pixel to the "
               "nearest rendered one and back, mean / 95th percentile. ★ marks the Pareto front (no configuration is both faster and "
               "more accurate).\n")

    # Reproductions.
    naive = by_label(repro, "pcf-gsm-naive-5x5-1024-d24")
    point = by_label(repro, "pcf-gsm-point-5x5-1024-d24")
    average = by_label(repro, "pcf-gsm-average-5x5-1024-d24")
    quadratic = by_label(repro, "pcf-gsm-quadratic-5x5-1024-d24")
    pcf = by_label(repro, "pcf-5x5-1024-d24")
    rnd16, flr16 = by_label(repro, "rpb-d16-round"), by_label(repro, "rpb-d16-floor")
    rnd24, flr24 = by_label(repro, "rpb-d24-round"), by_label(repro, "rpb-d24-floor")
    circ, circ4 = by_label(repro, "average-circular8"), by_label(repro, "average-circular8-vec4")
    naive8 = by_label(repro, "naive-circular8")
    ratio_pcf = average["lightingPassMs"]["median"] / pcf["lightingPassMs"]["median"]
    ratio_naive = average["lightingPassMs"]["median"] / naive["lightingPassMs"]["median"]
    ratio_c8 = circ4["lightingPassMs"]["median"] / naive8["lightingPassMs"]["median"]
    out.append("## Reproducing the references (knob, 5x5 taps, radius 2 texels, 1024² D24)\n")
    out.append("| claim | reference | ours | holds? |")
    out.append("| --- | --- | --- | --- |")
    out.append(f"| naive PCF over GSM darkens lit surfaces by about half | GSM multisampling, Fig. 4.2.3 | darkening "
               f"{naive['darkening']:.3f} (corrected: point {point['darkening']:.4f}, average {average['darkening']:.4f}) "
               f"| {'yes' if naive['darkening'] > 0.3 else 'no'} |")
    out.append(f"| following the average gradient darkens concave regions less than the point gradient | Fig. 4.2.5 | "
               f"concave darkening point {point['concaveDarkening']:.4f}, average {average['concaveDarkening']:.4f} "
               f"({point['pixels']['concave']} concave lit pixels) | "
               f"{'yes' if average['concaveDarkening'] < point['concaveDarkening'] else 'no'} |")
    out.append(f"| higher-order correction follows curvature (\"the obvious improvement\") | Fig. 4.2.5 text | "
               f"concave darkening quadratic {quadratic['concaveDarkening']:.4f} | "
               f"{'yes' if quadratic['concaveDarkening'] < min(point['concaveDarkening'], average['concaveDarkening']) else 'no'} |")
    out.append(f"| the comparison rounds the reference to D16; flooring it removes the extra acne | bias reference | "
               f"receiver plane, no bias: D16 acne {100 * rnd16['acneRate']:.2f} % rounded vs {100 * flr16['acneRate']:.2f} % "
               f"floored; D24 {100 * rnd24['acneRate']:.2f} % vs {100 * flr24['acneRate']:.2f} % | "
               f"{'yes' if flr16['acneRate'] < rnd16['acneRate'] else 'no'} |")
    out.append(f"| average-gradient PCF needs no extra lookups: target ≤ 1.15x plain PCF with the same taps | "
               f"GSM multisampling, \"Optimizing Texture Look-ups\" | lighting pass {average['lightingPassMs']['median']:.2f} ms "
               f"vs plain PCF {pcf['lightingPassMs']['median']:.2f} ms = {ratio_pcf:.2f}x; vs naive PCF over GSM (same "
               f"linear-filtered lookups) {ratio_naive:.2f}x; circular-8 SIMD form vs naive circular-8 {ratio_c8:.2f}x | "
               f"{'yes' if ratio_pcf <= 1.15 else 'no'} |")
    out.append("")
    out.append(f"Circular-8 closed form and SIMD form agree with the general regression: MAE {circ['mae']:.4f} and "
               f"{circ4['mae']:.4f}.\n")

    filtered_section(filtered, load_views("moments16"), load("moments16-lights"))

    # Knob sweep.
    out.append("## Default scene (knob): techniques x taps x map sizes\n")
    plot(sweep["results"], "knob", plot_folder / "knob-pareto.png")
    out.append("![knob: time versus error](results/knob-pareto.png)\n")
    out.append(table(sweep["results"]) + "\n")
    side = work / "knob-sweep" / "knob" / "side-by-side.png"
    if side.exists():
        # Every third pixel: the sheet stays a few hundred KB in the repository.
        plt.imsave(plot_folder / "knob-side-by-side.png", plt.imread(side)[::3, ::3])
        out.append("![knob, every configuration of the sweep in order, shaded](results/knob-side-by-side.png)\n")

    # Other scenes.
    for scene in sorted({r["scene"] for r in scenes["results"]}):
        rows = [r for r in scenes["results"] if r["scene"] == scene]
        plot(rows, scene, plot_folder / f"{scene}-pareto.png")
        out.append(f"## {scene}\n")
        out.append(f"![{scene}: time versus error](results/{scene}-pareto.png)\n")
        out.append(table(rows) + "\n")


# Real models.
def frame_ms(r):
    return r["frameMs"]["median"]


def plot_frames(rows, scene, path):
    """Whole-frame time versus MAE, ours and the osgShadow peer's rows in one plot."""
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=110)
    peers = itertools.cycle("XP*Dd+x1")  # a marker per peer run (vdsm .. pssm4, vdsm-csm2), reused past eight
    for n, r in enumerate(sorted(rows, key=lambda r: r["label"])):
        peer = bool(r["peer"])
        ax.scatter([frame_ms(r)], [r["mae"]], s=45 if peer else 20, marker=next(peers) if peer else "os^vD<>P*h"[n % 10],
                   color="black" if peer else plt.cm.tab20(n % 20), label=r["label"])
    ax.set_xlabel(f"whole frame, ms (median; {real_meta['timingMethod']})")
    ax.set_ylabel("mean absolute visibility error vs ray-traced truth")
    ax.set_yscale("symlog", linthresh=1e-3)
    ax.set_title(f"{scene}: ours and osgShadow (black), {real_meta['width']}x{real_meta['height']}, 2048² maps",
                 fontsize=8)
    ax.legend(fontsize=5, ncol=3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def accuracy_summary(real):
    """Which models `gsm` measures worse than osg-vdsm on, by metric."""
    worse = []
    for scene in [c["scene"] for c in real["scenes"]]:
        rows = [r for r in real["results"] if r["scene"] == scene]
        vdsm = next((r for r in rows if r["label"] == "osg-vdsm"), None)
        gsm = next((r for r in rows if r["label"].startswith("gsm-")), None)
        if vdsm and gsm:
            metrics = [m for m, key in (("acne", "acneRate"), ("leak", "leakRate"), ("darkening", "darkening"))
                       if gsm[key] > vdsm[key]]
            if metrics:
                worse.append(f"{scene} ({', '.join(metrics)})")
    return ("Accuracy: `gsm` has no more acne, leak or darkening than ViewDependentShadowMap on every model"
            + (f" except {'; '.join(worse)}." if worse else "."))


def timed_frames(run):
    """How a run's frame medians were timed, in words: its frames, and its rounds where it alternated them."""
    rounds = run.get("rounds", 1)
    if rounds > 1:
        return (f"{rounds} rounds of {run['frames']} frames, each scene's configurations timed in turn in every "
                "round")
    return f"{run['frames']} frames"


def vdsm_ratio(row, vdsm):
    """A row's frame over VDSM's: the median of the rounds' ratios where it ran in rounds beside the peer
    (merge_rounds), else over the peer's one run."""
    return row.get("vdsmRatio", frame_ms(row) / frame_ms(vdsm))


def real_models(real, scaling):
    costs = {c["scene"]: c for c in real["scenes"]}
    out.append("## Real models\n")
    out.append(f"The real-model corpus (`tools/corpus.sh`, models and licences in `third_party_notes/assimp-testmodels.md`) at "
               f"{real['width']}x{real['height']} with 2048² maps, every technique at its defaults (PCF families 4x4 "
               "taps) and every osgShadow technique of OpenSceneGraph "
               "3.6 (`tools/osgpeer`, same scene, camera and light, white diffuse, no ambient) against the same "
               f"ray-traced truth. Frame times are whole frames, {real['timingMethod']}, both programs on "
               f"{real['renderer']}. The machine's speed drifts by up to 2× within a minute, so each model runs "
               f"{real['peerRounds']} rounds of ours ({timed_frames(real)} each, our techniques timed in turn), "
               "osgShadow's ViewDependentShadowMap (`osg-vdsm`) timed before the first and after each: a round's "
               "ratio is ours over the mean of the peer's runs either side of it, and the tables give the medians "
               "over the rounds, of our times, the peer's and the ratios (the unshadowed frames' likewise, from the "
               "same runs). The peer's other techniques are single runs beside them. Acne, leak and darkening are "
               "the rates defined above.\n")
    summary = ["| model | triangles | our draws | mesh memory | unshadowed: ours / osg | ratio | gsm / osg-vdsm frame | ratio "
               "| gsm acne, leak, darkening | osg-vdsm acne, leak, darkening |",
               "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for scene in [c["scene"] for c in real["scenes"]]:
        rows = [r for r in real["results"] if r["scene"] == scene]
        vdsm = next((r for r in rows if r["label"] == "osg-vdsm"), None)
        gsm = next((r for r in rows if r["label"].startswith("gsm-")), None)
        cost = costs[scene]
        peer_unshadowed = cost["peerUnshadowedFrameMs"]["median"] if cost["peerUnshadowedFrameMs"] else None
        ours_unshadowed = cost["unshadowedFrameMs"]["median"]
        unshadowed_ratio = cost.get("unshadowedPeerRatio", ours_unshadowed / peer_unshadowed if peer_unshadowed else 0)
        def metrics(r):
            return f"{100 * r['acneRate']:.3f} %, {100 * r['leakRate']:.3f} %, {r['darkening']:.4f}" if r else "–"
        summary.append(
            f"| {scene} | {cost['triangles']} | {cost['drawCalls']} | {cost['meshBytes'] / 2**20:.1f} MiB | "
            f"{ours_unshadowed:.1f} / {peer_unshadowed:.1f} ms | {unshadowed_ratio:.2f}x | "
            f"{frame_ms(gsm):.1f} / {frame_ms(vdsm):.1f} ms | {vdsm_ratio(gsm, vdsm):.2f}x | "
            f"{metrics(gsm)} | {metrics(vdsm)} |" if vdsm and gsm and peer_unshadowed else f"| {scene} | {cost['triangles']} | – |")
        plot_frames(rows, scene, plot_folder / f"real-{scene}.png")
        lines = [f"### {scene}\n", f"![{scene}: frame time versus error, ours and osgShadow](results/real-{scene}.png)\n",
                 f"{cost['triangles']} triangles, {cost['drawCalls']} draw calls ({cost['culledChunks']} chunks culled), "
                 f"{cost['meshBytes'] / 2**20:.1f} MiB of mesh buffers; unshadowed frame {ours_unshadowed:.1f} ms"
                 + (f" (osg {peer_unshadowed:.1f} ms)" if peer_unshadowed else "") + ".\n",
                 "| technique | acne | leak | darkening | MAE | edges true→rendered px | edges rendered→true px | m ≤ 1 / m p99 | frame ms "
                 "| / osg-vdsm | shadow memory |",
                 "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
        for r in sorted(rows, key=frame_ms):
            ratio = f"{vdsm_ratio(r, vdsm):.2f}x" if vdsm else "–"
            memory = f"{r['shadowBytes'] / 2**20:.0f} MiB" if not r["peer"] else "–"
            lines.append(f"| {r['label']}{' (' + r['peer'] + ')' if r['peer'] else ''} | {100 * r['acneRate']:.3f} % | "
                         f"{100 * r['leakRate']:.3f} % | {r['darkening']:.4f} | {r['mae']:.4f} | {edges(r)} | {frame_ms(r):.1f} | "
                         f"{ratio} | {memory} |")
        model_sections.append("\n".join(lines) + "\n")
    out.append("### Goals: every model\n")
    out.append("Goals of the real-content work: unshadowed frame ≤ 1.0x osgShadow's, `gsm` ≤ 0.6x "
               "ViewDependentShadowMap's frame with better acne, leak and darkening.\n")
    out.append("\n".join(summary) + "\n")
    # The per-pixel lighting's own cost shows on the small models, where little else is drawn.
    gaps = [c["unshadowedFrameMs"]["median"] - c["peerUnshadowedFrameMs"]["median"] for c in real["scenes"]
            if c.get("peerUnshadowedFrameMs") and c["triangles"] < 20000]
    gap = f" (here {min(gaps):.1f} to {max(gaps):.1f} ms over the models under 20k triangles)" if gaps else ""
    # Part of it is the sRGB encode, which the peer's linear target does without (step 6's alternated runs).
    encode = ", ".join(f"{model} {saved:.1f} of {frame:.1f} ms" for model, (saved, frame) in
                       ((folder.name, encode_ms(folder)) for folder in sorted((work / "encode").iterdir())))
    encode_cost = (" Our target stores sRGB, which the renderer encodes per pixel, and the peer's the linear colour: "
                   f"the encode costs {encode} of our unshadowed frame (`gs-render --linear-output` stores the colour "
                   "as computed; medians over 5 rounds, each round's two runs back to back)." if encode else "")
    out.append("Where the goals are missed, and why. (1) Unshadowed: our lighting pass shades every "
               "pixel with Blinn-Phong; osgShadow's fixed-function lighting is evaluated per vertex, so its fragments "
               "only interpolate a colour. On llvmpipe a 640x480 frame of per-pixel lighting costs a few "
               f"milliseconds whatever the triangle count{gap}, which is the whole gap on models of a few thousand "
               f"triangles.{encode_cost} The peer runs on the glibc thresholds our renderer sets (tools/osgpeer/README.md); "
               "before it did, its first pass, the unshadowed one, paid fresh mappings every frame and read slower "
               "than ours on the large models. (2) Large models: both renderers then spend most of the frame in "
               "llvmpipe's triangle setup, binning and shaders (a profile of our frame shows little time in our own "
               "code). (3) `gsm` versus "
               "ViewDependentShadowMap: both render one 2048² depth pass over the casters; our lighting pass then "
               "adds a filtered lookup per pixel and the receiver's gradient from its screen derivatives, VDSM one "
               "comparison. (4) Timing noise: two identical runs differ by the spread of the `repeat` column of the "
               "renderer options table below; ratios within it are not differences. " + accuracy_summary(real) + "\n")
    out.append("### Frame time from 10k to 1M triangles\n")
    out.append("Generated hills (`gs-corpus tessellation`), the same view and sun at every size.\n")
    scale = ["| triangles | ours unshadowed | osg unshadowed | ours gsm | osg-vdsm | gsm / osg-vdsm |",
             "| --- | --- | --- | --- | --- | --- |"]
    for cost in scaling["scenes"]:
        rows = [r for r in scaling["results"] if r["scene"] == cost["scene"]]
        gsm = next(r for r in rows if r["label"].startswith("gsm-"))
        vdsm = next((r for r in rows if r["label"] == "osg-vdsm"), None)
        peer = cost["peerUnshadowedFrameMs"]
        scale.append(f"| {cost['triangles']} | {cost['unshadowedFrameMs']['median']:.1f} ms | "
                     f"{peer['median']:.1f} ms | {frame_ms(gsm):.1f} ms | {frame_ms(vdsm):.1f} ms | "
                     f"{frame_ms(gsm) / frame_ms(vdsm):.2f}x |" if vdsm and peer else f"| {cost['triangles']} | – |")
    out.append("\n".join(scale) + "\n")
    engine_options()
    out.extend(model_sections)


def encode_ms(folder):
    """What the sRGB encode costs a model's unshadowed frame (step 6's runs in `folder`, the defaults and
    --linear-output alternated over rounds): the median over the rounds of the difference, and of the frame, ms."""
    def frame(run):
        return json.loads((run / "report.json").read_text())["frameMillisecondsMedian"]
    plain = {run.name.split("-")[1]: frame(run) for run in folder.glob("plain-*")}
    saved = [plain[round_] - frame(folder / f"linear-output-{round_}") for round_ in plain]
    return statistics.median(saved), statistics.median(plain.values())


def engine_options():
    folder = work / "engine"
    out.append("### Renderer options\n")
    out.append("`gs-render` whole frames (median of 15, 640x480) per model and technique with the defaults (chunks of "
               "4096 triangles, culling, tuned allocator, no pre-pass; every frame drawing its shadow maps, "
               "`--redraw-maps`) and the ratio of each alternative to it, all "
               "in one run: `prepass` lays down depth first and shades with an EQUAL test; `default allocator` "
               "keeps glibc's mmap/trim thresholds; `unchunked` draws each mesh whole (culling then has nothing to "
               "cull within a mesh); `every face` draws the faces that closed meshes hide from the camera and the "
               "light too (`--draw-hidden-faces --caster-faces both`; docs/MODULES.md, \"Closed parts\"), as before "
               "they were left out; `repeat` is the defaults run again, so it shows how far two identical runs differ "
               "(ratios closer to 1 than that are noise). Page faults per frame are the robust measure of the "
               "allocator setting.\n")
    rows = ["| model | technique | defaults | prepass | default allocator | unchunked | every face | repeat | page faults per frame: defaults / default allocator |",
            "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for model in sorted(p.name for p in folder.iterdir()):
        for technique in ("none", "gsm", "pcf-gsm-average"):
            def report(variant):
                return json.loads((folder / model / f"{technique}-{variant}" / "report.json").read_text())
            base = report("plain")["frameMillisecondsMedian"]
            rows.append(f"| {model} | {technique} | {base:.1f} ms | " +
                        " | ".join(f"{report(v)['frameMillisecondsMedian'] / base:.2f}x"
                                   for v in ("prepass", "default-allocator", "unchunked", "every-face", "plain-again")) +
                        f" | {report('plain')['pageFaultsPerFrame']:.0f} / {report('default-allocator')['pageFaultsPerFrame']:.0f} |")
    out.append("\n".join(rows) + "\n")


def density_cells(mine):
    """Texel density over rows: mean fraction of lit receivers at m <= 1, the worst row's, and the worst p99."""
    known = [r["density"] for r in mine if r.get("density")]
    if not known:
        return "– | – | –"
    fractions = [d["atMostOnePixel"] for d in known]
    return (f"{100 * sum(fractions) / len(fractions):.1f} % | {100 * min(fractions):.1f} % | "
            f"{max(d['p99'] for d in known):.1f}")


def defaults_section(views, real):
    rows = [r for r in views["results"] if not r["peer"]]
    techniques = list(dict.fromkeys(r["settings"]["technique"] for r in rows))
    scenes = list(dict.fromkeys(r["scene"].split("-az")[0] for r in rows))
    corpus_ms = {}
    for r in real["results"]:
        if not r["peer"]:
            corpus_ms.setdefault(r["settings"]["technique"], []).append(frame_ms(r))
    with open(plot_folder / "defaults.csv", "w") as csv:
        csv.write("scene,technique,acne_rate,leak_rate,darkening,mae,lit,shadowed,edge_true_to_rendered_mean,"
                  "edge_true_to_rendered_p95,edge_rendered_to_true_mean,edge_rendered_to_true_p95,true_edge_pixels,"
                  "density_m_at_most_1,density_m_p50,density_m_p99,meets_floor\n")
        for r in rows:
            e = r["edges"]
            d = r.get("density") or {"atMostOnePixel": -1, "median": -1, "p99": -1}
            csv.write(f"{r['scene']},{r['settings']['technique']},{r['acneRate']:.6f},{r['leakRate']:.6f},"
                      f"{r['darkening']:.6f},{r['mae']:.6f},{r['pixels']['lit']},{r['pixels']['shadowed']},"
                      f"{e['trueToRendered']['mean']:.3f},{e['trueToRendered']['p95']:.3f},"
                      f"{e['renderedToTrue']['mean']:.3f},{e['renderedToTrue']['p95']:.3f},"
                      f"{e['trueToRendered']['pixels']},{d['atMostOnePixel']:.4f},{d['median']:.3f},{d['p99']:.3f},"
                      f"{meets_floor(r)}\n")
    out.append("## Defaults\n")
    s = rows[0]["settings"]
    out.append(f"Every technique at its defaults ({s['resolution']}² {s['depthFormat'].upper()} maps, PCF "
               f"{s['pcfTaps']}x{s['pcfTaps']} over {s['pcfRadius']:g} texels, moments blurred over "
               f"{s['momentBlurRadius']} texels, the automatic bias of "
               f"docs/SHADOWS.md) on every content scene and real model, under the scene's own light and a sweep of "
               f"azimuths x elevations down to 1° above the horizon ({len(set(r['scene'] for r in rows))} views, "
               f"{views['width']}x{views['height']}, accuracy only), against the ray-traced truth. Floor: acne < "
               f"{100 * FLOOR['acneRate']:.2f} %, leak < {100 * FLOOR['leakRate']:.2f} %, darkening < "
               f"{100 * FLOOR['darkening']:.1f} %, outside the band ({band_description(views)}); a rate counts only "
               f"over at least {MIN_PIXELS} pixels (grazing views see few receivers); and edge placement, both ways "
               f"mean ≤ {EDGE_FLOOR['mean']} px and 95th percentile ≤ {EDGE_FLOOR['p95']:g} px on views with at least "
               f"{MIN_EDGE_PIXELS} true edge pixels. Edge placement: from each true shadow-edge pixel to the nearest "
               "rendered edge (missing or displaced edges: peter-panning, shrunken or swollen shadows, staircases) and "
               "back (edges that should not be there: speckle lines), in pixels; the table gives the mean over views "
               "of the per-view mean and the worst per-view 95th percentile. Texel density: Lloyd et al.'s m, the "
               "largest extent of one shadow texel in screen pixels, at every truly lit receiver; the table gives "
               "the mean and the worst view's fraction at m ≤ 1 and the worst view's 99th percentile. Every row is in "
               "`docs/results/defaults.csv`.\n")
    table = ["| technique | views meeting the floor | worst acne | worst leak | worst darkening | true→rendered edge: "
             "mean / worst p95 | rendered→true edge: mean / worst p95 | m ≤ 1: mean | m ≤ 1: worst | worst m p99 | "
             "corpus frame ms (median) | memory per 2048² map |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for technique in techniques:
        mine = [r for r in rows if r["settings"]["technique"] == technique]
        naive = mine[0]["naive"]

        def worst(key):
            values = [scored(r)[key] for r in mine if key in scored(r)]
            return max(values) if values else 0.0

        def edge(direction, stat):
            values = [r["edges"][direction][stat] for r in mine
                      if r["edges"]["trueToRendered"]["pixels"] >= MIN_EDGE_PIXELS and r["edges"][direction]["pixels"] > 0]
            return (sum(values) / len(values) if stat == "mean" else max(values)) if values else 0.0

        met = sum(meets_floor(r) for r in mine)
        ms = sorted(corpus_ms.get(technique, [0.0]))[len(corpus_ms.get(technique, [0.0])) // 2]
        mib = max((map_mib(r) for r in mine if r["shadowMaps"] > 0), default=0.0)
        table.append(f"| `{technique}`{' (naive)' if naive else ''} | {met} / {len(mine)} | {100 * worst('acneRate'):.3f} % | "
                     f"{100 * worst('leakRate'):.3f} % | {100 * worst('darkening'):.3f} % | "
                     f"{edge('trueToRendered', 'mean'):.2f} / {edge('trueToRendered', 'p95'):.1f} | "
                     f"{edge('renderedToTrue', 'mean'):.2f} / {edge('renderedToTrue', 'p95'):.1f} | "
                     f"{density_cells(mine)} | {ms:.1f} | {mib:.0f} MiB |")
    out.append("\n".join(table) + "\n")
    matrix = ["| technique | " + " | ".join(scenes) + " |", "| --- |" + " --- |" * len(scenes)]
    for technique in techniques:
        cells = []
        for scene in scenes:
            mine = [r for r in rows if r["settings"]["technique"] == technique and r["scene"].split("-az")[0] == scene]
            cells.append(f"{sum(meets_floor(r) for r in mine)}/{len(mine)}")
        matrix.append(f"| `{technique}` | " + " | ".join(cells) + " |")
    out.append("Views meeting the floor, per scene (its own light and the sweep's):\n")
    out.append("\n".join(matrix) + "\n")
    technique, line = recommend(rows, real["results"])
    configured = views.get("defaultTechnique")
    misses_section(rows, configured or technique)
    if configured == technique:
        line += "`ShadowSettings::technique` defaults to it."
    elif configured:
        line += f"`ShadowSettings::technique` is `{configured}`: the rule and the default differ."
    out.append(line + f" (The rule: tools/shadowbench/default_rule.py, memory budget {MEMORY_BUDGET_MIB:g} MiB.)\n")


def misses_section(rows, default):
    """Every view where the default technique misses the floor: what it misses by, and its texel density."""
    misses = [r for r in rows if r["settings"]["technique"] == default and not meets_floor(r)]
    out.append(f"### Where the default `{default}` misses the floor\n")
    if not misses:
        out.append("Nowhere: it meets the floor in every Defaults view.\n")
        return
    edge_only = [r for r in misses if all(v < FLOOR[k] for k, v in scored(r).items())]
    others = {r["scene"]: sum(not meets_floor(o) for o in rows if o["scene"] == r["scene"] and not o["naive"])
              for r in misses}
    non_naive = len({o["settings"]["technique"] for o in rows if not o["naive"]})
    out.append(f"{len(misses)} views, {len(edge_only)} of them on edge placement alone (acne, leak and darkening "
               f"within the floor); the rows give the acne / leak / darkening rates, both edge distances (mean, 95th "
               f"percentile), the fraction of lit receivers at m ≤ 1, the maps drawn and how many of the "
               f"{non_naive} non-naive techniques miss there too.\n")
    lines = ["| view | acne / leak / darkening | edges true→rendered px | edges rendered→true px | m ≤ 1 | maps | "
             "techniques missing | what misses |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in misses:
        e = r["edges"]
        density = r.get("density") or {}
        lines.append(f"| {r['scene']} | {100 * r['acneRate']:.3f} / {100 * r['leakRate']:.3f} / "
                     f"{100 * r['darkening']:.3f} % | {e['trueToRendered']['mean']:.2f} / "
                     f"{e['trueToRendered']['p95']:.1f} | {e['renderedToTrue']['mean']:.2f} / "
                     f"{e['renderedToTrue']['p95']:.1f} | "
                     + (f"{100 * density['atMostOnePixel']:.0f} %" if density else "–")
                     + f" | {r['shadowMaps']} | {others[r['scene']]} | {miss_kind(r)} |")
    out.append("\n".join(lines) + "\n")
    out.append("A true edge the image lacks (true→rendered beyond the floor) is a shadow the truth has and the image "
               "does not. On the terrain these are mostly isolated shadowed pixels of the truth over lit slopes, and "
               "clusters of two or three: the shadows of the terrain's own relief, a crest one to three pixels away "
               "shading the facets behind it, narrower than a texel of any map here, so every technique misses them "
               "alike. An edge the truth lacks (rendered→true) is a rendered edge off the true one, or a speckle "
               "line.\n")


def miss_kind(r):
    """Which part of the floor a row misses, in words."""
    parts = [{"acneRate": "acne", "leakRate": "leak", "darkening": "darkening"}[k]
             for k, v in scored(r).items() if v >= FLOOR[k]]
    if edges_scored(r):
        def over(direction):
            return any(r["edges"][direction][k] > EDGE_FLOOR[k] for k in EDGE_FLOOR)
        if over("trueToRendered"):
            parts.append("true edges the image lacks")
        if over("renderedToTrue"):
            parts.append("edges the truth lacks")
    return ", ".join(parts)


CONTENT_SCENES = {"knob", "torus", "bowl", "thin-shell", "crease-cube", "grazing-plane", "spheres"}
PCF_GSM_GOAL_ACNE = 5e-5  # 0.005 %


def pcf_over_gsm_section(views):
    """Each PCF-over-GSM correction's darkening against single-tap gsm's on the same view of the real corpus."""
    rows = [r for r in views["results"] if not r["peer"] and r["scene"].split("-az")[0] not in CONTENT_SCENES]
    gsm = {r["scene"]: r for r in rows if r["settings"]["technique"] == "gsm"}
    techniques = [t for t in dict.fromkeys(r["settings"]["technique"] for r in rows) if t.startswith("pcf-gsm-")]
    out.append("## PCF over GSM against single-tap GSM\n")
    out.append("The same runs as Defaults, real corpus only: on each view, each PCF-over-GSM correction's darkening of "
               "lit surfaces against single-tap `gsm`'s (the goal: at most twice it, at acne below "
               f"{100 * PCF_GSM_GOAL_ACNE:.3f} %). A view counts when both have at least {MIN_PIXELS} lit pixels; "
               "\"within 2x\" allows two pixels' worth of darkening where `gsm`'s is nearly zero (2 / lit pixels).\n")
    table = ["| technique | views | within 2x of gsm's darkening | and acne below the goal | median ratio | "
             "mean darkening (gsm's) | worst acne |", "| --- | --- | --- | --- | --- | --- | --- |"]
    for technique in techniques:
        pairs = [(r, gsm[r["scene"]]) for r in rows
                 if r["settings"]["technique"] == technique and r["scene"] in gsm
                 and "darkening" in scored(r) and "darkening" in scored(gsm[r["scene"]])]
        if not pairs:
            continue
        within = [max(2 * g["darkening"], 2 / r["pixels"]["lit"]) >= r["darkening"] for r, g in pairs]
        clean = [w and r["acneRate"] < PCF_GSM_GOAL_ACNE for w, (r, _) in zip(within, pairs)]
        ratios = sorted(r["darkening"] / max(g["darkening"], 1.0 / g["pixels"]["lit"]) for r, g in pairs)
        mean = sum(r["darkening"] for r, _ in pairs) / len(pairs)
        mean_gsm = sum(g["darkening"] for _, g in pairs) / len(pairs)
        naive = " (naive)" if pairs[0][0]["naive"] else ""
        table.append(f"| `{technique}`{naive} | {len(pairs)} | {sum(within)} | {sum(clean)} | "
                     f"{ratios[len(ratios) // 2]:.1f} | {100 * mean:.4f} % ({100 * mean_gsm:.4f} %) | "
                     f"{100 * max(r['acneRate'] for r, _ in pairs):.4f} % |")
    out.append("\n".join(table) + "\n")


def every_light_section(cascades, every):
    # Every configuration of the cascade run starts from the module's defaults (results.sh: --techniques default).
    ours = {r["settings"]["technique"] for r in cascades["results"] if not r["peer"]}
    if len(ours) != 1:
        raise SystemExit(f"the cascade run mixes techniques {sorted(ours)}; it should run the default only")
    default_technique = ours.pop()
    out.append("## Every light: cascades and point lights\n")
    out.append(f"The 4 km outdoor scene (content/scenes/outdoor.gltf: camera 1.8 m above the ground looking at the "
               f"horizon, near 0.3 m, far 5 km; sun 30° high), {cascades['width']}x{cascades['height']}, 2048² maps, "
               f"the default technique (`{default_technique}`) with 1-4 cascades and several split weights, against the "
               "ray-traced truth (rays towards the sun). `automatic` is the default (`cascadeCount` 0). Shimmer: the "
               "fraction of receiver pixels whose visibility changes by more than 0.5 between frames while the view "
               f"the maps are fitted to moves a third of a texel per frame for {cascades['shimmerFrames']} frames and the observer stays "
               "still (`gs-shadowbench --shimmer`); snapped cascades keep every map identical. osgShadow's "
               "ParallelSplitShadowMap (`pssmN`: N splits) and ViewDependentShadowMap (one map, and `csm2`: its "
               "two cascades, the most it draws) ran on the same scene, camera and light in the same run, at their "
               "own defaults.\n")
    lines = ["| configuration | maps | split weight | acne | leak | darkening | edges true→rendered px | "
             "edges rendered→true px | m ≤ 1 / m p99 | shimmer | shadow ms | frame ms | memory |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    rows = [r for r in cascades["results"] if r["scene"] == "outdoor"]
    for r in sorted(rows, key=lambda r: (bool(r["peer"]), r["label"])):
        st = r["settings"]
        if r["peer"]:
            label, maps, weight, shimmer, shadow, memory = f"osg `{r['label']}`", "—", "—", "—", "—", "—"
        else:
            label = "automatic (default)" if st["cascadeCount"] == 0 else r["label"]
            maps = str(r["shadowMaps"])
            weight = f"{st['cascadeSplitWeight']:.2f}" if r["shadowMaps"] > 1 else "—"
            shimmer = f"{100 * r['shimmer']:.3f} %" if r["shimmer"] >= 0 else "—"
            shadow = f"{r['shadowPassMs']['median']:.1f}"
            memory = f"{r['shadowBytes'] / 2**20:.0f} MiB"
        lines.append(f"| {label} | {maps} | {weight} | {100 * r['acneRate']:.3f} % | {100 * r['leakRate']:.3f} % | "
                     f"{100 * r['darkening']:.3f} % | {edges(r)} | {shimmer} | {shadow} | {frame_ms(r):.1f} | "
                     f"{memory} |")
    out.append("\n".join(lines) + "\n")
    ours = [r for r in rows if not r["peer"] and r["settings"]["texelSnapping"] and r["shadowMaps"] == 4]
    if ours:
        best = min(ours, key=lambda r: r["edges"]["trueToRendered"]["mean"] + r["edges"]["renderedToTrue"]["mean"])
        out.append(f"With four cascades the edges lie closest to the truth at split weight "
                   f"{best['settings']['cascadeSplitWeight']:.2f} (mean {best['edges']['trueToRendered']['mean']:.2f} "
                   f"+ {best['edges']['renderedToTrue']['mean']:.2f} px).\n")
    out.append(f"Every technique at its defaults on the outdoor scene (automatic cascades) and in the room lit by two "
               f"point lights (content/scenes/room.gltf; cube faces drawn only where they see visible receivers; rays "
               f"towards the light's position), {every['width']}x{every['height']}, against the truth. Seams between "
               "cube faces: `./build-ci/bin/ShadowsGLTest --gtest_filter='*PointLight*' | grep measured` prints every "
               "technique's errors over all receivers and over those within 8 texels of a face edge.\n")
    scenes = ["outdoor", "room"]
    lines = ["| technique | " + " | ".join(f"{s}: acne / leak / darkening | {s}: edges px | {s}: frame ms | {s}: maps"
                                         for s in scenes) + " |",
             "| --- |" + " --- | --- | --- | --- |" * len(scenes)]
    techniques = list(dict.fromkeys(r["settings"]["technique"] for r in every["results"]))
    for technique in techniques:
        cells = []
        for scene in scenes:
            r = next(r for r in every["results"] if r["scene"] == scene and r["settings"]["technique"] == technique)
            e = r["edges"]
            cells.append(f"{100 * r['acneRate']:.3f} / {100 * r['leakRate']:.3f} / {100 * r['darkening']:.3f} % | "
                         f"{e['trueToRendered']['mean']:.2f} / {e['renderedToTrue']['mean']:.2f} | "
                         f"{frame_ms(r):.1f} | {r['shadowMaps']} ({r['shadowBytes'] / 2**20:.0f} MiB)")
        naive = " (naive)" if r["naive"] else ""
        lines.append(f"| `{technique}`{naive} | " + " | ".join(cells) + " |")
    out.append("\n".join(lines) + "\n")


def fit_section(fit):
    """The maps fitted to the visible samples (the default) against mesh bounds, per scene."""
    out.append("## Fitted to what the screen sees\n")
    out.append(f"Directional maps fitted to the visible depth samples (`directionalFit` `samples`, the default: rows "
               f"named after the technique) and to mesh bounds (`-bounds` rows), at their defaults otherwise, "
               f"{fit['width']}x{fit['height']}, {fit['results'][0]['settings']['resolution']}² maps, the automatic "
               "cascade count of each fit; every scene under its own light (the apron's sun is 8° up). Band, floor and "
               "texel density as in \"Defaults\"; times are whole frames, the shadow pass (the sample pass and its "
               "reduction included for the samples fit) and the lighting pass, "
               f"{fit['timingMethod']}.\n")
    for scene in dict.fromkeys(r["scene"] for r in fit["results"]):
        rows = [r for r in fit["results"] if r["scene"] == scene]
        lines = [f"**{scene}**\n",
                 "| configuration | maps | acne | leak | edges true→rendered px | edges rendered→true px | m ≤ 1 / m p99 | "
                 "meets the floor | shadow ms | lighting ms | frame ms | memory |",
                 "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
        for r in rows:
            lines.append(f"| {r['label']} | {r['shadowMaps']} | {100 * r['acneRate']:.3f} % | {100 * r['leakRate']:.3f} % | "
                         f"{edges(r)} | {'yes' if meets_floor(r) else 'no'} | {r['shadowPassMs']['median']:.1f} | "
                         f"{r['lightingPassMs']['median']:.1f} | {frame_ms(r):.1f} | {r['shadowBytes'] / 2**20:.0f} MiB |")
        out.append("\n".join(lines) + "\n")
    density_gap(fit)


def density_gap(fit):
    """Per scene, why the default fit's lit receivers are not all at m <= 1: what its maps would need."""
    resolution = fit["results"][0]["settings"]["resolution"]
    lines = [f"Where fewer than 95 % of the lit receivers get a texel per pixel (m ≤ 1) with the default fit: m falls "
             f"as the map's side grows, so a side of {resolution} x (m p99) per map would bring 99 % of them there; "
             "the texels that takes, against the maps drawn now.\n",
             "| scene | maps | m ≤ 1 | m p99 | side for 99 % | texels per map: now / needed |", "| --- | --- | --- | --- | --- | --- |"]
    short = 0
    for scene in dict.fromkeys(r["scene"] for r in fit["results"]):
        r = next((r for r in fit["results"] if r["scene"] == scene and not r["label"].endswith("-bounds")), None)
        d = (r or {}).get("density")
        if not d or d["atMostOnePixel"] >= 0.95:
            continue
        short += 1
        side = resolution * max(d["p99"], 1.0)
        lines.append(f"| {scene} | {r['shadowMaps']} | {100 * d['atMostOnePixel']:.0f} % | {d['p99']:.1f} | "
                     f"{side:,.0f} | {resolution ** 2 / 1e6:.1f} M / {side ** 2 / 1e6:.0f} M |")
    if short:
        out.append(lines[0])
        out.append("\n".join(lines[1:]) + "\n")
        out.append("These views look across hundreds of metres or kilometres from a few metres up: the receivers near the camera "
                   "need texels of centimetres, and the fit, a few axis-aligned rectangles of whole maps, spends the "
                   "same density on everything inside each. Texels only where pixels ask for them are the virtual "
                   "maps' work (a fixed budget of pages, each at the level its pixels need).\n")


def path_shimmer_section(path):
    """Shimmer along a camera path: the default technique snapped, unsnapped and fitted to bounds."""
    out.append("## Shimmer along a camera path\n")
    out.append(f"The camera moves 4 % of the distance to what it looks at and turns 3° over {path['pathFrames']} frames, "
               "the maps fitted to each frame's view; the fraction of receiver pixels (each compared with its "
               "reprojection in the previous frame, on the same surface) whose visibility changes by more than 0.5 where "
               "the ray-traced truth does not (docs/SHADOWS.md, \"How a view is scored\"). A map whose edges lie a texel "
               "off the truth's scores above 0 even when it does not move: compare rows of one scene.\n")
    lines = ["| scene | " + " | ".join(dict.fromkeys(r["label"] for r in path["results"])) + " |"]
    labels = list(dict.fromkeys(r["label"] for r in path["results"]))
    lines.append("| --- |" + " --- |" * len(labels))
    for scene in dict.fromkeys(r["scene"] for r in path["results"]):
        cells = []
        for label in labels:
            r = next((r for r in path["results"] if r["scene"] == scene and r["label"] == label), None)
            cells.append(f"{100 * r['pathShimmer']:.3f} %" if r and r["pathShimmer"] >= 0 else "–")
        lines.append(f"| {scene} | " + " | ".join(cells) + " |")
    out.append("\n".join(lines) + "\n")
    out.append("Where the default's shimmer is above the goal of 0.01 %, the unsnapped and bounds columns show how much "
               "is the fit's motion: the rest is the shadow edges' placement, within a texel of the truth's, met by "
               "pixel centres that slide over the surface as the camera moves; a texel spans m pixels, so it falls with "
               "the texel density (\"Fitted to what the screen sees\").\n")


def seams(r):
    """Error rates (visibility off the truth by more than 0.5) of scored pixels whose kernel straddles a page
    border, against the page interiors'."""
    m = r.get("seams")
    if not m:
        return "–"
    return f"{m['pixels']}: {100 * m['errorRate']:.2f} % / {100 * m['interiorErrorRate']:.2f} %"


def virtual_table(timed):
    """The rows of a virtual-maps run (fitted and virtual configurations, a peer where present) and the goals' tally."""
    lines = ["| scene | configuration | m ≤ 1 / p99 / p99.9 | edges p95 px | meets the floor | cold pages (× lit px) | "
             "walk (× lit px per frame) | coarsened | memory | shadow ms | lighting ms | frame ms | frame / VDSM | "
             "walking frame ms (/ VDSM) |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    summary = {"density": 0, "cold": 0, "walk": 0, "memory": 0, "frame": 0, "views": 0, "peers": 0,
               "walkingFitted": [0, 0], "walkingVirtual": [0, 0]}  # [at most VDSM's, rows with a peer]
    for scene in dict.fromkeys(r["scene"] for r in timed["results"]):
        rows = [r for r in timed["results"] if r["scene"] == scene]
        peer = next((r for r in rows if r["label"] == "osg-vdsm"), None)
        for r in rows:
            if r["label"].startswith("osg-") and r is not peer:
                continue
            d = r.get("density")
            density = f"{100 * d['atMostOnePixel']:.1f} % / {d['p99']:.2f} / {d.get('p999', 0):.2f}" if d else "–"
            pages = r.get("pages")
            lit = max(d["pixels"], 1) if d else 1
            cold = f"{pages['coldRendered']} ({pages['coldTexels'] / lit:.1f}×)" if pages else "–"
            walk = f"{pages['walkTexelsPerFrame'] / lit:.2f}×" if pages and pages["walkTexelsPerFrame"] >= 0 else "–"
            # Rounds alternated with the peer's runs give the median of their ratios (merge_rounds).
            frame_ratio = (r.get("vdsmRatio", frame_ms(r) / frame_ms(peer)) if peer and r is not peer else None)
            ratio = f"{frame_ratio:.2f}×" if frame_ratio is not None else "–"
            walking = r.get("walkFrameMs")
            walking_cell = "–"
            if walking and r is not peer:
                walking_ratio = r.get("walkingVdsmRatio", walking["median"] / frame_ms(peer)) if peer else None
                walking_cell = f"{walking['median']:.1f}" + (f" ({walking_ratio:.2f}×)" if peer else "")
                if not pages and r.get("walkKeptFrames") is not None:
                    walking_cell += f", {r['walkKeptFrames']} kept"
                if peer:
                    tally = summary["walkingVirtual" if pages else "walkingFitted"]
                    tally[0] += walking_ratio <= 1.0
                    tally[1] += 1
            e = r["edges"]
            lines.append(f"| {scene} | {r['label']} | {density} | {e['trueToRendered']['p95']:.1f} / "
                         f"{e['renderedToTrue']['p95']:.1f} | {'yes' if meets_floor(r) else 'no'} | {cold} | {walk} | "
                         f"{pages['coarsened'] if pages else '–'} | {r['shadowBytes'] / 2**20:.0f} MiB | "
                         f"{r['shadowPassMs']['median']:.1f} | {r['lightingPassMs']['median']:.1f} | {frame_ms(r):.1f} | "
                         f"{ratio} | {walking_cell} |")
            if pages:
                summary["views"] += 1
                summary["density"] += bool(d and d["atMostOnePixel"] >= 0.99 and d.get("p999", 9) <= 1.5)
                summary["cold"] += pages["coldTexels"] / lit <= 3.0
                summary["walk"] += 0 <= pages["walkTexelsPerFrame"] / lit <= 0.3
                summary["memory"] += r["shadowBytes"] <= 64 * 2**20 + 2**21
                if peer:
                    summary["peers"] += 1
                    summary["frame"] += frame_ratio <= 0.6
    return lines, summary


def virtual_section(timed, suns):
    """Virtual maps against the default fitted maps: density, pages, memory, edges and frame time beside VDSM."""
    out.append("## Virtual maps\n")
    out.append(f"The default technique with whole fitted maps (`{timed['defaultTechnique']}-2048-d24`) and with virtual "
               "maps (`virtual`: `mapAllocation` `virtual`, 64 MiB of 128² pages, docs/SHADOWS.md \"Virtual maps\"), "
               f"{timed['width']}x{timed['height']}, every scene under its own light; osgShadow's ViewDependentShadowMap "
               "(`osg-vdsm`) where the peer has the scene. m as in \"Defaults\", measured in the clipmap level each "
               "pixel actually read. Pages: drawn in the cold first frame (the same view again draws none), and per "
               "frame while the camera walks 1.5 units/s at 30 frames/s for "
               f"{timed.get('walkFrames', 30)} frames, in texels (borders included) as multiples of the lit receiver "
               "pixels. Times are the static view's frames (no page drawn) and, walking, the median of the walk's frames "
               "after its first (fitted maps draw theirs whole where a step leaves their placements and keep them where "
               "it does not, the frames that kept them counted; virtual maps draw the pages each step newly asks "
               f"for), {timed['timingMethod']}. Where the peer has the scene, our configurations run "
               f"{timed['peerRounds']} rounds, the peer's VDSM timed before the first and after each "
               "(the machine's speed drifts by up to 2× within a minute): times are the medians over the rounds, a ratio "
               "the median of each round's over the mean of the peer's runs either side of it, and VDSM's frame the "
               "median of those means.\n")
    lines, summary = virtual_table(timed)
    out.append("\n".join(lines) + "\n")
    out.append(f"Against the goals, of {summary['views']} views: {summary['density']} have ≥ 99 % of lit receivers at "
               f"m ≤ 1 with p99.9 ≤ 1.5; {summary['cold']} draw a cold frame of ≤ 3× the lit receiver pixels; "
               f"{summary['walk']} draw ≤ 0.3× per frame while walking; {summary['memory']} fit in 64 MiB (the page "
               f"tables and request bits of about 1.1 MiB beside the pool); {summary['frame']} of the "
               f"{summary['peers']} with a peer row run a frame ≤ 0.6× VDSM's. Walking, frames ≤ 1.0× VDSM's: "
               f"fitted {summary['walkingFitted'][0]} of {summary['walkingFitted'][1]}, virtual "
               f"{summary['walkingVirtual'][0]} of {summary['walkingVirtual'][1]}.\n")
    out.append("Why the texel counts stay above the goal: m is a texel's largest extent in pixels, and a square texel "
               "meets m ≤ 1 only at the pixel footprint's shortest axis. A surface seen at a grazing angle from the "
               "camera, or lit at one from the sun, stretches that footprint, so m ≤ 1 costs 1/sin of the angle in "
               "texels per pixel (about 11× at 5°, 19× at 3°): the density goal and the texel goal cannot both hold "
               "on such views with square texels. Pages add their own waste where few pixels fall in one.\n")
    # Low suns: the fitted default and the virtual map side by side.
    lines = ["| view | fitted: m ≤ 1 / p99.9 / edges p95 | virtual: m ≤ 1 / p99.9 / edges p95 | virtual cold pages (× lit px) | "
             "coarsened | seam pixels: errors / interior errors |",
             "| --- | --- | --- | --- | --- | --- |"]
    for scene in dict.fromkeys(r["scene"] for r in suns["results"]):
        rows = {("virtual" if r["label"] == "virtual" else "fitted"): r for r in suns["results"] if r["scene"] == scene}
        if len(rows) < 2:
            continue
        cells = []
        for kind in ("fitted", "virtual"):
            r = rows[kind]
            d = r.get("density") or {"atMostOnePixel": 0, "p999": 0}
            e = r["edges"]
            cells.append(f"{100 * d['atMostOnePixel']:.1f} % / {d.get('p999', 0):.2f} / {e['trueToRendered']['p95']:.1f}, "
                         f"{e['renderedToTrue']['p95']:.1f}")
        pages = rows["virtual"].get("pages") or {}
        lit = max((rows["virtual"].get("density") or {}).get("pixels", 1), 1)
        lines.append(f"| {scene} | {cells[0]} | {cells[1]} | {pages.get('coldRendered', 0)} "
                     f"({pages.get('coldTexels', 0) / lit:.1f}×) | {pages.get('coarsened', 0)} | {seams(rows['virtual'])} |")
    out.append(f"The generated apron under suns from 40° to 3°, {suns['width']}x{suns['height']}, accuracy only:\n")
    out.append("\n".join(lines) + "\n")


def virtual_lights_section(lights):
    """Spot and point lights through virtual maps: the room's faces and the spheres' spot, fitted and virtual."""
    out.append("### Spot and point lights\n")
    out.append("Spot lights and point lights' cube faces through virtual maps (one 16k² perspective map with mip levels "
               "each, docs/SHADOWS.md \"Virtual maps\"), against whole 2048² fitted maps, for the default technique "
               f"and msm (`virtual-msm`), {lights['width']}x{lights['height']}, columns as above. Since these runs "
               "the budget holds the page tables and request bits too: memory is everything the virtual maps "
               "hold.\n")
    lines, summary = virtual_table(lights)
    out.append("\n".join(lines) + "\n")
    fitted = {(r["scene"], r["settings"]["technique"]): r for r in lights["results"]
              if r["settings"]["mapAllocation"] == "fitted"}
    for r in lights["results"]:
        if r["settings"]["mapAllocation"] != "virtual":
            continue
        f = fitted.get((r["scene"], r["settings"]["technique"]))
        if f:
            pages = r["pages"]
            out.append(f"- {r['scene']} `{r['label']}`: {f['shadowBytes'] / 2**20:.0f} MiB fitted → "
                       f"{r['shadowBytes'] / 2**20:.1f} MiB virtual; {pages['coldRequested']} pages asked for, "
                       f"{pages['poolPages']} in the pool, {pages['coarsened']} requests coarsened.")
    out.append("\nWhere the pool holds fewer pages than the pixels ask for (the room: two lights, six faces each, and "
               "walls at grazing angles to both), whole levels give way to their parents and the density falls "
               "below the fitted maps'; a larger `virtualBudgetMiB` or `virtualTexelPixels` 2 trades it back.\n")


def virtual_texels_section(texels):
    """The texel size pages are drawn for against the texels they take and what the edges show."""
    labels = [label for label in dict.fromkeys(r["label"] for r in texels["results"])]
    out.append(f"The texel size on screen the pages are drawn for (`virtualTexelPixels`, m1 the default, m2, m4), against "
               f"the fitted default, {texels['width']}x{texels['height']}, each scene under its own light, accuracy only: "
               "m ≤ 1 / m p99, edges p95 (true→rendered, rendered→true), cold pages in texels as multiples of the lit "
               "receiver pixels, and per frame of the walk.\n")
    lines = ["| scene | " + " | ".join(labels) + " |", "| --- |" + " --- |" * len(labels)]
    for scene in dict.fromkeys(r["scene"] for r in texels["results"]):
        cells = []
        for label in labels:
            r = next((r for r in texels["results"] if r["scene"] == scene and r["label"] == label), None)
            if not r:
                cells.append("–")
                continue
            d = r.get("density") or {"atMostOnePixel": 0, "p99": 0, "pixels": 1}
            e = r["edges"]
            cell = (f"{100 * d['atMostOnePixel']:.0f} % / {d['p99']:.1f}; {e['trueToRendered']['p95']:.1f}, "
                    f"{e['renderedToTrue']['p95']:.1f}")
            pages = r.get("pages")
            if pages:
                lit = max(d["pixels"], 1)
                cell += f"; {pages['coldTexels'] / lit:.0f}×, walk {pages['walkTexelsPerFrame'] / lit:.2f}×"
            cells.append(cell)
        lines.append(f"| {scene} | " + " | ".join(cells) + " |")
    out.append("\n".join(lines) + "\n")


def soft_section(soft, coarse, seams):
    """Techniques against the ray-traced truth of each light's own size: penumbra errors and the truth's convergence."""
    out.append("## Soft shadows\n")
    truths = {c["scene"]: c.get("softTruth") for c in soft["scenes"]}
    out.append("Every light has a size (a sun's `angularDiameter`, a spot or point light's `radius`, in the glTF light's "
               "`extras`: docs/CONTENT.md), and the truth here is that light's: each receiver's visibility is the "
               "fraction of rays, uniform in solid angle over the cone the light fills seen from it, that reach it "
               "(docs/SHADOWS.md, \"How a view is scored\"). The scenes: `soft-contact`, a wall standing on the ground "
               "under a sun 4° wide (the shadow hardens where it touches the ground); `soft-overlap`, two plates at "
               "heights 0.5 and 1.9 under a sun 5° wide, whose penumbrae overlap; `soft-fence`, slats under the real "
               "sun (0.53°) 7° above the horizon; `room`, the first of its two point lights, bulbs 8 cm across; "
               f"`outdoor`, 4 km under the real sun with cascades. {soft['width']}x{soft['height']}, accuracy only. "
               "Penumbra: RMSE over the mask 0.02 < truth < 0.98 dilated by 2 px; false lit: umbra pixels (truth ≤ "
               "0.02, outside the mask) rendered above 0.5; false shadow: lit ones (truth ≥ 0.98) rendered below; "
               "width: the distance between the 0.1 and 0.9 iso-lines along the truth's gradient at its 0.5 "
               "iso-line, rendered against true where the true one is at least 4 px wide, median / 95th percentile "
               "of the difference in pixels (samples), and the median of rendered over true width (above 1: too "
               "wide). `pcss` is the soft technique (docs/SHADOWS.md); `msm-soft` its filterable variant, two "
               "fetches of mip-filtered moments whatever the width (docs/SHADOWS.md, \"Filterable soft shadows\"); "
               "`pcss-screen-plane` (naive) is PCSS as engines ship it, each tap compared at the plane from "
               "screen derivatives rather than the receiver's tangent plane: on the flat receivers of these scenes "
               "the two planes agree, and so do their figures; they part at silhouettes and grazing receivers "
               "(the room's acne and false shadow). The others cast one penumbra width everywhere. The goal for a soft shadow: width error median ≤ 1 px and p95 "
               "≤ 3 px where the true penumbra is at least 4 px wide. A map fitted tightly to `soft-contact`'s "
               "wall has texels of about a millimetre at 2048², and its widest penumbrae (a 4° sun, 3.5 m behind "
               "the wall's top) span over 200 of them: `pcss` reaches as far as a directional map's fit holds for "
               "its light's penumbrae (docs/SHADOWS.md, \"Percentage-closer soft shadows\"), `msm-soft` a radius "
               "of 64 texels (its kernel 96), so its rows there are cut; the rows marked 256² show both at a map "
               "size where 64 texels hold them. Seam jump: where a penumbra crosses "
               "from one map to the next (cascades; the room's cube faces), pairs of width samples within 3 px on "
               "either side, and how much the rendered width changes between them beyond the truth's change; "
               "the goal is 1 px. The `-4-cascades` rows split the wall's and the fence's views in 4 cascades so "
               "that the seams cross their penumbrae.\n")
    lines = ["| scene | truth: rays, RMS from 4× the rays | configuration | penumbra RMSE / MAE | false lit / umbra px "
             "| false shadow / lit px | width error median / p95 px (samples) | width × | seam jump median / max "
             "px (pairs) |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    # The seam runs' cascaded rows (their plain pcss row repeats the main run's).
    cascaded = [r for r in seams["results"] if "cascades" in r["label"]]
    for r in soft["results"] + coarse["results"] + cascaded:
        q = r.get("soft")
        if not q:
            continue
        t = truths.get(r["scene"]) or {}
        truth = (f"{t['samplesPerAxis']}², {t['convergenceRmse']:.4f}" if t else "–")
        lines.append(f"| {r['scene']} | {truth} | {r['label']} | {q['penumbraRmse']:.3f} / {q['penumbraMae']:.3f} | "
                     f"{q['falseLit']} / {q['umbraPixels']} | {q['falseShadow']} / {q['litPixels']} | "
                     f"{q['widthErrorMedian']:.1f} / {q['widthErrorP95']:.1f} ({q['widthSamples']}) | "
                     f"{q['widthRatioMedian']:.2f} | " +
                     (f"{q['seamJumpMedian']:.2f} / {q['seamJumpMax']:.2f} ({q['seamPairs']}) |" if q.get("seamPairs")
                      else "– |"))
    out.append("\n".join(lines) + "\n")


# Labels of the sizing runs' configurations (tools/results.sh step 13); the default's rows are named otherwise.
SIZING_CONFIGURATIONS = ("full-", "texel-", "virtual", "d16")


# The rates a sizing configuration is compared on, view by view, against the default.
RATES = ("acneRate", "leakRate", "darkening")


def map_side(r):
    """The map a row drew, as the sizing tables name it: its side, or pages for virtual maps (no whole map)."""
    return f"{r['mapResolution']}²" if r["mapResolution"] > 0 else "pages"


def sizing_section(sizing, floor_views=None):
    """The default technique's directional map sized to the view at several targets, and at the full
    resolution, per scene; with `floor_views` (the same targets over the Defaults views), which views each
    keeps within the floor."""
    rows = [r for r in sizing["results"] if not r["peer"]]
    default = next(r for r in rows if not r["label"].startswith(SIZING_CONFIGURATIONS))
    resolution = default["settings"]["resolution"]
    out.append("## Maps sized to the view\n")
    out.append(f"The default `{default['settings']['technique']}`, {sizing['width']}x{sizing['height']}, its "
               "directional map sized to what the view resolves (`fittedTexelPixels`: a texel of at most that many "
               "pixels at each cascade's nearest sample, the smallest power of two up to `resolution`; "
               "docs/SHADOWS.md, \"Every light\"): the default "
               f"{default['settings']['fittedTexelPixels']:g} (rows named after the technique), half a pixel and a "
               f"pixel (`texel-` rows), against the full {resolution}² (`full-`, `fittedTexelPixels` 0). Times are "
               f"medians of the shadow pass (the sample pass included) and of the whole frame, {sizing['timingMethod']}, "
               f"all in one run, over {timed_frames(sizing)}; edges and m ≤ 1 as in \"Defaults\" (texel density from "
               "the map drawn). The default keeps the full map at this size wherever the Defaults sweep's low suns need it (docs/SHADOWS.md); "
               "the coarser targets show what fill and memory the view would let go, and the table after it what "
               "they lose in the Defaults views. Two alternatives to the default's map, with its settings otherwise: "
               "`virtual`, virtual maps (`mapAllocation` virtual: pages only where pixels ask, "
               "\"Virtual maps\"), and `d16`, the map in 16-bit depth (`depthFormat` d16: half the memory and the "
               "bytes each lookup reads).\n")
    lines = ["| scene | configuration | map side | cascades | shadow pass ms | frame ms | edges true→rendered "
             "mean / p95 px | edges rendered→true mean / p95 px | m ≤ 1 | acne / leak | memory |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        t, b = r["edges"]["trueToRendered"], r["edges"]["renderedToTrue"]
        density = (r.get("density") or {}).get("atMostOnePixel", -1)
        lines.append(f"| {r['scene']} | {r['label']} | {map_side(r)} | {r['shadowMaps']} | "
                     f"{r['shadowPassMs']['median']:.1f} | {frame_ms(r):.1f} | {t['mean']:.2f} / {t['p95']:.1f} | "
                     f"{b['mean']:.2f} / {b['p95']:.1f} | {100 * density:.0f} % | "
                     f"{100 * r['acneRate']:.3f} / {100 * r['leakRate']:.3f} % | {r['shadowBytes'] / 2**20:.0f} MiB |")
    out.append("\n".join(lines) + "\n")
    if floor_views:
        sizing_floor(floor_views)


SIZING_LOST_LISTED = 6  # views lost per target named in the table; the CSV holds them all


def sizing_floor(views):
    """Per sizing target over the Defaults views: the views meeting the floor, the map sides taken, and each view
    the default meets and the target does not."""
    rows = [r for r in views["results"] if not r["peer"]]
    by_label = {}
    for r in rows:
        by_label.setdefault(r["label"], {})[r["scene"]] = r
    default_label = next(label for label in by_label if not label.startswith(SIZING_CONFIGURATIONS))
    default = by_label[default_label]
    with open(plot_folder / "sizing-floor.csv", "w") as csv:
        csv.write("scene,configuration,map_side,acne_rate,leak_rate,darkening,edge_true_to_rendered_mean,"
                  "edge_true_to_rendered_p95,edge_rendered_to_true_mean,edge_rendered_to_true_p95,meets_floor\n")
        for r in rows:
            t, b = r["edges"]["trueToRendered"], r["edges"]["renderedToTrue"]
            csv.write(f"{r['scene']},{r['label']},{r['mapResolution']},{r['acneRate']:.6f},{r['leakRate']:.6f},"
                      f"{r['darkening']:.6f},{t['mean']:.3f},{t['p95']:.3f},{b['mean']:.3f},{b['p95']:.3f},"
                      f"{int(meets_floor(r))}\n")
    out.append(f"The same configurations over the {len(default)} Defaults views ({views['width']}x{views['height']}, "
               "accuracy only, the floor of \"Defaults\"): how many views each meets the floor in, the map sides it "
               "took (views in brackets), the views where its acne, leak or darkening is higher than the default's "
               "and where lower, the views the default misses and it meets, and the views the default meets the "
               f"floor in and it does not (the first {SIZING_LOST_LISTED}; every row is in "
               "`docs/results/sizing-floor.csv`).\n")
    lines = ["| configuration | views meeting the floor | map sides | rates higher / lower | views gained | "
             "views lost against the default |",
             "| --- | --- | --- | --- | --- | --- |"]
    for label, mine in by_label.items():
        sides = {}
        for r in mine.values():
            sides[r["mapResolution"]] = sides.get(r["mapResolution"], 0) + 1  # 0: pages
        lost = [scene for scene, r in mine.items() if meets_floor(default[scene]) and not meets_floor(r)]
        lost_text = "; ".join(
            f"{scene} ({map_side(mine[scene])}, default {map_side(default[scene])}: "
            f"{miss_kind(mine[scene])}, edges {mine[scene]['edges']['trueToRendered']['mean']:.2f} / "
            f"{mine[scene]['edges']['trueToRendered']['p95']:.1f} and "
            f"{mine[scene]['edges']['renderedToTrue']['mean']:.2f} / {mine[scene]['edges']['renderedToTrue']['p95']:.1f} "
            "px)" for scene in lost[:SIZING_LOST_LISTED]) if label != default_label else "–"
        if len(lost) > SIZING_LOST_LISTED:
            lost_text += f"; and {len(lost) - SIZING_LOST_LISTED} more"
        gained = [scene for scene, r in mine.items() if not meets_floor(default[scene]) and meets_floor(r)]
        higher = sum(any(r[k] > default[scene][k] for k in RATES) for scene, r in mine.items())
        lower = sum(any(r[k] < default[scene][k] for k in RATES) for scene, r in mine.items())
        lines.append(f"| {label} | {sum(meets_floor(r) for r in mine.values())} / {len(mine)} | "
                     + ", ".join(f"{f'{side}²' if side else 'pages'} ({n})"
                                 for side, n in sorted(sides.items(), reverse=True))
                     + (f" | {higher} / {lower} | {', '.join(gained) or 'none'}" if label != default_label
                        else " | – | –")
                     + f" | {lost_text or 'none'} |")
    out.append("\n".join(lines) + "\n")
    out.append("Edges are given as true→rendered and rendered→true, mean / 95th percentile.\n")


def load_views(prefix):
    """The Defaults views' three runs (defaults_views in tools/results.sh: -own, -swept, -large) as one."""
    own, swept, large = load(f"{prefix}-own"), load(f"{prefix}-swept"), load(f"{prefix}-large")
    return {**own, "results": own["results"] + swept["results"] + large["results"]}


def corpus_views():
    """The Defaults views of the content scenes and real models: -own and -swept (the apron's, -large, are not of
    the real corpus)."""
    own, swept = load("defaults-own"), load("defaults-swept")
    return {**own, "results": own["results"] + swept["results"]}


def drawn_texels(r):
    """The fraction of its maps' texels a result's casters were drawn into (ShadowStats::casterTexels)."""
    texels = r["mapResolution"] ** 2 * r["shadowMaps"]
    return f"{100.0 * r['casterTexels'] / texels:.0f} %" if texels and "casterTexels" in r else "–"


def load_rounds(name):
    """A step of tools/results.sh run scene by scene in rounds, in the order the scenes ran: per scene its rounds
    (<name>/<scene>/<round>/results.json) and the peer's VDSM runs timed before the first round and after each
    (osg-<name>/<scene>/<n>.json), none for a scene the peer lacks."""
    folders = sorted((path.parent.parent for path in (work / name).glob("*/1/results.json")),
                     key=lambda folder: (folder / "1" / "results.json").stat().st_mtime)
    if not folders:
        sys.exit(f"results.py: {work / name} holds no scene's rounds (run tools/results.sh)")
    scenes = []
    for folder in folders:
        rounds = []
        while (path := folder / str(len(rounds) + 1) / "results.json").exists():
            rounds.append(json.loads(path.read_text()))
        peers = [work / f"osg-{name}" / folder.name / f"{n}.json" for n in range(len(rounds) + 1)]
        missing = [str(path) for path in peers if not path.exists()]
        if 0 < len(missing) < len(peers):
            sys.exit(f"results.py: {', '.join(missing)} missing (run tools/results.sh)")
        scenes.append({"scene": folder.name, "rounds": rounds,
                       "peers": [json.loads(path.read_text()) for path in peers if path.exists()]})
    return scenes


def merge_rounds(name):
    """A step run scene by scene in rounds (load_rounds) as one run (every scene's first round), where a scene has
    the peer's runs beside its rounds: our rows' times the medians over the rounds, with the medians of their ratios
    to VDSM's frame ("vdsmRatio", "walkingVdsmRatio"), the peer's VDSM row's frame the median of its runs either side
    of each round, and each scene's unshadowed frames, ours and the peer's, likewise ("unshadowedPeerRatio")."""
    scenes = load_rounds(name)
    merged = {**scenes[0]["rounds"][0], "results": [], "scenes": [],
              "peerRounds": max((len(entry["rounds"]) for entry in scenes if entry["peers"]), default=0)}
    for entry in scenes:
        first = entry["rounds"][0]
        costs = [dict(c) for c in first["scenes"]]
        rows = [dict(r) for r in first["results"]]
        if entry["peers"]:
            rounds = len(entry["rounds"])
            vdsm = bracketed(entry["peers"], "shadowedMs", rounds)
            unshadowed = bracketed(entry["peers"], "unshadowedMs", rounds)
            for cost in costs:
                ours = [next(c for c in run["scenes"] if c["scene"] == cost["scene"])["unshadowedFrameMs"]["median"]
                        for run in entry["rounds"]]
                cost["unshadowedFrameMs"] = {**cost["unshadowedFrameMs"], "median": statistics.median(ours)}
                cost["peerUnshadowedFrameMs"] = {**(cost.get("peerUnshadowedFrameMs") or {}),
                                                 "median": statistics.median(unshadowed)}
                cost["unshadowedPeerRatio"] = median_ratio(ours, unshadowed)
        for row in rows:
            if not entry["peers"] or (row["peer"] and row["label"] != "osg-vdsm"):
                continue
            if row["peer"]:
                row["frameMs"] = {**row["frameMs"], "median": statistics.median(vdsm)}
                continue
            same = [next(r for r in run["results"] if r["label"] == row["label"]) for run in entry["rounds"]]
            row["vdsmRatio"] = median_ratio([frame_ms(r) for r in same], vdsm)
            if all(r.get("walkFrameMs") for r in same):
                row["walkingVdsmRatio"] = median_ratio([r["walkFrameMs"]["median"] for r in same], vdsm)
            for key in ("frameMs", "shadowPassMs", "lightingPassMs", "walkFrameMs"):
                if row.get(key):
                    row[key] = {**row[key], "median": statistics.median(r[key]["median"] for r in same)}
        merged["scenes"] += costs
        merged["results"] += rows
    return merged


def load_still():
    """Step 14's rounds as one run (the first round's fields) with "stillScenes" (load_rounds)."""
    scenes = load_rounds("still")
    return {**scenes[0]["rounds"][0], "stillScenes": scenes}


def still_section(still):
    """The default technique's frame with every frame drawing its maps and on a still view that keeps them, beside
    osgShadow's ViewDependentShadowMap timed in turn with it, per scene, and the frame goal's tally."""
    def ours_of(run):
        return next(r for r in run["results"] if not r["peer"])

    first = ours_of(still)
    technique = first["settings"]["technique"]
    rounds = len(still["stillScenes"][0]["rounds"])
    out.append("## A still view keeps its maps\n")
    out.append(f"The default `{technique}` on every real model and the generated apron (one mesh), "
               f"{still['width']}x{still['height']}, {first['settings']['resolution']}² maps, each scene under its "
               "own light, against osgShadow's ViewDependentShadowMap (`osg-vdsm`, the same scene, camera and light; "
               "its edges are from its run in \"Real models\"). The machine's speed drifts by up to 2× within a "
               f"minute, so each scene runs {rounds} rounds of ours, the peer's run before the first and after each: "
               "a round's ratio is ours over the mean of the peer's runs either side of it, and the table gives the "
               "medians over the rounds (the peer's frame with the range of its runs). *Moving*: every frame draws "
               "its maps (`reuseUnchangedMaps` off), as each frame of a "
               "moving view does: the sample pass, the casters and the lighting pass. *Still*: the same view's "
               "frames after one that drew them, which keep them (`reuseUnchangedMaps`, the default; docs/SHADOWS.md, "
               "\"Kept while nothing changes\"); VDSM draws its map every frame either way, so *moving* is the like-for-"
               "like comparison and *still* what a view that stands still costs. *Walking*: the camera walks forward "
               f"1.5 units/s at 30 frames/s for {still.get('walkFrames', 0)} frames with the default settings, which keep "
               "the maps while their placements hold the view's samples (docs/SHADOWS.md, \"Kept while the view moves "
               "within them\"): the median frame after the first, and how many of those frames kept the maps. Texels "
               "drawn: the part of the maps' texels "
               "the casters were drawn into, within the reach of the visible samples' lookups (docs/SHADOWS.md, "
               f"\"Casters drawn only where the samples read\"). The shadow pass's parts, timed apart in the same "
               "frames (a wait between them, so they add up to a little more): the fit (the sample pass, whose depth "
               "the lighting pass then reuses, and the reduction of its samples) and the maps (their clear and the "
               f"casters). Medians of {still['frames']} frames, "
               f"{still['timingMethod']}, both programs on {still['renderer']}. Edges: p95 true→rendered / "
               "rendered→true, px, as in \"Defaults\".\n")
    lines = ["| scene | triangles | unshadowed: ours / osg ms | shadow pass ms (moving): fit + maps | texels drawn "
             "| moving frame ms | still frame ms | walking frame ms (kept) | osg-vdsm frame ms (its runs) "
             "| moving / VDSM | still / VDSM | walking / VDSM | memory | edges p95: ours / VDSM |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    tally = {"peers": 0, "moving": 0, "still": 0, "still06": 0, "walking": 0, "walkingPeers": 0, "pass": 0, "maps": 0,
             "unshadowed": 0}
    peer_allocators = set()
    median = statistics.median
    for entry in still["stillScenes"]:
        scene = entry["scene"]
        if not entry["peers"]:
            raise SystemExit(f"results.py: {scene} has no VDSM runs beside its rounds (osg-still)")
        runs = [ours_of(run) for run in entry["rounds"]]
        costs = [next(c for c in run["scenes"] if c["scene"] == scene) for run in entry["rounds"]]
        r, cost = runs[0], costs[0]
        if not all(run["stillFrameKeptMaps"] for run in runs):
            raise SystemExit(f"results.py: {scene}'s still frames drew their maps (stillFrameKeptMaps false)")
        # Each round against the mean of the peer's runs either side of it.
        vdsm = bracketed(entry["peers"], "shadowedMs", len(runs))
        vdsm_unshadowed = bracketed(entry["peers"], "unshadowedMs", len(runs))
        peer_allocators.update(run.get("allocatorTuned") for run in entry["peers"])
        peer_edges = next((p["edges"] for p in entry["rounds"][0]["results"] if p["label"] == "osg-vdsm"), None)
        moving = [frame_ms(run) for run in runs]
        kept = [run["stillFrameMs"]["median"] for run in runs]
        walking = [run["walkFrameMs"]["median"] for run in runs if run.get("walkFrameMs")]
        moving_ratio, kept_ratio = median_ratio(moving, vdsm), median_ratio(kept, vdsm)
        walking_ratio = median_ratio(walking, vdsm) if len(walking) == len(runs) else None
        unshadowed = [c["unshadowedFrameMs"]["median"] for c in costs]
        tally["peers"] += 1
        tally["moving"] += moving_ratio <= 1.0
        tally["still"] += kept_ratio <= 1.0
        tally["still06"] += kept_ratio <= 0.6
        tally["unshadowed"] += median_ratio(unshadowed, vdsm_unshadowed) <= 1.0
        if walking_ratio is not None:
            tally["walkingPeers"] += 1
            tally["walking"] += walking_ratio <= 1.0
        overheads = [v - u for v, u in zip(vdsm, unshadowed)]
        tally["pass"] += median(run["shadowPassMs"]["median"] - o for run, o in zip(runs, overheads)) > 0.0
        tally["maps"] += median(run["shadowMapsMs"]["median"] - o for run, o in zip(runs, overheads)) > 0.0
        peers = [run["shadowedMs"]["median"] for run in entry["peers"]]
        walking_cell = (f"{median(walking):.1f} ({r['walkKeptFrames']} of {still['walkFrames']})"
                        if walking_ratio is not None else "–")
        mine = r["edges"]
        lines.append(
            f"| {scene} | {cost['triangles']} | {median(unshadowed):.1f} / {median(vdsm_unshadowed):.1f} "
            f"| {median(run['shadowPassMs']['median'] for run in runs):.1f}: "
            f"{median(run['shadowFitMs']['median'] for run in runs):.1f} + "
            f"{median(run['shadowMapsMs']['median'] for run in runs):.1f} | {drawn_texels(r)} | {median(moving):.1f} "
            f"| {median(kept):.1f} | {walking_cell} | {median(vdsm):.1f} ({min(peers):.1f}–{max(peers):.1f}) "
            f"| {moving_ratio:.2f}× | {kept_ratio:.2f}× | "
            + (f"{walking_ratio:.2f}×" if walking_ratio is not None else "–")
            + f" | {r['shadowBytes'] / 2**20:.0f} MiB | {mine['trueToRendered']['p95']:.1f} / "
            f"{mine['renderedToTrue']['p95']:.1f}; "
            + (f"{peer_edges['trueToRendered']['p95']:.1f} / {peer_edges['renderedToTrue']['p95']:.1f} |"
               if peer_edges else "– |"))
    out.append("\n".join(lines) + "\n")
    out.append(f"Against the goal (the default's frame ≤ 1.0× VDSM's), scenes meeting it (median ratio over the "
               f"rounds): moving {tally['moving']} of {tally['peers']}, still {tally['still']} of {tally['peers']} "
               f"({tally['still06']} at ≤ 0.6×, the goal with virtual maps), walking {tally['walking']} of "
               f"{tally['walkingPeers']}. Why moving frames miss: on "
               f"{tally['pass']} of {tally['peers']} our shadow pass alone (the sample pass, then the casters "
               "into a map fitted to the visible samples, which the model then fills) costs more than VDSM's frame over "
               f"our unshadowed one, and on {tally['maps']} the maps alone do. VDSM fits its map to the view frustum "
               "and the scene's bounds, so the model covers fewer of its texels, and its edges are the coarser ones of "
               "the last column.\n")
    allocator = ("its glibc thresholds raised as ours are (gs-osgshadow --allocator tuned; tools/osgpeer/README.md)"
                 if peer_allocators == {True} else "not every run of it on the glibc thresholds ours run on")
    out.append(f"Unshadowed, against the peer's own unshadowed pass in the same runs, {allocator}: ours ≤ 1.0× on "
               f"{tally['unshadowed']} of {tally['peers']} scenes.\n")


def splice(heading, sections, renderer, option):
    """RESULTS_MD with its `heading` section, up to the next "## " heading, replaced by `sections` (inserted before
    "## Cost model", or at the end, where it has none yet)."""
    previous = results_md.read_text().rstrip("\n").split("\n")
    if heading in previous:
        begin = previous.index(heading)
        end = next((i for i in range(begin + 1, len(previous)) if previous[i].startswith("## ")), len(previous))
    else:
        begin = end = previous.index("## Cost model") if "## Cost model" in previous else len(previous)
    note = (f"Regenerated alone by `bash tools/results.sh --only {option}` ({renderer}); the other sections are "
            "from the last full run of `bash tools/results.sh`.\n")
    fresh = "\n".join([sections[0], note] + sections[1:]).split("\n")
    return "\n".join(previous[:begin] + fresh + previous[end:]) + "\n"


def build_real():
    real_meta = merge_rounds("real")
    real_models(real_meta, load("scaling"))
    return real_meta


def build_virtual():
    timed = merge_rounds("virtual")
    virtual_section(timed, load("virtual-suns"))
    virtual_texels_section(load("virtual-texels"))
    virtual_lights_section(load("virtual-lights"))
    return timed


def build_soft():
    soft = load("soft")
    soft_section(soft, load("soft-coarse"), load("soft-seams"))
    return soft


def build_sizing():
    sizing = load("sizing")
    sizing_section(sizing, load_views("sizing-floor"))
    return sizing


def build_still():
    still = load_still()
    still_section(still)
    return still


def build_filtered():
    filtered = load("filtered")
    filtered_section(filtered, load_views("moments16"), load("moments16-lights"))
    return filtered


def build_lights():
    cascades = load("outdoor-cascades")
    every_light_section(cascades, load("every-light"))
    return cascades


def build_cost():
    costs = load("cost-model")
    nir_path = work / "cost-model" / "nir-counts.json"
    out.extend(cost_model.section(costs, json.loads(nir_path.read_text()) if nir_path.exists() else None))
    return costs


# The builders of the sections --only regenerates one at a time, which the full run calls too: each appends its
# section to `out` and returns the run whose renderer a regenerated section's note names.
ONE_SECTION_BUILDS = {"real": build_real, "virtual": build_virtual, "soft": build_soft, "sizing": build_sizing,
                      "still": build_still, "filtered": build_filtered, "lights": build_lights, "cost": build_cost}

if partial in ONE_SECTION_BUILDS:
    model_sections = []
    run = ONE_SECTION_BUILDS[partial]()
    results_md.write_text(splice(PARTIAL_SECTIONS[partial], out, run["renderer"], partial))
    sys.exit(0)
if partial == "defaults":
    # Three sections, each spliced in place of its previous text.
    real_meta = merge_rounds("real")
    model_sections = []
    for heading, build in ((PARTIAL_SECTIONS["real"], lambda: real_models(real_meta, load("scaling"))),
                           (PARTIAL_SECTIONS["defaults"], lambda: defaults_section(load_views("defaults"), real_meta)),
                           ("## PCF over GSM against single-tap GSM", lambda: pcf_over_gsm_section(corpus_views()))):
        out.clear()
        build()
        results_md.write_text(splice(heading, out, real_meta["renderer"], partial))
    sys.exit(0)

reference_sections()
model_sections = []
real_meta = merge_rounds("real")
defaults_section(load_views("defaults"), real_meta)
pcf_over_gsm_section(corpus_views())
real_models(real_meta, load("scaling"))
build_lights()
fit_section(load("fit"))
path_shimmer_section(load("path-shimmer"))
if any((work / "virtual").glob("*/1/results.json")):
    virtual_section(merge_rounds("virtual"), load("virtual-suns"))
    virtual_texels_section(load("virtual-texels"))
    if (work / "virtual-lights" / "results.json").exists():
        virtual_lights_section(load("virtual-lights"))
if (work / "soft" / "results.json").exists():
    build_soft()
if (work / "sizing" / "results.json").exists():
    build_sizing()
if any((work / "still").glob("*/1/results.json")):
    build_still()
if (work / "cost-model" / "results.json").exists():
    build_cost()

results_md.write_text("\n".join(out) + "\n")
