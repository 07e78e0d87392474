//! Film tiles: owned by one thread, filled with samples, merged back into the film.

use crate::bounds::Bounds;
use crate::error::Error;
use crate::extras::{ExtraSums, sample_half};
use crate::pixel::Pixel;
use crate::sample::FilmSample;
use crate::setup::Setup;
use crate::stats::FilmStats;
use crate::tile_spec::TileSpec;
use nyquist::filter::{Axis, FilmTable, Filter, MAX_TAPS, PhaseTable, Weights};
use std::sync::Arc;

/// Where a tile's samples go, cached per tile in the forms the per-sample path uses.
#[derive(Clone, Copy, Debug)]
struct Geometry {
    /// The stored pixels.
    bounds: Bounds,
    /// Filter radius `[rx, ry]`.
    radius: [f64; 2],
    /// `2r` per axis.
    diameter: [f64; 2],
    /// Corner of the first stored pixel, `(x0, y0)`.
    corner: [f64; 2],
    /// Centre of the first stored pixel, `(x0 + ½, y0 + ½)`.
    origin: [f64; 2],
    /// Stored columns and rows.
    size: [i64; 2],
    /// `−2r − 1`, the lower clamp of a footprint's left edge (every footprint starting there or
    /// below is empty).
    low: [f64; 2],
    /// `size + 1`, the upper clamp of a footprint's left edge.
    limit: [f64; 2],
    /// `size` as floats.
    size_f: [f64; 2],
    /// `size − 4`: the last start of a 4-pixel footprint that is stored in full.
    block_last: [f64; 2],
}

impl Geometry {
    fn new(bounds: Bounds, radius: [f32; 2]) -> Geometry {
        let size = [bounds.width() as i64, bounds.height() as i64];
        let radius = radius.map(f64::from);
        Geometry {
            bounds,
            radius,
            diameter: radius.map(|r| 2.0 * r),
            corner: [bounds.x0 as f64, bounds.y0 as f64],
            origin: [bounds.x0 as f64 + 0.5, bounds.y0 as f64 + 0.5],
            size,
            low: radius.map(|r| -2.0 * r - 1.0),
            limit: [(size[0] + 1) as f64, (size[1] + 1) as f64],
            size_f: [size[0] as f64, size[1] as f64],
            block_last: [(size[0] - 4) as f64, (size[1] - 4) as f64],
        }
    }

    /// The footprint along axis `a` of a sample at the finite position `p`: film pixels
    /// `⌈p − ½ − r⌉ … ⌊p − ½ + r⌋` clipped to the stored ones, in tile-local indices.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn span(&self, p: f64, a: usize) -> Span {
        // c: the sample's local position (local pixel i's centre is i − c away); q: the
        // footprint's left edge. Clamping q keeps the conversions exact for any finite p (even
        // 1e30) without changing any non-empty footprint (those have −2r ≤ q ≤ size − 1).
        // Everything stays in f64 until the final conversions (integer compares of i64 lanes
        // cost SSE2 a dozen instructions each).
        let c = p - self.origin[a];
        let q = min(max(c - self.radius[a], self.low[a]), self.limit[a]);
        let first = ceil_f64(q);
        let last = floor_f64(q + self.diameter[a]);
        let i0 = max(first, 0.0);
        Span {
            i0,
            i1: min(last + 1.0, self.size_f[a]),
            c,
            // first − q ∈ [0, 1), exact (q is within 1 below the integer first).
            phase: (first - q) as f32,
            skip: i0 - first,
        }
    }
}

/// `max` for operands that are not NaN: one `maxsd` (`f64::max` adds NaN handling).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn max(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// `min` for operands that are not NaN.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn min(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// An integer-valued `f64` below 2³¹ in magnitude as `i64`, by its bits after adding
/// [`ROUND_MAGIC`]: two instructions where `as i64` (saturating, NaN → 0) takes five.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn int(v: f64) -> i64 {
    i64::from((v + ROUND_MAGIC).to_bits() as u32 as i32)
}

/// One axis of a footprint: stored pixels `[i0, i1)` (empty when `i0 ≥ i1`), the sample's local
/// position `c`, and for phase tables the footprint's phase and the taps clipped off its start.
/// Integers are held as floats (exact, below 2³¹) so that the emptiness test is a float compare.
#[derive(Clone, Copy, Debug)]
struct Span {
    i0: f64,
    i1: f64,
    c: f64,
    phase: f32,
    skip: f64,
}

/// A footprint in tile-local indices: columns `[x0, x1)`, rows `[y0, y1)`, the sample's local
/// position `c` (see [`Geometry::span`]), and per axis the phase and the first tap.
#[derive(Clone, Copy, Debug)]
struct Footprint {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
    c: [f64; 2],
    phase: [f32; 2],
    tap0: [usize; 2],
}

impl Footprint {
    /// Offset from the sample to the centre of local column `i`, formed in `f64` and rounded
    /// once.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn dx(&self, i: usize) -> f32 {
        // i64 → f64 is one instruction (cvtsi2sd); usize → f64 is several.
        (i as i64 as f64 - self.c[0]) as f32
    }
    /// Offset from the sample to the centre of local row `j`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn dy(&self, j: usize) -> f32 {
        (j as i64 as f64 - self.c[1]) as f32
    }
}

/// `2⁵² + 2⁵¹`: `(v + ROUND_MAGIC) − ROUND_MAGIC` is `v` rounded to an integer (ties to even)
/// for `|v| < 2⁵¹`.
const ROUND_MAGIC: f64 = 6_755_399_441_055_744.0;

/// `⌊v⌋` for `|v| < 2⁵¹` (the clamped footprint ends), as a float, without a libm call (no
/// SSE4.1 `roundsd` on baseline x86-64): round to nearest by [`ROUND_MAGIC`], then step down
/// when that went up.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn floor_f64(v: f64) -> f64 {
    let r = (v + ROUND_MAGIC) - ROUND_MAGIC;
    r - if r > v { 1.0 } else { 0.0 }
}

/// `⌈v⌉` for `|v| < 2⁵¹`, as a float.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn ceil_f64(v: f64) -> f64 {
    let r = (v + ROUND_MAGIC) - ROUND_MAGIC;
    r + if r < v { 1.0 } else { 0.0 }
}

