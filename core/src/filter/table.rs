//! Precomputed filter tables: [`Table`] over its storages, the lookups every form shares, and
//! the lookup kernel [`PhaseTable`](super::PhaseTable) reuses.

use super::{Axis, Filter, Weights};
use crate::Error;
use crate::error::Interval;

/// How a table reads between its sample points.
///
/// ```
/// use nyquist::filter::Interpolation;
/// assert_eq!(Interpolation::default(), Interpolation::Linear);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Interpolation {
    /// The value at the nearest sample point (pbrt-v2/v3's lookup, with centred cells).
    Nearest,
    /// Linear per axis (bilinear for 2D tables) between the two neighbouring sample points.
    #[default]
    Linear,
}

/// Validates a plugin filter's radius for tabulation: each finite and `> 0`, else
/// [`Error::OutOfRange`] naming `"filter radius rx"` or `"filter radius ry"` with `(0, ∞)`.
pub(super) fn table_radius<F: Filter + ?Sized>(filter: &F) -> Result<[f32; 2], Error> {
    let radius = filter.radius();
    for (r, what) in radius
        .into_iter()
        .zip(["filter radius rx", "filter radius ry"])
    {
        if !(r > 0.0 && r <= f32::MAX) {
            return Err(Error::OutOfRange {
                what,
                value: f64::from(r),
                range: Interval::above(0.0),
            });
        }
    }
    Ok(radius)
}

/// The scale from `|offset|` to table coordinates, `(n − 1)/r`, nudged up so that
/// `r · scale ≥ n − 1` (the radius lands on the last sample).
fn table_scale(r: f32, n: usize) -> f32 {
    let last = (n - 1) as f32;
    let mut s = last / r;
    for _ in 0..4 {
        if r * s >= last {
            break;
        }
        s = s.next_up();
    }
    s
}

/// Sample point `i`: the smallest `x` with `x · scale ≥ i` (so `x · scale == i` whenever such
/// an `x` exists, and otherwise exceeds `i` by a rounding error or two, which lookups snap back
/// onto `i`); the last one is the radius itself.
fn table_point(i: usize, n: usize, r: f32, scale: f32) -> f32 {
    if i + 1 >= n {
        return r;
    }
    if i == 0 {
        return 0.0;
    }
    let target = i as f32;
    let mut x = target / scale;
    for _ in 0..16 {
        if x * scale >= target {
            break;
        }
        x = x.next_up();
    }
    for _ in 0..16 {
        if x.next_down() * scale < target {
            break;
        }
        x = x.next_down();
    }
    x
}

/// The largest magnitude a table stores, `2⁶²`: products and interpolations of entries stay
/// finite, so masking them with a 0 factor gives 0, never NaN.
const VALUE_CAP: f32 = 4_611_686_018_427_387_904.0;

/// A filter value made safe for a table: non-finite values (a broken plugin) become 0 and
/// magnitudes are capped at `2⁶²` (no practical filter comes near).
#[inline]
pub(super) fn finite_or_zero(v: f32) -> f32 {
    if v.is_finite() {
        v.clamp(-VALUE_CAP, VALUE_CAP)
    } else {
        0.0
    }
}

/// `1` inside the support, `0` outside, as a factor. Multiplying by it (rather than selecting
/// between the lookup and 0) keeps the lookup unconditional: LLVM turns a select of loaded
/// values into a branch, which mispredicts at every footprint edge. Entries are finite and
/// capped, so the product is exactly ±0 outside.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn mask(inside: bool) -> f32 {
    if inside { 1.0 } else { 0.0 }
}

/// The constants of two table axes whose entries are each all equal (a box filter), else
/// `None`.
fn constant_axes(x: &[f32], y: &[f32]) -> Option<[f32; 2]> {
    let constant = |v: &[f32]| v.iter().all(|&e| e == v[0]).then_some(v[0]);
    Some([constant(x)?, constant(y)?])
}

/// The weight of a table with constant axes `c` at the folded offsets `a = |d|`: what the
/// lookups give there, `(c_x·[a_x ≤ r_x])·(c_y·[a_y ≤ r_y])`, exactly `c_x·c_y` inside (a linear
/// lookup `(1 − t)·c + t·c` can round off `c` by an ulp for `c ≠ 1`; for a box's 1 it is
/// exact, so there the two agree bit for bit), with no table read.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn constant_weight(c: [f32; 2], radius: [f32; 2], ax: f32, ay: f32) -> f32 {
    (c[0] * mask(ax <= radius[0])) * (c[1] * mask(ay <= radius[1]))
}

/// `1.5·2²³`: `c + MAGIC` holds `round(c)` (ties to even) in its low mantissa bits for
/// `−2²² ≤ c < 2²²`, so rounding is two adds and no saturating float-to-int conversion.
pub(super) const MAGIC: f32 = 12_582_912.0;

/// The bits of `MAGIC`: `(c + MAGIC).to_bits() − MAGIC_BITS == round(c)` for `c ≥ −½`.
pub(super) const MAGIC_BITS: u32 = 0x4B40_0000;

/// Per-size constants of a lookup, computed once (a `usize → f32` conversion is not free on
/// x86-64): entries per axis `n`, the last coordinate `n − 1`, the last cell `n − 2` and the
/// snap tolerance `(n − 1)·2⁻²¹`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    n: usize,
    last: f32,
    last_cell: f32,
    eps: f32,
}

impl Grid {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    const fn new(n: usize) -> Grid {
        Grid {
            n,
            last: (n - 1) as f32,
            last_cell: (n - 2) as f32,
            eps: (n - 1) as f32 * (1.0 / 2_097_152.0),
        }
    }

    /// Table coordinate of a folded offset `a = |d|`: `min(a · scale, n − 1)`, in `[0, n − 1]`
    /// for every input (NaN and ∞ give `n − 1`; callers mask them out), so the index arithmetic
    /// never sees them. One `minss`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn coord(&self, a: f32, scale: f32) -> f32 {
        let p = a * scale;
        if p < self.last { p } else { self.last }
    }

    /// Cell `k ∈ [0, n − 2]` and position `t ∈ [0, 1]` of coordinate `c ∈ [0, n − 1]`:
    /// `k = round(min(c − ½, n − 2))`, `t = c − k`. At an integer `c = i` the tie gives `k = i`,
    /// `t = 0` or `k = i − 1`, `t = 1`; `(1 − t)·a + t·b` is exact at both. Sample points sit at
    /// or a rounding error above their index ([`table_point`]), so `t < (n − 1)·2⁻²¹` snaps
    /// to 0. No branches, no bounds on the float side.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn cell(&self, c: f32) -> (usize, f32) {
        let u = c - 0.5;
        let u = if u < self.last_cell {
            u
        } else {
            self.last_cell
        };
        let m = u + MAGIC;
        let k = m.to_bits().wrapping_sub(MAGIC_BITS) as usize;
        let t = c - (m - MAGIC);
        // A multiply by the mask, not a select: LLVM turns the select into a branch per lane.
        let t = t * mask(t >= self.eps);
        (k, t)
    }

    /// Nearest index of coordinate `c ∈ [0, n − 1]`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn nearest(&self, c: f32) -> usize {
        (c + MAGIC).to_bits().wrapping_sub(MAGIC_BITS) as usize
    }
}

