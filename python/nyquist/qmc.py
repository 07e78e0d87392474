"""Quasi-Monte Carlo engines and measures with the interface of SciPy's ``scipy.stats.qmc``.

Where SciPy is installed, every engine here is a subclass of ``scipy.stats.qmc.QMCEngine``, so
SciPy accepts it wherever it takes an engine (``MultivariateNormalQMC``, ``qmc_quad``); without
SciPy the engines have the same methods on their own base class.

>>> from nyquist import qmc
>>> qmc.Sobol(d=2, scramble=False).random_base2(2)
array([[0.  , 0.  ],
       [0.5 , 0.5 ],
       [0.75, 0.25],
       [0.25, 0.75]])
"""

from __future__ import annotations

import copy
import numbers
import os
import warnings

import numpy as np

from . import _core

__all__ = [
    "QMCEngine",
    "Sobol",
    "Halton",
    "PMJ02",
    "ZeroTwo",
    "R2",
    "Lattice",
    "LatinHypercube",
    "PoissonDisk",
    "PixelSampler",
    "ZSobol",
    "BestCandidate",
    "discrepancy",
    "update_discrepancy",
    "geometric_discrepancy",
    "scale",
]

try:  # SciPy's base class, so that SciPy accepts these engines.
    from scipy.stats.qmc import QMCEngine as _Base

    _HAVE_SCIPY = True
except ImportError:  # pragma: no cover - exercised where SciPy is absent
    _Base = object
    _HAVE_SCIPY = False


def _check_d(d):
    if isinstance(d, bool) or not isinstance(d, numbers.Integral) or d < 0:
        raise ValueError("d must be a non-negative integer value")
    return int(d)


def _seed_of(rng):
    """A 64-bit seed for the Rust side, drawn from ``rng`` the way SciPy draws from it: an int or
    None seeds a NumPy Generator, a Generator (or a legacy ``RandomState``) is used as is."""
    if isinstance(rng, np.random.RandomState):
        return int(rng.randint(0, 2**63, dtype=np.int64)) * 2 + int(rng.randint(0, 2))
    gen = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
    return int(gen.integers(0, 2**63, dtype=np.int64)) * 2 + int(gen.integers(0, 2))


def _rng_argument(rng, seed):
    """SciPy's SPEC 7 rules (its ``_transition_to_rng("seed")``): ``rng`` is passed through
    ``numpy.random.default_rng``; the older ``seed`` is passed as given to SciPy's set-up, which
    spawns a given Generator, keeps a legacy ``RandomState`` and seeds a new Generator from an
    int."""
    if seed is not None:
        if rng is not None:
            raise TypeError("got multiple values for argument now known as `rng`")
        return seed
    return None if rng is None else np.random.default_rng(rng)


