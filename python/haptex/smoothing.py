"""The smoothed training targets of `haptex train` (`--target-smoothing`, default 7), as
predict/target_smoothing.cpp computes them (docs/predict.md, "Smoothed training targets").

Each spectrum (100 bins, 10..1000 Hz) is replaced by its triangular moving mean over `bins` (odd)
neighbouring bins, centred: weights 1, 2, .., h + 1, .., 2, 1 for bins = 2h + 1 (3: 1, 2, 1; 7: 1, 2,
3, 4, 3, 2, 1). At the band's ends the mean is over the neighbours there are, its weights renormalised.
bins = 1 returns the spectra unchanged. haptex smooths only the training windows' targets: validation,
early stopping and every evaluation use the windows' own spectra.
"""
import numpy as np

DEFAULT_BINS = 7  # haptex train's --target-smoothing default


def triangular_weights(bins):
    """The kernel's weights for an odd number of bins: 1, 2, .., bins // 2 + 1, .., 2, 1."""
    half = _half(bins)
    return (half + 1 - np.abs(np.arange(-half, half + 1))).astype(np.float32)


def smooth_targets(targets, bins=DEFAULT_BINS, axis=-1):
    """Targets smoothed as haptex train smooths them before stage 2, along `axis` (the bins; the last
    axis of a Windows table's (W, 100) `target`). Computed in float32 in C++'s order (neighbours from
    the lowest bin up), so the result is haptex's to the last bit on the same input; a float32 array
    in, a float32 array out. Raises ValueError for an even or non-positive `bins`, as haptex does."""
    half = _half(bins)
    t = np.moveaxis(np.asarray(targets, dtype=np.float32), axis, -1)
    rows = t.shape[-1]
    total = np.zeros_like(t)
    weight = np.zeros(rows, dtype=np.float32)
    for offset in range(-half, half + 1):  # j = b + offset, ascending: C++'s summation order
        w = np.float32(half + 1 - abs(offset))
        lo, hi = max(0, -offset), min(rows, rows - offset)  # bins b whose neighbour b + offset exists
        if lo >= hi:
            continue
        total[..., lo:hi] += w * t[..., lo + offset:hi + offset]
        weight[lo:hi] += w
    return np.moveaxis(total / weight, -1, axis)


def _half(bins):
    if isinstance(bins, bool) or not isinstance(bins, (int, np.integer)) or bins < 1 or bins % 2 == 0:
        raise ValueError(f"target smoothing must be an odd number of bins, not {bins}")
    return int(bins) // 2
