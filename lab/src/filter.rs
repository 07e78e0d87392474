//! A reconstruction filter's 1D profile and the magnitude of its Fourier transform, as the
//! command's filter plot and the explorer draw them.

use nyquist::filter::{Axis, Filter};

/// The 1D profile along x: the separable factor, or `f(x, 0)` for a non-separable filter.
///
/// ```
/// let f = nyquist::filter::FilterKind::parse("triangle:radius=1").unwrap();
/// assert_eq!(nyquist_lab::filter::profile(f.as_dyn(), 0.25), 0.75); // 1 − |x|
/// ```
pub fn profile(f: &dyn Filter, x: f32) -> f64 {
    f64::from(f.eval_1d(Axis::X, x).unwrap_or_else(|| f.eval(x, 0.0)))
}

/// `|F(ν)| = |∫ f(x) e^(−2πiνx) dx|` by the midpoint rule on 4096 cells over [−r, r].
///
/// ```
/// // The box of radius ½: |F(ν)| = |sinc(πν)|, 0 at ν = 1.
/// let f = nyquist::filter::FilterKind::parse("box").unwrap();
/// assert!((nyquist_lab::filter::spectrum(f.as_dyn(), 0.0) - 1.0).abs() < 1e-6);
/// assert!(nyquist_lab::filter::spectrum(f.as_dyn(), 1.0) < 1e-6);
/// ```
pub fn spectrum(f: &dyn Filter, nu: f64) -> f64 {
    const CELLS: u32 = 4096;
    let r = f64::from(f.radius()[0]);
    let h = 2.0 * r / f64::from(CELLS);
    let (mut re, mut im) = (0.0f64, 0.0f64);
    for k in 0..CELLS {
        let x = -r + (f64::from(k) + 0.5) * h;
        let v = profile(f, x as f32);
        let phase = 2.0 * std::f64::consts::PI * nu * x;
        // libm's, as on every target: the browser explorer draws the same curve.
        re += v * libm::cos(phase);
        im -= v * libm::sin(phase);
    }
    libm::hypot(re * h, im * h)
}
