//! Star discrepancy: exact in 1D (sorting), exact in 2D (an O(N²) sweep), exact in d dimensions
//! by enumerating critical boxes (small sets), and a grid bracket `[lower, upper]` for the rest.
//!
//! All exact methods evaluate the local discrepancy on the critical grid
//! `Γ̄ = ∏_k ({x_ik} ∪ {1})`: the open-box deficit `λ([0,q)) − A([0,q))/N` and the closed-box
//! excess `A([0,q])/N − λ([0,q])`. Their maximum is `D*_N` (Niederreiter 1992, §2.1;
//! Gnewuch, Srivastav & Winzen 2009, Lemma 1).

use super::{PointSet, check_scratch};
use crate::Error;

/// Most dimensions [`star_discrepancy_enumerate`] and [`star_discrepancy_bounds`] accept.
pub const MAX_DIMS: usize = 32;

/// Work limit of [`star_discrepancy_enumerate`]: the estimated cost
/// `d · N · ∏_{k<d−1} (distinct values on axis k + 1)` must not exceed it (about a few seconds).
pub const ENUMERATION_LIMIT: u64 = 1 << 32;

/// Whether an enumeration of estimated cost `work` may run: the limit is inclusive. (A function
/// of its own so that the boundary is tested without running 2³² steps.)
fn within_enumeration_limit(work: u64) -> bool {
    work <= ENUMERATION_LIMIT
}

/// `f64` scratch that every exact star-discrepancy function accepts for `n` points in `dims`
/// dimensions, `2n + (dims − 1)(n + 1)`, or `None` on overflow or `dims == 0`. (The 1D and 2D
/// functions need only `n` and `3n`.)
///
/// ```
/// use nyquist::analysis::star_discrepancy_scratch_len;
/// assert_eq!(star_discrepancy_scratch_len(10, 1), Some(20));
/// assert_eq!(star_discrepancy_scratch_len(10, 2), Some(31));
/// assert_eq!(star_discrepancy_scratch_len(10, 3), Some(42));
/// ```
pub fn star_discrepancy_scratch_len(n: usize, dims: usize) -> Option<usize> {
    let extra = dims.checked_sub(1)?.checked_mul(n.checked_add(1)?)?;
    n.checked_mul(2)?.checked_add(extra)
}

/// Exact star discrepancy `D*_N`, choosing the method by dimension: [`star_discrepancy_1d`],
/// [`star_discrepancy_2d`] or [`star_discrepancy_enumerate`]. Result in `[0, 1]`.
/// Allocates: no.
///
/// # Errors
/// [`Error::BufferTooShort`] if `scratch` is shorter than the chosen method needs: `N` in 1D,
/// `3N` in 2D, [`star_discrepancy_scratch_len`] otherwise (that length always suffices);
/// [`Error::TooMany`] when enumeration (3 or more dimensions) would exceed
/// [`ENUMERATION_LIMIT`] — use [`star_discrepancy_bounds`] then.
///
/// ```
/// use nyquist::analysis::{star_discrepancy, PointSet};
/// let pts = [[0.25, 0.25], [0.75, 0.75]];
/// let mut scratch = [0.0; 6];
/// let d = star_discrepancy(&PointSet::from_2d(&pts).unwrap(), &mut scratch).unwrap();
/// // The closed box [0, 0.75] × [0, 0.75] holds both points and has area 9/16: 1 − 9/16.
/// assert!((d - 0.4375).abs() < 1e-15);
/// ```
pub fn star_discrepancy(points: &PointSet<'_>, scratch: &mut [f64]) -> Result<f64, Error> {
    match points.dims() {
        1 => star_discrepancy_1d(points, scratch),
        2 => star_discrepancy_2d(points, scratch),
        _ => star_discrepancy_enumerate(points, scratch),
    }
}

/// Exact 1D star discrepancy, `1/(2N) + max_i |x_(i) − (2i−1)/(2N)|` over the sorted points
/// (Niederreiter 1992, Thm. 2.6). O(N log N); `scratch` needs `N` elements. Allocates: no.
///
/// # Errors
/// [`Error::NotInRange`] (`"dims"`) unless the set is 1D; [`Error::BufferTooShort`].
///
/// ```
/// use nyquist::analysis::{star_discrepancy_1d, PointSet};
/// // The midpoint rule {1/4, 3/4} has the optimal D* = 1/(2N).
/// let mut s = [0.0; 2];
/// let d = star_discrepancy_1d(&PointSet::new(&[0.75, 0.25], 1).unwrap(), &mut s).unwrap();
/// assert_eq!(d, 0.25);
/// ```
pub fn star_discrepancy_1d(points: &PointSet<'_>, scratch: &mut [f64]) -> Result<f64, Error> {
    if points.dims() != 1 {
        return Err(Error::NotInRange {
            what: "dims",
            value: points.dims() as u64,
            min: 1,
            max: 1,
        });
    }
    let n = points.len();
    let xs = check_scratch(scratch, n)?;
    xs.copy_from_slice(points.coords());
    xs.sort_unstable_by(f64::total_cmp);
    let inv2n = 0.5 / n as f64;
    let mut worst = 0.0f64;
    for (i, &x) in xs.iter().enumerate() {
        worst = worst.max((x - (2 * i + 1) as f64 * inv2n).abs());
    }
    Ok((inv2n + worst).min(1.0))
}