class QMCEngine(_Base):
    """The base of nyquist's engines: ``random``, ``integers``, ``reset`` and ``fast_forward``
    over a ``_points(first, n)`` each engine defines. A subclass of SciPy's ``QMCEngine`` when
    SciPy is installed."""

    def __init__(self, d, *, optimization=None, rng=None, seed=None):
        rng = _rng_argument(rng, seed)
        if _HAVE_SCIPY:
            # SciPy's own set-up: d's check, the Generator (a given one is spawned, as SciPy
            # does), and its optimizers ("random-cd", "lloyd") applied after each draw.
            self._initialize(d, optimization=optimization, rng=rng)
            return
        if optimization is not None:
            known = {"random-cd", "lloyd"}
            if str(optimization).lower() in known:
                raise ValueError(f"optimization {optimization!r} needs SciPy installed")
            raise ValueError(
                f"{optimization!r} is not a valid optimization method. It must be one of {known!r}"
            )
        self.d = _check_d(d)
        legacy = (np.random.Generator, np.random.RandomState)
        self.rng = rng if isinstance(rng, legacy) else np.random.default_rng(rng)
        self.rng_seed = copy.deepcopy(self.rng)
        self.num_generated = 0
        self.optimization_method = None

    def _points(self, first, n):  # pragma: no cover - every engine defines it
        raise NotImplementedError

    def _random(self, n=1, *, workers=1):
        return self._points(self.num_generated, n)

    def random(self, n=1, *, workers=1):
        """Draw ``n`` points in ``[0, 1)^d``, continuing where the last draw stopped."""
        n = _check_n(n)
        try:
            sample = self._random(n, workers=workers)
        except OverflowError as exc:  # an index past what the Rust side takes (u64, u32)
            raise ValueError(
                f"points {self.num_generated}..{self.num_generated + n} are past the points "
                f"this engine indexes ({exc})"
            ) from None
        if self.optimization_method is not None:
            sample = self.optimization_method(sample)
        self.num_generated += n
        return sample

    def integers(self, l_bounds, *, u_bounds=None, n=1, endpoint=False, workers=1):
        """Draw ``n`` integer points in ``[l_bounds, u_bounds)`` (``]`` with ``endpoint``),
        as SciPy's ``QMCEngine.integers``."""
        if u_bounds is None:
            u_bounds = l_bounds
            l_bounds = 0
        u_bounds = np.atleast_1d(u_bounds)
        l_bounds = np.atleast_1d(l_bounds)
        if endpoint:
            u_bounds = u_bounds + 1
        if not np.issubdtype(l_bounds.dtype, np.integer) or not np.issubdtype(
            u_bounds.dtype, np.integer
        ):
            raise ValueError(
                "'u_bounds' and 'l_bounds' must be integers or array-like of integers"
            )
        sample = self.random(n=n, workers=workers)
        sample = scale(sample, l_bounds=l_bounds, u_bounds=u_bounds)
        return np.floor(sample).astype(np.int64)

    def reset(self):
        """Start again from the first point (and the first scramble)."""
        self.rng = copy.deepcopy(self.rng_seed)
        self.num_generated = 0
        return self

    def fast_forward(self, n):
        """Skip ``n`` points: the next draw starts ``n`` points later. O(1)."""
        self.num_generated += _check_n(n)
        return self


def _check_n(n):
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < 0:
        raise ValueError(f"n {n!r} must be a non-negative integer")
    return int(n)


class Sobol(QMCEngine):
    """Sobol' points (Joe–Kuo 6.21201 direction numbers; 2^64 points; past 1024 dimensions the
    core's padding, independently seeded Owen-scrambled 4-D blocks).

    The points come in SciPy's (Gray-code) order; unscrambled they are SciPy's, bit for bit.
    ``scramble=True`` Owen-scrambles each coordinate (Burley's hash-based nested uniform
    scramble, one key per dimension drawn from ``rng``), where SciPy applies a linear matrix
    scramble plus a digital shift: both keep every power-of-two prefix a (t, m, d)-net.
    ``bits`` (up to 64) bounds the number of points, ``2**bits``; the values keep at most 32
    bits.

    >>> from nyquist.qmc import Sobol
    >>> x = Sobol(d=3, rng=7).random_base2(4)
    >>> x.shape
    (16, 3)
    >>> sorted((x[:, 0] * 16).astype(int).tolist()) == list(range(16))
    True
    """

    MAXDIM = 2**32 - 1

    def __init__(self, d, *, scramble=True, bits=None, rng=None, optimization=None, seed=None):
        super().__init__(d, optimization=optimization, rng=rng, seed=seed)
        if self.d > self.MAXDIM:
            raise ValueError(f"Maximum supported dimensionality is {self.MAXDIM}.")
        if bits is None:
            bits = 30
        if bits > 64:
            raise ValueError("Maximum supported 'bits' is 64")
        if bits < 1:
            raise ValueError(f"bits {bits}: need at least 1")
        self.bits = bits
        self.maxn = 2**bits
        self.scramble = bool(scramble)
        self._seed = _seed_of(self.rng) if self.scramble else None

    def _points(self, first, n):
        total = first + n
        if total > self.maxn:
            raise ValueError(
                f"At most 2**{self.bits}={self.maxn} distinct points can be generated. "
                f"{first} points have been previously generated, then: n={first}+{n}={total}. "
                + ("Consider increasing `bits`." if self.bits < 64 else "")
            )
        if self.d == 0:
            return np.empty((n, 0))
        return _core.sobol(n, self.d, first, self._seed, self.bits)

    def random(self, n=1, *, workers=1):
        n = _check_n(n)
        if self.num_generated == 0 and n & (n - 1) != 0:
            warnings.warn(
                "The balance properties of Sobol' points require n to be a power of 2.",
                stacklevel=2,
            )
        return super().random(n, workers=workers)

    def random_base2(self, m):
        """Draw ``2**m`` points; the total drawn must stay a power of two (the balance
        properties of the nets)."""
        n = 2**m
        total = self.num_generated + n
        if total & (total - 1) != 0:
            raise ValueError(
                "The balance properties of Sobol' points require n to be a power of 2. "
                f"{self.num_generated} points have been previously generated, then: "
                f"n={self.num_generated}+2**{m}={total}. "
                "If you still want to do this, the function 'Sobol.random()' can be used."
            )
        return self.random(n)


