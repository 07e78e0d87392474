//! Reconstruction filters: the [`Filter`] trait (the plugin point), the six built-in filters,
//! precomputed lookup tables and filter importance sampling.
//!
//! A filter is a weight function `f(x, y)` of the offset from a pixel centre, in pixels, with
//! support `[−rx, rx] × [−ry, ry]`. The film reconstructs a pixel as
//! `Σ f(xᵢ − x, yᵢ − y)·L(xᵢ, yᵢ) / Σ f(xᵢ − x, yᵢ − y)`.
//!
//! | filter | default radius | definition per axis (`|x| ≤ r`, else 0) |
//! |---|---|---|
//! | [`Boxcar`] | ½ | `1` |
//! | [`Triangle`] | 2 | `r − |x|` |
//! | [`Gaussian`] | 2, α = 2 | `e^(−αx²) − e^(−αr²)`; `σ` form α = 1/(2σ²) |
//! | [`Mitchell`] | 2, B = C = ⅓ | Mitchell–Netravali cubic at `t = 2|x|/r`; Catmull–Rom is B = 0, C = ½ ([`Mitchell::catmull_rom`]) |
//! | [`Lanczos`] | 4, τ = 3 | `sinc(x)·sinc(x/τ)`, `sinc(x) = sin(πx)/(πx)` |
//! | [`BlackmanHarris`] | 1.5 | `a₀ − a₁cos 2πu + a₂cos 4πu − a₃cos 6πu`, `u = x/(2r) + ½` |
//!
//! Every built-in filter is separable, `f(x, y) = f(x)·f(y)` with a radius per axis.
//!
//! - [`FilterTable`] tabulates any filter once (separable: two 1D tables; otherwise a full 2D
//!   table) for a branch-free lookup; [`Table::footprint`] fills every weight of one sample's
//!   footprint at once. [`SeparableTable`], [`Table2d`] and the size-erased [`TableView`] are
//!   the same [`Table`] over other storages: one implementation, the same bits.
//! - [`PhaseTable`] tabulates a separable filter by footprint phase: all of a sample's weights
//!   along an axis come from one interpolated row (the film's fast path, radii below 8).
//! - [`FilmTable`] is the table a film reads: the phase table where it holds the filter, a
//!   64-entry [`FilterTable`] elsewhere. Every table implements [`Weights`], the one interface
//!   a film accumulates through.
//! - [`FilterSampler`] draws offsets with density ∝ `|f|` and returns the weight `f/pdf`
//!   (pbrt-v4's filter importance sampling).
//! - [`FilterKind`] gathers the built-ins for configuration, with a parser for command-line specs
//!   like `mitchell:b=0.5,c=0.25` ([`FilterKind::parse`]).
//!
//! Sources: Mitchell & Netravali 1988, "Reconstruction Filters in Computer Graphics" (the
//! cubic); Catmull & Rom 1974 (the interpolating spline, the cubic's B = 0, C = ½); Harris 1978
//! (the 4-term Blackman–Harris window); Duchon 1979 (Lanczos windowed sinc); Pharr, Jakob & Humphreys, *Physically Based
//! Rendering* 2nd–4th ed. (the α-form Gaussian, 16-entry tables, filter importance sampling).
//!
//! ```
//! use nyquist::filter::{Filter, FilterTable, Interpolation, Mitchell};
//!
//! let m = Mitchell::default();
//! assert!((m.eval(0.0, 0.0) - (1.0 - 1.0 / 9.0) * (1.0 - 1.0 / 9.0)).abs() < 1e-6);
//! assert_eq!(m.eval(2.5, 0.0), 0.0); // past the radius
//! let table: FilterTable = FilterTable::new(&m, Interpolation::Linear).unwrap();
//! assert!((table.weight(0.3, -0.7) - m.eval(0.3, -0.7)).abs() <= 0.0138);
//! ```

// `!(x <= r)` is deliberate throughout: NaN fails every comparison, so it lands on the zero side.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::Error;
use crate::error::Interval;

mod blackman_harris;
mod boxcar;
mod film_table;
mod gaussian;
mod kind;
mod lanczos;
mod mitchell;
mod phase;
mod sample;
mod table;
mod triangle;
mod weights;

#[cfg(test)]
mod tests;

pub use blackman_harris::BlackmanHarris;
pub use boxcar::Boxcar;
pub use film_table::FilmTable;
pub use gaussian::Gaussian;
pub use kind::{FILTER_NAMES, FilterKind, SpecError};
pub use lanczos::{Lanczos, sinc};
pub use mitchell::Mitchell;
pub use phase::{MAX_TAPS, PHASES, PhaseTable};
pub use sample::{FilterSample, FilterSampler};
pub use table::{FilterTable, Interpolation, SeparableTable, Table, Table2d, TableView, storage};
pub use triangle::Triangle;
pub use weights::Weights;

