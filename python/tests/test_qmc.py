"""nyquist.qmc: exact values, net properties, SciPy's values where SciPy defines them, and
properties of the bindings (shapes, dtypes, bounds, seeds, fast_forward) with Hypothesis."""

import pathlib

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nyquist import qmc

try:
    import scipy.stats.qmc as sqmc
except ImportError:  # pragma: no cover
    sqmc = None

needs_scipy = pytest.mark.skipif(sqmc is None, reason="SciPy is not installed")


def is_net(points, m, t=0):
    """Whether the 2-D ``points`` (2**m of them) are a (t, m, 2)-net in base 2: every
    elementary box of area 2**(t - m) holds exactly 2**t points."""
    for j in range(m - t + 1):
        k = m - t - j
        ix = np.floor(points[:, 0] * 2**j).astype(np.int64)
        iy = np.floor(points[:, 1] * 2**k).astype(np.int64)
        counts = np.bincount(ix * 2**k + iy, minlength=2 ** (m - t))
        if not np.all(counts == 2**t):
            return False
    return True


def test_unscrambled_sobol_starts_as_published():
    # Gray-code order, as SciPy draws them.
    x = qmc.Sobol(d=2, scramble=False).random_base2(3)
    assert x.tolist() == [
        [0.0, 0.0],
        [0.5, 0.5],
        [0.75, 0.25],
        [0.25, 0.75],
        [0.375, 0.375],
        [0.875, 0.875],
        [0.625, 0.125],
        [0.125, 0.625],
    ]


@needs_scipy
@pytest.mark.parametrize("d", [1, 2, 5, 64, 1024])
def test_unscrambled_sobol_is_scipys_bit_for_bit(d):
    ours = qmc.Sobol(d=d, scramble=False).random_base2(8)
    theirs = sqmc.Sobol(d=d, scramble=False).random_base2(8)
    assert np.array_equal(ours, theirs)
    # Continuing draws and skips land on the same points too.
    a, b = qmc.Sobol(d=d, scramble=False), sqmc.Sobol(d=d, scramble=False)
    a.fast_forward(37)
    b.fast_forward(37)
    assert np.array_equal(a.random(5), b.random(5))


@needs_scipy
def test_unscrambled_halton_is_scipys():
    ours = qmc.Halton(d=7, scramble=False).random(500)
    theirs = sqmc.Halton(d=7, scramble=False).random(500)
    np.testing.assert_allclose(ours, theirs, rtol=0, atol=1e-15)


@pytest.mark.parametrize("seed", [0, 1, 12345])
@pytest.mark.parametrize("m", [1, 4, 9])
def test_scrambled_sobol_keeps_the_first_pair_a_zero_net(seed, m):
    x = qmc.Sobol(d=4, rng=seed).random_base2(m)
    assert is_net(x[:, :2], m)
    assert np.all((x >= 0) & (x < 1))
    # Every 1-D projection is stratified: one point in each interval of length 2**-m.
    for dim in range(4):
        assert sorted(np.floor(x[:, dim] * 2**m).astype(int).tolist()) == list(range(2**m))


def test_seeds_decide_the_scramble():
    a = qmc.Sobol(d=3, rng=5).random(8)
    b = qmc.Sobol(d=3, rng=5).random(8)
    c = qmc.Sobol(d=3, rng=6).random(8)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    h1, h2 = qmc.Halton(d=3, rng=5).random(8), qmc.Halton(d=3, rng=6).random(8)
    assert not np.array_equal(h1, h2)
    gen = np.random.default_rng(3)
    assert np.array_equal(
        qmc.Sobol(d=2, rng=gen).random(4), qmc.Sobol(d=2, rng=np.random.default_rng(3)).random(4)
    )


def test_reset_starts_again():
    e = qmc.Sobol(d=2, rng=9)
    first = e.random(16)
    e.random(16)
    assert np.array_equal(e.reset().random(16), first)
    assert e.num_generated == 16


