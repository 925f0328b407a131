"""help() shows the module's docstrings and argument names."""
import pydoc

import vct


def text(obj):
    return pydoc.render_doc(obj, renderer=pydoc.plaintext)


def test_session_help():
    doc = text(vct.Session)
    assert "One glTF scene, loaded once" in doc
    for needle in ("render(self", "ao: str = 'none'", "aovs", "voxel_res", "Renders one view",
                   "compare(self", "ref_spp", "pass_run_counts", "scene_path: str"):
        assert needle in doc, needle


def test_module_and_metrics_help():
    doc = text(vct)
    assert "ValueError" in doc and "methods(" in doc and "to_dataframe" in doc
    m = text(vct.metrics)
    for needle in ("rmse(estimate", "ssim(estimate", "roi(ao_with", "error_metrics("):
        assert needle in m, needle
