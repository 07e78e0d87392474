//! Analytic test scenes for `nyquist render` and `nyquist compare`, with exact references where a
//! closed form exists.
//!
//! - `zoneplate`: L(x, y) = ½ + ½·cos(π r² / W), r the distance in pixels from the image centre
//!   (W/2, H/2), W the image width (docs/cli.md, "Scenes"). Its local frequency r/W cycles per pixel reaches the
//!   Nyquist limit at the edge midpoints. The box-filtered pixel integral has a closed form through
//!   the Fresnel integrals: the integrand factors as e^{iπu²/W}·e^{iπv²/W}.

//! - `checkerboard`: Tom Duff's classic: an infinite checkered ground plane seen in perspective,
//!   receding to the horizon. Above the horizon the sky is ½, the mean of the checks, so the
//!   far field (where every pixel covers many checks) averages to ½ on both sides.
//! - `disk`: a hard-edged white disk on black (jaggies along every edge direction).
//! - `edge`: a half plane whose edge is tilted 8° from vertical (the staircase of jaggies).
//! - `stripes`: vertical black and white stripes moving sideways during the shutter interval,
//!   faster further down the image (0 at the top, two stripe periods per shutter at the
//!   bottom): the time sample turns motion into blur, a fixed time freezes it (the
//!   wagon-wheel effect).

/// The built-in scenes of `render` and `compare`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Scene {
    /// ½ + ½·cos(π r²/W): rings whose frequency reaches Nyquist at the edge midpoints.
    Zoneplate,
    /// An infinite checkered ground plane in perspective, receding to the horizon.
    Checkerboard,
    /// A hard-edged disk.
    Disk,
    /// A hard edge tilted 8° from vertical.
    Edge,
    /// Stripes moving during the shutter (uses the time sample): motion blur vs strobing.
    #[cfg_attr(feature = "clap", value(alias = "moving-stripes"))]
    Stripes,
    /// A disk of area ½ centred in every pixel: every pixel integrates the same function of its
    /// image sample, so the error image shows how the sampler lays its errors out across
    /// pixels (blue noise or white); exact pixel means ½.
    Dots,
}

impl Scene {
    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            Scene::Zoneplate => "zoneplate",
            Scene::Checkerboard => "checkerboard",
            Scene::Disk => "disk",
            Scene::Edge => "edge",
            Scene::Stripes => "stripes",
            Scene::Dots => "dots",
        }
    }

    /// Whether the scene reads the time sample.
    pub fn uses_time(self) -> bool {
        self == Scene::Stripes
    }

    /// The radiance at film position `(x, y)` (pixels) and shutter time `t ∈ [0, 1)` for a
    /// `width × height` image.
    #[inline]
    pub fn eval(self, x: f64, y: f64, t: f64, width: f64, height: f64) -> f64 {
        match self {
            Scene::Zoneplate => zoneplate(x, y, width, height),
            Scene::Checkerboard => checkerboard(x, y, width, height),
            Scene::Disk => {
                // Off-centre by a fraction of a pixel so no symmetry lines up with the grid.
                let (cx, cy) = (0.5 * width + 0.123, 0.5 * height + 0.057);
                let r = 0.375 * width.min(height);
                let (dx, dy) = (x - cx, y - cy);
                if dx * dx + dy * dy <= r * r { 1.0 } else { 0.0 }
            }
            Scene::Edge => {
                // White left of a line through the centre, tilted 8° from vertical.
                let (cx, cy) = (0.5 * width, 0.5 * height);
                let tan = 0.140_540_834_702_391_4; // tan(8°)
                if x - cx < tan * (y - cy) { 1.0 } else { 0.0 }
            }
            Scene::Stripes => {
                let period = (width / 16.0).max(2.0);
                let speed = 2.0 * period * (y / height);
                let u = (x - speed * t) / period;
                if u - u.floor() < 0.5 { 1.0 } else { 0.0 }
            }
            Scene::Dots => {
                let (dx, dy) = (x - x.floor() - 0.5, y - y.floor() - 0.5);
                if dx * dx + dy * dy < DOT_RADIUS2 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }
}

/// The squared radius of [`Scene::Dots`]' disks: `1 / (2π)`, area ½.
const DOT_RADIUS2: f64 = 0.5 / std::f64::consts::PI;

/// What a scene shows at a film position besides its radiance, for the film's extra channels
/// ([`Scene::surface`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Surface {
    /// The surface's reflectance (grey): the pattern a uniform light shows as the radiance.
    pub albedo: f64,
    /// The unit normal in camera space (x right, y up, z forward, so a surface facing the
    /// camera has normal (0, 0, −1)); zero where no surface is hit.
    pub normal: [f64; 3],
    /// Distance along the view axis (camera space z); [`SKY_DEPTH`] where no surface is hit.
    pub depth: f64,
}

/// The depth of the sky (no surface), as renderers write it (Cycles writes 10¹⁰ too): finite,
/// so a film's average stays finite.
pub const SKY_DEPTH: f64 = 1e10;

