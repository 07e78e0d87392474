//! The Hammersley point set and its folded (Hammersley–Zaremba) variant: `N` points, point `k`
//! is `((k + ½)/N, Φ₂(k), Φ₃(k), …)` (Ψ in place of Φ for the Zaremba form).
//!
//! Sources: Hammersley (1960); the first coordinate is centred, `(i − ½)/N` for 1-based `i`,
//! which is `(k + ½)/N` for 0-based `k`: the `N`-point set of least star discrepancy in one
//! dimension, `1/(2N)` (Niederreiter 1992, ch. 2); De Clerck (1986) for the exact star
//! discrepancy used in the tests.

use super::Sequence;
use crate::Error;
use crate::radical::{
    PRIME_COUNT, folded_radical_inverse, folded_radical_inverse_f64, radical_inverse,
    radical_inverse_f64, ratio_f32, ratio_f64,
};

/// Validates `(n, dims)` for the Hammersley sets.
fn check(n: u64, dims: u32) -> Result<(), Error> {
    if n == 0 {
        return Err(Error::ZeroSize { what: "n" });
    }
    if dims == 0 {
        return Err(Error::ZeroSize { what: "dims" });
    }
    if dims > PRIME_COUNT + 1 {
        return Err(Error::NotInRange {
            what: "dims",
            value: dims as u64,
            min: 1,
            max: PRIME_COUNT as u64 + 1,
        });
    }
    Ok(())
}

/// `(k + ½)/n` for `k < n`, within 1 ulp (`f64`: correctly rounded).
#[inline]
fn centre_f32(k: u64, n: u64) -> f32 {
    // (k + ½)/n < 1, but for n ≥ 2²⁴ the last points round to 1 in f32: clamp below it.
    let x = if n < 1 << 52 {
        // Exact operands, one correctly rounded division, one narrowing.
        ((k as f64 + 0.5) / n as f64) as f32
    } else {
        ratio_f32(u128::from(k) * 2 + 1, u128::from(n) * 2)
    };
    x.min(crate::math::ONE_MINUS_EPSILON)
}

#[inline]
fn centre_f64(k: u64, n: u64) -> f64 {
    let x = if n < 1 << 52 {
        (k as f64 + 0.5) / n as f64
    } else {
        ratio_f64(u128::from(k) * 2 + 1, u128::from(n) * 2)
    };
    x.min(crate::math::ONE_MINUS_EPSILON_F64)
}

/// The Hammersley set of `n` points: point `k` is `((k + ½)/n, Φ₂(k), Φ₃(k), …)`, up to 1025
/// dimensions (dimension 0 is the centred fraction, dimensions `1 ..= 1024` the radical inverses
/// of the first 1024 primes). Indices wrap modulo `n`.
///
/// ```
/// use nyquist::sequence::{Hammersley, Sequence};
/// let h = Hammersley::new(4, 2).unwrap();
/// let pts: Vec<(f32, f32)> = (0..4).map(|k| (h.sample(k, 0), h.sample(k, 1))).collect();
/// assert_eq!(pts, [(0.125, 0.0), (0.375, 0.5), (0.625, 0.25), (0.875, 0.75)]);
/// assert_eq!(h.point_count(), Some(4));
/// assert_eq!(h.sample(5, 0), h.sample(1, 0)); // index wraps modulo n
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hammersley {
    n: u64,
    dims: u32,
}

impl Hammersley {
    /// A Hammersley set of `n` points in `dims` dimensions.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `n == 0` (`what: "n"`) or `dims == 0`; [`Error::NotInRange`]
    /// (`what: "dims"`) if `dims > 1025`.
    ///
    /// ```
    /// use nyquist::{sequence::Hammersley, Error};
    /// assert!(Hammersley::new(16, 1025).is_ok());
    /// assert_eq!(Hammersley::new(0, 2), Err(Error::ZeroSize { what: "n" }));
    /// assert_eq!(
    ///     Hammersley::new(16, 1026).unwrap_err().to_string(),
    ///     "dims 1026 is outside 1..=1025"
    /// );
    /// ```
    pub fn new(n: u64, dims: u32) -> Result<Hammersley, Error> {
        check(n, dims)?;
        Ok(Hammersley { n, dims })
    }
}

