//! Film tiles: owned by one thread, filled with samples, merged back into the film.

use crate::Bounds;
use crate::film::{FilmStats, Setup, TileSpec};
use crate::weights::{Direct, WeightSource};
use nyquist::filter::{Filter, FilterTable};
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

/// Where a tile's samples go: the stored pixel rectangle and the filter radius, cached per tile
/// so the per-sample path reads no shared state but the table.
#[derive(Clone, Copy, Debug)]
struct Geometry {
    /// The stored pixels.
    bounds: Bounds,
    /// Filter radius `[rx, ry]`, widened to `f64` once.
    radius: [f64; 2],
}

/// A footprint: pixels `[x0, x1) × [y0, y1)` and the offsets of their first centre from `p`.
#[derive(Clone, Copy, Debug)]
struct Footprint {
    x0: i64,
    x1: i64,
    y0: i64,
    y1: i64,
    /// The sample position in `f64`; offsets `x + ½ − p` are formed in `f64` and rounded once.
    p: [f64; 2],
}

impl Footprint {
    #[inline(always)]
    fn dx(&self, x: i64) -> f32 {
        (x as f64 + 0.5 - self.p[0]) as f32
    }
    #[inline(always)]
    fn dy(&self, y: i64) -> f32 {
        (y as f64 + 0.5 - self.p[1]) as f32
    }
}

/// `⌊v⌋` for finite `v` within ±2⁶², without a libm call (x86-64's baseline has no `roundsd`).
#[inline(always)]
fn floor_i64(v: f64) -> i64 {
    let t = v as i64;
    t - i64::from(t as f64 > v)
}

/// `⌈v⌉` for finite `v` within ±2⁶².
#[inline(always)]
fn ceil_i64(v: f64) -> i64 {
    let t = v as i64;
    t + i64::from((t as f64) < v)
}

/// Pixels `[a, b)` along one axis reached from the finite position `p`: `⌈p − ½ − r⌉ …
/// ⌊p − ½ + r⌋`, clipped to `[lo, hi)` (empty when `a ≥ b`).
#[inline(always)]
fn span(p: f64, r: f64, lo: i64, hi: i64) -> (i64, i64) {
    let c = p - 0.5;
    // Clamping first keeps the conversions exact for any finite p (even 1e30).
    let (flo, fhi) = ((lo - 1) as f64, (hi + 1) as f64);
    let a = (c - r).max(flo).min(fhi);
    let b = (c + r).max(flo).min(fhi);
    (ceil_i64(a).max(lo), (floor_i64(b) + 1).min(hi))
}

/// Adds `f·l` and `f` to every pixel of the footprint, `f` from `w`. `pixels` is the tile's
/// row-major storage of `g.bounds`. Separable sources take `nx + ny` 1D weights (once per column
/// and row) and an outer product; the others one `xy` per pixel.
#[inline(always)]
fn accumulate<W: WeightSource + ?Sized>(
    pixels: &mut [Pixel],
    g: &Geometry,
    fp: &Footprint,
    l: [f64; 3],
    w: &W,
) {
    let b = g.bounds;
    let stride = b.width() as usize;
    let (nx, ny) = ((fp.x1 - fp.x0) as usize, (fp.y1 - fp.y0) as usize);
    let first = (fp.y0 - b.y0) as usize * stride + (fp.x0 - b.x0) as usize;
    // One bounds check for the whole footprint; every row below is inside it.
    let Some(rows) = pixels.get_mut(first..first + (ny - 1) * stride + nx) else {
        return;
    };
    if w.separable() {
        // Stack buffers sized for the footprint: box (≤ 2), radius ≤ 1.5 (≤ 4), ≤ 3.5 (≤ 8),
        // ≤ 15.5 (≤ 32); wider footprints fall through to the per-pixel path.
        match nx {
            0..=2 => return separable::<2, W>(rows, stride, fp, nx, ny, l, w),
            3..=4 => return separable::<4, W>(rows, stride, fp, nx, ny, l, w),
            5..=8 => return separable::<8, W>(rows, stride, fp, nx, ny, l, w),
            9..=32 => return separable::<32, W>(rows, stride, fp, nx, ny, l, w),
            _ => {}
        }
    }
    for (j, row) in rows.chunks_mut(stride).take(ny).enumerate() {
        let dy = fp.dy(fp.y0 + j as i64);
        for (i, p) in row[..nx].iter_mut().enumerate() {
            let f = if w.separable() {
                f64::from(w.x(fp.dx(fp.x0 + i as i64))) * f64::from(w.y(dy))
            } else {
                f64::from(w.xy(fp.dx(fp.x0 + i as i64), dy))
            };
            p.rgb_sum[0] += f * l[0];
            p.rgb_sum[1] += f * l[1];
            p.rgb_sum[2] += f * l[2];
            p.weight_sum += f;
        }
    }
}