/// The footprint's rows of the tile's row-major storage (`stride` columns): `rows[j·stride + i]`
/// is the pixel at column `x0 + i`, row `y0 + j`. One bounds check for the whole footprint.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn footprint_rows<'a>(
    pixels: &'a mut [Pixel],
    stride: usize,
    fp: &Footprint,
) -> Option<&'a mut [Pixel]> {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    let first = fp.y0 * stride + fp.x0;
    pixels.get_mut(first..first + (ny - 1) * stride + nx)
}

/// The weight of a one-pixel footprint (the box filter, nearly always): the filter's constant,
/// or one tap per axis.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn single_weight(fp: &Footprint, t: &PhaseTable) -> f64 {
    match t.constant() {
        Some(c) => f64::from(c),
        None => {
            f64::from(t.tap(Axis::X, fp.phase[0], fp.tap0[0]))
                * f64::from(t.tap(Axis::Y, fp.phase[1], fp.tap0[1]))
        }
    }
}

/// Adds `f·l` and `f` to every pixel of the footprint (its `rows`) with weights from a phase
/// table: one interpolated row of taps per axis, then the outer product.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phase_footprint(rows: &mut [Pixel], stride: usize, fp: &Footprint, l: [f64; 3], t: &PhaseTable) {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    let mut fx = [0.0f32; MAX_TAPS];
    let mut fy = [0.0f32; MAX_TAPS];
    t.row(Axis::X, fp.phase[0], &mut fx);
    t.row(Axis::Y, fp.phase[1], &mut fy);
    // The footprint's pixels are taps tap0 … tap0 + n − 1, all below MAX_TAPS; the clamps only
    // tell the compiler so.
    let fx = fx.get(fp.tap0[0]..).unwrap_or(&[]);
    let fy = fy.get(fp.tap0[1]..).unwrap_or(&[]);
    outer_product(
        rows,
        stride,
        [nx.min(fx.len()), ny.min(fy.len())],
        fx,
        fy,
        l,
    );
}

/// Adds `f·l` and `f` to every pixel of the footprint, `f` from `w`. Separable weights take
/// `nx + ny` 1D factors (once per column and row) and an outer product; the others one
/// `weight` per pixel.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn accumulate<W: Weights + ?Sized>(
    rows: &mut [Pixel],
    stride: usize,
    fp: &Footprint,
    l: [f64; 3],
    w: &W,
) {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    let separable = w.is_separable();
    let x = |d: f32| w.weight_1d(Axis::X, d).unwrap_or(0.0);
    let y = |d: f32| w.weight_1d(Axis::Y, d).unwrap_or(0.0);
    // Footprints up to 32 wide take the separable path; wider ones fall through.
    if separable && nx <= 32 && ny <= 32 {
        let mut fx = [0.0f32; 32];
        let mut fy = [0.0f32; 32];
        for (i, f) in fx[..nx].iter_mut().enumerate() {
            *f = x(fp.dx(fp.x0 + i));
        }
        for (j, f) in fy[..ny].iter_mut().enumerate() {
            *f = y(fp.dy(fp.y0 + j));
        }
        return outer_product(rows, stride, [nx, ny], &fx, &fy, l);
    }
    for j in 0..ny {
        let dy = fp.dy(fp.y0 + j);
        for (i, p) in rows[j * stride..j * stride + nx].iter_mut().enumerate() {
            let dx = fp.dx(fp.x0 + i);
            let f = if separable {
                f64::from(x(dx)) * f64::from(y(dy))
            } else {
                f64::from(w.weight(dx, dy))
            };
            add(p, f, l);
        }
    }
}

/// Visits every pixel of the footprint with the factors `(a, b)` of its weight as the sums
/// ([`phase_footprint`], [`single_weight`]) take them: the pixel gets `b·(a·l)` and `b·a`.
fn phase_weights(fp: &Footprint, t: &PhaseTable, mut visit: impl FnMut(usize, usize, f64, f64)) {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    if nx == 1 && ny == 1 {
        return visit(0, 0, single_weight(fp, t), 1.0);
    }
    let mut fx = [0.0f32; MAX_TAPS];
    let mut fy = [0.0f32; MAX_TAPS];
    t.row(Axis::X, fp.phase[0], &mut fx);
    t.row(Axis::Y, fp.phase[1], &mut fy);
    let fx = fx.get(fp.tap0[0]..).unwrap_or(&[]);
    let fy = fy.get(fp.tap0[1]..).unwrap_or(&[]);
    for (j, &b) in fy.iter().take(ny).enumerate() {
        for (i, &a) in fx.iter().take(nx).enumerate() {
            visit(i, j, f64::from(a), f64::from(b));
        }
    }
}

/// [`phase_weights`] for weights `w` as [`accumulate`] takes them.
fn table_weights<W: Weights + ?Sized>(
    fp: &Footprint,
    w: &W,
    mut visit: impl FnMut(usize, usize, f64, f64),
) {
    let (nx, ny) = (fp.x1 - fp.x0, fp.y1 - fp.y0);
    let separable = w.is_separable();
    let x = |d: f32| w.weight_1d(Axis::X, d).unwrap_or(0.0);
    let y = |d: f32| w.weight_1d(Axis::Y, d).unwrap_or(0.0);
    for j in 0..ny {
        let dy = fp.dy(fp.y0 + j);
        for i in 0..nx {
            let dx = fp.dx(fp.x0 + i);
            if !separable {
                visit(i, j, f64::from(w.weight(dx, dy)), 1.0);
            } else if nx <= 32 && ny <= 32 {
                // The outer product's factors.
                visit(i, j, f64::from(x(dx)), f64::from(y(dy)));
            } else {
                visit(i, j, f64::from(x(dx)) * f64::from(y(dy)), 1.0);
            }
        }
    }
}

/// A filter evaluated directly, as weights: `eval_1d` per axis when `separable`, else `eval`.
/// [`FilmTile::add_sample_direct`]'s source, beside the film's table.
struct Direct<'a, F: ?Sized> {
    filter: &'a F,
    separable: bool,
}

