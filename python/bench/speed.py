"""nyquist.qmc against scipy.stats.qmc in one process: the median wall time of several
interleaved runs of each case (nyquist, SciPy, nyquist, …), their ratio, and a check that both
results follow the same law (the same points where both are deterministic, the net or
stratification property where they are scrambled or random, the Poisson-disk radius, the same
discrepancy to 1e-10 absolute).

    python python/bench/speed.py [runs]      # default 7

Prints a Markdown table (docs/python.md).
"""

import statistics
import sys
import time

import numpy as np
from scipy.stats import qmc as scipy_qmc

from nyquist import qmc


def is_net(points, m):
    """(0, m, 2)-net in base 2: every elementary box of area 2**-m holds one point."""
    for j in range(m + 1):
        k = m - j
        ix = np.floor(points[:, 0] * 2**j).astype(np.int64)
        iy = np.floor(points[:, 1] * 2**k).astype(np.int64)
        if not np.all(np.bincount(ix * 2**k + iy, minlength=2**m) == 1):
            return False
    return True


def stratified(column, n):
    """One value in each interval [i/n, (i+1)/n)."""
    return np.array_equal(np.sort(np.floor(column * n).astype(np.int64)), np.arange(n))


def sobol(d, scramble):
    def run(module):
        return module.Sobol(d=d, scramble=scramble, rng=1).random_base2(20)

    def check(ours, theirs):
        if not scramble:
            return np.array_equal(ours, theirs)
        return is_net(ours[:, :2], 20) and is_net(theirs[:, :2], 20)

    return run, check


def halton():
    def run(module):
        return module.Halton(d=8, scramble=True, rng=1).random(10**6)

    def check(ours, theirs):
        # The first 2**19 points in base 2 and 3**12 in base 3: one per interval.
        return all(
            stratified(x[: 2**19, 0], 2**19) and stratified(x[: 3**12, 1], 3**12)
            for x in (ours, theirs)
        )

    return run, check


def centered_discrepancy():
    sample = np.random.default_rng(5).random((10**4, 4))

    def run(module):
        return module.discrepancy(sample, method="CD")

    def check(ours, theirs):
        # An absolute agreement: CD² (about 1e-4 here) is the difference of terms near 1.4,
        # so each side's rounding is some 1e-12 absolute.
        return abs(ours - theirs) <= 1e-10

    return run, check


def latin_hypercube():
    def run(module):
        return module.LatinHypercube(d=8, rng=1).random(10**6)

    def check(ours, theirs):
        return all(stratified(x[:, j], 10**6) for x in (ours, theirs) for j in range(8))

    return run, check


def poisson_disk():
    # Radius 0.005 leaves room for about 3·10⁴ points, so both stop at 10⁴.
    def run(module):
        return module.PoissonDisk(d=2, radius=0.005, rng=1).random(10**4)

    def check(ours, theirs):
        from scipy.spatial import cKDTree

        def ok(x):
            nearest, _ = cKDTree(x).query(x, k=2)
            return len(x) == 10**4 and nearest[:, 1].min() >= 0.005

        return ok(ours) and ok(theirs)

    return run, check


CASES = [
    ("Sobol `random_base2(20)`, d = 2", *sobol(2, False)),
    ("Sobol `random_base2(20)`, d = 2, scrambled", *sobol(2, True)),
    ("Sobol `random_base2(20)`, d = 32", *sobol(32, False)),
    ("Sobol `random_base2(20)`, d = 32, scrambled", *sobol(32, True)),
    ("Halton 10⁶ × 8, scrambled", *halton()),
    ("Latin hypercube 10⁶ × 8", *latin_hypercube()),
    ("Poisson disk, 10⁴ points in 2-D", *poisson_disk()),
    ("centered discrepancy of 10⁴ × 4", *centered_discrepancy()),
]


def timed(f):
    start = time.perf_counter()
    out = f()
    return time.perf_counter() - start, out


def main(runs):
    import scipy

    import nyquist

    print(f"nyquist {nyquist.__version__}, SciPy {scipy.__version__}, NumPy {np.__version__};"
          f" median of {runs} interleaved runs\n")
    print("| case | nyquist | SciPy | SciPy / nyquist | same law |")
    print("|---|---|---|---|---|")
    for name, run, check in CASES:
        ours_t, theirs_t = [], []
        ours = theirs = None
        for _ in range(runs):
            t, ours = timed(lambda: run(qmc))
            ours_t.append(t)
            t, theirs = timed(lambda: run(scipy_qmc))
            theirs_t.append(t)
        a, b = statistics.median(ours_t), statistics.median(theirs_t)
        ok = "yes" if check(ours, theirs) else "**no**"
        print(f"| {name} | {a * 1e3:.1f} ms | {b * 1e3:.1f} ms | {b / a:.1f}× | {ok} |")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
