//! Quality measures of point sets: exact and bracketed star discrepancy, the L2 discrepancies
//! (star, centered, wrap-around, mixture, and their sums for updates), the t-value of a base-2 net,
//! and the minimum distance with its relative radius ρ.
//!
//! # Points
//!
//! Every measure takes a validated [`PointSet`]: a flat, point-major `&[f64]`
//! (`[x0, y0, x1, y1, …]`) with its number of dimensions. `f64` because discrepancies of large
//! sets are small differences of large sums. [`PointSet::from_2d`] views a `&[[f64; 2]]`, and
//! [`PointSet::from_f32`] widens `f32` samples into a caller buffer. The constructor checks the
//! values once (finite, inside `[0, 1]`), so the measures themselves only check buffer sizes.
//!
//! # Scratch
//!
//! Nothing allocates: functions that sort or bin take a caller scratch slice, sized by the
//! matching `*_scratch_len` query, and return [`Error::BufferTooShort`] when it is short.
//!
//! # Definitions
//!
//! The star discrepancy is `D*_N = sup_t |A(B_t)/N − λ(B_t)|` over the anchored boxes
//! `B_t = [0, t)` and `[0, t]`, `t ∈ [0, 1]^d` (the convention of Dobkin, Eppstein & Mitchell 1996
//! and Gnewuch, Srivastav & Winzen 2009). For points in `[0, 1)^d` it equals Niederreiter's
//! half-open definition; it differs only for points with a coordinate exactly 1, which closed
//! boxes can count.
//!
//! Sources: H. Niederreiter, *Random Number Generation and Quasi-Monte Carlo Methods* (1992),
//! Thm. 2.6 (the 1D formula); L. De Clerck, "A method for exact calculation of the stardiscrepancy
//! of plane sets applied to the sequences of Hammersley", *Monatsh. Math.* 101 (1986);
//! D. Dobkin, D. Eppstein, D. Mitchell, "Computing the discrepancy with applications to
//! supersampling patterns", *ACM TOG* 15 (1996); T. Warnock, "Computational investigations of
//! low-discrepancy point sets" (1972); F. J. Hickernell, "A generalized discrepancy and
//! quadrature error bound", *Math. Comp.* 67 (1998).

mod distance;
mod l2;
mod net;
mod star;

pub use distance::{MinDistance, Topology, min_distance, min_distance_scratch_len};
pub use l2::{
    L2Kind, L2Sums, centered_l2_discrepancy, l2_point_sums, l2_star_discrepancy, l2_sums,
    l2_sums_rows, mixture_l2_discrepancy, wraparound_l2_discrepancy,
};
pub use net::{net_t_value, net_t_value_scratch_len};
pub use star::{
    ENUMERATION_LIMIT, MAX_DIMS, StarBounds, star_bounds_scratch_len, star_discrepancy,
    star_discrepancy_1d, star_discrepancy_2d, star_discrepancy_bounds, star_discrepancy_enumerate,
    star_discrepancy_scratch_len,
};

use crate::Error;
use crate::error::Interval;

/// A validated, borrowed point set: `len() · dims()` coordinates, point-major, each finite and
/// in `[0, 1]`, at least one point, at most `u32::MAX` points.
///
/// ```
/// use nyquist::analysis::PointSet;
/// let set = PointSet::new(&[0.1, 0.2, 0.3, 0.4], 2).unwrap();
/// assert_eq!((set.len(), set.dims()), (2, 2));
/// assert_eq!(set.point(1), &[0.3, 0.4]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PointSet<'a> {
    coords: &'a [f64],
    dims: usize,
    len: usize,
}

impl<'a> PointSet<'a> {
    /// Views `coords` as points of `dims` coordinates each, checking every value once.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `dims == 0` or no coordinates; [`Error::BufferLength`] if the
    /// length is not a multiple of `dims`; [`Error::NonFinite`] for NaN or ±∞;
    /// [`Error::OutOfRange`] (`what: "point coordinate"`) for a value outside `[0, 1]`;
    /// [`Error::TooMany`] above `u32::MAX` points.
    ///
    /// ```
    /// use nyquist::{analysis::PointSet, Error};
    /// assert!(PointSet::new(&[0.0, 1.0], 1).is_ok());
    /// assert_eq!(PointSet::new(&[], 2).unwrap_err(), Error::ZeroSize { what: "points" });
    /// let e = PointSet::new(&[0.5, 1.5], 1).unwrap_err();
    /// assert!(matches!(e, Error::OutOfRange { what: "point coordinate", value: 1.5, .. }));
    /// assert_eq!(e.to_string(), "point coordinate 1.5 is outside [0, 1]");
    /// assert_eq!(PointSet::new(&[f64::NAN], 1).unwrap_err(), Error::NonFinite { what: "points" });
    /// ```
    pub fn new(coords: &'a [f64], dims: usize) -> Result<Self, Error> {
        if dims == 0 {
            return Err(Error::ZeroSize { what: "dims" });
        }
        if coords.is_empty() {
            return Err(Error::ZeroSize { what: "points" });
        }
        if !coords.len().is_multiple_of(dims) {
            return Err(Error::BufferLength {
                multiple_of: dims,
                actual: coords.len(),
            });
        }
        let len = coords.len() / dims;
        if u32::try_from(len).is_err() {
            return Err(Error::TooMany {
                what: "points",
                value: len as u64,
                max: u64::from(u32::MAX),
            });
        }
        for &x in coords {
            if !x.is_finite() {
                return Err(Error::NonFinite { what: "points" });
            }
            if !(0.0..=1.0).contains(&x) {
                return Err(Error::OutOfRange {
                    what: "point coordinate",
                    value: x,
                    range: Interval::closed(0.0, 1.0),
                });
            }
        }
        Ok(PointSet { coords, dims, len })
    }

