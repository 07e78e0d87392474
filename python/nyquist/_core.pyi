"""Type stubs of the extension module ``nyquist._core``."""

import numpy as np
import numpy.typing as npt

def sobol(
    n: int, d: int, first: int = 0, seed: int | None = None, bits: int = 32
) -> npt.NDArray[np.float64]: ...
def halton(
    n: int, d: int, first: int = 0, seed: int | None = None
) -> npt.NDArray[np.float64]: ...
def discrepancy(sample: npt.NDArray[np.float64], method: str) -> float: ...
def sequence(
    name: str,
    n: int,
    d: int,
    first: int = 0,
    seed: int | None = None,
    points: int | None = None,
    multiplier: int | None = None,
) -> npt.NDArray[np.float64]: ...
