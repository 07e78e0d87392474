//! Minimum distance of 2D point sets and the relative radius
//! `ρ = d_min / d_hex`, `d_hex = √(2 / (√3·N))`, the spacing of the densest (hexagonal) packing of
//! `N` points in the unit square (Lagae & Dutré, "A comparison of methods for generating Poisson
//! disk distributions", CGF 2008).
//!
//! Method: a counting sort of the point indices into a uniform grid of about `N/2` cells
//! (caller scratch), then for each point a search over rings of cells that stops as soon as the
//! next ring is farther than the best distance so far. For well-spread sets that is O(N).
//! Duplicates end the search at once (distance 0). A set crowded into very few cells (a tight
//! cluster beside far-away points) degrades towards O(N²); the Euclidean grid spans the bounding
//! box of the points, so a single cluster does not.

use super::{PointSet, check_scratch};
use crate::Error;
use crate::math::sqrt;

/// The metric of [`min_distance`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Topology {
    /// The unit square, Euclidean distance.
    Square,
    /// The unit torus: per axis the distance is `min(|a − b|, 1 − |a − b|)`.
    Torus,
}

/// Result of [`min_distance`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MinDistance {
    /// The smallest distance between two distinct points (0 for duplicates).
    pub distance: f64,
    /// `distance / √(2/(√3·N))`: 1 for a hexagonal lattice, about 0.93 for a square grid.
    pub relative_radius: f64,
}

/// `u32` scratch needed by [`min_distance`] for `n` points: `2n + 1` (`n` indices and up to
/// `n + 1` cell offsets), or `None` on overflow.
///
/// ```
/// assert_eq!(nyquist::analysis::min_distance_scratch_len(100), Some(201));
/// ```
pub fn min_distance_scratch_len(n: usize) -> Option<usize> {
    n.checked_mul(2)?.checked_add(1)
}

/// Grid geometry shared by binning and search.
struct Grid {
    origin: [f64; 2],
    extent: [f64; 2],
    cells: [usize; 2],
    wrap: bool,
}