/// 1D lookup at table coordinate `c ∈ [0, n − 1]`; `v.len() == g.n ≥ 2`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn lookup_1d(v: &[f32], g: Grid, c: f32, interp: Interpolation) -> f32 {
    match interp {
        Interpolation::Nearest => v[g.nearest(c)],
        Interpolation::Linear => {
            let (k, t) = g.cell(c);
            let ab = &v[k..k + 2];
            // (1 − t)·a + t·b is exact at t = 0 and t = 1.
            (1.0 - t) * ab[0] + t * ab[1]
        }
    }
}

/// 2D lookup in a row-major `n × n` grid (`v[j·n + i]`, `i` along x).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn lookup_2d(v: &[f32], g: Grid, cx: f32, cy: f32, interp: Interpolation) -> f32 {
    let n = g.n;
    match interp {
        Interpolation::Nearest => v[g.nearest(cy) * n + g.nearest(cx)],
        Interpolation::Linear => {
            let (i, tx) = g.cell(cx);
            let (j, ty) = g.cell(cy);
            let r0 = &v[j * n + i..j * n + i + 2];
            let r1 = &v[(j + 1) * n + i..(j + 1) * n + i + 2];
            let a = (1.0 - tx) * r0[0] + tx * r0[1];
            let b = (1.0 - tx) * r1[0] + tx * r1[1];
            (1.0 - ty) * a + ty * b
        }
    }
}

/// One axis of a separable table, masked: the 1D factor at offset `d`, 0 past the radius `r`
/// and for NaN or ∞ (the comparison fails). A select, not a branch.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn factor(v: &[f32], g: Grid, r: f32, scale: f32, interp: Interpolation, d: f32) -> f32 {
    let a = d.abs();
    let w = lookup_1d(v, g, g.coord(a, scale), interp);
    w * mask(a <= r)
}

/// Four 1D factors at once, written stage by stage over `[f32; 4]` so that LLVM's SLP
/// vectoriser packs the arithmetic into 4-wide SIMD; only the index extraction and the loads
/// stay scalar. Lane for lane the same operations as [`factor`], so the same values.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn factor4(v: &[f32], g: Grid, r: f32, scale: f32, interp: Interpolation, d: [f32; 4]) -> [f32; 4] {
    let mut a = [0.0f32; 4];
    let mut c = [0.0f32; 4];
    let mut m = [0.0f32; 4];
    for l in 0..4 {
        a[l] = d[l].abs();
        c[l] = g.coord(a[l], scale);
        m[l] = mask(a[l] <= r);
    }
    let mut w = [0.0f32; 4];
    match interp {
        Interpolation::Nearest => {
            for l in 0..4 {
                w[l] = v[g.nearest(c[l])];
            }
        }
        Interpolation::Linear => {
            let mut k = [0usize; 4];
            let mut t = [0.0f32; 4];
            for l in 0..4 {
                (k[l], t[l]) = g.cell(c[l]);
            }
            let mut lo = [0.0f32; 4];
            let mut hi = [0.0f32; 4];
            for l in 0..4 {
                let ab = &v[k[l]..k[l] + 2];
                (lo[l], hi[l]) = (ab[0], ab[1]);
            }
            for l in 0..4 {
                w[l] = (1.0 - t[l]) * lo[l] + t[l] * hi[l];
            }
        }
    }
    for l in 0..4 {
        w[l] *= m[l];
    }
    w
}

/// Lane offsets of a batch of four consecutive pixels.
const LANE: [f32; 4] = [0.0, 1.0, 2.0, 3.0];

/// `f(d0 + i)` into `out[i]`: four at a time through `f4`, the remainder one at a time
/// through `f1` (the same values). Offsets are `d0 + i` with `i` counted in floats (exact below
/// 2²⁴): the same rounding as `d0 + i as f32`, without an int-to-float conversion per pixel.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn factors_into(
    d0: f32,
    out: &mut [f32],
    f4: impl Fn([f32; 4]) -> [f32; 4],
    f1: impl Fn(f32) -> f32,
) {
    let mut base = 0.0f32;
    let mut chunks = out.chunks_exact_mut(4);
    for chunk in &mut chunks {
        chunk.copy_from_slice(&f4(LANE.map(|l| d0 + (base + l))));
        base += 4.0;
    }
    for w in chunks.into_remainder() {
        *w = f1(d0 + base);
        base += 1.0;
    }
}

/// `out[j·nx + i] = fx(d0[0] + i) · fy(d0[1] + j)`: `nx + ny` factor evaluations (four at a
/// time where possible) and one multiply per weight. `out.len()` is a positive multiple of
/// `nx` (checked by the callers).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn outer_product(
    d0: [f32; 2],
    [nx, ny]: [usize; 2],
    out: &mut [f32],
    fx4: impl Fn([f32; 4]) -> [f32; 4] + Copy,
    fx1: impl Fn(f32) -> f32 + Copy,
    fy4: impl Fn([f32; 4]) -> [f32; 4],
) {
    if nx <= 4 && ny <= 4 {
        // Up to 4 × 4 (radius ≤ 2, the usual filters): one 4-lane evaluation per axis and the
        // rows straight from registers.
        let wx = fx4(LANE.map(|l| d0[0] + l));
        let wy = fy4(LANE.map(|l| d0[1] + l));
        return narrow_outer_product(&wx, &wy, nx, out);
    }
    // Row 0 holds the x factors until it is scaled last.
    let (first, rest) = out.split_at_mut(nx);
    factors_into(d0[0], first, fx4, fx1);
    // Four at a time, then the rest: footprints are a few pixels wide, too short for the
    // compiler's own vectorised loop (with its run-time checks) to pay off.
    let scale_row = |row: &mut [f32], first: &[f32], w: f32| {
        let mut o4 = row.chunks_exact_mut(4);
        let mut x4 = first.chunks_exact(4);
        for (o, x) in (&mut o4).zip(&mut x4) {
            for l in 0..4 {
                o[l] = x[l] * w;
            }
        }
        for (o, &x) in o4.into_remainder().iter_mut().zip(x4.remainder()) {
            *o = x * w;
        }
    };
    // The y factors four rows at a time (lanes past the last row are computed and dropped);
    // row 0's factor is kept for last. j counted in floats as above.
    let mut r = 0;
    let mut wy0 = 0.0;
    let mut j = 0.0f32;
    for j0 in (0..ny).step_by(4) {
        let wy = fy4(LANE.map(|l| d0[1] + (j + l)));
        j += 4.0;
        let skip = if j0 == 0 {
            wy0 = wy[0];
            1
        } else {
            0
        };
        for &w in &wy[skip..(ny - j0).min(4)] {
            if let Some(row) = rest.get_mut(r * nx..(r + 1) * nx) {
                scale_row(row, first, w);
            }
            r += 1;
        }
    }
    for w in first.iter_mut() {
        *w *= wy0;
    }
}

