//! L2 discrepancies by their closed forms, O(d·N²) time, no scratch.
//!
//! - L2-star (Warnock 1972):
//!   `T² = 3^−d − (2^{1−d}/N) Σ_i Π_k (1 − x_ik²) + (1/N²) Σ_i Σ_j Π_k (1 − max(x_ik, x_jk))`.
//! - Centered L2 (Hickernell 1998, eq. 5.1c):
//!   `CD² = (13/12)^d − (2/N) Σ_i Π_k (1 + ½|x_ik − ½| − ½|x_ik − ½|²)
//!   + (1/N²) Σ_i Σ_j Π_k (1 + ½|x_ik − ½| + ½|x_jk − ½| − ½|x_ik − x_jk|)`.
//! - Wrap-around L2 (Hickernell 1998, eq. 5.1d):
//!   `WD² = −(4/3)^d + (1/N²) Σ_i Σ_j Π_k (3/2 − |x_ik − x_jk| (1 − |x_ik − x_jk|))`.
//!
//! The double sums use the symmetry of the kernel (diagonal once, each pair twice). The result is
//! the square root of the formula, clamped at 0 against rounding.

use super::PointSet;
use crate::math::{pow, sqrt};

/// `Σ_i Σ_j K(x_i, x_j)` for a symmetric kernel, summed row by row.
#[inline]
fn double_sum(points: &PointSet<'_>, kernel: impl Fn(&[f64], &[f64]) -> f64) -> f64 {
    let d = points.dims();
    let c = points.coords();
    let mut total = 0.0;
    for (i, p) in c.chunks_exact(d).enumerate() {
        let mut row = 0.0;
        for q in c[(i + 1) * d..].chunks_exact(d) {
            row += kernel(p, q);
        }
        total += 2.0 * row + kernel(p, p);
    }
    total
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
    let d = points.dims() as f64;
    let n = points.len() as f64;
    let single: f64 = points
        .coords()
        .chunks_exact(points.dims())
        .map(|p| p.iter().map(|&x| 1.0 - x * x).product::<f64>())
        .sum();
    let pairs = double_sum(points, |p, q| {
        p.iter().zip(q).map(|(&a, &b)| 1.0 - a.max(b)).product()
    });
    let t2 = pow(3.0, -d) - pow(2.0, 1.0 - d) / n * single + pairs / (n * n);
    sqrt(t2.max(0.0))
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
    let d = points.dims() as f64;
    let n = points.len() as f64;
    let single: f64 = points
        .coords()
        .chunks_exact(points.dims())
        .map(|p| {
            p.iter()
                .map(|&x| {
                    let a = (x - 0.5).abs();
                    1.0 + 0.5 * a - 0.5 * a * a
                })
                .product::<f64>()
        })
        .sum();
    let pairs = double_sum(points, |p, q| {
        p.iter()
            .zip(q)
            .map(|(&a, &b)| {
                1.0 + 0.5 * (a - 0.5).abs() + 0.5 * (b - 0.5).abs() - 0.5 * (a - b).abs()
            })
            .product()
    });
    let c2 = pow(13.0 / 12.0, d) - 2.0 / n * single + pairs / (n * n);
    sqrt(c2.max(0.0))
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
    let d = points.dims() as f64;
    let n = points.len() as f64;
    let pairs = double_sum(points, |p, q| {
        p.iter()
            .zip(q)
            .map(|(&a, &b)| {
                let t = (a - b).abs();
                1.5 - t * (1.0 - t)
            })
            .product()
    });
    let w2 = -pow(4.0 / 3.0, d) + pairs / (n * n);
    sqrt(w2.max(0.0))
}