impl Scene {
    /// The surface at film position `(x, y)` and time `t` of a `width × height` image: every
    /// scene but the checkerboard is a pattern on the plane z = 1 facing the camera, with its
    /// radiance as albedo; the checkerboard's ground is the plane y = −1 seen from the camera's
    /// height, with the sky above the horizon.
    ///
    /// ```
    /// use nyquist_lab::scene::{Scene, SKY_DEPTH};
    /// let s = Scene::Disk.surface(128.0, 128.0, 0.5, 256.0, 256.0);
    /// assert_eq!((s.albedo, s.normal, s.depth), (1.0, [0.0, 0.0, -1.0], 1.0));
    /// let ground = Scene::Checkerboard.surface(128.0, 200.0, 0.5, 256.0, 256.0);
    /// assert_eq!(ground.normal, [0.0, 1.0, 0.0]);
    /// assert!((ground.depth - 128.0 / (200.0 - 0.3 * 256.0)).abs() < 1e-12);
    /// assert_eq!(Scene::Checkerboard.surface(128.0, 10.0, 0.5, 256.0, 256.0).depth, SKY_DEPTH);
    /// ```
    pub fn surface(self, x: f64, y: f64, t: f64, width: f64, height: f64) -> Surface {
        let albedo = self.eval(x, y, t, width, height);
        if self == Scene::Checkerboard {
            let sy = (y - 0.3 * height) / (0.5 * width);
            return if sy > 0.0 {
                Surface {
                    albedo,
                    normal: [0.0, 1.0, 0.0],
                    depth: 1.0 / sy,
                }
            } else {
                Surface {
                    albedo,
                    normal: [0.0; 3],
                    depth: SKY_DEPTH,
                }
            };
        }
        Surface {
            albedo,
            normal: [0.0, 0.0, -1.0],
            depth: 1.0,
        }
    }
}

/// The checkerboard: a camera 1 unit above the plane, looking level, focal length W/2 pixels
/// (90° horizontal field of view), horizon at 30 % of the height; checks of side ¼ unit.
fn checkerboard(x: f64, y: f64, width: f64, height: f64) -> f64 {
    let f = 0.5 * width;
    let horizon = 0.3 * height;
    let sy = (y - horizon) / f;
    if !(sy > 0.0) {
        return 0.5;
    }
    let depth = 1.0 / sy;
    let side = (x - 0.5 * width) / f * depth;
    let (i, j) = ((side * 4.0).floor(), (depth * 4.0).floor());
    // Far beyond 2⁵³ the parity of a float is meaningless; the pixel there averages to ½ anyway.
    if !(i.abs() < 9e15 && j.abs() < 9e15) {
        return 0.5;
    }
    if (i as i64 + j as i64).rem_euclid(2) == 0 {
        1.0
    } else {
        0.0
    }
}

