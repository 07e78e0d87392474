//! The one interface every filter table offers a film: [`Weights`].

use super::Axis;
use super::table::{check_footprint, one_weight, per_weight};
use crate::Error;

/// Filter weights by offset from a pixel centre, as a film reads them: single weights, the two
/// per-axis factors of a separable filter, or every weight of a sample's footprint at once.
///
/// Every table implements it ([`Table`](super::Table) in each of its forms,
/// [`PhaseTable`](super::PhaseTable), [`FilmTable`](super::FilmTable)), so code that
/// accumulates samples is written once for all of them; implement it to give such code another
/// source, such as direct evaluation of a [`Filter`](super::Filter). The trait is object-safe,
/// and `&W` implements it whenever `W` does.
///
/// # Contract
///
/// - [`radius`](Weights::radius) is `[rx, ry]`, finite and `> 0`.
/// - [`weight`](Weights::weight) is finite for every input, and exactly `0.0` past the radius on
///   either axis and for NaN or infinite offsets.
/// - [`weight_1d`](Weights::weight_1d) returns `Some` for every input exactly when
///   [`is_separable`](Weights::is_separable) is true, and then
///   `weight(dx, dy) == weight_1d(X, dx).unwrap() * weight_1d(Y, dy).unwrap()`.
/// - [`footprint`](Weights::footprint) writes the weights of the pixels at offsets
///   `(d0[0] + i, d0[1] + j)`; a table computes them faster than one `weight` call each.
///
/// # Examples
///
/// One accumulation loop over a table and over direct evaluation:
///
/// ```
/// use nyquist::filter::{Axis, Filter, FilterTable, Interpolation, Mitchell, Weights};
///
/// /// A filter evaluated directly, as weights.
/// struct Direct<F>(F);
/// impl<F: Filter> Weights for Direct<F> {
///     fn radius(&self) -> [f32; 2] { self.0.radius() }
///     fn integral(&self) -> f32 { self.0.integral() }
///     fn weight(&self, dx: f32, dy: f32) -> f32 { self.0.eval(dx, dy) }
///     fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> { self.0.eval_1d(axis, d) }
/// }
///
/// /// The weight sum a sample at offset `d0` from its first pixel gives a 4 × 4 footprint.
/// fn footprint_sum(w: &dyn Weights, d0: [f32; 2]) -> f32 {
///     let mut out = [0.0f32; 16];
///     w.footprint(d0, 4, &mut out).unwrap();
///     out.iter().sum()
/// }
///
/// let m = Mitchell::default();
/// let table: FilterTable = FilterTable::new(&m, Interpolation::Linear).unwrap();
/// let (a, b) = (footprint_sum(&table, [-1.6, -1.3]), footprint_sum(&Direct(m), [-1.6, -1.3]));
/// assert!((a - b).abs() < 0.02);
/// assert!(Direct(m).is_separable() && table.is_separable());
/// ```
pub trait Weights {
    /// Half-width of the support in pixels, `[rx, ry]`.
    fn radius(&self) -> [f32; 2];

    /// `∫∫ f(x, y) dx dy` of the filter the weights come from (what splats are divided by).
    fn integral(&self) -> f32;

    /// The weight at offset `(dx, dy)` from the pixel centre; 0 past the radius and for NaN or
    /// infinite offsets.
    fn weight(&self, dx: f32, dy: f32) -> f32;

    /// The factor along `axis` at offset `d` when the weights are separable, so that
    /// `weight(dx, dy) == weight_1d(X, dx)·weight_1d(Y, dy)`; `None` (the default) when they are
    /// not.
    fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        let _ = (axis, d);
        None
    }

    /// Whether [`weight_1d`](Weights::weight_1d) gives the per-axis factors (the provided
    /// method probes it at 0).
    fn is_separable(&self) -> bool {
        self.weight_1d(Axis::X, 0.0).is_some()
    }

    /// The weights of a whole footprint: `out[j·nx + i]` is the weight of the pixel at offset
    /// `(d0[0] + i, d0[1] + j)`, for `j < out.len() / nx`. The provided method calls
    /// [`weight`](Weights::weight) per pixel; tables override it with their fast paths.
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `out.len()` is a positive multiple of `nx` (and whatever
    /// else the implementation documents).
    fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        if let Some(w) = one_weight(nx, &mut *out) {
            *w = self.weight(d0[0], d0[1]);
            return Ok(());
        }
        let ny = check_footprint(nx, out)?;
        per_weight(d0, [nx, ny], out, |x, y| self.weight(x, y));
        Ok(())
    }
}

impl<W: Weights + ?Sized> Weights for &W {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        (**self).radius()
    }
    #[inline]
    fn integral(&self) -> f32 {
        (**self).integral()
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight(&self, dx: f32, dy: f32) -> f32 {
        (**self).weight(dx, dy)
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        (**self).weight_1d(axis, d)
    }
    #[inline]
    fn is_separable(&self) -> bool {
        (**self).is_separable()
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        (**self).footprint(d0, nx, out)
    }
}
