#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The figures of the processing-order study (`lepp paper --orders`).

    /usr/bin/python3 paper/orders_plots.py docs/paper/orders.json docs/paper

Reads orders.json (one record per run: problem, method, order, seed, theta,
steiner, budget, converged) and writes orders_points_<method>.png (box plots of
the random orders' points added per theta, the named orders as markers, the
paper's Table 1 as crosses) and orders_converged.png (the share of random
orders that converge per theta). Needs Debian's python3-matplotlib.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

NAMES = {"square400": "Square400", "circles240": "Circles240", "rect162": "Rectangle162", "A": "A-case"}
# Table 1, Lepp-centroid: theta -> points added.
TABLE1 = {
    "square400": {20: 391, 25: 491, 28: 543, 30: 595, 32: 703, 34: 919, 35: 1264, 36: 1843},
    "circles240": {20: 274, 25: 335, 28: 371, 30: 416, 32: 493, 34: 722, 35: 911, 36: 1630},
    "rect162": {20: 217, 25: 271, 28: 286, 30: 310, 32: 363, 34: 490, 35: 570, 36: 5473},
    "A": {20: 30, 25: 43, 28: 44, 30: 49, 32: 57, 34: 85, 35: 121, 36: 239},
}
NAMED = [("fifo", "tab:blue", "o"), ("lifo", "tab:orange", "s"), ("flip", "tab:green", "^"),
         ("smallest-angle", "tab:red", "D"), ("batch", "tab:purple", "v")]


def main(path, outdir):
    with open(path) as f:
        study = json.load(f)
    runs = study["runs"]
    problems, angles = study["problems"], study["angles"]
    for method in study["methods"]:
        fig, axes = plt.subplots(len(problems), 1, figsize=(9, 3.2 * len(problems)), squeeze=False)
        for ax, problem in zip(axes[:, 0], problems):
            cell = [r for r in runs if r["problem"] == problem and r["method"] == method]
            data = [[r["steiner"] for r in cell if r["order"] == "random" and r["theta"] == t] for t in angles]
            if any(data):
                ax.boxplot([d if d else [float("nan")] for d in data], positions=angles, widths=0.5, whis=(0, 100),
                           medianprops=dict(color="black"))
            for k, (name, color, marker) in enumerate(NAMED):
                for conv in (True, False):
                    pts = [(r["theta"] + (k - 1.5) * 0.08, r["steiner"]) for r in cell
                           if r["order"] == name and r["converged"] == conv]
                    if pts:
                        ax.scatter([p[0] for p in pts], [p[1] for p in pts], marker=marker, s=28, zorder=3,
                                   color=color if conv else "none", edgecolors=color,
                                   label=name if conv else None)
            budgets = sorted({(r["theta"], r["budget"]) for r in cell})
            ax.plot([b[0] for b in budgets], [b[1] for b in budgets], ":", color="gray", label="budget")
            if method == "centroid" and problem in TABLE1:
                paper = [(t, TABLE1[problem][t]) for t in angles if t in TABLE1[problem]]
                ax.scatter([p[0] for p in paper], [p[1] for p in paper], marker="x", color="black", s=40, zorder=4,
                           label="paper (Table 1)")
            ax.set_yscale("log")
            ax.set_title(f"{NAMES.get(problem, problem)}, Lepp-{method}")
            ax.set_ylabel("points added")
            ax.set_xticks(angles)
            ax.set_xticklabels([f"{t:g}" for t in angles])
            ax.grid(True, which="both", alpha=0.3)
        axes[-1, 0].set_xlabel("θ (degrees)")
        handles, labels = axes[0, 0].get_legend_handles_labels()
        uniq = dict(zip(labels, handles))
        axes[0, 0].legend(uniq.values(), uniq.keys(), fontsize=7, loc="upper left", ncol=3)
        fig.tight_layout()
        fig.savefig(f"{outdir}/orders_points_{method}.png", dpi=90)
        plt.close(fig)

    fig, axes = plt.subplots(1, len(study["methods"]), figsize=(5.5 * len(study["methods"]), 3.6), squeeze=False)
    for ax, method in zip(axes[0], study["methods"]):
        for problem in problems:
            share = []
            for t in angles:
                cell = [r for r in runs if r["problem"] == problem and r["method"] == method and r["order"] == "random"
                        and r["theta"] == t]
                share.append(100.0 * sum(r["converged"] for r in cell) / len(cell) if cell else float("nan"))
            ax.plot(angles, share, marker="o", label=NAMES.get(problem, problem))
        ax.set_title(f"Lepp-{method}: random orders converged")
        ax.set_xlabel("θ (degrees)")
        ax.set_ylabel("% of seeds")
        ax.set_ylim(-5, 105)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{outdir}/orders_converged.png", dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: orders_plots.py ORDERS.json OUTDIR")
    main(sys.argv[1], sys.argv[2])
