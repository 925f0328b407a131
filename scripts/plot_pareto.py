#!/usr/bin/env python3
"""Error-versus-time plots of a merged sweep (`vct merge ... -o OUT` -> OUT/results.json).

One figure per (scene, kind), one panel per case (camera, radius): every variant at (time_ms,
error), a colour per method, the points of one method's parameter grid joined in grid order; the
Pareto front (no other variant of the case is at most as slow and as wrong, and better in one)
is drawn as a step line with ringed points. Log time axis. The title
names the scene, the resolution, the reference's samples and the GL renderer, since the times
only mean something on that renderer.

    plot_pareto.py OUT/results.json -o docs/results [--metric rmse|roi_rmse|nonroi_rmse] [--png]

Writes <scene>__<kind>__<metric>.svg (and .png with --png) and prints the written paths.
Needs matplotlib (Debian: python3-matplotlib).
"""
import argparse
import json
import os
import sys


def _import_matplotlib():
    try:
        import matplotlib
    except ImportError:
        # Debian's python3-matplotlib lives in the system interpreter; a pyenv python3 on
        # PATH would not see it.
        if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
            os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
        sys.exit("plot_pareto.py: needs matplotlib (apt-get install python3-matplotlib)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def pareto_front(points):
    """Indices of the non-dominated (time, error) points: no other point is at most as slow and
    at most as wrong and strictly better in one of the two."""
    front = []
    for i, (t, e) in enumerate(points):
        dominated = any(
            (t2 <= t and e2 <= e and (t2 < t or e2 < e)) for j, (t2, e2) in enumerate(points) if j != i)
        if not dominated:
            front.append(i)
    return front


def group_records(records, metric):
    """{(scene, kind): {case: [records with a numeric time and metric]}} in first-seen order."""
    groups = {}
    for r in records:
        if not isinstance(r.get(metric), (int, float)) or not isinstance(r.get("time_ms"), (int, float)):
            continue
        groups.setdefault((r["scene"], r["kind"]), {}).setdefault(r["case"], []).append(r)
    return groups


def short_params(r):
    p = r.get("params") or {}
    return ";".join(f"{k.split('.')[-1]}={v}" for k, v in sorted(p.items()))


def plot_group(plt, scene, kind, cases, metric, out_dir, png):
    from matplotlib.ticker import LogLocator, ScalarFormatter
    n = len(cases)
    cols = min(n, 3)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(6.5 * cols, 4.6 * rows), squeeze=False)
    methods = []
    for recs in cases.values():
        for r in recs:
            if r["method"] not in methods:
                methods.append(r["method"])
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colour = {m: colours[i % len(colours)] for i, m in enumerate(methods)}
    for ci, (case, recs) in enumerate(cases.items()):
        ax = axes[ci // cols][ci % cols]
        for m in methods:
            mine = [r for r in recs if r["method"] == m]
            if not mine:
                continue
            ax.plot([r["time_ms"] for r in mine], [r[metric] for r in mine], marker="o", linestyle=":",
                    linewidth=0.8, color=colour[m], markersize=5, label=m)
            if len(mine) > 1 or mine[0].get("params"):
                for r in mine:
                    ax.annotate(short_params(r), (r["time_ms"], r[metric]), fontsize=6, alpha=0.75,
                                xytext=(4, 3), textcoords="offset points")
        front = sorted((recs[i] for i in pareto_front([(r["time_ms"], r[metric]) for r in recs])),
                       key=lambda r: r["time_ms"])
        ax.step([r["time_ms"] for r in front], [r[metric] for r in front], where="post", color="black",
                linewidth=1.2, alpha=0.6, label="Pareto front")
        ax.scatter([r["time_ms"] for r in front], [r[metric] for r in front], s=90, facecolors="none",
                   edgecolors="black", linewidths=1.0)
        r0 = recs[0]
        ax.set_xscale("log")
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(plt.NullFormatter())
        ax.set_xlabel("time per frame (ms, median of timed runs; log scale)")
        ax.set_ylabel(metric + (" of indirect radiance" if kind == "gi" else " of AO"))
        ax.set_title(f"camera {r0.get('camera')}, R = {r0.get('radius'):g}", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    for k in range(n, rows * cols):
        axes[k // cols][k % cols].axis("off")
    first = next(iter(cases.values()))[0]
    fig.suptitle(f"{scene}: {kind.upper()} {metric} vs time, {first.get('width')}x{first.get('height')}, "
                 f"reference {first.get('ref_spp')} spp, {first.get('gl_renderer', '')}", fontsize=9)
    fig.tight_layout()
    stem = os.path.join(out_dir, f"{scene}__{kind}__{metric}")
    written = [stem + ".svg"]
    fig.savefig(stem + ".svg", metadata={"Date": None})  # no date: regenerating gives the same file
    if png:
        fig.savefig(stem + ".png", dpi=110)
        written.append(stem + ".png")
    plt.close(fig)
    return written


def plot_all(results_path, out_dir, metric="rmse", png=False):
    plt = _import_matplotlib()
    plt.rcParams["svg.hashsalt"] = "vct"  # stable element ids
    with open(results_path) as f:
        merged = json.load(f)
    os.makedirs(out_dir, exist_ok=True)
    written = []
    for (scene, kind), cases in group_records(merged["records"], metric).items():
        written += plot_group(plt, scene, kind, cases, metric, out_dir, png)
    return written


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", help="merged results.json (vct merge)")
    ap.add_argument("-o", "--output", default=".", help="directory for the plots")
    ap.add_argument("--metric", default="rmse", choices=["rmse", "roi_rmse", "nonroi_rmse", "mae"],
                    help="error on the y axis (roi_rmse: only cases with off-screen occluders)")
    ap.add_argument("--png", action="store_true", help="also write PNG")
    args = ap.parse_args()
    written = plot_all(args.results, args.output, args.metric, args.png)
    if not written:
        print(f"plot_pareto.py: no record of {args.results} has time_ms and {args.metric}", file=sys.stderr)
        return 1
    for w in written:
        print(w)
    return 0


if __name__ == "__main__":
    sys.exit(main())
