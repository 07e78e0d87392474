//! The t-value of a point set as a digital net in base 2.
//!
//! A set of `2^m` points in `[0, 1)^d` is a (t, m, d)-net in base 2 when every elementary box
//! `Π_j [a_j / 2^k_j, (a_j + 1) / 2^k_j)` with `k_1 + … + k_d = m − t` holds exactly `2^t`
//! points (Niederreiter, *Random Number Generation and Quasi-Monte Carlo Methods*, 1992,
//! Def. 4.1). A (t, m, d)-net is also a (t + 1, m, d)-net, so the t-value, the smallest such `t`,
//! says how well the set is stratified: 0 is the best, `m` holds for any set.

use super::PointSet;
use crate::Error;
use crate::error::Interval;

/// The scratch length [`net_t_value`] needs: one count per point plus one part per dimension.
///
/// ```
/// use nyquist::analysis::net_t_value_scratch_len;
/// assert_eq!(net_t_value_scratch_len(16, 2), Some(18));
/// ```
pub fn net_t_value_scratch_len(points: usize, dims: usize) -> Option<usize> {
    points.checked_add(dims)
}

/// The t-value of `points` as a net in base 2 (module docs): the smallest `t` for which every
/// elementary box of volume `2^(t − m)` holds exactly `2^t` of the `2^m` points.
///
/// Each candidate `t` counts the points of every box shape `(k_1, …, k_d)` with
/// `Σ k_j = m − t`, from `t = 0` up, and stops a shape at its first box with more than `2^t`
/// points. A set with t-value `t*` costs about `N · C(m − t* + d − 1, d − 1)` box lookups at the
/// level that passes, plus the failures below it: milliseconds for `2^16` points in 2 to 4
/// dimensions, but `C(m + d − 1, d − 1)` grows fast with `d`. Allocates: no.
///
/// # Errors
/// [`Error::Invalid`] (`what: "points"`) unless the count is a power of two;
/// [`Error::OutOfRange`] (`what: "point coordinate"`) for a coordinate equal to 1 (a net lives in
/// `[0, 1)^d`); [`Error::BufferTooShort`] when `scratch` is shorter than
/// [`net_t_value_scratch_len`].
///
/// ```
/// use nyquist::analysis::{net_t_value, PointSet};
/// // The 2-D Hammersley set of 4 points is a (0, 2, 2)-net.
/// let pts = [0.0, 0.0, 0.25, 0.5, 0.5, 0.25, 0.75, 0.75];
/// let mut scratch = [0u32; 6];
/// assert_eq!(net_t_value(&PointSet::new(&pts, 2).unwrap(), &mut scratch), Ok(0));
/// // Four points on the diagonal: the boxes [0, ½)² and [½, 1)² hold two each, so t = 1.
/// let diag = [0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75];
/// assert_eq!(net_t_value(&PointSet::new(&diag, 2).unwrap(), &mut scratch), Ok(1));
/// ```
pub fn net_t_value(points: &PointSet<'_>, scratch: &mut [u32]) -> Result<u32, Error> {
    let n = points.len();
    let d = points.dims();
    if !n.is_power_of_two() {
        return Err(Error::Invalid {
            what: "points",
            value: n as u64,
            rule: "is not a power of",
            other: 2,
        });
    }
    if let Some(&x) = points.coords().iter().find(|&&x| x >= 1.0) {
        return Err(Error::OutOfRange {
            what: "point coordinate",
            value: x,
            range: Interval {
                min: 0.0,
                max: 1.0,
                min_open: false,
                max_open: true,
            },
        });
    }
    let needed = n + d;
    if scratch.len() < needed {
        return Err(Error::BufferTooShort {
            needed,
            actual: scratch.len(),
        });
    }
    let m = n.trailing_zeros();
    let (parts, counts) = scratch.split_at_mut(d);
    for t in 0..m {
        if every_box_holds(points, m - t, 1 << t, parts, counts) {
            return Ok(t);
        }
    }
    Ok(m)
}

/// Whether, for every shape `k` with `Σ k_j = s`, every box of that shape holds at most `cap`
/// points (with `2^s · cap` points, at most means exactly). `parts` holds the shape, `counts`
/// one count per box.
fn every_box_holds(
    points: &PointSet<'_>,
    s: u32,
    cap: u32,
    parts: &mut [u32],
    counts: &mut [u32],
) -> bool {
    let d = parts.len();
    parts.fill(0);
    parts[0] = s;
    let counts = &mut counts[..1 << s];
    loop {
        if !shape_holds(points, parts, cap, counts) {
            return false;
        }
        // The next composition of s into d parts (Nijenhuis and Wilf's NEXCOM): move one unit
        // from the last non-zero part before the end to its right neighbour, which also takes
        // whatever the last part held.
        let Some(i) = parts[..d - 1].iter().rposition(|&k| k > 0) else {
            return true;
        };
        let last = core::mem::take(&mut parts[d - 1]);
        parts[i] -= 1;
        parts[i + 1] = last + 1;
    }
}

