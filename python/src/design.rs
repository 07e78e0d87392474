//! Random designs of SciPy's interface: Latin hypercubes and incremental Poisson-disk sets in
//! any dimension.

use numpy::{IntoPyArray, PyArray2, PyArrayMethods};
use pyo3::prelude::*;

use nyquist::hash::{hash2, unit_f64, wyrand};
use nyquist::rng::{DefaultRng, default_rng, uniform_below, uniform_below_u64, uniform_f64};

use crate::{filled, par_rows, value_error, values};

/// `n` Latin-hypercube points in `d` dimensions as an `(n, d)` float64 array: in every dimension
/// the values fall one in each stratum `[k/n, (k+1)/n)`, the strata assigned to points by an
/// independent uniform permutation per dimension (an inside-out Fisher–Yates over `u32`s from
/// the core's PCG32, keyed by `hash2(seed, dimension)`, the dimensions shared among the
/// threads), each value jittered uniformly inside its stratum (`wyrand` of the point's index,
/// so the rows fill in parallel), or at its centre with `centered`. At most 2³² points.
#[pyfunction]
#[pyo3(signature = (n, d, seed, centered=false))]
pub fn latin_hypercube<'py>(
    py: Python<'py>,
    n: u64,
    d: u32,
    seed: u64,
    centered: bool,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let len = values(n, d)?;
    if n > u64::from(u32::MAX) {
        return Err(value_error(format!(
            "n {n} is above {} for a Latin hypercube",
            u32::MAX
        )));
    }
    let rows = n as usize;
    let dims = d as usize;
    let mut strata = filled(len, 0u32)?;
    let mut out = filled(len, 0.0)?;
    py.detach(|| {
        let threads = std::thread::available_parallelism().map_or(1, |t| t.get());
        let per = dims.div_ceil(threads).max(1);
        std::thread::scope(|scope| {
            for (k, block) in strata.chunks_mut((per * rows).max(1)).enumerate() {
                scope.spawn(move || {
                    for (j, column) in block.chunks_mut(rows.max(1)).enumerate() {
                        shuffle_strata(column, hash2(seed, (k * per + j) as u64));
                    }
                });
            }
        });
        let count = n as f64;
        let keys: Vec<u64> = (0..d)
            .map(|j| hash2(seed ^ 0x5bd1_e995, u64::from(j)))
            .collect();
        par_rows(&mut out, dims, 0, |first, block| {
            for (i, row) in (first as usize..).zip(block.chunks_exact_mut(dims)) {
                for (j, x) in row.iter_mut().enumerate() {
                    let jitter = if centered {
                        0.5
                    } else {
                        unit_f64(wyrand(keys[j], i as u64))
                    };
                    let v = (f64::from(strata[j * rows + i]) + jitter) / count;
                    *x = v.min(nyquist::ONE_MINUS_EPSILON_F64);
                }
            }
        });
    });
    out.into_pyarray(py).reshape([rows, dims])
}

/// A uniform permutation of the strata `0..column.len()`, in place: an inside-out
/// Fisher–Yates (after step k, positions 0..=k hold a uniform permutation of 0..=k).
fn shuffle_strata(column: &mut [u32], key: u64) {
    let mut rng = default_rng(key);
    for k in 0..column.len() {
        let j = uniform_below(&mut rng, k as u32 + 1) as usize;
        column[k] = column[j];
        column[j] = k as u32;
    }
}

/// Cells the Poisson-disk grid may have (2²⁷ `u32`s, 512 MiB).
const MAX_CELLS: u64 = 1 << 27;

const EMPTY: u32 = u32::MAX;

