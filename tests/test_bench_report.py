"""scripts/bench_report.py on a small synthetic benchmark CSV (run with /usr/bin/python3)."""

import csv
import importlib.util
import os
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts",
                      "bench_report.py")
spec = importlib.util.spec_from_file_location("bench_report", SCRIPT)
bench_report = importlib.util.module_from_spec(spec)
spec.loader.exec_module(bench_report)

TORUS, BUNNY = 22931, 34834


def row(name, cloud, material, strategy, moving_s, err_mean, plain_s=0.04, paper=0, default=0,
        points=None, kind="sweep", rss=512.0, map_size=4096):
    """One CSV row; `name` is the test's handle for it (not a column)."""
    points = points or (TORUS if cloud == "torus" else BUNNY)
    return name, {
        "cloud": cloud, "points": points, "material": material, "strategy": strategy,
        "map_size": map_size, "opening_angle": 0.4 if strategy != "paper" else "",
        "cell_samples": 64 if strategy != "paper" else "", "is_paper": paper,
        "is_default": default, "bake_s": 0.5 * moving_s if isinstance(moving_s, float) else "",
        "light_s": 0.9 * moving_s if isinstance(moving_s, float) else "",
        "frame_static_s": 0.044, "frame_moving_s": moving_s, "plain_points_s": plain_s,
        "near_field_mib": 12.5 if strategy != "paper" else "",
        "virtual_points": 1200 if strategy == "paper" else "", "lit_cells": 25000,
        "err_mean": err_mean, "err_p99": "" if err_mean == "" else 3 * err_mean,
        "err_max": "" if err_mean == "" else 6 * err_mean,
        "err8_mean": "" if err_mean == "" else 0.4, "err8_max": "" if err_mean == "" else 9,
        "peak_rss_mb": rss, "kind": kind}


# Hand-checked fronts (time ratio = moving / plain, error mean):
# torus marble: paper 2.5x 45.6 %, coarse 7.5x 17.7 %, map-1024 20x 3 %, default 65x 0.35 %
# are each beaten by none; a slower row (67.5x, 1.2 %) is beaten by the default, the second
# coarse row (same time, 20 %) by the first, the row without an error is never on it.
# torus ketchup: alone, so on its own front although torus marble's default beats it.
# bunny marble: default and paper on the front; the row without a plain time is not.
# sphere marble: a NaN error is never on the front, an infinite one is beaten by any finite one.
ROWS = [
    row("torus_default", "torus", "marble", "near-far", 2.6, 0.0035, default=1),
    row("torus_slower", "torus", "marble", "near-far", 2.7, 0.012),
    row("torus_coarse", "torus", "marble", "near-far", 0.3, 0.177),
    row("torus_paper", "torus", "marble", "paper", 0.1, 0.456, paper=1, map_size=512),
    row("torus_map_1024", "torus", "marble", "near-far", 0.8, 0.03, map_size=1024),
    row("torus_no_error", "torus", "marble", "near-far", 1.0, ""),
    row("torus_coarse_worse", "torus", "marble", "near-far", 0.3, 0.2),
    row("torus_ketchup", "torus", "ketchup", "near-far", 4.2, 0.0039, default=1),
    row("bunny_default", "bunny", "marble", "near-far", 41.0, 0.004, plain_s=0.05, default=1),
    row("bunny_paper", "bunny", "marble", "paper", 0.2, 0.5, plain_s=0.05, paper=1),
    row("bunny_no_plain", "bunny", "marble", "near-far", 3.0, 0.01, plain_s=""),
    row("sphere_nan", "sphere", "marble", "near-far", 0.04, float("nan"), points=500),
    row("sphere_inf", "sphere", "marble", "near-far", 0.16, float("inf"), points=500),
    row("sphere_fine", "sphere", "marble", "near-far", 0.12, 0.01, points=500),
    row("scale_1k", "torus", "marble", "near-far", 0.1, 0.003, points=1000, kind="scale",
        default=1),
    row("scale_10k", "torus", "marble", "near-far", 1.1, 0.0033, points=10000, kind="scale",
        default=1, rss=""),
    row("scale_100k", "torus", "marble", "near-far", 12.0, 0.0036, points=100000, kind="scale",
        default=1, rss=900.0),
]
FRONT = {"torus_default", "torus_coarse", "torus_paper", "torus_map_1024", "torus_ketchup",
         "bunny_default", "bunny_paper", "sphere_fine"}