impl Sequence for Hammersley {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        Some(self.n)
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        let k = index % self.n;
        match dim % self.dims {
            0 => centre_f32(k, self.n),
            d => radical_inverse(d - 1, k),
        }
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        let k = index % self.n;
        match dim % self.dims {
            0 => centre_f64(k, self.n),
            d => radical_inverse_f64(d - 1, k),
        }
    }
}

/// The Hammersley–Zaremba set: point `k` of `n` is `((k + ½)/n, Ψ₂(k), Ψ₃(k), …)` with the folded
/// radical inverse Ψ. Same dimensions and wrapping as [`Hammersley`].
///
/// ```
/// use nyquist::sequence::{HammersleyZaremba, Sequence};
/// let h = HammersleyZaremba::new(8, 2).unwrap();
/// assert_eq!(h.sample(0, 0), 0.0625);
/// assert_eq!(h.sample(0, 1), 1.0 / 3.0); // Ψ₂(0)
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HammersleyZaremba {
    n: u64,
    dims: u32,
}

impl HammersleyZaremba {
    /// A Hammersley–Zaremba set of `n` points in `dims` dimensions.
    ///
    /// # Errors
    /// As [`Hammersley::new`].
    ///
    /// ```
    /// assert!(nyquist::sequence::HammersleyZaremba::new(0, 2).is_err());
    /// ```
    pub fn new(n: u64, dims: u32) -> Result<HammersleyZaremba, Error> {
        check(n, dims)?;
        Ok(HammersleyZaremba { n, dims })
    }
}

