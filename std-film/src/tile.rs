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

/// Where a tile's samples go, cached per tile in the forms the per-sample path uses.
#[derive(Clone, Copy, Debug)]
struct Geometry {
    /// The stored pixels.
    bounds: Bounds,
    /// Filter radius `[rx, ry]`.
    radius: [f64; 2],
    /// Centre of the first stored pixel, `(x0 + ½, y0 + ½)`.
    origin: [f64; 2],
    /// Stored columns and rows.
    size: [i64; 2],
    /// `size + 1`, the upper clamp of footprint ends.
    limit: [f64; 2],
}

impl Geometry {
    fn new(bounds: Bounds, radius: [f32; 2]) -> Geometry {
        let size = [bounds.width() as i64, bounds.height() as i64];
        Geometry {
            bounds,
            radius: radius.map(f64::from),
            origin: [bounds.x0 as f64 + 0.5, bounds.y0 as f64 + 0.5],
            size,
            limit: [(size[0] + 1) as f64, (size[1] + 1) as f64],
        }
    }

    /// Stored columns (or rows, `a = 1`) `[i0, i1)` reached from the finite position `p` along
    /// axis `a`, in tile-local indices: film pixels `⌈p − ½ − r⌉ … ⌊p − ½ + r⌋` clipped to the
    /// stored ones (empty when `i0 ≥ i1`), and `c = p − ½ − first`, the sample's local position
    /// (the offset of local pixel `i`'s centre from the sample is `i − c`).
    #[inline(always)]
    fn span(&self, p: f64, a: usize) -> (i64, i64, f64) {
        let c = p - self.origin[a];
        let r = self.radius[a];
        // Clamping first keeps the conversions exact for any finite p (even 1e30).
        let lo = (c - r).max(-1.0).min(self.limit[a]);
        let hi = (c + r).max(-1.0).min(self.limit[a]);
        (
            ceil_i64(lo).max(0),
            (floor_i64(hi) + 1).min(self.size[a]),
            c,
        )
    }
}

/// A footprint in tile-local indices: columns `[x0, x1)`, rows `[y0, y1)`, and the sample's
/// local position `c` (see [`Geometry::span`]).
#[derive(Clone, Copy, Debug)]
struct Footprint {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
    c: [f64; 2],
}

impl Footprint {
    /// Offset from the sample to the centre of local column `i`, formed in `f64` and rounded
    /// once.
    #[inline(always)]
    fn dx(&self, i: usize) -> f32 {
        // i64 → f64 is one instruction (cvtsi2sd); usize → f64 is several.
        (i as i64 as f64 - self.c[0]) as f32
    }
    /// Offset from the sample to the centre of local row `j`.
    #[inline(always)]
    fn dy(&self, j: usize) -> f32 {
        (j as i64 as f64 - self.c[1]) as f32
    }
}

/// `2⁵² + 2⁵¹`: adding it to an `f64` below 2³¹ in magnitude rounds it to an integer held in
/// the low mantissa bits (two's complement in the low 32).
const ROUND_MAGIC: f64 = 6_755_399_441_055_744.0;

/// `⌊v⌋` for `|v| < 2³¹` (the clamped footprint ends), without a libm call or a saturating
/// conversion: round to nearest by [`ROUND_MAGIC`], then step down when that went up.
#[inline(always)]
fn floor_i64(v: f64) -> i64 {
    let m = v + ROUND_MAGIC;
    let r = m - ROUND_MAGIC;
    i64::from(m.to_bits() as u32 as i32) - i64::from(r > v)
}

/// `⌈v⌉` for `|v| < 2³¹`.
#[inline(always)]
fn ceil_i64(v: f64) -> i64 {
    let m = v + ROUND_MAGIC;
    let r = m - ROUND_MAGIC;
    i64::from(m.to_bits() as u32 as i32) + i64::from(r < v)
}

/// Adds `f·l` and `f` to every pixel of the footprint, `f` from `w`. `pixels` is the tile's
/// row-major storage (`stride` columns). Separable sources take `nx + ny` 1D weights (once per
/// column and row) and an outer product; the others one `xy` per pixel.
#[inline(always)]
fn accumulate<W: WeightSource + ?Sized>(
    pixels: &mut [Pixel],
    stride: usize,
    fp: &Footprint,
    l: [f64; 3],
    w: &W,
) {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    let first = fp.y0 * stride + fp.x0;
    // One bounds check for the whole footprint; every row below is inside it.
    let Some(rows) = pixels.get_mut(first..first + (ny - 1) * stride + nx) else {
        return;
    };
    if w.separable() {
        // Stack buffers sized for the footprint: box (≤ 2), radius ≤ 1.5 (≤ 4), ≤ 3.5 (≤ 8),
        // ≤ 15.5 (≤ 32); wider footprints fall through to the per-pixel path.
        match nx {
            1 if ny == 1 => {
                let f = f64::from(w.x(fp.dx(fp.x0))) * f64::from(w.y(fp.dy(fp.y0)));
                return add(&mut rows[0], f, l);
            }
            0..=2 => return separable::<2, W>(rows, stride, fp, l, w),
            3..=4 => return separable::<4, W>(rows, stride, fp, l, w),
            5..=8 => return separable::<8, W>(rows, stride, fp, l, w),
            9..=32 => return separable::<32, W>(rows, stride, fp, l, w),
            _ => {}
        }
    }
    for j in 0..ny {
        let dy = fp.dy(fp.y0 + j);
        for (i, p) in rows[j * stride..j * stride + nx].iter_mut().enumerate() {
            let dx = fp.dx(fp.x0 + i);
            let f = if w.separable() {
                f64::from(w.x(dx)) * f64::from(w.y(dy))
            } else {
                f64::from(w.xy(dx, dy))
            };
            add(p, f, l);
        }
    }
}

