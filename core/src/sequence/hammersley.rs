//! The Hammersley point set and its folded (Zaremba) form.
//!
//! Point `k` of `N` is `((k + ½)/N, Φ₂(k), Φ₃(k), …)` (DESIGN.md; the seed's `((i − ½)/N, …)` with
//! 1-based `i`); the Zaremba form uses the folded radical inverse Ψ in place of Φ.

use super::Sequence;
use crate::Error;
use crate::math::{clamp_unit, clamp_unit_f64};
use crate::radical::{
    PRIME_COUNT, folded_radical_inverse, folded_radical_inverse_f64, radical_inverse,
    radical_inverse_f64, ratio_f32, ratio_f64,
};

/// Validates `(n, dims)` for the Hammersley sets: `n ≥ 1`, `1 ≤ dims ≤ 1025`.
fn check(n: u64, dims: u32) -> Result<(), Error> {
    if n == 0 {
        return Err(Error::ZeroSize { what: "points" });
    }
    if dims == 0 {
        return Err(Error::ZeroSize { what: "dims" });
    }
    if dims > PRIME_COUNT + 1 {
        return Err(Error::DimensionOutOfRange {
            dim: dims - 1,
            dims: PRIME_COUNT + 1,
        });
    }
    Ok(())
}

/// `(k + ½)/n` for `k < n`, correctly rounded, in `[0, 1)`.
fn first_f64(k: u64, n: u64) -> f64 {
    clamp_unit_f64(ratio_f64(2 * u128::from(k) + 1, 2 * u128::from(n)))
}

/// `(k + ½)/n` for `k < n`, correctly rounded to `f32`, in `[0, 1)`.
fn first_f32(k: u64, n: u64) -> f32 {
    clamp_unit(ratio_f32(2 * u128::from(k) + 1, 2 * u128::from(n)))
}

macro_rules! hammersley {
    ($(#[$doc:meta])* $name:ident, $phi:ident, $phi64:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub struct $name {
            n: u64,
            dims: u32,
        }

        impl $name {
            /// The set of `n` points in `dims` dimensions (dimension 0 is `(k + ½)/n`, dimension
            /// `d ≥ 1` uses the `(d−1)`-th prime).
            ///
            /// # Errors
            /// [`Error::ZeroSize`] if `n` or `dims` is 0; [`Error::DimensionOutOfRange`] if
            /// `dims > 1025`.
            pub fn new(n: u64, dims: u32) -> Result<Self, Error> {
                check(n, dims)?;
                Ok(Self { n, dims })
            }
        }

        impl Sequence for $name {
            fn dims(&self) -> u32 {
                self.dims
            }

            fn point_count(&self) -> Option<u64> {
                Some(self.n)
            }

            fn sample(&self, index: u64, dim: u32) -> f32 {
                let k = index % self.n;
                match dim % self.dims {
                    0 => first_f32(k, self.n),
                    d => $phi(d - 1, k),
                }
            }

            fn sample_f64(&self, index: u64, dim: u32) -> f64 {
                let k = index % self.n;
                match dim % self.dims {
                    0 => first_f64(k, self.n),
                    d => $phi64(d - 1, k),
                }
            }
        }
    };
}

hammersley!(
    /// The Hammersley set of `N` points: point `k` is `((k + ½)/N, Φ₂(k), Φ₃(k), …)`.
    ///
    /// Index `≥ N` wraps modulo `N`; `dim ≥ dims()` wraps modulo `dims()`.
    ///
    /// ```
    /// use nyquist::sequence::{Hammersley, Sequence};
    /// let h = Hammersley::new(4, 2).unwrap();
    /// let pts: Vec<[f32; 2]> = (0..4).map(|k| [h.sample(k, 0), h.sample(k, 1)]).collect();
    /// assert_eq!(pts, [[0.125, 0.0], [0.375, 0.5], [0.625, 0.25], [0.875, 0.75]]);
    /// assert!(Hammersley::new(0, 2).is_err());
    /// ```
    Hammersley,
    radical_inverse,
    radical_inverse_f64
);

hammersley!(
    /// The Hammersley–Zaremba set of `N` points: `((k + ½)/N, Ψ₂(k), Ψ₃(k), …)` with the folded
    /// radical inverse Ψ.
    ///
    /// ```
    /// use nyquist::sequence::{HammersleyZaremba, Sequence};
    /// let h = HammersleyZaremba::new(8, 2).unwrap();
    /// // Ψ₂(0) = 1/3.
    /// assert!((h.sample_f64(0, 1) - 1.0 / 3.0).abs() < 1e-15);
    /// assert_eq!(h.sample(8, 0), h.sample(0, 0)); // wraps modulo N
    /// ```
    HammersleyZaremba,
    folded_radical_inverse,
    folded_radical_inverse_f64
);

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// Exact star discrepancy of a 2D set by brute force over critical boxes: for every pair of
    /// critical coordinates (point coordinates and 1), both open and closed counts.
    fn star_discrepancy_brute(pts: &[(f64, f64)]) -> f64 {
        let n = pts.len() as f64;
        let mut xs: Vec<f64> = pts.iter().map(|p| p.0).chain([1.0]).collect();
        let mut ys: Vec<f64> = pts.iter().map(|p| p.1).chain([1.0]).collect();
        xs.sort_by(f64::total_cmp);
        ys.sort_by(f64::total_cmp);
        let mut d: f64 = 0.0;
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
    fn hammersley_star_discrepancy_matches_de_clercks_formula() {
        // De Clerck (1986): for the points (i/N, Φ₂(i)), N = 2^m,
        // N·D* = m/3 + 13/9 − (−1)^m·4/(9N).
        for m in 2..=8u32 {
            let n = 1u64 << m;
            let pts: Vec<(f64, f64)> = (0..n)
                .map(|i| (i as f64 / n as f64, radical_inverse_f64(0, i)))
                .collect();
            let nd = n as f64 * star_discrepancy_brute(&pts);
            let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
            let want = f64::from(m) / 3.0 + 13.0 / 9.0 - sign * 4.0 / (9.0 * n as f64);
            assert!((nd - want).abs() < 1e-9, "m={m}: {nd} vs {want}");
        }
    }

    #[test]
    fn dimensions_past_the_first_are_the_radical_inverses() {
        let h = Hammersley::new(1000, 5).unwrap();
        let z = HammersleyZaremba::new(1000, 5).unwrap();
        for k in [0u64, 1, 2, 99, 999] {
            for d in 1..5 {
                assert_eq!(h.sample(k, d), radical_inverse(d - 1, k));
                assert_eq!(z.sample(k, d), folded_radical_inverse(d - 1, k));
            }
            assert_eq!(h.sample_f64(k, 0), (k as f64 + 0.5) / 1000.0);
        }
    }

    #[test]
    fn bad_sizes_are_errors() {
        assert_eq!(
            Hammersley::new(0, 1),
            Err(Error::ZeroSize { what: "points" })
        );
        assert_eq!(Hammersley::new(5, 0), Err(Error::ZeroSize { what: "dims" }));
        assert!(Hammersley::new(5, 1025).is_ok());
        assert!(HammersleyZaremba::new(5, 1026).is_err());
        let h = Hammersley::new(u64::MAX, 2).unwrap();
        assert!(h.sample(u64::MAX - 1, 0) < 1.0);
    }
}