impl Sequence for HammersleyZaremba {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        Some(self.n)
    }

    fn sample(&self, index: u64, dim: u32) -> f32 {
        let k = index % self.n;
        match dim % self.dims {
            0 => centre_f32(k, self.n),
            d => folded_radical_inverse(d - 1, k),
        }
    }

    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        let k = index % self.n;
        match dim % self.dims {
            0 => centre_f64(k, self.n),
            d => folded_radical_inverse_f64(d - 1, k),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::vec::Vec;

    /// Star discrepancy by brute force over the critical boxes `[0, x) × [0, y)`, with `x`, `y`
    /// running over the points' coordinates and 1, counting both open and closed boxes.
    fn star_discrepancy(pts: &[(f64, f64)]) -> f64 {
        let n = pts.len() as f64;
        let mut xs: Vec<f64> = pts.iter().map(|p| p.0).chain([1.0]).collect();
        let mut ys: Vec<f64> = pts.iter().map(|p| p.1).chain([1.0]).collect();
        xs.sort_by(f64::total_cmp);
        ys.sort_by(f64::total_cmp);
        let mut d = 0.0f64;
        for &x in &xs {
            for &y in &ys {
                let open = pts.iter().filter(|p| p.0 < x && p.1 < y).count() as f64;
                let closed = pts.iter().filter(|p| p.0 <= x && p.1 <= y).count() as f64;
                d = d.max(x * y - open / n).max(closed / n - x * y);
            }
        }
        d
    }

    #[test]
    fn de_clerck_star_discrepancy_of_the_two_dimensional_hammersley_set() {
        // N·D* = m/3 + 13/9 − (−1)^m·4/(9N) for the points (i/N, Φ₂(i)), N = 2^m (De Clerck 1986).
        for m in 2..=8u32 {
            let n = 1u64 << m;
            let pts: Vec<(f64, f64)> = (0..n)
                .map(|i| (i as f64 / n as f64, radical_inverse_f64(0, i)))
                .collect();
            let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
            let expect = f64::from(m) / 3.0 + 13.0 / 9.0 - sign * 4.0 / (9.0 * n as f64);
            let got = star_discrepancy(&pts) * n as f64;
            assert!(
                (got - expect).abs() < 1e-9,
                "m={m}: N·D* = {got}, want {expect}"
            );
        }
    }

    #[test]
    fn star_discrepancy_oracle_sanity() {
        // One point at the origin: the box [0,1)² misses nothing, the closed box at (0,0)
        // holds it, and the open box [0,1)×[0,1) has count 1 vs area 1 — D* = 1.
        assert!((star_discrepancy(&[(0.0, 0.0)]) - 1.0).abs() < 1e-12);
        assert!((star_discrepancy(&[(0.5, 0.5)]) - 0.75).abs() < 1e-12);
    }

    #[test]
    fn hammersley_points_match_the_definition() {
        let h = Hammersley::new(100, 1025).unwrap();
        for k in [0u64, 1, 37, 99] {
            assert_eq!(h.sample_f64(k, 0), (k as f64 + 0.5) / 100.0);
            assert_eq!(h.sample(k, 0), ((k as f64 + 0.5) / 100.0) as f32);
            for d in [1u32, 2, 3, 500, 1024] {
                assert_eq!(h.sample(k, d), radical_inverse(d - 1, k));
                assert_eq!(h.sample_f64(k + 100, d), radical_inverse_f64(d - 1, k));
            }
        }
        let z = HammersleyZaremba::new(100, 3).unwrap();
        assert_eq!(z.sample(7, 2), folded_radical_inverse(1, 7));
        assert_eq!(z.sample_f64(107, 1), folded_radical_inverse_f64(0, 7));
        // Huge n takes the exact long-division path for the first coordinate.
        let big = Hammersley::new(u64::MAX, 1).unwrap();
        assert_eq!(big.sample_f64(u64::MAX - 1, 0), ONE_BELOW);
        assert!(big.sample(u64::MAX - 1, 0) < 1.0);
        assert_eq!(big.sample_f64(0, 0), 0.5 / u64::MAX as f64);
    }

    /// (2⁶⁴ − 1.5)/(2⁶⁴ − 1) rounds to 1 − 2⁻⁵³·… : the f64 just below 1.
    const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;

    #[test]
    fn constructors_validate() {
        assert_eq!(Hammersley::new(0, 1), Err(Error::ZeroSize { what: "n" }));
        assert_eq!(Hammersley::new(1, 0), Err(Error::ZeroSize { what: "dims" }));
        assert!(HammersleyZaremba::new(1, 1026).is_err());
        assert_eq!(Hammersley::new(1, 1).unwrap().sample(0, 0), 0.5);
    }

    /// Found by the fuzzer: with n ≥ 2²⁴ the last centres rounded to 1.0 in f32.
    #[test]
    fn centres_stay_below_one_for_huge_n() {
        for n in [1u64 << 24, (1 << 24) + 1, 1 << 40, u64::MAX] {
            let h = Hammersley::new(n, 2).unwrap();
            let z = HammersleyZaremba::new(n, 2).unwrap();
            for k in [n - 1, n - 2, n / 2] {
                assert!(h.sample(k, 0) < 1.0 && z.sample(k, 0) < 1.0, "n={n} k={k}");
                assert!(h.sample_f64(k, 0) < 1.0, "n={n} k={k}");
            }
        }
    }

    #[test]
    fn fill_equals_repeated_sample_and_respects_n() {
        let h = Hammersley::new(64, 4).unwrap();
        let z = HammersleyZaremba::new(64, 4).unwrap();
        for set in [&h as &dyn Sequence, &z] {
            let mut buf = [0.0f32; 64 * 4];
            assert_eq!(set.fill(0, 4, &mut buf), Ok(64));
            for (k, p) in buf.chunks_exact(4).enumerate() {
                for (d, &x) in p.iter().enumerate() {
                    assert_eq!(x, set.sample(k as u64, d as u32));
                }
            }
            assert!(set.fill(1, 4, &mut buf).is_err()); // would pass n
        }
        // The first coordinate hits every one of the n cells once.
        let mut seen = [false; 64];
        for k in 0..64 {
            seen[(h.sample(k, 0) * 64.0) as usize] = true;
        }
        assert!(seen.iter().all(|&s| s));
    }

    proptest! {
        #[test]
        fn values_are_in_unit_interval(n in 1u64.., index in any::<u64>(), dim in any::<u32>()) {
            let h = Hammersley::new(n, 1025).unwrap();
            let z = HammersleyZaremba::new(n, 1025).unwrap();
            for x in [h.sample(index, dim), z.sample(index, dim)] {
                prop_assert!((0.0..1.0).contains(&x));
            }
            for x in [h.sample_f64(index, dim), z.sample_f64(index, dim)] {
                prop_assert!((0.0..1.0).contains(&x));
            }
        }
    }
}