class Halton(QMCEngine):
    """Halton points: radical inverses in the first ``d`` primes (up to 1024 dimensions).
    ``scramble=True`` randomizes each base's digits (seeded from ``rng``) by ``scrambling``:

    - ``"permute-positions"`` (default): each digit position through its own random
      permutation, Owen's randomized Halton and SciPy's law; filled incrementally, a few
      nanoseconds per value, for the first 2**42 points;
    - ``"permute-digits"``: one permutation per base for every position, the infinitely many
      leading zeros included (pbrt's scheme): as fast, but base 2 has only two of them;
    - ``"owen"``: nested uniform digit permutations (Owen scrambling in base b), value by
      value and some 20 times slower.

    All keep every base's stratification.

    >>> from nyquist.qmc import Halton
    >>> Halton(d=2, scramble=False).random(3)
    array([[0.        , 0.        ],
           [0.5       , 0.33333333],
           [0.25      , 0.66666667]])
    """

    SCRAMBLINGS = ("permute-positions", "permute-digits", "owen")

    def __init__(self, d, *, scramble=True, scrambling="permute-positions", optimization=None,
                 rng=None, seed=None):
        super().__init__(d, optimization=optimization, rng=rng, seed=seed)
        if scrambling not in self.SCRAMBLINGS:
            raise ValueError(f"scrambling {scrambling!r} is not one of {self.SCRAMBLINGS}")
        self.scramble = bool(scramble)
        self.scrambling = scrambling
        self._seed = _seed_of(self.rng) if self.scramble else None

    def _points(self, first, n):
        if self.d == 0:
            return np.empty((n, 0))
        return _core.halton(n, self.d, first, self._seed, self.scrambling)


class _Named(QMCEngine):
    """An engine over one of the core's named point sets (``NamedSequence``)."""

    _name = ""

    def __init__(self, d, *, scramble=True, rng=None, optimization=None, seed=None,
                 points=None, multiplier=None):
        super().__init__(d, optimization=optimization, rng=rng, seed=seed)
        self.scramble = bool(scramble)
        self._seed = _seed_of(self.rng) if self.scramble else None
        self._set_size = points
        self._multiplier = multiplier
        if self.d:
            self._points(0, 0)  # the core's checks, now rather than at the first draw

    def _points(self, first, n):
        if self.d == 0:
            return np.empty((n, 0))
        return _core.sequence(
            self._name, n, self.d, first, self._seed, self._set_size, self._multiplier
        )


class PMJ02(_Named):
    """Progressive multi-jittered (0,2) points (Christensen, Kensler and Kilpatrick 2018), in
    one or two dimensions: every power-of-two prefix is a (0, m, 2)-net. ``scramble=True``
    Owen-scrambles them (seeded from ``rng``); unscrambled they are nyquist's baked sequence.

    >>> from nyquist.qmc import PMJ02
    >>> x = PMJ02(d=2, rng=3).random(16)
    >>> sorted((x[:, 1] * 16).astype(int).tolist()) == list(range(16))
    True
    """

    _name = "pmj02"


class ZeroTwo(_Named):
    """The (0,2)-sequence in base 2 (Sobol's first two dimensions, van der Corput and its
    Pascal-matrix partner), in one or two dimensions; ``scramble=True`` applies a random
    digital shift (seeded from ``rng``), which keeps every net.

    >>> from nyquist.qmc import ZeroTwo
    >>> ZeroTwo(d=2, scramble=False).random(4).tolist()
    [[0.0, 0.0], [0.5, 0.5], [0.25, 0.75], [0.75, 0.25]]
    """

    _name = "zero-two"


class R2(_Named):
    """Roberts' R_d Kronecker sequence: point i is {½ + i·α}, with α the powers of the inverse
    of the generalised golden ratio in ``d`` dimensions (Roberts' start at ½).
    ``scramble=True`` replaces the ½ by a random Cranley–Patterson rotation (seeded from
    ``rng``).

    >>> from nyquist.qmc import R2
    >>> R2(d=1, scramble=False).random(2)[:, 0].tolist()  # ½, then ½ + 1/φ − 1
    [0.5, 0.11803398874989479]
    """

    _name = "rd"