impl<F: Filter + ?Sized> Weights for Direct<'_, F> {
    fn radius(&self) -> [f32; 2] {
        self.filter.radius()
    }
    fn integral(&self) -> f32 {
        self.filter.integral()
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight(&self, dx: f32, dy: f32) -> f32 {
        self.filter.eval(dx, dy)
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        self.separable
            .then(|| self.filter.eval_1d(axis, d).unwrap_or(0.0))
    }
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn is_separable(&self) -> bool {
        self.separable
    }
}

/// `rgb · weight` in `f64`, and whether `rgb` and `weight` are all finite. In `f64` because the
/// `f32` product of two finite values can overflow to ±∞ (`f32::MAX × 2`), while the `f64`
/// product of two `f32`s is exact, so finite input keeps the sums finite. The inputs are all
/// finite exactly when the three products are (∞·0 is NaN), and those exactly when their sum
/// is (∞ − ∞ is NaN): one test instead of four.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn weighted(rgb: [f32; 3], weight: f32) -> ([f64; 3], bool) {
    let w = f64::from(weight);
    let l = [
        f64::from(rgb[0]) * w,
        f64::from(rgb[1]) * w,
        f64::from(rgb[2]) * w,
    ];
    (l, (l[0] + l[1] + l[2]).is_finite())
}

#[cfg_attr(not(feature = "small-code"), inline(always))]
fn add(p: &mut Pixel, f: f64, l: [f64; 3]) {
    p.rgb_sum[0] += f * l[0];
    p.rgb_sum[1] += f * l[1];
    p.rgb_sum[2] += f * l[2];
    p.weight_sum += f;
}

/// `p += fy[j]·fx[i]·[l, 1]` over the `nx × ny` footprint: per column `fx·[l, 1]` in `f64`,
/// then per row `p += fy·column`, so the weight is the exact `f64` product `fx·fy` of the two
/// `f32` factors. Widths up to 8 get a loop unrolled for exactly that width; wider footprints
/// (up to 32 columns) share one stack buffer.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn outer_product(
    rows: &mut [Pixel],
    stride: usize,
    [nx, ny]: [usize; 2],
    fx: &[f32],
    fy: &[f32],
    l: [f64; 3],
) {
    let fy = &fy[..ny.min(fy.len())];
    match nx {
        1 => columns::<1>(rows, stride, fx, fy, l),
        2 => columns::<2>(rows, stride, fx, fy, l),
        3 => columns::<3>(rows, stride, fx, fy, l),
        4 => columns::<4>(rows, stride, fx, fy, l),
        5 => columns::<5>(rows, stride, fx, fy, l),
        6 => columns::<6>(rows, stride, fx, fy, l),
        7 => columns::<7>(rows, stride, fx, fy, l),
        8 => columns::<8>(rows, stride, fx, fy, l),
        _ => wide_columns(rows, stride, nx, fx, fy, l),
    }
}

/// The column factors `fx·[l, 1]` of `fx[..n]` (missing ones 0).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn column_factors<const M: usize>(n: usize, fx: &[f32], l: [f64; 3]) -> [[f64; 4]; M] {
    let mut cols = [[0.0f64; 4]; M];
    for (c, &f) in cols[..n.min(M)].iter_mut().zip(fx) {
        let f = f64::from(f);
        *c = [f * l[0], f * l[1], f * l[2], f];
    }
    cols
}

/// `p += fy·column` for every pixel of a row.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn add_row(row: &mut [Pixel], cols: &[[f64; 4]], fy: f64) {
    for (p, c) in row.iter_mut().zip(cols) {
        p.rgb_sum[0] += fy * c[0];
        p.rgb_sum[1] += fy * c[1];
        p.rgb_sum[2] += fy * c[2];
        p.weight_sum += fy * c[3];
    }
}

/// [`outer_product`] for exactly `N` columns.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn columns<const N: usize>(rows: &mut [Pixel], stride: usize, fx: &[f32], fy: &[f32], l: [f64; 3]) {
    let cols = column_factors::<N>(N, fx, l);
    for (j, &f) in fy.iter().enumerate() {
        let Some(row) = rows.get_mut(j * stride..j * stride + N) else {
            return;
        };
        // Always N long: the conversion only tells the compiler so (a fully unrolled row).
        let Ok(row) = <&mut [Pixel; N]>::try_from(row) else {
            return;
        };
        add_row(row, &cols, f64::from(f));
    }
}

/// [`outer_product`] for 9 to 32 columns.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn wide_columns(rows: &mut [Pixel], stride: usize, nx: usize, fx: &[f32], fy: &[f32], l: [f64; 3]) {
    let nx = nx.min(32);
    let cols = column_factors::<32>(nx, fx, l);
    for (j, &f) in fy.iter().enumerate() {
        let Some(row) = rows.get_mut(j * stride..j * stride + nx) else {
            return;
        };
        add_row(row, &cols[..nx], f64::from(f));
    }
}

/// One thread's part of a [`crate::Film`]: the pixels that samples inside its bounds can reach.
///
/// Created by [`crate::Film::tile`], filled with [`FilmTile::add_sample`], handed back with
/// [`crate::Film::merge`]. NaN or infinite radiance or weight is dropped and counted, never added.
/// (A renderer on one thread can skip tiles: [`crate::Film::add_sample`].)
///
/// ```
/// use nyquist_film::{Film, FilmConfig};
/// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Mitchell::default()).unwrap();
/// let spec = film.tiles(4).unwrap()[0];
/// let mut tile = film.tile(spec);
/// tile.add_sample([2.0, 2.0], [1.0; 3], 1.0);
/// film.merge(tile).unwrap();
/// assert_eq!(film.stats().samples, 1);
/// ```
#[derive(Debug)]
pub struct FilmTile {
    spec: TileSpec,
    /// The film pixels this tile merges ([`FilmTile::pixel_bounds`]).
    pixel_bounds: Bounds,
    /// Where the stored pixels lie ([`FilmTile::stored_bounds`]).
    geometry: Geometry,
    pixels: Vec<Pixel>,
    splats: Vec<[f64; 3]>,
    /// The per-pixel extras the film keeps ([`crate::PixelExtras`]), row-major like the pixels.
    extras: Option<Box<ExtraSums>>,
    setup: Arc<Setup>,
    stats: FilmStats,
    /// The per-sample fast path the film's filter allows (see [`FastPath::for_setup`]).
    fast: FastPath,
    /// [`FastPath::Block4`]'s held samples, `queue[..queued]`, oldest first (see [`Queued`]).
    queue: [Queued; QUEUE],
    queued: usize,
}

