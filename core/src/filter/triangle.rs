//! The triangle (tent) filter.

use super::{Axis, Filter, check_radius};
use crate::Error;

/// The triangle filter: `max(0, rx − |x|) · max(0, ry − |y|)`. Default radius 2. Its peak is
/// `rx·ry` (not 1); the film divides by the weight sum, so only the shape matters.
///
/// ```
/// use nyquist::filter::{Filter, Triangle};
/// let t = Triangle::default();
/// assert_eq!(t.eval(0.0, 0.0), 4.0);
/// assert_eq!(t.eval(1.0, 1.5), 0.5);
/// assert_eq!(t.eval(2.0, 0.0), 0.0);
/// assert_eq!(t.integral(), 16.0); // rx²·ry²
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    radius: [f32; 2],
}

impl Triangle {
    /// A triangle of half-widths `[rx, ry]`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] / [`Error::OutOfRange`] (`what` = `"rx"` or `"ry"`) unless each
    /// radius is finite and in [`MIN_RADIUS`](super::MIN_RADIUS)`..=`[`MAX_RADIUS`](super::MAX_RADIUS).
    ///
    /// ```
    /// use nyquist::{filter::Triangle, Error};
    /// assert!(Triangle::new([1.0, 3.0]).is_ok());
    /// assert_eq!(Triangle::new([1.0, f32::NAN]), Err(Error::NonFinite { what: "ry" }));
    /// ```
    pub fn new(radius: [f32; 2]) -> Result<Triangle, Error> {
        Ok(Triangle {
            radius: check_radius(radius)?,
        })
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn axis(r: f32, x: f32) -> f32 {
        let d = r - x.abs();
        // NaN (and −∞ for infinite x) fail `d > 0`: weight 0.
        if d > 0.0 { d } else { 0.0 }
    }
}

impl Default for Triangle {
    /// Radius 2 on both axes.
    fn default() -> Triangle {
        Triangle { radius: [2.0, 2.0] }
    }
}

impl Filter for Triangle {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        Self::axis(self.radius[0], x) * Self::axis(self.radius[1], y)
    }
    /// `rx²·ry²`.
    fn integral(&self) -> f32 {
        let [rx, ry] = self.radius;
        (rx * rx) * (ry * ry)
    }
    #[inline]
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        Some(Self::axis(self.radius[axis.index()], x))
    }
    fn is_separable(&self) -> bool {
        true
    }
}
