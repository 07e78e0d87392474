//! The truncated Gaussian filter.

use super::{Axis, Filter, check, check_radius};
use crate::{Error, math};

/// The smallest `f32` σ whose `α = 1/(2σ²)` (in `f64`) is at most `f32::MAX`.
pub(super) const MIN_SIGMA: f32 = 3.833_233_8e-20;
/// The largest `f32` σ whose `α = 1/(2σ²)` (in `f64`) is at least `f32::MIN_POSITIVE`.
pub(super) const MAX_SIGMA: f32 = 6.521_909e18;

/// The Gaussian filter, shifted to reach 0 at the radius: per axis
/// `max(0, e^(−αx²) − e^(−αr²))` for `|x| ≤ r`, the 2D weight being the product. Defaults:
/// radius 2, α = 2. [`Gaussian::with_sigma`] takes the standard deviation instead,
/// `α = 1/(2σ²)`.
///
/// ```
/// use nyquist::filter::{Filter, Gaussian};
/// let g = Gaussian::default();
/// let e8 = (-8.0f32).exp();
/// assert!((g.eval(0.0, 0.0) - (1.0 - e8) * (1.0 - e8)).abs() < 1e-6);
/// assert_eq!(g.eval(2.0, 0.0), 0.0);
/// assert!((g.integral() - 1.5672358300).abs() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gaussian {
    radius: [f32; 2],
    alpha: f32,
    /// `e^(−α r²)` per axis.
    offset: [f32; 2],
}

impl Gaussian {
    /// A Gaussian of half-widths `[rx, ry]` and falloff `alpha` (`e^(−αx²)`).
    ///
    /// # Errors
    /// [`Error::NonFinite`] / [`Error::OutOfRange`] naming `"rx"`, `"ry"` or `"alpha"`: each
    /// radius must be in [`MIN_RADIUS`](super::MIN_RADIUS)`..=`[`MAX_RADIUS`](super::MAX_RADIUS)
    /// and `alpha` finite and `> 0` (at least `f32::MIN_POSITIVE`); then
    /// [`Error::OutOfRange`] naming `"filter integral"` when the Gaussian's integral is below
    /// [`MIN_INTEGRAL`](super::MIN_INTEGRAL): α so small against the radius that the filter is
    /// nearly 0 everywhere (`e^(−αx²) − e^(−αr²)`), or so large that it is a spike.
    ///
    /// ```
    /// use nyquist::{filter::Gaussian, Error};
    /// assert!(Gaussian::new([1.5, 1.5], 4.0).is_ok());
    /// let e = Gaussian::new([1.5, 1.5], 0.0).unwrap_err();
    /// assert!(matches!(e, Error::OutOfRange { what: "alpha", value: 0.0, .. }));
    /// assert_eq!(e.to_string(), "alpha 0 is outside [1.1754944e-38, 3.4028235e38]");
    /// ```
    pub fn new(radius: [f32; 2], alpha: f32) -> Result<Gaussian, Error> {
        let radius = check_radius(radius)?;
        let alpha = check(alpha, "alpha", f32::MIN_POSITIVE, f32::MAX)?;
        let off = |r: f32| math::exp(-f64::from(alpha) * f64::from(r) * f64::from(r)) as f32;
        let g = Gaussian {
            radius,
            alpha,
            offset: [off(radius[0]), off(radius[1])],
        };
        super::check_integral(g.integral())?;
        Ok(g)
    }

    /// A Gaussian of half-widths `[rx, ry]` and standard deviation `sigma`: `α = 1/(2σ²)`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] / [`Error::OutOfRange`] with `what = "sigma"` unless `sigma` is in
    /// `[3.8332338e-20, 6.521909e18]`, the `f32` values for which `1/(2σ²)` is a finite, normal
    /// `f32`; then as [`Gaussian::new`] for the radius and the integral.
    ///
    /// ```
    /// use nyquist::filter::Gaussian;
    /// let g = Gaussian::with_sigma([1.5, 1.5], 0.5).unwrap();
    /// assert_eq!(g.alpha(), 2.0);
    /// assert_eq!(
    ///     Gaussian::with_sigma([1.5, 1.5], -0.5).unwrap_err().to_string(),
    ///     "sigma -0.5 is outside [3.8332338e-20, 6.521909e18]"
    /// );
    /// ```
    pub fn with_sigma(radius: [f32; 2], sigma: f32) -> Result<Gaussian, Error> {
        let sigma = check(sigma, "sigma", MIN_SIGMA, MAX_SIGMA)?;
        let alpha = 1.0 / (2.0 * f64::from(sigma) * f64::from(sigma));
        Gaussian::new(radius, alpha as f32)
    }

    /// The falloff α.
    ///
    /// ```
    /// assert_eq!(nyquist::filter::Gaussian::default().alpha(), 2.0);
    /// ```
    pub fn alpha(&self) -> f32 {
        self.alpha
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn axis(&self, i: usize, x: f32) -> f32 {
        let v = (math::exp_f32(-self.alpha * x * x) - self.offset[i]).max(0.0);
        // Select, not branch; NaN fails the comparison: weight 0.
        if x.abs() <= self.radius[i] { v } else { 0.0 }
    }

    /// `∫_{−r}^{r} (e^(−αx²) − e^(−αr²)) dx` in `f64`.
    fn axis_integral(r: f64, alpha: f64) -> f64 {
        let a = alpha * r * r;
        let v = if a < 1e-3 {
            // Series in a = αr² (avoids cancelling two nearly equal terms):
            // 2r·(2a/3 − 2a²/5 + a³/7 − …).
            2.0 * r * (a * (2.0 / 3.0) - a * a * (2.0 / 5.0) + a * a * a / 7.0)
        } else {
            math::sqrt(core::f64::consts::PI / alpha) * math::erf(math::sqrt(a))
                - 2.0 * r * math::exp(-a)
        };
        v.max(0.0)
    }
}

impl Default for Gaussian {
    /// Radius 2, α = 2.
    fn default() -> Gaussian {
        Gaussian {
            radius: [2.0, 2.0],
            alpha: 2.0,
            offset: [math::exp(-8.0) as f32; 2],
        }
    }
}

impl Filter for Gaussian {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        self.axis(0, x) * self.axis(1, y)
    }
    /// Closed form per axis, `√(π/α)·erf(√α·r) − 2r·e^(−αr²)`, multiplied.
    fn integral(&self) -> f32 {
        let alpha = f64::from(self.alpha);
        let ix = Self::axis_integral(f64::from(self.radius[0]), alpha);
        let iy = Self::axis_integral(f64::from(self.radius[1]), alpha);
        (ix * iy) as f32
    }
    #[inline]
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        Some(self.axis(axis.index(), x))
    }
    fn is_separable(&self) -> bool {
        true
    }
}
