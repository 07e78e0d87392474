//! The peer the speed targets are quoted against: pbrt-v3's film-side filter code (Pharr,
//! Jakob, Humphreys, *Physically Based Rendering*, 3rd ed., §7.8–7.9; `src/core/film.{h,cpp}`,
//! `src/filters/{mitchell,sinc}.h`), re-implemented here from the book's algorithms so the
//! benches can run it beside ours in the same process and report ratios that a noisy machine
//! does not move. Not pbrt's code, and not a drop-in: only what the benches time.
//!
//! What it does, as pbrt-v3 does it:
//! - filters evaluated through a virtual call (`dyn PbrtFilter`), Mitchell as the product of
//!   two cubics in `|2x/r|`, Lanczos as `sinc(x)·sinc(x/τ)` with `f32` `sin`;
//! - a 16 × 16 `f32` table over the first quadrant, entry `(x, y)` holding
//!   `f((x + ½)·rx/16, (y + ½)·ry/16)`, read with the nearest-lower index
//!   `min(⌊|d|/r·16⌋, 15)` per footprint column and row;
//! - `FilmTile::AddSample`: the luminance clamp test, the footprint `⌈p − ½ − r⌉ … ⌊p − ½ + r⌋`
//!   clipped to the tile, the column and row indices, then `f32` sums
//!   `contribSum += L·(w·f)`, `filterWeightSum += f` per pixel.
#![allow(dead_code)]

use nyquist::filter::Filter;

/// pbrt-v3's `Filter::Evaluate`, called through `dyn` as pbrt calls it.
pub trait PbrtFilter {
    /// The filter at offset `p` from the sample.
    fn evaluate(&self, p: [f32; 2]) -> f32;
}

/// pbrt-v3's `MitchellFilter`: radius `r`, parameters `B`, `C`.
pub struct PbrtMitchell {
    pub inv_radius: [f32; 2],
    pub b: f32,
    pub c: f32,
}

impl PbrtMitchell {
    /// Mitchell–Netravali with `B = C = ⅓` and radius 2, this crate's default.
    pub fn new() -> PbrtMitchell {
        PbrtMitchell {
            inv_radius: [0.5, 0.5],
            b: 1.0 / 3.0,
            c: 1.0 / 3.0,
        }
    }

    /// The cubic in `|2x|` (x already divided by the radius).
    fn mitchell_1d(&self, x: f32) -> f32 {
        let (b, c) = (self.b, self.c);
        let x = (2.0 * x).abs();
        if x > 1.0 {
            ((-b - 6.0 * c) * x * x * x
                + (6.0 * b + 30.0 * c) * x * x
                + (-12.0 * b - 48.0 * c) * x
                + (8.0 * b + 24.0 * c))
                * (1.0 / 6.0)
        } else {
            ((12.0 - 9.0 * b - 6.0 * c) * x * x * x
                + (-18.0 + 12.0 * b + 6.0 * c) * x * x
                + (6.0 - 2.0 * b))
                * (1.0 / 6.0)
        }
    }
}

impl PbrtFilter for PbrtMitchell {
    fn evaluate(&self, p: [f32; 2]) -> f32 {
        self.mitchell_1d(p[0] * self.inv_radius[0]) * self.mitchell_1d(p[1] * self.inv_radius[1])
    }
}

/// pbrt-v3's `LanczosSincFilter`: radius `r`, `τ` lobes.
pub struct PbrtLanczos {
    pub radius: [f32; 2],
    pub tau: f32,
}

impl PbrtLanczos {
    /// Radius 4, τ = 3, this crate's default.
    pub fn new() -> PbrtLanczos {
        PbrtLanczos {
            radius: [4.0, 4.0],
            tau: 3.0,
        }
    }

    fn sinc(x: f32) -> f32 {
        let x = x.abs();
        if x < 1e-5 {
            return 1.0;
        }
        let px = std::f32::consts::PI * x;
        px.sin() / px
    }

    fn windowed_sinc(&self, x: f32, radius: f32) -> f32 {
        let x = x.abs();
        if x > radius {
            return 0.0;
        }
        Self::sinc(x) * Self::sinc(x / self.tau)
    }
}

impl PbrtFilter for PbrtLanczos {
    fn evaluate(&self, p: [f32; 2]) -> f32 {
        self.windowed_sinc(p[0], self.radius[0]) * self.windowed_sinc(p[1], self.radius[1])
    }
}

/// pbrt-v3's table width.
pub const WIDTH: usize = 16;

/// pbrt-v3's film filter table: 16 × 16 `f32` over the first quadrant.
pub struct PbrtTable {
    pub radius: [f32; 2],
    pub inv_radius: [f32; 2],
    pub values: [f32; WIDTH * WIDTH],
}

impl PbrtTable {
    /// Tabulates `filter` at the cell centres `((x + ½)·rx/16, (y + ½)·ry/16)`.
    pub fn new(filter: &dyn Filter) -> PbrtTable {
        let radius = filter.radius();
        let mut values = [0.0f32; WIDTH * WIDTH];
        for y in 0..WIDTH {
            for x in 0..WIDTH {
                let px = (x as f32 + 0.5) * radius[0] / WIDTH as f32;
                let py = (y as f32 + 0.5) * radius[1] / WIDTH as f32;
                values[y * WIDTH + x] = filter.eval(px, py);
            }
        }
        PbrtTable {
            radius,
            inv_radius: [1.0 / radius[0], 1.0 / radius[1]],
            values,
        }
    }

