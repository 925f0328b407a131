#!/usr/bin/env python3
"""Regenerates docs/results.md and docs/results/*.svg from the committed sweep spec.

    python3 scripts/make_results.py [--vct build/vct] [--spec sweeps/study.json]
                                    [--work out/results-study] [--resume]

Steps: probe which methods of the spec this build can run (a 16x16 render each; the others are
left out and listed in the report), write the runnable spec to WORK/study.json, `vct sweep` it
into WORK/sweep (from scratch unless --resume), `vct merge` into WORK/merged, plot error against
time (scripts/plot_pareto.py) into docs/results/, and write the tables to docs/results.md; then the
sequence study (scripts/sequence_study.py, sweeps/sequences.json): `vct compare --path` per case,
its tables and per-frame plots appended (`--sequences-only` reruns just that section).
Run from the repository root (`make results` does).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import plot_pareto  # noqa: E402  (after the path tweak)
import sequence_study  # noqa: E402

SEQ_BEGIN, SEQ_END = "<!-- sequences: begin -->", "<!-- sequences: end -->"


def sequence_section(args, vct, work, plot_dir, docs_dir):
    """The sequence study's markdown, between markers (so --sequences-only can replace it)."""
    with open(os.path.join(REPO, args.sequences)) as f:
        spec = json.load(f)
    for name in os.listdir(plot_dir) if os.path.isdir(plot_dir) else []:
        if name.startswith("seq_") and name.endswith(".svg"):
            os.remove(os.path.join(plot_dir, name))
    cases = sequence_study.run_cases(vct, spec, os.path.join(work, "sequences"), args.resume)
    plots = sequence_study.plot(cases, plot_dir)
    return [SEQ_BEGIN] + sequence_study.markdown(cases, plots, docs_dir, "make results") + [SEQ_END]


def run(cmd, **kw):
    print("+ " + " ".join(cmd), flush=True)
    return subprocess.run(cmd, cwd=REPO, **kw)


def probe(vct, kind, method, tmp):
    """None if `vct render` runs the method, else the error line."""
    out = os.path.join(tmp, f"probe_{kind}_{method}.png")
    flag = "--ao" if kind == "ao" else "--gi"
    r = subprocess.run([vct, "render", "scenes/cornell_box.gltf", "--size", "16", flag, method, "-o", out],
                       cwd=REPO, capture_output=True, text=True)
    if r.returncode == 0:
        return None
    lines = [l for l in (r.stderr + r.stdout).splitlines() if l.strip()]
    return lines[-1] if lines else f"exit code {r.returncode}"


def runnable_spec(spec, vct, tmp):
    """The spec without the methods this build cannot run, and {kind/method: reason}."""
    dropped = {}
    cache = {}

    def keep(m):
        key = (m.get("kind", "ao"), m["method"])
        if key not in cache:
            cache[key] = probe(vct, key[0], key[1], tmp)
            if cache[key]:
                dropped[f"{key[0]} {key[1]}"] = cache[key]
        return cache[key] is None

    spec = json.loads(json.dumps(spec))
    if "methods" in spec:
        spec["methods"] = [m for m in spec["methods"] if keep(m)]
    scenes = []
    for s in spec["scenes"]:
        if isinstance(s, dict) and "methods" in s:
            s["methods"] = [m for m in s["methods"] if keep(m)]
            if not s["methods"]:
                dropped[f"scene {s['path']}"] = "none of its methods runs in this build"
                continue
        scenes.append(s)
    spec["scenes"] = scenes
    if not spec.get("methods"):
        spec.pop("methods", None)
        spec["scenes"] = [s for s in scenes if isinstance(s, dict) and s.get("methods")]
    return spec, dropped


def fmt(v, digits=4):
    if v is None:
        return "–"
    if isinstance(v, bool):
        return "yes" if v else ""
    if isinstance(v, float):
        return f"{v:.{digits}f}"
    return str(v)


def params_text(r):
    p = r.get("params") or {}
    return ", ".join(f"`{k}={v}`" for k, v in sorted(p.items())) or "defaults"