class Lattice(_Named):
    """A rank-1 lattice of ``n`` points: ``kind="fibonacci"`` (two dimensions, ``n`` a Fibonacci
    number) or ``"korobov"`` (generator (1, a, a², …) mod ``n``; ``multiplier`` a, or Stroud's
    tabled one, else the minimiser of the P2 criterion). Point i is {i·z / n}; ``scramble=True``
    adds a random Cranley–Patterson rotation (seeded from ``rng``). At most ``n`` points can be
    drawn.

    >>> from nyquist.qmc import Lattice
    >>> (Lattice(d=2, n=5, multiplier=2, scramble=False).random(5) * 5).round().tolist()
    [[0.0, 0.0], [1.0, 2.0], [2.0, 4.0], [3.0, 1.0], [4.0, 3.0]]
    """

    def __init__(self, d, n, *, kind="korobov", multiplier=None, scramble=True, rng=None,
                 optimization=None, seed=None):
        if kind not in ("fibonacci", "korobov"):
            raise ValueError(f"kind {kind!r} is not 'fibonacci' or 'korobov'")
        self._name = kind
        super().__init__(d, scramble=scramble, rng=rng, optimization=optimization, seed=seed,
                         points=n, multiplier=multiplier)
        self.n = n


class LatinHypercube(QMCEngine):
    """Latin hypercube points: in every dimension the ``n`` values of a draw fall one in each
    stratum ``[k/n, (k+1)/n)``. ``scramble=True`` jitters each value uniformly inside its
    stratum, ``False`` puts it at the stratum's centre. ``strength=2`` gives an orthogonal-array
    Latin hypercube (Tang 1993; Art Owen's construction, as SciPy's): ``n = p²`` for a prime
    ``p`` and ``d ≤ p + 1``, and every pair of dimensions puts one point in each of the ``p × p``
    coarse cells. Each ``random(n)`` is a new, independent design (not a continuation).

    Strength 1 is computed in Rust (one independent permutation per dimension, on every
    thread); strength 2 builds its small orthogonal array with NumPy from ``rng``.

    >>> from nyquist.qmc import LatinHypercube
    >>> x = LatinHypercube(d=2, rng=5).random(8)
    >>> sorted((x[:, 0] * 8).astype(int).tolist())
    [0, 1, 2, 3, 4, 5, 6, 7]
    """

    def __init__(self, d, *, scramble=True, strength=1, optimization=None, rng=None, seed=None):
        super().__init__(d, optimization=optimization, rng=rng, seed=seed)
        if strength not in (1, 2):
            raise ValueError(f"{strength!r} is not a valid strength. It must be one of {{1, 2}}")
        self.scramble = bool(scramble)
        self.strength = strength

    def _random(self, n=1, *, workers=1):
        if self.strength == 2:
            return self._orthogonal_array(n)
        seed = _seed_of(self.rng)
        if self.d == 0 or n == 0:
            return np.empty((n, self.d))
        return _core.latin_hypercube(n, self.d, seed, centered=not self.scramble)

    def _orthogonal_array(self, n):
        p = int(np.sqrt(n))
        if p * p != n or not _is_prime(p):
            near = [q * q for q in range(max(p - 3, 2), p + 4) if _is_prime(q)][-2:]
            raise ValueError(f"n is not the square of a prime number. Close values are {near}")
        if self.d > p + 1:
            raise ValueError("n is too small for d. Must be n > (d-1)**2")
        # The orthogonal array OA(p², p + 1, p, 2): columns i, j and i + k·j mod p.
        i, j = np.divmod(np.arange(n), p)
        columns = [i, j] + [(i + k * j) % p for k in range(1, p)]
        out = np.empty((n, self.d))
        for c, column in enumerate(columns[: self.d]):
            symbols = self.rng.permutation(p)[column]
            # Within each symbol's p rows, a Latin hypercube of p strata.
            for symbol in range(p):
                rows = np.flatnonzero(symbols == symbol)
                strata = self.rng.permutation(p)
                jitter = self.rng.random(p) if self.scramble else 0.5
                out[rows, c] = (symbol * p + strata + jitter) / n
        return out

    def fast_forward(self, n):
        """Counts ``n`` points as drawn and moves ``rng`` on as one draw would (a Latin
        hypercube is a set, not a sequence: there is nothing to skip to)."""
        n = _check_n(n)
        if self.strength == 1:
            _seed_of(self.rng)
        else:
            self._orthogonal_array(n)  # as SciPy: the draw is made and dropped
        self.num_generated += n
        return self


