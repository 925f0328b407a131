#!/usr/bin/env python3
"""The ray-traced AO reference against Blender Cycles' AO pass: same scene, view, size,
samples per pixel and radius, render time against render time, and the two images'
agreement.

    python3 bench/reference_vs_cycles.py [--size 512] [--spp 256] [--radius 1] [--out DIR]

Times, each from the renderer's own account, leaving out program start-up and scene load:
- Cycles: the span of its log from "Sample 0/N" to "Sample N/N" (sampling), and its log's
  frame "Time:" (sampling plus scene sync and BVH build);
- the reference: the passes of `vct render --stats` (reference_ao, plus bvh and the
  G-buffer that give the sampling its surface points), in both of its modes:
  `reference.pixel=center` (the default: every sample at the pixel's G-buffer point) and
  `reference.pixel=area` (the estimator Cycles runs: a jittered primary ray per sample,
  box filter).
Agreement: RMSE of reference against Cycles over the pixels Cycles sees a surface at (its
Combined alpha > 0; Cycles gives the sky AO 0, the reference 1).

Needs Blender (Debian: `apt-get install blender`; not a build or test dependency) and the
scene (default ../shared/scenes/mcguire_sponza.glb, or $VCT_SHARED_SCENES); prints a note
and exits 0 without them, as the other benchmarks do.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def sampling_seconds(log, spp):
    """Cycles' sampling time from its log: the first "Sample 0/N" line to "Sample N/N"."""
    def stamp(line):
        m = re.search(r"Time:(\d+):(\d+\.\d+)", line)
        return int(m.group(1)) * 60 + float(m.group(2)) if m else None
    start = end = None
    for line in log.splitlines():
        if start is None and re.search(r"\| Sample 0/%d\b" % spp, line):
            start = stamp(line)
        if re.search(r"\| Sample %d/%d\b" % (spp, spp), line):
            end = stamp(line)
    frame = re.findall(r"^ Time: (\d+):(\d+\.\d+)", log, re.M)
    total = int(frame[-1][0]) * 60 + float(frame[-1][1]) if frame else None
    return (end - start if start is not None and end is not None else None), total


def run_cycles(args, out):
    exr = os.path.join(out, "cycles.exr")
    cmd = ["blender", "-b", "--factory-startup", "--python", os.path.join(HERE, "cycles_ao.py"), "--",
           args.scene, str(args.size), str(args.spp), str(args.radius), exr, args.eye, args.target, str(args.fov)]
    log = subprocess.run(cmd, capture_output=True, text=True)
    with open(os.path.join(out, "cycles.log"), "w") as f:
        f.write(log.stdout + log.stderr)
    if log.returncode != 0 or not os.path.exists(exr):
        sys.exit("reference_vs_cycles: Blender failed (log: %s)" % os.path.join(out, "cycles.log"))
    sampling, frame = sampling_seconds(log.stdout, args.spp)
    return exr, sampling, frame


def run_reference(args, out, pixel):
    exr = os.path.join(out, "reference_%s.exr" % pixel)
    stats = os.path.join(out, "reference_%s.json" % pixel)
    cmd = [args.vct, "render", args.scene, "--eye", args.eye, "--target", args.target, "--fov", str(args.fov),
           "--ao", "reference", "--param", "reference.pixel=" + pixel, "--radius", str(args.radius),
           "--spp", str(args.spp), "--size", str(args.size), "--aov", "ao", "-o", exr, "--stats", stats]
    subprocess.run(cmd, check=True, capture_output=True)
    with open(stats) as f:
        passes = {p["name"]: p["wall_ms"] / 1000.0 for p in json.load(f)["passes"]}
    return exr, passes


def agreement(cycles_exr, reference_exr):
    import numpy as np
    import OpenImageIO as oiio
    c = oiio.ImageBuf(cycles_exr)
    names = list(c.spec().channelnames)
    pixels = c.get_pixels(oiio.FLOAT)
    ao = pixels[..., names.index("ViewLayer.AO.R")]
    alpha = pixels[..., names.index("ViewLayer.Combined.A")]
    r = oiio.ImageBuf(reference_exr).get_pixels(oiio.FLOAT)[..., 0]
    seen = alpha > 0
    d = (r - ao)[seen]
    return float(np.sqrt(np.mean(d * d))), float(np.mean(d)), float(ao[seen].mean()), float(r[seen].mean())


def main():
    scenes = os.environ.get("VCT_SHARED_SCENES", os.path.join(ROOT, "..", "shared", "scenes"))
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scene", default=os.path.join(scenes, "mcguire_sponza.glb"))
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--radius", type=float, default=1.0)
    p.add_argument("--eye", default="-11,1.8,0.5")
    p.add_argument("--target", default="4,3.5,-0.5")
    p.add_argument("--fov", type=float, default=60.0)
    p.add_argument("--vct", default=os.path.join(ROOT, "build", "vct"))
    p.add_argument("--out", default=os.path.join(ROOT, "out", "reference_vs_cycles"))
    args = p.parse_args()
    if not os.path.exists(args.scene):
        print("reference_vs_cycles: %s not found; skipped" % args.scene)
        return
    if shutil.which("blender") is None:
        print("reference_vs_cycles: no blender on PATH (Debian: apt-get install blender); skipped")
        return
    # The comparison reads the EXRs with numpy and OpenImageIO: say so before Cycles' minutes.
    try:
        import numpy  # noqa: F401
        import OpenImageIO  # noqa: F401
    except ImportError as e:
        sys.exit("reference_vs_cycles: %s under %s (Debian: apt-get install python3-numpy "
                 "python3-openimageio, and run it with /usr/bin/python3)" % (e, sys.executable))
    os.makedirs(args.out, exist_ok=True)
    print("%s, %d^2, %d spp, R = %g, eye %s, target %s, fov %g, %d cores" %
          (os.path.basename(args.scene), args.size, args.spp, args.radius, args.eye, args.target, args.fov,
           os.cpu_count()))
    cycles_exr, sampling, frame = run_cycles(args, args.out)
    print("| renderer | render s | Cycles / it | RMSE vs Cycles | bias | mean AO |")
    print("|---|---:|---:|---:|---:|---:|")
    print("| Cycles AO pass, sampling (log: Sample 0 to %d) | %.2f | 1.0 | | | |" % (args.spp, sampling))
    print("| Cycles, frame (log: Time, with sync and BVH) | %.2f | | | | |" % frame)
    for pixel in ("center", "area"):
        exr, passes = run_reference(args, args.out, pixel)
        render = passes.get("reference_ao", 0.0)
        whole = render + passes.get("bvh", 0.0) + passes.get("gbuffer", 0.0)
        rmse, bias, cycles_mean, mean = agreement(cycles_exr, exr)
        print("| reference, pixel=%s (reference_ao pass) | %.2f | %.1f | %.4f | %+.4f | %.4f |" %
              (pixel, render, sampling / render, rmse, bias, mean))
        print("| reference, pixel=%s, with bvh and G-buffer | %.2f | %.1f | | | |" % (pixel, whole, frame / whole))
    print("(Cycles' mean AO over the same pixels: %.4f; images and logs in %s)" % (cycles_mean, args.out))


if __name__ == "__main__":
    main()