/// Exact 2D star discrepancy by a sweep over the sorted x-coordinates: for each critical x it
/// scans the sorted y-coordinates of the points to its left (kept sorted by insertion), with
/// open counts before and closed counts after inserting the points on that x. O(N²) time,
/// `scratch` of `3N` elements (`2N` for the x-sorted points, `N` for the y list). Allocates: no.
///
/// # Errors
/// [`Error::NotInRange`] (`"dims"`) unless the set is 2D; [`Error::BufferTooShort`].
///
/// ```
/// use nyquist::analysis::{star_discrepancy_2d, PointSet};
/// let mut s = [0.0; 3];
/// let d = star_discrepancy_2d(&PointSet::from_2d(&[[0.5, 0.5]]).unwrap(), &mut s).unwrap();
/// // [0, 1) × [0, 0.5) is empty and has area 1/2; the closed box [0, ½]² holds the point.
/// assert_eq!(d, 0.75);
/// ```
pub fn star_discrepancy_2d(points: &PointSet<'_>, scratch: &mut [f64]) -> Result<f64, Error> {
    if points.dims() != 2 {
        return Err(Error::NotInRange {
            what: "dims",
            value: points.dims() as u64,
            min: 2,
            max: 2,
        });
    }
    let n = points.len();
    let buf = check_scratch(scratch, 3 * n)?;
    let (sorted, ys) = buf.split_at_mut(2 * n);
    sorted.copy_from_slice(points.coords());
    let (pairs, _) = sorted.as_chunks_mut::<2>();
    pairs.sort_unstable_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    let inv_n = 1.0 / n as f64;
    let mut worst = 0.0f64;
    let mut filled = 0usize;
    let mut i = 0usize;
    while i < n {
        let xi = pairs[i][0];
        worst = worst.max(open_scan(xi, &ys[..filled], inv_n));
        while i < n && pairs[i][0] == xi {
            let y = pairs[i][1];
            let at = ys[..filled].partition_point(|&v| v <= y);
            ys.copy_within(at..filled, at + 1);
            ys[at] = y;
            filled += 1;
            i += 1;
        }
        worst = worst.max(closed_scan(xi, &ys[..filled], inv_n));
    }
    worst = worst.max(open_scan(1.0, &ys[..filled], inv_n));
    Ok(worst.min(1.0))
}

/// `max_k (v·y_k − k/N)` and `v − len/N`: open boxes `[0, ξ) × [0, η)` with area factor `v = ξ`.
#[inline]
fn open_scan(v: f64, ys: &[f64], inv_n: f64) -> f64 {
    let mut worst = v - ys.len() as f64 * inv_n;
    for (k, &y) in ys.iter().enumerate() {
        worst = worst.max(v * y - k as f64 * inv_n);
    }
    worst
}

/// `max_k ((k+1)/N − v·y_k)`: closed boxes `[0, ξ] × [0, y_k]`.
#[inline]
fn closed_scan(v: f64, ys: &[f64], inv_n: f64) -> f64 {
    let mut worst = f64::NEG_INFINITY;
    for (k, &y) in ys.iter().enumerate() {
        worst = worst.max((k + 1) as f64 * inv_n - v * y);
    }
    worst
}