def case_section(doc, records, plot_dir_rel):
    c = doc["case"]
    ref = doc.get("reference", {})
    kind = records[0]["kind"]
    lines = [f"### {c['id']}", ""]
    cam = doc.get("camera", {})
    eye = ", ".join(f"{x:.2f}" for x in cam.get("eye", []))
    target = ", ".join(f"{x:.2f}" for x in cam.get("target", []))
    scene = doc["scene"]
    if os.path.isabs(scene) and scene.startswith(REPO + os.sep):
        scene = os.path.relpath(scene, REPO)
    lines.append(f"Scene `{scene}`, camera {c['camera']['label']} (eye {eye}, target {target}, "
                 f"fov {cam.get('fov_deg', 0):.0f}°), {doc['width']}x{doc['height']}, R = {doc['radius']:g}, "
                 f"voxel_res {doc.get('voxel_res')}, sky {doc.get('sky')}.  ")
    if kind == "ao":
        lines.append(f"Reference AO: {ref.get('spp')} spp, RMS per-pixel standard error "
                     f"{fmt(ref.get('ao_rms_pixel_stderr'))}, {fmt(ref.get('ao_time_ms'), 0)} ms.  ")
        roi = doc.get("roi_pixels")
        lines.append(f"ROI (pixels whose reference AO changes when the off-screen occluders are removed): "
                     f"{roi if roi is not None else 'none (no off-screen occluders)'} of "
                     f"{records[0].get('pixels')} valid pixels.")
    else:
        lines.append(f"Reference GI: {ref.get('spp')} spp, {ref.get('gi_bounces')} bounces, RMS per-pixel standard "
                     f"error {fmt(ref.get('gi_rms_pixel_stderr'))}, {fmt(ref.get('gi_time_ms'), 0)} ms; "
                     f"errors are relative to the reference's peak.  ")
        roi = doc.get("roi_pixels_gi")
        lines.append(f"ROI (pixels whose reference indirect light changes when the off-screen surfaces are "
                     f"removed): {roi if roi is not None else 'none (no off-screen surfaces)'} of "
                     f"{records[0].get('pixels')} valid pixels.")
    lines += ["", "| method | params | time (ms) | frame (ms) | rmse | roi_rmse | nonroi_rmse | ssim | Pareto |",
              "|---|---|---:|---:|---:|---:|---:|---:|:---:|"]
    for r in sorted(records, key=lambda r: r["time_ms"]):
        front = "●" if r.get("pareto") else ""
        if r.get("pareto_roi"):
            front += " (roi ●)"
        lines.append(f"| {r['method']} | {params_text(r)} | {fmt(r['time_ms'], 2)} | {fmt(r.get('frame_ms'), 2)} | {fmt(r['rmse'])} | "
                     f"{fmt(r.get('roi_rmse'))} | {fmt(r.get('nonroi_rmse'))} | {fmt(r.get('ssim'), 3)} | {front} |")
    lines.append("")
    return lines