#[inline(always)]
fn add(p: &mut Pixel, f: f64, l: [f64; 3]) {
    p.rgb_sum[0] += f * l[0];
    p.rgb_sum[1] += f * l[1];
    p.rgb_sum[2] += f * l[2];
    p.weight_sum += f;
}

/// The separable path for `nx ≤ M` columns: per column `fx·[l, 1]` in `f64`, then per row
/// `p += fy·column` — the weight is the exact `f64` product `fx·fy` of the two `f32` factors.
#[inline(always)]
fn separable<const M: usize, W: WeightSource + ?Sized>(
    rows: &mut [Pixel],
    stride: usize,
    fp: &Footprint,
    l: [f64; 3],
    w: &W,
) {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    let mut cols = [[0.0f64; 4]; M];
    for (i, c) in cols[..nx].iter_mut().enumerate() {
        let fx = f64::from(w.x(fp.dx(fp.x0 + i)));
        *c = [fx * l[0], fx * l[1], fx * l[2], fx];
    }
    for j in 0..ny {
        let fy = f64::from(w.y(fp.dy(fp.y0 + j)));
        let row = &mut rows[j * stride..j * stride + nx];
        for (p, c) in row.iter_mut().zip(&cols[..nx]) {
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
            // Saturating: a rectangle reaching i64::MAX (any `TileSpec` is valid) must not wrap.
            ((b.x1 as f64 - 0.5 + f64::from(rx)).floor() as i64).saturating_add(1),
            ((b.y1 as f64 - 0.5 + f64::from(ry)).floor() as i64).saturating_add(1),
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
            geometry: Geometry::new(pixel_bounds, [rx, ry]),
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

    /// The film setup this tile was made from.
    pub(crate) fn setup(&self) -> &Arc<Setup> {
        &self.setup
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
        let stride = self.geometry.size[0] as usize;
        match self.setup.weights.table() {
            FilterTable::Separable(t) => accumulate(&mut self.pixels, stride, &fp, l, t),
            FilterTable::Full(t) => accumulate(&mut self.pixels, stride, &fp, l, t),
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
        let stride = self.geometry.size[0] as usize;
        let separable = self.setup.weights.table().is_separable() && filter.is_separable();
        let direct = Direct { filter, separable };
        accumulate(&mut self.pixels, stride, &fp, l, &direct);
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
        // In f64: the f32 product of two finite values can overflow to ±∞ (f32::MAX × 2), and
        // the f64 product of two f32s is exact, so finite input keeps the sums finite.
        let w = f64::from(weight);
        let l = [
            f64::from(rgb[0]) * w,
            f64::from(rgb[1]) * w,
            f64::from(rgb[2]) * w,
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
        let stride = self.geometry.size[0] as usize;
        if self.splats.is_empty() {
            self.splats = vec![[0.0; 3]; self.pixels.len()];
        }
        for y in fp.y0..fp.y1 {
            for x in fp.x0..fp.x1 {
                let f = f64::from(self.setup.weights.weight(fp.dx(x), fp.dy(y)));
                let s = &mut self.splats[y * stride + x];
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

    /// The stored pixels reached by a sample at the finite position `p` (film pixels
    /// `⌈p − ½ − r⌉ … ⌊p − ½ + r⌋` per axis, clipped), in tile-local indices. `None` when nothing
    /// is reached.
    #[inline(always)]
    fn footprint(&self, p: [f32; 2]) -> Option<Footprint> {
        let g = &self.geometry;
        let (x0, x1, cx) = g.span(f64::from(p[0]), 0);
        let (y0, y1, cy) = g.span(f64::from(p[1]), 1);
        (x0 < x1 && y0 < y1).then_some(Footprint {
            x0: x0 as usize,
            x1: x1 as usize,
            y0: y0 as usize,
            y1: y1 as usize,
            c: [cx, cy],
        })
    }
}