/// The separable path for `nx ≤ M` columns: per column `fx·[l, 1]` in `f64`, then per row
/// `p += fy·column` — the weight is the exact `f64` product `fx·fy` of the two `f32` factors.
#[inline(always)]
fn separable<const M: usize, W: WeightSource + ?Sized>(
    rows: &mut [Pixel],
    stride: usize,
    fp: &Footprint,
    nx: usize,
    ny: usize,
    l: [f64; 3],
    w: &W,
) {
    let mut cols = [[0.0f64; 4]; M];
    for (i, c) in cols[..nx].iter_mut().enumerate() {
        let fx = f64::from(w.x(fp.dx(fp.x0 + i as i64)));
        *c = [fx * l[0], fx * l[1], fx * l[2], fx];
    }
    for (j, row) in rows.chunks_mut(stride).take(ny).enumerate() {
        let fy = f64::from(w.y(fp.dy(fp.y0 + j as i64)));
        for (p, c) in row[..nx].iter_mut().zip(&cols[..nx]) {
            p.rgb_sum[0] += fy * c[0];
            p.rgb_sum[1] += fy * c[1];
            p.rgb_sum[2] += fy * c[2];
            p.weight_sum += fy * c[3];
        }
    }
}

/// One thread's part of a [`crate::Film`]: the pixels that samples inside its bounds can reach.
///
/// Created by [`crate::Film::tile`], filled with [`FilmTile::add_sample`], handed back with
/// [`crate::Film::merge`]. NaN or infinite radiance or weight is dropped and counted, never added.
#[derive(Debug)]
pub struct FilmTile {
    spec: TileSpec,
    geometry: Geometry,
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
            geometry: Geometry {
                bounds: pixel_bounds,
                radius: [f64::from(rx), f64::from(ry)],
            },
            pixels: vec![Pixel::default(); n],
            // Allocated by the first splat: most renderers never splat.
            splats: Vec::new(),
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
        self.geometry.bounds
    }

    pub(crate) fn pixels(&self) -> &[Pixel] {
        &self.pixels
    }

    /// The splat sums, row-major like the pixels, or empty if nothing was splatted.
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
    /// `f(centre − p)·weight·rgb` and `f(centre − p)`, `f` read from the film's filter table
    /// (for a separable filter, one 1D lookup per footprint column and row). A NaN or infinite
    /// component, weight or position is dropped and counted ([`FilmTile::rejected`]); with the
    /// film's `max_component` set, a brighter sample is scaled down to it. Pixels outside the
    /// tile's pixel bounds are skipped.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Triangle::default()).unwrap();
    /// let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    /// tile.add_sample([1.5, 1.5], [1.0, 2.0, 3.0], 0.5);
    /// tile.add_sample([1.5, 1.5], [f32::NAN, 2.0, 3.0], 0.5);
    /// assert_eq!((tile.stats().samples, tile.rejected()), (1, 1));
    /// film.merge(tile).unwrap();
    /// // The triangle (r = 2) at the centre weighs 2·2 = 4.
    /// assert_eq!(film.pixel(1, 1).unwrap().weight_sum, 4.0);
    /// assert_eq!(film.pixel(1, 1).unwrap().rgb_sum, [2.0, 4.0, 6.0]);
    /// ```
    #[inline]
    pub fn add_sample(&mut self, p_film: [f32; 2], rgb: [f32; 3], weight: f32) {
        let Some((fp, l)) = self.prepare(p_film, rgb, weight) else {
            return;
        };
        match self.setup.weights.table() {
            FilterTable::Separable(t) => accumulate(&mut self.pixels, &self.geometry, &fp, l, t),
            FilterTable::Full(t) => accumulate(&mut self.pixels, &self.geometry, &fp, l, t),
        }
    }

    /// [`FilmTile::add_sample`] with `filter` evaluated directly (its `eval_1d` per column and
    /// row when separable, else `eval` per pixel) instead of the film's table: slower, and exact
    /// where the table interpolates. The footprint is the film's (its filter's radius), so
    /// `filter` should be the film's filter. For comparisons and for checking the table.
    ///
    /// ```
    /// use nyquist::filter::{Filter, Mitchell};
    /// use nyquist_film::{Film, FilmConfig};
    /// let m = Mitchell::default();
    /// let mut film = Film::new(FilmConfig::new(4, 4), &m).unwrap();
    /// let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    /// tile.add_sample_direct(&m, [1.2, 1.9], [1.0; 3], 1.0);
    /// film.merge(tile).unwrap();
    /// let want = f64::from(m.eval(2.5 - 1.2, 1.5 - 1.9));
    /// assert!((film.pixel(2, 1).unwrap().weight_sum - want).abs() < 1e-7);
    /// ```
    #[inline]
    pub fn add_sample_direct<F: Filter + ?Sized>(
        &mut self,
        filter: &F,
        p_film: [f32; 2],
        rgb: [f32; 3],
        weight: f32,
    ) {
        let Some((fp, l)) = self.prepare(p_film, rgb, weight) else {
            return;
        };
        let separable = self.setup.weights.table().is_separable() && filter.is_separable();
        let direct = Direct { filter, separable };
        accumulate(&mut self.pixels, &self.geometry, &fp, l, &direct);
    }

    /// Checks, counts and clamps a sample; its footprint and `weight·rgb` in `f64`, or `None`
    /// when it is rejected or reaches no stored pixel.
    #[inline(always)]
    fn prepare(
        &mut self,
        p: [f32; 2],
        rgb: [f32; 3],
        weight: f32,
    ) -> Option<(Footprint, [f64; 3])> {
        if !(rgb[0].is_finite()
            & rgb[1].is_finite()
            & rgb[2].is_finite()
            & weight.is_finite()
            & p[0].is_finite()
            & p[1].is_finite())
        {
            self.stats.rejected += 1;
            return None;
        }
        let rgb = self.clamp(rgb);
        self.stats.samples += 1;
        let l = [
            f64::from(rgb[0] * weight),
            f64::from(rgb[1] * weight),
            f64::from(rgb[2] * weight),
        ];
        let fp = self.footprint(p)?;
        Some((fp, l))
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
        let Some(fp) = self.footprint(p_film) else {
            return;
        };
        let b = self.geometry.bounds;
        let stride = b.width() as usize;
        if self.splats.is_empty() {
            self.splats = vec![[0.0; 3]; self.pixels.len()];
        }
        for y in fp.y0..fp.y1 {
            for x in fp.x0..fp.x1 {
                let f = f64::from(self.setup.weights.weight(fp.dx(x), fp.dy(y)));
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

    /// The pixels reached by a sample at the finite position `p`, clipped to the stored pixels:
    /// `⌈p − ½ − r⌉ … ⌊p − ½ + r⌋` per axis. `None` when nothing is reached.
    #[inline(always)]
    fn footprint(&self, p: [f32; 2]) -> Option<Footprint> {
        let g = &self.geometry;
        let p = [f64::from(p[0]), f64::from(p[1])];
        let (x0, x1) = span(p[0], g.radius[0], g.bounds.x0, g.bounds.x1);
        let (y0, y1) = span(p[1], g.radius[1], g.bounds.y0, g.bounds.y1);
        (x0 < x1 && y0 < y1).then_some(Footprint { x0, x1, y0, y1, p })
    }
}
