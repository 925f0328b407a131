"""Bad input raises a Python exception of the command line's kind with its message:
ValueError where `vct` exits with 2, RuntimeError where it exits with 1; the process and the
session survive every one of them."""
import os

import pytest
import vct

from conftest import cli_error, scene

CORNELL = scene("cornell_box.gltf")

# (Session.render keyword arguments, the same request's vct render options)
USAGE_ERRORS = [
    (dict(ao="bogus"), ["--ao", "bogus"]),
    (dict(gi="gtao"), ["--gi", "gtao"]),
    (dict(backend="cuda"), ["--backend", "cuda"]),
    (dict(aovs=["beauty", "bogus"]), ["--aov", "beauty,bogus"]),
    (dict(aovs=["ao"]), ["--aov", "ao"]),  # AO requested without an AO method
    (dict(ao="gtao", params={"gtao.slices": "abc"}), ["--ao", "gtao", "--param", "gtao.slices=abc"]),
    (dict(ao="gtao", params={"gtao.slices": 100000}), ["--ao", "gtao", "--param", "gtao.slices=100000"]),
    (dict(ao="gtao", params={"gtao.no-such-key": 1}), ["--ao", "gtao", "--param", "gtao.no-such-key=1"]),
    (dict(ao="gtao", params=["gtao.slices"]), ["--ao", "gtao", "--param", "gtao.slices"]),
    (dict(radius=-1.0), ["--radius", "-1"]),
    (dict(spp=0), ["--spp", "0"]),
    (dict(voxel_res=2), ["--voxel-res", "2"]),
    (dict(camera="no-such-camera"), ["--camera", "no-such-camera"]),
    (dict(camera=7), ["--camera", "7"]),
    (dict(camera=dict(eye=(1, 1, 1), target=(1, 1, 1))), ["--eye", "1,1,1", "--target", "1,1,1"]),
]


@pytest.fixture(scope="module")
def session():
    return vct.Session(CORNELL)


@pytest.mark.parametrize("kwargs,cli", USAGE_ERRORS, ids=[" ".join(c) for _, c in USAGE_ERRORS])
def test_usage_errors_are_value_errors_with_the_cli_message(tmp_path, session, kwargs, cli):
    code, message = cli_error("render", CORNELL, "--size", "16", "-o", os.path.join(tmp_path, "x.png"), *cli)
    assert code == 2
    with pytest.raises(ValueError) as e:
        session.render(size=16, **kwargs)
    assert str(e.value) == message


def test_size_zero_is_a_value_error(session):
    for size in (0, (16, 0), (-3, 16), (20000, 16)):
        with pytest.raises(ValueError, match="--size"):
            session.render(size=size)
    code, _ = cli_error("render", CORNELL, "--size", "0", "-o", "x.png")
    assert code == 2


def test_eye_without_target(session):
    with pytest.raises(ValueError, match="--eye and --target go together"):
        session.render(size=16, camera=dict(eye=(0, 1, 3)))


def test_wrong_argument_shapes_are_type_errors(session):
    for kwargs in (dict(size="big"), dict(size=(1, 2, 3)), dict(camera=1.5), dict(aovs=[1]),
                   dict(params=3), dict(camera=dict(eye=(0, 1), target=(0, 0, 0)))):
        with pytest.raises(TypeError):
            session.render(**kwargs)
    with pytest.raises(ValueError, match="unknown key 'up'"):
        session.render(camera=dict(up=(0, 1, 0)))


def test_missing_scene_is_a_runtime_error_with_the_cli_message(tmp_path):
    missing = os.path.join(tmp_path, "no-such-scene.gltf")
    code, message = cli_error("render", missing, "-o", os.path.join(tmp_path, "x.png"))
    assert code == 1
    with pytest.raises(RuntimeError) as e:
        vct.Session(missing)
    assert str(e.value) == message


def test_invalid_scene_is_a_runtime_error(tmp_path):
    bad = os.path.join(tmp_path, "bad.gltf")
    with open(bad, "w") as f:
        f.write('{"asset": {"version": "2.0"}, "accessors": [{"count": 3}]')
    code, message = cli_error("render", bad, "-o", os.path.join(tmp_path, "x.png"))
    assert code == 1
    with pytest.raises(RuntimeError) as e:
        vct.Session(bad)
    assert str(e.value) == message


def test_bad_gl_device_is_a_value_error():
    with pytest.raises(ValueError, match="gl-device"):
        vct.Session(CORNELL, gl_device="tpu")


COMPARE_ERRORS = [
    (dict(runs=0), ["--runs", "0"]),
    (dict(ref_spp=0), ["--ref-spp", "0"]),
    (dict(methods=["reference"]), ["--methods", "reference"]),
    (dict(methods=["gtao[gtao.slices]"]), ["--methods", "gtao[gtao.slices]"]),
    (dict(methods=[], gi=[]), ["--methods", ""]),
]


@pytest.mark.parametrize("kwargs,cli", COMPARE_ERRORS, ids=[" ".join(c) for _, c in COMPARE_ERRORS])
def test_compare_usage_errors(tmp_path, session, kwargs, cli):
    code, message = cli_error("compare", CORNELL, "--size", "16", "-o", os.path.join(tmp_path, "cmp"), *cli)
    assert code == 2
    with pytest.raises(ValueError) as e:
        session.compare(size=16, **kwargs)
    assert str(e.value) == message


def test_session_still_renders_after_errors(session):
    with pytest.raises(ValueError):
        session.render(ao="bogus")
    out = session.render(ao="gtao", aovs=["ao"], size=16)
    assert out["ao"].shape == (16, 16)
