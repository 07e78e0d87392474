//! Kronecker sequences `frac(s + k·α)`; Roberts' `R_d` picks `α_j = φ_d^{−(j+1)}`.

use super::{fixed_to_f32, fixed_to_f64, rotation};
use crate::Error;
use crate::sequence::Sequence;

/// The most dimensions a [`Kronecker`] sequence has.
pub const KRONECKER_MAX_DIMS: u32 = 1024;

/// Roberts' `R_d` sequence: point `k`, dimension `j < d`, is `frac(½ + k·α_j)` with
/// `α_j = φ_d^{−(j+1)}` and `φ_d` the positive root of `x^{d+1} = x + 1` (the golden ratio for
/// `d = 1`, the plastic number 1.3247… for `d = 2`, where it is `R2`). A Cranley–Patterson
/// rotation replaces the start `½` by a seeded shift per dimension.
///
/// `α_j` is held in 64-bit fixed point from its `f64` value (53 significant bits), and `k·α_j`
/// wraps exactly, so point `k` is exact for that `α` at every index.
///
/// Source: M. Roberts, "The unreasonable effectiveness of quasirandom sequences" (2018).
///
/// ```
/// use nyquist::lattice::Kronecker;
/// use nyquist::sequence::Sequence;
/// let r2 = Kronecker::new(2).unwrap();
/// assert_eq!(r2.sample(0, 0), 0.5);
/// let plastic = 1.324_717_957_244_746_f64;
/// assert!((r2.sample_f64(1, 0) - (0.5 + 1.0 / plastic).fract()).abs() < 1e-12);
/// assert!((r2.sample_f64(1, 1) - (0.5 + 1.0 / (plastic * plastic)).fract()).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kronecker {
    dims: u32,
    phi: f64,
    seed: Option<u64>,
    /// `α_j` in fixed point for the first [`CACHED`] dimensions.
    alphas: [u64; CACHED],
}

/// Dimensions whose `α_j` is computed at construction rather than per value.
const CACHED: usize = 8;

/// `φ^{−(dim+1)}` in 64-bit fixed point.
fn alpha_of(phi: f64, dim: u32) -> u64 {
    let a = crate::math::pow(phi, -f64::from(dim + 1));
    // a ∈ (0, 1): the product is below 2⁶⁴ and exact in f64's 53 bits.
    (a * 18_446_744_073_709_551_616.0) as u64
}

impl Kronecker {
    /// Roberts' `R_d` in `dims` dimensions.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `dims == 0`; [`Error::NotInRange`] above
    /// [`KRONECKER_MAX_DIMS`].
    ///
    /// ```
    /// use nyquist::{lattice::Kronecker, Error};
    /// assert!((Kronecker::new(1).unwrap().phi() - 1.618_033_988_749_895).abs() < 1e-15);
    /// assert_eq!(Kronecker::new(0), Err(Error::ZeroSize { what: "dims" }));
    /// ```
    pub fn new(dims: u32) -> Result<Kronecker, Error> {
        if dims == 0 {
            return Err(Error::ZeroSize { what: "dims" });
        }
        if dims > KRONECKER_MAX_DIMS {
            return Err(Error::NotInRange {
                what: "dims",
                value: u64::from(dims),
                min: 1,
                max: u64::from(KRONECKER_MAX_DIMS),
            });
        }
        // x ← (1 + x)^{1/(d+1)} contracts to the root (Roberts 2018); Newton then polishes it.
        let e = f64::from(dims + 1);
        let mut x = 2.0f64;
        for _ in 0..64 {
            x = crate::math::pow(1.0 + x, 1.0 / e);
        }
        for _ in 0..4 {
            let f = crate::math::pow(x, e) - x - 1.0;
            let df = e * crate::math::pow(x, e - 1.0) - 1.0;
            x -= f / df;
        }
        let mut alphas = [0u64; CACHED];
        for (j, a) in alphas.iter_mut().enumerate() {
            *a = alpha_of(x, j as u32);
        }
        Ok(Kronecker {
            dims,
            phi: x,
            seed: None,
            alphas,
        })
    }

    /// The same sequence with the start `½` replaced by a Cranley–Patterson shift drawn from
    /// `seed`.
    ///
    /// ```
    /// use nyquist::lattice::Kronecker;
    /// use nyquist::sequence::Sequence;
    /// assert_ne!(Kronecker::new(2).unwrap().rotated(1).sample(0, 0), 0.5);
    /// ```
    #[must_use]
    pub fn rotated(self, seed: u64) -> Kronecker {
        Kronecker {
            seed: Some(seed),
            ..self
        }
    }

    /// `φ_d`, the positive root of `x^{d+1} = x + 1`.
    pub fn phi(&self) -> f64 {
        self.phi
    }

    /// `α_j = φ_d^{−(j+1)}` in 64-bit fixed point.
    #[inline]
    fn alpha(&self, dim: u32) -> u64 {
        match self.alphas.get(dim as usize) {
            Some(&a) => a,
            None => alpha_of(self.phi, dim),
        }
    }

    #[inline]
    pub(crate) fn fixed(&self, index: u64, dim: u32) -> u64 {
        let dim = dim % self.dims;
        let start = self.seed.map_or(1 << 63, |s| rotation(s, dim));
        start.wrapping_add(index.wrapping_mul(self.alpha(dim)))
    }
}

impl Sequence for Kronecker {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        fixed_to_f32(self.fixed(index, dim))
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        fixed_to_f64(self.fixed(index, dim))
    }
}
