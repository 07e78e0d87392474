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

import numbers

import numpy as np

from . import _core

__all__ = ["samples", "Filter", "SAMPLERS", "FILTERS", "SCRAMBLES"]

SAMPLERS = (
    "random", "uniform", "stratified", "halton", "hammersley", "zero-two", "sobol",
    "best-candidate", "adaptive", "owen-sobol", "owen-sobol-bn", "zsobol", "pmj02",
    "pmj02-bn", "bluenoise-dithered",
    "fibonacci", "r2", "korobov", "lattice-bn",
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
    for name, value in (("n", n), ("d", d), ("first", first), ("seed", seed),
                        *(("pixel", v) for v in pixel), *(("size", v) for v in size),
                        *((("spp", spp),) if spp is not None else ())):
        if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0:
            raise ValueError(f"{name} {value!r} must be a non-negative integer")
    try:
        return _core.pixel_samples(
            sampler, tuple(pixel), n, d, first=first, size=tuple(size), spp=spp, seed=seed,
            scramble=scramble,
        )
    except OverflowError:
        raise ValueError(
            f"n {n}, d {d}, first {first}, pixel {tuple(pixel)}, size {tuple(size)} and spp "
            f"{spp} must fit in 32 bits (seed in 64)"
        ) from None


def _pairs(a, name):
    a = np.ascontiguousarray(a, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 2:
        raise ValueError(f"{name} must have shape (n, 2), not {a.shape}")
    return a


class Filter:
    """A reconstruction filter from a spec such as ``"mitchell"``, ``"gaussian:sigma=0.5"`` or
    ``"lanczos:radius=3,tau=3"`` (the CLI's ``--filter``).

    - ``name``, ``spec``, ``radius`` (half-widths in pixels), ``integral``, ``separable``;
    - ``evaluate(x, y)``: the filter at offsets from the pixel centre (any array-likes of one
      shape);
    - ``table(n=16)``: the film's ``n × n`` table ``(values, xs, ys)``, ``values[j, i]`` at
      ``(xs[i], ys[j])``;
    - ``sample(u)``: importance samples ``(offsets, weights)`` from ``(n, 2)`` uniforms, with
      ``weights = f / pdf``, so the mean weight is the integral; ``pdf(offsets)``.

    >>> Filter("box").integral
    1.0
    """

    def __init__(self, spec):
        self._filter = _core.Filter(str(spec))

    def __repr__(self):
        return repr(self._filter)

    name = property(lambda self: self._filter.name, doc="The filter's name.")
    spec = property(lambda self: self._filter.spec, doc="The spec, which parses back to it.")
    radius = property(lambda self: self._filter.radius, doc="Half-widths ``(rx, ry)``.")
    integral = property(lambda self: self._filter.integral, doc="The filter's integral.")
    separable = property(lambda self: self._filter.separable, doc="Whether f = fx·fy.")

    def evaluate(self, x, y):
        """``f(x, y)`` at offsets (pixels from the centre), with ``x`` and ``y``'s shape."""
        x, y = np.broadcast_arrays(np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64))
        values = self._filter.evaluate(np.ascontiguousarray(x).ravel(), np.ascontiguousarray(y).ravel())
        return values.reshape(x.shape)

    def table(self, n=16):
        """The film's ``n × n`` table (``n`` 8, 16, 32 or 64) as ``(values, xs, ys)``."""
        return self._filter.table(int(n))

    def sample(self, u):
        """Importance samples from ``(n, 2)`` uniforms in ``[0, 1)``: ``(offsets, weights)``."""
        return self._filter.sample(_pairs(u, "u"))

    def pdf(self, offsets):
        """The sampling density at each of ``(n, 2)`` offsets (0 outside the support)."""
        return self._filter.pdf(_pairs(offsets, "offsets"))