/// Exact star discrepancy in any dimension by enumerating the critical grid of the first
/// `d − 1` axes (distinct coordinates and 1) and scanning the last axis in sorted order, as in
/// the 2D sweep. O(d · N · ∏_{k<d−1} M_k) with `M_k ≤ N + 1` the critical values of axis k, i.e.
/// O(d · N^d); `scratch` as [`star_discrepancy_scratch_len`]. Works for `d = 1` and `2` too
/// (slower than the dedicated functions). Allocates: no.
///
/// # Errors
/// [`Error::NotInRange`] (`"dims"`) above [`MAX_DIMS`]; [`Error::TooMany`]
/// (`"enumeration cost"`, the estimated cost saturated at `u64::MAX`) when the cost exceeds
/// [`ENUMERATION_LIMIT`]; [`Error::BufferTooShort`].
///
/// ```
/// use nyquist::analysis::{star_discrepancy_enumerate, PointSet};
/// let mut s = [0.0; 2 + 2 * 2];
/// let set = PointSet::new(&[0.5, 0.5, 0.5], 3).unwrap();
/// // The closed box [0, ½]³ holds the only point: 1 − 1/8.
/// assert_eq!(star_discrepancy_enumerate(&set, &mut s).unwrap(), 0.875);
/// ```
pub fn star_discrepancy_enumerate(
    points: &PointSet<'_>,
    scratch: &mut [f64],
) -> Result<f64, Error> {
    let d = points.dims();
    if d > MAX_DIMS {
        return Err(Error::NotInRange {
            what: "dims",
            value: d as u64,
            min: 1,
            max: MAX_DIMS as u64,
        });
    }
    let n = points.len();
    // 2n + (d − 1)(n + 1) ≤ usize::MAX.
    let needed = star_discrepancy_scratch_len(n, d).ok_or(Error::TooMany {
        what: "points",
        value: n as u64,
        max: ((usize::MAX - (d - 1)) / (d + 1)) as u64,
    })?;
    let buf = check_scratch(scratch, needed)?;
    let (order, axes) = buf.split_at_mut(2 * n);
    let coords = points.coords();
    let last = d - 1;
    // (last coordinate, point index) sorted by the last coordinate; indices < 2^32 are exact.
    let (pairs, _) = order.as_chunks_mut::<2>();
    for (i, p) in pairs.iter_mut().enumerate() {
        *p = [coords[i * d + last], i as f64];
    }
    pairs.sort_unstable_by(|a, b| a[0].total_cmp(&b[0]));
    // Critical values of the first d − 1 axes: sorted, distinct, then 1.
    let mut counts = [0usize; MAX_DIMS];
    let mut work: u64 = (d as u64).saturating_mul(n as u64);
    for k in 0..last {
        let axis = &mut axes[k * (n + 1)..(k + 1) * (n + 1)];
        for (i, a) in axis[..n].iter_mut().enumerate() {
            *a = coords[i * d + k];
        }
        axis[..n].sort_unstable_by(f64::total_cmp);
        let mut m = 1usize;
        for i in 1..n {
            if axis[i] != axis[m - 1] {
                axis[m] = axis[i];
                m += 1;
            }
        }
        if axis[m - 1] < 1.0 {
            axis[m] = 1.0;
            m += 1;
        }
        counts[k] = m;
        work = work.saturating_mul(m as u64);
    }
    if !within_enumeration_limit(work) {
        return Err(Error::TooMany {
            what: "enumeration cost",
            value: work,
            max: ENUMERATION_LIMIT,
        });
    }
    let inv_n = 1.0 / n as f64;
    let mut idx = [0usize; MAX_DIMS];
    let mut q = [0.0f64; MAX_DIMS];
    let mut worst = 0.0f64;
    loop {
        let mut v = 1.0;
        for k in 0..last {
            q[k] = axes[k * (n + 1) + idx[k]];
            v *= q[k];
        }
        let (mut open, mut closed) = (0usize, 0usize);
        for &[y, i] in pairs.iter() {
            let p = &coords[i as usize * d..i as usize * d + last];
            let mut is_open = true;
            let mut is_closed = true;
            for (&pk, &qk) in p.iter().zip(&q[..last]) {
                is_open &= pk < qk;
                is_closed &= pk <= qk;
            }
            if is_open {
                worst = worst.max(v * y - open as f64 * inv_n);
                open += 1;
            }
            if is_closed {
                closed += 1;
                worst = worst.max(closed as f64 * inv_n - v * y);
            }
        }
        worst = worst.max(v - open as f64 * inv_n);
        // Odometer over the critical grid.
        let mut k = 0;
        loop {
            if k == last {
                return Ok(worst.min(1.0));
            }
            idx[k] += 1;
            if idx[k] < counts[k] {
                break;
            }
            idx[k] = 0;
            k += 1;
        }
    }
}

/// A bracket `lower ≤ D*_N ≤ upper` from [`star_discrepancy_bounds`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StarBounds {
    /// The largest local discrepancy over grid boxes: a true lower bound.
    pub lower: f64,
    /// An upper bound; `upper − lower ≤ 1 − (1 − 1/m)^d ≤ d/m`.
    pub upper: f64,
}

/// `u32` scratch needed by [`star_discrepancy_bounds`]: `2 (m + 1)^dims`, or `None` on overflow
/// or zero arguments.
///
/// ```
/// assert_eq!(nyquist::analysis::star_bounds_scratch_len(2, 8), Some(2 * 81));
/// ```
pub fn star_bounds_scratch_len(dims: usize, m: u32) -> Option<usize> {
    if dims == 0 || m == 0 {
        return None;
    }
    let side = usize::try_from(m).ok()?.checked_add(1)?;
    let mut cells = 1usize;
    for _ in 0..dims {
        cells = cells.checked_mul(side)?;
    }
    cells.checked_mul(2)
}

/// The largest `m` for which [`star_bounds_scratch_len`] is `Some` in `dims ≥ 1` dimensions.
fn largest_bounds_m(dims: usize) -> u32 {
    // The length grows with m: bisect for the last m that fits (m = 1 always does).
    let (mut fits, mut overflows) = (1u64, 1u64 << 32);
    while overflows - fits > 1 {
        let mid = fits + (overflows - fits) / 2;
        if star_bounds_scratch_len(dims, mid as u32).is_some() {
            fits = mid;
        } else {
            overflows = mid;
        }
    }
    fits as u32
}