    /// The table index of offset `d` along axis `a`: `min(⌊|d|/r·16⌋, 15)`.
    #[inline(always)]
    fn index(&self, a: usize, d: f32) -> usize {
        ((d * self.inv_radius[a] * WIDTH as f32).abs().floor() as usize).min(WIDTH - 1)
    }

    /// The weights of the `nx`-wide footprint whose first pixel is at offset `d0` from the
    /// sample, as `AddSample` reads them: one index per column and row, one table read per
    /// pixel. (Our tables' `footprint` fills the same buffer.)
    #[inline(always)]
    pub fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) {
        let mut ifx = [0usize; 32];
        for (i, f) in ifx.iter_mut().take(nx).enumerate() {
            *f = self.index(0, d0[0] + i as f32);
        }
        for (j, row) in out.chunks_exact_mut(nx).enumerate() {
            let iy = self.index(1, d0[1] + j as f32) * WIDTH;
            for (w, &ix) in row.iter_mut().zip(&ifx) {
                *w = self.values[iy + ix];
            }
        }
    }
}

/// The widest footprint [`PbrtTile`] handles per axis (radius below 32).
pub const MAX_SPAN: usize = 64;

/// pbrt-v3's `FilmTilePixel`: `f32` sums.
#[derive(Clone, Copy, Default)]
pub struct PbrtPixel {
    pub contrib_sum: [f32; 3],
    pub filter_weight_sum: f32,
}

/// pbrt-v3's `FilmTile` over pixels `[x0, x1) × [y0, y1)`.
pub struct PbrtTile {
    pub bounds: [i32; 4],
    pub table: PbrtTable,
    pub max_sample_luminance: f32,
    pub pixels: Vec<PbrtPixel>,
}

impl PbrtTile {
    /// A tile for the pixels `[x0, x1) × [y0, y1)` (already grown by the filter radius and
    /// clipped to the film, as pbrt's `Film::GetFilmTile` makes them) with no luminance clamp.
    /// Footprints are capped at [`MAX_SPAN`] pixels per axis.
    pub fn new(filter: &dyn Filter, bounds: [i32; 4]) -> PbrtTile {
        let area = ((bounds[2] - bounds[0]) * (bounds[3] - bounds[1])).max(0) as usize;
        PbrtTile {
            bounds,
            table: PbrtTable::new(filter),
            max_sample_luminance: f32::INFINITY,
            pixels: vec![PbrtPixel::default(); area],
        }
    }

    /// `FilmTile::AddSample(pFilm, L, sampleWeight)`.
    #[inline(never)]
    pub fn add_sample(&mut self, p_film: [f32; 2], l: [f32; 3], sample_weight: f32) {
        let mut l = l;
        // sRGB luminance, as pbrt-v3's RGBSpectrum::y().
        let y = 0.212671 * l[0] + 0.715160 * l[1] + 0.072169 * l[2];
        if y > self.max_sample_luminance {
            let s = self.max_sample_luminance / y;
            l = l.map(|c| c * s);
        }
        let [bx0, by0, bx1, by1] = self.bounds;
        let r = self.table.radius;
        let d = [p_film[0] - 0.5, p_film[1] - 0.5];
        let x0 = ((d[0] - r[0]).ceil() as i32).max(bx0);
        let y0 = ((d[1] - r[1]).ceil() as i32).max(by0);
        // Saturating, and capped at MAX_SPAN pixels so the index buffers below always hold
        // the footprint (pbrt sizes them per sample with ALLOCA).
        let x1 = ((d[0] + r[0]).floor() as i32).saturating_add(1).min(bx1);
        let y1 = ((d[1] + r[1]).floor() as i32).saturating_add(1).min(by1);
        let x1 = x1.min(x0.saturating_add(MAX_SPAN as i32));
        let y1 = y1.min(y0.saturating_add(MAX_SPAN as i32));
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let mut ifx = [0usize; MAX_SPAN];
        let mut ify = [0usize; MAX_SPAN];
        for (x, i) in (x0..x1).zip(ifx.iter_mut()) {
            *i = self.table.index(0, x as f32 - d[0]);
        }
        for (y, i) in (y0..y1).zip(ify.iter_mut()) {
            *i = self.table.index(1, y as f32 - d[1]);
        }
        let width = (bx1 - bx0) as usize;
        for y in y0..y1 {
            for x in x0..x1 {
                let offset = ify[(y - y0) as usize] * WIDTH + ifx[(x - x0) as usize];
                let filter_weight = self.table.values[offset];
                let pixel = &mut self.pixels[(x - bx0) as usize + (y - by0) as usize * width];
                let weight = sample_weight * filter_weight;
                for c in 0..3 {
                    pixel.contrib_sum[c] += l[c] * weight;
                }
                pixel.filter_weight_sum += filter_weight;
            }
        }
    }
}