/// `out[j·nx + i] = fx[i] · fy[j]` for a footprint at most 4 wide (`1 ≤ nx ≤ 4`), one row per
/// `fy` entry while `out` lasts: the rows straight from registers, fully unrolled at width 4.
/// Shared by the 4 × 4 paths of the table and phase-table footprints.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn narrow_outer_product(fx: &[f32; 4], fy: &[f32; 4], nx: usize, out: &mut [f32]) {
    if nx == 4 {
        if let Ok(all) = <&mut [[f32; 4]; 4]>::try_from(out.as_chunks_mut::<4>().0) {
            // Exactly 4 × 4 (a radius-2 footprint): four rows, each one vector product.
            for (row, &w) in all.iter_mut().zip(fy) {
                *row = fx.map(|x| x * w);
            }
            return;
        }
        for (row, &w) in out.chunks_exact_mut(4).zip(fy) {
            for l in 0..4 {
                row[l] = fx[l] * w;
            }
        }
    } else {
        for (row, &w) in out.chunks_exact_mut(nx).zip(fy) {
            for (o, &x) in row.iter_mut().zip(fx) {
                *o = x * w;
            }
        }
    }
}

/// Below this many weights a footprint is filled weight by weight: the outer product's setup
/// (eight lookups at least) costs more than it saves.
const SMALL_FOOTPRINT: usize = 4;

/// The one-weight footprint (`nx == 1`, one entry: a box of radius ½, nearly always), which
/// every table's `footprint` answers with a single `weight(d0)` inlined into the caller, ahead of
/// its general path and that path's set-up: the entry to fill, if `out` is that footprint.
/// Every other valid footprint has more than one weight (`check_footprint`). (A slot, not a
/// closure to call: LLVM left such a closure out of line, a call per footprint.)
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn one_weight(nx: usize, out: &mut [f32]) -> Option<&mut f32> {
    match (out, nx) {
        ([w], 1) => Some(w),
        _ => None,
    }
}

/// `out[j·nx + i] = weight(d0[0] + i, d0[1] + j)`, one lookup per weight (2D tables and tiny
/// footprints). Offsets counted in floats as in [`factors_into`].
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn per_weight(
    d0: [f32; 2],
    [nx, ny]: [usize; 2],
    out: &mut [f32],
    weight: impl Fn(f32, f32) -> f32,
) {
    let mut j = 0.0f32;
    for r in 0..ny {
        let Some(row) = out.get_mut(r * nx..(r + 1) * nx) else {
            return;
        };
        let dy = d0[1] + j;
        let mut i = 0.0f32;
        for w in row.iter_mut() {
            *w = weight(d0[0] + i, dy);
            i += 1.0;
        }
        j += 1.0;
    }
}

/// The footprint's length check: `out.len()` a positive multiple of `nx`; returns the row count
/// `ny`. Square footprints (symmetric filters, the usual case) are recognised by a multiply, so
/// the film's hot path divides nothing.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn check_footprint(nx: usize, out: &[f32]) -> Result<usize, Error> {
    let len = out.len();
    if nx != 0 && len != 0 {
        if nx.checked_mul(nx) == Some(len) {
            return Ok(nx);
        }
        if len.is_multiple_of(nx) {
            return Ok(len / nx);
        }
    }
    Err(Error::BufferLength {
        multiple_of: nx,
        actual: len,
    })
}

/// The batch check: `dy` and `out` as long as `dx`.
fn check_batch(dx: &[f32], dy: &[f32], out: &[f32]) -> Result<(), Error> {
    for len in [dy.len(), out.len()] {
        if len != dx.len() {
            return Err(Error::BufferLength {
                multiple_of: dx.len(),
                actual: len,
            });
        }
    }
    Ok(())
}

/// `out[i] = fx(dx[i]) · fy(dy[i])`: four at a time through `f4`, the rest through `f1`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn separable_batch(
    dx: &[f32],
    dy: &[f32],
    out: &mut [f32],
    f4: impl Fn([f32; 4], [f32; 4]) -> [f32; 4],
    f1: impl Fn(f32, f32) -> f32,
) {
    let (x4, xr) = dx.as_chunks::<4>();
    let (y4, yr) = dy.as_chunks::<4>();
    let (o4, or) = out.as_chunks_mut::<4>();
    for ((o, x), y) in o4.iter_mut().zip(x4).zip(y4) {
        *o = f4(*x, *y);
    }
    for ((o, &x), &y) in or.iter_mut().zip(xr).zip(yr) {
        *o = f1(x, y);
    }
}

/// Where a [`Table`]'s entries live. Each storage is one form of table; the lookups are the
/// same code over all of them ([`Table`]).
///
/// ```
/// use nyquist::filter::{storage, FilterTable, Interpolation, Mitchell, Table};
/// // `FilterTable<16>` is the table over `storage::Either<16>`.
/// let t: Table<storage::Either<16>> = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
/// assert_eq!(t.len(), 16);
/// ```
pub mod storage {
    use super::{Entries, Grid};

    /// The storages of a [`Table`](super::Table). Sealed: the four below are all there are.
    pub trait Storage: sealed::Sealed {}

    impl<T: sealed::Sealed> Storage for T {}

    pub(super) mod sealed {
        use super::super::{Entries, Grid};

        /// What the lookups read from a storage: the per-size constants and the entries.
        pub trait Sealed {
            /// The lookup constants of the entries' size (a constant for the inline forms).
            fn grid(&self) -> Grid;
            /// The entries: two 1D tables or one row-major 2D table.
            fn entries(&self) -> Entries<'_>;
        }
    }

    /// Two inline 1D tables of `N` entries each, x then y: the storage of
    /// [`SeparableTable`](super::SeparableTable). Allocates: no.
    ///
    /// ```
    /// use nyquist::filter::storage;
    /// assert_eq!(size_of::<storage::Separable<16>>(), 2 * 16 * 4);
    /// ```
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Separable<const N: usize>(pub(super) [[f32; N]; 2]);

    /// One inline `N × N` table, row-major (`[j][i]`, `i` along x): the storage of
    /// [`Table2d`](super::Table2d). Allocates: no.
    ///
    /// ```
    /// use nyquist::filter::storage;
    /// assert_eq!(size_of::<storage::Full<16>>(), 16 * 16 * 4);
    /// ```
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Full<const N: usize>(pub(super) [[f32; N]; N]);

    /// [`Separable`] or [`Full`], chosen by the filter when the table is built: the storage of
    /// [`FilterTable`](super::FilterTable). As large as the larger, [`Full`]. Allocates: no.
    ///
    /// ```
    /// use nyquist::filter::storage;
    /// assert!(size_of::<storage::Either<16>>() >= size_of::<storage::Full<16>>());
    /// ```
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Either<const N: usize>(pub(super) EitherForm<N>);

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub(super) enum EitherForm<const N: usize> {
        Separable([[f32; N]; 2]),
        Full([[f32; N]; N]),
    }

    /// The entries of any other storage, borrowed, with their size held as a value rather than
    /// a type parameter: the storage of [`TableView`](super::TableView). `Copy`: a pointer or
    /// two and a few numbers.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Triangle};
    /// let t: FilterTable<64> = FilterTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// let v = t.view(); // a Table<storage::View<'_>>
    /// assert_eq!((v.len(), v.weight(0.0, 0.0)), (64, 4.0));
    /// ```
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct View<'a> {
        pub(super) grid: Grid,
        pub(super) entries: Entries<'a>,
    }

    impl<const N: usize> sealed::Sealed for Separable<N> {
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn grid(&self) -> Grid {
            const { Grid::new(N) }
        }
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn entries(&self) -> Entries<'_> {
            Entries::Separable(&self.0[0], &self.0[1])
        }
    }

    impl<const N: usize> sealed::Sealed for Full<N> {
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn grid(&self) -> Grid {
            const { Grid::new(N) }
        }
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn entries(&self) -> Entries<'_> {
            Entries::Full(self.0.as_flattened())
        }
    }

    impl<const N: usize> sealed::Sealed for Either<N> {
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn grid(&self) -> Grid {
            const { Grid::new(N) }
        }
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn entries(&self) -> Entries<'_> {
            match &self.0 {
                EitherForm::Separable([x, y]) => Entries::Separable(x, y),
                EitherForm::Full(v) => Entries::Full(v.as_flattened()),
            }
        }
    }

    impl sealed::Sealed for View<'_> {
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn grid(&self) -> Grid {
            self.grid
        }
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn entries(&self) -> Entries<'_> {
            self.entries
        }
    }
}

