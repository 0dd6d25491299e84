#!/usr/bin/python3
"""Speed-against-error report of a benchmark CSV: a Markdown table and two PNG plots.

Usage: bench_report.py results.csv --out-dir DIR

Writes DIR/bench.md (tables), DIR/bench_tradeoff.png (light-moving frame time against mean
error, the Pareto front marked) and DIR/bench_scale.png (times and memory against the point
count). A plot without rows to show is not written (the Markdown says so). Each file is
written whole or not at all.

The CSV has a header row with these columns, in any order, one row per measured setting; an
empty cell is a value that was not measured (it shows as "-" and the row stays out of what
needs it):

  cloud           name of the point cloud
  points          surfels in the cloud
  material        material preset name
  strategy        kernel strategy: near-far or paper
  map_size        largest light-map side, texels
  opening_angle   far-field walk opening angle (near-far)
  cell_samples    points of each cell asked for their light, per light (near-far)
  is_paper        1 for the paper's own setting, else 0
  is_default      1 for the renderer's default setting, else 0
  bake_s          what a geometry or material change costs before the light's steps (the
                  near-field table; the paper's grid), seconds
  light_s         steps 1-2 once (light map, lit cells, B): what a light move costs, seconds
  frame_static_s  one frame with the light static (camera move), seconds
  frame_moving_s  one frame with the light moving (steps 1-3), seconds
  plain_points_s  one frame of plain VTK points of the same cloud in the same run, seconds
  near_field_mib  GPU memory of the near-field table, MiB
  virtual_points  virtual grid points kept after pruning (paper)
  lit_cells       surfel cells the light reaches in the far field's pyramids (near-far; 0
                  without a far field), or lit map texels (paper)
  err_mean        per-point relative error against the CPU reference (core/reference/error_metric.h):
  err_p99           mean, 99th percentile and max, as fractions (0.01 = 1 %)
  err_max
  err8_mean       mean and max difference of 8-bit sRGB values (0-255)
  err8_max
  peak_rss_mb     peak resident memory of the process, MiB
  kind            sweep (a setting of the trade-off), scale (the default setting at
                  another point count) or view (the view alone, light static, radiance
                  given: strategy is the splatting, blended or discs)

"Time ratio" is a frame time over plain_points_s. A sweep row is on the Pareto front when no
other sweep row of the same cloud and material has both a time ratio (light moving) and a
mean error at most its own and one of them smaller.
"""

import argparse
import csv
import itertools
import math
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)
from matplotlib import ticker  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

TEXT_COLUMNS = ("cloud", "material", "strategy", "kind")
INT_COLUMNS = ("points", "map_size", "cell_samples", "virtual_points", "lit_cells")
FLAG_COLUMNS = ("is_paper", "is_default")
COLUMNS = ("cloud", "points", "material", "strategy", "map_size", "opening_angle",
           "cell_samples", "is_paper", "is_default", "bake_s", "light_s", "frame_static_s",
           "frame_moving_s", "plain_points_s", "near_field_mib", "virtual_points", "lit_cells",
           "err_mean", "err_p99", "err_max", "err8_mean", "err8_max", "peak_rss_mb", "kind")
KINDS = ("sweep", "scale", "view")

MISSING = "-"
STRATEGY_MARKERS = OrderedDict([("near-far", "o"), ("paper", "D")])
SPARE_MARKERS = ("v", "P", "X", "*", "h", "<", ">")


class CsvError(ValueError):
    """A CSV that cannot be read as a benchmark result; the message names the line."""


def _number(text, line, column, integer):
    try:
        value = float(text)
    except ValueError:
        raise CsvError(f"line {line}, column {column}: '{text}' is not a number") from None
    if integer:
        if not value.is_integer():
            raise CsvError(f"line {line}, column {column}: '{text}' is not a whole number")
        return int(value)
    return value


