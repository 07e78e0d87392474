"""The engines and measures beyond the sequences: Latin hypercubes, Poisson-disk sets, pixel
samplers, the discrepancy update and the geometric discrepancies, the t-value, the periodogram
and the filters. Properties with Hypothesis; SciPy's values where SciPy defines them."""

import itertools
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nyquist import analysis, pixel, qmc

try:
    import scipy.stats.qmc as sqmc
    from scipy.spatial.distance import pdist
except ImportError:  # pragma: no cover
    sqmc = None

needs_scipy = pytest.mark.skipif(sqmc is None, reason="SciPy is not installed")


def brute_t_value(x):
    """The t-value by listing every elementary box (NumPy), for small sets."""
    n, d = x.shape
    m = n.bit_length() - 1
    for t in range(m + 1):
        ok = True
        for k in itertools.product(range(m - t + 1), repeat=d):
            if sum(k) != m - t:
                continue
            cells = np.zeros(n, dtype=np.int64)
            for j, kj in enumerate(k):
                cells = cells * 2**kj + np.floor(x[:, j] * 2**kj).astype(np.int64)
            if not np.all(np.bincount(cells, minlength=2 ** (m - t)) == 2**t):
                ok = False
                break
        if ok:
            return t
    raise AssertionError("unreachable")


# Latin hypercubes


@settings(max_examples=60, deadline=None)
@given(n=st.integers(1, 3000), d=st.integers(1, 12), scramble=st.booleans(),
       seed=st.integers(0, 2**64 - 1))
def test_latin_hypercubes_put_one_point_in_each_stratum(n, d, scramble, seed):
    x = qmc.LatinHypercube(d, scramble=scramble, rng=seed).random(n)
    assert x.shape == (n, d) and x.dtype == np.float64
    assert np.all((x >= 0) & (x < 1))
    strata = np.floor(x * n).astype(np.int64)
    assert np.all(np.sort(strata, axis=0) == np.arange(n)[:, None])
    if not scramble:
        assert np.array_equal(np.sort(x, axis=0), np.broadcast_to((np.arange(n)[:, None] + 0.5) / n, x.shape))


@pytest.mark.parametrize("p", [2, 3, 5, 7])
@pytest.mark.parametrize("scramble", [False, True])
def test_strength_two_puts_one_point_in_each_coarse_cell_of_every_pair(p, scramble):
    n, d = p * p, p + 1
    x = qmc.LatinHypercube(d, strength=2, scramble=scramble, rng=p).random(n)
    assert np.all(np.sort(np.floor(x * n), axis=0) == np.arange(n)[:, None])
    for i, j in itertools.combinations(range(d), 2):
        cells = np.floor(x[:, i] * p) * p + np.floor(x[:, j] * p)
        assert sorted(cells.tolist()) == list(range(n))


def test_latin_hypercubes_are_new_each_draw_and_repeat_after_reset():
    e = qmc.LatinHypercube(3, rng=11)
    a, b = e.random(64), e.random(64)
    assert not np.array_equal(a, b)
    e.reset()
    assert np.array_equal(e.random(64), a)
    # The dimensions are independent permutations: two columns are not the same permutation.
    assert not np.array_equal(np.argsort(a[:, 0]), np.argsort(a[:, 1]))


# Poisson-disk sets


def min_distance(x):
    diff = x[:, None, :] - x[None, :, :]
    dist = np.sqrt((diff**2).sum(-1))
    dist[np.diag_indices(len(x))] = np.inf
    return dist.min() if len(x) > 1 else np.inf


@settings(max_examples=40, deadline=None)
@given(d=st.integers(1, 4), radius=st.floats(0.08, 0.4), surface=st.booleans(),
       lower=st.floats(-3, 3), width=st.floats(0.5, 3), seed=st.integers(0, 2**32),
       n=st.integers(1, 80))