/// An incremental Poisson-disk set in a box of any dimension, by Bridson's algorithm ("Fast
/// Poisson disk sampling in arbitrary dimensions", SIGGRAPH 2007 sketches): a background grid
/// of cell side `r/√d` (at most one point per cell) and an active list. Each step picks a
/// random active point and throws up to `candidates` candidates around it; the first one at
/// least `r` from every point (checked against the `⌈√d⌉` neighbouring cells on each side) is
/// added, and a point whose candidates all fail is retired. `extend(n)` continues the same set,
/// so successive calls give one Poisson-disk set.
///
/// Candidates are uniform in the shell `r ≤ |x − c| < 2r` (`volume`) or on the sphere of radius
/// `1.001·r` (`surface`); SciPy's `PoissonDisk` draws its volume candidates in the whole ball of
/// radius `2r`, where those within `r` are always rejected, so a candidate count means more
/// here. The box is `[lower, upper)`.
#[pyclass(module = "nyquist._core")]
pub struct PoissonDiskState {
    radius: f64,
    lower: Vec<f64>,
    upper: Vec<f64>,
    cell: f64,
    shape: Vec<usize>,
    reach: u32,
    surface: bool,
    candidates: u32,
    grid: Vec<u32>,
    points: Vec<f64>,
    active: Vec<u32>,
    rng: DefaultRng,
}

#[pymethods]
impl PoissonDiskState {
    /// An empty set in the box `[lower, upper)` (one bound per dimension).
    #[new]
    #[pyo3(signature = (radius, lower, upper, surface, candidates, seed))]
    fn new(
        radius: f64,
        lower: Vec<f64>,
        upper: Vec<f64>,
        surface: bool,
        candidates: u32,
        seed: u64,
    ) -> PyResult<Self> {
        let d = lower.len();
        if !(radius.is_finite() && radius > 0.0) {
            return Err(value_error(format!("radius {radius} is outside (0, ∞)")));
        }
        if candidates == 0 {
            return Err(value_error("ncandidates 0 is outside 1..=4294967295"));
        }
        if upper.len() != d || d == 0 {
            return Err(value_error("the bounds must have one value per dimension"));
        }
        if d > 64 {
            return Err(value_error(format!(
                "d {d} is outside 1..=64 for a Poisson-disk set (a grid of 3 cells per side would have 3^{d} cells)"
            )));
        }
        let cell = radius / (d as f64).sqrt();
        let mut shape = Vec::with_capacity(d);
        let mut cells = 1u64;
        for (l, u) in lower.iter().zip(&upper) {
            if !(l.is_finite() && u.is_finite() && l < u) {
                return Err(value_error(
                    "Bounds are not consistent 'l_bounds' < 'u_bounds'",
                ));
            }
            let side = ((u - l) / cell).ceil().max(1.0);
            cells = cells.saturating_mul(side.min(u64::MAX as f64) as u64);
            if cells > MAX_CELLS {
                return Err(value_error(format!(
                    "radius {radius}: the Poisson-disk grid of cells of side r/√d = {cell} has more than {MAX_CELLS} cells; take a larger radius or fewer dimensions"
                )));
            }
            shape.push(side as usize);
        }
        Ok(PoissonDiskState {
            radius,
            lower,
            upper,
            cell,
            shape,
            reach: (d as f64).sqrt().ceil() as u32,
            surface,
            candidates,
            grid: vec![EMPTY; cells as usize],
            points: Vec::new(),
            active: Vec::new(),
            rng: default_rng(seed),
        })
    }

    /// Adds up to `n` points (`None`: until no active point is left, the set then being
    /// saturated for these candidates) and returns them as an `(k, d)` array, `k ≤ n`.
    #[pyo3(signature = (n=None))]
    fn extend<'py>(
        &mut self,
        py: Python<'py>,
        n: Option<u64>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let d = self.lower.len();
        let start = self.points.len();
        py.detach(|| self.grow(n.unwrap_or(u64::MAX)));
        let new = self.points[start..].to_vec();
        let k = new.len() / d;
        new.into_pyarray(py).reshape([k, d])
    }

    /// The number of points so far.
    fn __len__(&self) -> usize {
        self.points.len() / self.lower.len()
    }
}

