//! Minimum distance of 2D point sets and the relative radius
//! `ρ = d_min / d_hex`, `d_hex = √(2 / (√3·N))`, the spacing of the densest (hexagonal) packing of
//! `N` points in the unit square (Lagae & Dutré, "A comparison of methods for generating Poisson
//! disk distributions", CGF 2008).
//!
//! Method: a counting sort of the coordinates into a uniform grid of about `N/2` cells
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

/// `u64` scratch needed by [`min_distance`] for `n` points: `3n + 1` (the coordinates
/// reordered by cell, stored as `f64` bits, and up to `n + 1` cell offsets), or `None` on
/// overflow.
///
/// ```
/// assert_eq!(nyquist::analysis::min_distance_scratch_len(100), Some(301));
/// ```
pub fn min_distance_scratch_len(n: usize) -> Option<usize> {
    n.checked_mul(3)?.checked_add(1)
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

    /// The largest ring the search needs: every cell lies within it of every other (rings are
    /// Chebyshev distances in cells; on the torus they wrap, so no cell is more than half the grid
    /// away).
    fn max_ring(&self) -> usize {
        let [gx, gy] = self.cells;
        if self.wrap {
            gx.max(gy) / 2
        } else {
            gx.max(gy) - 1
        }
    }

    /// The distance each ring adds at least: two points whose cells are `Δ ≥ 1` rings apart are
    /// at least `(Δ − 1) · ring_gap` apart, and no larger value has that property. Cells `Δ ≥ 2`
    /// rings apart are `Δ` apart along some axis, with `Δ − 1` whole cells between them, so the gap
    /// is the narrowest cell side among the axes where two cells can be that far apart (3 cells,
    /// or 4 when the axis wraps); ∞ when no axis can.
    fn ring_gap(&self) -> f64 {
        let least = if self.wrap { 4 } else { 3 };
        let mut gap = f64::INFINITY;
        for k in 0..2 {
            if self.cells[k] >= least {
                gap = gap.min(self.extent[k] / self.cells[k] as f64);
            }
        }
        gap
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

/// Whether the search around a point can stop after ring `r`: no ring lies past `max_ring`,
/// or every cell past ring `r` is at least `r · gap` away (see [`Grid::ring_gap`]), so it holds
/// no pair closer than the best squared distance so far, `best2`.
#[inline]
fn search_done(r: usize, max_ring: usize, gap: f64, best2: f64) -> bool {
    let reach = r as f64 * gap;
    r >= max_ring || reach * reach >= best2
}

/// Minimum distance between distinct points of a 2D set and its relative radius ρ, in the unit
/// square or on the unit torus. A single point has no pair: the result is then the largest
/// distance the domain allows (√2 in the square, √2/2 on the torus). Allocates: no.
///
/// # Errors
/// [`Error::NotInRange`] (`"dims"`) unless the set is 2D; [`Error::BufferTooShort`] if `scratch`
/// is shorter than [`min_distance_scratch_len`].
///
/// ```
/// use nyquist::analysis::{min_distance, PointSet, Topology};
/// let pts = [[0.05, 0.5], [0.95, 0.5], [0.5, 0.5]];
/// let set = PointSet::from_2d(&pts).unwrap();
/// let mut s = [0u64; 10];
/// let sq = min_distance(&set, Topology::Square, &mut s).unwrap();
/// let torus = min_distance(&set, Topology::Torus, &mut s).unwrap();
/// assert!((sq.distance - 0.45).abs() < 1e-12);
/// assert!((torus.distance - 0.1).abs() < 1e-12); // 0.05 and 0.95 meet across the edge
/// ```
pub fn min_distance(
    points: &PointSet<'_>,
    topology: Topology,
    scratch: &mut [u64],
) -> Result<MinDistance, Error> {
    if points.dims() != 2 {
        return Err(Error::NotInRange {
            what: "dims",
            value: points.dims() as u64,
            min: 2,
            max: 2,
        });
    }
    let n = points.len();
    let needed = min_distance_scratch_len(n).ok_or(Error::TooMany {
        what: "points",
        value: n as u64,
        max: ((usize::MAX - 1) / 3) as u64,
    })?;
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
    let (sorted, rest) = buf.split_at_mut(2 * n);
    let start = &mut rest[..cells + 1];
    // Counting sort of the coordinates by cell (raster order): afterwards cell c holds the
    // points in slots start[c]..start[c + 1], so neighbours are contiguous in memory.
    start.fill(0);
    for p in points.coords().chunks_exact(2) {
        let [cx, cy] = grid.cell(p);
        start[cy * gx + cx] += 1;
    }
    let mut sum = 0u64;
    for s in start.iter_mut() {
        sum += *s;
        *s = sum;
    }
    for p in points.coords().chunks_exact(2).rev() {
        let [cx, cy] = grid.cell(p);
        let c = cy * gx + cx;
        start[c] -= 1;
        let at = 2 * start[c] as usize;
        sorted[at] = p[0].to_bits();
        sorted[at + 1] = p[1].to_bits();
    }
    let start = &*start;
    let sorted = &*sorted;
    let at = |slot: usize| {
        [
            f64::from_bits(sorted[2 * slot]),
            f64::from_bits(sorted[2 * slot + 1]),
        ]
    };
    let (ring_gap, max_ring) = (grid.ring_gap(), grid.max_ring());
    let (gxi, gyi) = (gx as isize, gy as isize);
    let mut best2 = f64::INFINITY;
    for c in 0..cells {
        let (cx, cy) = ((c % gx) as isize, (c / gx) as isize);
        for i in start[c] as usize..start[c + 1] as usize {
            let p = at(i);
            let mut r = 0isize;
            loop {
                for dy in -r..=r {
                    let step = if dy.abs() == r || r == 0 {
                        1
                    } else {
                        2 * r as usize
                    };
                    for dx in (-r..=r).step_by(step) {
                        let (mut x, mut y) = (cx + dx, cy + dy);
                        if grid.wrap {
                            x = x.rem_euclid(gxi);
                            y = y.rem_euclid(gyi);
                        } else if x < 0 || y < 0 || x >= gxi || y >= gyi {
                            continue;
                        }
                        let cc = y as usize * gx + x as usize;
                        // Each pair once: only slots after i (earlier cells come first).
                        if cc < c {
                            continue;
                        }
                        let from = (start[cc] as usize).max(i + 1);
                        for j in from..start[cc + 1] as usize {
                            let d2 = grid.dist2(&p, &at(j));
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
                if search_done(r as usize, max_ring, ring_gap, best2) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::testsets::random;
    use proptest::prelude::*;
    use std::format;
    use std::vec;
    use std::vec::Vec;

    fn grid_min(pts: &[f64], t: Topology) -> MinDistance {
        let set = PointSet::new(pts, 2).unwrap();
        let mut s = vec![0u64; min_distance_scratch_len(set.len()).unwrap()];
        min_distance(&set, t, &mut s).unwrap()
    }

    fn brute(pts: &[f64], t: Topology) -> f64 {
        let n = pts.len() / 2;
        let mut best = f64::INFINITY;
        for i in 0..n {
            for j in i + 1..n {
                let mut dx = (pts[2 * i] - pts[2 * j]).abs();
                let mut dy = (pts[2 * i + 1] - pts[2 * j + 1]).abs();
                if t == Topology::Torus {
                    dx = dx.min(1.0 - dx);
                    dy = dy.min(1.0 - dy);
                }
                best = best.min((dx * dx + dy * dy).sqrt());
            }
        }
        best
    }

    #[test]
    fn grid_search_matches_brute_force() {
        for seed in 0..200u64 {
            let n = 2 + (seed as usize * 13) % 300;
            let mut pts = random(n, 2, seed);
            let mut rng = crate::rng::default_rng(seed ^ 0xabc);
            match seed % 8 {
                // a duplicate pair
                0 => {
                    let j = crate::rng::uniform_below(&mut rng, n as u32 - 1) as usize;
                    pts[2 * n - 2] = pts[2 * j];
                    pts[2 * n - 1] = pts[2 * j + 1];
                }
                // boundary values, some meeting across the torus edge
                1 => {
                    for v in pts.iter_mut().step_by(3) {
                        *v = if crate::rng::uniform_below(&mut rng, 2) == 0 {
                            0.0
                        } else {
                            1.0
                        };
                    }
                }
                // a tight cluster plus a few far points
                2 => {
                    for v in pts.iter_mut().skip(6) {
                        *v = 0.3 + *v * 1e-3;
                    }
                }
                // the whole set in a small square away from the origin: the grid's origin and
                // extent are then far from 0 and 1
                4 => {
                    for v in pts.iter_mut() {
                        *v = 0.5 + *v * 1e-2;
                    }
                }
                // a thin horizontal strip, and a narrow vertical band: cells far from square
                5 => {
                    for v in pts.iter_mut().skip(1).step_by(2) {
                        *v = 0.7 + *v * 1e-4;
                    }
                }
                6 => {
                    for v in pts.iter_mut().step_by(2) {
                        *v = 0.2 + *v * 0.05;
                    }
                }
                _ => {}
            }
            for t in [Topology::Square, Topology::Torus] {
                let g = grid_min(&pts, t);
                let b = brute(&pts, t);
                assert_eq!(g.distance, b, "seed {seed} n {n} {t:?}");
                let hex = (2.0 / (3f64.sqrt() * n as f64)).sqrt();
                assert!((g.relative_radius - b / hex).abs() < 1e-12);
            }
        }
    }

    /// How many rings apart cells `a` and `b` (column, row) of `grid` are, and the distance
    /// between the nearest points of the two cells: the whole cells between them per axis.
    fn cell_separation(grid: &Grid, a: [usize; 2], b: [usize; 2]) -> (usize, f64) {
        let (mut rings, mut d2) = (0, 0.0);
        for k in 0..2 {
            let g = grid.cells[k];
            let mut steps = a[k].abs_diff(b[k]);
            if grid.wrap {
                steps = steps.min(g - steps);
            }
            rings = rings.max(steps);
            let between = steps.saturating_sub(1) as f64 * (grid.extent[k] / g as f64);
            d2 += between * between;
        }
        (rings, d2.sqrt())
    }

    #[test]
    fn ring_gap_and_max_ring_are_the_tight_bounds() {
        // The search's stop rule rests on these two: found here by walking every pair of cells
        // of grids built for sets in rectangles of many shapes (thin strips, bands, single
        // rows, a point) and on the torus.
        let sides = [1.0, 0.5, 0.1, 1e-2, 1e-4, 0.0];
        for seed in 0..400u64 {
            let n = 2 + (seed as usize * 7) % 150;
            let mut pts = random(n, 2, seed);
            let (w, h) = (sides[seed as usize % 6], sides[(seed as usize / 6) % 6]);
            for p in pts.chunks_exact_mut(2) {
                p[0] = 0.2 + w * 0.7 * p[0];
                p[1] = 0.1 + h * 0.8 * p[1];
            }
            let set = PointSet::new(&pts, 2).unwrap();
            for t in [Topology::Square, Topology::Torus] {
                let grid = Grid::new(&set, t);
                let [gx, gy] = grid.cells;
                let cells: Vec<[usize; 2]> = (0..gx * gy).map(|c| [c % gx, c / gx]).collect();
                let (mut max_ring, mut gap) = (0, f64::INFINITY);
                for &a in &cells {
                    for &b in &cells {
                        let (rings, d) = cell_separation(&grid, a, b);
                        max_ring = max_ring.max(rings);
                        if rings >= 2 {
                            gap = gap.min(d / (rings - 1) as f64);
                        }
                    }
                }
                let at = format!("seed {seed}, {t:?}, {gx} x {gy} cells");
                assert_eq!(grid.max_ring(), max_ring, "{at}");
                let got = grid.ring_gap();
                assert!(
                    got == gap || (got - gap).abs() <= 1e-12 * gap,
                    "{at}: gap {got}, cells say {gap}"
                );
            }
        }
    }

    #[test]
    fn sets_touching_zero_bin_from_the_origin() {
        // Coordinates exactly 0 put the grid's origin at 0, and the closest pair beside that
        // edge must still be binned into neighbouring cells of the 3 × 3 grid.
        let pts = [
            0.0, 0.5, 0.05, 0.5, 0.5, 0.0, 0.6, 0.0, 1.0, 1.0, 0.9, 0.3, 0.3, 0.9, 0.75, 0.65, 0.3,
            0.3, 0.6, 0.95, 0.95, 0.05, 0.05, 0.95, 0.45, 0.6, 0.75, 0.3, 0.2, 0.7, 0.97, 0.8,
            0.15, 0.15, 0.6, 0.45,
        ];
        for t in [Topology::Square, Topology::Torus] {
            assert_eq!(grid_min(&pts, t).distance, brute(&pts, t), "{t:?}");
        }
        assert!((brute(&pts, Topology::Square) - 0.05).abs() < 1e-15);
    }

    #[test]
    fn search_stops_once_the_next_ring_is_too_far() {
        // Cells past ring r are at least r · gap away: done once (r · gap)² ≥ best².
        assert!(!search_done(1, 9, 0.5, 0.3)); // ring 2 may hold a pair 0.5 apart < √0.3
        assert!(search_done(1, 9, 0.5, 0.25)); // no closer pair past ring 1
        assert!(search_done(2, 9, 0.5, 0.3));
        assert!(!search_done(2, 9, 0.25, 0.3));
        assert!(!search_done(0, 9, 0.5, 1e-300)); // ring 0 alone never settles it
        assert!(search_done(9, 9, 0.5, 100.0)); // nothing past the last ring
        assert!(search_done(10, 9, 0.5, 100.0));
        // No axis with cells two rings apart: ring 0 goes on (0 · ∞ is NaN), ring 1 is the last.
        assert!(!search_done(0, 9, f64::INFINITY, 1.0));
        assert!(search_done(1, 9, f64::INFINITY, f64::INFINITY));
    }

    #[test]
    fn regular_grid_has_known_relative_radius() {
        // k×k cell centres: d_min = 1/k, so ρ = √(√3/2) ≈ 0.9306 (square and torus alike).
        for k in [2usize, 7, 32, 100] {
            let pts: Vec<f64> = (0..k * k)
                .flat_map(|i| {
                    [
                        ((i % k) as f64 + 0.5) / k as f64,
                        ((i / k) as f64 + 0.5) / k as f64,
                    ]
                })
                .collect();
            for t in [Topology::Square, Topology::Torus] {
                let r = grid_min(&pts, t);
                assert!((r.distance - 1.0 / k as f64).abs() < 1e-12);
                assert!((r.relative_radius - (3f64.sqrt() / 2.0).sqrt()).abs() < 1e-9);
            }
        }
        // A hexagonal lattice, columns a apart, rows a·√3/2 apart, odd rows shifted by a/2:
        // ρ ≈ 1 up to the fit of the lattice in the square (here ρ ≈ 0.987).
        let (cols, rows) = (16usize, 18usize);
        let a = 1.0 / cols as f64;
        let h = a * 3f64.sqrt() / 2.0;
        let pts: Vec<f64> = (0..rows * cols)
            .flat_map(|i| {
                let (r, c) = (i / cols, i % cols);
                let shift = if r % 2 == 1 { 0.5 * a } else { 0.0 };
                [c as f64 * a + shift, r as f64 * h]
            })
            .collect();
        let r = grid_min(&pts, Topology::Square);
        assert!((r.distance - a).abs() < 1e-12);
        // N = 288, d_hex = √(2/(√3·288)); ρ = a / d_hex.
        let expected = a / (2.0 / (3f64.sqrt() * 288.0)).sqrt();
        assert!((r.relative_radius - expected).abs() < 1e-12 && expected > 0.98);
    }

    #[test]
    fn single_points_duplicates_and_lines() {
        let one = grid_min(&[0.3, 0.3], Topology::Square);
        assert_eq!(one.distance, core::f64::consts::SQRT_2);
        let dup = grid_min(&[0.5, 0.5, 0.2, 0.1, 0.5, 0.5], Topology::Torus);
        assert_eq!((dup.distance, dup.relative_radius), (0.0, 0.0));
        let same = [0.25; 200];
        assert_eq!(grid_min(&same, Topology::Square).distance, 0.0);
        // All on a vertical line: the grid degenerates to one column.
        let line: Vec<f64> = (0..50).flat_map(|i| [0.5, f64::from(i) / 49.0]).collect();
        assert!((grid_min(&line, Topology::Square).distance - 1.0 / 49.0).abs() < 1e-15);
        // 0 and 1 are the same point on the torus.
        assert_eq!(
            grid_min(&[0.0, 0.5, 1.0, 0.5], Topology::Torus).distance,
            0.0
        );
        assert_eq!(
            grid_min(&[0.0, 0.5, 1.0, 0.5], Topology::Square).distance,
            1.0
        );
    }

    #[test]
    fn errors_are_typed() {
        let set = PointSet::new(&[0.5, 0.5, 0.25, 0.75], 2).unwrap();
        let mut s = [0u64; 6];
        assert_eq!(
            min_distance(&set, Topology::Square, &mut s),
            Err(Error::BufferTooShort {
                needed: 7,
                actual: 6
            })
        );
        let set3 = PointSet::new(&[0.5; 3], 3).unwrap();
        assert_eq!(
            min_distance(&set3, Topology::Square, &mut [0u64; 16]),
            Err(Error::NotInRange {
                what: "dims",
                value: 3,
                min: 2,
                max: 2
            })
        );
    }

    proptest! {
        #[test]
        fn any_set_matches_brute_force(
            raw in proptest::collection::vec(
                prop_oneof![Just(0.0f64), Just(1.0f64), Just(0.5f64), 0.0f64..=1.0, 0.49f64..0.51], 4..120),
        ) {
            let n = raw.len() / 2;
            let pts = &raw[..2 * n];
            for t in [Topology::Square, Topology::Torus] {
                let g = grid_min(pts, t);
                prop_assert_eq!(g.distance, brute(pts, t));
                prop_assert!(g.relative_radius.is_finite() && g.relative_radius >= 0.0);
            }
        }
    }
}