/// Brackets the star discrepancy with a regular grid of `m` cells per axis (grid values
/// `j/m`): counts of open and closed anchored boxes at every grid point come from a
/// d-dimensional histogram and prefix sums. Every `t` lies in a cell `[a, a + 1/m]`, and
/// `A([0,t))` lies between the open count at `a` and the closed count at `a + 1/m`, so
///
/// - `lower = max_g max(λ(g) − A_open(g)/N, A_closed(g)/N − λ(g))` over grid points (real boxes),
/// - `upper = max_a max(A_closed(a⁺)/N − λ(a), λ(a⁺) − A_open(a)/N)` over cells,
///
/// and `upper − lower ≤ 1 − (1 − 1/m)^d`. Exact results need [`star_discrepancy`]; this is the
/// method for large `N·d` (cost O(N·d + d·(m+1)^d)). Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] (`"m"`) for `m == 0`; [`Error::NotInRange`] (`"dims"`) above
/// [`MAX_DIMS`]; [`Error::TooMany`] (`"m"`, with the largest `m` whose scratch length fits a
/// `usize`) if the grid size overflows; [`Error::BufferTooShort`].
///
/// ```
/// use nyquist::analysis::{star_discrepancy_bounds, PointSet};
/// let set = PointSet::from_2d(&[[0.25, 0.25], [0.75, 0.75]]).unwrap();
/// let mut s = [0u32; 2 * 17 * 17];
/// let b = star_discrepancy_bounds(&set, 16, &mut s).unwrap();
/// assert!(b.lower <= 0.4375 && 0.4375 <= b.upper && b.upper - b.lower <= 2.0 / 16.0);
/// ```
pub fn star_discrepancy_bounds(
    points: &PointSet<'_>,
    m: u32,
    scratch: &mut [u32],
) -> Result<StarBounds, Error> {
    if m == 0 {
        return Err(Error::ZeroSize { what: "m" });
    }
    let d = points.dims();
    if d > MAX_DIMS {
        return Err(Error::NotInRange {
            what: "dims",
            value: d as u64,
            min: 1,
            max: MAX_DIMS as u64,
        });
    }
    let needed = star_bounds_scratch_len(d, m).ok_or_else(|| Error::TooMany {
        what: "m",
        value: u64::from(m),
        max: u64::from(largest_bounds_m(d)),
    })?;
    let buf = check_scratch(scratch, needed)?;
    buf.fill(0);
    let cells = needed / 2;
    let (open, closed) = buf.split_at_mut(cells);
    let side = m as usize + 1;
    let mf = f64::from(m);
    let grid = |j: usize| j as f64 / mf;
    let mut stride = [0usize; MAX_DIMS];
    let mut s = 1usize;
    for st in stride[..d].iter_mut() {
        *st = s;
        s *= side;
    }
    for p in points.coords().chunks_exact(d) {
        let (mut io, mut ic, mut in_open) = (0usize, 0usize, true);
        for (k, &x) in p.iter().enumerate() {
            let (jo, jc) = grid_indices(x, m);
            ic += jc * stride[k];
            if jo > m as usize {
                // x = 1: no open box [0, g) holds the point.
                in_open = false;
            } else {
                io += jo * stride[k];
            }
        }
        if in_open {
            open[io] += 1;
        }
        closed[ic] += 1;
    }
    // Inclusive prefix sums along every axis: count at g = points binned at or below g.
    for &st in &stride[..d] {
        for flat in 0..cells {
            if (flat / st) % side != 0 {
                open[flat] += open[flat - st];
                closed[flat] += closed[flat - st];
            }
        }
    }
    let inv_n = 1.0 / points.len() as f64;
    let volume = |flat: usize| {
        let mut v = 1.0;
        for &st in &stride[..d] {
            v *= grid((flat / st) % side);
        }
        v
    };
    let (mut lower, mut upper) = (0.0f64, 0.0f64);
    let mut upper_offset = 0usize;
    for st in &stride[..d] {
        upper_offset += st;
    }
    for flat in 0..cells {
        let v = volume(flat);
        let o = f64::from(open[flat]) * inv_n;
        let c = f64::from(closed[flat]) * inv_n;
        lower = lower.max(v - o).max(c - v);
        let is_lower_corner = (0..d).all(|k| (flat / stride[k]) % side < m as usize);
        if is_lower_corner {
            let up = flat + upper_offset;
            let vu = volume(up);
            let cu = f64::from(closed[up]) * inv_n;
            upper = upper.max(cu - v).max(vu - o);
        }
    }
    Ok(StarBounds {
        lower: lower.min(1.0),
        upper: upper.clamp(lower, 1.0),
    })
}