/// The smallest radius a built-in filter accepts, `2⁻¹⁶` pixels.
///
/// ```
/// use nyquist::filter::{Boxcar, MIN_RADIUS};
/// assert!(Boxcar::new([MIN_RADIUS, 1.0]).is_ok());
/// assert!(Boxcar::new([MIN_RADIUS / 2.0, 1.0]).is_err());
/// ```
pub const MIN_RADIUS: f32 = 1.0 / 65_536.0;

/// The largest radius a built-in filter accepts, 1024 pixels (keeps every integral finite).
///
/// ```
/// use nyquist::filter::{Triangle, MAX_RADIUS};
/// assert!(Triangle::new([MAX_RADIUS, MAX_RADIUS]).is_ok());
/// assert!(Triangle::new([MAX_RADIUS * 2.0, 1.0]).is_err());
/// ```
pub const MAX_RADIUS: f32 = 1024.0;

/// One of the two axes of a filter's support.
///
/// ```
/// use nyquist::filter::Axis;
/// assert_eq!(Axis::Y.index(), 1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The horizontal axis (`x`, radius `rx`).
    X,
    /// The vertical axis (`y`, radius `ry`).
    Y,
}

impl Axis {
    /// 0 for [`Axis::X`], 1 for [`Axis::Y`]: the index into `[rx, ry]`.
    ///
    /// ```
    /// assert_eq!(nyquist::filter::Axis::X.index(), 0);
    /// ```
    #[inline]
    pub const fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
        }
    }
}

/// A reconstruction filter: a weight function of the offset `(x, y)` from a pixel centre, in
/// pixels. This is the plugin point: implement it for your own type and it tabulates
/// ([`FilterTable`]) and samples ([`FilterSampler`]) like a built-in. The trait is object-safe,
/// so `&dyn Filter` works, and `&F` is a filter whenever `F` is.
///
/// # Contract
///
/// - [`radius`](Filter::radius) is `[rx, ry]`, finite and `> 0`, constant for the value.
/// - [`eval`](Filter::eval) is total: finite for every input, exactly `0.0` when `|x| > rx` or
///   `|y| > ry`, and `0.0` for NaN or infinite offsets.
/// - If [`eval_1d`](Filter::eval_1d) returns `Some` for one input it returns `Some` for all, and
///   then `eval(x, y) == eval_1d(X, x).unwrap() * eval_1d(Y, y).unwrap()` (the filter is
///   separable).
/// - Tables assume the filter is even on each axis, `f(x, y) = f(|x|, |y|)`, as pbrt's do (an
///   uneven filter shifts the image); the importance sampler assumes nothing about symmetry.
///
/// # Examples
///
/// A user-defined, non-separable filter (a cone):
///
/// ```
/// use nyquist::filter::{Filter, FilterTable, Interpolation};
///
/// #[derive(Debug)]
/// struct Cone;
/// impl Filter for Cone {
///     fn radius(&self) -> [f32; 2] { [1.0, 1.0] }
///     fn eval(&self, x: f32, y: f32) -> f32 {
///         let d = 1.0 - (x * x + y * y);
///         if d > 0.0 { d } else { 0.0 } // NaN compares false: weight 0
///     }
/// }
/// let dynamic: &dyn Filter = &Cone;
/// assert_eq!(dynamic.eval(0.0, 0.0), 1.0);
/// // ∫∫ (1 − ρ²) over the unit disk is π/2; the default integral is numeric.
/// assert!((dynamic.integral() - core::f32::consts::FRAC_PI_2).abs() < 1e-3);
/// let table: FilterTable = FilterTable::new(dynamic, Interpolation::Linear).unwrap();
/// assert!(!table.is_separable());
/// ```
pub trait Filter {
    /// Half-width of the support in pixels, `[rx, ry]`; finite and `> 0`.
    fn radius(&self) -> [f32; 2];

    /// Weight at offset `(x, y)` from the pixel centre. Finite; exactly `0.0` past the radius on
    /// either axis and for NaN or infinite offsets.
    fn eval(&self, x: f32, y: f32) -> f32;

    /// `∫∫ f(x, y) dx dy` over the support.
    ///
    /// The provided method integrates numerically in `f64` (midpoint rule: 4096 cells per axis
    /// for separable filters, 256 × 256 cells otherwise); built-ins override it with closed
    /// forms.
    fn integral(&self) -> f32 {
        numeric_integral(self) as f32
    }

    /// The 1D factor along `axis` at offset `x` if the filter is separable
    /// (`eval(x, y) == eval_1d(X, x)·eval_1d(Y, y)`), or `None` (the default) if it is not.
    /// Same totality rules as [`eval`](Filter::eval).
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        let _ = (axis, x);
        None
    }

    /// Whether [`eval_1d`](Filter::eval_1d) provides the separable form (probes it at 0).
    ///
    /// ```
    /// use nyquist::filter::{Filter, Lanczos};
    /// assert!(Lanczos::default().is_separable());
    /// ```
    fn is_separable(&self) -> bool {
        self.eval_1d(Axis::X, 0.0).is_some()
    }
}