    /// Views 2D points stored as pairs.
    ///
    /// # Errors
    /// As [`PointSet::new`].
    ///
    /// ```
    /// use nyquist::analysis::PointSet;
    /// let pts = [[0.25, 0.5], [0.75, 0.0]];
    /// assert_eq!(PointSet::from_2d(&pts).unwrap().len(), 2);
    /// ```
    pub fn from_2d(points: &'a [[f64; 2]]) -> Result<Self, Error> {
        Self::new(points.as_flattened(), 2)
    }

    /// Widens `f32` coordinates into `buf` (its first `src.len()` elements) and views them.
    ///
    /// # Errors
    /// [`Error::BufferTooShort`] if `buf` is shorter than `src`; otherwise as [`PointSet::new`].
    ///
    /// ```
    /// use nyquist::analysis::PointSet;
    /// let mut buf = [0.0f64; 4];
    /// let set = PointSet::from_f32(&[0.5, 0.25, 0.125, 1.0], 2, &mut buf).unwrap();
    /// assert_eq!(set.point(0), &[0.5, 0.25]);
    /// ```
    pub fn from_f32(src: &[f32], dims: usize, buf: &'a mut [f64]) -> Result<Self, Error> {
        let out = check_scratch(buf, src.len())?;
        for (o, &s) in out.iter_mut().zip(src) {
            *o = f64::from(s);
        }
        Self::new(out, dims)
    }

    /// Number of points (at least 1).
    ///
    /// ```
    /// assert_eq!(nyquist::analysis::PointSet::new(&[0.5; 6], 3).unwrap().len(), 2);
    /// ```
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Always `false`: a `PointSet` holds at least one point.
    ///
    /// ```
    /// assert!(!nyquist::analysis::PointSet::new(&[0.5], 1).unwrap().is_empty());
    /// ```
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Coordinates per point.
    ///
    /// ```
    /// assert_eq!(nyquist::analysis::PointSet::new(&[0.5; 6], 3).unwrap().dims(), 3);
    /// ```
    #[inline]
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// All coordinates, point-major.
    ///
    /// ```
    /// let c = [0.1, 0.2];
    /// assert_eq!(nyquist::analysis::PointSet::new(&c, 1).unwrap().coords(), &c);
    /// ```
    #[inline]
    pub fn coords(&self) -> &'a [f64] {
        self.coords
    }

    /// Point `i`'s coordinates. Total: `i` wraps to `i % len()`.
    ///
    /// ```
    /// let set = nyquist::analysis::PointSet::new(&[0.1, 0.2], 1).unwrap();
    /// assert_eq!(set.point(3), &[0.2]);
    /// ```
    #[inline]
    pub fn point(&self, i: usize) -> &'a [f64] {
        let i = i % self.len;
        &self.coords[i * self.dims..(i + 1) * self.dims]
    }
}

/// The first `needed` elements of `buf`, or [`Error::BufferTooShort`].
pub(crate) fn check_scratch<T>(buf: &mut [T], needed: usize) -> Result<&mut [T], Error> {
    let actual = buf.len();
    buf.get_mut(..needed)
        .ok_or(Error::BufferTooShort { needed, actual })
}

#[cfg(test)]
pub(crate) mod testsets {
    //! Point sets for the tests, built here so this module needs no sequence code.
    use std::vec::Vec;

    /// Φ₂(i), the base-2 radical inverse, by bit reversal.
    pub fn vdc(i: u32) -> f64 {
        f64::from(i.reverse_bits()) * crate::math::TWO_POW_MINUS_32
    }

    /// The first `n` van der Corput points.
    pub fn van_der_corput(n: u32) -> Vec<f64> {
        (0..n).map(vdc).collect()
    }

    /// Hammersley `(i/N, Φ₂(i))`, flat.
    pub fn hammersley(n: u32) -> Vec<f64> {
        (0..n)
            .flat_map(|i| [f64::from(i) / f64::from(n), vdc(i)])
            .collect()
    }

    /// `n` uniform random points in `dims` dimensions, flat.
    pub fn random(n: usize, dims: usize, seed: u64) -> Vec<f64> {
        let mut rng = crate::rng::default_rng(seed);
        (0..n * dims)
            .map(|_| crate::rng::uniform_f64(&mut rng))
            .collect()
    }
}
