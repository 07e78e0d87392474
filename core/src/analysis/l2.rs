//! L2 discrepancies by their closed forms, O(d·N²) time, no scratch.
//!
//! - L2-star (Warnock 1972):
//!   `T² = 3^−d − (2^{1−d}/N) Σ_i Π_k (1 − x_ik²) + (1/N²) Σ_i Σ_j Π_k (1 − max(x_ik, x_jk))`.
//! - Centered L2 (Hickernell 1998, eq. 5.1c):
//!   `CD² = (13/12)^d − (2/N) Σ_i Π_k (1 + ½|x_ik − ½| − ½|x_ik − ½|²)
//!   + (1/N²) Σ_i Σ_j Π_k (1 + ½|x_ik − ½| + ½|x_jk − ½| − ½|x_ik − x_jk|)`.
//! - Wrap-around L2 (Hickernell 1998, eq. 5.1d):
//!   `WD² = −(4/3)^d + (1/N²) Σ_i Σ_j Π_k (3/2 − |x_ik − x_jk| (1 − |x_ik − x_jk|))`.
//! - Mixture L2 (Zhou, Fang and Ning 2013, "Mixture discrepancy for quasi-random point sets"):
//!   `MD² = (19/12)^d − (2/N) Σ_i Π_k (5/3 − ¼|x_ik − ½| − ¼|x_ik − ½|²)
//!   + (1/N²) Σ_i Σ_j Π_k (15/8 − ¼|x_ik − ½| − ¼|x_jk − ½| − ¾|x_ik − x_jk| + ½|x_ik − x_jk|²)`.
//!
//! The double sums use the symmetry of the kernel (diagonal once, each pair twice). The result is
//! the square root of the formula, clamped at 0 against rounding.

use core::ops::Range;

use super::PointSet;
use crate::Error;
use crate::math::{pow, sqrt};

/// `Σ_i Σ_j K(x_i, x_j)` for a symmetric kernel: each row summed in four lanes (less rounding,
/// and the lanes vectorise), the rows added with Neumaier's compensated summation. The result
/// is a small difference of O(1) terms, so summation error would otherwise dominate for large N.
/// Dimensions 1–4 get a copy with the dimension fixed at compile time (unrolled kernels).
/// Only the rows `i` in `rows` (within `0..N`) are summed, each with the points `j ≥ i`: rows
/// that partition `0..N` give sums that add up to the whole.
#[inline]
fn double_sum(
    points: &PointSet<'_>,
    rows: Range<usize>,
    kernel: impl Fn(&[f64], &[f64]) -> f64,
) -> f64 {
    let c = points.coords();
    match points.dims() {
        1 => double_sum_fixed::<1>(c, rows, &kernel),
        2 => double_sum_fixed::<2>(c, rows, &kernel),
        3 => double_sum_fixed::<3>(c, rows, &kernel),
        4 => double_sum_fixed::<4>(c, rows, &kernel),
        d => {
            let mut total = Neumaier::default();
            for (i, p) in (rows.start..).zip(c[rows.start * d..rows.end * d].chunks_exact(d)) {
                let mut row = 0.0;
                for q in c[(i + 1) * d..].chunks_exact(d) {
                    row += kernel(p, q);
                }
                total.add(2.0 * row);
                total.add(kernel(p, p));
            }
            total.sum()
        }
    }
}

#[cfg_attr(not(feature = "small-code"), inline(always))]
fn double_sum_fixed<const D: usize>(
    c: &[f64],
    rows: Range<usize>,
    kernel: &impl Fn(&[f64], &[f64]) -> f64,
) -> f64 {
    let (pts, _) = c.as_chunks::<D>();
    let mut total = Neumaier::default();
    for (i, p) in (rows.start..).zip(&pts[rows.clone()]) {
        let mut lanes = [0.0f64; 4];
        let (quads, tail) = pts[i + 1..].as_chunks::<4>();
        for quad in quads {
            for (lane, q) in lanes.iter_mut().zip(quad) {
                *lane += kernel(p, q);
            }
        }
        for q in tail {
            lanes[0] += kernel(p, q);
        }
        let row = (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
        total.add(2.0 * row);
        total.add(kernel(p, p));
    }
    total.sum()
}

/// `max(a, b)` for non-NaN inputs, written so it vectorises (`f64::max` carries NaN rules).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn max2(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// Neumaier's improved Kahan summation.
#[derive(Default)]
struct Neumaier {
    sum: f64,
    carry: f64,
}

impl Neumaier {
    #[inline]
    fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.carry += (self.sum - t) + x;
        } else {
            self.carry += (x - t) + self.sum;
        }
        self.sum = t;
    }

    #[inline]
    fn sum(&self) -> f64 {
        self.sum + self.carry
    }
}

