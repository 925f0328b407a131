#!/usr/bin/env python3
"""The off-screen occluder study from Python: a few AO methods scored against the
ray-traced reference on every scenes/offscreen_*.gltf, and their error plotted against
their time (everywhere, and inside the region the hidden occluders darken).

    cmake --build build -j2
    PYTHONPATH=build/python /usr/bin/python3 docs/python_example.py -o out/python_example.png

About 15 s on 2 cores with llvmpipe at the defaults; --size 32 --ref-spp 16 for a
quick look."""
import argparse
import glob
import os

import matplotlib

matplotlib.use("Agg")  # no display needed: the figure goes to a file
import matplotlib.pyplot as plt

import vct

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scenes", default=os.path.join(HERE, "..", "scenes", "offscreen_*.gltf"))
    p.add_argument("--methods", default="alchemy,hbao,gtao,vct", help="AO methods, comma-separated")
    p.add_argument("--size", type=int, default=128)
    p.add_argument("--ref-spp", type=int, default=64)
    p.add_argument("--runs", type=int, default=3, help="timed runs per method (the median is plotted)")
    p.add_argument("--voxel-res", type=int, default=64)
    p.add_argument("-o", "--output", default="out/python_example.png")
    a = p.parse_args()

    methods = a.methods.split(",")
    rows = []  # (scene, record)
    renderer = ""
    for path in sorted(glob.glob(a.scenes)):
        name = os.path.splitext(os.path.basename(path))[0]
        session = vct.Session(path)
        # One G-buffer and one reference for every method of the scene.
        doc = session.compare(methods=methods, ref_spp=a.ref_spp, runs=a.runs, size=a.size,
                              voxel_res=a.voxel_res, full=True)
        renderer = doc["gl_renderer"].split(" (")[0]
        for r in doc["records"]:
            rows.append((name, r))
            roi = "-" if r["roi_rmse"] is None else f"{r['roi_rmse']:.4f}"
            print(f"{name:28s} {r['label']:10s} {r['time_ms']:9.1f} ms  rmse {r['rmse']:.4f}  roi_rmse {roi}")
    if not rows:
        raise SystemExit(f"no scene matches {a.scenes}")

    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharex=True)
    for ax, key, title in ((axes[0], "rmse", "all valid pixels"), (axes[1], "roi_rmse", "inside the ROI")):
        for i, method in enumerate(methods):
            pts = [(r["time_ms"], r[key]) for _, r in rows if r["method"] == method and r[key] is not None]
            if pts:
                ax.scatter(*zip(*pts), color=f"C{i}", label=method)
        ax.set_xscale("log")
        ax.set_xlabel(f"time per frame (ms, {renderer})")
        ax.set_ylabel("AO RMSE against the reference")
        ax.set_title(title)
        ax.grid(True, alpha=0.3)
    axes[0].legend()
    scenes = len({s for s, _ in rows})
    fig.suptitle(f"off-screen occluders: one point per method and scene ({scenes} scenes), "
                 f"{a.size}x{a.size}, reference {a.ref_spp} spp")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
    fig.savefig(a.output, dpi=120)
    print("wrote", a.output)


if __name__ == "__main__":
    main()