def _is_prime(p):
    return p >= 2 and all(p % q for q in range(2, int(p**0.5) + 1))


def _validate_bounds(l_bounds, u_bounds, d):
    try:
        lower = np.broadcast_to(np.asarray(l_bounds, dtype=float), d)
        upper = np.broadcast_to(np.asarray(u_bounds, dtype=float), d)
    except ValueError as exc:
        raise ValueError(
            "'l_bounds' and 'u_bounds' must be broadcastable and respect the sample dimension"
        ) from exc
    if not np.all(lower < upper):
        raise ValueError("Bounds are not consistent 'l_bounds' < 'u_bounds'")
    return lower, upper


class PoissonDisk(QMCEngine):
    """Poisson-disk points in the box ``[l_bounds, u_bounds)`` of any dimension: no two closer
    than ``radius``. Bridson's algorithm in Rust: an active list and a grid of cell side
    ``radius/√d``; each step tries up to ``ncandidates`` candidates around a random active point
    and keeps the first one far enough from every point. Candidates are uniform in the shell
    between ``radius`` and ``2·radius`` (``hypersphere="volume"``) or on the sphere of radius
    ``1.001·radius`` (``"surface"``).

    ``random(n)`` returns up to ``n`` new points of the same set (fewer once the space is
    full); ``fill_space()`` adds points until no active point is left.

    >>> from nyquist.qmc import PoissonDisk
    >>> x = PoissonDisk(d=2, radius=0.2, rng=1).fill_space()
    >>> bool(min(np.hypot(*(a - b)) for k, a in enumerate(x) for b in x[:k]) >= 0.2)
    True
    """

    def __init__(self, d, *, radius=0.05, hypersphere="volume", ncandidates=30,
                 optimization=None, rng=None, seed=None, l_bounds=None, u_bounds=None):
        super().__init__(d, optimization=optimization, rng=rng, seed=seed)
        if hypersphere not in ("volume", "surface"):
            raise ValueError(
                f"{hypersphere!r} is not a valid hypersphere sampling method. It must be one of "
                "{'volume', 'surface'}"
            )
        self.radius = float(radius)
        self.hypersphere = hypersphere
        self.ncandidates = int(ncandidates)
        lower = np.zeros(self.d) if l_bounds is None else l_bounds
        upper = np.ones(self.d) if u_bounds is None else u_bounds
        self.l_bounds, self.u_bounds = _validate_bounds(lower, upper, self.d)
        self._new_state()

    def _new_state(self):
        self._state = None
        if self.d:
            self._state = _core.PoissonDiskState(
                self.radius, self.l_bounds.tolist(), self.u_bounds.tolist(),
                self.hypersphere == "surface", self.ncandidates, _seed_of(self.rng),
            )

    def _draw(self, n):
        if n == 0 or self._state is None:
            return np.empty((0 if n is None else n, self.d))
        return self._state.extend(n)

    def random(self, n=1, *, workers=1):
        """Up to ``n`` new points of the set, fewer when the space is full; ``n=np.inf`` (as
        SciPy's ``fill_space`` passes it) until it is full."""
        sample = self._draw(None if n == np.inf else _check_n(n))
        if self.optimization_method is not None:
            sample = self.optimization_method(sample)
        self.num_generated += len(sample)
        return sample

    def fill_space(self):
        """Adds points until no active point can place another, and returns them."""
        sample = self._draw(None)
        self.num_generated += len(sample)
        return sample

    def reset(self):
        super().reset()
        self._new_state()
        return self

    def fast_forward(self, n):
        """Adds ``n`` points to the set without returning them (a Poisson-disk set grows by a
        random process: later points depend on earlier ones)."""
        self.random(n)
        return self