/// Samples a [`FastPath::Block4`] tile holds before adding them: enough that the weights of
/// one are computed while the sums of another are written (measured: 8 gained less, 32 no
/// more).
const QUEUE: usize = 16;

/// A checked sample waiting in a tile's queue: its film position and `weight·rgb`.
///
/// A radius-2 footprint's weights are a long chain of dependent steps (position, phase, table
/// row, interpolation, outer product) ending in 32 pixel stores, and one sample's chain fills
/// the processor's reorder window: adding each sample at once runs those chains one after
/// another. Held in a queue, a batch's weights are computed together (independent chains that
/// overlap), then its sums are written in arrival order, so every pixel gets the same additions
/// in the same order as without the queue: the same sums, bit for bit.
#[derive(Clone, Copy, Debug, Default)]
struct Queued {
    p: [f32; 2],
    l: [f64; 3],
}

/// The part of a [`FastPath::Block4`] sample its sums need: the first pixel of its 4 × 4
/// footprint (an index into the tile's pixels) and the four weights per axis.
#[derive(Clone, Copy, Debug)]
struct Block4 {
    start: usize,
    fx: [f32; 4],
    fy: [f32; 4],
}

/// The 4 × 4 footprint of a sample at `p` when it is exactly 4 × 4 pixels and stored in full
/// (else `None`, also for NaN and ∞). Same as the general path, bit for bit: the same footprint
/// start `⌈q⌉` and end `⌊q + 2r⌋` (tested without the floor: four pixels exactly when
/// `⌈q⌉ + 3 ≤ q + 2r < ⌈q⌉ + 4`), the same phase, and the first four taps of the same table row
/// ([`PhaseTable::row4`]).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn block4(g: &Geometry, t: &PhaseTable, p: [f32; 2]) -> Option<Block4> {
    // As in `Geometry::span`, whose clamps change nothing for the footprints taken here.
    let c = [f64::from(p[0]) - g.origin[0], f64::from(p[1]) - g.origin[1]];
    let q = [c[0] - g.radius[0], c[1] - g.radius[1]];
    let first = [ceil_f64(q[0]), ceil_f64(q[1])];
    let end = [q[0] + g.diameter[0], q[1] + g.diameter[1]];
    // False for NaN and ∞ positions as well.
    let stored = (first[0] >= 0.0)
        & (first[0] <= g.block_last[0])
        & (first[1] >= 0.0)
        & (first[1] <= g.block_last[1]);
    let four = (end[0] >= first[0] + 3.0)
        & (end[0] < first[0] + 4.0)
        & (end[1] >= first[1] + 3.0)
        & (end[1] < first[1] + 4.0);
    if !(stored & four) {
        return None;
    }
    let stride = g.size[0] as usize;
    Some(Block4 {
        start: int(first[1]) as usize * stride + int(first[0]) as usize,
        fx: t.row4(Axis::X, (first[0] - q[0]) as f32),
        fy: t.row4(Axis::Y, (first[1] - q[1]) as f32),
    })
}

/// The fast paths of [`FilmTile::add_sample`], each taking the samples it can and handing the
/// rest to the general path, with the same sums bit for bit.
#[derive(Clone, Copy, Debug, PartialEq)]
enum FastPath {
    /// None applies: every sample takes the general path.
    None,
    /// The film keeps per-pixel extras: every sample goes through [`FilmTile::add`], which adds
    /// the sums by the general path and the extras beside them.
    Extras,
    /// A box of radius ≤ ½ ([`one_pixel_weight`]): the filter's constant weight, and whether
    /// a radius is below ½ (then a sample can miss its pixel's centre, and each is tested).
    OnePixel { weight: f64, narrow: bool },
    /// A phase table whose footprints are often 4 × 4 (4 or 5 taps: 1.5 ≤ r < 2.5 per axis,
    /// the Mitchell, triangle and Gaussian defaults) and no radiance clamp: a sample whose
    /// footprint is 4 × 4 and stored in full skips the footprint machinery (clips, tap offsets,
    /// widths) and reads four taps per axis.
    Block4,
}

impl FastPath {
    fn for_setup(setup: &Setup) -> FastPath {
        if setup.extras.any() {
            return FastPath::Extras;
        }
        if let Some(weight) = one_pixel_weight(setup) {
            let narrow = setup.table.radius().iter().any(|&r| r < 0.5);
            return FastPath::OnePixel { weight, narrow };
        }
        match &setup.table {
            FilmTable::Phase(t)
                if setup.max_component.is_none()
                    && [Axis::X, Axis::Y]
                        .iter()
                        .all(|&a| (4..=5).contains(&t.taps(a))) =>
            {
                FastPath::Block4
            }
            _ => FastPath::None,
        }
    }
}

/// The weight of [`FilmTile::add_sample`]'s one-pixel path, when it applies: a box filter (a
/// constant phase table) with radii of at most ½ and no radiance clamp. Such a box reaches at
/// most the one pixel a sample lies in, so the pixel comes from a floor per axis and the
/// footprint machinery is skipped. Samples on a pixel edge (a box of radius ½ reaches both
/// neighbours) and near the stored area's border take the general path.
fn one_pixel_weight(setup: &Setup) -> Option<f64> {
    let FilmTable::Phase(t) = &setup.table else {
        return None;
    };
    let weight = f64::from(t.constant()?);
    (setup.max_component.is_none() && t.radius().iter().all(|&r| r <= 0.5)).then_some(weight)
}

/// Tiles of filters with every radius below this store a guard band outside the film
/// ([`FilmTile::stored_bounds`]): the 4 × 4 path's radii (4 or 5 taps) and all smaller ones.
const BAND_RADIUS: f32 = 2.5;

