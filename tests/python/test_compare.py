"""Session.compare: vct compare's records as Python objects, scored with the same metrics
vct.metrics offers."""
import json
import os

import numpy as np
import pytest
import vct

from conftest import scene

SIZE = 24
REF_SPP = 8


@pytest.fixture(scope="module")
def overhang():
    return vct.Session(scene("offscreen_overhang.gltf"))


@pytest.fixture(scope="module")
def records(overhang):
    return overhang.compare(methods=["gtao", "hbao[hbao.directions=4]"], ref_spp=REF_SPP, runs=1, size=SIZE)


def test_records(records):
    assert [r["label"] for r in records] == ["gtao", "hbao[hbao.directions=4]"]
    for r in records:
        assert r["kind"] == "ao"
        assert r["time_ms"] > 0 and r["rmse"] > 0
        assert r["roi_rmse"] is not None  # the scene marks an off-screen occluder
        assert {"mae", "bias", "max_abs", "psnr", "ssim", "pixels", "passes", "extra", "params"} <= set(r)
    assert records[1]["params"] == {"hbao.directions": "4"}


def test_record_rmse_equals_the_module_metrics(overhang, records):
    ref = overhang.render(ao="reference", aovs=["ao", "ao_stderr", "depth"], size=SIZE, spp=REF_SPP)
    gtao = overhang.render(ao="gtao", aovs=["ao"], size=SIZE)
    valid = ref["depth"] > 0
    assert vct.metrics.rmse(gtao["ao"], ref["ao"], valid) == pytest.approx(records[0]["rmse"], rel=1e-12)
    assert vct.metrics.ssim(gtao["ao"], ref["ao"], valid) == pytest.approx(records[0]["ssim"], rel=1e-12)


def test_full_document_and_files(overhang, tmp_path):
    doc = overhang.compare(methods=["alchemy"], gi=["vct"], ref_spp=4, runs=1, size=16, voxel_res=16,
                           full=True, output_dir=str(tmp_path))
    assert doc["width"] == 16 and doc["reference"]["spp"] == 4
    assert doc["reference"]["ao_mean_stderr"] > 0 and "gi_mean_stderr" in doc["reference"]
    assert [(r["kind"], r["method"]) for r in doc["records"]] == [("ao", "alchemy"), ("gi", "vct")]
    with open(os.path.join(tmp_path, "results.json")) as f:
        written = json.load(f)
    assert [r["label"] for r in written["records"]] == ["alchemy", "vct"]
    assert os.path.exists(os.path.join(tmp_path, "reference_ao_stderr.exr"))


def test_default_methods_are_every_scored_ao_method(overhang):
    records = overhang.compare(ref_spp=2, runs=1, size=8, voxel_res=8)
    expected = [m["name"] for m in vct.methods() if m["kind"] == "ao" and not m["ground_truth"]]
    assert [r["method"] for r in records] == expected


def test_dataframe(records, overhang):
    pd = pytest.importorskip("pandas")
    frame = vct.to_dataframe(records)
    assert isinstance(frame, pd.DataFrame) and list(frame["label"]) == ["gtao", "hbao[hbao.directions=4]"]
    assert isinstance(overhang.compare(methods=["gtao"], ref_spp=2, runs=1, size=8, dataframe=True), pd.DataFrame)