@settings(max_examples=120, deadline=None)
@given(
    d=st.integers(1, 40),
    skip=st.integers(0, 5000),
    n=st.integers(0, 300),
    scramble=st.booleans(),
    kind=st.sampled_from(
        ["sobol", "halton", "halton-digits", "halton-owen", "pmj02", "zero-two", "r2", "lattice"]
    ),
)
def test_fast_forward_equals_skipping(d, skip, n, scramble, kind):
    two = min(d, 2)
    make = {
        "sobol": lambda: qmc.Sobol(d=d, scramble=scramble, rng=4),
        "halton": lambda: qmc.Halton(d=d, scramble=scramble, rng=4),
        "halton-digits": lambda: qmc.Halton(
            d=d, scramble=scramble, scrambling="permute-digits", rng=4
        ),
        "halton-owen": lambda: qmc.Halton(d=d, scramble=scramble, scrambling="owen", rng=4),
        "pmj02": lambda: qmc.PMJ02(d=two, scramble=scramble, rng=4),
        "zero-two": lambda: qmc.ZeroTwo(d=two, scramble=scramble, rng=4),
        "r2": lambda: qmc.R2(d=d, scramble=scramble, rng=4),
        "lattice": lambda: qmc.Lattice(d=d, n=4096, multiplier=1487, scramble=scramble, rng=4),
    }[kind]
    if kind == "lattice":
        skip %= 3000  # the lattice has 4096 points
    if kind in ("pmj02", "zero-two"):
        d = two
    a, b = make(), make()
    with np.errstate(all="raise"), _quiet():
        whole = a.random(skip + n)
        b.fast_forward(skip)
        tail = b.random(n)
    assert tail.shape == (n, d) and tail.dtype == np.float64
    assert np.array_equal(whole[skip:], tail)
    assert np.all((tail >= 0) & (tail < 1))
    assert b.num_generated == skip + n


@settings(max_examples=40, deadline=None)
@given(
    lo=st.lists(st.integers(-50, 50), min_size=1, max_size=5),
    width=st.integers(1, 20),
    endpoint=st.booleans(),
)
def test_integers_stay_in_bounds(lo, width, endpoint):
    lo = np.array(lo)
    hi = lo + width
    with _quiet():
        x = qmc.Sobol(d=len(lo), rng=1).integers(lo, u_bounds=hi, n=64, endpoint=endpoint)
    assert x.shape == (64, len(lo)) and x.dtype == np.int64
    top = hi if endpoint else hi - 1
    assert np.all((x >= lo) & (x <= top))


def test_bad_arguments_raise_value_errors_naming_the_limit():
    with pytest.raises(ValueError, match="Maximum supported dimensionality is 4294967295"):
        qmc.Sobol(d=2**32)
    with pytest.raises(ValueError, match="d must be a non-negative integer value"):
        qmc.Halton(d=-1)
    with pytest.raises(ValueError, match="dims 2000 is outside 1..=1024"):
        qmc.Halton(d=2000).random(1)
    with pytest.raises(ValueError, match=r"At most 2\*\*4=16 distinct points"):
        qmc.Sobol(d=1, bits=4).random(32)
    with pytest.raises(ValueError, match="balance properties"):
        e = qmc.Sobol(d=1)
        e.random_base2(1)
        e.random_base2(2)
    with pytest.raises(ValueError, match="not a valid method"):
        qmc.discrepancy([[0.5]], method="XX")
    with pytest.raises(ValueError, match="not in unit hypercube"):
        qmc.discrepancy([[1.5]])
    with pytest.raises(ValueError, match="'toto' is not a valid optimization method"):
        qmc.Sobol(d=2, optimization="toto")
    with pytest.raises(ValueError, match="Maximum supported 'bits' is 64"):
        qmc.Sobol(d=2, bits=65)
    with pytest.raises(ValueError, match=r"bits 0: need at least 1"):
        qmc.Sobol(d=2, bits=0)
    with pytest.raises(TypeError, match="got multiple values for argument now known as `rng`"):
        qmc.Sobol(d=2, rng=1, seed=1)
    with pytest.warns(UserWarning, match="power of 2"):
        qmc.Sobol(d=1).random(3)


def test_sobol_past_2_32_points_and_1024_dimensions():
    # 64-bit indices: the points past 2**32 in Gray-code order are the core's sobol_u64 at
    # k ^ (k >> 1), checked here against Bratley and Fox's integer recurrence in Python big
    # integers for dimensions 0 to 3 (the reference file the core's test reads).
    ref = {}
    path = pathlib.Path(__file__).parents[2] / "core/src/sequence/sobol64_reference.txt"
    for line in path.read_text().splitlines():
        if not line.startswith("#"):
            d, i, v = map(int, line.split())
            ref[(d, i)] = v
    e = qmc.Sobol(d=4, scramble=False, bits=64)
    for (d, i), v in ref.items():
        if d < 4 and i ^ (i >> 1) < 2**64 - 2:
            # The Gray-code position k whose natural index is i: k = inverse Gray of i.
            k, g = 0, i
            while g:
                k ^= g
                g >>= 1
            e.reset()
            e.fast_forward(k)
            assert e.random(1)[0, d] == v / 2**32, (d, i)
    # Past 1024 dimensions: values in [0, 1), each padded block's pair stratified.
    x = qmc.Sobol(d=1500, scramble=False).random_base2(6)
    assert x.shape == (64, 1500) and np.all((x >= 0) & (x < 1))
    cells = set(zip((x[:, 1200] * 8).astype(int), (x[:, 1201] * 8).astype(int)))
    assert len(cells) == 64


