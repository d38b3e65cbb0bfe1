#!/usr/bin/env python3
"""Every chart of the studies, drawn with matplotlib from the JSON the study wrote.

    scripts/draw-charts.py DATA.json [-o OUT]
    scripts/draw-charts.py --check DATA.json [-o OUT]

The studies measure and write their figures as JSON; this script alone draws them. DATA's
"study" field says which study wrote it:

    pareto          `raystep-reference bench --pareto --out FOLDER` (FOLDER/pareto.json): a
                    chart per family of hard cases, pareto-FAMILY.svg, and pareto-offsets.svg,
                    into OUT (a folder; by default the JSON's own).
    sampling-noise  `raystep-reference bench --sampling --json FILE`: one chart, OUT (by default
                    FILE with .svg for .json).
    epsilon         `raystep-reference bench --epsilon --json FILE`: one chart, likewise.
    pareto-family   one family of the pareto study with a submission's point ("family",
                    "footnote"): the chart of the grader's HTML report, likewise.

DATA - reads the JSON from stdin, and -o - writes the one chart to stdout (the grader's report).

The same JSON draws the same SVG, byte for byte (a fixed hash salt, no date), so that a chart
in docs/ changes only when its figures do. --check draws without writing and exits 1, naming
each chart, where a file on disk is not what its JSON draws (a ctest test holds docs/ to it);
it exits 77, ctest's skip, where the file was drawn by another matplotlib version, whose SVG
differs in its details, and where matplotlib is not installed (Debian: python3-matplotlib). Exits
2 for a file that is not such JSON, naming it."""

import argparse
import atexit
import io
import json
import math
import os
import pathlib
import shutil
import sys
import tempfile

# matplotlib keeps its settings and cache under the home folder, and fails to start without one:
# a run with no HOME (the grader runs this as a user of its own, with no environment) gets a
# folder of its own, removed at exit.
if "MPLCONFIGDIR" not in os.environ and "HOME" not in os.environ:
    os.environ["MPLCONFIGDIR"] = tempfile.mkdtemp(prefix="draw-charts-")
    atexit.register(shutil.rmtree, os.environ["MPLCONFIGDIR"], ignore_errors=True)

try:
    import matplotlib

    matplotlib.use("svg")
    from matplotlib import pyplot
    from matplotlib.lines import Line2D

    matplotlib.rcParams.update({
        "svg.hashsalt": "raystep",  # the same ids on every run
        "svg.fonttype": "none",  # text stays text: searchable, and smaller
        "font.size": 8,
        "axes.titlesize": 9,
        "axes.grid": True,
        "grid.color": "#e5e5e5",
    })
except ImportError:
    matplotlib = None  # said once the data is read, which needs no matplotlib

# A colour per method or rule, in order of first appearance; the noise study's kinds keep theirs
# in every panel.
COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"]
NOISE_KIND_COLOURS = {"stratified": COLOURS[0], "regular": COLOURS[1], "random": COLOURS[2]}


class Mismatch(Exception):
    """--check: the chart on disk is not what its JSON draws, or another matplotlib drew it."""

    def __init__(self, path, other_version):
        super().__init__(str(path))
        self.path = path
        self.other_version = other_version


CHECKING = False  # --check: compare each chart with its file instead of writing it


def save(figure, path):
    # "tight" takes in the legend, which sits under the panels, outside the axes' layout.
    options = {"format": "svg", "metadata": {"Date": None}, "bbox_inches": "tight"}
    if CHECKING:
        drawn = io.BytesIO()
        figure.savefig(drawn, **options)
        pyplot.close(figure)
        on_disk = path.read_bytes() if path.is_file() else b""
        if drawn.getvalue() != on_disk:
            version = f"Matplotlib v{matplotlib.__version__},".encode()
            raise Mismatch(path, bool(on_disk) and version not in on_disk)
        print(f"up to date: {path}")
        return
    if str(path) == "-":
        figure.savefig(sys.stdout.buffer, **options)
    else:
        path.parent.mkdir(parents=True, exist_ok=True)
        figure.savefig(path, **options)
        print(f"wrote {path}")
    pyplot.close(figure)


def decade_label(decade):
    """10^decade as a number where it is short (0.001 to 1000), else as 1e-5 or 1e8."""
    return f"{10.0 ** decade:g}" if -3 <= decade <= 3 else f"1e{decade}"


def log_axis_with_zero(axes, low, high, unit=""):
    """A log y axis from 10^low to 10^high with 0 on its bottom line, half a decade below 10^low,
    so that zero stands apart from the smallest nonzero value. Returns where to draw a value."""
    bottom = 10.0 ** (low - 0.5)
    axes.set_yscale("log")
    axes.set_ylim(bottom, 10.0 ** high)
    decades = [10.0 ** d for d in range(low, high + 1)]
    axes.set_yticks([bottom] + decades,
                    ["0"] + [decade_label(d) + unit for d in range(low, high + 1)])
    axes.minorticks_off()
    return lambda value: min(max(value, bottom), 10.0 ** high)