impl PoissonDiskState {
    fn grow(&mut self, n: u64) {
        let d = self.lower.len();
        let mut drawn = 0u64;
        let mut candidate = vec![0.0; d];
        if self.points.is_empty() && n > 0 {
            for (j, c) in candidate.iter_mut().enumerate() {
                let (l, u) = (self.lower[j], self.upper[j]);
                *c = (l + uniform_f64(&mut self.rng) * (u - l)).min(prev(u));
            }
            self.insert(&candidate);
            drawn = 1;
        }
        let mut direction = vec![0.0; d];
        while drawn < n && !self.active.is_empty() {
            let slot = uniform_below_u64(&mut self.rng, self.active.len() as u64) as usize;
            let centre = self.active[slot] as usize * d;
            let mut found = false;
            for _ in 0..self.candidates {
                self.direction(&mut direction);
                let r = if self.surface {
                    1.001 * self.radius
                } else {
                    // Uniform by volume in the shell [r, 2r).
                    let u = uniform_f64(&mut self.rng);
                    self.radius
                        * (1.0 + u * ((1u64 << d.min(63)) as f64 - 1.0)).powf(1.0 / d as f64)
                };
                for j in 0..d {
                    candidate[j] = self.points[centre + j] + r * direction[j];
                }
                if self.inside(&candidate) && !self.crowded(&candidate) {
                    self.insert(&candidate);
                    drawn += 1;
                    found = true;
                    break;
                }
            }
            if !found {
                self.active.swap_remove(slot);
            }
        }
    }

    /// A uniform direction on the unit sphere: normalised Gaussian coordinates (Box–Muller).
    fn direction(&mut self, out: &mut [f64]) {
        loop {
            let mut norm = 0.0;
            for x in out.iter_mut() {
                let u1 = 1.0 - uniform_f64(&mut self.rng);
                let u2 = uniform_f64(&mut self.rng);
                *x = (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
                norm += *x * *x;
            }
            if norm > 1e-300 {
                let scale = 1.0 / norm.sqrt();
                out.iter_mut().for_each(|x| *x *= scale);
                return;
            }
        }
    }

    fn inside(&self, x: &[f64]) -> bool {
        x.iter()
            .zip(self.lower.iter().zip(&self.upper))
            .all(|(&v, (&l, &u))| l <= v && v < u)
    }

    /// The grid cell of `x` on each axis.
    fn cell_of(&self, x: &[f64], j: usize) -> usize {
        (((x[j] - self.lower[j]) / self.cell) as usize).min(self.shape[j] - 1)
    }

    fn insert(&mut self, x: &[f64]) {
        let d = x.len();
        let index = (0..d).fold(0, |index, j| index * self.shape[j] + self.cell_of(x, j));
        let id = (self.points.len() / d) as u32;
        self.grid[index] = id;
        self.points.extend_from_slice(x);
        self.active.push(id);
    }

    /// Whether a point lies closer than `r` to `x`: the grid cells within `reach` of `x`'s cell
    /// on every axis (cut at the grid's edges), visited as an odometer, or every point when
    /// there are fewer points than such cells (high dimensions: 9¹² cells at d = 12).
    fn crowded(&self, x: &[f64]) -> bool {
        let d = x.len();
        let r2 = self.radius * self.radius;
        let near = |p: &[f64]| p.iter().zip(x).map(|(a, b)| (a - b) * (a - b)).sum::<f64>() < r2;
        // At most 64 dimensions, as `new` checks.
        let (mut lo, mut hi, mut cell) = ([0usize; 64], [0usize; 64], [0usize; 64]);
        let mut cells = 1u64;
        for j in 0..d {
            let c = self.cell_of(x, j);
            let reach = self.reach as usize;
            lo[j] = c.saturating_sub(reach);
            hi[j] = (c + reach).min(self.shape[j] - 1);
            cell[j] = lo[j];
            cells = cells.saturating_mul((hi[j] - lo[j] + 1) as u64);
        }
        if cells > (self.points.len() / d) as u64 {
            return self.points.chunks_exact(d).any(near);
        }
        loop {
            let index = (0..d).fold(0, |index, j| index * self.shape[j] + cell[j]);
            let id = self.grid[index];
            if id != EMPTY && near(&self.points[id as usize * d..(id as usize + 1) * d]) {
                return true;
            }
            let mut j = 0;
            loop {
                if j == d {
                    return false;
                }
                cell[j] += 1;
                if cell[j] <= hi[j] {
                    break;
                }
                cell[j] = lo[j];
                j += 1;
            }
        }
    }
}

/// The largest float below `x`.
fn prev(x: f64) -> f64 {
    if x > 0.0 {
        f64::from_bits(x.to_bits() - 1)
    } else if x < 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        -f64::from_bits(1)
    }
}
