//! Analytic test scenes for `nyquist render` and `nyquist compare`, with exact references where a
//! closed form exists.
//!
//! - `zoneplate`: L(x, y) = ½ + ½·cos(π r² / W), r the distance in pixels from the image centre
//!   (W/2, H/2), W the image width (DESIGN.md). Its local frequency r/W cycles per pixel reaches the
//!   Nyquist limit at the edge midpoints. The box-filtered pixel integral has a closed form through
//!   the Fresnel integrals: the integrand factors as e^{iπu²/W}·e^{iπv²/W}.

// The scene module is prework for the render/compare commands; only the reference is used yet.
#![allow(dead_code)]

/// The zone plate's radiance at film position `(x, y)` (pixels) for a `width × height` image.
pub fn zoneplate(x: f64, y: f64, width: f64, height: f64) -> f64 {
    let (dx, dy) = (x - 0.5 * width, y - 0.5 * height);
    0.5 + 0.5 * (std::f64::consts::PI * (dx * dx + dy * dy) / width).cos()
}

/// The Fresnel integrals `(C(t), S(t))` = (∫₀ᵗ cos(πs²/2) ds, ∫₀ᵗ sin(πs²/2) ds), to about 1e-14.
///
/// Power series for |t| < 1.5; above, the complementary error function's continued fraction
/// (the standard route, e.g. Abramowitz & Stegun 7.3.22 with 7.1.4), evaluated by the modified
/// Lentz method.
pub fn fresnel(t: f64) -> (f64, f64) {
    use std::f64::consts::{FRAC_PI_2, PI};
    let a = t.abs();
    let sign = t.signum();
    if a < 1e-300 {
        return (0.0, 0.0);
    }
    let (c, s) = if a < 1.5 {
        // C = Σ (−1)^n (π/2)^{2n} a^{4n+1} / ((2n)! (4n+1)), S likewise with odd powers.
        let x = FRAC_PI_2 * a * a;
        let (mut c, mut s) = (0.0, 0.0);
        let mut term = a; // (π/2)^k a^{2k+1} / k!, k = 0, 1, 2, …
        let mut k = 0u32;
        loop {
            let contribution = term / f64::from(2 * k + 1);
            let signed = if (k / 2).is_multiple_of(2) {
                contribution
            } else {
                -contribution
            };
            if k.is_multiple_of(2) {
                c += signed
            } else {
                s += signed
            }
            k += 1;
            term *= x / f64::from(k);
            if contribution < 1e-17 * (c.abs() + s.abs()) {
                break;
            }
        }
        (c, s)
    } else {
        // (C + iS)(a) = (1+i)/2 · [1 − e^{iπa²/2} · h], h = erfc-type continued fraction:
        // h = (1 − i)·a·K, K = 1/(b₀ + a₁/(b₁ + a₂/(b₂ + …))), b_k = 1 − iπa² + 4k … (Lentz).
        let pix2 = PI * a * a;
        let tiny = 1e-300;
        let mut b = (1.0, -pix2);
        let mut cc = (1.0 / tiny, 0.0);
        let mut d = cinv(b);
        let mut h = d;
        let mut n = -1.0f64;
        for _ in 0..200 {
            n += 2.0;
            let an = -n * (n + 1.0);
            b.0 += 4.0;
            d = cinv(cadd(cscale(d, an), b));
            cc = cadd(b, cscale(cinv(cc), an));
            let del = cmul(cc, d);
            h = cmul(h, del);
            if (del.0 - 1.0).abs() + del.1.abs() < 1e-16 {
                break;
            }
        }
        h = cmul(h, (a, -a));
        let e = ((0.5 * pix2).cos(), (0.5 * pix2).sin());
        let one_minus = (1.0 - cmul(e, h).0, -cmul(e, h).1);
        let r = cmul((0.5, 0.5), one_minus);
        (r.0, r.1)
    };
    (sign * c, sign * s)
}

fn cadd(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 + b.0, a.1 + b.1)
}
fn cscale(a: (f64, f64), k: f64) -> (f64, f64) {
    (a.0 * k, a.1 * k)
}
fn cmul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}
fn cinv(a: (f64, f64)) -> (f64, f64) {
    let m = a.0 * a.0 + a.1 * a.1;
    (a.0 / m, -a.1 / m)
}