def scatter(axes, x, y, colour, marker, label=None):
    """A point: filled for double, open for float, a black labelled diamond for anything else."""
    if marker == "diamond":
        axes.plot([x], [y], marker="D", color="black", markersize=6, linestyle="none")
        axes.annotate(label, (x, y), xytext=(6, 4), textcoords="offset points")
    else:
        axes.plot([x], [y], marker="o", markersize=5, linestyle="none", color=colour,
                  markerfacecolor=colour if marker == "filled" else "white")


def pareto_family_chart(family, footnote):
    """Throughput across; wrong answers (% of cases) up on the left, the median t error in double
    ulps with a whisker to the 99th percentile up on the right."""
    in_study = [p for p in family["points"] if p["precision"] in ("double", "float")]
    colour_of = {}
    for point in in_study:
        colour_of.setdefault(point["label"], COLOURS[len(colour_of) % len(COLOURS)])
    fastest = max((p["mrays_per_second"] for p in family["points"]), default=0.0)
    largest_ulps = max([1.0] + [p["t_ulps"]["p99"] for p in family["points"]])

    figure, (wrong, t_error) = pyplot.subplots(1, 2, figsize=(8.2, 4.2), layout="constrained")
    figure.suptitle(f"{family['name']}: {family['cases']:,} decided cases\n"
                    f"{family['description']}", fontsize=9)
    wrong_at = log_axis_with_zero(wrong, -2, 2, "%")
    t_at = log_axis_with_zero(t_error, 0, max(1, math.ceil(math.log10(largest_ulps))))
    wrong.set_title("wrong answers: false hits + false misses, % of cases")
    t_error.set_title("t error in double ulps: median, whisker to the 99th percentile")
    for axes in (wrong, t_error):
        axes.set_xlim(0, fastest * 1.1 if fastest > 0 else 1.0)
        axes.set_xlabel("Mrays/s, one thread (ray-primitive tests)")
    for point in family["points"]:
        studied = point["precision"] in ("double", "float")
        colour = colour_of.get(point["label"], "black")
        marker = ("diamond" if not studied else
                  "filled" if point["precision"] == "double" else "open")
        x = point["mrays_per_second"]
        scatter(wrong, x, wrong_at(100.0 * point["wrong_share"]), colour, marker, point["label"])
        median, p99 = t_at(point["t_ulps"]["median"]), t_at(point["t_ulps"]["p99"])
        t_error.vlines(x, median, p99, colors=colour, linewidth=1)
        scatter(t_error, x, median, colour, marker, point["label"])

    handles = [Line2D([], [], marker="o", color=colour, linestyle="none", label=label)
               for label, colour in colour_of.items()]
    handles += [Line2D([], [], marker="o", color="#555", linestyle="none", label="double"),
                Line2D([], [], marker="o", color="#555", markerfacecolor="white",
                       linestyle="none",
                       label="float: the ray and shapes rounded to float; "
                             "its ulp is 2^29 double ulps")]
    figure.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.02, 0.0), ncol=4, frameon=False,
                  title=footnote, title_fontsize=7)
    return figure


def pareto_offsets_chart(rules, footnote):
    """A panel per acne scene: shadow rays per second across, wrong pixel-lights up, a point per
    rule and epsilon."""
    scenes = list(dict.fromkeys(r["scene"] for r in rules))
    names = ["along-ray", "along-normal", "error-bound"]
    figure, panels = pyplot.subplots(1, len(scenes), figsize=(0.7 + 3.3 * len(scenes), 4.0),
                                     layout="constrained", squeeze=False)
    figure.suptitle("ray offset rules: the cost of a shadow ray against its acne and leaks",
                    fontsize=9)
    for axes, scene in zip(panels[0], scenes):
        rows = [r for r in rules if r["scene"] == scene]
        at = log_axis_with_zero(axes, -4, 2, "%")
        axes.set_title(scene)
        axes.set_xlabel("million shadow rays/s, one thread")
        fastest = max(1000.0 / r["nanoseconds_per_ray"] for r in rows)
        axes.set_xlim(0, fastest * 1.15)
        for r in rows:
            wrong = 100.0 * (r["acne"] + r["leaks"]) / r["decided"] if r["decided"] else 0.0
            scatter(axes, 1000.0 / r["nanoseconds_per_ray"], at(wrong),
                    COLOURS[names.index(r["rule"])], "filled")
    handles = [Line2D([], [], marker="o", color=COLOURS[k], linestyle="none", label=name)
               for k, name in enumerate(names)]
    figure.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.02, 0.0), ncol=3, frameon=False,
                  title="a point per epsilon: 1e-10, 1e-8, 1e-6, 1e-4, 1e-2; up: acne + leaks, "
                        "% of the decided pixel-lights\n" + footnote, title_fontsize=7)
    return figure


