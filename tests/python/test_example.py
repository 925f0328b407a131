"""docs/python_example.py runs (at a tiny size) and writes its figure."""
import os
import subprocess
import sys

import vct

from conftest import SOURCE_DIR


def test_example_writes_its_plot(tmp_path):
    out = os.path.join(tmp_path, "plot.png")
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.path.dirname(vct.__file__))
    p = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "docs", "python_example.py"),
                        "--scenes", os.path.join(SOURCE_DIR, "scenes", "offscreen_[os]*.gltf"),
                        "--methods", "gtao,vct", "--size", "16", "--ref-spp", "4", "--voxel-res", "16",
                        "-o", out], capture_output=True, text=True, env=env, timeout=600)
    assert p.returncode == 0, p.stderr
    assert "roi_rmse" in p.stdout
    with open(out, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