use storage::{Either, EitherForm, Full, Separable, Storage, View};

/// A table's entries as the lookups read them: two 1D tables (x, y) of `n` entries each, or one
/// row-major `n × n` table (`v[j·n + i]`, `i` along x).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Entries<'a> {
    /// The x and the y table.
    Separable(&'a [f32], &'a [f32]),
    /// The 2D table.
    Full(&'a [f32]),
}

/// A filter tabulated for branch-free lookups: the one implementation behind every table form
/// (below), over a storage `S` ([`storage`]).
///
/// A table samples the filter at `N` points per axis, `xᵢ ≈ i·r/(N − 1)` for `i = 0 … N − 1`
/// (both the centre and the radius are sample points), over the quadrant `[0, rx] × [0, ry]`;
/// lookups fold the offset with `|·|`, so the filter is assumed even on each axis (pbrt-v2/v3
/// make the same assumption; every practical reconstruction filter is).
///
/// Lookups are exactly 0 past the radius and for NaN or infinite offsets, and exact (bit for
/// bit) at the sample points: `weight(xᵢ, yⱼ) == eval(xᵢ, yⱼ)` where `xᵢ` is
/// [`sample_point`](Table::sample_point). Elsewhere the error against direct evaluation
/// at the default size, measured over a 2001 × 2001 grid on `[−r, r]²` (the test
/// `documented_table_error_bounds` holds these bounds):
///
/// | filter (defaults) | peak | nearest: max abs error | linear: max abs error |
/// |---|---|---|---|
/// | box, r = ½ | 1 | 0 | 0 |
/// | triangle, r = 2 | 4 | 0.26 | 7.2e-7 (rounding only) |
/// | gaussian, r = 2, α = 2 | 1 | 0.113 | 0.0171 |
/// | mitchell, r = 2, B = C = ⅓ | 0.79 | 0.089 | 0.0138 |
/// | lanczos, r = 4, τ = 3 | 1 | 0.223 | 0.0575 |
///
/// Linear error falls about 4× per doubling of `N` (Lanczos at `N = 256`: below 5·10⁻⁴).
/// Linear interpolation is the default ([`Interpolation::Linear`]); it is exact for the box and
/// the triangle (piecewise bilinear) and costs one more multiply-add per axis.
///
/// # One implementation over four storages
///
/// The lookups are written once, over a storage `S` that only says where the entries live
/// ([`storage`]), as heapless writes `Vec<T, N>` and `VecView<T>` once over one `VecInner`. Each
/// table form is an alias of `Table` over one storage, and the same lookup gives the same bits
/// through every form:
///
/// | type | storage | entries |
/// |---|---|---|
/// | [`SeparableTable<N>`] | [`storage::Separable<N>`] | two inline 1D tables (`2·N` floats) |
/// | [`Table2d<N>`] | [`storage::Full<N>`] | one inline 2D table (`N²` floats), for any filter |
/// | [`FilterTable<N>`] | [`storage::Either<N>`] | either, chosen by the filter at construction |
/// | [`TableView<'a>`](TableView) | [`storage::View<'a>`](storage::View) | borrowed from any of them, with no `N` in the type |
///
/// All of them, [`PhaseTable`](super::PhaseTable) and [`FilmTable`](super::FilmTable)
/// implement [`Weights`](super::Weights), the interface a film accumulates through.
///
/// # Table size
///
/// `N` defaults to 16, pbrt-v2/v3's size and the C API's (`NYQ_FILTER_TABLE_SIZE`), for which the
/// error table above is given. Tables are stored inline, on the caller's stack or in a static:
/// a `Table2d<16>` holds 1 KB of entries, a `Table2d<64>` 16 KB, more stack than many embedded
/// targets (this crate's `no_std`, no-alloc users) can spare. A film is the other case: each
/// pixel is a weighted mean of many samples, so the table's interpolation error does not average
/// out but biases the converged image: where a film does not read a phase table it reads 64
/// entries per axis ([`FilmTable`](super::FilmTable)'s default, a linear error about 16× below
/// 16 entries').
/// Choose `N` per table: `FilterTable::<64>::new(…)`.
///
/// # Speed
///
/// Every lookup is branch-free apart from never-taken bounds checks: the coordinate is clamped
/// with one `min`, the cell found by the `1.5·2²³` rounding trick (no saturating float-to-int
/// conversion), and the radius test is a 0/1 factor, so NaN and offsets past the radius cost
/// the same as any other. Entries are finite and capped at `2⁶²`, so that factor yields an
/// exact 0. A single [`weight`](Table::weight) costs about as much as evaluating a cheap filter
/// directly. The fast path is [`footprint`](Table::footprint): it computes the `nx` x factors
/// and `ny` y factors of one sample, four lanes at a time, and writes their outer product, a
/// fraction of a lookup per weight for separable tables; a one-weight footprint of a constant
/// table (a box) answers the constant without reading the table. Code that accumulates pixel by
/// pixel can do the same with [`weight_1d`](SeparableTable::weight_1d) per row and column.
/// Measured figures, and the command that measures them, are in `docs/performance.md` (section
/// "Filter tables").
///
/// # Examples
///
/// ```
/// use nyquist::filter::{Filter, FilterTable, Interpolation, Lanczos};
/// let l = Lanczos::default();
/// let table: FilterTable = FilterTable::new(&l, Interpolation::Linear).unwrap();
/// assert!(table.is_separable());
/// assert!((table.weight(1.3, -0.2) - l.eval(1.3, -0.2)).abs() <= 0.0575);
/// assert_eq!(table.weight(4.001, 0.0), 0.0);
/// assert_eq!(table.view().weight(1.3, -0.2), table.weight(1.3, -0.2));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Table<S> {
    radius: [f32; 2],
    scale: [f32; 2],
    integral: f32,
    interp: Interpolation,
    /// Each axis's value when every entry of both axes equals its axis's first (a box; separable
    /// entries only): a one-weight [`footprint`](Table::footprint) then answers it with no
    /// lookup. (Checked in `weight` itself, the branch slowed every other table's lookup by a
    /// fifth.)
    constant: Option<[f32; 2]>,
    values: S,
}