impl Grid {
    fn new(points: &PointSet<'_>, topology: Topology) -> Grid {
        let n = points.len();
        let target = (n / 2).max(1);
        if topology == Topology::Torus {
            let g = (sqrt(target as f64) as usize).max(1);
            return Grid {
                origin: [0.0; 2],
                extent: [1.0; 2],
                cells: [g, g],
                wrap: true,
            };
        }
        let (mut lo, mut hi) = ([1.0f64; 2], [0.0f64; 2]);
        for p in points.coords().chunks_exact(2) {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let extent = [hi[0] - lo[0], hi[1] - lo[1]];
        let cells = match (extent[0] > 0.0, extent[1] > 0.0) {
            (true, true) => {
                let s = sqrt(extent[0] * extent[1] / target as f64);
                let gx = ((extent[0] / s) as usize).clamp(1, target);
                let gy = ((extent[1] / s) as usize).clamp(1, (target / gx).max(1));
                [gx, gy]
            }
            (true, false) => [target, 1],
            (false, true) => [1, target],
            (false, false) => [1, 1],
        };
        Grid {
            origin: lo,
            extent,
            cells,
            wrap: false,
        }
    }

    #[inline]
    fn axis_cell(&self, x: f64, k: usize) -> usize {
        if self.extent[k] > 0.0 {
            let c = (x - self.origin[k]) / self.extent[k] * self.cells[k] as f64;
            (c.max(0.0) as usize).min(self.cells[k] - 1)
        } else {
            0
        }
    }

    #[inline]
    fn cell(&self, p: &[f64]) -> [usize; 2] {
        [self.axis_cell(p[0], 0), self.axis_cell(p[1], 1)]
    }

    #[inline]
    fn dist2(&self, p: &[f64], q: &[f64]) -> f64 {
        let mut dx = (p[0] - q[0]).abs();
        let mut dy = (p[1] - q[1]).abs();
        if self.wrap {
            dx = dx.min(1.0 - dx);
            dy = dy.min(1.0 - dy);
        }
        dx * dx + dy * dy
    }
}

/// Minimum distance between distinct points of a 2D set and its relative radius ρ, in the unit
/// square or on the unit torus. A single point has no pair: the result is then the largest
/// distance the domain allows (√2 in the square, √2/2 on the torus). Allocates: no.
///
/// # Errors
/// [`Error::OutOfRange`] (`"dims"`) unless the set is 2D; [`Error::BufferTooShort`] if `scratch`
/// is shorter than [`min_distance_scratch_len`].
///
/// ```
/// use nyquist::analysis::{min_distance, PointSet, Topology};
/// let pts = [[0.05, 0.5], [0.95, 0.5], [0.5, 0.5]];
/// let set = PointSet::from_2d(&pts).unwrap();
/// let mut s = [0u32; 7];
/// let sq = min_distance(&set, Topology::Square, &mut s).unwrap();
/// let torus = min_distance(&set, Topology::Torus, &mut s).unwrap();
/// assert!((sq.distance - 0.45).abs() < 1e-12);
/// assert!((torus.distance - 0.1).abs() < 1e-12); // 0.05 and 0.95 meet across the edge
/// ```
pub fn min_distance(
    points: &PointSet<'_>,
    topology: Topology,
    scratch: &mut [u32],
) -> Result<MinDistance, Error> {
    if points.dims() != 2 {
        return Err(Error::OutOfRange { what: "dims" });
    }
    let n = points.len();
    let needed = min_distance_scratch_len(n).ok_or(Error::TooMany { what: "points" })?;
    let buf = check_scratch(scratch, needed)?;
    let rho = |d: f64| d / sqrt(2.0 / (sqrt(3.0) * n as f64));
    if n == 1 {
        let d = match topology {
            Topology::Square => core::f64::consts::SQRT_2,
            Topology::Torus => core::f64::consts::FRAC_1_SQRT_2,
        };
        return Ok(MinDistance {
            distance: d,
            relative_radius: rho(d),
        });
    }
    let grid = Grid::new(points, topology);
    let [gx, gy] = grid.cells;
    let cells = gx * gy;
    let (index, rest) = buf.split_at_mut(n);
    let start = &mut rest[..cells + 1];
    let coords = points.coords();
    // Counting sort: start[c] becomes the first slot of cell c, start[cells] = n.
    start.fill(0);
    for p in coords.chunks_exact(2) {
        let [cx, cy] = grid.cell(p);
        start[cy * gx + cx] += 1;
    }
    let mut sum = 0u32;
    for s in start.iter_mut() {
        sum += *s;
        *s = sum;
    }
    for (i, p) in coords.chunks_exact(2).enumerate().rev() {
        let [cx, cy] = grid.cell(p);
        let c = cy * gx + cx;
        start[c] -= 1;
        index[start[c] as usize] = i as u32;
    }
    let (cw, ch) = (grid.extent[0] / gx as f64, grid.extent[1] / gy as f64);
    let ring_gap = match (gx > 1, gy > 1) {
        (true, true) => cw.min(ch),
        (true, false) => cw,
        (false, true) => ch,
        (false, false) => f64::INFINITY,
    };
    let max_ring = if grid.wrap {
        gx.max(gy) / 2
    } else {
        gx.max(gy)
    };
    let mut best2 = f64::INFINITY;
    for c in 0..cells {
        let (cx, cy) = ((c % gx) as isize, (c / gx) as isize);
        for slot in start[c]..start[c + 1] {
            let i = index[slot as usize] as usize;
            let p = &coords[2 * i..2 * i + 2];
            let mut r = 0isize;
            loop {
                for dy in -r..=r {
                    let edge = dy.abs() == r;
                    let step = if edge || r == 0 { 1 } else { 2 * r as usize };
                    for dx in (-r..=r).step_by(step.max(1)) {
                        let (mut x, mut y) = (cx + dx, cy + dy);
                        if grid.wrap {
                            x = x.rem_euclid(gx as isize);
                            y = y.rem_euclid(gy as isize);
                        } else if x < 0 || y < 0 || x >= gx as isize || y >= gy as isize {
                            continue;
                        }
                        let cc = y as usize * gx + x as usize;
                        for &j in &index[start[cc] as usize..start[cc + 1] as usize] {
                            let j = j as usize;
                            if j > i {
                                let d2 = grid.dist2(p, &coords[2 * j..2 * j + 2]);
                                if d2 < best2 {
                                    best2 = d2;
                                    if d2 == 0.0 {
                                        return Ok(MinDistance {
                                            distance: 0.0,
                                            relative_radius: 0.0,
                                        });
                                    }
                                }
                            }
                        }
                    }
                }
                let reach = r as f64 * ring_gap;
                if r as usize >= max_ring || reach * reach >= best2 {
                    break;
                }
                r += 1;
            }
        }
    }
    let d = sqrt(best2);
    Ok(MinDistance {
        distance: d,
        relative_radius: rho(d),
    })
}