def test_poisson_disk_sets_keep_their_radius_and_their_box(d, radius, surface, lower, width,
                                                           seed, n):
    e = qmc.PoissonDisk(d, radius=radius, hypersphere="surface" if surface else "volume",
                        rng=seed, l_bounds=[lower] * d, u_bounds=[lower + width] * d)
    first = e.random(n)
    more = e.random(n)
    assert 1 <= len(first) <= n and len(more) <= n
    both = np.concatenate([first, more])
    assert np.all((both >= lower) & (both < lower + width))
    assert min_distance(both) >= radius
    assert e.num_generated == len(both)
    e.reset()
    assert np.array_equal(e.random(n), first)


def test_fill_space_leaves_little_room_in_the_square():
    # Bridson's sets in the unit square at r = 0.05 cover it well: the fraction of random probes
    # farther than r from every point is small (maximal sets have none).
    x = qmc.PoissonDisk(2, radius=0.05, rng=3).fill_space()
    assert min_distance(x) >= 0.05
    probes = np.random.default_rng(0).random((20000, 2))
    far = np.sqrt(((probes[:, None, :] - x[None, :, :]) ** 2).sum(-1)).min(1) >= 0.05
    assert far.mean() < 0.02
    assert 250 < len(x) < 400


def test_poisson_disk_refuses_bad_arguments():
    with pytest.raises(ValueError, match=r"radius -1 is outside \(0, ∞\)"):
        qmc.PoissonDisk(2, radius=-1.0)
    with pytest.raises(ValueError, match="more than 134217728 cells"):
        qmc.PoissonDisk(6, radius=0.01)
    with pytest.raises(ValueError, match="not a valid hypersphere"):
        qmc.PoissonDisk(2, hypersphere="shell")
    assert qmc.PoissonDisk(0).random(3).shape == (3, 0)


# Pixel samplers


@pytest.mark.parametrize("sampler", ["zsobol", "pmj02", "owen-sobol", "sobol", "zero-two"])
def test_pixel_samplers_image_samples_are_nets(sampler):
    x = pixel.samples(sampler, (5, 3), 256, 6, size=(16, 16), seed=9)
    assert x.shape == (256, 6)
    assert np.all((x >= 0) & (x < 1))
    # ZSobol shuffles the base-4 digits of the sample index, so its prefixes are nets at
    # powers of 4 (and at spp); the others at every power of 2.
    for m in range(0, 9, 2 if sampler == "zsobol" else 1):
        n = 2**m
        assert brute_t_value(x[:n, :2]) == 0, (sampler, m)


@settings(max_examples=40, deadline=None)
@given(first=st.integers(0, 200), n=st.integers(0, 50), d=st.integers(1, 9),
       kind=st.sampled_from(["zsobol", "best-candidate", "pmj02", "halton"]))
def test_pixel_sampler_engines_fast_forward_and_match_the_function(first, n, d, kind):
    e = qmc.PixelSampler(d, kind, pixel=(2, 1), size=(4, 4), spp=256, rng=5)
    f = qmc.PixelSampler(d, kind, pixel=(2, 1), size=(4, 4), spp=256, rng=5)
    whole = e.random(first + n)
    f.fast_forward(first)
    assert np.array_equal(f.random(n), whole[first:])
    again = pixel.samples(kind, (2, 1), n, d, first=first, size=(4, 4), spp=256, seed=e._seed)
    assert np.array_equal(again, whole[first:])


def test_zsobol_and_best_candidate_engines():
    z = qmc.ZSobol(2, pixel=(1, 1), size=(4, 4), spp=64, rng=1).random(64)
    assert brute_t_value(z) == 0
    b = qmc.BestCandidate(2, spp=64, rng=1).random(64)
    # Best-candidate image samples are spread: their toroidal minimum distance beats random
    # points' by far (random 64 points: about 0.02).
    diff = np.abs(b[:, None, :] - b[None, :, :])
    diff = np.minimum(diff, 1 - diff)
    dist = np.sqrt((diff**2).sum(-1)) + np.eye(64) * 9
    assert dist.min() > 0.07


