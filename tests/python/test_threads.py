"""Rendering from several Python threads: one GL context for the process, made current on
whichever thread renders, one render at a time; images equal the single-threaded ones."""
import threading

import numpy as np
import vct

from conftest import scene

REQUESTS = {
    "gtao": dict(ao="gtao", aovs=["ao", "beauty"], size=32),
    "vct": dict(ao="vct", gi="vct", aovs=["ao", "indirect"], size=32, voxel_res=16),
}


def run_threads(work):
    errors = []

    def guarded(name):
        try:
            work(name)
        except BaseException as e:  # reported by the main thread
            errors.append(e)

    threads = [threading.Thread(target=guarded, args=(name,)) for name in REQUESTS]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=600)
    assert not errors, errors


def test_two_threads_two_sessions_identical_images():
    path = scene("cornell_box.gltf")
    baseline = {name: vct.Session(path).render(**r) for name, r in REQUESTS.items()}
    results = {}

    def work(name):
        s = vct.Session(path)  # opened on this thread
        results[name] = [s.render(**REQUESTS[name]) for _ in range(3)]

    run_threads(work)
    for name, renders in results.items():
        for out in renders:
            for aov in REQUESTS[name]["aovs"]:
                assert np.array_equal(out[aov], baseline[name][aov]), (name, aov)


def test_two_threads_share_one_session():
    s = vct.Session(scene("cornell_box.gltf"))
    baseline = {name: s.render(**r) for name, r in REQUESTS.items()}
    results = {}

    def work(name):
        results[name] = [s.render(**REQUESTS[name]) for _ in range(3)]

    run_threads(work)
    for name, renders in results.items():
        for out in renders:
            for aov in REQUESTS[name]["aovs"]:
                assert np.array_equal(out[aov], baseline[name][aov]), (name, aov)
    # Everything was cached by the baseline: the threads only rendered from the caches.
    assert s.pass_run_counts()["gbuffer"] == 1


def test_session_dropped_on_another_thread():
    s = vct.Session(scene("cornell_box.gltf"))
    s.render(size=16)
    box = [s]
    del s
    t = threading.Thread(target=box.clear)  # the last reference dies on this thread
    t.start()
    t.join()
    assert vct.Session(scene("cornell_box.gltf")).render(size=16)["beauty"].shape == (16, 16, 3)
