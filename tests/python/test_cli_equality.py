"""The module's images equal the command line's for the same request, bit for bit: the CLI
writes an EXR (32-bit float, lossless), OpenImageIO's Python binding reads it, and every
AOV is compared as raw float32 bits with what Session.render returned."""
import os

import numpy as np
import OpenImageIO as oiio
import pytest
import vct

from conftest import run_cli, scene


def cli_args(kwargs):
    """The vct render options of a Session.render call."""
    args = []
    for key, value in kwargs.items():
        if key == "aovs":
            args += ["--aov", ",".join(value)]
        elif key == "size":
            args += ["--size", f"{value[0]}x{value[1]}" if isinstance(value, tuple) else str(value)]
        elif key == "camera" and isinstance(value, dict):
            args += ["--eye", ",".join(map(repr, value["eye"])), "--target", ",".join(map(repr, value["target"]))]
            if "fov" in value:
                args += ["--fov", repr(value["fov"])]
        elif key == "params":
            for k, v in value.items():
                args += ["--param", f"{k}={v}"]
        else:
            args += ["--" + key.replace("_", "-"), str(value)]
    return args


def read_exr(path):
    """{channel name: HxW float32 array} of an EXR file."""
    inp = oiio.ImageInput.open(path)
    assert inp, oiio.geterror()
    names = list(inp.spec().channelnames)
    pixels = inp.read_image(oiio.FLOAT)
    inp.close()
    return {name: np.ascontiguousarray(pixels[:, :, c]) for c, name in enumerate(names)}


def channels_of(aov, array):
    """The EXR channel names the CLI writes for one AOV, with the module's planes."""
    if array.ndim == 2:
        return {aov: array}
    names = ["R", "G", "B"] if aov == "beauty" else [f"{aov}.{c}" for c in "RGB"]
    return {name: np.ascontiguousarray(array[:, :, c]) for c, name in enumerate(names)}


CASES = [
    ("cornell_box.gltf", dict(ao="gtao", aovs=["beauty", "ao", "normal", "depth"], size=(48, 32), radius=0.5,
                              params={"gtao.slices": 3})),
    ("cornell_box.gltf", dict(gi="vct", aovs=["beauty", "indirect", "direct"], size=32, voxel_res=32)),
    ("offscreen_overhang.gltf", dict(ao="reference", aovs=["ao", "ao_stderr"], size=32, spp=8, seed=3)),
    ("default.gltf", dict(ao="vct", aovs=["beauty", "ao"], size=(40, 24), voxel_res=32, sky=0.5,
                          camera=dict(eye=(4.0, 3.0, 6.0), target=(0.0, 0.5, 0.0), fov=40.0))),
]


@pytest.mark.parametrize("scene_name,kwargs", CASES, ids=[f"{s}:{k.get('ao', k.get('gi'))}" for s, k in CASES])
def test_module_images_equal_cli_exr(tmp_path, scene_name, kwargs):
    exr = os.path.join(tmp_path, "cli.exr")
    code, err = run_cli("render", scene(scene_name), "-o", exr, *cli_args(kwargs))
    assert code == 0, err
    from_cli = read_exr(exr)

    out = vct.Session(scene(scene_name)).render(**kwargs)
    planes = {}
    for aov in kwargs["aovs"]:
        assert out[aov].dtype == np.float32
        planes.update(channels_of(aov, out[aov]))
    assert sorted(planes) == sorted(from_cli)
    for name, plane in planes.items():
        assert plane.shape == from_cli[name].shape, name
        same = plane.view(np.uint32) == from_cli[name].view(np.uint32)
        assert same.all(), f"{name}: {np.count_nonzero(~same)} pixels differ"