/// Whether every box of shape `parts` holds at most `cap` points.
fn shape_holds(points: &PointSet<'_>, parts: &[u32], cap: u32, counts: &mut [u32]) -> bool {
    counts.fill(0);
    for p in points.coords().chunks_exact(parts.len()) {
        let mut cell = 0usize;
        for (&x, &k) in p.iter().zip(parts) {
            // The top k of the 32 leading bits of x: ⌊x·2^k⌋ for x in [0, 1), k ≤ 31.
            let bits = (x * 4_294_967_296.0) as u64;
            cell = (cell << k) | (bits >> (32 - k)) as usize;
        }
        counts[cell] += 1;
        if counts[cell] > cap {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::testsets::{hammersley, random};
    use crate::sequence::{Halton, Sequence, Sobol};
    use std::string::ToString;
    use std::vec;
    use std::vec::Vec;

    fn t_value(pts: &[f64], d: usize) -> Result<u32, Error> {
        let set = PointSet::new(pts, d)?;
        let mut scratch = vec![0; net_t_value_scratch_len(set.len(), d).unwrap()];
        net_t_value(&set, &mut scratch)
    }

    /// The t-value by brute force: every shape and every box listed and counted directly.
    fn brute_force(pts: &[f64], d: usize) -> u32 {
        let n = pts.len() / d;
        let m = n.trailing_zeros();
        'levels: for t in 0..=m {
            let s = m - t;
            // Every shape as d digits in base s + 1, keeping those that sum to s.
            for code in 0..(s as usize + 1).pow(d as u32) {
                let k: Vec<u32> = (0..d)
                    .map(|j| (code / (s as usize + 1).pow(j as u32) % (s as usize + 1)) as u32)
                    .collect();
                if k.iter().sum::<u32>() != s {
                    continue;
                }
                let mut boxes = std::collections::HashMap::new();
                for p in pts.chunks_exact(d) {
                    let key: Vec<u64> = p
                        .iter()
                        .zip(&k)
                        .map(|(&x, &kj)| (x * f64::from(1u32 << kj)).floor() as u64)
                        .collect();
                    *boxes.entry(key).or_insert(0u32) += 1;
                }
                if boxes.len() != 1 << s || boxes.values().any(|&c| c != 1 << t) {
                    continue 'levels;
                }
            }
            return t;
        }
        unreachable!()
    }

    #[test]
    fn sobol_prefixes_have_their_published_t_values() {
        // Sobol's first two dimensions are a (0, 2)-sequence, so every power-of-two prefix is a
        // (0, m, 2)-net; the first three (Joe–Kuo) give t = 1 for m ≥ 2 (two points are always a (0, 1, d)-net).
        let sobol = Sobol::new(3).unwrap();
        for m in 0..=12u32 {
            let n = 1u64 << m;
            let pts2: Vec<f64> = (0..n)
                .flat_map(|i| [sobol.sample_f64(i, 0), sobol.sample_f64(i, 1)])
                .collect();
            assert_eq!(t_value(&pts2, 2), Ok(0), "m {m}");
            let pts3: Vec<f64> = (0..n)
                .flat_map(|i| (0..3).map(move |j| sobol.sample_f64(i, j)))
                .collect();
            assert_eq!(t_value(&pts3, 3), Ok(u32::from(m >= 2)), "m {m}");
        }
    }

    #[test]
    fn agrees_with_brute_force_on_varied_sets() {
        let halton = Halton::new(3).unwrap();
        for d in 1..=3usize {
            for m in 0..=6u32 {
                let n = 1usize << m;
                // Hammersley's 2-D set, cut to d axes (a constant third axis when d = 3),
                // random points and Halton's.
                let sets = [
                    hammersley(n as u32)
                        .chunks_exact(2)
                        .flat_map(|p| [p[0], p[1], 0.3].into_iter().take(d))
                        .collect::<Vec<f64>>(),
                    random(n, d, (d * 10 + m as usize) as u64)
                        .iter()
                        .map(|&x| x.min(0.999))
                        .collect(),
                    (0..n as u64)
                        .flat_map(|i| (0..d as u32).map(move |j| halton.sample_f64(i, j)))
                        .collect(),
                ];
                for pts in &sets {
                    assert_eq!(t_value(pts, d).unwrap(), brute_force(pts, d), "d {d} m {m}");
                }
            }
        }
    }

    #[test]
    fn a_single_point_and_a_repeated_point() {
        assert_eq!(t_value(&[0.7, 0.2], 2), Ok(0));
        // Eight copies of one point: only the whole cube is balanced.
        assert_eq!(t_value(&[0.3; 8], 1), Ok(3));
    }

    #[test]
    fn refuses_bad_sets_and_short_scratch() {
        assert_eq!(
            t_value(&[0.1, 0.2, 0.3], 1),
            Err(Error::Invalid {
                what: "points",
                value: 3,
                rule: "is not a power of",
                other: 2
            })
        );
        let e = t_value(&[0.1, 1.0], 1).unwrap_err();
        assert!(matches!(
            e,
            Error::OutOfRange {
                what: "point coordinate",
                value: 1.0,
                ..
            }
        ));
        assert_eq!(e.to_string(), "point coordinate 1 is outside [0, 1)");
        let set = PointSet::new(&[0.1, 0.6], 1).unwrap();
        assert_eq!(
            net_t_value(&set, &mut [0; 2]),
            Err(Error::BufferTooShort {
                needed: 3,
                actual: 2
            })
        );
        assert_eq!(net_t_value(&set, &mut [0; 3]), Ok(0));
        assert_eq!(net_t_value_scratch_len(usize::MAX, 1), None);
    }
}
