"""vct.metrics: src/eval's metrics and ROI on NumPy arrays."""
import math

import numpy as np
import pytest
import vct


def test_rmse_with_and_without_mask():
    ref = np.zeros((2, 2), np.float32)
    est = np.array([[0, 1], [0, 0]], np.float32)
    assert vct.metrics.rmse(est, ref) == pytest.approx(0.5)
    mask = np.array([[1, 0], [1, 1]], bool)
    assert vct.metrics.rmse(est, ref, mask) == 0.0
    assert vct.metrics.rmse(est.astype(np.float64), ref.tolist()) == pytest.approx(0.5)


def test_channels():
    ref = np.zeros((4, 4, 3), np.float32)
    est = ref.copy()
    est[:, :, 1] = 0.3
    assert vct.metrics.rmse(est, ref, channel=0) == 0.0
    assert vct.metrics.rmse(est, ref, channel=1) == pytest.approx(0.3)
    assert vct.metrics.rmse(est, ref) == pytest.approx(0.3 / math.sqrt(3))


def test_ssim_and_error_metrics():
    rng = np.random.default_rng(1)
    a = rng.random((24, 24), dtype=np.float32)
    assert vct.metrics.ssim(a, a) == pytest.approx(1.0)
    b = np.clip(a + rng.normal(0, 0.2, a.shape), 0, 1).astype(np.float32)
    assert vct.metrics.ssim(b, a) < 0.9
    m = vct.metrics.error_metrics(b, a)
    assert set(m) == {"rmse", "mae", "bias", "max_abs", "psnr", "ssim", "pixels"}
    assert m["pixels"] == 24 * 24
    assert m["rmse"] == pytest.approx(float(np.sqrt(np.mean((b.astype(np.float64) - a) ** 2))), rel=1e-6)
    assert m["ssim"] == pytest.approx(vct.metrics.ssim(b, a))
    assert vct.metrics.error_metrics(a, a)["psnr"] == 200.0


def test_roi():
    with_ = np.full((8, 8), 0.5, np.float32)
    without = with_.copy()
    without[2:4, 2:4] = 0.9
    se = np.full((8, 8), 0.01, np.float32)
    roi = vct.metrics.roi(with_, without, se, se)
    assert roi.shape == (8, 8) and roi.dtype == np.float32
    assert roi.sum() == 4 and roi[2:4, 2:4].all()
    assert vct.metrics.roi(with_, without, se * 100, se * 100).sum() == 0


def test_bad_input_is_a_value_error():
    a = np.zeros((4, 4), np.float32)
    with pytest.raises(ValueError):
        vct.metrics.rmse(a, np.zeros((4, 5), np.float32))
    nan = a.copy()
    nan[1, 1] = np.nan
    with pytest.raises(ValueError, match="NaN|finite"):
        vct.metrics.rmse(nan, a)
    with pytest.raises(ValueError):
        vct.metrics.rmse(np.zeros(4), np.zeros(4))
    with pytest.raises(ValueError):
        vct.metrics.roi(a, a, a - 1, a)
    with pytest.raises(TypeError):
        vct.metrics.rmse("a", a)