def noise_chart(study):
    """A panel per scene: RMSE against the mean processor time of a render, both logarithmic, a
    line per curve through its sample counts, a whisker of one spread either side of each point."""
    scenes = study["scenes"]
    figure, panels = pyplot.subplots(1, len(scenes), figsize=(0.6 + 3.05 * len(scenes), 4.2),
                                     layout="constrained", squeeze=False)
    figure.suptitle("Noise against time: RMSE against a converged render, a dot per sample count",
                    fontsize=9)
    for axes, scene in zip(panels[0], scenes):
        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.set_title(f"{scene['name']}: {scene['sampled']}")
        axes.set_xlabel("processor seconds per render (log)")
        axes.set_ylabel("RMSE (log)")
        for curve in scene["curves"]:
            colour = NOISE_KIND_COLOURS[curve["kind"]]
            points = curve["points"]
            seconds = [p["seconds"] for p in points]
            rmse = [p["rmse"] for p in points]
            # A whisker reaching zero or below stops at the axis's bottom.
            low = [max(p["rmse"] - p["rmse_spread"], p["rmse"] / 100) for p in points]
            high = [p["rmse"] + p["rmse_spread"] for p in points]
            axes.vlines(seconds, low, high, colors=colour, linewidth=1)
            axes.plot(seconds, rmse, marker="o", markersize=4, color=colour, linewidth=1,
                      label=f"{curve['method']}: RMSE ~ N^{curve['slope']:.2f}")
        axes.legend(loc="lower left", frameon=False)
    return figure


def epsilon_chart(study):
    """A panel per acne scene: epsilon across (log), wrong pixels up (log, 0 on the bottom line),
    acne and leaks of the two fixed rules; error-bound's counts in words under each panel."""
    scenes = study["scenes"]
    figure, panels = pyplot.subplots(1, len(scenes), figsize=(0.4 + 3.3 * len(scenes), 3.2),
                                     layout="constrained", squeeze=False)
    series = [("along_ray", "acne", "#c0392b", "-"), ("along_ray", "leaks", "#c0392b", "--"),
              ("along_normal", "acne", "#2471a3", "-"), ("along_normal", "leaks", "#2471a3", "--")]
    for axes, scene in zip(panels[0], scenes):
        at = log_axis_with_zero(axes, 0, 5)
        axes.set_xscale("log")
        axes.set_title(pathlib.Path(scene["scene"]).stem, fontweight="bold")
        bound = scene["error_bound"]
        axes.set_xlabel(f"epsilon\nerror-bound: {bound['acne']:,} acne, {bound['leaks']:,} leaks")
        for rule, error, colour, style in series:
            counts = [at(errors[error]) for errors in scene[rule]]
            axes.plot(scene["epsilons"], counts, color=colour, linestyle=style, linewidth=1.5)
    handles = [Line2D([], [], color="#c0392b", label="along-ray"),
               Line2D([], [], color="#2471a3", label="along-normal"),
               Line2D([], [], color="#333", label="acne: pixels wrongly in shadow"),
               Line2D([], [], color="#333", linestyle="--", label="leaks: pixels wrongly lit")]
    figure.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.02, 0.0), ncol=4, frameon=False)
    return figure


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("data", type=pathlib.Path, help="the JSON a study wrote")
    parser.add_argument("-o", "--out", type=pathlib.Path,
                        help="the chart (a folder for pareto); by default beside the JSON")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 where a chart on disk is not what the JSON draws")
    arguments = parser.parse_args()
    global CHECKING
    CHECKING = arguments.check
    from_stdin = str(arguments.data) == "-"
    try:
        study = json.loads(sys.stdin.read() if from_stdin else arguments.data.read_text())
        kind = study["study"]
    except (OSError, ValueError, KeyError, TypeError) as error:
        print(f"{arguments.data}: not the JSON of a study ({error})", file=sys.stderr)
        return 2
    if matplotlib is None:
        print("matplotlib is not installed; Debian: apt-get install python3-matplotlib",
              file=sys.stderr)
        return 77
    # Where a study of one chart draws it: -o, else beside the JSON, else (from stdin) stdout.
    one_chart = arguments.out or (arguments.data if from_stdin else arguments.data.with_suffix(".svg"))
    try:
        if kind == "pareto":
            out = arguments.out or (pathlib.Path() if from_stdin else arguments.data.parent)
            footnote = f"raystep-reference bench --pareto, {study['date']}, {study['machine']}"
            for family in study["families"]:
                save(pareto_family_chart(family, footnote), out / f"pareto-{family['name']}.svg")
            save(pareto_offsets_chart(study["offset_rules"], footnote), out / "pareto-offsets.svg")
        elif kind == "pareto-family":
            save(pareto_family_chart(study["family"], study["footnote"]), one_chart)
        elif kind in ("sampling-noise", "epsilon"):
            save((noise_chart if kind == "sampling-noise" else epsilon_chart)(study), one_chart)
        else:
            print(f"{arguments.data}: a study this script does not draw: '{kind}'",
                  file=sys.stderr)
            return 2
    except (KeyError, TypeError, IndexError, ValueError) as error:
        print(f"{arguments.data}: a field is missing or of another type ({error!r})",
              file=sys.stderr)
        return 2
    except Mismatch as mismatch:
        if mismatch.other_version:
            print(f"{mismatch.path}: drawn by another matplotlib than {matplotlib.__version__}; "
                  "not compared", file=sys.stderr)
            return 77
        print(f"{mismatch.path}: not what {arguments.data} draws; redraw it: "
              f"scripts/draw-charts.py {arguments.data}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
