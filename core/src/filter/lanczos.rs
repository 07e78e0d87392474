//! The Lanczos windowed-sinc filter and the normalised sinc.

use super::{Axis, Filter, check, check_radius};
use crate::{Error, math};

/// Coefficients of `sin(πr)/(πr) = Σ (−1)ᵏ (πr)²ᵏ / (2k+1)!` in powers of `r²`, `k = 0…6`.
/// On `|r| ≤ ½` the truncation error is below `(π/2)¹⁴/15! < 5·10⁻¹⁰`.
const SINC_POLY: [f32; 7] = {
    const PI2: f64 = core::f64::consts::PI * core::f64::consts::PI;
    let mut c = [0.0f32; 7];
    let mut term = 1.0f64; // (−1)ᵏ π²ᵏ / (2k+1)!
    let mut k = 0;
    while k < 7 {
        c[k] = term as f32;
        let d = ((2 * k + 2) * (2 * k + 3)) as f64;
        term = -term * PI2 / d;
        k += 1;
    }
    c
};

/// `sin(πr)/(πr)` for `|r| ≤ ½` (a little more is fine), as a polynomial in `r²`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn sinc_reduced(r: f32) -> f32 {
    let u = r * r;
    let [c0, c1, c2, c3, c4, c5, c6] = SINC_POLY;
    (((((c6 * u + c5) * u + c4) * u + c3) * u + c2) * u + c1) * u + c0
}

/// The normalised sinc, `sin(πx)/(πx)`, with `sinc(0) = 1`.
///
/// Total and branch-free: no division by zero near 0 (a polynomial there), and 0 for NaN, ±∞
/// and `|x| ≥ 2²²` (where every `f32` is a multiple of ½, so the true value is 0 or below
/// `1/(π·2²²) < 10⁻⁷` in magnitude). The argument is reduced exactly to `x = n + r`, `|r| ≤ ½`,
/// so the result stays accurate near the zeros: within `4·10⁻⁷` relative or `10⁻⁷` absolute of
/// the true value.
///
/// ```
/// use nyquist::filter::sinc;
/// assert_eq!(sinc(0.0), 1.0);
/// assert_eq!(sinc(3.0), 0.0);
/// assert!((sinc(0.5) - 2.0 / core::f32::consts::PI).abs() < 1e-7);
/// assert_eq!(sinc(f32::NAN), 0.0);
/// ```
#[inline]
pub fn sinc(x: f32) -> f32 {
    let ax = x.abs();
    let in_range = ax < 4_194_304.0; // false for NaN and ±∞ too
    let a = if in_range { ax } else { 0.0 };
    // n = round(a) (ties to even) from the mantissa of a + 1.5·2²³; r = a − n is exact.
    let m = a + 12_582_912.0;
    let n = m.to_bits().wrapping_sub(0x4B40_0000);
    let r = a - (m - 12_582_912.0);
    // sin(π(n + r)) = (−1)ⁿ sin(πr) = (−1)ⁿ πr·sinc(r), and πr/(π·a) = r/a; for n = 0 the
    // polynomial alone is the answer (no 0/0).
    let p = sinc_reduced(r);
    let zero = n == 0;
    let s = if zero { 1.0 } else { r } * p / if zero { 1.0 } else { a };
    let s = f32::from_bits(s.to_bits() ^ ((n & 1) << 31));
    if in_range { s } else { 0.0 }
}

/// `sin(πx)/(πx)` in `f64` (for the numeric integral).
fn sinc_f64(x: f64) -> f64 {
    let px = core::f64::consts::PI * x;
    if px.abs() < 1e-4 {
        1.0 - px * px / 6.0
    } else {
        math::sin(px) / px
    }
}

/// Positive nodes and weights of the 8-point Gauss–Legendre rule on `[−1, 1]`, found by Newton's
/// method on the Legendre polynomial `P₈` (no stored table).
fn gauss_legendre_8() -> [(f64, f64); 4] {
    const N: usize = 8;
    let mut out = [(0.0, 0.0); 4];
    for (i, slot) in out.iter_mut().enumerate() {
        let mut x = math::cos(core::f64::consts::PI * (i as f64 + 0.75) / (N as f64 + 0.5));
        let mut dp = 1.0;
        for _ in 0..100 {
            // P_N(x) and P_{N−1}(x) by the three-term recurrence.
            let (mut p0, mut p1) = (1.0f64, x);
            for k in 1..N {
                let k = k as f64;
                let p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
                p0 = p1;
                p1 = p2;
            }
            dp = N as f64 * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() < 1e-15 {
                break;
            }
        }
        *slot = (x, 2.0 / ((1.0 - x * x) * dp * dp));
    }
    out
}

