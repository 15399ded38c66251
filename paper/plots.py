#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The figures of the paper's empirical study, from the runs `lepp paper` made.

    /usr/bin/python3 paper/plots.py docs/paper/results.json docs/paper

Reads results.json (one record per run: problem, method, theta, vertices,
min_angle, ...) and writes fig10..fig14 and two more plots as PNG. Only runs
that finished under the budget are plotted, since the statistics of a stopped
run describe a half-refined mesh. Needs Debian's python3-matplotlib, which
/usr/bin/python3 sees (the pyenv python3 first on PATH does not).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

PROBLEMS = [("square400", "Square400"), ("circles240", "Circles240"), ("rect162", "Rectangle162"), ("A", "A-case")]
STYLE = {
    "centroid": dict(color="tab:blue", marker="o", label="Lepp-centroid"),
    "midpoint": dict(color="tab:orange", marker="s", label="Lepp-midpoint"),
    "triangle": dict(color="tab:green", marker="^", label="Triangle (off-center)"),
    "cgal": dict(color="tab:gray", marker="x", label="CGAL Mesh_2"),
}
# Points added in Fig. 12's caption: (method, theta) -> points.
FIG12_PAPER = {("midpoint", 10): 230, ("centroid", 10): 185, ("midpoint", 25): 668, ("centroid", 25): 491}


def series(runs, problem, method, x, y):
    """(x, y, theta) of the finished fifo runs of one method on one corpus problem, by theta."""
    rows = [r for r in runs if r["problem"] == problem and r["method"] == method and r["reading"] == ""
            and r["order"] == "fifo" and r["finished"]]
    rows.sort(key=lambda r: r["theta"])
    return [r[x] for r in rows], [r[y] for r in rows], [r["theta"] for r in rows]


def grid(title):
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    fig.suptitle(title)
    return fig, [ax for row in axes for ax in row]


def per_problem(runs, out, name, title, methods, x, y, xlabel, ylabel, logx=False, annotate=True, hline=None):
    fig, axes = grid(title)
    for ax, (key, label) in zip(axes, PROBLEMS):
        for method in methods:
            xs, ys, thetas = series(runs, key, method, x, y)
            if not xs:
                continue
            ax.plot(xs, ys, linestyle="-", linewidth=1, markersize=4, **STYLE[method])
            if annotate:
                for xv, yv, t in zip(xs, ys, thetas):
                    ax.annotate(f"{t:g}", (xv, yv), fontsize=6, xytext=(2, 2), textcoords="offset points",
                                color=STYLE[method]["color"])
        if hline is not None:
            ax.axhline(hline, color="k", linewidth=0.5, linestyle=":")
        ax.set_title(label)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        if logx:
            ax.set_xscale("log")
        ax.grid(True, linewidth=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)


def fig12(runs, out):
    """Area-quality distribution of Square400 at 10 and 25 degrees, centroid vs midpoint."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    fig.suptitle("Fig. 12: area quality distribution, Square400")
    for ax, theta in zip(axes, (10, 25)):
        width = 0.05 / 2.2
        for k, method in enumerate(("midpoint", "centroid")):
            rows = [r for r in runs if r["problem"] == "square400" and r["method"] == method and r["reading"] == ""
                    and r["order"] == "fifo" and r["theta"] == theta and r["triangles"] > 0]
            if not rows:
                continue
            r = rows[0]
            total = sum(r["q_hist"])
            share = [100.0 * c / total for c in r["q_hist"]]
            left = [i * 0.05 + k * width for i in range(len(share))]
            label = (f"{STYLE[method]['label']}: {r['steiner']} points (paper: {FIG12_PAPER[(method, theta)]})"
                     + ("" if r["finished"] else ", did not finish"))
            ax.bar(left, share, width=width, align="edge", color=STYLE[method]["color"], label=label)
        ax.set_title(f"θ = {theta}°")
        ax.set_xlabel("area quality q (1 = equilateral)")
        ax.set_ylabel("% of triangles")
        ax.set_xlim(0, 1)
        ax.legend(fontsize=8)
        ax.grid(True, axis="y", linewidth=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fig12_quality_distribution.png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plots.py results.json OUT_DIR")
    with open(sys.argv[1]) as f:
        data = json.load(f)
    runs = data["runs"]
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    per_problem(runs, out, "fig10_min_area_quality.png", "Fig. 10: minimum area quality vs number of vertices",
                ["centroid", "midpoint"], "vertices", "min_area_quality", "vertices", "minimum area quality q", logx=True)
    per_problem(runs, out, "fig11_avg_min_angle.png", "Fig. 11: average smallest angle vs number of vertices",
                ["centroid", "midpoint"], "vertices", "avg_min_angle", "vertices", "average smallest angle (°)", logx=True)
    fig12(runs, out)
    per_problem(runs, out, "fig14_min_angle.png", "Fig. 14: minimum angle vs number of vertices",
                ["centroid", "triangle", "cgal"], "vertices", "min_angle", "vertices", "minimum angle (°)", logx=True)
    per_problem(runs, out, "shortest_edge.png", "Shortest mesh edge / shortest input segment vs θ",
                ["centroid", "midpoint", "triangle"], "theta", "shortest_edge_ratio", "θ (°)",
                "normalized shortest edge", annotate=False)
    per_problem(runs, out, "lepp_size.png", "Average Lepp size vs θ", ["centroid", "midpoint"], "theta", "avg_lepp",
                "θ (°)", "triangles per Lepp search", annotate=False)


if __name__ == "__main__":
    main()