/// The pixels whose centres lie within the filter radius `[rx, ry]` of rectangle `b`: `b` grown
/// by the radius, in whole pixels.
fn reach(b: Bounds, [rx, ry]: [f32; 2]) -> Bounds {
    Bounds::new(
        (b.x0 as f64 - 0.5 - f64::from(rx)).ceil() as i64,
        (b.y0 as f64 - 0.5 - f64::from(ry)).ceil() as i64,
        // Saturating: a rectangle reaching i64::MAX (any `TileSpec` is valid) must not wrap.
        ((b.x1 as f64 - 0.5 + f64::from(rx)).floor() as i64).saturating_add(1),
        ((b.y1 as f64 - 0.5 + f64::from(ry)).floor() as i64).saturating_add(1),
    )
}

impl FilmTile {
    pub(crate) fn new(spec: TileSpec, setup: Arc<Setup>) -> FilmTile {
        let (pixel_bounds, stored) = Self::layout(spec.bounds, &setup, true);
        let n = stored.area() as usize;
        let pixels = vec![Pixel::default(); n];
        // As `vec!` above does for the pixels, a tile's allocation failure ends the program.
        let extras = ExtraSums::new(&setup.extras, n)
            .unwrap_or_else(|e| panic!("a film tile could not be allocated: {e}"));
        Self::with_pixels(spec, setup, pixel_bounds, stored, pixels, extras)
    }

    /// The film's own sums: a tile taking samples anywhere in the film and storing exactly the
    /// film's pixels (no guard band: these sums are the film's), outside the merge order.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`] if the allocator cannot provide the pixels.
    pub(crate) fn whole(setup: Arc<Setup>) -> Result<FilmTile, Error> {
        let bounds = setup.pixel_bounds;
        let (pixel_bounds, stored) = Self::layout(bounds, &setup, false);
        let n = stored.area() as usize;
        let pixels = crate::error::try_filled(n, Pixel::default(), "the film's pixels")?;
        let extras = ExtraSums::new(&setup.extras, n)?;
        let spec = TileSpec {
            index: usize::MAX,
            bounds,
        };
        Ok(Self::with_pixels(
            spec,
            setup,
            pixel_bounds,
            stored,
            pixels,
            extras,
        ))
    }

    /// The film pixels a tile over `b` merges and the pixels it stores: those and, with `band`,
    /// for radii below `BAND_RADIUS` (every film that can take the 4 × 4 path, clamped or
    /// not), a guard band along the film's edges of the pixels just outside it that the tile's
    /// samples reach, at most two wide. The band's sums are never merged; they let a sample
    /// near the film's edge take the 4 × 4 path with its whole footprint stored, instead of the
    /// general path that clips it, and the general path then stores the same unclipped
    /// footprint, so both add the same bits. Wider filters, whose radius may reach
    /// `MAX_RADIUS`, store no band: it would be most of the allocation for nothing.
    fn layout(b: Bounds, setup: &Setup, band: bool) -> (Bounds, Bounds) {
        let radius = setup.table.radius();
        let grown = reach(b, radius);
        let fb = setup.pixel_bounds;
        let mut pixel_bounds = grown.intersect(&fb);
        let mut stored = if band && radius.iter().all(|&r| r < BAND_RADIUS) {
            grown.intersect(&reach(fb, radius))
        } else {
            pixel_bounds
        };
        if pixel_bounds.is_empty() || b.is_empty() {
            // Nothing to store: an empty rectangle at the film's corner keeps merges trivial.
            pixel_bounds = Bounds::new(fb.x0, fb.y0, fb.x0, fb.y0);
            stored = pixel_bounds;
        }
        (pixel_bounds, stored)
    }

    fn with_pixels(
        spec: TileSpec,
        setup: Arc<Setup>,
        pixel_bounds: Bounds,
        stored: Bounds,
        pixels: Vec<Pixel>,
        extras: Option<Box<ExtraSums>>,
    ) -> FilmTile {
        let fast = FastPath::for_setup(&setup);
        FilmTile {
            spec,
            pixel_bounds,
            geometry: Geometry::new(stored, setup.table.radius()),
            pixels,
            // Allocated by the first splat: most renderers never splat.
            splats: Vec::new(),
            extras,
            setup,
            stats: FilmStats::default(),
            fast,
            queue: [Queued::default(); QUEUE],
            queued: 0,
        }
    }

    /// The tile's place in the merge order.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let spec = film.tiles(2).unwrap()[3];
    /// assert_eq!(film.tile(spec).index(), 3);
    /// ```
    pub fn index(&self) -> usize {
        self.spec.index
    }

    /// The pixels whose samples this tile takes.
    ///
    /// ```
    /// use nyquist_film::{Bounds, Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let spec = film.tiles(2).unwrap()[1];
    /// assert_eq!(film.tile(spec).bounds(), Bounds::new(2, 0, 4, 2));
    /// ```
    pub fn bounds(&self) -> Bounds {
        self.spec.bounds
    }

    /// The film pixels this tile holds sums for, and merges: its bounds grown by the filter
    /// radius, clipped to the film.
    ///
    /// ```
    /// use nyquist_film::{Bounds, Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(8, 8), &nyquist::filter::Triangle::default()).unwrap();
    /// let spec = film.tiles(4).unwrap()[3]; // pixels 4..8 × 4..8
    /// assert_eq!(film.tile(spec).pixel_bounds(), Bounds::new(2, 2, 8, 8));
    /// ```
    pub fn pixel_bounds(&self) -> Bounds {
        self.pixel_bounds
    }

    /// The pixels this tile stores, row-major in [`FilmTile::pixels`]: [`FilmTile::pixel_bounds`]
    /// and, along the film's edges, a guard band of pixels outside the film (never merged).
    pub(crate) fn stored_bounds(&self) -> Bounds {
        self.geometry.bounds
    }

    /// The film setup this tile was made from.
    pub(crate) fn setup(&self) -> &Arc<Setup> {
        &self.setup
    }

    pub(crate) fn pixels(&self) -> &[Pixel] {
        &self.pixels
    }

    pub(crate) fn pixels_mut(&mut self) -> &mut [Pixel] {
        &mut self.pixels
    }

    /// The splat sums, row-major like the pixels, or empty if nothing was splatted.
    pub(crate) fn splats(&self) -> &[[f64; 3]] {
        &self.splats
    }

