"""Session.render: arrays of the right shape and type for every AOV, the stats document,
the reference's standard errors, cameras, and a session that keeps its G-buffers and
voxel grids between calls."""
import numpy as np
import pytest
import vct

from conftest import scene


def test_shapes_and_stats(cornell):
    out = cornell.render(ao="gtao", aovs=["beauty", "ao", "normal", "depth"], size=(40, 24))
    assert out["beauty"].shape == (24, 40, 3) and out["beauty"].dtype == np.float32
    assert out["normal"].shape == (24, 40, 3)
    assert out["ao"].shape == (24, 40) and out["depth"].shape == (24, 40)
    assert 0.0 <= out["ao"].min() and out["ao"].max() <= 1.0
    stats = out["stats"]
    assert stats["width"] == 40 and stats["height"] == 24
    assert stats["ao"] == "gtao" and stats["gi"] == "none"
    assert stats["total_ms"] > 0
    assert "gbuffer" in stats["passes_run"] and "ssao" in stats["passes_run"]
    assert all({"name", "wall_ms", "gpu_ms"} <= set(p) for p in stats["passes"])
    assert all({"pass", "reason"} <= set(s) for s in stats["passes_skipped"])
    assert stats["scene"]["path"].endswith("cornell_box.gltf")
    assert set(out) == {"beauty", "ao", "normal", "depth", "stats"}


def test_default_is_beauty_at_256(cornell):
    out = cornell.render(size=24)
    assert set(out) == {"beauty", "stats"}
    assert out["beauty"].shape == (24, 24, 3)


def test_reference_with_standard_errors(cornell):
    out = cornell.render(ao="reference", gi="reference", aovs=["ao", "ao_stderr", "indirect", "indirect_stderr"],
                         size=16, spp=4)
    assert out["ao_stderr"].shape == (16, 16) and (out["ao_stderr"] >= 0).all()
    assert out["ao_stderr"].max() > 0  # 4 samples: noisy somewhere
    assert out["indirect"].shape == (16, 16, 3)
    assert (out["indirect_stderr"] >= 0).all()
    assert out["stats"]["reference_ao"]["spp"] == 4


def test_cameras_by_name_index_and_dict(cornell):
    assert cornell.cameras == ["front"]
    by_name = cornell.render(aovs=["depth"], size=16, camera="front")["depth"]
    by_index = cornell.render(aovs=["depth"], size=16, camera=0)["depth"]
    default = cornell.render(aovs=["depth"], size=16)["depth"]
    assert np.array_equal(by_name, by_index) and np.array_equal(by_name, default)
    moved = cornell.render(aovs=["depth"], size=16, camera=dict(eye=[0, 1, 3.5], target=[0, 1, 0], fov=50))
    assert not np.array_equal(moved["depth"], default)


def test_seed_and_params_change_the_image(cornell):
    a = cornell.render(ao="reference", aovs=["ao"], size=16, spp=2, seed=1)["ao"]
    b = cornell.render(ao="reference", aovs=["ao"], size=16, spp=2, seed=2)["ao"]
    assert not np.array_equal(a, b)
    low = cornell.render(ao="gtao", aovs=["ao"], size=16, params={"gtao.preset": "low"})["ao"]
    ultra = cornell.render(ao="gtao", aovs=["ao"], size=16, params=["gtao.preset=ultra"])["ao"]
    assert not np.array_equal(low, ultra)


def test_two_methods_share_the_gbuffer_and_one_voxelization():
    s = vct.Session(scene("offscreen_overhang.gltf"))
    s.render(ao="vct", aovs=["ao"], size=24, voxel_res=32)
    s.render(ao="gtao", aovs=["ao"], size=24)
    assert s.pass_run_counts()["gbuffer"] == 1
    # The beauty reads the materials the AO-only renders' G-buffer left out: drawn again, whole.
    s.render(ao="vct", aovs=["ao", "beauty"], size=24, voxel_res=32)
    counts = s.pass_run_counts()
    assert counts["gbuffer"] == 2
    assert counts["voxelize"] == 1
    s.render(ao="vct", aovs=["ao"], size=24, voxel_res=16)
    assert s.pass_run_counts()["voxelize"] == 2


def test_params_read_from_a_cache_stay_known():
    # The second render finds the shadow maps and the voxel grid cached; its parameters are
    # the first one's, so they are no typo.
    s = vct.Session(scene("cornell_box.gltf"))
    kwargs = dict(ao="vct", aovs=["beauty"], size=16, voxel_res=16,
                  params={"shadow.size": 256, "vct.voxel.precision": "float"})
    first = s.render(**kwargs)["beauty"]
    second = s.render(**kwargs)["beauty"]
    assert np.array_equal(first, second)
    assert s.pass_run_counts()["voxelize"] == 1
    assert s.pass_run_counts()["shadow"] == 1
    s.render(**{**kwargs, "params": {"shadow.size": 512}})
    assert s.pass_run_counts()["shadow"] == 2
    # A key read by another method's render is still unknown to this one.
    with pytest.raises(ValueError, match="--param vct.voxel.precision: unknown parameter"):
        s.render(ao="gtao", aovs=["ao"], size=16, params={"vct.voxel.precision": "float"})