class PixelSampler(QMCEngine):
    """The samples of one pixel from one of nyquist's pixel samplers, as an engine: point k is
    pixel sample k, its ``d`` values the sampler's dimensions in the renderer's order (the image
    sample first, then 2-D draws, a last 1-D draw when ``d`` is odd). ``sampler`` is any of
    ``nyquist.pixel.SAMPLERS`` (``"zsobol"``, ``"pmj02"``, ``"best-candidate"``, ``"sobol"``,
    …); ``size`` is the image in pixels and ``spp`` the samples per pixel the sampler is built
    for (at most ``spp`` points can be drawn). The scramble is seeded from ``rng``;
    ``scramble=False`` (for ``halton``, ``hammersley``, ``sobol``, ``zsobol``) gives the
    unscrambled sets.

    >>> from nyquist.qmc import PixelSampler
    >>> x = PixelSampler(2, "pmj02", spp=16, rng=2).random(16)
    >>> sorted((x[:, 0] * 16).astype(int).tolist()) == list(range(16))
    True
    """

    def __init__(self, d, sampler="zsobol", *, pixel=(0, 0), size=(1, 1), spp=256,
                 scramble=True, rng=None, optimization=None, seed=None):
        super().__init__(d, optimization=optimization, rng=rng, seed=seed)
        self.sampler = sampler
        self.pixel = tuple(pixel)
        self.size = tuple(size)
        self.spp = spp
        if any(isinstance(v, bool) or not isinstance(v, numbers.Integral) or v < 0
               for v in (*self.pixel, *self.size, self.spp)):
            raise ValueError(f"pixel {pixel}, size {size} and spp {spp} must be non-negative integers")
        self.scramble = bool(scramble)
        # Unscrambled, one fixed set whatever rng says (ZSobol's Morton-index shuffle included);
        # the samplers with a choice of scramble get none, the others their seed-0 set.
        self._seed = _seed_of(self.rng) if self.scramble else 0
        self._choice = str(sampler).lower() in ("halton", "hammersley", "sobol", "zsobol")
        self._points(0, 0)  # the core's checks, now rather than at the first draw

    def _points(self, first, n):
        return _core.pixel_samples(
            self.sampler, self.pixel, n, self.d, first=first, size=self.size, spp=self.spp,
            seed=self._seed, scramble=None if self.scramble or not self._choice else "none",
        )


class ZSobol(PixelSampler):
    """Ahmed and Wonka's ZSobol pixel sampler (pbrt-v4's ``ZSobolSampler``): one Owen-scrambled
    Sobol sequence over the whole image, indexed by the pixel's Morton code, so every pixel's
    samples are a (0, m, 2)-net and neighbouring pixels are decorrelated.

    >>> from nyquist.qmc import ZSobol
    >>> ZSobol(2, pixel=(3, 1), size=(8, 8), spp=4, rng=1).random(4).shape
    (4, 2)
    """

    def __init__(self, d, *, pixel=(0, 0), size=(1, 1), spp=256, scramble=True, rng=None,
                 optimization=None, seed=None):
        super().__init__(d, "zsobol", pixel=pixel, size=size, spp=spp, scramble=scramble,
                         rng=rng, optimization=optimization, seed=seed)


class BestCandidate(PixelSampler):
    """Mitchell's best-candidate pixel sampler (pbrt-v2's): the image samples are a toroidal
    best-candidate (blue-noise) pattern, the other dimensions stratified.

    >>> from nyquist.qmc import BestCandidate
    >>> BestCandidate(2, spp=8, rng=1).random(8).shape
    (8, 2)
    """

    def __init__(self, d, *, pixel=(0, 0), size=(1, 1), spp=256, rng=None, optimization=None,
                 seed=None):
        super().__init__(d, "best-candidate", pixel=pixel, size=size, spp=spp, rng=rng,
                         optimization=optimization, seed=seed)


def scale(sample, l_bounds, u_bounds, *, reverse=False):
    """Scale ``sample`` from the unit hypercube to ``[l_bounds, u_bounds]`` (or back with
    ``reverse``), as SciPy's ``qmc.scale``: the bounds are broadcast to the sample's dimension.

    >>> scale([[0.5, 0.25]], [0, 2], [2, 6])
    array([[1., 3.]])
    """
    sample = np.asarray(sample)
    if not sample.ndim == 2:
        raise ValueError("Sample is not a 2D array")
    lower, upper = _validate_bounds(l_bounds, u_bounds, sample.shape[1])
    if not reverse:
        if sample.size and (sample.max() > 1.0 or sample.min() < 0.0):
            raise ValueError("Sample is not in unit hypercube")
        return sample * (upper - lower) + lower
    if not (np.all(sample >= lower) and np.all(sample <= upper)):
        raise ValueError("Sample is out of bounds")
    return (sample - lower) / (upper - lower)


