#!/usr/bin/env python3
"""tools/demo_report.py: the accuracy table from a synthetic gs-shadowbench results.json, and the whole report on
a synthetic demo folder."""
import json
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools"))
import demo_report  # noqa: E402


def row(label, acne, leak, darkening, scene="knob", peer=None, edges=(1.0, 4.123)):
    return {"scene": scene, "label": label, "acneRate": acne, "leakRate": leak, "darkening": darkening,
            "mae": 0.0123, "frameMs": {"median": 12.34, "min": 1.0, "max": 20.0}, "peer": peer,
            "edges": {"trueToRendered": {"pixels": 10, "mean": 0.5, "p95": edges[0]},
                      "renderedToTrue": {"pixels": 12, "mean": 0.7, "p95": edges[1]}}}


RESULTS = {"width": 640, "height": 480, "groundTruth": "hard", "timingMethod": "glFinish + steady_clock",
           "results": [row("hard", 0.25, 0.001, 0.3, edges=(6.4, 49.0)),
                       row("pcf-gsm-average", 0.0004, 0.02, 0.0125),
                       row("osg-vdsm", 0.1, 0.1, 0.1, peer="osgShadow::ViewDependentShadowMap")]}


class AccuracyTableTest(unittest.TestCase):
    def test_one_row_per_technique_in_run_order_without_peers(self):
        table = demo_report.accuracy_table(RESULTS)
        rows = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line][1:]
        self.assertEqual(rows, ["| hard | 25.00 | 0.10 | 30.00 | 0.0123 | 6.4 / 49.0 | 12.3 |",
                                "| pcf-gsm-average | 0.040 | 2.00 | 1.25 | 0.0123 | 1.0 / 4.1 | 12.3 |"])
        self.assertIn("| technique | acne % | leak % | darkening % | MAE | edge p95 px | frame ms |", table)
        self.assertIn("Scene knob at 640x480, against hard ray-traced truth", table)

    def test_small_rates_keep_two_significant_digits(self):
        # As the sheets' labels: two pixels of acne among 140 000 receivers is neither none nor twenty.
        self.assertEqual([demo_report.percent(f) for f in (2 / 140000, 20 / 140000, 0.0, 0.00383, 1 / 307200, 1e-7)],
                         ["0.0014", "0.014", "0", "0.38", "0.0003", "<0.0001"])

    def test_several_scenes_name_the_scene(self):
        results = dict(RESULTS, results=[row("hard", 0, 0, 0), row("hard", 0, 0, 0, scene="torus")])
        self.assertIn("| torus hard |", demo_report.accuracy_table(results))

    def test_no_rows_of_ours_is_an_error(self):
        with self.assertRaises(ValueError):
            demo_report.accuracy_table(dict(RESULTS, results=[RESULTS["results"][2]]))


class ReportTest(unittest.TestCase):
    def test_accuracy_before_frames_with_the_sheets(self):
        with tempfile.TemporaryDirectory() as folder:
            root = pathlib.Path(folder)
            (root / "accuracy").mkdir()
            (root / "accuracy" / "results.json").write_text(json.dumps(RESULTS))
            (root / "knob" / "hard").mkdir(parents=True)
            (root / "knob" / "hard" / "report.json").write_text(json.dumps({
                "renderer": "llvmpipe", "glVersion": "4.5", "timingMethod": "glFinish", "frames": 5,
                "image": str(root / "knob" / "hard" / "knob.png"), "shadowTechnique": "hard", "width": 1024,
                "height": 768, "triangles": 1000, "frameMillisecondsMedian": 40.0, "programsCompiled": 3}))
            text = demo_report.report(root)
            self.assertLess(text.index("## Accuracy"), text.index("## Frames"))
            self.assertIn("![every technique, labelled](contact-sheet.png)", text)
            self.assertIn("| knob/hard/knob.png | hard | 1024x768 | 1000 | 40.0 | 3 |", text)

    def test_empty_folder_is_an_error(self):
        with tempfile.TemporaryDirectory() as folder:
            with self.assertRaises(ValueError):
                demo_report.report(folder)


if __name__ == "__main__":
    unittest.main()