/// ∫ₐᵇ e^{iπu²/W} du as (re, im), through the Fresnel integrals: with s = u·√(2/W),
/// the integral is √(W/2)·[(C + iS)(s_b) − (C + iS)(s_a)].
fn phase_integral(a: f64, b: f64, width: f64) -> (f64, f64) {
    let k = (2.0 / width).sqrt();
    let (ca, sa) = fresnel(a * k);
    let (cb, sb) = fresnel(b * k);
    let scale = (0.5 * width).sqrt();
    (scale * (cb - ca), scale * (sb - sa))
}

/// The exact mean of the zone plate over pixel `(px, py)` (the box-filtered pixel value).
pub fn zoneplate_pixel_mean(px: u32, py: u32, width: u32, height: u32) -> f64 {
    let (w, h) = (f64::from(width), f64::from(height));
    let (x0, y0) = (f64::from(px) - 0.5 * w, f64::from(py) - 0.5 * h);
    let fx = phase_integral(x0, x0 + 1.0, w);
    let fy = phase_integral(y0, y0 + 1.0, w);
    0.5 + 0.5 * cmul(fx, fy).0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent check: the midpoint rule on ∫cos(πs²/2), Richardson-extrapolated to O(h⁴).
    fn fresnel_numeric(t: f64) -> (f64, f64) {
        let (c1, s1) = midpoint(t, 100_000);
        let (c2, s2) = midpoint(t, 200_000);
        ((4.0 * c2 - c1) / 3.0, (4.0 * s2 - s1) / 3.0)
    }

    fn midpoint(t: f64, n: u32) -> (f64, f64) {
        let h = t / f64::from(n);
        let (mut c, mut s) = (0.0, 0.0);
        for i in 0..n {
            let u = (f64::from(i) + 0.5) * h;
            let p = std::f64::consts::FRAC_PI_2 * u * u;
            c += p.cos() * h;
            s += p.sin() * h;
        }
        (c, s)
    }

    #[test]
    fn fresnel_matches_published_values_and_quadrature() {
        // A&S table 7.7 / DLMF: C(1) = 0.7798934003768228, S(1) = 0.4382591473903548,
        // C(∞) = S(∞) = ½.
        let (c, s) = fresnel(1.0);
        assert!((c - 0.779_893_400_376_822_8).abs() < 1e-14, "{c}");
        assert!((s - 0.438_259_147_390_354_8).abs() < 1e-14, "{s}");
        let (c, s) = fresnel(1e6);
        assert!((c - 0.5).abs() < 1e-6 && (s - 0.5).abs() < 1e-6);
        for t in [0.1, 0.7, 1.49, 1.51, 2.0, 3.3, 7.9, 15.0] {
            let (c, s) = fresnel(t);
            let (cn, sn) = fresnel_numeric(t);
            assert!(
                (c - cn).abs() < 1e-9 && (s - sn).abs() < 1e-9,
                "t={t}: {c},{s} vs {cn},{sn}"
            );
            assert_eq!(fresnel(-t), (-c, -s));
        }
    }

    #[test]
    fn zoneplate_pixel_mean_matches_fine_quadrature() {
        let (w, h) = (64u32, 48u32);
        for (px, py) in [(0, 0), (31, 23), (32, 24), (63, 47), (10, 40)] {
            let n = 400;
            let mut sum = 0.0;
            for j in 0..n {
                for i in 0..n {
                    let x = f64::from(px) + (f64::from(i) + 0.5) / f64::from(n);
                    let y = f64::from(py) + (f64::from(j) + 0.5) / f64::from(n);
                    sum += zoneplate(x, y, f64::from(w), f64::from(h));
                }
            }
            let numeric = sum / f64::from(n * n);
            let exact = zoneplate_pixel_mean(px, py, w, h);
            assert!(
                (exact - numeric).abs() < 1e-5,
                "({px},{py}): {exact} vs {numeric}"
            );
        }
    }
}