/// `Σ_i f(x_i)` over the rows `i` in `rows` (within `0..N`), compensated.
#[inline]
fn single_sum(points: &PointSet<'_>, rows: Range<usize>, f: impl Fn(&[f64]) -> f64) -> f64 {
    let d = points.dims();
    let mut total = Neumaier::default();
    for p in points.coords()[rows.start * d..rows.end * d].chunks_exact(d) {
        total.add(f(p));
    }
    total.sum()
}

/// One of the four L2 discrepancies of the module docs.
///
/// ```
/// use nyquist::analysis::{l2_sums, L2Kind, PointSet};
/// let set = PointSet::new(&[0.25, 0.75], 1).unwrap();
/// assert_eq!(l2_sums(&set, L2Kind::WrapAround).weight, 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum L2Kind {
    /// The L2-star discrepancy (Warnock 1972): boxes anchored at the origin.
    Star,
    /// The centered L2 discrepancy (Hickernell 1998): boxes anchored at the nearest corner.
    Centered,
    /// The wrap-around L2 discrepancy (Hickernell 1998): boxes on the torus.
    WrapAround,
    /// The mixture L2 discrepancy (Zhou, Fang and Ning 2013).
    Mixture,
}

/// The sums of an L2 discrepancy's closed form (module docs): for `N` points,
/// `D² = constant − (weight / N)·single + pairs / N²`, where `single = Σ_i f(x_i)` and
/// `pairs = Σ_i Σ_j K(x_i, x_j)` with the kind's `f` and `K`.
///
/// Keeping the sums instead of `D` lets a caller change `N` ([`L2Sums::squared`] with `N + 1`
/// is SciPy's `discrepancy(..., iterative=True)`), and add a point in `O(d·N)`
/// ([`l2_point_sums`]).
///
/// ```
/// use nyquist::analysis::{centered_l2_discrepancy, l2_sums, L2Kind, PointSet};
/// let set = PointSet::new(&[0.1, 0.4, 0.8], 1).unwrap();
/// let sums = l2_sums(&set, L2Kind::Centered);
/// assert_eq!(sums.squared(3.0).sqrt(), centered_l2_discrepancy(&set));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct L2Sums {
    /// Which discrepancy.
    pub kind: L2Kind,
    /// The integral of the kernel over the cube: `3^−d`, `(13/12)^d`, `−(4/3)^d` or
    /// `(19/12)^d` (0 in the sums one point adds, [`l2_point_sums`]).
    pub constant: f64,
    /// The factor of the single sum: `2^{1−d}` for L2-star, 2 for centered and mixture, 0 for
    /// wrap-around.
    pub weight: f64,
    /// `Σ_i f(x_i)`.
    pub single: f64,
    /// `Σ_i Σ_j K(x_i, x_j)`, each pair twice and the diagonal once.
    pub pairs: f64,
}

impl L2Sums {
    /// `D²` for `n` points: `constant − (weight / n)·single + pairs / n²`, not clamped (a
    /// rounding can make a tiny `D²` negative).
    ///
    /// ```
    /// use nyquist::analysis::{l2_sums, L2Kind, PointSet};
    /// // One point at the origin: T² = 1/3 − 1 + 1.
    /// let sums = l2_sums(&PointSet::new(&[0.0], 1).unwrap(), L2Kind::Star);
    /// assert!((sums.squared(1.0) - 1.0 / 3.0).abs() < 1e-15);
    /// ```
    pub fn squared(&self, n: f64) -> f64 {
        self.constant - self.weight / n * self.single + self.pairs / (n * n)
    }
}

/// `1 − x²` per coordinate: L2-star's `f`.
#[inline]
fn star_single(p: &[f64]) -> f64 {
    p.iter().map(|&x| 1.0 - x * x).product()
}

#[inline]
fn star_pair(p: &[f64], q: &[f64]) -> f64 {
    p.iter().zip(q).map(|(&a, &b)| 1.0 - max2(a, b)).product()
}

#[inline]
fn centered_single(p: &[f64]) -> f64 {
    p.iter()
        .map(|&x| {
            let a = (x - 0.5).abs();
            1.0 + 0.5 * a - 0.5 * a * a
        })
        .product()
}

#[inline]
fn centered_pair(p: &[f64], q: &[f64]) -> f64 {
    p.iter()
        .zip(q)
        .map(|(&a, &b)| 1.0 + 0.5 * (a - 0.5).abs() + 0.5 * (b - 0.5).abs() - 0.5 * (a - b).abs())
        .product()
}

#[inline]
fn wraparound_pair(p: &[f64], q: &[f64]) -> f64 {
    p.iter()
        .zip(q)
        .map(|(&a, &b)| {
            let t = (a - b).abs();
            1.5 - t * (1.0 - t)
        })
        .product()
}

#[inline]
fn mixture_single(p: &[f64]) -> f64 {
    p.iter()
        .map(|&x| {
            let a = (x - 0.5).abs();
            5.0 / 3.0 - 0.25 * a - 0.25 * a * a
        })
        .product()
}

