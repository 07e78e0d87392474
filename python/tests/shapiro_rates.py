"""How often SciPy's fixed-seed normality checks of MultivariateNormalQMC hold, over seeds, with
SciPy's own Sobol engine and with nyquist's: the figures behind two entries of
scipy_expected.txt. The checks are those of SciPy's test_NormalQMCShapiro and
test_MultivariateNormalQMCShapiroInvTransform: 256 points, |mean| < 0.01, |std − 1| < 0.01,
Shapiro–Wilk p > 0.9 for each coordinate, |cov| < 0.01.

    python python/tests/shapiro_rates.py [seeds]
"""

import sys

import numpy as np
import scipy.stats._qmc as private
from scipy.stats import qmc, shapiro

from nyquist import qmc as nyquist_qmc


def holds(rng, inv_transform):
    engine = qmc.MultivariateNormalQMC(
        mean=[0, 0], cov=[[1, 0], [0, 1]], rng=rng, inv_transform=inv_transform
    )
    x = engine.random(256)
    return bool(
        np.all(np.abs(x.mean(axis=0)) < 1e-2)
        and np.all(np.abs(x.std(axis=0) - 1) < 1e-2)
        and all(shapiro(x[:, i])[1] > 0.9 for i in (0, 1))
        and abs(np.cov(x.T)[0, 1]) < 1e-2
    )


def main(seeds):
    scipy_sobol = private.Sobol
    for name, engine in [("scipy", scipy_sobol), ("nyquist", nyquist_qmc.Sobol)]:
        private.Sobol = engine  # MultivariateNormalQMC builds its engine from this name
        for inv in (False, True):
            n = sum(holds(np.random.default_rng(k), inv) for k in range(seeds))
            kind = "inverse transform" if inv else "Box-Muller"
            print(f"{name:8} {kind:17} {n} of {seeds} seeds")
    private.Sobol = scipy_sobol


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 400)
