"""Type stubs of the extension module ``nyquist._core``."""

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]

def sobol(
    n: int, d: int, first: int = 0, seed: int | None = None, bits: int = 32
) -> Array: ...
def halton(
    n: int, d: int, first: int = 0, seed: int | None = None, scramble: str = "permute-positions"
) -> Array: ...
def sequence(
    name: str,
    n: int,
    d: int,
    first: int = 0,
    seed: int | None = None,
    points: int | None = None,
    multiplier: int | None = None,
) -> Array: ...
def latin_hypercube(n: int, d: int, seed: int, centered: bool = False) -> Array: ...
def discrepancy(sample: Array, method: str, iterative: bool = False) -> float: ...
def update_discrepancy(x_new: npt.NDArray[np.float64], sample: Array, initial: float) -> float: ...
def geometric_discrepancy(sample: Array, method: str, metric_name: str) -> tuple[float, bool]: ...
def t_value(sample: Array) -> int: ...
def periodogram(
    sets: npt.NDArray[np.float64], max_freq: int
) -> tuple[Array, npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def pixel_samples(
    name: str,
    pixel: tuple[int, int],
    n: int,
    d: int,
    *,
    first: int = 0,
    size: tuple[int, int] = (1, 1),
    spp: int | None = None,
    seed: int = 0,
    scramble: str | None = None,
) -> Array: ...

class PoissonDiskState:
    def __init__(
        self,
        radius: float,
        lower: list[float],
        upper: list[float],
        surface: bool,
        candidates: int,
        seed: int,
    ) -> None: ...
    def extend(self, n: int | None = None) -> Array: ...
    def __len__(self) -> int: ...

class Filter:
    def __init__(self, spec: str) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def spec(self) -> str: ...
    @property
    def radius(self) -> tuple[float, float]: ...
    @property
    def integral(self) -> float: ...
    @property
    def separable(self) -> bool: ...
    def evaluate(
        self, x: npt.NDArray[np.float64], y: npt.NDArray[np.float64]
    ) -> npt.NDArray[np.float32]: ...
    def table(
        self, n: int = 16
    ) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    def sample(
        self, u: Array
    ) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    def pdf(self, offsets: Array) -> npt.NDArray[np.float32]: ...