/// A separable filter's table: two 1D tables of `N` entries each (default 16, see the
/// [`Table`] docs), stored inline. Allocates: no; size `8·N + 36` bytes.
///
/// # Examples
///
/// ```
/// use nyquist::filter::{Filter, Gaussian, Interpolation, SeparableTable};
/// let g = Gaussian::default();
/// let t: SeparableTable = SeparableTable::new(&g, Interpolation::Linear).unwrap();
/// assert!((t.weight(0.3, 1.1) - g.eval(0.3, 1.1)).abs() <= 0.0171);
/// assert_eq!(t.weight(2.01, 0.0), 0.0);
/// assert_eq!(size_of::<SeparableTable<16>>(), 8 * 16 + 36);
/// ```
pub type SeparableTable<const N: usize = 16> = Table<Separable<N>>;

/// A full 2D table of `N × N` entries (default 16 × 16) over `[0, rx] × [0, ry]`, for filters
/// that are not separable. Allocates: no; size `4·N² + 36` bytes.
///
/// ```
/// use nyquist::filter::{Filter, Interpolation, Table2d, Triangle};
/// // Any filter can use a 2D table, separable or not.
/// let t: Table2d = Table2d::new(&Triangle::default(), Interpolation::Linear).unwrap();
/// assert!((t.weight(0.3, 1.7) - Triangle::default().eval(0.3, 1.7)).abs() < 1e-5);
/// assert_eq!(size_of::<Table2d<16>>(), 4 * 16 * 16 + 36);
/// ```
pub type Table2d<const N: usize = 16> = Table<Full<N>>;

/// A filter table that picks its layout: two 1D tables ([`SeparableTable`]'s) for separable
/// filters, a 2D table ([`Table2d`]'s) otherwise. As large as a [`Table2d<N>`]. Allocates: no.
///
/// ```
/// use nyquist::filter::{Filter, FilterTable, Interpolation, Lanczos};
/// let l = Lanczos::default();
/// let table: FilterTable = FilterTable::new(&l, Interpolation::Linear).unwrap();
/// assert!(table.is_separable());
/// assert!((table.weight(1.3, -0.2) - l.eval(1.3, -0.2)).abs() <= 0.0575);
/// assert_eq!(table.weight(4.001, 0.0), 0.0);
/// ```
pub type FilterTable<const N: usize = 16> = Table<Either<N>>;

/// A borrowed, size-erased view of any table ([`FilterTable`], [`SeparableTable`],
/// [`Table2d`]): the same lookups, without the const generic. `Copy`; from
/// [`Table::view`].
///
/// ```
/// use nyquist::filter::{FilterTable, Interpolation, TableView, Triangle};
/// fn centre(view: TableView<'_>) -> f32 { view.weight(0.0, 0.0) }
/// let t: FilterTable<64> = FilterTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
/// assert_eq!(centre(t.view()), 4.0);
/// ```
pub type TableView<'a> = Table<View<'a>>;

/// Validates the filter and tabulates it: the radius (finite and `> 0`), the separable form
/// when `separable` asks for it, the scale for `n` entries per axis, then `values(radius,
/// scale)` and the integral.
fn tabulate<F: Filter + ?Sized, S>(
    filter: &F,
    interp: Interpolation,
    n: usize,
    separable: bool,
    values: impl FnOnce([f32; 2], [f32; 2]) -> S,
) -> Result<Table<S>, Error> {
    let radius = table_radius(filter)?;
    let integral = super::check_integral(filter.integral())?;
    if separable && !filter.is_separable() {
        return Err(Error::NotSeparable {
            what: "separable table",
        });
    }
    let scale = [table_scale(radius[0], n), table_scale(radius[1], n)];
    let values = values(radius, scale);
    Ok(Table {
        radius,
        scale,
        integral,
        interp,
        constant: None,
        values,
    })
}

/// `2 ≤ N < 2²²`, checked at compile time by the constructors.
const fn check_size<const N: usize>() {
    assert!(
        N >= 2 && N < 1 << 22,
        "a filter table needs 2 ≤ N < 2²² entries per axis"
    );
}

impl<const N: usize> SeparableTable<N> {
    /// Tabulates `filter`'s separable form ([`Filter::eval_1d`]) at `N` points per axis, and
    /// stores [`Filter::integral`]. `N < 2` (or `N ≥ 2²²`) does not compile.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter's radius is not finite and `> 0` (`what` is
    /// `"filter radius rx"` or `"filter radius ry"`, the range `(0, ∞)`);
    /// [`Error::NotSeparable`] if the filter is not separable. Non-finite values from a plugin
    /// filter are stored as 0, magnitudes above 2⁶² as ±2⁶².
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
    /// let t = SeparableTable::<32>::new(&Mitchell::default(), Interpolation::Nearest).unwrap();
    /// assert_eq!(t.radius(), [2.0, 2.0]);
    /// ```
    ///
    /// One entry per axis is refused when the program is compiled:
    ///
    /// ```compile_fail
    /// use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
    /// let t = SeparableTable::<1>::new(&Mitchell::default(), Interpolation::Nearest);
    /// ```
    pub fn new<F: Filter + ?Sized>(
        filter: &F,
        interp: Interpolation,
    ) -> Result<SeparableTable<N>, Error> {
        const { check_size::<N>() };
        let mut table = tabulate(filter, interp, N, true, |radius, scale| {
            let mut values = [[0.0f32; N]; 2];
            for (a, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
                for (i, v) in values[a].iter_mut().enumerate() {
                    let x = table_point(i, N, radius[a], scale[a]);
                    *v = finite_or_zero(filter.eval_1d(axis, x).unwrap_or(0.0));
                }
            }
            Separable(values)
        })?;
        let [x, y] = &table.values.0;
        table.constant = constant_axes(x, y);
        Ok(table)
    }

    /// The 1D factor along `axis` at offset `d`, so that
    /// `weight(dx, dy) == weight_1d(X, dx) * weight_1d(Y, dy)` (the same product). (The
    /// [`Weights`] form returns it as `Some`, as other tables may have no such factor.)
    ///
    /// ```
    /// use nyquist::filter::{Axis, Interpolation, SeparableTable, Triangle};
    /// let t: SeparableTable = SeparableTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight_1d(Axis::X, 0.5) * t.weight_1d(Axis::Y, 1.5), t.weight(0.5, 1.5));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> f32 {
        let a = axis.index();
        let v = &self.values.0[a];
        factor(
            v,
            const { Grid::new(N) },
            self.radius[a],
            self.scale[a],
            self.interp,
            d,
        )
    }

    /// The stored values along `axis`: entry `i` is the filter's 1D factor at
    /// [`sample_point(axis, i)`](Table::sample_point).
    ///
    /// ```
    /// use nyquist::filter::{Axis, Boxcar, Interpolation, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.values(Axis::X), &[1.0; 16]);
    /// ```
    pub fn values(&self, axis: Axis) -> &[f32; N] {
        &self.values.0[axis.index()]
    }
}