    /// The splat sums, allocated (zero) on first use.
    pub(crate) fn splats_mut(&mut self) -> &mut [[f64; 3]] {
        if self.splats.is_empty() {
            self.splats = vec![[0.0; 3]; self.pixels.len()];
        }
        &mut self.splats
    }

    /// The per-pixel extras, when the film keeps any.
    pub(crate) fn extras(&self) -> Option<&ExtraSums> {
        self.extras.as_deref()
    }

    pub(crate) fn extras_mut(&mut self) -> Option<&mut ExtraSums> {
        self.extras.as_deref_mut()
    }

    /// Bytes of the pixel sums (32 a pixel), of the splat sums once allocated (24 a pixel) and
    /// of the extras ([`crate::PixelExtras::bytes_per_pixel`]).
    pub(crate) fn storage_bytes(&self) -> usize {
        self.pixels.len() * size_of::<Pixel>()
            + self.splats.len() * size_of::<[f64; 3]>()
            + self.extras.as_ref().map_or(0, |e| e.bytes())
    }

    /// Counters of this tile.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    /// tile.add_splat([1.0, 1.0], [1.0; 3]);
    /// assert_eq!((tile.stats().samples, tile.stats().splats), (0, 1));
    /// ```
    pub fn stats(&self) -> FilmStats {
        self.stats
    }

    /// Samples this tile dropped for NaN or infinite radiance or weight.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    /// tile.add_sample([1.0, f32::NAN], [1.0; 3], 1.0);
    /// assert_eq!(tile.rejected(), 1);
    /// ```
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
    /// Radius-2 filters (Mitchell, triangle, Gaussian defaults, no clamp) are checked and
    /// counted at once but added in batches of 16, oldest first, the last batch when the tile is
    /// merged: one sample's weights are computed while another's sums are written, and the
    /// film's sums are the same, bit for bit.
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
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn add_sample(&mut self, p_film: [f32; 2], rgb: [f32; 3], weight: f32) {
        match self.fast {
            FastPath::OnePixel {
                weight: filter_weight,
                narrow,
            } => {
                let added = if narrow {
                    self.add_one_pixel::<true>(filter_weight, p_film, rgb, weight)
                } else {
                    self.add_one_pixel::<false>(filter_weight, p_film, rgb, weight)
                };
                if !added {
                    self.add_sample_footprint(p_film, rgb, weight);
                }
            }
            FastPath::Block4 => self.enqueue(p_film, rgb, weight),
            FastPath::None => self.add_sample_footprint(p_film, rgb, weight),
            FastPath::Extras => self.add(&FilmSample::new(p_film, rgb, weight)),
        }
    }

