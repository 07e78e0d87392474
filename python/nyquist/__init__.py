"""nyquist: sampling and reconstruction for image synthesis, from Python.

``nyquist.qmc`` has quasi-Monte Carlo engines and discrepancies with the interface of SciPy's
``scipy.stats.qmc``, computed by the Rust library (``nyquist._core``).

>>> import nyquist
>>> nyquist.qmc.discrepancy([[0.25], [0.75]], method="star")
0.25
"""

from . import analysis, pixel, qmc

__all__ = ["analysis", "pixel", "qmc"]
__version__ = "0.1.0"