impl<const N: usize> Table2d<N> {
    /// Tabulates `filter.eval` at `N × N` points and stores [`Filter::integral`]. `N < 2` (or
    /// `N ≥ 2²²`) does not compile.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter's radius is not finite and `> 0`. Non-finite values
    /// from a plugin filter are stored as 0, magnitudes above 2⁶² as ±2⁶².
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, Interpolation, Table2d};
    /// assert!(Table2d::<8>::new(&Boxcar::default(), Interpolation::Nearest).is_ok());
    /// ```
    pub fn new<F: Filter + ?Sized>(filter: &F, interp: Interpolation) -> Result<Table2d<N>, Error> {
        const { check_size::<N>() };
        tabulate(filter, interp, N, false, |radius, scale| {
            let mut values = [[0.0f32; N]; N];
            for (j, row) in values.iter_mut().enumerate() {
                let y = table_point(j, N, radius[1], scale[1]);
                for (i, v) in row.iter_mut().enumerate() {
                    let x = table_point(i, N, radius[0], scale[0]);
                    *v = finite_or_zero(filter.eval(x, y));
                }
            }
            Full(values)
        })
    }

    /// The stored values, `values()[j][i]` at ([`sample_point(X, i)`](Table::sample_point),
    /// `sample_point(Y, j)`).
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, Interpolation, Table2d};
    /// let t: Table2d<4> = Table2d::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.values(), &[[1.0; 4]; 4]);
    /// ```
    pub fn values(&self) -> &[[f32; N]; N] {
        &self.values.0
    }
}

impl<const N: usize> FilterTable<N> {
    /// Tabulates any filter, built-in or plugin, in one call: separable filters get two 1D
    /// tables ([`SeparableTable::new`]), others a 2D table ([`Table2d::new`]).
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter's radius is not finite and `> 0`.
    ///
    /// ```
    /// use nyquist::filter::{Filter, FilterKind, FilterTable, Interpolation};
    /// let f = FilterKind::parse("gaussian:sigma=0.5").unwrap();
    /// let t = FilterTable::<16>::new(&f as &dyn Filter, Interpolation::Nearest).unwrap();
    /// assert_eq!(t.weight(0.0, 0.0), f.eval(0.0, 0.0));
    /// ```
    pub fn new<F: Filter + ?Sized>(
        filter: &F,
        interp: Interpolation,
    ) -> Result<FilterTable<N>, Error> {
        if filter.is_separable() {
            SeparableTable::new(filter, interp).map(FilterTable::from)
        } else {
            Table2d::new(filter, interp).map(FilterTable::from)
        }
    }

    /// The 1D factor along `axis` when the table is separable (see
    /// [`SeparableTable::weight_1d`]), `None` for a 2D table.
    ///
    /// ```
    /// use nyquist::filter::{Axis, Boxcar, FilterTable, Interpolation};
    /// let t: FilterTable = FilterTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight_1d(Axis::Y, 0.6), Some(0.0));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        self.factor_1d(axis, d)
    }
}

impl<const N: usize> From<SeparableTable<N>> for FilterTable<N> {
    /// The same table, as a [`FilterTable`]: the same lookups, bit for bit.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Mitchell, SeparableTable};
    /// let t = SeparableTable::<16>::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(FilterTable::from(t).weight(0.3, 0.7), t.weight(0.3, 0.7));
    /// ```
    fn from(t: SeparableTable<N>) -> FilterTable<N> {
        t.with_values(Either(EitherForm::Separable(t.values.0)))
    }
}

impl<const N: usize> From<Table2d<N>> for FilterTable<N> {
    /// The same table, as a [`FilterTable`]: the same lookups, bit for bit.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterTable, Interpolation, Table2d};
    /// let t = Table2d::<8>::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert!(!FilterTable::from(t).is_separable());
    /// ```
    fn from(t: Table2d<N>) -> FilterTable<N> {
        t.with_values(Either(EitherForm::Full(t.values.0)))
    }
}

impl TableView<'_> {
    /// The 1D factor along `axis` for separable tables (so `weight(dx, dy) ==
    /// weight_1d(X, dx)·weight_1d(Y, dy)`, the same product), `None` for 2D tables.
    ///
    /// ```
    /// use nyquist::filter::{Axis, FilterTable, Interpolation, Mitchell};
    /// let t: FilterTable = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// let v = t.view();
    /// let w = v.weight_1d(Axis::X, 0.3).unwrap() * v.weight_1d(Axis::Y, 1.2).unwrap();
    /// assert_eq!(w, v.weight(0.3, 1.2));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        self.factor_1d(axis, d)
    }
}

impl<S> Table<S> {
    /// This table's header over other values.
    fn with_values<T>(&self, values: T) -> Table<T> {
        Table {
            radius: self.radius,
            scale: self.scale,
            integral: self.integral,
            interp: self.interp,
            constant: self.constant,
            values,
        }
    }
}