def read_rows(path):
    """The rows of a benchmark CSV as dicts of parsed values (None where a cell is empty)."""
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
        if missing:
            raise CsvError(f"{path}: missing columns: {', '.join(missing)}")
        rows = []
        for record in reader:
            line = reader.line_num
            row = {"line": line}
            for column in COLUMNS:
                text = (record.get(column) or "").strip()
                if column in TEXT_COLUMNS:
                    row[column] = text
                elif column in FLAG_COLUMNS:
                    row[column] = text not in ("", "0")
                elif text == "":
                    row[column] = None
                else:
                    row[column] = _number(text, line, column, column in INT_COLUMNS)
            if row["kind"] not in KINDS:
                raise CsvError(f"line {line}, column kind: '{row['kind']}' is not one of "
                               f"{', '.join(KINDS)}")
            rows.append(row)
    return rows


def _ratio(time_s, plain_s):
    if time_s is None or plain_s is None or plain_s <= 0:
        return None
    return time_s / plain_s


def moving_ratio(row):
    """Light-moving frame time over the plain points frame time."""
    return _ratio(row["frame_moving_s"], row["plain_points_s"])


def static_ratio(row):
    return _ratio(row["frame_static_s"], row["plain_points_s"])


def comparable(row):
    """Both coordinates of the trade-off present and not NaN (an infinite error compares)."""
    ratio, error = moving_ratio(row), row["err_mean"]
    return ratio is not None and error is not None and not math.isnan(ratio + error)


def plottable(row):
    """Both coordinates of the trade-off finite and positive (log axes)."""
    return (comparable(row) and 0 < moving_ratio(row) < math.inf and
            0 < row["err_mean"] < math.inf)


def group_by(rows, *columns):
    """Rows grouped by the values of `columns`, groups and rows in their CSV order."""
    groups = OrderedDict()
    for row in rows:
        groups.setdefault(tuple(row[c] for c in columns), []).append(row)
    return groups


def pareto_front(rows):
    """The lines of the rows no other row beats in both time ratio and mean error.

    Rows without both values (or with a NaN) are never on the front. Call with the rows of one
    cloud and material.
    """
    candidates = [r for r in rows if comparable(r)]
    front = set()
    for r in candidates:
        t, e = moving_ratio(r), r["err_mean"]
        beaten = any(moving_ratio(s) <= t and s["err_mean"] <= e and
                     (moving_ratio(s) < t or s["err_mean"] < e) for s in candidates)
        if not beaten:
            front.add(r["line"])
    return front


def front_lines(sweep_rows):
    """Lines of every sweep row on the Pareto front of its cloud and material."""
    lines = set()
    for group in group_by(sweep_rows, "cloud", "material").values():
        lines |= pareto_front(group)
    return lines


# Markdown

def _figures(value):
    """Three significant figures without an exponent: 36,900 / 44 / 2.5 / 0.00312."""
    if value is None:
        return MISSING
    if value == 0 or not math.isfinite(value):
        return f"{value:g}"
    decimals = max(0, 2 - math.floor(math.log10(abs(value))))
    text = f"{round(value, decimals):,.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def _ms(seconds):
    return MISSING if seconds is None else _figures(1000 * seconds)


def _times(ratio):
    return MISSING if ratio is None else _figures(ratio) + "x"


def _percent(fraction):
    return MISSING if fraction is None else _figures(100 * fraction)


def _count(value):
    return MISSING if value is None else f"{value:,}"


def _whole(value):
    return MISSING if value is None else str(value)


def _marks(row, front):
    marks = []
    if row["line"] in front:
        marks.append("front")
    if row["is_paper"]:
        marks.append("paper")
    if row["is_default"]:
        marks.append("default")
    return ", ".join(marks)


