//! The box filter.

use super::{Axis, Filter, check_radius};
use crate::Error;

/// The box filter: weight 1 for `|x| ≤ rx` and `|y| ≤ ry`, 0 elsewhere. Default radius ½ (one
/// pixel wide). Cheap, and "about the worst filter possible": its frequency response is a sinc
/// that passes much of the aliased spectrum.
///
/// ```
/// use nyquist::filter::{Boxcar, Filter};
/// let b = Boxcar::default();
/// assert_eq!(b.radius(), [0.5, 0.5]);
/// assert_eq!(b.eval(0.5, -0.5), 1.0); // the edge is inside
/// assert_eq!(b.eval(0.5001, 0.0), 0.0);
/// assert_eq!(b.integral(), 1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Boxcar {
    radius: [f32; 2],
}

impl Boxcar {
    /// A box of half-widths `[rx, ry]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] / [`Error::OutOfRange`] (`what` = `"rx"` or `"ry"`) unless each
    /// radius is finite and in [`MIN_RADIUS`](super::MIN_RADIUS)`..=`[`MAX_RADIUS`](super::MAX_RADIUS).
    ///
    /// ```
    /// use nyquist::{filter::Boxcar, Error};
    /// assert!(Boxcar::new([1.0, 0.5]).is_ok());
    /// let e = Boxcar::new([0.0, 0.5]).unwrap_err();
    /// assert!(matches!(e, Error::OutOfRange { what: "rx", value: 0.0, .. }));
    /// assert_eq!(e.to_string(), "rx 0 is outside [0.000015258789, 1024]");
    /// ```
    pub fn new(radius: [f32; 2]) -> Result<Boxcar, Error> {
        Ok(Boxcar {
            radius: check_radius(radius)?,
        })
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn axis(r: f32, x: f32) -> f32 {
        // NaN and ±∞ fail the comparison: weight 0.
        if x.abs() <= r { 1.0 } else { 0.0 }
    }
}

impl Default for Boxcar {
    /// Radius ½ on both axes.
    fn default() -> Boxcar {
        Boxcar { radius: [0.5, 0.5] }
    }
}

impl Filter for Boxcar {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        Self::axis(self.radius[0], x) * Self::axis(self.radius[1], y)
    }
    /// `(2rx)(2ry)`.
    fn integral(&self) -> f32 {
        4.0 * self.radius[0] * self.radius[1]
    }
    #[inline]
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        Some(Self::axis(self.radius[axis.index()], x))
    }
    fn is_separable(&self) -> bool {
        true
    }
}
