"""A renderer's side of sampling: pixel samplers by (pixel, sample, dimension), and
reconstruction filters with their tables and importance sampling.

>>> from nyquist import pixel
>>> x = pixel.samples("zsobol", (3, 2), 16, 4, size=(8, 8), seed=7)
>>> x.shape
(16, 4)
>>> sorted((x[:, 0] * 16).astype(int).tolist()) == list(range(16))  # a (0, 4, 2)-net
True

A filter's importance samples integrate it: the mean weight is its integral.

>>> import numpy as np
>>> f = pixel.Filter("gaussian:sigma=0.5")
>>> f.name, f.radius
('gaussian', (2.0, 2.0))
>>> offsets, weights = f.sample(np.random.default_rng(1).random((20000, 2)))
>>> bool(abs(weights.mean() - f.integral) < 0.01 * f.integral)
True
"""

from __future__ import annotations

from . import _core

__all__ = ["samples", "Filter", "SAMPLERS", "FILTERS", "SCRAMBLES"]

SAMPLERS = (
    "random", "uniform", "stratified", "halton", "hammersley", "zero-two", "sobol",
    "best-candidate", "adaptive", "owen-sobol", "zsobol", "pmj02", "bluenoise-dithered",
    "fibonacci", "r2", "korobov",
)
"""The pixel samplers' names (the CLI's ``--sampler`` list)."""

FILTERS = ("box", "triangle", "gaussian", "mitchell", "catmull-rom", "blackman-harris", "lanczos")
"""The reconstruction filters' names; ``Filter`` takes each with optional parameters."""

SCRAMBLES = ("none", "permute-digits", "fast-owen", "owen")
"""The scrambles ``halton``, ``hammersley``, ``sobol`` and ``zsobol`` take."""


def samples(sampler, pixel, n, d, *, first=0, size=(1, 1), spp=None, seed=0, scramble=None):
    """Samples ``first … first + n − 1`` of ``pixel`` (``(x, y)``) from pixel sampler
    ``sampler`` built for an image of ``size`` pixels at ``spp`` samples per pixel (default
    ``first + n``), as an ``(n, d)`` float64 array of the sampler's 32-bit values. Each row's
    first two values are the image sample, then come 2-D draws and, when ``d`` is odd, a last
    1-D draw: the order a path tracer asks in. ``scramble`` is one of ``SCRAMBLES`` for the
    samplers that offer a choice.

    >>> samples("stratified", (0, 0), 4, 2, seed=1).shape
    (4, 2)
    """
    return _core.pixel_samples(
        sampler, tuple(pixel), n, d, first=first, size=tuple(size), spp=spp, seed=seed,
        scramble=scramble,
    )


Filter = _core.Filter