def test_pixel_samples_refuse_bad_requests():
    with pytest.raises(ValueError, match=r"pixel \(4, 0\) is outside the 4×4 image"):
        pixel.samples("zsobol", (4, 0), 4, 2, size=(4, 4), spp=4)
    with pytest.raises(ValueError, match="past the 4 samples per pixel"):
        pixel.samples("zsobol", (0, 0), 4, 2, first=1, size=(4, 4), spp=4)
    with pytest.raises(ValueError, match="unknown"):
        pixel.samples("nope", (0, 0), 4, 2)
    with pytest.raises(ValueError, match="scramble 'x' is not one of"):
        pixel.samples("sobol", (0, 0), 4, 2, scramble="x")
    plain = pixel.samples("sobol", (0, 0), 4, 2, scramble="none", seed=1)
    assert np.array_equal(plain, pixel.samples("sobol", (0, 0), 4, 2, scramble="none", seed=2))


# Discrepancy update, iterative and geometric discrepancies


@settings(max_examples=60, deadline=None)
@given(n=st.integers(1, 60), d=st.integers(1, 8), seed=st.integers(0, 2**32))
def test_update_discrepancy_equals_the_whole_sets(n, d, seed):
    x = np.random.default_rng(seed).random((n + 1, d))
    initial = qmc.discrepancy(x[:-1], iterative=True)
    updated = qmc.update_discrepancy(x[-1], x[:-1], initial)
    assert abs(updated - qmc.discrepancy(x)) < 1e-13 * (1 + qmc.discrepancy(x))


@needs_scipy
@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
def test_iterative_discrepancies_are_scipys(method):
    x = np.random.default_rng(7).random((40, 5))
    ours = qmc.discrepancy(x, method=method, iterative=True)
    theirs = sqmc.discrepancy(x, method=method, iterative=True)
    assert abs(ours - theirs) < 1e-10


@needs_scipy
@pytest.mark.parametrize("metric", ["euclidean", "cityblock", "chebyshev"])
@pytest.mark.parametrize("method", ["mindist", "mst"])
def test_geometric_discrepancies_are_scipys(method, metric):
    x = np.random.default_rng(3).random((300, 3))
    ours = qmc.geometric_discrepancy(x, method=method, metric=metric)
    theirs = sqmc.geometric_discrepancy(x, method=method, metric=metric)
    assert abs(ours - theirs) < 1e-12
    if method == "mindist":
        assert abs(ours - pdist(x, metric=metric).min()) < 1e-15


def test_geometric_discrepancy_counts_zero_edges_and_warns():
    x = [[0, 0], [0, 0], [0, 1]]
    with pytest.warns(UserWarning, match="duplicate"):
        assert qmc.geometric_discrepancy(x, method="mst") == 0.5
    with pytest.warns(UserWarning, match="duplicate"):
        assert qmc.geometric_discrepancy(x) == 1.0
    with pytest.raises(ValueError, match="metric 'hamming' is not one of"):
        qmc.geometric_discrepancy([[0, 0], [1, 1]], metric="hamming")
    with pytest.raises(ValueError, match="iterative=True: the star discrepancy"):
        qmc.discrepancy([[0.5]], method="star", iterative=True)


# t-value and periodogram


@settings(max_examples=60, deadline=None)
@given(m=st.integers(0, 7), d=st.integers(1, 3), seed=st.integers(0, 2**32),
       kind=st.sampled_from(["random", "sobol", "halton", "lhs"]))
def test_t_value_agrees_with_brute_force(m, d, seed, kind):
    n = 2**m
    x = {
        "random": lambda: np.random.default_rng(seed).random((n, d)),
        "sobol": lambda: qmc.Sobol(d, rng=seed).random_base2(m),
        "halton": lambda: qmc.Halton(d, rng=seed).random(n),
        "lhs": lambda: qmc.LatinHypercube(d, rng=seed).random(n),
    }[kind]()
    assert analysis.t_value(x) == brute_t_value(x)