/// The Lanczos filter (Duchon 1979): the sinc windowed by a wider sinc, per axis
/// `sinc(x)·sinc(x/τ)` for `|x| ≤ r`, 0 beyond; the 2D weight is the product. Defaults:
/// radius 4, `τ = 3`. Sharp, with negative lobes (ringing).
///
/// ```
/// use nyquist::filter::{Filter, Lanczos};
/// let l = Lanczos::default();
/// assert_eq!(l.eval(0.0, 0.0), 1.0);
/// assert_eq!(l.eval(1.0, 0.0), 0.0); // a zero of sinc(x)
/// assert!(l.eval(1.5, 0.0) < 0.0); // a negative lobe
/// assert!((l.integral() - 1.0238348420).abs() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lanczos {
    radius: [f32; 2],
    tau: f32,
    inv_tau: f32,
}

impl Lanczos {
    /// A Lanczos filter of half-widths `[rx, ry]` and window scale `tau`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] / [`Error::OutOfRange`] naming `"rx"`, `"ry"` or `"tau"`: each
    /// radius must be in [`MIN_RADIUS`](super::MIN_RADIUS)`..=`[`MAX_RADIUS`](super::MAX_RADIUS)
    /// and `tau` finite and `> 0` (at least `f32::MIN_POSITIVE`).
    ///
    /// ```
    /// use nyquist::{filter::Lanczos, Error};
    /// assert!(Lanczos::new([3.0, 3.0], 3.0).is_ok());
    /// let e = Lanczos::new([3.0, 3.0], -1.0).unwrap_err();
    /// assert!(matches!(e, Error::OutOfRange { what: "tau", value: -1.0, .. }));
    /// assert_eq!(e.to_string(), "tau -1 is outside [1.1754944e-38, 3.4028235e38]");
    /// ```
    pub fn new(radius: [f32; 2], tau: f32) -> Result<Lanczos, Error> {
        let tau = check(tau, "tau", f32::MIN_POSITIVE, f32::MAX)?;
        Ok(Lanczos {
            radius: check_radius(radius)?,
            tau,
            // ∞ for subnormal-ish τ: sinc(x·∞) is then 0 (or NaN → 0 at x = 0, masked below).
            inv_tau: 1.0 / tau,
        })
    }

    /// The window scale τ.
    ///
    /// ```
    /// assert_eq!(nyquist::filter::Lanczos::default().tau(), 3.0);
    /// ```
    pub fn tau(&self) -> f32 {
        self.tau
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn axis(&self, i: usize, x: f32) -> f32 {
        // x·(1/τ) at x = 0 and 1/τ = ∞ is NaN, and sinc(NaN) = 0: keep the window's 1 there.
        let w = sinc(x * self.inv_tau);
        let w = if x == 0.0 { 1.0 } else { w };
        let v = sinc(x) * w;
        // Select rather than branch: offsets past the radius are common in a film.
        if x.abs() <= self.radius[i] { v } else { 0.0 }
    }

    /// `∫_{−r}^{r} sinc(x)·sinc(x/τ) dx`: 8-point Gauss–Legendre on segments of width at most
    /// `min(½, τ/2)` (at most 4096 of them), in `f64`.
    fn axis_integral(r: f64, tau: f64) -> f64 {
        let nodes = gauss_legendre_8();
        let width = (0.5f64).min(tau / 2.0).max(r / 4096.0);
        let segments = math::ceil(r / width).clamp(1.0, 4096.0) as u32;
        let h = r / f64::from(segments);
        let mut sum = 0.0;
        for s in 0..segments {
            let mid = (f64::from(s) + 0.5) * h;
            for &(x, w) in &nodes {
                for x in [mid - x * h / 2.0, mid + x * h / 2.0] {
                    sum += w * sinc_f64(x) * sinc_f64(x / tau);
                }
            }
        }
        // Half-width h/2 per segment, and the integrand is even: × 2.
        sum * h
    }
}

impl Default for Lanczos {
    /// Radius 4, `τ = 3`.
    fn default() -> Lanczos {
        Lanczos {
            radius: [4.0, 4.0],
            tau: 3.0,
            inv_tau: 1.0 / 3.0,
        }
    }
}

impl Filter for Lanczos {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        self.axis(0, x) * self.axis(1, y)
    }
    /// No closed form: Gauss–Legendre quadrature per axis in `f64` (relative error < 10⁻¹²
    /// for `τ ≥ 1`), multiplied.
    fn integral(&self) -> f32 {
        let tau = f64::from(self.tau);
        let ix = Self::axis_integral(f64::from(self.radius[0]), tau);
        let iy = Self::axis_integral(f64::from(self.radius[1]), tau);
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
