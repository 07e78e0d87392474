//! Deterministic point sets in `[0, 1)^d`, addressed by index.
//!
//! Every set implements [`Sequence`]: `sample(index, dim)` depends only on its arguments and the
//! set's construction parameters, so tiles on different threads can share one instance and replay
//! the same bits in any order. [`Sequence::fill`] writes many points into a caller slice.
//!
//! | type | point `i`, dimension `d` |
//! |---|---|
//! | [`VanDerCorput`] | Φ₂(i) |
//! | [`Halton`] | Φ_{p_d}(i), `p_d` the d-th prime |
//! | [`HaltonZaremba`] | Ψ_{p_d}(i), the folded radical inverse |
//! | [`ScrambledHalton`] | Φ with a seeded digit permutation per base |
//! | [`Hammersley`] | `((i + ½)/N, Φ₂(i), Φ₃(i), …)` |
//! | [`HammersleyZaremba`] | `((i + ½)/N, Ψ₂(i), Ψ₃(i), …)` |
//! | [`Sobol`] | Joe–Kuo Sobol, natural order, 1024 dimensions |
//! | [`OwenSobol`] | Sobol with Burley's index shuffle and a fast Owen scramble per dimension |
//! | [`ZeroTwo`] | pbrt's (0,2)-sequence: van der Corput and Sobol's second dimension, XOR-scrambled |
//! | [`Pmj02`] | progressive multi-jittered (0,2) points, a baked table, optionally Owen-scrambled |

use crate::Error;

mod halton;
mod hammersley;
mod named;
mod owen_sobol;
pub(crate) mod pmj02;
mod sobol;
#[cfg(any(feature = "lazy-tables", test))]
mod sobol_lazy;
mod sobol_table;
mod zero_two;

pub use halton::{Halton, HaltonZaremba, ScrambledHalton, VanDerCorput};
pub use hammersley::{Hammersley, HammersleyZaremba};
pub use named::{
    NamedSequence, NamedSequenceError, SEQUENCE_NAMES, SequenceSpec, canonical_sequence_name,
    randomization, takes_points,
};
pub use owen_sobol::OwenSobol;
pub(crate) use owen_sobol::{
    DimSeeds, IndexShuffle, dim_seed, owen_sobol_rev_f32, owen_sobol_u64, padded_u32, padded_u32_by,
};
pub use pmj02::{PMJ02_MAX_POINTS, PMJ02_TABLE, PMJ02_TABLE_SEED, Pmj02, pmj02_build};

pub use sobol::{SOBOL_DIMS, Sobol, sobol_u32, sobol_u64};
pub(crate) use sobol::{product as sobol_product, sobol_run_f32};
// The generator matrices: stored, or with `lazy-tables` built at first use (the tests compile
// both and compare them).
#[cfg(all(feature = "lazy-tables", not(test)))]
pub(crate) use sobol_lazy::{
    SOBOL_MATRICES, SOBOL_MATRICES_HI, matrix_rows as sobol_matrix_rows,
    matrix_rows_hi as sobol_matrix_rows_hi,
};
#[cfg(any(not(feature = "lazy-tables"), test))]
pub(crate) use sobol_table::{SOBOL_MATRICES, SOBOL_MATRICES_HI};
pub use zero_two::ZeroTwo;

/// `dims` if it is in `1 ..= max`: else [`Error::ZeroSize`] for 0 and [`Error::NotInRange`]
/// (`what: "dims"`) above `max`.
pub(crate) fn dims_within(dims: u32, max: u32) -> Result<u32, Error> {
    match dims {
        0 => Err(Error::ZeroSize { what: "dims" }),
        d if d > max => Err(Error::NotInRange {
            what: "dims",
            value: u64::from(d),
            min: 1,
            max: u64::from(max),
        }),
        d => Ok(d),
    }
}