def test_t_values_of_known_nets_and_refusals():
    for m in range(12):
        assert analysis.t_value(qmc.Sobol(2, rng=m).random_base2(m)) == 0
        assert analysis.t_value(qmc.PMJ02(2, rng=m).random(2**m)) == 0
    with pytest.raises(ValueError, match="points 3 is not a power of 2"):
        analysis.t_value(np.full((3, 1), 0.5))
    with pytest.raises(ValueError, match=r"outside \[0, 1\)"):
        analysis.t_value(np.ones((2, 1)))
    with pytest.raises(ValueError, match="above max_work"):
        analysis.t_value(np.zeros((2**20, 12)))


def test_periodogram_of_known_sets():
    one = analysis.periodogram(np.array([[0.3, 0.8]]), max_freq=4)
    assert one.power.shape == (9, 9)
    assert np.allclose(one.power, 1.0)
    grid = (np.stack(np.meshgrid(np.arange(8), np.arange(8)), -1).reshape(-1, 2) + 0.5) / 8
    p = analysis.periodogram(grid, max_freq=8)
    # A regular 8 × 8 grid has power N at multiples of 8 on each axis and 0 elsewhere.
    expect = np.zeros((17, 17))
    for fy in (-8, 0, 8):
        for fx in (-8, 0, 8):
            expect[fy + 8, fx + 8] = 64
    assert np.allclose(p.power, expect, atol=1e-9)
    rng = np.random.default_rng(2)
    sets = rng.random((5, 100, 2))
    avg = analysis.periodogram(sets, max_freq=6).power
    each = np.mean([analysis.periodogram(s, max_freq=6).power for s in sets], axis=0)
    assert np.allclose(avg, each, rtol=1e-12)


# Filters


def test_filters_tables_and_importance_sampling():
    box = pixel.Filter("box")
    assert box.radius == (0.5, 0.5) and box.integral == 1.0 and box.separable
    m = pixel.Filter("mitchell")
    # Mitchell–Netravali at B = C = 1/3: k(0) = (6 − 2B)/6 = 8/9 per axis.
    assert abs(float(m.evaluate(np.zeros(1), np.zeros(1))[0]) - (8 / 9) ** 2) < 1e-6
    values, xs, ys = m.table(16)
    assert values.shape == (16, 16)
    assert np.allclose(values, m.evaluate(np.repeat(xs[None, :], 16, 0).ravel().astype(float),
                                          np.repeat(ys[:, None], 16, 1).ravel().astype(float))
                       .reshape(16, 16), atol=1e-7)
    u = qmc.Sobol(2, rng=1).random_base2(14)
    for spec in ["gaussian:sigma=0.5", "mitchell", "lanczos", "triangle", "blackman-harris"]:
        f = pixel.Filter(spec)
        offsets, weights = f.sample(u)
        rx, ry = f.radius
        assert np.all(np.abs(offsets[:, 0]) <= rx) and np.all(np.abs(offsets[:, 1]) <= ry)
        assert abs(weights.mean() - f.integral) < 2e-3 * abs(f.integral), spec
        # The density integrates to 1 over the support (midpoint rule, 200 × 200).
        g = (np.arange(200) + 0.5) / 200 * 2 - 1
        gx, gy = np.meshgrid(g * rx, g * ry)
        pdf = f.pdf(np.stack([gx.ravel(), gy.ravel()], -1))
        assert abs(pdf.sum() * (2 * rx / 200) * (2 * ry / 200) - 1) < 1e-2, spec
    with pytest.raises(ValueError, match="filter spec"):
        pixel.Filter("mitchell:b=x")
    with pytest.raises(ValueError, match="outside"):
        pixel.Filter("box").sample(np.array([[0.5, 1.5]]))
    with pytest.raises(ValueError, match="n 12 is not one of 8, 16, 32, 64"):
        pixel.Filter("box").table(12)


def test_everything_is_quiet_on_good_input():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        qmc.geometric_discrepancy(np.random.default_rng(1).random((50, 2)))
        qmc.LatinHypercube(2, rng=1).random(10)