def test_the_star_discrepancy_is_exact():
    # Centred points (2i + 1) / 2n have D* = 1 / 2n.
    for n in [1, 2, 7, 100]:
        x = ((2 * np.arange(n) + 1) / (2 * n)).reshape(-1, 1)
        assert qmc.discrepancy(x, method="star") == pytest.approx(1 / (2 * n), rel=1e-14)
    # The 2-D origin point: the box [0, 1)² minus nothing has volume 1, but the origin lies
    # in every anchored box: D* = 1.
    assert qmc.discrepancy([[0.0, 0.0]], method="star") == pytest.approx(1.0)


@needs_scipy
@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
def test_l2_discrepancies_are_scipys(method):
    x = np.random.default_rng(2).random((200, 4))
    ours = qmc.discrepancy(x, method=method)
    theirs = sqmc.discrepancy(x, method=method)
    assert ours == pytest.approx(theirs, rel=1e-10)


@needs_scipy
def test_scipy_takes_these_engines():
    engine = qmc.Sobol(d=2, rng=3)
    normal = sqmc.MultivariateNormalQMC(mean=[0, 0], engine=engine)
    z = normal.random(1024)
    assert z.shape == (1024, 2)
    assert abs(z.mean()) < 0.01 and abs(z.std() - 1) < 0.02


def test_the_scale_maps_and_maps_back():
    x = qmc.Halton(d=2, rng=1).random(10)
    y = qmc.scale(x, [-1, 10], [1, 20])
    assert np.all((y >= [-1, 10]) & (y < [1, 20]))
    assert np.allclose(qmc.scale(y, [-1, 10], [1, 20], reverse=True), x)
    with pytest.raises(ValueError, match="Bounds are not consistent"):
        qmc.scale(x, [1, 1], [0, 2])


class _quiet:
    """Silences the Sobol balance warning inside property tests."""

    def __enter__(self):
        import warnings

        self._ctx = warnings.catch_warnings()
        self._ctx.__enter__()
        warnings.simplefilter("ignore", UserWarning)

    def __exit__(self, *exc):
        return self._ctx.__exit__(*exc)


@pytest.mark.parametrize("engine", [qmc.PMJ02, qmc.ZeroTwo])
@pytest.mark.parametrize("scramble", [False, True])
def test_the_zero_two_sets_are_nets_at_every_power_of_two(engine, scramble):
    x = engine(d=2, scramble=scramble, rng=11).random(2**10)
    for m in range(1, 11):
        assert is_net(x[: 2**m], m), f"{engine.__name__} m={m}"


def test_lattices_are_their_generators():
    n, a = 13, 5
    x = qmc.Lattice(d=3, n=n, multiplier=a, scramble=False).random(n)
    i = np.arange(n)
    want = np.stack([i / n, (i * a % n) / n, (i * a * a % n) / n], axis=1)
    np.testing.assert_allclose(x, want, rtol=0, atol=1e-15)
    fib = qmc.Lattice(d=2, n=21, kind="fibonacci", scramble=False).random(21)
    np.testing.assert_allclose(fib[:, 1], (np.arange(21) * 13 % 21) / 21, rtol=0, atol=1e-15)
    with pytest.raises(ValueError, match="past the 13 points"):
        qmc.Lattice(d=2, n=13, multiplier=5).random(14)
    with pytest.raises(ValueError):
        qmc.Lattice(d=2, n=20, kind="fibonacci")  # not a Fibonacci number


def test_r2_is_the_golden_kronecker_sequence():
    x = qmc.R2(d=2, scramble=False).random(100)
    # φ₂ is the real root of x³ = x + 1; α = (1/φ₂, 1/φ₂²); Roberts starts at ½.
    phi = 1.324717957244746
    i = np.arange(100)[:, None]
    want = np.mod(0.5 + i * np.array([1 / phi, 1 / phi**2]), 1.0)
    np.testing.assert_allclose(x, want, rtol=0, atol=1e-12)


def test_named_engines_check_their_arguments_at_construction():
    with pytest.raises(ValueError, match="dims 3 is outside"):
        qmc.PMJ02(d=3)
    with pytest.raises(ValueError, match="kind 'x'"):
        qmc.Lattice(d=2, n=8, kind="x")
    e = qmc.ZeroTwo(d=2, rng=1)
    first = e.random(8)
    assert np.array_equal(e.reset().random(8), first)
    assert not np.array_equal(qmc.ZeroTwo(d=2, rng=2).random(8), first)