_METHODS = {"CD": "CD", "WD": "WD", "MD": "MD", "L2-star": "L2-star", "star": "star"}


def _check_workers(workers):
    """SciPy's rules for ``workers``: a positive count, or -1 for every CPU (which must be
    known). nyquist computes a discrepancy on one thread whatever the count."""
    workers = int(workers)
    if workers == -1:
        workers = os.cpu_count()
        if workers is None:
            raise NotImplementedError("Cannot determine the number of cpus using os.cpu_count(), "
                                      "cannot use -1 for the number of workers")
    elif workers <= 0:
        raise ValueError(f"Invalid number of workers: {workers}, must be -1 or > 0")
    return workers


def _unit_sample(sample, name="Sample"):
    sample = np.ascontiguousarray(sample, dtype=np.float64)
    if sample.ndim != 2:
        raise ValueError(f"{name} is not a 2D array")
    if sample.size and ((sample.max() > 1.0) or (sample.min() < 0.0)):
        raise ValueError(f"{name} is not in unit hypercube")
    return sample


def discrepancy(sample, *, iterative=False, method="CD", workers=1):
    """The discrepancy of ``sample`` (an ``(n, d)`` array in ``[0, 1]``): ``"CD"``, ``"WD"``
    and ``"MD"`` squared and ``"L2-star"`` not, as SciPy returns them, and ``"star"``,
    nyquist's exact star discrepancy. ``iterative=True`` normalises an L2 discrepancy by
    ``n + 1``, ready for :func:`update_discrepancy`.

    >>> discrepancy([[0.5]], method="star")
    0.5
    """
    sample = _unit_sample(sample)
    _check_workers(workers)
    if method not in _METHODS:
        raise ValueError(
            f"{method!r} is not a valid method. It must be one of {set(_METHODS)!r}"
        )
    return _core.discrepancy(sample, _METHODS[method], bool(iterative))


def update_discrepancy(x_new, sample, initial_disc):
    """The squared centered discrepancy of ``sample`` with ``x_new`` added, in O(n·d), from
    ``initial_disc = discrepancy(sample, iterative=True)`` (SciPy's ``update_discrepancy``).

    >>> import numpy as np
    >>> x = np.array([[0.1, 0.3], [0.6, 0.8], [0.35, 0.55]])
    >>> d0 = discrepancy(x[:2], iterative=True)
    >>> bool(abs(update_discrepancy(x[2], x[:2], d0) - discrepancy(x)) < 1e-15)
    True
    """
    sample = _unit_sample(sample)
    x_new = np.ascontiguousarray(x_new, dtype=np.float64)
    if x_new.ndim != 1:
        raise ValueError("x_new is not a 1D array")
    if x_new.size and ((x_new.max() > 1.0) or (x_new.min() < 0.0)):
        raise ValueError("x_new is not in unit hypercube")
    if x_new.shape[0] != sample.shape[1]:
        raise ValueError("x_new and sample must be broadcastable")
    return _core.update_discrepancy(x_new, sample, float(initial_disc))


def geometric_discrepancy(sample, method="mindist", metric="euclidean"):
    """SciPy's geometric discrepancy: ``"mindist"``, the smallest distance between two distinct
    points, or ``"mst"``, the mean edge length of a minimum spanning tree. ``metric`` is
    ``"euclidean"``, ``"cityblock"`` or ``"chebyshev"``. Duplicate points raise a warning; the
    spanning tree counts their zero-length edges (SciPy's drops them, its issue #18892).

    >>> geometric_discrepancy([[0, 0], [0, 1], [0.5, 1]], method="mst")
    0.75
    """
    sample = _unit_sample(sample)
    if sample.shape[0] < 2:
        raise ValueError("Sample must contain at least two points")
    if method not in ("mindist", "mst"):
        raise ValueError(f"{method!r} is not a valid method. It must be one of {{'mindist', 'mst'}}")
    value, duplicate = _core.geometric_discrepancy(sample, method, metric)
    if duplicate:
        warnings.warn("Sample contains duplicate points.", stacklevel=2)
    return value


