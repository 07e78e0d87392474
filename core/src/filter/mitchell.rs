//! The Mitchell–Netravali filter.

use super::{Axis, Filter, check, check_radius};
use crate::Error;

/// The largest `|B|` or `|C|` [`Mitchell::new`] accepts (keeps every weight finite).
pub(super) const MAX_BC: f32 = 1000.0;

/// The Mitchell–Netravali cubic filter (Mitchell & Netravali 1988) scaled to the radius: per
/// axis `M(t)` at `t = 2|x|/r`, 0 for `t ≥ 2`, where
///
/// - `6·M(t) = (12 − 9B − 6C)t³ + (−18 + 12B + 6C)t² + (6 − 2B)` for `t < 1`,
/// - `6·M(t) = (−B − 6C)t³ + (6B + 30C)t² + (−12B − 48C)t + (8B + 24C)` for `1 ≤ t < 2`.
///
/// Defaults: radius 2 (so `t = |x|`), `B = C = ⅓`, the paper's recommendation. `M` integrates
/// to 1 over `t` for every `(B, C)`, so the 2D integral is `rx·ry/4`.
///
/// ```
/// use nyquist::filter::{Filter, Mitchell};
/// let m = Mitchell::new([2.0, 2.0], 0.5, 0.25).unwrap();
/// let m0 = m.eval_1d(nyquist::filter::Axis::X, 0.0).unwrap();
/// assert!((m0 - (1.0 - 0.5 / 3.0)).abs() < 1e-6); // M(0) = 1 − B/3
/// assert!((m.integral() - 1.0).abs() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mitchell {
    radius: [f32; 2],
    /// `2/r` per axis: offset to `t`.
    scale: [f32; 2],
    b: f32,
    c: f32,
    /// `[t³, t², 1]` coefficients on `[0, 1)`, divided by 6.
    near: [f32; 3],
    /// `[t³, t², t, 1]` coefficients on `[1, 2)`, divided by 6.
    far: [f32; 4],
}

impl Mitchell {
    /// A Mitchell–Netravali filter of half-widths `[rx, ry]` with parameters `b` and `c`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] / [`Error::OutOfRange`] naming `"rx"`, `"ry"`, `"b"` or `"c"`: each
    /// radius must be in [`MIN_RADIUS`](super::MIN_RADIUS)`..=`[`MAX_RADIUS`](super::MAX_RADIUS),
    /// `b` and `c` finite with magnitude at most 1000.
    ///
    /// ```
    /// use nyquist::{filter::Mitchell, Error};
    /// assert!(Mitchell::new([2.0, 2.0], 0.0, 0.5).is_ok()); // Catmull–Rom
    /// assert_eq!(Mitchell::new([2.0, 2.0], f32::NAN, 0.5), Err(Error::NonFinite { what: "b" }));
    /// ```
    pub fn new(radius: [f32; 2], b: f32, c: f32) -> Result<Mitchell, Error> {
        let radius = check_radius(radius)?;
        let b = check(b, "b", -MAX_BC, MAX_BC)?;
        let c = check(c, "c", -MAX_BC, MAX_BC)?;
        let (b6, c6) = (f64::from(b), f64::from(c));
        let k = |v: f64| (v / 6.0) as f32;
        Ok(Mitchell {
            radius,
            scale: [2.0 / radius[0], 2.0 / radius[1]],
            b,
            c,
            near: [
                k(12.0 - 9.0 * b6 - 6.0 * c6),
                k(-18.0 + 12.0 * b6 + 6.0 * c6),
                k(6.0 - 2.0 * b6),
            ],
            far: [
                k(-b6 - 6.0 * c6),
                k(6.0 * b6 + 30.0 * c6),
                k(-12.0 * b6 - 48.0 * c6),
                k(8.0 * b6 + 24.0 * c6),
            ],
        })
    }

    /// The Catmull–Rom spline as a filter (Catmull & Rom 1974): the Mitchell–Netravali cubic at
    /// `B = 0`, `C = ½`, radius 2 (Mitsuba's `catmullrom`). It interpolates (1 at 0, 0 at the
    /// other integers) and has negative lobes of −0.0741 at `|x| = 4/3`; integral 1. Another
    /// radius: [`Mitchell::new`]`(radius, 0.0, 0.5)`, or the spec `catmull-rom:radius=R`.
    ///
    /// ```
    /// use nyquist::filter::{Axis, Filter, Mitchell};
    /// let f = Mitchell::catmull_rom();
    /// assert_eq!(f.bc(), [0.0, 0.5]);
    /// assert_eq!(f.eval_1d(Axis::X, 0.0), Some(1.0));
    /// assert_eq!(f.eval_1d(Axis::X, 1.0), Some(0.0));
    /// assert_eq!(f.integral(), 1.0);
    /// ```
    pub fn catmull_rom() -> Mitchell {
        match Mitchell::new([2.0, 2.0], 0.0, 0.5) {
            Ok(m) => m,
            Err(_) => unreachable!("the Catmull–Rom parameters are valid"),
        }
    }

    /// The parameters `[B, C]`.
    ///
    /// ```
    /// let [b, c] = nyquist::filter::Mitchell::default().bc();
    /// assert_eq!((b, c), (1.0 / 3.0, 1.0 / 3.0));
    /// ```
    pub fn bc(&self) -> [f32; 2] {
        [self.b, self.c]
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn axis(&self, i: usize, x: f32) -> f32 {
        let ax = x.abs();
        let t = ax * self.scale[i];
        let [a3, a2, a0] = self.near;
        let [b3, b2, b1, b0] = self.far;
        // Both pieces, then selects: no branch to mispredict on random offsets.
        let near = (a3 * t + a2) * (t * t) + a0;
        let far = ((b3 * t + b2) * t + b1) * t + b0;
        let v = if t < 1.0 { near } else { far };
        // M(2) = 0 exactly, not the cubic's rounding noise at the radius.
        let v = if t < 2.0 { v } else { 0.0 };
        // NaN fails the comparison: weight 0. (t < 2 at |x| ≤ r up to rounding; M(2) = 0.)
        if ax <= self.radius[i] { v } else { 0.0 }
    }
}

impl Default for Mitchell {
    /// Radius 2, `B = C = ⅓`.
    fn default() -> Mitchell {
        match Mitchell::new([2.0, 2.0], 1.0 / 3.0, 1.0 / 3.0) {
            Ok(m) => m,
            Err(_) => unreachable!("the default parameters are valid"),
        }
    }
}

impl Filter for Mitchell {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        self.axis(0, x) * self.axis(1, y)
    }
    /// `rx·ry/4` for every `(B, C)`.
    fn integral(&self) -> f32 {
        self.radius[0] * self.radius[1] / 4.0
    }
    #[inline]
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        Some(self.axis(axis.index(), x))
    }
    fn is_separable(&self) -> bool {
        true
    }
}
