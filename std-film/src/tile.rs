//! Film tiles: owned by one thread, filled with samples, merged back into the film.

use crate::Bounds;
use crate::film::{FilmStats, Setup, TileSpec};
use std::sync::Arc;

/// Accumulated sums of one pixel: Σ f·w·L per channel and Σ f, in `f64`.
///
/// ```
/// let p = nyquist_film::Pixel::default();
/// assert_eq!(p.weight_sum, 0.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pixel {
    /// Σ filter weight × sample weight × radiance, per RGB channel.
    pub rgb_sum: [f64; 3],
    /// Σ filter weight.
    pub weight_sum: f64,
}

impl Pixel {
    pub(crate) fn add(&mut self, o: &Pixel) {
        for c in 0..3 {
            self.rgb_sum[c] += o.rgb_sum[c];
        }
        self.weight_sum += o.weight_sum;
    }
}

/// Footprints up to this many pixels per axis use stack buffers of per-axis weights.
const MAX_AXIS: usize = 32;

/// One thread's part of a [`crate::Film`]: the pixels that samples inside its bounds can reach.
///
/// Created by [`crate::Film::tile`], filled with [`FilmTile::add_sample`], handed back with
/// [`crate::Film::merge`]. NaN or infinite radiance or weight is dropped and counted, never added.
#[derive(Debug)]
pub struct FilmTile {
    spec: TileSpec,
    pixel_bounds: Bounds,
    pixels: Vec<Pixel>,
    splats: Vec<[f64; 3]>,
    setup: Arc<Setup>,
    stats: FilmStats,
}

impl FilmTile {
    pub(crate) fn new(spec: TileSpec, setup: Arc<Setup>) -> FilmTile {
        let [rx, ry] = setup.weights.radius();
        let b = spec.bounds;
        let grown = Bounds::new(
            (b.x0 as f64 - 0.5 - f64::from(rx)).ceil() as i64,
            (b.y0 as f64 - 0.5 - f64::from(ry)).ceil() as i64,
            (b.x1 as f64 - 0.5 + f64::from(rx)).floor() as i64 + 1,
            (b.y1 as f64 - 0.5 + f64::from(ry)).floor() as i64 + 1,
        );
        let fb = setup.pixel_bounds;
        let mut pixel_bounds = grown.intersect(&fb);
        if pixel_bounds.is_empty() || b.is_empty() {
            // Nothing to store: an empty rectangle at the film's corner keeps merges trivial.
            pixel_bounds = Bounds::new(fb.x0, fb.y0, fb.x0, fb.y0);
        }
        let n = pixel_bounds.area() as usize;
        FilmTile {
            spec,
            pixel_bounds,
            pixels: vec![Pixel::default(); n],
            splats: vec![[0.0; 3]; n],
            setup,
            stats: FilmStats::default(),
        }
    }

    /// The tile's place in the merge order.
    pub fn index(&self) -> usize {
        self.spec.index
    }

    /// The pixels whose samples this tile takes.
    pub fn bounds(&self) -> Bounds {
        self.spec.bounds
    }

    /// The pixels this tile stores: its bounds grown by the filter radius, clipped to the film.
    pub fn pixel_bounds(&self) -> Bounds {
        self.pixel_bounds
    }

    pub(crate) fn pixels(&self) -> &[Pixel] {
        &self.pixels
    }

    pub(crate) fn splats(&self) -> &[[f64; 3]] {
        &self.splats
    }

    /// Counters of this tile.
    pub fn stats(&self) -> FilmStats {
        self.stats
    }

    /// Samples this tile dropped for NaN or infinite radiance or weight.
    pub fn rejected(&self) -> u64 {
        self.stats.rejected
    }