impl<S: Storage> Table<S> {
    /// The weight at offset `(dx, dy)` from the pixel centre: the product of the two 1D lookups
    /// for separable entries, one 2D lookup otherwise. 0 past the radius and for NaN or
    /// infinite offsets; exact at the sample points.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, Interpolation, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight(0.25, -0.5), 1.0);
    /// assert_eq!(t.weight(f32::NAN, 0.0), 0.0);
    /// assert_eq!(t.view().weight(f32::INFINITY, 0.0), 0.0);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn weight(&self, dx: f32, dy: f32) -> f32 {
        let (ax, ay) = (dx.abs(), dy.abs());
        // Look up unconditionally (coordinates are clamped), then mask: no branch to mispredict.
        let (mx, my) = (mask(ax <= self.radius[0]), mask(ay <= self.radius[1]));
        let g = self.values.grid();
        let cx = g.coord(ax, self.scale[0]);
        let cy = g.coord(ay, self.scale[1]);
        match self.values.entries() {
            Entries::Separable(x, y) => {
                (lookup_1d(x, g, cx, self.interp) * mx) * (lookup_1d(y, g, cy, self.interp) * my)
            }
            Entries::Full(v) => lookup_2d(v, g, cx, cy, self.interp) * (mx * my),
        }
    }

    /// The 1D factor along `axis` of separable entries, `None` for 2D entries.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn factor_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        let Entries::Separable(x, y) = self.values.entries() else {
            return None;
        };
        let a = axis.index();
        let v = if a == 0 { x } else { y };
        Some(factor(
            v,
            self.values.grid(),
            self.radius[a],
            self.scale[a],
            self.interp,
            d,
        ))
    }

    /// The weights at many offsets at once: `out[i] = weight(dx[i], dy[i])`, the same values as
    /// per-offset [`weight`](Self::weight) calls, four lanes at a time for separable entries (for
    /// splatting batches of samples, or evaluating the filter over any set of points).
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `dy` and `out` are as long as `dx`.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// let (dx, dy) = ([0.1, -1.3, 2.5, 0.7, f32::NAN], [0.0, 0.4, 0.2, -1.9, 0.0]);
    /// let mut w = [0.0f32; 5];
    /// t.weights(&dx, &dy, &mut w).unwrap();
    /// assert!((0..5).all(|i| w[i] == t.weight(dx[i], dy[i])));
    /// assert!(t.weights(&dx, &dy[..4], &mut w).is_err());
    /// ```
    pub fn weights(&self, dx: &[f32], dy: &[f32], out: &mut [f32]) -> Result<(), Error> {
        check_batch(dx, dy, out)?;
        let g = self.values.grid();
        match self.values.entries() {
            Entries::Separable(vx, vy) => {
                let ([rx, ry], [sx, sy]) = (self.radius, self.scale);
                let product =
                    |a: [f32; 4], b: [f32; 4]| [a[0] * b[0], a[1] * b[1], a[2] * b[2], a[3] * b[3]];
                // The two arms are spelled out: folding them into one closure taking the
                // interpolation measured 2× slower (the loop was no longer specialised).
                match self.interp {
                    Interpolation::Nearest => separable_batch(
                        dx,
                        dy,
                        out,
                        |x, y| {
                            product(
                                factor4(vx, g, rx, sx, Interpolation::Nearest, x),
                                factor4(vy, g, ry, sy, Interpolation::Nearest, y),
                            )
                        },
                        |x, y| self.weight(x, y),
                    ),
                    Interpolation::Linear => separable_batch(
                        dx,
                        dy,
                        out,
                        |x, y| {
                            product(
                                factor4(vx, g, rx, sx, Interpolation::Linear, x),
                                factor4(vy, g, ry, sy, Interpolation::Linear, y),
                            )
                        },
                        |x, y| self.weight(x, y),
                    ),
                }
            }
            Entries::Full(_) => {
                for ((o, &x), &y) in out.iter_mut().zip(dx).zip(dy) {
                    *o = self.weight(x, y);
                }
            }
        }
        Ok(())
    }

    /// The weights of a whole footprint at once: `out[j·nx + i] = weight(d0[0] + i, d0[1] + j)`
    /// for `j < out.len() / nx`, the offsets from one sample to a block of pixel centres.
    /// Identical to calling [`weight`](Self::weight) per entry, but separable entries take
    /// `nx + ny` 1D lookups and one multiply per weight, well under a lookup per weight: the
    /// film's fast path. 2D entries take one lookup per weight.
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `out.len()` is a positive multiple of `nx`.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Lanczos, Mitchell};
    /// let t: FilterTable = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// let mut w = [0.0f32; 16];
    /// t.footprint([-1.7, -1.2], 4, &mut w).unwrap();
    /// assert_eq!(w[2 * 4 + 3], t.weight(-1.7 + 3.0, -1.2 + 2.0));
    /// let l: FilterTable = FilterTable::new(&Lanczos::default(), Interpolation::Linear).unwrap();
    /// let mut w = [0.0f32; 8 * 8];
    /// l.view().footprint([-3.6, -3.1], 8, &mut w).unwrap();
    /// assert_eq!(w[5 * 8 + 2], l.weight(-3.6 + 2.0, -3.1 + 5.0));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        if let Some(w) = one_weight(nx, &mut *out) {
            // A constant table (a box) answers its constant, exactly and with no lookup.
            *w = match self.constant {
                Some(c) => constant_weight(c, self.radius, d0[0].abs(), d0[1].abs()),
                None => self.weight(d0[0], d0[1]),
            };
            return Ok(());
        }
        self.footprint_many(d0, nx, out)
    }

    /// [`footprint`](Self::footprint) past the one-weight case.
    #[inline]
    fn footprint_many(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        let ny = check_footprint(nx, out)?;
        let g = self.values.grid();
        match self.values.entries() {
            Entries::Separable(..) if out.len() < SMALL_FOOTPRINT => {
                per_weight(
                    d0,
                    [nx, ny],
                    out,
                    #[cfg_attr(not(feature = "small-code"), inline(always))]
                    |x, y| self.weight(x, y),
                );
            }
            Entries::Separable(vx, vy) => {
                let ([rx, ry], [sx, sy]) = (self.radius, self.scale);
                // One dispatch per footprint, then monomorphic loops.
                match self.interp {
                    Interpolation::Nearest => outer_product(
                        d0,
                        [nx, ny],
                        out,
                        #[cfg_attr(not(feature = "small-code"), inline(always))]
                        |d| factor4(vx, g, rx, sx, Interpolation::Nearest, d),
                        #[cfg_attr(not(feature = "small-code"), inline(always))]
                        |d| factor(vx, g, rx, sx, Interpolation::Nearest, d),
                        #[cfg_attr(not(feature = "small-code"), inline(always))]
                        |d| factor4(vy, g, ry, sy, Interpolation::Nearest, d),
                    ),
                    Interpolation::Linear => outer_product(
                        d0,
                        [nx, ny],
                        out,
                        #[cfg_attr(not(feature = "small-code"), inline(always))]
                        |d| factor4(vx, g, rx, sx, Interpolation::Linear, d),
                        #[cfg_attr(not(feature = "small-code"), inline(always))]
                        |d| factor(vx, g, rx, sx, Interpolation::Linear, d),
                        #[cfg_attr(not(feature = "small-code"), inline(always))]
                        |d| factor4(vy, g, ry, sy, Interpolation::Linear, d),
                    ),
                }
            }
            Entries::Full(_) => per_weight(
                d0,
                [nx, ny],
                out,
                #[cfg_attr(not(feature = "small-code"), inline(always))]
                |x, y| self.weight(x, y),
            ),
        }
        Ok(())
    }

    /// Whether the entries are two 1D tables (then `weight` is the product of two
    /// [`weight_1d`](SeparableTable::weight_1d) factors).
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Mitchell, Table2d};
    /// let t: FilterTable = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// assert!(t.is_separable() && t.view().is_separable());
    /// let full: Table2d = Table2d::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// assert!(!full.is_separable());
    /// ```
    pub fn is_separable(&self) -> bool {
        matches!(self.values.entries(), Entries::Separable(..))
    }

    /// Entries per axis (`N`).
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Mitchell};
    /// let t: FilterTable<32> = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// assert_eq!((t.len(), t.view().len()), (32, 32));
    /// ```
    #[allow(clippy::len_without_is_empty)] // never empty: N ≥ 2
    pub fn len(&self) -> usize {
        self.values.grid().n
    }

    /// The offset of sample `i` along `axis` (`i ≥ len()` gives the radius).
    ///
    /// ```
    /// use nyquist::filter::{Axis, FilterTable, Interpolation, Triangle};
    /// let t: FilterTable = FilterTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.sample_point(Axis::X, 0), 0.0);
    /// assert_eq!(t.sample_point(Axis::X, 15), 2.0);
    /// assert_eq!(t.view().sample_point(Axis::Y, 99), 2.0);
    /// ```
    pub fn sample_point(&self, axis: Axis, i: usize) -> f32 {
        let a = axis.index();
        let n = self.len();
        table_point(i.min(n - 1), n, self.radius[a], self.scale[a])
    }

    /// The stored weight at sample `(i, j)` (indices clamped to `len() − 1`): the product of the
    /// two 1D entries, or the 2D entry.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Triangle};
    /// let t: FilterTable = FilterTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.entry(0, 0), 4.0);
    /// assert_eq!(t.view().entry(99, 0), 0.0);
    /// ```
    pub fn entry(&self, i: usize, j: usize) -> f32 {
        let n = self.len();
        let (i, j) = (i.min(n - 1), j.min(n - 1));
        match self.values.entries() {
            Entries::Separable(x, y) => x[i] * y[j],
            Entries::Full(v) => v[j * n + i],
        }
    }

    /// The filter's radius `[rx, ry]`.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Lanczos, Table2d};
    /// let t: Table2d = Table2d::new(&Lanczos::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.radius(), [4.0, 4.0]);
    /// ```
    pub fn radius(&self) -> [f32; 2] {
        self.radius
    }

    /// The filter's integral (from [`Filter::integral`] at build time).
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterTable, Interpolation};
    /// let t: FilterTable = FilterTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.integral(), 1.0);
    /// ```
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// The interpolation chosen at build time.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterTable, Interpolation};
    /// let t: FilterTable = FilterTable::new(&Boxcar::default(), Interpolation::Nearest).unwrap();
    /// assert_eq!(t.interpolation(), Interpolation::Nearest);
    /// ```
    pub fn interpolation(&self) -> Interpolation {
        self.interp
    }

    /// A borrowed view of the same table without the size parameter ([`TableView`]), so code
    /// that holds tables need not be generic over `N`. Its lookups are this table's, bit for
    /// bit.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.view().weight(0.4, 0.9), t.weight(0.4, 0.9));
    /// ```
    pub fn view(&self) -> TableView<'_> {
        self.with_values(View {
            grid: self.values.grid(),
            entries: self.values.entries(),
        })
    }
}