#[inline]
fn mixture_pair(p: &[f64], q: &[f64]) -> f64 {
    p.iter()
        .zip(q)
        .map(|(&a, &b)| {
            let t = (a - b).abs();
            15.0 / 8.0 - 0.25 * (a - 0.5).abs() - 0.25 * (b - 0.5).abs() - 0.75 * t + 0.5 * t * t
        })
        .product()
}

/// A kind's `f`.
type Single = fn(&[f64]) -> f64;

/// A kind's `K`.
type Pair = fn(&[f64], &[f64]) -> f64;

/// The kind's constant and single-sum weight in `d` dimensions.
fn constant_and_weight(kind: L2Kind, d: f64) -> (f64, f64) {
    match kind {
        L2Kind::Star => (pow(3.0, -d), pow(2.0, 1.0 - d)),
        L2Kind::Centered => (pow(13.0 / 12.0, d), 2.0),
        L2Kind::WrapAround => (-pow(4.0 / 3.0, d), 0.0),
        L2Kind::Mixture => (pow(19.0 / 12.0, d), 2.0),
    }
}

/// The sums of `kind`'s closed form over `points` ([`L2Sums`]). O(d·N²); allocates: no.
///
/// ```
/// use nyquist::analysis::{l2_sums, L2Kind, PointSet};
/// let sums = l2_sums(&PointSet::new(&[0.5, 0.5], 2).unwrap(), L2Kind::Mixture);
/// assert_eq!(sums.single, (5.0f64 / 3.0).powi(2));
/// assert_eq!(sums.pairs, (15.0f64 / 8.0).powi(2));
/// ```
pub fn l2_sums(points: &PointSet<'_>, kind: L2Kind) -> L2Sums {
    l2_sums_rows(points, kind, 0..points.len())
}

/// The part of [`l2_sums`] that the rows `i` in `rows` contribute: `f(x_i)` to `single`, and
/// `K(x_i, x_i) + 2·Σ_{j>i} K(x_i, x_j)` to `pairs` (`constant` and `weight` are the whole
/// set's). Sums over rows that partition `0..N` add up to `l2_sums` (up to rounding), so
/// threads can share the O(d·N²) work: row `i` costs `N − i` kernel calls. `rows` is clamped
/// to `0..N`. Allocates: no.
///
/// ```
/// use nyquist::analysis::{l2_sums, l2_sums_rows, L2Kind, PointSet};
/// let set = PointSet::new(&[0.1, 0.9, 0.4, 0.3, 0.75, 0.2], 2).unwrap();
/// let (a, b) = (l2_sums_rows(&set, L2Kind::Star, 0..1), l2_sums_rows(&set, L2Kind::Star, 1..9));
/// let whole = l2_sums(&set, L2Kind::Star);
/// assert!((a.pairs + b.pairs - whole.pairs).abs() < 1e-15);
/// assert!((a.single + b.single - whole.single).abs() < 1e-15);
/// ```
pub fn l2_sums_rows(points: &PointSet<'_>, kind: L2Kind, rows: Range<usize>) -> L2Sums {
    match kind {
        L2Kind::Star => sums_of(points, kind, rows, star_single, star_pair),
        L2Kind::Centered => sums_of(points, kind, rows, centered_single, centered_pair),
        L2Kind::WrapAround => sums_of(points, kind, rows, |_| 0.0, wraparound_pair),
        L2Kind::Mixture => sums_of(points, kind, rows, mixture_single, mixture_pair),
    }
}

/// [`l2_sums_rows`] for one kind's `f` and `K`, so that a caller naming one kind (the
/// `*_l2_discrepancy` functions) carries only that kind's kernels: a browser build that uses
/// three of the four does not link the fourth.
#[inline]
fn sums_of(
    points: &PointSet<'_>,
    kind: L2Kind,
    rows: Range<usize>,
    f: impl Fn(&[f64]) -> f64,
    k: impl Fn(&[f64], &[f64]) -> f64,
) -> L2Sums {
    let n = points.len();
    let rows = rows.start.min(n)..rows.end.min(n);
    let (constant, weight) = constant_and_weight(kind, points.dims() as f64);
    L2Sums {
        kind,
        constant,
        weight,
        single: single_sum(points, rows.clone(), f),
        pairs: double_sum(points, rows, k),
    }
}