    /// Adds a sample at film position `p_film` (pixels) with radiance `rgb` and sample weight
    /// `weight`: every stored pixel whose centre is within the filter radius gets
    /// `f(centre − p)·weight·rgb` and `f(centre − p)`. A NaN or infinite component or weight is
    /// dropped and counted ([`FilmTile::rejected`]); with the film's `max_component` set, a
    /// brighter sample is scaled down to it. Pixels outside the tile's pixel bounds are skipped.
    pub fn add_sample(&mut self, p_film: [f32; 2], rgb: [f32; 3], weight: f32) {
        if !(rgb.iter().all(|c| c.is_finite())
            && weight.is_finite()
            && p_film[0].is_finite()
            && p_film[1].is_finite())
        {
            self.stats.rejected += 1;
            return;
        }
        let rgb = self.clamp(rgb);
        self.stats.samples += 1;
        let l = [
            f64::from(rgb[0] * weight),
            f64::from(rgb[1] * weight),
            f64::from(rgb[2] * weight),
        ];
        let Some((x0, x1, y0, y1)) = self.footprint(p_film) else {
            return;
        };
        let (nx, ny) = ((x1 - x0) as usize, (y1 - y0) as usize);
        let weights = &self.setup.weights;
        let b = self.pixel_bounds;
        let stride = b.width() as usize;
        // Offsets from the pixel centres: x + ½ − p.
        let dx0 = (x0 as f64 + 0.5 - f64::from(p_film[0])) as f32;
        let dy0 = (y0 as f64 + 0.5 - f64::from(p_film[1])) as f32;
        if let (true, true, true) = (weights.is_separable(), nx <= MAX_AXIS, ny <= MAX_AXIS) {
            let mut wx = [0.0f32; MAX_AXIS];
            let mut wy = [0.0f32; MAX_AXIS];
            for (i, w) in wx[..nx].iter_mut().enumerate() {
                *w = weights.weight_x(dx0 + i as f32);
            }
            for (j, w) in wy[..ny].iter_mut().enumerate() {
                *w = weights.weight_y(dy0 + j as f32);
            }
            for (j, &fy) in wy[..ny].iter().enumerate() {
                let row = (y0 - b.y0) as usize + j;
                let start = row * stride + (x0 - b.x0) as usize;
                for (p, &fx) in self.pixels[start..start + nx].iter_mut().zip(&wx[..nx]) {
                    let f = f64::from(fx * fy);
                    p.rgb_sum[0] += f * l[0];
                    p.rgb_sum[1] += f * l[1];
                    p.rgb_sum[2] += f * l[2];
                    p.weight_sum += f;
                }
            }
        } else {
            for j in 0..ny {
                let row = (y0 - b.y0) as usize + j;
                let start = row * stride + (x0 - b.x0) as usize;
                let dy = dy0 + j as f32;
                for (i, p) in self.pixels[start..start + nx].iter_mut().enumerate() {
                    let f = f64::from(weights.weight(dx0 + i as f32, dy));
                    p.rgb_sum[0] += f * l[0];
                    p.rgb_sum[1] += f * l[1];
                    p.rgb_sum[2] += f * l[2];
                    p.weight_sum += f;
                }
            }
        }
    }

    /// Adds a splat (pbrt-v4 style, e.g. for light tracing): every reached pixel gets
    /// `f(centre − p)·rgb`, and the film divides splats by the filter integral when it resolves.
    /// Non-finite values are dropped and counted as rejected.
    pub fn add_splat(&mut self, p_film: [f32; 2], rgb: [f32; 3]) {
        if !(rgb.iter().all(|c| c.is_finite()) && p_film[0].is_finite() && p_film[1].is_finite()) {
            self.stats.rejected += 1;
            return;
        }
        let rgb = self.clamp(rgb);
        self.stats.splats += 1;
        let Some((x0, x1, y0, y1)) = self.footprint(p_film) else {
            return;
        };
        let b = self.pixel_bounds;
        let stride = b.width() as usize;
        for y in y0..y1 {
            for x in x0..x1 {
                let dx = (x as f64 + 0.5 - f64::from(p_film[0])) as f32;
                let dy = (y as f64 + 0.5 - f64::from(p_film[1])) as f32;
                let f = f64::from(self.setup.weights.weight(dx, dy));
                let s = &mut self.splats[(y - b.y0) as usize * stride + (x - b.x0) as usize];
                for c in 0..3 {
                    s[c] += f * f64::from(rgb[c]);
                }
            }
        }
    }

    fn clamp(&mut self, rgb: [f32; 3]) -> [f32; 3] {
        match self.setup.max_component {
            Some(m) => {
                let max = rgb[0].max(rgb[1]).max(rgb[2]);
                if max > m {
                    self.stats.clamped += 1;
                    let s = m / max;
                    [rgb[0] * s, rgb[1] * s, rgb[2] * s]
                } else {
                    rgb
                }
            }
            None => rgb,
        }
    }

    /// Pixels `[x0, x1) × [y0, y1)` reached by a sample at `p`, clipped to the stored pixels:
    /// from `⌈p − ½ − r⌉` to `⌊p − ½ + r⌋` per axis. `None` when nothing is reached.
    fn footprint(&self, p: [f32; 2]) -> Option<(i64, i64, i64, i64)> {
        let [rx, ry] = self.setup.weights.radius();
        let b = self.pixel_bounds;
        let (px, py) = (f64::from(p[0]) - 0.5, f64::from(p[1]) - 0.5);
        let x0 = ((px - f64::from(rx)).ceil() as i64).max(b.x0);
        let x1 = ((px + f64::from(rx)).floor() as i64 + 1).min(b.x1);
        let y0 = ((py - f64::from(ry)).ceil() as i64).max(b.y0);
        let y1 = ((py + f64::from(ry)).floor() as i64 + 1).min(b.y1);
        (x0 < x1 && y0 < y1).then_some((x0, x1, y0, y1))
    }
}
