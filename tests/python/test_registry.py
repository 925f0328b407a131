"""vct.methods(), vct.settings() and vct.aovs() come from the registry: they list what the
command line accepts, and every method listed renders."""
import re
import subprocess

import pytest
import vct

from conftest import BINARY, cli_error, scene


def test_methods_carry_kind_summary_and_settings():
    methods = vct.methods()
    assert {m["kind"] for m in methods} == {"ao", "gi"}
    for m in methods:
        assert m["name"] and m["summary"], m
        for s in m["settings"]:
            assert set(s) == {"key", "default", "range", "doc"}, s
    names = {(m["kind"], m["name"]) for m in methods}
    assert {("ao", "gtao"), ("ao", "vct"), ("ao", "reference"), ("gi", "vct"), ("gi", "reference")} <= names
    assert [m["name"] for m in methods if m["ground_truth"]] == ["reference", "reference"]


def test_method_names_match_the_cli():
    # The command line lists the names it accepts when it rejects one.
    for kind in ("ao", "gi"):
        _, message = cli_error("render", scene("cornell_box.gltf"), "--" + kind, "bogus", "-o", "x.png")
        cli = message.split("expected one of ")[1].split(", ")
        assert cli == ["none"] + [m["name"] for m in vct.methods() if m["kind"] == kind]


def test_settings_equal_help_params():
    text = subprocess.run([BINARY, "render", "--help-params"], capture_output=True, text=True).stdout
    cli = {}
    for line in text.splitlines()[1:]:
        m = re.match(r"  (\S+)  default (.*?)  range (.*?)(?:  (.*))?$", line)
        assert m, line
        cli[m.group(1)] = (m.group(2), m.group(3), m.group(4) or "")
    ours = {s["key"]: (s["default"], s["range"], s["doc"]) for s in vct.settings()}
    assert ours == cli
    per_method = {s["key"] for m in vct.methods() for s in m["settings"]}
    assert per_method <= set(ours)
    assert "shadow.size" in ours  # the renderer's own


def test_aovs_list_the_methods_outputs():
    aovs = {a["name"]: a["channels"] for a in vct.aovs()}
    assert aovs["beauty"] == 3 and aovs["ao"] == 1
    assert "ao_stderr" in aovs and "indirect_stderr" in aovs
    for m in vct.methods():
        for a in m["aovs"]:
            assert aovs[a["name"]] == a["channels"]


@pytest.mark.parametrize("kind", ["ao", "gi"])
def test_every_method_renders(kind):
    s = vct.Session(scene("cornell_box.gltf"))
    for m in vct.methods():
        if m["kind"] != kind:
            continue
        aov = "ao" if kind == "ao" else "indirect"
        out = s.render(**{kind: m["name"]}, aovs=[aov], size=16, spp=2, voxel_res=16)
        assert out[aov].shape[:2] == (16, 16), m["name"]