def write_markdown(merged, plots, dropped, spec_path, out_path, command):
    records = merged["records"]
    cases = merged["cases"]
    renderer = records[0]["gl_renderer"] if records else "?"
    cores = cases[0].get("cores") if cases else "?"
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=REPO, capture_output=True,
                                text=True).stdout.strip()
    except OSError:
        commit = ""
    L = ["# Results: screen-space vs world-space AO and GI, against the ray tracer", "",
         f"Generated by `{command}` (`python3 scripts/make_results.py`) from [`{spec_path}`](../{spec_path}) "
         f"(sweep format: [sweeps.md](sweeps.md)); do not edit by hand.  ",
         f"Machine: GL renderer **{renderer}**, {cores} cores" + (f", commit `{commit}`" if commit else "") +
         f"; {cases[0].get('timing_runs') if cases else '?'} timed runs per variant.  ",
         "Times are wall-clock per frame on this renderer (median of the timed runs after a warm-up, "
         "including the method's own passes and the G-buffer a moved camera draws again; see `vct compare`), "
         "so they rank methods on a CPU rasterizer "
         "and say little about a GPU. Errors are against the Embree reference at the same G-buffer points; "
         "differences below about twice the reference's standard error are noise.", ""]
    if dropped:
        L += ["Left out because this build cannot run them yet:", ""]
        L += [f"- {k}: {v}" for k, v in sorted(dropped.items())]
        L += [""]
    # Summary: per case, the best variant per method family and the most accurate overall.
    L += ["## Summary", "",
          "Per case: the most accurate variant overall and on the ROI, and the fastest variant on the "
          "Pareto front.", "",
          "| case | kind | lowest rmse | lowest roi_rmse | fastest on the front |", "|---|---|---|---|---|"]
    by_case = {}
    for r in records:
        by_case.setdefault((r["case"], r["kind"]), []).append(r)
    for (case, kind), recs in by_case.items():
        best = min(recs, key=lambda r: r["rmse"])
        roi = [r for r in recs if isinstance(r.get("roi_rmse"), (int, float))]
        best_roi = min(roi, key=lambda r: r["roi_rmse"]) if roi else None
        front = [r for r in recs if r.get("pareto")]
        fastest = min(front, key=lambda r: r["time_ms"]) if front else None
        L.append(f"| {case} | {kind} | {best['label']} ({fmt(best['rmse'])}) | "
                 + (f"{best_roi['label']} ({fmt(best_roi['roi_rmse'])})" if best_roi else "–") + " | "
                 + (f"{fastest['label']} ({fmt(fastest['time_ms'], 2)} ms, rmse {fmt(fastest['rmse'])})"
                    if fastest else "–") + " |")
    L += ["", "## Error against time", ""]
    for p in plots:
        rel = os.path.relpath(p, os.path.dirname(out_path))
        L += [f"![{os.path.basename(p)}]({rel})", ""]
    L += ["## Per case", ""]
    for doc in cases:
        recs = [r for r in records if r["case"] == doc["case"]["id"]]
        for kind in ("ao", "gi"):
            mine = [r for r in recs if r["kind"] == kind]
            if mine:
                L += case_section(doc, mine, "results")
    if any("sponza" in d["case"]["id"] for d in cases):
        L += ["Sponza: Dabrovic Sponza by Marko Dabrovic, fixes by Kenzie Lamar, McGuire Computer Graphics "
              "Archive (CC BY-NC).", ""]
    with open(out_path, "w") as f:
        f.write("\n".join(L))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--vct", default="build/vct")
    ap.add_argument("--spec", default="sweeps/study.json")
    ap.add_argument("--work", default="out/results-study")
    ap.add_argument("--docs", default="docs")
    ap.add_argument("--resume", action="store_true", help="keep WORK/sweep and run only the missing cases")
    ap.add_argument("--sequences", default="sweeps/sequences.json", help="the camera-path cases")
    ap.add_argument("--sequences-only", action="store_true",
                    help="rerun only the sequence study and replace its section of results.md")
    args = ap.parse_args()
    plot_pareto._import_matplotlib()  # may re-exec under /usr/bin/python3: do it before any work
    vct = os.path.abspath(os.path.join(REPO, args.vct))
    work = os.path.join(REPO, args.work)
    plot_dir = os.path.join(REPO, args.docs, "results")
    out = os.path.join(REPO, args.docs, "results.md")
    if args.sequences_only:
        with open(out) as f:
            text = f.read()
        section = "\n".join(sequence_section(args, vct, work, plot_dir, os.path.dirname(out)))
        if SEQ_BEGIN in text and SEQ_END in text:
            text = text[:text.index(SEQ_BEGIN)] + section + text[text.index(SEQ_END) + len(SEQ_END):]
        else:
            text = text.rstrip("\n") + "\n\n" + section + "\n"
        with open(out, "w") as f:
            f.write(text)
        print(f"make_results: replaced the sequence section of {os.path.relpath(out, REPO)}")
        return
    sweep_dir, merged_dir = os.path.join(work, "sweep"), os.path.join(work, "merged")
    if not args.resume and os.path.exists(sweep_dir):
        shutil.rmtree(sweep_dir)
    os.makedirs(work, exist_ok=True)

    with open(os.path.join(REPO, args.spec)) as f:
        spec = json.load(f)
    spec, dropped = runnable_spec(spec, vct, work)
    for k, v in dropped.items():
        print(f"make_results: leaving out {k}: {v}")
    # WORK lies inside the repository, so the derived spec's relative scene paths still
    # resolve against the repository (and ${shared} beside it).
    derived = os.path.join(work, "study.json")
    with open(derived, "w") as f:
        json.dump(spec, f, indent=2)
    if run([vct, "sweep", derived, "-o", sweep_dir, "--no-images"]).returncode != 0:
        sys.exit("make_results: vct sweep failed")
    if run([vct, "merge", sweep_dir, "-o", merged_dir]).returncode != 0:
        sys.exit("make_results: vct merge failed")
    merged_json = os.path.join(merged_dir, "results.json")
    if os.path.isdir(plot_dir):
        for name in os.listdir(plot_dir):
            if name.endswith(".svg") and not name.startswith("seq_"):
                os.remove(os.path.join(plot_dir, name))
    plots = plot_pareto.plot_all(merged_json, plot_dir, "rmse")
    plots += plot_pareto.plot_all(merged_json, plot_dir, "roi_rmse")
    with open(merged_json) as f:
        merged = json.load(f)
    write_markdown(merged, plots, dropped, args.spec, out, "make results")
    with open(out, "a") as f:
        f.write("\n" + "\n".join(sequence_section(args, vct, work, plot_dir, os.path.dirname(out))) + "\n")
    print(f"make_results: wrote {os.path.relpath(out, REPO)} and {len(plots)} plots in "
          f"{os.path.relpath(plot_dir, REPO)}")


if __name__ == "__main__":
    main()
