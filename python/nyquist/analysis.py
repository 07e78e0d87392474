"""Measures of point sets beyond SciPy's: the t-value of a base-2 net and the periodogram.

(The exact star discrepancy is ``nyquist.qmc.discrepancy(sample, method="star")``.)

>>> from nyquist import analysis, qmc
>>> analysis.t_value(qmc.Sobol(d=2, scramble=False).random_base2(8))
0
"""

from __future__ import annotations

import math
import numbers
from typing import NamedTuple

import numpy as np

from . import _core

__all__ = ["t_value", "periodogram", "Periodogram", "T_VALUE_MAX_WORK"]

# The most box lookups t_value accepts: N · C(m + d, d) bounds the count for a set of N = 2^m
# points in d dimensions (every shape of every level), and 2^36 of them take minutes.
T_VALUE_MAX_WORK = 2**36


def t_value(sample, *, max_work=T_VALUE_MAX_WORK):
    """The t-value of ``sample`` (``2^m`` points in ``[0, 1)^d``) as a digital net in base 2:
    the smallest ``t`` for which every elementary box of volume ``2^(t−m)`` holds exactly
    ``2^t`` points (0 is the best stratification, ``m`` holds for any set). Exact, by counting
    (nyquist's ``analysis::net_t_value``). Refuses sets whose worst case, ``N · C(m + d, d)``
    box lookups, is above ``max_work``.

    >>> import numpy as np
    >>> t_value(np.array([[0.0, 0.0], [0.25, 0.25], [0.5, 0.5], [0.75, 0.75]]))
    1
    """
    sample = np.ascontiguousarray(sample, dtype=np.float64)
    if sample.ndim != 2:
        raise ValueError("Sample is not a 2D array")
    n, d = sample.shape
    if n and n & (n - 1) == 0:
        work = n * math.comb(n.bit_length() - 1 + d, d)
        if work > max_work:
            raise ValueError(
                f"t_value of {n} points in {d} dimensions: up to {work} box lookups, above "
                f"max_work {max_work}"
            )
    return _core.t_value(sample)


class Periodogram(NamedTuple):
    """A periodogram on the integer frequencies ``[−F, F]²``."""

    power: np.ndarray
    """``(2F + 1, 2F + 1)`` mean power, row ``f_y + F``, column ``f_x + F``; the DC entry is
    the number of points, and white noise averages 1 elsewhere."""
    radial_mean: np.ndarray
    """Mean power over each annulus ``round(|f|) = r``, ``r = 0 … F``."""
    anisotropy_db: np.ndarray
    """Ulichney's anisotropy of each annulus in dB (``−inf`` where the power is constant)."""


def periodogram(sample, max_freq=32):
    """The periodogram of 2-D points: ``|Σ_k exp(−2πi f·x_k)|² / N`` at every integer frequency
    ``f`` in ``[−F, F]²`` (``F = max_freq``), averaged over realisations when ``sample`` is a
    ``(k, n, 2)`` stack of ``k`` sets; with its radial mean and anisotropy (nyquist-film's
    ``periodogram``).

    >>> import numpy as np
    >>> p = periodogram(np.array([[0.0, 0.0], [0.5, 0.0]]), max_freq=2)
    >>> float(p.power[2, 2 + 2]), float(round(p.power[2, 2 + 1], 12))  # f = (2, 0), (1, 0)
    (2.0, 0.0)
    """
    sample = np.ascontiguousarray(sample, dtype=np.float64)
    if sample.ndim == 2:
        sample = sample[np.newaxis]
    if sample.ndim != 3 or sample.shape[2] != 2:
        raise ValueError("sample must have shape (n, 2) or (k, n, 2)")
    if isinstance(max_freq, bool) or not isinstance(max_freq, numbers.Integral) or max_freq < 1:
        raise ValueError(f"max_freq {max_freq!r} must be a positive integer")
    if max_freq >= 2**32:
        raise ValueError(f"max_freq {max_freq} is above 4096")
    return Periodogram(*_core.periodogram(sample, int(max_freq)))
