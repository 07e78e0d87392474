"""How often SciPy's ``TestPoisson::test_optimizers[lloyd]`` condition holds, over seeds.

The test draws 64 Poisson-disk points with and without Lloyd relaxation from one seed and asks
that the relaxation increase the minimum pairwise L1 distance. This script counts the seeds
0..99 for which that holds, with SciPy's own PoissonDisk and with nyquist's:

    python python/tests/lloyd_rates.py
"""

import warnings

from scipy.stats import qmc as scipy_qmc
from scipy.stats._qmc import _l1_norm

from nyquist import qmc as nyquist_qmc

warnings.simplefilter("ignore")
for name, engine in [("scipy", scipy_qmc.PoissonDisk), ("nyquist", nyquist_qmc.PoissonDisk)]:
    held = 0
    for seed in range(100):
        plain = engine(d=2, seed=seed).random(64)
        relaxed = engine(d=2, seed=seed, optimization="lloyd").random(64)
        held += bool(_l1_norm(relaxed) > _l1_norm(plain))
    print(f"{name}: the condition holds for {held} of 100 seeds")