/// A deterministic point set in `[0, 1)^d`, addressed by index.
///
/// Contract for every implementation:
/// - values are in `[0, 1)` and never NaN;
/// - `sample(i, d)` depends only on `i`, `d` and the construction parameters;
/// - `dim >= dims()` wraps: it is read as `dim % dims()`;
/// - where the set has a finite number of points ([`Sequence::point_count`] is `Some(n)`),
///   `index >= n` wraps to `index % n`.
///
/// ```
/// use nyquist::sequence::{Sequence, VanDerCorput};
/// let vdc = VanDerCorput;
/// let firsts: Vec<f32> = (0..4).map(|i| vdc.sample(i, 0)).collect();
/// assert_eq!(firsts, [0.0, 0.5, 0.25, 0.75]);
/// ```
pub trait Sequence {
    /// Number of dimensions, at least 1.
    fn dims(&self) -> u32;

    /// Number of distinct points: `Some(n)` for finite sets (Hammersley's `N`, Sobol's `2³²`),
    /// `None` when every `u64` index gives its own point.
    fn point_count(&self) -> Option<u64>;

    /// Coordinate `dim` of point `index`, in `[0, 1)`.
    fn sample(&self, index: u64, dim: u32) -> f32;

    /// Coordinate `dim` of point `index` in double precision, in `[0, 1)`. The default widens
    /// [`Sequence::sample`]; sets that can do better override it.
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        f64::from(self.sample(index, dim))
    }

    /// Writes points `first, first + 1, …` into `out`, point-major (`[x0, y0, x1, y1, …]` for
    /// `dims == 2`), `out.len() / dims` points, the first `dims` coordinates of each. Returns the
    /// number of points written. Allocates: no.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `dims == 0`; [`Error::DimensionOutOfRange`] if `dims > self.dims()`;
    /// [`Error::BufferLength`] if `out` is empty or not a multiple of `dims`; [`Error::TooMany`]
    /// if the indices would pass `u64::MAX` or the set's point count.
    ///
    /// ```
    /// use nyquist::sequence::{Halton, Sequence};
    /// let h = Halton::new(3).unwrap();
    /// let mut buf = [0.0f32; 6];
    /// assert_eq!(h.fill(10, 3, &mut buf), Ok(2));
    /// assert_eq!(buf[3], h.sample(11, 0));
    /// assert!(h.fill(0, 4, &mut buf).is_err());
    /// ```
    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        let n = check_fill(self.dims(), self.point_count(), first, dims, out.len())?;
        // Indices from `0..n` offset by `first` (never past `first + n − 1 ≤ u64::MAX`: an
        // open range would compute the successor of the last index and overflow).
        for (k, point) in (0..n).zip(out.chunks_exact_mut(dims as usize)) {
            let index = first + k;
            for (dim, x) in (0..dims).zip(point) {
                *x = self.sample(index, dim);
            }
        }
        Ok(n)
    }
}

/// Validates a [`Sequence::fill`] request and returns the number of points it writes.
///
/// # Errors
/// As [`Sequence::fill`] describes.
///
/// ```
/// use nyquist::{sequence::check_fill, Error};
/// assert_eq!(check_fill(2, None, 0, 2, 8), Ok(4));
/// assert_eq!(
///     check_fill(2, Some(4), 2, 2, 8),
///     Err(Error::TooMany { what: "index range", value: 6, max: 4 })
/// );
/// ```
pub fn check_fill(
    set_dims: u32,
    point_count: Option<u64>,
    first: u64,
    dims: u32,
    len: usize,
) -> Result<u64, Error> {
    if dims == 0 {
        return Err(Error::ZeroSize { what: "dims" });
    }
    if dims > set_dims {
        return Err(Error::DimensionOutOfRange {
            dim: dims - 1,
            dims: set_dims,
        });
    }
    if len == 0 || !len.is_multiple_of(dims as usize) {
        return Err(Error::BufferLength {
            multiple_of: dims as usize,
            actual: len,
        });
    }
    // usize has at most 64 bits on every target.
    let n = (len / dims as usize) as u64;
    let end = first.checked_add(n).ok_or(Error::TooMany {
        what: "first",
        value: first,
        max: u64::MAX - n,
    })?;
    if let Some(count) = point_count
        && end > count
    {
        return Err(Error::TooMany {
            what: "index range",
            value: end,
            max: count,
        });
    }
    Ok(n)
}