    /// Adds a sample with everything a film that keeps [`crate::PixelExtras`] takes from it:
    /// the sums as [`FilmTile::add_sample`] adds them (the same bits whether extras are kept or
    /// not), and per reached pixel with filter weight `f`, the variance moments of
    /// `weight·rgb` with weight `f²`, the B half's sums when `index` is in the B half
    /// ([`crate::extras::sample_half`]), and `f·a` for each channel value `a`.
    ///
    /// A sample is rejected and counted ([`FilmTile::rejected`]) when a value is NaN or
    /// infinite (channels included) or when it has another number of channels than the film
    /// keeps (so on a film that keeps channels, [`FilmTile::add_sample`] is rejected).
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig, FilmSample, PixelExtras};
    /// let mut config = FilmConfig::new(4, 4);
    /// config.extras = PixelExtras { variance: true, halves: false, channels: 1 };
    /// let mut film = Film::new(config, &nyquist::filter::Boxcar::default()).unwrap();
    /// let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    /// for (i, v) in [1.0f32, 3.0].into_iter().enumerate() {
    ///     let depth = [2.5];
    ///     tile.add(&FilmSample { index: i as u64, channels: &depth, ..FilmSample::new([0.5, 0.5], [v; 3], 1.0) });
    /// }
    /// tile.add(&FilmSample::new([0.5, 0.5], [1.0; 3], 1.0)); // no depth: rejected
    /// assert_eq!((tile.stats().samples, tile.rejected()), (2, 1));
    /// film.merge(tile).unwrap();
    /// let e = film.estimate(0, 0).unwrap();
    /// assert_eq!(e.value, [2.0; 3]);
    /// assert_eq!(e.variance, Some([1.0; 3])); // s² = 2 over n = 2
    /// assert_eq!(film.channel_values(0, 0).unwrap(), [2.5]);
    /// ```
    pub fn add(&mut self, s: &FilmSample) {
        let n = self.extras.as_ref().map_or(0, |e| e.n);
        // The sum is finite exactly when every value is (∞ − ∞ is NaN).
        let finite = s
            .channels
            .iter()
            .map(|&v| f64::from(v))
            .sum::<f64>()
            .is_finite();
        if s.channels.len() != n || !finite {
            self.stats.rejected += 1;
            return;
        }
        if self.extras.is_none() {
            return self.add_sample(s.p_film, s.rgb, s.weight);
        }
        let Some(l) = self.prepare(s.p_film, s.rgb, s.weight) else {
            return;
        };
        self.add_footprint(s.p_film, l);
        let Some(fp) = self.footprint(s.p_film) else {
            return;
        };
        let half = sample_half(s.index);
        let stride = self.geometry.size[0] as usize;
        let (Some(extras), setup) = (self.extras.as_deref_mut(), &self.setup) else {
            return;
        };
        let visit = |i: usize, j: usize, a: f64, b: f64| {
            extras.add((fp.y0 + j) * stride + fp.x0 + i, a, b, l, half, s.channels);
        };
        match &setup.table {
            FilmTable::Phase(t) => phase_weights(&fp, t, visit),
            FilmTable::Table(t) => table_weights(&fp, t, visit),
        }
    }

    /// [`FilmTile::add_sample`] without the queue: each sample is in the sums when this returns
    /// (the film's own sums, which [`crate::Film::pixel`] reads at any time). The same sums, bit
    /// for bit: the queue only reorders the work, never the additions.
    pub(crate) fn add_sample_now(&mut self, p_film: [f32; 2], rgb: [f32; 3], weight: f32) {
        match self.fast {
            FastPath::Block4 => {
                let Some(l) = self.prepare(p_film, rgb, weight) else {
                    return;
                };
                let block = match &self.setup.table {
                    FilmTable::Phase(t) => block4(&self.geometry, t, p_film),
                    FilmTable::Table(_) => None,
                };
                self.add_block_or_footprint(block, p_film, l);
            }
            _ => self.add_sample(p_film, rgb, weight),
        }
    }

    /// Adds a checked sample through its 4 × 4 block when it has one, else its footprint.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn add_block_or_footprint(&mut self, block: Option<Block4>, p: [f32; 2], l: [f64; 3]) {
        match block {
            Some(b) => {
                let stride = self.geometry.size[0] as usize;
                let start = b.start;
                if let Some(rows) = self.pixels.get_mut(start..start + 3 * stride + 4) {
                    columns::<4>(rows, stride, &b.fx, &b.fy, l);
                }
            }
            None => self.add_footprint(p, l),
        }
    }

    /// [`FilmTile::add_sample`] for [`FastPath::Block4`]: checks and counts the sample now
    /// ([`FilmTile::prepare`]), holds it in the queue ([`Queued`]), and adds the queue when it
    /// is full.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn enqueue(&mut self, p: [f32; 2], rgb: [f32; 3], weight: f32) {
        let Some(l) = self.prepare(p, rgb, weight) else {
            return;
        };
        if let Some(slot) = self.queue.get_mut(self.queued) {
            *slot = Queued { p, l };
            self.queued += 1;
        }
        if self.queued >= QUEUE {
            self.drain_queue();
        }
    }

    /// Adds the held samples, oldest first, and empties the queue: first the 4 × 4 weights of
    /// all of them, then their sums (the general path's for the samples [`block4`] declines).
    /// Called when the queue is full, before [`FilmTile::add_sample_direct`], and by
    /// [`crate::Film::merge`].
    pub(crate) fn drain_queue(&mut self) {
        let n = self.queued.min(QUEUE);
        self.queued = 0;
        let queue = self.queue;
        let mut blocks = [None; QUEUE];
        if let FilmTable::Phase(t) = &self.setup.table {
            for (b, q) in blocks.iter_mut().zip(&queue[..n]) {
                *b = block4(&self.geometry, t, q.p);
            }
        }
        for (&b, q) in blocks.iter().zip(&queue[..n]) {
            self.add_block_or_footprint(b, q.p, q.l);
        }
    }

    /// [`FilmTile::add_sample`] for a box of radius ≤ ½ and weight `filter_weight`
    /// ([`one_pixel_weight`]): `false`, with nothing done, when the sample needs the general
    /// path (non-finite input, a pixel edge, the border of the stored area). Same sums as the
    /// general path, bit for bit: the pixel is `⌊p − corner⌋` per axis, reached when its centre
    /// is within the radius (both exact in `f64`), and it gets `filter_weight · (rgb · w)`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn add_one_pixel<const NARROW: bool>(
        &mut self,
        filter_weight: f64,
        p: [f32; 2],
        rgb: [f32; 3],
        weight: f32,
    ) -> bool {
        let (l, finite) = weighted(rgb, weight);
        if !finite {
            return false;
        }
        let g = &self.geometry;
        let q = [f64::from(p[0]) - g.corner[0], f64::from(p[1]) - g.corner[1]];
        let i = [floor_f64(q[0]), floor_f64(q[1])];
        let f = [q[0] - i[0], q[1] - i[1]];
        // One test for the usual case, everything else to the general path: strictly inside
        // the stored area (false for NaN and ∞ too; then ⌊q⌋ is a stored pixel, |q| < 2³¹ and
        // the floor above is exact), not on a pixel edge (where a box of radius ½ reaches the
        // pixels on both sides), and the pixel's centre, |f − ½| away (exact), within the
        // radius (only radii below ½, `NARROW`, can miss it: a test left out when no radius is).
        let inside = (q[0] > 0.0) & (q[0] < g.size_f[0]) & (q[1] > 0.0) & (q[1] < g.size_f[1]);
        let off_edge = (f[0] > 0.0) & (f[1] > 0.0);
        let reached =
            !NARROW || (((f[0] - 0.5).abs() <= g.radius[0]) & ((f[1] - 0.5).abs() <= g.radius[1]));
        if !(inside & off_edge & reached) {
            return false;
        }
        self.stats.samples += 1;
        let stride = g.size[0] as usize;
        let index = int(i[1]) as usize * stride + int(i[0]) as usize;
        if let Some(pixel) = self.pixels.get_mut(index) {
            add(pixel, filter_weight, l);
        }
        true
    }

    /// [`FilmTile::add_sample`] through the footprint: the general path.
    fn add_sample_footprint(&mut self, p_film: [f32; 2], rgb: [f32; 3], weight: f32) {
        if let Some(l) = self.prepare(p_film, rgb, weight) {
            self.add_footprint(p_film, l);
        }
    }

    /// Adds `f·l` and `f` to every stored pixel of the footprint of a checked, counted sample at
    /// the finite position `p` (`l` its `weight·rgb`, clamped).
    fn add_footprint(&mut self, p: [f32; 2], l: [f64; 3]) {
        let Some(fp) = self.footprint(p) else {
            return;
        };
        let stride = self.geometry.size[0] as usize;
        let Some(rows) = footprint_rows(&mut self.pixels, stride, &fp) else {
            return;
        };
        match &self.setup.table {
            FilmTable::Phase(t) => {
                if fp.x1 - fp.x0 == 1 && fp.y1 - fp.y0 == 1 {
                    return add(&mut rows[0], single_weight(&fp, t), l);
                }
                phase_footprint(rows, stride, &fp, l, t)
            }
            FilmTable::Table(t) => accumulate(rows, stride, &fp, l, t),
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
        // The held samples first: each pixel's additions stay in arrival order.
        self.drain_queue();
        if self.extras.as_ref().is_some_and(|e| e.n > 0) {
            // No channel values: a film that keeps channels takes samples through `add`.
            self.stats.rejected += 1;
            return;
        }
        let Some(l) = self.prepare(p_film, rgb, weight) else {
            return;
        };
        let Some(fp) = self.footprint(p_film) else {
            return;
        };
        let stride = self.geometry.size[0] as usize;
        let separable = self.setup.table.is_separable() && filter.is_separable();
        let direct = Direct { filter, separable };
        if let Some(rows) = footprint_rows(&mut self.pixels, stride, &fp) {
            accumulate(rows, stride, &fp, l, &direct);
        }
        if let Some(extras) = self.extras.as_deref_mut() {
            table_weights(&fp, &direct, |i, j, a, b| {
                extras.add((fp.y0 + j) * stride + fp.x0 + i, a, b, l, 0, &[]);
            });
        }
    }

    /// Checks, counts and clamps a sample: its `weight·rgb` in `f64`, or `None` when it is
    /// rejected.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn prepare(&mut self, p: [f32; 2], rgb: [f32; 3], weight: f32) -> Option<[f64; 3]> {
        let (l, finite) = weighted(rgb, weight);
        if !(finite & p[0].is_finite() & p[1].is_finite()) {
            self.stats.rejected += 1;
            return None;
        }
        self.stats.samples += 1;
        Some(match self.setup.max_component {
            Some(_) => weighted(self.clamp(rgb), weight).0,
            None => l,
        })
    }

    /// Adds a splat (pbrt-v4 style, e.g. for light tracing): every reached pixel gets
    /// `f(centre − p)·rgb`, and the film divides splats by the filter integral when it resolves.
    /// Non-finite values are dropped and counted as rejected.
    ///
    /// ```
    /// use nyquist_film::{Film, FilmConfig};
    /// let mut film = Film::new(FilmConfig::new(4, 4), &nyquist::filter::Boxcar::default()).unwrap();
    /// let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    /// tile.add_splat([2.5, 0.5], [4.0, 0.0, 0.0]);
    /// tile.add_splat([2.5, 0.5], [f32::INFINITY, 0.0, 0.0]);
    /// assert_eq!((tile.stats().splats, tile.rejected()), (1, 1));
    /// film.merge(tile).unwrap();
    /// assert_eq!(film.image().0.get(2, 0), [4.0, 0.0, 0.0]);
    /// ```
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
                let f = f64::from(self.setup.table.weight(fp.dx(x), fp.dy(y)));
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
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn footprint(&self, p: [f32; 2]) -> Option<Footprint> {
        let g = &self.geometry;
        let (x, y) = (g.span(f64::from(p[0]), 0), g.span(f64::from(p[1]), 1));
        // Non-negative integers below 2³¹ once non-empty: `int` converts them exactly.
        (x.i0 < x.i1 && y.i0 < y.i1).then(|| Footprint {
            x0: int(x.i0) as usize,
            x1: int(x.i1) as usize,
            y0: int(y.i0) as usize,
            y1: int(y.i1) as usize,
            c: [x.c, y.c],
            phase: [x.phase, y.phase],
            tap0: [int(x.skip) as usize, int(y.skip) as usize],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::FilmConfig;
    use nyquist::filter::{Boxcar, Gaussian, Lanczos, Mitchell, Triangle};

    /// The tile over the film's first 16 × 16 pixels.
    fn tile_for(filter: &dyn Filter, config: FilmConfig) -> FilmTile {
        let setup = Arc::new(Setup::new(&config, filter).unwrap());
        let bounds = Bounds::new(0, 0, 16, 16).intersect(&setup.pixel_bounds);
        FilmTile::new(TileSpec { index: 0, bounds }, setup)
    }

    /// Only filters of radius below 2.5 (those of the 4 × 4 path and smaller) store a guard
    /// band outside the film, at most two pixels wide: a film of 8 × 8 pixels with a filter of
    /// radius 1000 stores its 64 pixels, not ~2000².
    #[test]
    fn only_small_radii_store_a_guard_band() {
        let cfg = FilmConfig::new(8, 8);
        let film = Bounds::new(0, 0, 8, 8);
        let wide = tile_for(&Gaussian::new([1000.0, 1000.0], 2.0).unwrap(), cfg);
        assert_eq!(wide.stored_bounds(), film);
        assert_eq!(wide.pixels.len(), 64);
        assert_eq!(tile_for(&Lanczos::default(), cfg).stored_bounds(), film);
        let clamped = FilmConfig {
            max_component: Some(4.0),
            ..cfg
        };
        for c in [cfg, clamped] {
            let m = tile_for(&Mitchell::default(), c);
            assert_eq!(m.stored_bounds(), Bounds::new(-2, -2, 10, 10));
            assert_eq!(m.pixel_bounds(), film);
        }
        let box_tile = tile_for(&Boxcar::default(), cfg);
        assert_eq!(box_tile.stored_bounds(), Bounds::new(-1, -1, 9, 9));
    }

    /// The integration tests compare the 4 × 4 path with the general path; this checks that
    /// the path is chosen for the filters it is meant for, and taken by an interior sample.
    #[test]
    fn block4_is_chosen_for_radius_two_filters_and_taken_inside() {
        let cfg = FilmConfig::new(16, 16);
        let t = tile_for(&Mitchell::default(), cfg);
        assert_eq!(t.fast, FastPath::Block4);
        let FilmTable::Phase(table) = &t.setup.table else {
            panic!("Mitchell has a phase table");
        };
        let taken = |p: [f32; 2]| block4(&t.geometry, table, p).is_some();
        assert!(taken([7.3, 8.6]));
        // At the film's edge too: the guard band stores the footprint's outer pixels.
        assert!(taken([0.7, 8.6]) && taken([15.9, 0.1]));
        // Phase 0 (five pixels along x), past the guard band, NaN: declined.
        assert!(!taken([7.5, 8.6]));
        assert!(!taken([-1.7, 8.6]));
        assert!(!taken([f32::NAN, 8.6]));
        assert_eq!(tile_for(&Triangle::default(), cfg).fast, FastPath::Block4);
        assert_eq!(tile_for(&Lanczos::default(), cfg).fast, FastPath::None);
        assert_eq!(
            tile_for(&Boxcar::default(), cfg).fast,
            FastPath::OnePixel {
                weight: 1.0,
                narrow: false
            }
        );
        let clamped = FilmConfig {
            max_component: Some(4.0),
            ..cfg
        };
        assert_eq!(tile_for(&Mitchell::default(), clamped).fast, FastPath::None);
    }
}