impl<F: Filter + ?Sized> Filter for &F {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        (**self).radius()
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        (**self).eval(x, y)
    }
    #[inline]
    fn integral(&self) -> f32 {
        (**self).integral()
    }
    #[inline]
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        (**self).eval_1d(axis, x)
    }
    #[inline]
    fn is_separable(&self) -> bool {
        (**self).is_separable()
    }
}

/// The numeric integral used by [`Filter::integral`]'s provided method, in `f64`: the product
/// of two 4096-cell midpoint sums for separable filters, a 256 × 256-cell midpoint sum otherwise.
/// Allocates: no.
///
/// ```
/// use nyquist::filter::{numeric_integral, Triangle};
/// // The triangle's exact integral at the default radius is 16.
/// assert!((numeric_integral(&Triangle::default()) - 16.0).abs() < 1e-4);
/// ```
pub fn numeric_integral<F: Filter + ?Sized>(filter: &F) -> f64 {
    let [rx, ry] = radius_or_zero(filter);
    if filter.is_separable() {
        let axis = |axis: Axis, r: f32| {
            const N: u32 = 4096;
            let h = 2.0 * f64::from(r) / f64::from(N);
            let mut sum = 0.0f64;
            for i in 0..N {
                let x = -f64::from(r) + (f64::from(i) + 0.5) * h;
                sum += f64::from(filter.eval_1d(axis, x as f32).unwrap_or(0.0));
            }
            sum * h
        };
        axis(Axis::X, rx) * axis(Axis::Y, ry)
    } else {
        midpoint_integral(filter, [256, 256])
    }
}

/// The midpoint-rule integral of `filter.eval` over its support on an `n[0] × n[1]` grid, in
/// `f64` (cells of zero count give 0). Allocates: no.
///
/// ```
/// use nyquist::filter::{midpoint_integral, Boxcar};
/// assert_eq!(midpoint_integral(&Boxcar::default(), [8, 8]), 1.0);
/// ```
pub fn midpoint_integral<F: Filter + ?Sized>(filter: &F, n: [u32; 2]) -> f64 {
    let [rx, ry] = radius_or_zero(filter);
    if n[0] == 0 || n[1] == 0 {
        return 0.0;
    }
    let hx = 2.0 * f64::from(rx) / f64::from(n[0]);
    let hy = 2.0 * f64::from(ry) / f64::from(n[1]);
    let mut sum = 0.0f64;
    for j in 0..n[1] {
        let y = (-f64::from(ry) + (f64::from(j) + 0.5) * hy) as f32;
        for i in 0..n[0] {
            let x = (-f64::from(rx) + (f64::from(i) + 0.5) * hx) as f32;
            sum += f64::from(filter.eval(x, y));
        }
    }
    sum * hx * hy
}

/// The filter's radius with anything that breaks the contract (NaN, ∞, ≤ 0) replaced by 0, so
/// generic code over plugin filters stays total.
#[inline]
pub(crate) fn radius_or_zero<F: Filter + ?Sized>(filter: &F) -> [f32; 2] {
    let ok = |r: f32| if r > 0.0 && r <= f32::MAX { r } else { 0.0 };
    let [rx, ry] = filter.radius();
    [ok(rx), ok(ry)]
}

/// Checks a finite float parameter lies in `[lo, hi]`: NaN/∞ → [`Error::NonFinite`], outside →
/// [`Error::OutOfRange`] with the value and `[lo, hi]`.
pub(crate) fn check(value: f32, what: &'static str, lo: f32, hi: f32) -> Result<f32, Error> {
    if !value.is_finite() {
        Err(Error::NonFinite { what })
    } else if value >= lo && value <= hi {
        Ok(value)
    } else {
        Err(Error::OutOfRange {
            what,
            value: f64::from(value),
            range: Interval::closed(f64::from(lo), f64::from(hi)),
        })
    }
}

/// The smallest filter integral a filter or table accepts: below it a filter weights every sample
/// by almost nothing, and the film's weighted means (sums over sums of weights) lose their
/// precision or divide zero by zero.
pub const MIN_INTEGRAL: f32 = 1e-12;

/// Validates a filter's integral: finite and at least [`MIN_INTEGRAL`] (so neither 0, negative
/// nor NaN), named `filter integral`.
pub(crate) fn check_integral(integral: f32) -> Result<f32, Error> {
    check(integral, "filter integral", MIN_INTEGRAL, f32::MAX)
}

/// Validates a per-axis radius: each in [`MIN_RADIUS`]`..=`[`MAX_RADIUS`], named `rx` / `ry`.
pub(crate) fn check_radius(radius: [f32; 2]) -> Result<[f32; 2], Error> {
    Ok([
        check(radius[0], "rx", MIN_RADIUS, MAX_RADIUS)?,
        check(radius[1], "ry", MIN_RADIUS, MAX_RADIUS)?,
    ])
}