/// The zone plate's radiance at film position `(x, y)` (pixels) for a `width × height` image.
pub fn zoneplate(x: f64, y: f64, width: f64, height: f64) -> f64 {
    let (dx, dy) = (x - 0.5 * width, y - 0.5 * height);
    0.5 + 0.5 * libm::cos(std::f64::consts::PI * (dx * dx + dy * dy) / width)
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
        let e = (libm::cos(0.5 * pix2), libm::sin(0.5 * pix2));
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

/// The exact box-filtered zone plate: every pixel's mean, row-major, through one Fresnel
/// integral per column and per row.
pub fn zoneplate_reference(width: u32, height: u32) -> Vec<f64> {
    let w = f64::from(width);
    let fx: Vec<_> = (0..width)
        .map(|px| {
            let x0 = f64::from(px) - 0.5 * w;
            phase_integral(x0, x0 + 1.0, w)
        })
        .collect();
    let mut out = Vec::with_capacity(width as usize * height as usize);
    for py in 0..height {
        let y0 = f64::from(py) - 0.5 * f64::from(height);
        let fy = phase_integral(y0, y0 + 1.0, w);
        out.extend(fx.iter().map(|&f| 0.5 + 0.5 * cmul(f, fy).0));
    }
    out
}

/// The zone plate as a film with a separable filter converges to, pixel by pixel: the
/// filter-weighted mean ∫f·L / ∫f over the filter's footprint clipped to the image (the film only
/// receives samples inside it). The zone plate is ½ + ½·Re(e^{iπu²/W}·e^{iπv²/W}), so with
/// f(x, y) = f_x(x)·f_y(y) the 2D integrals are products of 1D ones, each taken by the midpoint
/// rule with 256 nodes per pixel. `None` for a filter without a separable form.
pub fn zoneplate_filtered_reference(
    width: u32,
    height: u32,
    filter: &dyn nyquist::filter::Filter,
) -> Option<Vec<f64>> {
    use nyquist::filter::Axis;
    let w = f64::from(width);
    let [rx, ry] = filter.radius();
    // One axis: (∫ f(u − c)·e^{iπ(u − mid)²/W} du, ∫ f(u − c) du) per pixel, u over the image.
    let axis = |n: u32, r: f32, ax: Axis| -> Option<Vec<((f64, f64), f64)>> {
        let (len, r) = (f64::from(n), f64::from(r));
        let mut out = Vec::with_capacity(n as usize);
        for p in 0..n {
            let c = f64::from(p) + 0.5;
            let (a, b) = ((c - r).max(0.0), (c + r).min(len));
            let cells = (((b - a) * 256.0).ceil() as usize).max(1);
            let h = (b - a) / cells as f64;
            let (mut re, mut im, mut norm) = (0.0, 0.0, 0.0);
            for k in 0..cells {
                let u = a + (k as f64 + 0.5) * h;
                let f = f64::from(filter.eval_1d(ax, (u - c) as f32)?);
                let d = u - 0.5 * len;
                let phase = std::f64::consts::PI * d * d / w;
                re += f * libm::cos(phase);
                im += f * libm::sin(phase);
                norm += f;
            }
            out.push(((re * h, im * h), norm * h));
        }
        Some(out)
    };
    let gx = axis(width, rx, Axis::X)?;
    let gy = axis(height, ry, Axis::Y)?;
    let mut out = Vec::with_capacity(width as usize * height as usize);
    for &(fy, ny) in &gy {
        out.extend(gx.iter().map(|&(fx, nx)| {
            let norm = nx * ny;
            if norm > 0.0 {
                0.5 + 0.5 * cmul(fx, fy).0 / norm
            } else {
                0.0
            }
        }));
    }
    Some(out)
}

/// The exact mean of the zone plate over pixel `(px, py)` (the box-filtered pixel value).
#[cfg(test)]
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
            c += libm::cos(p) * h;
            s += libm::sin(p) * h;
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
    fn reference_table_matches_pixel_means() {
        let (w, h) = (20u32, 12u32);
        let r = zoneplate_reference(w, h);
        for (py, px) in [(0, 0), (5, 7), (11, 19)] {
            let want = zoneplate_pixel_mean(px, py, w, h);
            assert!((r[(py * w + px) as usize] - want).abs() < 1e-15);
        }
    }

    #[test]
    fn filtered_reference_with_a_box_is_the_fresnel_reference() {
        let (w, h) = (24u32, 16u32);
        let exact = zoneplate_reference(w, h);
        let boxed = nyquist::filter::FilterKind::parse("box").unwrap();
        let quad = zoneplate_filtered_reference(w, h, boxed.as_dyn()).unwrap();
        for (a, b) in exact.iter().zip(&quad) {
            assert!((a - b).abs() < 1e-5, "{a} vs {b}");
        }
        // A wider filter blurs: the corner rings (above Nyquist) lose contrast.
        let m = nyquist::filter::FilterKind::parse("mitchell").unwrap();
        let blurred = zoneplate_filtered_reference(w, h, m.as_dyn()).unwrap();
        let spread = |v: &[f64]| {
            let corner: Vec<f64> = (0..4)
                .map(|k| v[(h as usize - 1 - k) * w as usize + w as usize - 1])
                .collect();
            corner.iter().cloned().fold(f64::MIN, f64::max)
                - corner.iter().cloned().fold(f64::MAX, f64::min)
        };
        assert!(spread(&blurred) < spread(&quad));
    }

    #[test]
    fn scenes_are_binary_or_in_unit_range() {
        for s in [
            Scene::Checkerboard,
            Scene::Disk,
            Scene::Edge,
            Scene::Stripes,
            Scene::Dots,
        ] {
            for k in 0..500 {
                let (x, y, t) = (k as f64 * 0.37 % 64.0, k as f64 * 0.71 % 48.0, 0.3);
                let v = s.eval(x, y, t, 64.0, 48.0);
                assert!(v == 0.0 || v == 1.0 || v == 0.5, "{s:?} {v}");
            }
        }
        // Sky and centre of the disk.
        assert_eq!(Scene::Checkerboard.eval(10.0, 1.0, 0.0, 64.0, 48.0), 0.5);
        assert_eq!(Scene::Disk.eval(32.0, 24.0, 0.0, 64.0, 48.0), 1.0);
        assert_eq!(Scene::Disk.eval(0.5, 0.5, 0.0, 64.0, 48.0), 0.0);
        // Stripes: the top row does not move, the bottom row moves.
        let top = |t| Scene::Stripes.eval(1.0, 0.0, t, 64.0, 48.0);
        assert_eq!(top(0.0), top(0.9));
        // Dots: a pixel's centre is inside, its corners outside, in every pixel.
        assert_eq!(Scene::Dots.eval(7.5, 3.5, 0.0, 64.0, 48.0), 1.0);
        assert_eq!(Scene::Dots.eval(7.01, 3.01, 0.0, 64.0, 48.0), 0.0);
        assert_eq!(Scene::Dots.eval(7.5 + 0.398, 3.5, 0.0, 64.0, 48.0), 1.0);
        assert_eq!(Scene::Dots.eval(7.5 + 0.399, 3.5, 0.0, 64.0, 48.0), 0.0);
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