/// For `x ∈ [0, 1]`: the smallest `j` with `j/m > x` (open; `m + 1` if none) and the smallest
/// `j` with `j/m ≥ x` (closed), computed from the same `j as f64 / m` values the volumes use.
fn grid_indices(x: f64, m: u32) -> (usize, usize) {
    let mf = f64::from(m);
    let m = m as usize;
    let grid = |j: usize| j as f64 / mf;
    let mut jo = (crate::math::floor(x * mf) as usize + 1).min(m + 1);
    while jo > 0 && grid(jo - 1) > x {
        jo -= 1;
    }
    while jo <= m && grid(jo) <= x {
        jo += 1;
    }
    let mut jc = (crate::math::ceil(x * mf) as usize).min(m);
    while jc > 0 && grid(jc - 1) >= x {
        jc -= 1;
    }
    while jc < m && grid(jc) < x {
        jc += 1;
    }
    (jo, jc)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::testsets::{hammersley, random, van_der_corput};
    use proptest::prelude::*;
    use std::vec;
    use std::vec::Vec;

    fn exact(coords: &[f64], dims: usize) -> f64 {
        let set = PointSet::new(coords, dims).unwrap();
        let mut s = vec![0.0; star_discrepancy_scratch_len(set.len(), dims).unwrap()];
        star_discrepancy(&set, &mut s).unwrap()
    }

    #[test]
    fn star_discrepancy_is_the_1d_and_2d_methods_with_their_scratch() {
        // 1D and 2D sets go to their own methods, which need only N and 3N of scratch (the
        // enumerator needs 2N and 3N + 1): the same values, bit for bit, and the same errors.
        for n in [1usize, 2, 3, 7, 64, 300] {
            for (dims, need) in [(1usize, n), (2, 3 * n)] {
                let coords = random(n, dims, n as u64 + 17 * dims as u64);
                let set = PointSet::new(&coords, dims).unwrap();
                let mut s = vec![0.0; need];
                let own = if dims == 1 {
                    star_discrepancy_1d(&set, &mut s)
                } else {
                    star_discrepancy_2d(&set, &mut s)
                }
                .unwrap();
                let got = star_discrepancy(&set, &mut s).unwrap();
                assert_eq!(got.to_bits(), own.to_bits(), "n {n} dims {dims}");
                assert_eq!(
                    star_discrepancy(&set, &mut s[..need - 1]),
                    Err(Error::BufferTooShort {
                        needed: need,
                        actual: need - 1
                    }),
                    "n {n} dims {dims}"
                );
            }
        }
    }

    fn enumerate(coords: &[f64], dims: usize) -> f64 {
        let set = PointSet::new(coords, dims).unwrap();
        let mut s = vec![0.0; star_discrepancy_scratch_len(set.len(), dims).unwrap()];
        star_discrepancy_enumerate(&set, &mut s).unwrap()
    }

    fn bounds(coords: &[f64], dims: usize, m: u32) -> StarBounds {
        let set = PointSet::new(coords, dims).unwrap();
        let mut s = vec![0u32; star_bounds_scratch_len(dims, m).unwrap()];
        star_discrepancy_bounds(&set, m, &mut s).unwrap()
    }

    /// O(N^(d+1)) oracle: every grid point of ∏({x_ik} ∪ {1}), counts by direct scans.
    fn brute(coords: &[f64], d: usize) -> f64 {
        let n = coords.len() / d;
        let axes: Vec<Vec<f64>> = (0..d)
            .map(|k| {
                let mut a: Vec<f64> = (0..n).map(|i| coords[i * d + k]).collect();
                a.push(1.0);
                a
            })
            .collect();
        let mut idx = vec![0usize; d];
        let mut worst = 0.0f64;
        loop {
            let q: Vec<f64> = (0..d).map(|k| axes[k][idx[k]]).collect();
            let v: f64 = q.iter().product();
            let pts = coords.chunks_exact(d);
            let open = pts.clone().filter(|p| p.iter().zip(&q).all(|(a, b)| a < b));
            let closed = pts.filter(|p| p.iter().zip(&q).all(|(a, b)| a <= b));
            worst = worst
                .max(v - open.count() as f64 / n as f64)
                .max(closed.count() as f64 / n as f64 - v);
            let mut k = 0;
            loop {
                if k == d {
                    return worst;
                }
                idx[k] += 1;
                if idx[k] <= n {
                    break;
                }
                idx[k] = 0;
                k += 1;
            }
        }
    }

    /// Random points, some snapped to 0, 1 or a coarse grid so ties and boundaries occur.
    fn nasty(n: usize, d: usize, seed: u64) -> Vec<f64> {
        let mut rng = crate::rng::default_rng(seed);
        (0..n * d)
            .map(|_| match crate::rng::uniform_below(&mut rng, 8) {
                0 => 0.0,
                1 => 1.0,
                2 | 3 => f64::from(crate::rng::uniform_below(&mut rng, 5)) / 4.0,
                _ => crate::rng::uniform_f64(&mut rng),
            })
            .collect()
    }

    #[test]
    fn van_der_corput_n_times_star_matches_published_values() {
        let expected = [
            1.0, 1.0, 1.5, 1.0, 1.75, 1.5, 1.75, 1.0, 1.875, 1.75, 2.125, 1.5, 2.125, 1.75, 1.875,
            1.0,
        ];
        for (n, &e) in (1..=16u32).zip(&expected) {
            let pts = van_der_corput(n);
            let d = exact(&pts, 1);
            assert!(
                (f64::from(n) * d - e).abs() < 1e-12,
                "N = {n}: {}",
                f64::from(n) * d
            );
            assert!((enumerate(&pts, 1) - d).abs() < 1e-15);
        }
    }

    #[test]
    fn hammersley_star_matches_de_clerck() {
        for m in 2..=12u32 {
            let n = 1u32 << m;
            let nf = f64::from(n);
            let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
            let expected = (f64::from(m) / 3.0 + 13.0 / 9.0 - sign * 4.0 / (9.0 * nf)) / nf;
            let got = exact(&hammersley(n), 2);
            assert!(
                (got - expected).abs() < 1e-12,
                "m = {m}: {got} vs {expected}"
            );
        }
    }

    #[test]
    fn exact_2d_and_enumeration_agree_with_brute_force() {
        for seed in 0..60u64 {
            let n = 1 + (seed as usize * 7) % 64;
            for pts in [random(n, 2, seed), nasty(n, 2, seed)] {
                let b = brute(&pts, 2);
                assert!((exact(&pts, 2) - b).abs() < 1e-14, "seed {seed} n {n}");
                assert!((enumerate(&pts, 2) - b).abs() < 1e-14, "seed {seed} n {n}");
            }
        }
    }

    #[test]
    fn enumeration_in_3d_and_4d_agrees_with_brute_force() {
        for seed in 0..12u64 {
            let n = 1 + seed as usize * 2;
            for d in [3, 4] {
                for pts in [random(n, d, seed), nasty(n, d, seed + 100)] {
                    let b = brute(&pts, d);
                    assert!((exact(&pts, d) - b).abs() < 1e-14, "seed {seed} d {d}");
                }
            }
        }
    }

    /// The 2D star discrepancy of the points `(t, t)` on the diagonal, by a formula over the
    /// sorted `t` alone (the "1D formula" of a set on a line): a box `[0,ξ) × [0,η)` holds the
    /// points below `m = min(ξ, η)`, a fraction `F(m)`, and its area ranges over `[m², m]`; so
    /// `D* = sup_m max(F(m) − m², m − F(m))`, reached as `m` falls to a value `v` from above
    /// (`#{t ≤ v}/N − v²`) or rises to it from below (`v − #{t < v}/N`).
    fn diagonal_formula(ts: &[f64]) -> f64 {
        let n = ts.len() as f64;
        let mut d = 0.0f64;
        for &v in ts {
            let below = ts.iter().filter(|&&t| t < v).count() as f64;
            let at_or_below = ts.iter().filter(|&&t| t <= v).count() as f64;
            d = d.max(at_or_below / n - v * v).max(v - below / n);
        }
        d
    }

    #[test]
    fn points_on_a_line_reduce_to_the_1d_formula_or_to_one() {
        // A 2D set is at least as discrepant as each projection (boxes [0,ξ) × [0,1]).
        for seed in 0..20u64 {
            let pts = random(40, 2, seed);
            let xs: Vec<f64> = pts.iter().step_by(2).copied().collect();
            let ys: Vec<f64> = pts.iter().skip(1).step_by(2).copied().collect();
            let d2 = exact(&pts, 2);
            assert!(d2 >= exact(&xs, 1) - 1e-15 && d2 >= exact(&ys, 1) - 1e-15);
            // The same x's at y = 1: closed boxes [0,ξ] × [0,1] give the 1D excess, but the
            // empty box [0,1) × [0,1) has area 1, so D* = 1 ("a set on a line has its 1D
            // discrepancy" fails here).
            let line: Vec<f64> = xs.iter().flat_map(|&x| [x, 1.0]).collect();
            assert_eq!(exact(&line, 2), 1.0);
            // Points (x, x) on the diagonal: every anchored box [0,ξ)×[0,η) holds the points
            // below min(ξ, η), so D* = max(1D deficit with area ξη, …); the 1D set bounds it below.
            let diag: Vec<f64> = xs.iter().flat_map(|&x| [x, x]).collect();
            assert!((exact(&diag, 2) - brute(&diag, 2)).abs() < 1e-14);
            assert!(
                (exact(&diag, 2) - diagonal_formula(&xs)).abs() < 1e-14,
                "seed {seed}"
            );
        }
        // The diagonal formula on tie-heavy sets too (the sweep's open/closed counts).
        for seed in 0..20u64 {
            let xs = nasty(1 + 3 * seed as usize, 1, seed);
            let diag: Vec<f64> = xs.iter().flat_map(|&x| [x, x]).collect();
            assert!(
                (exact(&diag, 2) - diagonal_formula(&xs)).abs() < 1e-14,
                "seed {seed}"
            );
        }
        // In 1D the enumerator is the 1D formula.
        for seed in 0..20u64 {
            let xs = nasty(1 + seed as usize, 1, seed);
            assert!((enumerate(&xs, 1) - exact(&xs, 1)).abs() < 1e-15);
        }
    }

    #[test]
    fn bounds_bracket_the_exact_value_and_tighten_with_m() {
        for seed in 0..10u64 {
            for d in [1usize, 2, 3] {
                let pts = nasty(30, d, seed);
                let e = exact(&pts, d);
                for m in [1u32, 4, 16, 64] {
                    if d == 3 && m == 64 {
                        continue;
                    }
                    let b = bounds(&pts, d, m);
                    assert!(b.lower <= e + 1e-14 && e <= b.upper + 1e-14, "{b:?} vs {e}");
                    let gap = 1.0 - (1.0 - 1.0 / f64::from(m)).powi(d as i32);
                    assert!(b.upper - b.lower <= gap + 1e-14, "{b:?} m {m} d {d}");
                }
            }
        }
        // Hammersley: 2^m points on the 1/2^m grid in x — the bracket is tight in practice.
        let b = bounds(&hammersley(256), 2, 512);
        let e = exact(&hammersley(256), 2);
        assert!(b.lower <= e && e <= b.upper && b.upper - b.lower < 0.004);
    }

    #[test]
    fn errors_are_typed() {
        let set = PointSet::new(&[0.5, 0.5, 0.25, 0.75], 2).unwrap();
        let mut s = [0.0; 5];
        assert_eq!(
            star_discrepancy_2d(&set, &mut s),
            Err(Error::BufferTooShort {
                needed: 6,
                actual: 5
            })
        );
        assert_eq!(
            star_discrepancy_1d(&set, &mut s),
            Err(Error::NotInRange {
                what: "dims",
                value: 2,
                min: 1,
                max: 1
            })
        );
        let mut u = [0u32; 3];
        assert!(matches!(
            star_discrepancy_bounds(&set, 4, &mut u),
            Err(Error::BufferTooShort { .. })
        ));
        assert_eq!(
            star_discrepancy_bounds(&set, 0, &mut u),
            Err(Error::ZeroSize { what: "m" })
        );
        // 2 · (m + 1)² overflows for m = 2³² − 1; the error names the largest m that fits.
        let largest = largest_bounds_m(2);
        assert_eq!(
            star_discrepancy_bounds(&set, u32::MAX, &mut u),
            Err(Error::TooMany {
                what: "m",
                value: u64::from(u32::MAX),
                max: u64::from(largest)
            })
        );
        for d in 1..=MAX_DIMS {
            let m = largest_bounds_m(d);
            assert!(star_bounds_scratch_len(d, m).is_some(), "dims {d}");
            assert!(m == u32::MAX || star_bounds_scratch_len(d, m + 1).is_none());
        }
        // 200 points in 6D: 200^5 · 1200 critical-box work is far beyond the limit.
        let pts = random(200, 6, 1);
        let set = PointSet::new(&pts, 6).unwrap();
        let mut s = vec![0.0; star_discrepancy_scratch_len(200, 6).unwrap()];
        let cost = 6 * 200 * 201u64.pow(5);
        assert_eq!(
            star_discrepancy(&set, &mut s),
            Err(Error::TooMany {
                what: "enumeration cost",
                value: cost,
                max: ENUMERATION_LIMIT
            })
        );
        assert_eq!(star_bounds_scratch_len(MAX_DIMS, u32::MAX), None);
    }

    /// The documented limit: a cost equal to [`ENUMERATION_LIMIT`] is enumerated, one more is
    /// refused.
    #[test]
    fn the_enumeration_limit_is_inclusive() {
        assert!(within_enumeration_limit(ENUMERATION_LIMIT));
        assert!(!within_enumeration_limit(ENUMERATION_LIMIT + 1));
        assert!(within_enumeration_limit(0));
    }

    /// The bracket of [`star_discrepancy_bounds`] by its definition, counting points directly:
    /// `lower` over every grid point `g` (`λ(g) − #{x < g}/N`, `#{x ≤ g}/N − λ(g)`), `upper` over
    /// every cell `[a, a + 1/m]` (`#{x ≤ a⁺}/N − λ(a)`, `λ(a⁺) − #{x < a}/N`). Grid values are
    /// `j as f64 / m`, as documented.
    fn brute_bounds(coords: &[f64], d: usize, m: u32) -> (f64, f64) {
        let n = coords.len() / d;
        let inv_n = 1.0 / n as f64;
        let side = m as usize + 1;
        let g = |j: usize| j as f64 / f64::from(m);
        let count = |q: &[f64], closed: bool| {
            let inside = |p: &&[f64]| {
                p.iter()
                    .zip(q)
                    .all(|(&x, &t)| if closed { x <= t } else { x < t })
            };
            coords.chunks_exact(d).filter(inside).count() as f64 * inv_n
        };
        let (mut lower, mut upper) = (0.0f64, 0.0f64);
        let mut idx = vec![0usize; d];
        loop {
            let q: Vec<f64> = idx.iter().map(|&j| g(j)).collect();
            let v: f64 = q.iter().product();
            lower = lower.max(v - count(&q, false)).max(count(&q, true) - v);
            if idx.iter().all(|&j| j < m as usize) {
                let qu: Vec<f64> = idx.iter().map(|&j| g(j + 1)).collect();
                let vu: f64 = qu.iter().product();
                upper = upper.max(count(&qu, true) - v).max(vu - count(&q, false));
            }
            let mut k = 0;
            loop {
                if k == d {
                    return (lower, upper);
                }
                idx[k] += 1;
                if idx[k] < side {
                    break;
                }
                idx[k] = 0;
                k += 1;
            }
        }
    }

    #[test]
    fn bounds_equal_their_definition_by_direct_counts() {
        for seed in 0..12u64 {
            for d in [1usize, 2, 3] {
                let n = 1 + (seed as usize * 5) % 23;
                // Coordinates on the grid (ties with grid values), at 0 and 1, and anywhere.
                let mut pts = nasty(n, d, seed + 7);
                for (i, x) in pts.iter_mut().enumerate() {
                    if i % 5 == 1 {
                        *x = f64::from((i % 7) as u32) / 6.0;
                    }
                }
                for m in [1u32, 2, 3, 5, 6, 8] {
                    let b = bounds(&pts, d, m);
                    let (lo, up) = brute_bounds(&pts, d, m);
                    assert!(
                        (b.lower - lo).abs() < 1e-15 && (b.upper - up).abs() < 1e-15,
                        "seed {seed} d {d} m {m}: {b:?} vs ({lo}, {up})"
                    );
                }
            }
        }
    }

    #[test]
    fn bounds_bin_points_beside_grid_values_by_their_f64_order() {
        // Beside or on a grid value k/m, x·m can round to the far side of k (at m = 6, the float
        // just below 5/6 gives x·6 = 5; just above 1/3 gives x·3 = 1; 15/22 gives x·22 < 15 and
        // 7/25 gives x·25 > 7): the binning must still follow the f64 order of x and the grid
        // values `j as f64 / m`, as the direct counts do.
        for m in [3u32, 6, 10, 12, 13, 22, 25] {
            let mut xs = Vec::new();
            for k in 0..=m {
                let g = f64::from(k) / f64::from(m);
                xs.extend(
                    [g.next_down(), g, g.next_up()]
                        .into_iter()
                        .filter(|x| (0.0..=1.0).contains(x)),
                );
            }
            let b = bounds(&xs, 1, m);
            assert_eq!((b.lower, b.upper), brute_bounds(&xs, 1, m), "m {m}");
            // Each neighbour alone, where one misbinned point moves the counts by 1/N = 1.
            for &x in &xs {
                let b = bounds(&[x], 1, m);
                assert_eq!((b.lower, b.upper), brute_bounds(&[x], 1, m), "m {m} x {x}");
            }
            // Pairs in 2D: the same values on both axes, crossed.
            let pts: Vec<f64> = xs
                .iter()
                .zip(xs.iter().rev())
                .flat_map(|(&a, &b)| [a, b])
                .collect();
            let b = bounds(&pts, 2, m);
            assert_eq!((b.lower, b.upper), brute_bounds(&pts, 2, m), "m {m} 2D");
        }
    }

    #[test]
    fn scratch_lengths_are_exactly_what_the_functions_need() {
        for d in 1..=4usize {
            for n in [1usize, 2, 5] {
                let pts = nasty(n, d, (d * 10 + n) as u64);
                let set = PointSet::new(&pts, d).unwrap();
                let len = star_discrepancy_scratch_len(n, d).unwrap();
                // As documented: 2n + (d − 1)(n + 1).
                assert_eq!(len, 2 * n + (d - 1) * (n + 1));
                let mut s = vec![0.0; len];
                assert!(star_discrepancy_enumerate(&set, &mut s).is_ok());
                assert_eq!(
                    star_discrepancy_enumerate(&set, &mut s[..len - 1]),
                    Err(Error::BufferTooShort {
                        needed: len,
                        actual: len - 1
                    })
                );
                for m in [1u32, 3] {
                    let len = star_bounds_scratch_len(d, m).unwrap();
                    assert_eq!(len, 2 * (m as usize + 1).pow(d as u32));
                    let mut u = vec![0u32; len];
                    assert!(star_discrepancy_bounds(&set, m, &mut u).is_ok());
                    assert!(matches!(
                        star_discrepancy_bounds(&set, m, &mut u[..len - 1]),
                        Err(Error::BufferTooShort { .. })
                    ));
                }
            }
        }
        assert_eq!(star_discrepancy_scratch_len(5, 0), None);
        assert_eq!(star_discrepancy_scratch_len(usize::MAX, 1), None);
        assert_eq!(star_discrepancy_scratch_len(usize::MAX / 2, 2), None);
        assert_eq!(star_bounds_scratch_len(0, 4), None);
        assert_eq!(star_bounds_scratch_len(3, 0), None);
        assert_eq!(star_bounds_scratch_len(1, 1), Some(4));
    }

    #[test]
    fn max_dims_is_accepted_and_one_more_refused() {
        // One point at (1, …, 1): the empty open box [0, 1)^d has volume 1, so D* = 1, and every
        // axis has the single critical value 1, so the enumeration is cheap even at 32 dims.
        let ones = [1.0; MAX_DIMS + 1];
        let set = PointSet::new(&ones[..MAX_DIMS], MAX_DIMS).unwrap();
        let mut s = vec![0.0; star_discrepancy_scratch_len(1, MAX_DIMS).unwrap()];
        assert_eq!(star_discrepancy(&set, &mut s), Ok(1.0));
        let set = PointSet::new(&ones, MAX_DIMS + 1).unwrap();
        let mut s = vec![0.0; star_discrepancy_scratch_len(1, MAX_DIMS + 1).unwrap()];
        assert_eq!(
            star_discrepancy_enumerate(&set, &mut s),
            Err(Error::NotInRange {
                what: "dims",
                value: MAX_DIMS as u64 + 1,
                min: 1,
                max: MAX_DIMS as u64
            })
        );
        let mut u = [0u32; 4];
        assert_eq!(
            star_discrepancy_bounds(&set, 1, &mut u),
            Err(Error::NotInRange {
                what: "dims",
                value: MAX_DIMS as u64 + 1,
                min: 1,
                max: MAX_DIMS as u64
            })
        );
        // The bracket accepts 32 dimensions too: with m = 1 it asks for its 2 · 2^32 counters
        // (more than this test can give it) rather than refusing the dimension.
        #[cfg(target_pointer_width = "64")]
        {
            let set = PointSet::new(&ones[..MAX_DIMS], MAX_DIMS).unwrap();
            assert_eq!(
                star_discrepancy_bounds(&set, 1, &mut u),
                Err(Error::BufferTooShort {
                    needed: 2 << 32,
                    actual: 4
                })
            );
        }
    }

    #[test]
    fn twenty_dimensions_two_points_by_hand() {
        // (½, …, ½) and (1, …, 1) in 20 dimensions. The open box [0, 1)^20 holds only the first
        // point: deficit 1 − ½; every other open box has volume at most ½. A closed box holding
        // the first point only has excess at most ½ − 2^−20, one holding both is [0, 1]^20
        // (excess 0). So D* = ½. The critical grid has 2 values per axis (½ and 1, the 1 counted
        // once although a point lies on it): cost 20 · 2 · 2^19, far inside the limit.
        let mut pts = vec![0.5; 20];
        pts.extend([1.0; 20]);
        assert_eq!(exact(&pts, 20), 0.5);
    }

    proptest! {
        #[test]
        fn any_set_gives_star_in_unit_interval(
            dims in 1usize..4,
            raw in proptest::collection::vec(
                prop_oneof![Just(0.0f64), Just(1.0f64), 0.0f64..=1.0, Just(0.5f64)], 1..40),
            m in 1u32..20,
        ) {
            let n = (raw.len() / dims).max(1);
            let mut pts = raw.clone();
            pts.resize(n * dims, 0.5);
            let e = exact(&pts, dims);
            prop_assert!((0.0..=1.0).contains(&e));
            prop_assert!(e >= 0.5 / n as f64 - 1e-15); // D* ≥ 1/(2N) for any set
            let b = bounds(&pts, dims, m);
            prop_assert!(b.lower <= e + 1e-14 && e <= b.upper + 1e-14);
            prop_assert!((0.0..=1.0).contains(&b.lower) && (0.0..=1.0).contains(&b.upper));
            if dims == 2 && n <= 12 {
                prop_assert!((e - brute(&pts, 2)).abs() < 1e-14);
            }
        }
    }
}