def write_csv(path, named_rows, columns=bench_report.COLUMNS):
    with open(path, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        for _, values in named_rows:
            writer.writerow(values)


def section_rows(md, heading):
    """The cells of the table under `heading`, header and separator left out."""
    lines = md.splitlines()
    start = lines.index(heading)
    table = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        table.append([cell.strip() for cell in line.strip("|").split("|")])
    return table[2:]


class BenchReport(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.csv = os.path.join(self.tmp.name, "results.csv")
        self.out = os.path.join(self.tmp.name, "report")

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, *args):
        return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)

    def test_pareto_front_on_a_hand_checked_case(self):
        write_csv(self.csv, ROWS)
        rows = bench_report.read_rows(self.csv)
        names = {r["line"]: name for r, (name, _) in zip(rows, ROWS)}
        sweep = [r for r in rows if r["kind"] == "sweep"]
        self.assertEqual({names[line] for line in bench_report.front_lines(sweep)}, FRONT)

    def test_writes_the_table_and_both_plots(self):
        write_csv(self.csv, ROWS)
        result = self.run_script(self.csv, "--out-dir", self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        for name in ("bench.md", "bench_tradeoff.png", "bench_scale.png"):
            path = os.path.join(self.out, name)
            self.assertTrue(os.path.isfile(path), name)
            if name.endswith(".png"):
                with open(path, "rb") as f:
                    self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", name)
                self.assertGreater(os.path.getsize(path), 20000, name)
        self.assertEqual([n for n in os.listdir(self.out) if n.endswith(".partial")], [])

        with open(os.path.join(self.out, "bench.md"), encoding="utf-8") as f:
            md = f.read()
        header = list(bench_report.SWEEP_HEADER)
        marks, strategy, moving_ms, ratio, mean = (header.index(c) for c in (
            "marks", "strategy", "moving frame (ms)", "moving / plain", "mean err (%)"))

        torus = section_rows(md, "### torus, marble (22,931 points)")
        # Sorted by the light-moving frame time; ties keep the CSV order.
        self.assertEqual([r[moving_ms] for r in torus],
                         ["100", "300", "300", "800", "1,000", "2,600", "2,700"])
        self.assertEqual([r[strategy] for r in torus],
                         ["paper"] + ["near-far"] * 6)
        self.assertEqual([r[marks] for r in torus],
                         ["front, paper", "front", "", "front", "", "front, default", ""])
        self.assertEqual(torus[0][ratio], "2.5x")
        self.assertEqual(torus[0][mean], "45.6")
        self.assertEqual(torus[4][mean], "-")  # not measured

        ketchup = section_rows(md, "### torus, ketchup (22,931 points)")
        self.assertEqual([r[marks] for r in ketchup], ["front, default"])

        bunny = section_rows(md, "### bunny, marble (34,834 points)")
        self.assertEqual([(r[strategy], r[marks]) for r in bunny],
                         [("paper", "front, paper"), ("near-far", ""),
                          ("near-far", "front, default")])
        self.assertEqual(bunny[1][ratio], "-")  # no plain points time

        scale = section_rows(md, "### torus, marble")
        self.assertEqual([r[0] for r in scale], ["1,000", "10,000", "100,000"])
        self.assertEqual(scale[1][-1], "-")

    def test_without_scale_rows_the_scale_plot_is_left_out(self):
        write_csv(self.csv, [r for r in ROWS if r[1]["kind"] == "sweep"])
        result = self.run_script(self.csv, "--out-dir", self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertTrue(os.path.isfile(os.path.join(self.out, "bench_tradeoff.png")))
        self.assertFalse(os.path.exists(os.path.join(self.out, "bench_scale.png")))
        self.assertIn("bench_scale.png", result.stderr)
        with open(os.path.join(self.out, "bench.md"), encoding="utf-8") as f:
            self.assertIn("No scale rows.", f.read())

    def test_view_rows_get_their_own_table(self):
        view = []
        for points, splatting, seconds in ((100000, "blended", 0.06), (100000, "discs", 0.03),
                                           (1000000, "blended", 0.5)):
            name, r = row(f"view_{points}_{splatting}", "dragon", "", splatting, "", "",
                          points=points, kind="view")
            r.update(frame_static_s=seconds, plain_points_s=0.05, bake_s="", light_s="",
                     near_field_mib="", lit_cells="")
            view.append((name, r))
        write_csv(self.csv, ROWS + view)
        result = self.run_script(self.csv, "--out-dir", self.out)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.out, "bench.md"), encoding="utf-8") as f:
            md = f.read()
        table = section_rows(md, "### dragon")
        self.assertEqual([(r[0], r[1], r[3]) for r in table],
                         [("100,000", "blended", "1.2x"), ("100,000", "discs", "0.6x"),
                          ("1,000,000", "blended", "10x")])

    def test_bad_input_is_named(self):
        write_csv(self.csv, ROWS, columns=[c for c in bench_report.COLUMNS if c != "err_p99"])
        result = self.run_script(self.csv, "--out-dir", self.out)
        self.assertEqual(result.returncode, 2)
        self.assertIn("missing columns: err_p99", result.stderr)

        bad = [row("x", "torus", "marble", "near-far", "fast", 0.01)]
        write_csv(self.csv, bad)
        result = self.run_script(self.csv, "--out-dir", self.out)
        self.assertEqual(result.returncode, 2)
        self.assertIn("line 2, column frame_moving_s: 'fast' is not a number", result.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.out, "bench.md")))


if __name__ == "__main__":
    unittest.main()