/// The sums that adding point `x` to `points` adds to [`l2_sums`]`(points, kind)`: `constant`
/// 0, `single = f(x)`, `pairs = 2·Σ_i K(x_i, x) + K(x, x)`. So for `N` points and a discrepancy
/// `D²` computed with `N + 1` in its normalisation, `D² + l2_point_sums(..).squared(N + 1)` is
/// the squared discrepancy of the `N + 1` points: SciPy's `update_discrepancy` (which offers
/// the centered one only). O(d·N); allocates: no.
///
/// # Errors
/// [`Error::NotInRange`] (`what: "point dims"`) when `x` does not have `points.dims()`
/// coordinates; [`Error::NonFinite`] or [`Error::OutOfRange`] for a coordinate that is NaN, ±∞
/// or outside `[0, 1]`, as [`PointSet::new`].
///
/// ```
/// use nyquist::analysis::{l2_point_sums, l2_sums, L2Kind, PointSet};
/// let all = [0.1, 0.2, 0.7, 0.4, 0.35, 0.9];
/// let first = PointSet::new(&all[..4], 2).unwrap();
/// let whole = l2_sums(&PointSet::new(&all, 2).unwrap(), L2Kind::Centered).squared(3.0);
/// let before = l2_sums(&first, L2Kind::Centered).squared(3.0);
/// let added = l2_point_sums(&first, &all[4..], L2Kind::Centered).unwrap().squared(3.0);
/// assert!((before + added - whole).abs() < 1e-15);
/// ```
pub fn l2_point_sums(points: &PointSet<'_>, x: &[f64], kind: L2Kind) -> Result<L2Sums, Error> {
    let d = points.dims();
    if x.len() != d {
        return Err(Error::NotInRange {
            what: "point dims",
            value: x.len() as u64,
            min: d as u64,
            max: d as u64,
        });
    }
    PointSet::new(x, d)?;
    let (_, weight) = constant_and_weight(kind, d as f64);
    let (f, k): (Single, Pair) = match kind {
        L2Kind::Star => (star_single, star_pair),
        L2Kind::Centered => (centered_single, centered_pair),
        L2Kind::WrapAround => (|_| 0.0, wraparound_pair),
        L2Kind::Mixture => (mixture_single, mixture_pair),
    };
    let cross = single_sum(points, 0..points.len(), |p| k(p, x));
    Ok(L2Sums {
        kind,
        constant: 0.0,
        weight,
        single: f(x),
        pairs: 2.0 * cross + k(x, x),
    })
}

/// `sqrt(max(D², 0))` from the sums over all of `points`, with `N` their count.
fn l2_discrepancy(points: &PointSet<'_>, sums: L2Sums) -> f64 {
    sqrt(sums.squared(points.len() as f64).max(0.0))
}

/// L2-star discrepancy `T_N` by Warnock's formula (module docs). O(d·N²); allocates: no.
/// `N·T_N` for the van der Corput set of `N = 2^m` points is `1/√3`.
///
/// ```
/// use nyquist::analysis::{l2_star_discrepancy, PointSet};
/// // One point at the origin: T² = 1/3 − 1 + 1.
/// let t = l2_star_discrepancy(&PointSet::new(&[0.0], 1).unwrap());
/// assert!((t - (1.0f64 / 3.0).sqrt()).abs() < 1e-15);
/// ```
pub fn l2_star_discrepancy(points: &PointSet<'_>) -> f64 {
    let sums = sums_of(
        points,
        L2Kind::Star,
        0..points.len(),
        star_single,
        star_pair,
    );
    l2_discrepancy(points, sums)
}

/// Centered L2 discrepancy (Hickernell 1998; module docs): invariant under reflections
/// `x_k → 1 − x_k`. O(d·N²); allocates: no.
///
/// ```
/// use nyquist::analysis::{centered_l2_discrepancy, PointSet};
/// let a = centered_l2_discrepancy(&PointSet::new(&[0.1, 0.7], 1).unwrap());
/// let b = centered_l2_discrepancy(&PointSet::new(&[0.9, 0.3], 1).unwrap());
/// assert!((a - b).abs() < 1e-15);
/// ```
pub fn centered_l2_discrepancy(points: &PointSet<'_>) -> f64 {
    let sums = sums_of(
        points,
        L2Kind::Centered,
        0..points.len(),
        centered_single,
        centered_pair,
    );
    l2_discrepancy(points, sums)
}

/// Wrap-around L2 discrepancy (Hickernell 1998; module docs): invariant under toroidal shifts.
/// O(d·N²); allocates: no.
///
/// ```
/// use nyquist::analysis::{wraparound_l2_discrepancy, PointSet};
/// // Evenly spaced points on the circle have the least wrap-around discrepancy, wherever they start.
/// let a = wraparound_l2_discrepancy(&PointSet::new(&[0.0, 0.5], 1).unwrap());
/// let b = wraparound_l2_discrepancy(&PointSet::new(&[0.3, 0.8], 1).unwrap());
/// assert!((a - b).abs() < 1e-15);
/// ```
pub fn wraparound_l2_discrepancy(points: &PointSet<'_>) -> f64 {
    let sums = sums_of(
        points,
        L2Kind::WrapAround,
        0..points.len(),
        |_| 0.0,
        wraparound_pair,
    );
    l2_discrepancy(points, sums)
}