def _table(header, body):
    lines = ["| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    lines += ["| " + " | ".join(cells) + " |" for cells in body]
    return lines


def _by_time(row):
    t = row["frame_moving_s"]
    return (t is None, t if t is not None else 0.0, row["line"])


SWEEP_HEADER = ("marks", "strategy", "map (texels)", "opening angle", "cell samples",
                "bake (ms)", "light steps (ms)", "static frame (ms)", "static / plain",
                "moving frame (ms)", "moving / plain", "plain points (ms)", "mean err (%)",
                "p99 err (%)", "max err (%)", "8-bit mean", "8-bit max", "near field (MiB)",
                "virtual points", "lit cells", "peak RSS (MiB)")


def sweep_cells(row, front):
    return (_marks(row, front), row["strategy"] or MISSING, _whole(row["map_size"]),
            _figures(row["opening_angle"]), _whole(row["cell_samples"]), _ms(row["bake_s"]),
            _ms(row["light_s"]), _ms(row["frame_static_s"]), _times(static_ratio(row)),
            _ms(row["frame_moving_s"]), _times(moving_ratio(row)), _ms(row["plain_points_s"]),
            _percent(row["err_mean"]), _percent(row["err_p99"]), _percent(row["err_max"]),
            _figures(row["err8_mean"]), _figures(row["err8_max"]),
            _figures(row["near_field_mib"]), _count(row["virtual_points"]),
            _count(row["lit_cells"]), _figures(row["peak_rss_mb"]))


SCALE_HEADER = ("points", "strategy", "bake (ms)", "light steps (ms)", "static frame (ms)",
                "static / plain", "moving frame (ms)", "moving / plain", "plain points (ms)",
                "near field (MiB)", "peak RSS (MiB)")


def scale_cells(row):
    return (_count(row["points"]), row["strategy"] or MISSING, _ms(row["bake_s"]),
            _ms(row["light_s"]), _ms(row["frame_static_s"]), _times(static_ratio(row)),
            _ms(row["frame_moving_s"]), _times(moving_ratio(row)), _ms(row["plain_points_s"]),
            _figures(row["near_field_mib"]), _figures(row["peak_rss_mb"]))


VIEW_HEADER = ("points", "splatting", "light static", "/ plain", "plain points",
               "peak RSS (MiB)")


def view_cells(row):
    return (_count(row["points"]), row["strategy"] or MISSING, _ms(row["frame_static_s"]),
            _times(static_ratio(row)), _ms(row["plain_points_s"]), _figures(row["peak_rss_mb"]))


def markdown(rows, source_name):
    sweep = [r for r in rows if r["kind"] == "sweep"]
    scale = [r for r in rows if r["kind"] == "scale"]
    view = [r for r in rows if r["kind"] == "view"]
    front = front_lines(sweep)
    out = [f"# Speed against error: {source_name}", ""]
    out += ["Times in milliseconds at the benchmark's image size; `/ plain` is a frame time "
            "over that of plain VTK points of the same cloud in the same run. Errors are per point "
            "against the CPU reference (relative, mean over RGB; points below 1 % of the "
            "brightest left out); 8-bit: difference of sRGB values. Marks: `front` on the "
            "Pareto front of moving-frame ratio against mean error within the cloud and "
            "material (no other row is at least as fast and as accurate and better in one); "
            "`paper` the paper's setting; `default` the renderer's default. Rows are sorted "
            "by the light-moving frame time; `-` was not measured.", ""]
    out += ["## Settings swept", ""]
    if not sweep:
        out += ["No sweep rows.", ""]
    for (cloud, material), group in group_by(sweep, "cloud", "material").items():
        points = next((r["points"] for r in group if r["points"] is not None), None)
        out += [f"### {cloud}, {material} ({_count(points)} points)", ""]
        out += _table(SWEEP_HEADER, [sweep_cells(r, front) for r in sorted(group, key=_by_time)])
        out.append("")
    out += ["## Scale (default setting)", ""]
    if not scale:
        out += ["No scale rows.", ""]
    for (cloud, material), group in group_by(scale, "cloud", "material").items():
        out += [f"### {cloud}, {material}", ""]
        ordered = sorted(group, key=lambda r: (r["points"] is None, r["points"] or 0, r["line"]))
        out += _table(SCALE_HEADER, [scale_cells(r) for r in ordered])
        out.append("")
    if view:
        out += ["## View alone (light static, radiance given)", ""]
        for (cloud,), group in group_by(view, "cloud").items():
            out += [f"### {cloud}", ""]
            ordered = sorted(group, key=lambda r: (r["points"] or 0, r["line"]))
            out += _table(VIEW_HEADER, [view_cells(r) for r in ordered])
            out.append("")
    return "\n".join(out)


# Plots

def strategy_markers(rows):
    """A marker shape per strategy: fixed for the known ones, spares for any other."""
    markers = OrderedDict()
    spare = itertools.cycle(SPARE_MARKERS)
    for name in sorted({r["strategy"] for r in rows}):
        markers[name] = STRATEGY_MARKERS.get(name) or next(spare)
    return markers


def material_colours(rows):
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    names = sorted({r["material"] for r in rows})
    return OrderedDict((name, cycle[k % len(cycle)]) for k, name in enumerate(names))


def tradeoff_figure(sweep):
    """Light-moving frame ratio against mean error, one panel per cloud."""
    shown = [r for r in sweep if plottable(r)]
    if not shown:
        return None
    front = front_lines(sweep)
    markers = strategy_markers(shown)
    colours = material_colours(shown)
    clouds = group_by(shown, "cloud")
    unshown = group_by([r for r in sweep if not plottable(r)], "cloud")
    columns = min(len(clouds), 2)
    rows_of_panels = math.ceil(len(clouds) / columns)
    figure, axes = plt.subplots(rows_of_panels, columns, squeeze=False, layout="constrained",
                                figsize=(6.2 * columns + 2.2, 4.8 * rows_of_panels))
    for ax, ((cloud,), group) in zip(axes.flat, clouds.items()):
        for row in group:
            on_front = row["line"] in front
            ax.scatter(moving_ratio(row), 100 * row["err_mean"], marker=markers[row["strategy"]],
                       s=52 if on_front else 40, color=colours[row["material"]],
                       alpha=1.0 if on_front else 0.45, edgecolors="black", linewidths=0.5,
                       zorder=3)
            label = _marks(row, front=())
            if label:
                ax.annotate(label, (moving_ratio(row), 100 * row["err_mean"]),
                            xytext=(7, 6), textcoords="offset points", fontsize=8.5,
                            zorder=4)
        for (material,), members in group_by(group, "material").items():
            on_front = sorted((r for r in members if r["line"] in front), key=moving_ratio)
            ax.plot([moving_ratio(r) for r in on_front],
                    [100 * r["err_mean"] for r in on_front], color=colours[material],
                    linewidth=1.2, zorder=2)
        points = next((r["points"] for r in group if r["points"] is not None), None)
        ax.set_title(f"{cloud} ({_count(points)} points)")
        log_axes(ax)
        ax.margins(0.12)
        hidden = len(unshown.get((cloud,), []))
        if hidden:
            ax.text(0.02, 0.02, f"{hidden} row(s) not shown: time ratio or error missing, zero "
                    "or not finite", transform=ax.transAxes, fontsize=8, color="0.3")
        ax.set_xlabel("frame time with the light moving / plain VTK points (x)")
        ax.set_ylabel("mean error against the CPU reference (%)")
    for ax in list(axes.flat)[len(clouds):]:
        ax.set_visible(False)

    handles = [Line2D([], [], linestyle="none", marker=m, color="0.55", markeredgecolor="black",
                      label=f"strategy {name}") for name, m in markers.items()]
    handles += [Line2D([], [], linestyle="none", marker="o", color=c, markeredgecolor="black",
                       label=f"material {name}") for name, c in colours.items()]
    handles.append(Line2D([], [], color="0.3", label="Pareto front (per material);\n"
                          "faded: off the front"))
    # Beside the top-right panel, where the constrained layout leaves room for it.
    axes[0, -1].legend(handles=handles, loc="upper left", bbox_to_anchor=(1.03, 1.0),
                       frameon=False, fontsize=9)
    figure.suptitle("Real-time renderer: frame time with a moving light against per-point error")
    return figure


def _tick_label(value, _position):
    return f"{value:,.0f}" if value >= 1000 else f"{value:g}"


def log_axes(ax):
    """Log axes labelled in plain numbers: 1-2-5 ticks over a short range, decades otherwise."""
    ax.set_xscale("log")
    ax.set_yscale("log")
    for axis, (low, high) in ((ax.xaxis, ax.dataLim.intervalx), (ax.yaxis, ax.dataLim.intervaly)):
        decades = math.log10(high / low) if 0 < low <= high < math.inf else 0.0
        axis.set_major_locator(ticker.LogLocator(subs=(1.0, 2.0, 5.0) if decades <= 2.5
                                                 else (1.0,)))
        axis.set_major_formatter(ticker.FuncFormatter(_tick_label))
        axis.set_minor_formatter(ticker.NullFormatter())
    ax.grid(True, which="both", linewidth=0.4, alpha=0.5)


SCALE_TIMES = (("frame_static_s", "frame, light static"),
               ("frame_moving_s", "frame, light moving"),
               ("bake_s", "bake (near-field table)"),
               ("light_s", "light steps (1-2)"),
               ("plain_points_s", "plain VTK points frame"))


def scale_figure(scale):
    """Times and peak memory against the point count, log-log."""
    groups = group_by(scale, "cloud", "material")
    series_markers = dict(zip(groups, itertools.cycle(("o", "s", "^", "D", "v", "P", "X"))))
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    figure, (times_ax, memory_ax) = plt.subplots(1, 2, figsize=(12.5, 4.8), layout="constrained")
    drawn = False
    for key, group in groups.items():
        ordered = sorted((r for r in group if r["points"] is not None and r["points"] > 0),
                         key=lambda r: r["points"])
        suffix = f" ({key[0]}, {key[1]})" if len(groups) > 1 else ""
        for k, (column, what) in enumerate(SCALE_TIMES):
            present = [r for r in ordered if r[column] is not None and r[column] > 0]
            if present:
                times_ax.plot([r["points"] for r in present], [r[column] for r in present],
                              marker=series_markers[key], color=cycle[k % len(cycle)],
                              label=what + suffix)
                drawn = True
        present = [r for r in ordered if r["peak_rss_mb"] is not None and r["peak_rss_mb"] > 0]
        if present:
            memory_ax.plot([r["points"] for r in present], [r["peak_rss_mb"] for r in present],
                           marker=series_markers[key], color="black",
                           label="peak resident memory" + suffix)
            drawn = True
    if not drawn:
        plt.close(figure)
        return None
    for ax, ylabel in ((times_ax, "time (s)"), (memory_ax, "peak resident memory (MiB)")):
        ax.set_xlabel("points in the cloud")
        ax.set_ylabel(ylabel)
        if ax.has_data():
            log_axes(ax)
            ax.legend(fontsize=9)
        else:
            ax.text(0.5, 0.5, "not measured", transform=ax.transAxes, ha="center")
            ax.set_xticks([])
            ax.set_yticks([])
    times_ax.set_title("Time per step")
    memory_ax.set_title("Memory")
    title = "Scale with the default setting"
    if len(groups) == 1:
        cloud, material = next(iter(groups))
        title += f": {cloud}, {material}"
    figure.suptitle(title)
    return figure


# Output, whole or not at all

def _replace_into(path, write):
    partial = f"{path}.{os.getpid()}.partial"
    try:
        write(partial)
        os.replace(partial, path)
    except BaseException:
        if os.path.exists(partial):
            os.unlink(partial)
        raise


def write_text(path, text):
    def write(partial):
        with open(partial, "w", encoding="utf-8") as f:
            f.write(text)
    _replace_into(path, write)


def write_png(path, figure):
    _replace_into(path, lambda partial: figure.savefig(partial, format="png", dpi=130))
    plt.close(figure)


def report(csv_path, out_dir):
    """Writes the report of `csv_path` into `out_dir`; returns the paths written."""
    rows = read_rows(csv_path)
    os.makedirs(out_dir, exist_ok=True)
    written = []
    md = os.path.join(out_dir, "bench.md")
    write_text(md, markdown(rows, os.path.basename(csv_path)) + "\n")
    written.append(md)
    for name, figure in (
            ("bench_tradeoff.png", tradeoff_figure([r for r in rows if r["kind"] == "sweep"])),
            ("bench_scale.png",
             scale_figure([r for r in rows if r["kind"] == "scale" and r["is_default"]]))):
        if figure is None:
            print(f"bench_report: no rows for {name}; not written", file=sys.stderr)
            continue
        path = os.path.join(out_dir, name)
        write_png(path, figure)
        written.append(path)
    return written


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", help="benchmark results (columns in this script's docstring)")
    parser.add_argument("--out-dir", required=True, help="folder for bench.md and the PNGs")
    args = parser.parse_args(argv)
    try:
        written = report(args.csv, args.out_dir)
    except (OSError, CsvError) as error:
        print(f"bench_report: {error}", file=sys.stderr)
        return 2
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