impl<S: Storage> Weights for Table<S> {
    fn radius(&self) -> [f32; 2] {
        self.radius
    }

    fn integral(&self) -> f32 {
        self.integral
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight(&self, dx: f32, dy: f32) -> f32 {
        Table::weight(self, dx, dy)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        self.factor_1d(axis, d)
    }

    fn is_separable(&self) -> bool {
        Table::is_separable(self)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        Table::footprint(self, d0, nx, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A non-separable plugin filter for the full 2D tables: an elliptic cone with unequal radii
    /// `[1.5, 1.25]`, so a radius reported for the wrong axis, or as a constant, shows (the
    /// filter tests' round `Cone` has radius 1 on both axes).
    struct EllipticCone;

    impl Filter for EllipticCone {
        fn radius(&self) -> [f32; 2] {
            [1.5, 1.25]
        }
        fn eval(&self, x: f32, y: f32) -> f32 {
            let d = 1.0 - (x / 1.5) * (x / 1.5) - (y / 1.25) * (y / 1.25);
            if d > 0.0 { d } else { 0.0 }
        }
    }

    /// A plugin filter of any radius, for the radius checks.
    struct Radius([f32; 2]);

    impl Filter for Radius {
        fn radius(&self) -> [f32; 2] {
            self.0
        }
        fn eval(&self, _: f32, _: f32) -> f32 {
            1.0
        }
    }

    /// A radius is tabulated when it is finite and above 0 on both axes; otherwise the error
    /// names the axis, carries the value and says `(0, ∞)`.
    #[test]
    fn radii_must_be_finite_and_positive() {
        let tiny = f32::from_bits(1);
        for r in [[tiny, f32::MAX], [1.0, 2.0], [f32::MAX, tiny]] {
            assert_eq!(table_radius(&Radius(r)), Ok(r));
        }
        for (r, what, value) in [
            ([0.0, 1.0], "filter radius rx", 0.0),
            ([1.0, -0.0], "filter radius ry", -0.0),
            ([-1.0, 1.0], "filter radius rx", -1.0),
            ([1.0, f32::INFINITY], "filter radius ry", f64::INFINITY),
            (
                [f32::NEG_INFINITY, 1.0],
                "filter radius rx",
                f64::NEG_INFINITY,
            ),
        ] {
            assert_eq!(
                table_radius(&Radius(r)),
                Err(Error::OutOfRange {
                    what,
                    value,
                    range: Interval::above(0.0)
                }),
                "{r:?}"
            );
        }
        assert!(matches!(
            table_radius(&Radius([f32::NAN, 1.0])),
            Err(Error::OutOfRange { what: "filter radius rx", value, .. }) if value.is_nan()
        ));
    }

    /// Every table form reports the radius and integral of its filter and the interpolation it
    /// was built with, and its sample points run from 0 to the radius, increasing, with every
    /// index past the last giving the radius.
    #[test]
    fn tables_report_their_filter_and_their_sample_points() {
        let mitchell = crate::filter::Mitchell::new([2.0, 1.5], 1.0 / 3.0, 1.0 / 3.0).unwrap();
        for interp in [Interpolation::Nearest, Interpolation::Linear] {
            let sep = SeparableTable::<16>::new(&mitchell, interp).unwrap();
            let full = Table2d::<16>::new(&EllipticCone, interp).unwrap();
            let tables = [
                (FilterTable::from(sep), &mitchell as &dyn Filter),
                (FilterTable::from(full), &EllipticCone as &dyn Filter),
            ];
            for (table, filter) in &tables {
                let (r, integral) = (filter.radius(), filter.integral());
                assert_eq!(table.radius(), r);
                assert_eq!(table.integral(), integral);
                let view = table.view();
                assert_eq!((view.radius(), view.integral()), (r, integral));
                assert_eq!(view.interpolation(), interp);
                assert_eq!(view.is_separable(), table.is_separable());
                // Entries are the filter at the sample points; indices past the last clamp.
                let last = view.len() - 1;
                for (i, j) in [(0, 0), (3, 5), (last, 2), (7, last)] {
                    let (x, y) = (view.sample_point(Axis::X, i), view.sample_point(Axis::Y, j));
                    assert!(
                        (view.entry(i, j) - filter.eval(x, y)).abs() < 1e-6,
                        "({i}, {j})"
                    );
                }
                assert_eq!(view.entry(last + 9, 4), view.entry(last, 4));
                assert_eq!(view.entry(4, last + 1), view.entry(4, last));
                for axis in [Axis::X, Axis::Y] {
                    let a = axis.index();
                    let points: std::vec::Vec<f32> =
                        (0..20).map(|i| view.sample_point(axis, i)).collect();
                    assert_eq!(points[0], 0.0);
                    assert!(points[..16].windows(2).all(|w| w[0] < w[1]), "{points:?}");
                    assert!(points[15..].iter().all(|&p| p == r[a]), "{points:?}");
                }
            }
            assert_eq!(
                (sep.radius(), sep.integral()),
                (mitchell.radius(), mitchell.integral())
            );
            assert_eq!(sep.interpolation(), interp);
            assert_eq!(
                (full.radius(), full.integral()),
                (EllipticCone.radius(), EllipticCone.integral())
            );
            for axis in [Axis::X, Axis::Y] {
                for i in [0, 1, 7, 15, 16, 99] {
                    assert_eq!(sep.sample_point(axis, i), sep.view().sample_point(axis, i));
                    assert_eq!(
                        full.sample_point(axis, i),
                        full.view().sample_point(axis, i)
                    );
                }
            }
        }
    }

    /// The sample points are what `table_point` promises: 0 first, the radius itself last, and in
    /// between the smallest offset whose table coordinate reaches its index; and the scale puts
    /// the radius on the last sample. Radii from 10⁻³ to 10³ against 2 to 257 samples: below a
    /// scale of 1, several neighbouring floats reach the same index and only the smallest is
    /// right.
    #[test]
    fn table_points_are_the_smallest_offsets_that_reach_their_index() {
        for n in [2usize, 3, 16, 17, 64, 257] {
            for r in [
                1e-3f32, 0.3, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 7.7, 64.0, 1000.0,
            ] {
                let s = table_scale(r, n);
                assert!(r * s >= (n - 1) as f32, "n {n} r {r}");
                assert_eq!(table_point(0, n, r, s), 0.0);
                assert_eq!(table_point(n - 1, n, r, s), r, "n {n} r {r}");
                for i in 1..n - 1 {
                    let x = table_point(i, n, r, s);
                    assert!(x * s >= i as f32, "n {n} r {r} i {i}");
                    assert!(x.next_down() * s < i as f32, "n {n} r {r} i {i}");
                }
            }
        }
    }
}