def test_the_readme_example_runs_as_printed():
    import pathlib
    import re

    readme = pathlib.Path(__file__).resolve().parents[2] / "README.md"
    if not readme.exists():  # pragma: no cover - an installed copy without the repository
        pytest.skip("README.md is not beside the tests")
    block = re.search(r"```python\n(.*?)```", readme.read_text(), re.S).group(1)
    scope = {}
    exec(block, scope)
    assert scope["analysis"].t_value(scope["x"]) == 0
    assert 0 < scope["qmc"].discrepancy(scope["x"], method="star") < 0.01


def test_hostile_requests_raise_python_errors():
    # An allocation that cannot succeed is a MemoryError, not an aborted interpreter.
    with pytest.raises(MemoryError):
        qmc.Halton(1024, scramble=False).random(2**40)
    with pytest.raises(MemoryError):
        qmc.LatinHypercube(1024, rng=1).random(2**32 - 1)
    with pytest.raises(ValueError, match="n 1099511627776 is above 4294967295"):
        qmc.LatinHypercube(2, rng=1).random(2**40)
    # Indices past what the Rust side takes are ValueErrors, not OverflowErrors.
    with pytest.raises(ValueError, match="past the points this engine indexes"):
        qmc.Halton(2).fast_forward(2**64).random(1)
    with pytest.raises(ValueError, match="past the points this engine indexes"):
        qmc.PixelSampler(2, "zsobol", spp=16, rng=1).fast_forward(2**40).random(1)
    with pytest.raises(ValueError, match="must be a non-negative integer"):
        pixel.samples("zsobol", (-1, 0), 4, 2)
    with pytest.raises(ValueError, match="must fit in 32 bits"):
        pixel.samples("zsobol", (0, 0), 2**33, 2)
    with pytest.raises(ValueError, match="max_freq -1 must be a positive integer"):
        analysis.periodogram(np.zeros((1, 2)), max_freq=-1)
    assert pixel.samples("sobol", (0, 0), 0, 2).shape == (0, 2)
    with pytest.raises(ValueError, match="no two distinct points"):
        qmc.geometric_discrepancy([[0.5, 0.5], [0.5, 0.5]])


def test_poisson_disk_in_twelve_dimensions_finishes():
    # (2·⌈√12⌉ + 1)^12 neighbour cells would be 2.8·10¹¹ per candidate; the grid's edges and
    # the point list bound the work instead.
    e = qmc.PoissonDisk(12, radius=1.0, l_bounds=[0] * 12, u_bounds=[1.15] * 12,
                        hypersphere="surface", ncandidates=2000, rng=1)
    x = e.random(3)
    assert min_distance(x) >= 1.0
    assert len(qmc.PoissonDisk(2, radius=0.2, rng=2).random(np.inf)) > 10


def test_filters_take_array_likes_and_name_bad_shapes():
    f = pixel.Filter("mitchell")
    assert f.evaluate([0.0, 0.5], [0.0, 0.5]).shape == (2,)
    assert np.array_equal(f.evaluate(np.array([0, 1]), 0), f.evaluate([0.0, 1.0], [0.0, 0.0]))
    u = np.random.default_rng(1).random((100, 3))
    offsets, weights = f.sample(u[:, :2])  # not contiguous
    assert offsets.shape == (100, 2) and weights.shape == (100,)
    assert f.pdf(u[:, 1:]).shape == (100,)
    with pytest.raises(ValueError, match=r"u must have shape \(n, 2\), not \(100, 3\)"):
        f.sample(u)


def test_engines_follow_scipys_semantics_for_skips_and_unscrambled_pixels():
    e = qmc.LatinHypercube(3, strength=2, rng=4)
    first, second = e.random(9), e.random(9)
    e.reset()
    e.fast_forward(9)
    assert np.array_equal(e.random(9), second) and not np.array_equal(second, first)
    for sampler in ["zsobol", "pmj02", "sobol"]:
        a = qmc.PixelSampler(2, sampler, spp=16, scramble=False, rng=1).random(16)
        b = qmc.PixelSampler(2, sampler, spp=16, scramble=False, rng=2).random(16)
        assert np.array_equal(a, b), sampler