/// Mixture L2 discrepancy (Zhou, Fang and Ning 2013; module docs): invariant under reflections
/// like the centered one, and free of its flaws under shifts of the points. O(d·N²); allocates:
/// no.
///
/// ```
/// use nyquist::analysis::{mixture_l2_discrepancy, PointSet};
/// // One point at the centre of the square: MD² = (19/12)² − 2·(5/3)² + (15/8)².
/// let md = mixture_l2_discrepancy(&PointSet::new(&[0.5, 0.5], 2).unwrap());
/// let want: f64 = (19.0f64 / 12.0).powi(2) - 2.0 * (5.0f64 / 3.0).powi(2) + (15.0f64 / 8.0).powi(2);
/// assert!((md - want.sqrt()).abs() < 1e-15);
/// ```
pub fn mixture_l2_discrepancy(points: &PointSet<'_>) -> f64 {
    let sums = sums_of(
        points,
        L2Kind::Mixture,
        0..points.len(),
        mixture_single,
        mixture_pair,
    );
    l2_discrepancy(points, sums)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::testsets::{hammersley, random, van_der_corput};
    use proptest::prelude::*;
    use std::vec::Vec;

    fn set(c: &[f64], d: usize) -> PointSet<'_> {
        PointSet::new(c, d).unwrap()
    }

    #[test]
    fn van_der_corput_l2_star_is_one_over_sqrt3_n() {
        for m in 0..=12u32 {
            let n = 1u32 << m;
            let t = l2_star_discrepancy(&set(&van_der_corput(n), 1));
            let expected = 1.0 / (3f64.sqrt() * f64::from(n));
            assert!((t - expected).abs() < 1e-9 * expected, "m = {m}: {t}");
        }
    }

    #[test]
    fn hammersley_l2_star_matches_closed_form() {
        for m in 1..=12i32 {
            let n = f64::from(1u32 << m);
            let mf = f64::from(m);
            let expected = mf * mf / 64.0 + 29.0 * mf / 192.0 + 3.0 / 8.0 - mf / 2f64.powi(m + 4)
                + 1.0 / 2f64.powi(m + 2)
                - 1.0 / (72.0 * 4f64.powi(m));
            let t = l2_star_discrepancy(&set(&hammersley(1 << m), 2));
            let got = (n * t).powi(2);
            assert!(
                (got - expected).abs() < 1e-9 * expected,
                "m = {m}: {got} vs {expected}"
            );
        }
    }

    #[test]
    fn l2_star_in_1d_matches_the_sorted_closed_form() {
        // T² = 1/(12N²) + (1/N) Σ (x_(i) − (2i−1)/(2N))² (Niederreiter 1992, Thm. 2.14).
        for seed in 0..20 {
            let n = 1 + seed * 5;
            let mut xs = random(n, 1, seed as u64);
            let t = l2_star_discrepancy(&set(&xs, 1));
            xs.sort_by(f64::total_cmp);
            let nf = n as f64;
            let s: f64 = xs
                .iter()
                .enumerate()
                .map(|(i, &x)| (x - (2 * i + 1) as f64 / (2.0 * nf)).powi(2))
                .sum();
            let expected = (1.0 / (12.0 * nf * nf) + s / nf).sqrt();
            assert!((t - expected).abs() < 1e-12, "{t} vs {expected}");
        }
    }

    #[test]
    fn random_sets_average_the_expected_squared_l2_star() {
        // E[T²] = (2^−d − 3^−d)/N for N independent uniform points.
        const SETS: usize = 2000;
        const N: usize = 32;
        for d in 1..=4usize {
            let samples: Vec<f64> = (0..SETS)
                .map(|s| {
                    let pts = random(N, d, (d * 100_000 + s) as u64);
                    l2_star_discrepancy(&set(&pts, d)).powi(2)
                })
                .collect();
            let mean = samples.iter().sum::<f64>() / SETS as f64;
            let var = samples.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (SETS - 1) as f64;
            let se = (var / SETS as f64).sqrt();
            let expected = (0.5f64.powi(d as i32) - (1.0 / 3.0f64).powi(d as i32)) / N as f64;
            assert!(
                (mean - expected).abs() < 3.0 * se,
                "d {d}: {mean} vs {expected} ± {se}"
            );
        }
    }

    #[test]
    fn centered_l2_matches_scipy_example() {
        // scipy.stats.qmc.discrepancy docs: the 6-point design [[1,3],[2,6],[3,2],[4,5],[5,1],
        // [6,4]] scaled from [0.5, 6.5]² gives CD² = 0.008142039609053464.
        let raw = [
            [1.0, 3.0],
            [2.0, 6.0],
            [3.0, 2.0],
            [4.0, 5.0],
            [5.0, 1.0],
            [6.0, 4.0],
        ];
        let pts: Vec<f64> = raw
            .iter()
            .flat_map(|p| p.map(|v: f64| (v - 0.5) / 6.0))
            .collect();
        let cd = centered_l2_discrepancy(&set(&pts, 2));
        assert!(
            (cd * cd - 0.008142039609053464).abs() < 1e-15,
            "{}",
            cd * cd
        );
        // SciPy 1.17.1's qmc.discrepancy(x, method="MD") of the same design.
        let md = mixture_l2_discrepancy(&set(&pts, 2));
        assert!(
            (md * md - 0.014895592206789487).abs() < 1e-15,
            "{}",
            md * md
        );
    }

    #[test]
    fn wraparound_is_shift_invariant_and_centered_reflection_invariant() {
        for seed in 0..10u64 {
            let pts = random(25, 3, seed);
            let shifted: Vec<f64> = pts.iter().map(|&x| (x + 0.37) % 1.0).collect();
            let reflected: Vec<f64> = pts.iter().map(|&x| 1.0 - x).collect();
            let (w, ws) = (
                wraparound_l2_discrepancy(&set(&pts, 3)),
                wraparound_l2_discrepancy(&set(&shifted, 3)),
            );
            assert!((w - ws).abs() < 1e-12);
            let (c, cr) = (
                centered_l2_discrepancy(&set(&pts, 3)),
                centered_l2_discrepancy(&set(&reflected, 3)),
            );
            assert!((c - cr).abs() < 1e-12);
            let (m, mr) = (
                mixture_l2_discrepancy(&set(&pts, 3)),
                mixture_l2_discrepancy(&set(&reflected, 3)),
            );
            assert!((m - mr).abs() < 1e-12);
            // L2-star is not reflection invariant: the check is not vacuous.
            assert!(
                (l2_star_discrepancy(&set(&pts, 3)) - l2_star_discrepancy(&set(&reflected, 3)))
                    .abs()
                    > 1e-6
            );
        }
    }

    /// The four closed forms of the module docs summed term by term over all ordered pairs
    /// `(i, j)`, no symmetry, no lanes, no compensation: `[T², CD², WD², MD²]`.
    fn naive_squares(c: &[f64], d: usize) -> [f64; 4] {
        naive_squares_normalised(c, d, (c.len() / d) as f64)
    }

    /// [`naive_squares`] with `n` in the normalisation instead of the number of points.
    fn naive_squares_normalised(c: &[f64], d: usize, n: f64) -> [f64; 4] {
        let pts: Vec<&[f64]> = c.chunks_exact(d).collect();
        let df = d as f64;
        let (mut s_star, mut s_cd, mut p_star, mut p_cd, mut p_wd) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let (mut s_md, mut p_md) = (0.0, 0.0);
        for p in &pts {
            s_md += p
                .iter()
                .map(|&x| 5.0 / 3.0 - (x - 0.5).abs() / 4.0 - (x - 0.5).powi(2) / 4.0)
                .product::<f64>();
            for q in &pts {
                p_md += p
                    .iter()
                    .zip(q.iter())
                    .map(|(&a, &b)| {
                        1.875
                            - (a - 0.5).abs() / 4.0
                            - (b - 0.5).abs() / 4.0
                            - 3.0 * (a - b).abs() / 4.0
                            + (a - b).powi(2) / 2.0
                    })
                    .product::<f64>();
            }
            s_star += p.iter().map(|&x| 1.0 - x * x).product::<f64>();
            s_cd += p
                .iter()
                .map(|&x| 1.0 + 0.5 * (x - 0.5).abs() - 0.5 * (x - 0.5).powi(2))
                .product::<f64>();
            for q in &pts {
                let pairs = p.iter().zip(q.iter());
                p_star += pairs
                    .clone()
                    .map(|(&a, &b)| 1.0 - a.max(b))
                    .product::<f64>();
                p_cd += pairs
                    .clone()
                    .map(|(&a, &b)| {
                        1.0 + 0.5 * (a - 0.5).abs() + 0.5 * (b - 0.5).abs() - 0.5 * (a - b).abs()
                    })
                    .product::<f64>();
                p_wd += pairs
                    .map(|(&a, &b)| 1.5 - (a - b).abs() * (1.0 - (a - b).abs()))
                    .product::<f64>();
            }
        }
        [
            3f64.powf(-df) - 2f64.powf(1.0 - df) / n * s_star + p_star / (n * n),
            (13.0f64 / 12.0).powf(df) - 2.0 / n * s_cd + p_cd / (n * n),
            -(4.0f64 / 3.0).powf(df) + p_wd / (n * n),
            (19.0f64 / 12.0).powf(df) - 2.0 / n * s_md + p_md / (n * n),
        ]
    }

    #[test]
    fn every_dimension_matches_the_formulas_summed_naively() {
        // Dimensions 1–4 take the unrolled route, 5 and up the generic one; N from 1 to 13
        // covers rows with 0–3 points left over after the groups of four.
        for d in 1..=7usize {
            for n in 1..=13usize {
                let pts = random(n, d, (d * 100 + n) as u64);
                let s = set(&pts, d);
                let got = [
                    l2_star_discrepancy(&s),
                    centered_l2_discrepancy(&s),
                    wraparound_l2_discrepancy(&s),
                    mixture_l2_discrepancy(&s),
                ];
                let want = naive_squares(&pts, d);
                for (g, w) in got.iter().zip(want) {
                    assert!(w > 0.0, "d {d} n {n}: {want:?}");
                    assert!(
                        (g * g - w).abs() < 1e-12 * (1.0 + w),
                        "d {d} n {n}: {got:?} vs {want:?}"
                    );
                }
            }
        }
    }

    const KINDS: [L2Kind; 4] = [
        L2Kind::Star,
        L2Kind::Centered,
        L2Kind::WrapAround,
        L2Kind::Mixture,
    ];

    #[test]
    fn sums_renormalised_and_extended_match_the_naive_formulas() {
        // `squared(N + 1)` is SciPy's `iterative=True`; the sums of the first N − 1 points plus
        // those the last point adds give the whole set's discrepancy, both normalised by N.
        for d in 1..=6usize {
            for n in 2..=9usize {
                let pts = random(n, d, (d * 1000 + n) as u64);
                let whole = set(&pts, d);
                let first = set(&pts[..(n - 1) * d], d);
                let last = &pts[(n - 1) * d..];
                let renormalised = naive_squares_normalised(&pts, d, (n + 1) as f64);
                let want = naive_squares(&pts, d);
                for (k, kind) in KINDS.into_iter().enumerate() {
                    let sums = l2_sums(&whole, kind);
                    assert_eq!(sums.kind, kind);
                    let it = sums.squared((n + 1) as f64);
                    let tol = 1e-12 * (1.0 + renormalised[k].abs());
                    assert!(
                        (it - renormalised[k]).abs() < tol,
                        "{kind:?} d {d} n {n}: {it}"
                    );
                    let added = l2_point_sums(&first, last, kind).unwrap();
                    assert_eq!((added.kind, added.constant), (kind, 0.0));
                    let nf = n as f64;
                    let got = l2_sums(&first, kind).squared(nf) + added.squared(nf);
                    let tol = 1e-12 * (1.0 + want[k]);
                    assert!((got - want[k]).abs() < tol, "{kind:?} d {d} n {n}: {got}");
                }
            }
        }
    }

    #[test]
    fn row_ranges_that_partition_the_set_add_up_to_its_sums() {
        // Dimensions 1–4 (unrolled) and 5–6 (generic); cuts at the ends, in the middle, and a
        // range past the end, which is clamped.
        for d in 1..=6usize {
            let n = 23;
            let pts = random(n, d, (d * 7) as u64);
            let s = set(&pts, d);
            for kind in KINDS {
                let whole = l2_sums(&s, kind);
                for cut in [0, 1, 5, 11, 22, 23] {
                    let a = l2_sums_rows(&s, kind, 0..cut);
                    let b = l2_sums_rows(&s, kind, cut..n + 40);
                    assert_eq!((a.constant, a.weight), (whole.constant, whole.weight));
                    assert!((a.pairs + b.pairs - whole.pairs).abs() < 1e-12 * whole.pairs);
                    let single = a.single + b.single - whole.single;
                    assert!(
                        single.abs() < 1e-12 * (1.0 + whole.single),
                        "{kind:?} d {d}"
                    );
                }
                // One row alone: its own kernel value plus twice those with the rows after it.
                let row = l2_sums_rows(&s, kind, 5..6);
                let rest = l2_sums_rows(&s, kind, 6..n);
                let from5 = l2_sums_rows(&s, kind, 5..n);
                assert!((row.pairs + rest.pairs - from5.pairs).abs() < 1e-12 * from5.pairs);
                assert!(row.pairs > 0.0 && row.pairs < from5.pairs, "{kind:?} d {d}");
                assert_eq!(l2_sums_rows(&s, kind, 30..40).pairs, 0.0);
            }
        }
    }

    #[test]
    fn point_sums_update_fang_et_als_design() {
        // Fang, Li and Sudjianto, "Design and Modeling for Computer Experiments" (2006): the
        // U-type design (1,3) (2,6) (3,2) (4,5) (5,1) (6,4), scaled by (2x − 1)/12, has
        // CD² = 0.0081 to the 4 decimals they print; SciPy's test of `update_discrepancy` builds it
        // from the first five points.
        let design = [1.0, 3.0, 2.0, 6.0, 3.0, 2.0, 4.0, 5.0, 5.0, 1.0, 6.0, 4.0];
        let pts: Vec<f64> = design.iter().map(|&x| (2.0 * x - 1.0) / 12.0).collect();
        let first = set(&pts[..10], 2);
        let before = l2_sums(&first, L2Kind::Centered).squared(6.0);
        let added = l2_point_sums(&first, &pts[10..], L2Kind::Centered).unwrap();
        let cd2 = before + added.squared(6.0);
        assert!((cd2 - 0.0081).abs() < 0.5e-4, "{cd2}");
        let whole = centered_l2_discrepancy(&set(&pts, 2));
        assert!((cd2 - whole * whole).abs() < 1e-15);
    }

    #[test]
    fn point_sums_refuse_a_bad_point() {
        let s = set(&[0.1, 0.2, 0.3, 0.4], 2);
        assert_eq!(
            l2_point_sums(&s, &[0.5], L2Kind::Centered).unwrap_err(),
            Error::NotInRange {
                what: "point dims",
                value: 1,
                min: 2,
                max: 2
            }
        );
        assert_eq!(
            l2_point_sums(&s, &[0.5, f64::NAN], L2Kind::Star).unwrap_err(),
            Error::NonFinite { what: "points" }
        );
        assert!(matches!(
            l2_point_sums(&s, &[1.5, 0.5], L2Kind::Mixture).unwrap_err(),
            Error::OutOfRange { value: 1.5, .. }
        ));
        assert!(l2_point_sums(&s, &[1.0, 0.0], L2Kind::WrapAround).is_ok());
    }

    #[test]
    fn single_points_have_hand_computed_values() {
        // One point at the centre, in d dimensions. L2-star: Π(1 − ¼) = (3/4)^d and
        // Π(1 − ½) = 2^−d, so T² = 3^−d − 2^{1−d}(3/4)^d + 2^−d. Centered: every |x − ½| is 0, so
        // CD² = (13/12)^d − 2 + 1. Wrap-around: |x − x| = 0, so WD² = (3/2)^d − (4/3)^d.
        let centre = [0.5; 8];
        for d in 1..=8usize {
            let s = set(&centre[..d], d);
            let di = d as i32;
            let t2 = 3f64.powi(-di) - 2f64.powi(1 - di) * 0.75f64.powi(di) + 0.5f64.powi(di);
            let c2 = (13.0f64 / 12.0).powi(di) - 1.0;
            let m2 = (19.0f64 / 12.0).powi(di) - 2.0 * (5.0f64 / 3.0).powi(di)
                + (15.0f64 / 8.0).powi(di);
            let m = mixture_l2_discrepancy(&s);
            assert!(
                (m - m2.sqrt()).abs() < 1e-14 * m2.sqrt().max(1.0),
                "d {d}: {m}"
            );
            let w2 = 1.5f64.powi(di) - (4.0f64 / 3.0).powi(di);
            assert!((l2_star_discrepancy(&s) - t2.sqrt()).abs() < 1e-14, "d {d}");
            assert!(
                (centered_l2_discrepancy(&s) - c2.sqrt()).abs() < 1e-14,
                "d {d}"
            );
            assert!(
                (wraparound_l2_discrepancy(&s) - w2.sqrt()).abs() < 1e-14,
                "d {d}"
            );
        }
        // Two points at opposite corners of the torus cell, 0 and ½ on every axis: the pair term
        // is (3/2 − ¼)^d = (5/4)^d, so WD² = ½(3/2)^d + ½(5/4)^d − (4/3)^d.
        for d in 1..=6usize {
            let mut pts = std::vec![0.0; d];
            pts.extend(core::iter::repeat_n(0.5, d));
            let di = d as i32;
            let w2 = 0.5 * 1.5f64.powi(di) + 0.5 * 1.25f64.powi(di) - (4.0f64 / 3.0).powi(di);
            let w = wraparound_l2_discrepancy(&set(&pts, d));
            assert!((w - w2.sqrt()).abs() < 1e-14, "d {d}: {w}");
        }
    }

    #[test]
    fn neumaier_recovers_what_plain_summation_loses() {
        // 1 + 10^100 + 1 − 10^100 is 2; plain f64 summation gives 0. The first two additions
        // take the branch for |x| > |sum|, the last two the one for |sum| ≥ |x|.
        for terms in [[1.0, 1e100, 1.0, -1e100], [1e100, 1.0, -1e100, 1.0]] {
            let mut s = Neumaier::default();
            for x in terms {
                s.add(x);
            }
            assert_eq!(s.sum(), 2.0, "{terms:?}");
        }
        let mut s = Neumaier::default();
        for x in [0.1; 10] {
            s.add(x);
        }
        // The sum of ten copies of fl(0.1), correctly rounded (plain summation: 0.9999999999999999).
        assert_eq!(s.sum(), 1.0);
    }

    proptest! {
        #[test]
        fn l2_measures_are_finite_and_nonnegative(
            dims in 1usize..5,
            raw in proptest::collection::vec(
                prop_oneof![Just(0.0f64), Just(1.0f64), 0.0f64..=1.0], 1..40),
        ) {
            let n = (raw.len() / dims).max(1);
            let mut pts = raw.clone();
            pts.resize(n * dims, 1.0);
            let s = set(&pts, dims);
            for v in [
                l2_star_discrepancy(&s),
                centered_l2_discrepancy(&s),
                wraparound_l2_discrepancy(&s),
                mixture_l2_discrepancy(&s),
            ] {
                prop_assert!(v.is_finite() && (0.0..=2.0).contains(&v));
            }
        }
    }
}
