//! Precomputed filter tables: the film's per-sample weight lookup.
//!
//! A table samples the filter at `N` points per axis, `xᵢ ≈ i·r/(N − 1)` for `i = 0 … N − 1`
//! (both the centre and the radius are sample points), over the quadrant `[0, rx] × [0, ry]`;
//! lookups fold the offset with `|·|`, so the filter is assumed even on each axis (pbrt-v2/v3
//! make the same assumption; every practical reconstruction filter is). The default `N = 16`
//! is pbrt-v2/v3's size.
//!
//! Lookups are exactly 0 past the radius and for NaN or infinite offsets, and exact (bit for
//! bit) at the sample points: `weight(xᵢ, yⱼ) == eval(xᵢ, yⱼ)` where `xᵢ` is
//! [`sample_point`](SeparableTable::sample_point). Elsewhere the error against direct evaluation
//! at the default size, measured over a 2001 × 2001 grid on `[−r, r]²` (the test
//! `documented_table_error_bounds` holds these bounds):
//!
//! | filter (defaults) | peak | nearest: max abs error | linear: max abs error |
//! |---|---|---|---|
//! | box, r = ½ | 1 | 0 | 0 |
//! | triangle, r = 2 | 4 | 0.26 | 7.2e-7 (rounding only) |
//! | gaussian, r = 2, α = 2 | 1 | 0.113 | 0.0171 |
//! | mitchell, r = 2, B = C = ⅓ | 0.79 | 0.089 | 0.0138 |
//! | lanczos, r = 4, τ = 3 | 1 | 0.223 | 0.0575 |
//!
//! Linear error falls about 4× per doubling of `N` (Lanczos at `N = 256`: below 5·10⁻⁴).
//! Linear interpolation is the default ([`Interpolation::Linear`]); it is exact for the box and
//! the triangle (piecewise bilinear) and costs one more multiply-add per axis.

use super::{Axis, Filter, radius_or_zero};
use crate::Error;

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

/// Validates a plugin filter's radius for tabulation.
fn table_radius<F: Filter + ?Sized>(filter: &F) -> Result<[f32; 2], Error> {
    let [rx, ry] = radius_or_zero(filter);
    if rx == 0.0 || ry == 0.0 {
        return Err(Error::OutOfRange {
            what: "filter radius (must be finite and > 0)",
        });
    }
    Ok([rx, ry])
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

/// Sample point `i`: an `x` with `min(x · scale, n − 1) == i` when one exists (so lookups are
/// exact there), else the closest float found; the last one is the radius itself.
fn table_point(i: usize, n: usize, r: f32, scale: f32) -> f32 {
    if i + 1 >= n {
        return r;
    }
    let target = i as f32;
    let mut x = target / scale;
    for _ in 0..8 {
        let p = x * scale;
        if p == target {
            break;
        }
        x = if p < target {
            x.next_up()
        } else {
            x.next_down()
        };
    }
    x
}

/// A filter value made safe for a table: non-finite values (a broken plugin) become 0.
#[inline]
fn finite_or_zero(v: f32) -> f32 {
    if v.is_finite() { v } else { 0.0 }
}

/// Per-size constants of a lookup: entries per axis, the last coordinate `n − 1` and the snap
/// tolerance, computed once (a `usize → f32` conversion is not free on x86-64).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Grid {
    n: usize,
    last: f32,
    eps: f32,
}

impl Grid {
    #[inline(always)]
    const fn new(n: usize) -> Grid {
        Grid {
            n,
            last: (n - 1) as f32,
            eps: (n - 1) as f32 * (1.0 / 2_097_152.0),
        }
    }

    /// Table coordinate of a folded offset `a = |d|`: in `[0, n − 1]` for every input (NaN and
    /// ∞ give `n − 1`; the caller masks them out), so the index arithmetic never sees them.
    #[inline(always)]
    fn coord(&self, a: f32, scale: f32) -> f32 {
        // f32::min returns the non-NaN operand.
        (a * scale).min(self.last)
    }

    /// Cell `k ∈ [0, n − 2]` and position `t ∈ [0, 1]` of coordinate `c ∈ [0, n − 1]`, with
    /// `t` snapped to 0 or 1 when it is within `(n − 1)·2⁻²¹` (a few rounding errors of
    /// `x·scale`) of either: a sample point whose coordinate rounded to just below or above its
    /// index still reads its entry exactly. Compiles to selects, not branches.
    #[inline(always)]
    fn cell(&self, c: f32) -> (usize, f32) {
        let (k, kf) = round_index(c - 0.5);
        let last_cell = self.last - 1.0;
        let (k, kf) = if kf > last_cell {
            (self.n - 2, last_cell)
        } else {
            (k, kf)
        };
        let t = c - kf;
        let t = if t < self.eps { 0.0 } else { t };
        let t = if t > 1.0 - self.eps { 1.0 } else { t };
        (k, t)
    }

    /// Nearest index of coordinate `c ∈ [0, n − 1]`.
    #[inline(always)]
    fn nearest(&self, c: f32) -> usize {
        round_index(c).0.min(self.n - 1)
    }
}

/// `c` rounded to the nearest integer (ties to even) for `−½ ≤ c < 2²²`, as an index and as a
/// float: adding `1.5·2²³` leaves the integer in the low mantissa bits. Two adds, no
/// saturating float-to-int conversion.
#[inline(always)]
fn round_index(c: f32) -> (usize, f32) {
    const MAGIC: f32 = 12_582_912.0;
    let m = c + MAGIC;
    (m.to_bits().wrapping_sub(0x4B40_0000) as usize, m - MAGIC)
}

/// 1D lookup at table coordinate `c ∈ [0, n − 1]`; `v.len() == g.n ≥ 2`.
#[inline(always)]
fn lookup_1d(v: &[f32], g: Grid, c: f32, interp: Interpolation) -> f32 {
    match interp {
        Interpolation::Nearest => v[g.nearest(c)],
        Interpolation::Linear => {
            let (k, t) = g.cell(c);
            // (1 − t)·a + t·b is exact at t = 0 and t = 1.
            (1.0 - t) * v[k] + t * v[k + 1]
        }
    }
}

/// 2D lookup in a row-major `n × n` grid (`v[j·n + i]`, `i` along x).
#[inline(always)]
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

/// A separable filter's table: two 1D tables of `N` entries each (default 16), stored inline.
/// Allocates: no; size `8·N + 24` bytes.
///
/// # Examples
///
/// ```
/// use nyquist::filter::{Filter, Gaussian, Interpolation, SeparableTable};
/// let g = Gaussian::default();
/// let t: SeparableTable = SeparableTable::new(&g, Interpolation::Linear).unwrap();
/// assert!((t.weight(0.3, 1.1) - g.eval(0.3, 1.1)).abs() <= 0.0171);
/// assert_eq!(t.weight(2.01, 0.0), 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeparableTable<const N: usize = 16> {
    values: [[f32; N]; 2],
    radius: [f32; 2],
    scale: [f32; 2],
    integral: f32,
    interp: Interpolation,
}

impl<const N: usize> SeparableTable<N> {
    /// Tabulates `filter`'s separable form ([`Filter::eval_1d`]) at `N` points per axis, and
    /// stores [`Filter::integral`]. `N < 2` (or `N ≥ 2²²`) does not compile.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter is not separable or its radius is not finite and
    /// `> 0`. Non-finite values from a plugin filter are stored as 0.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
    /// let t = SeparableTable::<32>::new(&Mitchell::default(), Interpolation::Nearest).unwrap();
    /// assert_eq!(t.radius(), [2.0, 2.0]);
    /// ```
    pub fn new<F: Filter + ?Sized>(
        filter: &F,
        interp: Interpolation,
    ) -> Result<SeparableTable<N>, Error> {
        const {
            assert!(
                N >= 2 && N < 1 << 22,
                "a filter table needs 2 ≤ N < 2²² entries per axis"
            )
        };
        let radius = table_radius(filter)?;
        if !filter.is_separable() {
            return Err(Error::OutOfRange {
                what: "filter (not separable)",
            });
        }
        let scale = [table_scale(radius[0], N), table_scale(radius[1], N)];
        let mut values = [[0.0f32; N]; 2];
        for (a, axis) in [Axis::X, Axis::Y].into_iter().enumerate() {
            for (i, v) in values[a].iter_mut().enumerate() {
                let x = table_point(i, N, radius[a], scale[a]);
                *v = finite_or_zero(filter.eval_1d(axis, x).unwrap_or(0.0));
            }
        }
        Ok(SeparableTable {
            values,
            radius,
            scale,
            integral: filter.integral(),
            interp,
        })
    }

    /// The weight at offset `(dx, dy)` from the pixel centre: the product of the two 1D lookups.
    /// 0 past the radius and for NaN or infinite offsets. This is the film's hot path.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, Interpolation, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight(0.25, -0.5), 1.0);
    /// assert_eq!(t.weight(f32::NAN, 0.0), 0.0);
    /// ```
    #[inline]
    pub fn weight(&self, dx: f32, dy: f32) -> f32 {
        let (ax, ay) = (dx.abs(), dy.abs());
        // Look up unconditionally (coordinates are clamped), then mask: no branch to mispredict.
        let inside = (ax <= self.radius[0]) & (ay <= self.radius[1]);
        let g = const { Grid::new(N) };
        let cx = g.coord(ax, self.scale[0]);
        let cy = g.coord(ay, self.scale[1]);
        let w = lookup_1d(&self.values[0], g, cx, self.interp)
            * lookup_1d(&self.values[1], g, cy, self.interp);
        if inside { w } else { 0.0 }
    }

    /// The 1D factor along `axis` at offset `d`, so that
    /// `weight(dx, dy) == weight_1d(X, dx) * weight_1d(Y, dy)` (the same product).
    ///
    /// ```
    /// use nyquist::filter::{Axis, Interpolation, SeparableTable, Triangle};
    /// let t: SeparableTable = SeparableTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight_1d(Axis::X, 0.5) * t.weight_1d(Axis::Y, 1.5), t.weight(0.5, 1.5));
    /// ```
    #[inline]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> f32 {
        let a = axis.index();
        let ad = d.abs();
        if !(ad <= self.radius[a]) {
            return 0.0;
        }
        let g = const { Grid::new(N) };
        lookup_1d(&self.values[a], g, g.coord(ad, self.scale[a]), self.interp)
    }

    /// The stored values along `axis`: entry `i` is the filter's 1D factor at
    /// [`sample_point(axis, i)`](Self::sample_point).
    ///
    /// ```
    /// use nyquist::filter::{Axis, Boxcar, Interpolation, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.values(Axis::X), &[1.0; 16]);
    /// ```
    pub fn values(&self, axis: Axis) -> &[f32; N] {
        &self.values[axis.index()]
    }

    /// The offset of sample `i` along `axis` (`i ≥ N` gives the radius).
    ///
    /// ```
    /// use nyquist::filter::{Axis, Interpolation, SeparableTable, Triangle};
    /// let t: SeparableTable = SeparableTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.sample_point(Axis::X, 0), 0.0);
    /// assert_eq!(t.sample_point(Axis::X, 15), 2.0);
    /// ```
    pub fn sample_point(&self, axis: Axis, i: usize) -> f32 {
        let a = axis.index();
        table_point(i.min(N - 1), N, self.radius[a], self.scale[a])
    }

    /// The filter's radius `[rx, ry]`.
    pub fn radius(&self) -> [f32; 2] {
        self.radius
    }

    /// The filter's integral (from [`Filter::integral`] at build time).
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// The interpolation chosen at build time.
    pub fn interpolation(&self) -> Interpolation {
        self.interp
    }

    /// A size-erased view, so code that holds tables need not be generic over `N`.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
    /// let t: SeparableTable = SeparableTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.view().weight(0.4, 0.9), t.weight(0.4, 0.9));
    /// ```
    pub fn view(&self) -> TableView<'_> {
        TableView {
            radius: self.radius,
            scale: self.scale,
            integral: self.integral,
            interp: self.interp,
            grid: Grid::new(N),
            data: ViewData::Separable(&self.values[0], &self.values[1]),
        }
    }
}

/// A full 2D table of `N × N` entries (default 16 × 16) over `[0, rx] × [0, ry]`, for filters that
/// are not separable. Allocates: no; size `4·N² + 24` bytes.
///
/// ```
/// use nyquist::filter::{Filter, Interpolation, Table2d, Triangle};
/// // Any filter can use a 2D table, separable or not.
/// let t: Table2d = Table2d::new(&Triangle::default(), Interpolation::Linear).unwrap();
/// assert!((t.weight(0.3, 1.7) - Triangle::default().eval(0.3, 1.7)).abs() < 1e-5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Table2d<const N: usize = 16> {
    /// `values[j][i]`: `i` along x, `j` along y.
    values: [[f32; N]; N],
    radius: [f32; 2],
    scale: [f32; 2],
    integral: f32,
    interp: Interpolation,
}

impl<const N: usize> Table2d<N> {
    /// Tabulates `filter.eval` at `N × N` points and stores [`Filter::integral`]. `N < 2` (or
    /// `N ≥ 2²²`) does not compile.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter's radius is not finite and `> 0`. Non-finite values
    /// from a plugin filter are stored as 0.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, Interpolation, Table2d};
    /// assert!(Table2d::<8>::new(&Boxcar::default(), Interpolation::Nearest).is_ok());
    /// ```
    pub fn new<F: Filter + ?Sized>(filter: &F, interp: Interpolation) -> Result<Table2d<N>, Error> {
        const {
            assert!(
                N >= 2 && N < 1 << 22,
                "a filter table needs 2 ≤ N < 2²² entries per axis"
            )
        };
        let radius = table_radius(filter)?;
        let scale = [table_scale(radius[0], N), table_scale(radius[1], N)];
        let mut values = [[0.0f32; N]; N];
        for (j, row) in values.iter_mut().enumerate() {
            let y = table_point(j, N, radius[1], scale[1]);
            for (i, v) in row.iter_mut().enumerate() {
                let x = table_point(i, N, radius[0], scale[0]);
                *v = finite_or_zero(filter.eval(x, y));
            }
        }
        Ok(Table2d {
            values,
            radius,
            scale,
            integral: filter.integral(),
            interp,
        })
    }

    /// The weight at offset `(dx, dy)` from the pixel centre; 0 past the radius and for NaN or
    /// infinite offsets.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Table2d, Triangle};
    /// let t: Table2d = Table2d::new(&Triangle::default(), Interpolation::Nearest).unwrap();
    /// assert_eq!(t.weight(0.0, 0.0), 4.0);
    /// assert_eq!(t.weight(0.0, -2.5), 0.0);
    /// ```
    #[inline]
    pub fn weight(&self, dx: f32, dy: f32) -> f32 {
        let (ax, ay) = (dx.abs(), dy.abs());
        let inside = (ax <= self.radius[0]) & (ay <= self.radius[1]);
        let g = const { Grid::new(N) };
        let cx = g.coord(ax, self.scale[0]);
        let cy = g.coord(ay, self.scale[1]);
        let w = lookup_2d(self.values.as_flattened(), g, cx, cy, self.interp);
        if inside { w } else { 0.0 }
    }

    /// The stored values, `values()[j][i]` at ([`sample_point(X, i)`](Self::sample_point),
    /// `sample_point(Y, j)`).
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, Interpolation, Table2d};
    /// let t: Table2d<4> = Table2d::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.values(), &[[1.0; 4]; 4]);
    /// ```
    pub fn values(&self) -> &[[f32; N]; N] {
        &self.values
    }

    /// The offset of sample `i` along `axis` (`i ≥ N` gives the radius).
    pub fn sample_point(&self, axis: Axis, i: usize) -> f32 {
        let a = axis.index();
        table_point(i.min(N - 1), N, self.radius[a], self.scale[a])
    }

    /// The filter's radius `[rx, ry]`.
    pub fn radius(&self) -> [f32; 2] {
        self.radius
    }

    /// The filter's integral (from [`Filter::integral`] at build time).
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// A size-erased view.
    ///
    /// ```
    /// use nyquist::filter::{Interpolation, Table2d, Triangle};
    /// let t: Table2d = Table2d::new(&Triangle::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.view().weight(0.4, 0.9), t.weight(0.4, 0.9));
    /// ```
    pub fn view(&self) -> TableView<'_> {
        TableView {
            radius: self.radius,
            scale: self.scale,
            integral: self.integral,
            interp: self.interp,
            grid: Grid::new(N),
            data: ViewData::Full(self.values.as_flattened()),
        }
    }
}

/// A filter table that picks its layout: [`SeparableTable`] for separable filters, [`Table2d`]
/// otherwise. This is what a film holds. Allocates: no.
///
/// ```
/// use nyquist::filter::{Filter, FilterTable, Interpolation, Lanczos};
/// let l = Lanczos::default();
/// let table: FilterTable = FilterTable::new(&l, Interpolation::Linear).unwrap();
/// assert!(table.is_separable());
/// assert!((table.weight(1.3, -0.2) - l.eval(1.3, -0.2)).abs() <= 0.0575);
/// assert_eq!(table.weight(4.001, 0.0), 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FilterTable<const N: usize = 16> {
    /// Two 1D tables.
    Separable(SeparableTable<N>),
    /// One 2D table.
    Full(Table2d<N>),
}

impl<const N: usize> FilterTable<N> {
    /// Tabulates any filter, built-in or plugin, in one call: separable filters get two 1D
    /// tables, others a 2D table.
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
            SeparableTable::new(filter, interp).map(FilterTable::Separable)
        } else {
            Table2d::new(filter, interp).map(FilterTable::Full)
        }
    }

    /// The weight at offset `(dx, dy)` from the pixel centre; 0 past the radius and for NaN or
    /// infinite offsets. Exact at the sample points.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterTable, Interpolation};
    /// let t: FilterTable = FilterTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight(0.1, 0.2), 1.0);
    /// ```
    #[inline]
    pub fn weight(&self, dx: f32, dy: f32) -> f32 {
        match self {
            FilterTable::Separable(t) => t.weight(dx, dy),
            FilterTable::Full(t) => t.weight(dx, dy),
        }
    }

    /// The 1D factor along `axis` for separable tables (see [`SeparableTable::weight_1d`]),
    /// `None` for 2D tables.
    ///
    /// ```
    /// use nyquist::filter::{Axis, Boxcar, FilterTable, Interpolation};
    /// let t: FilterTable = FilterTable::new(&Boxcar::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.weight_1d(Axis::Y, 0.6), Some(0.0));
    /// ```
    #[inline]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        match self {
            FilterTable::Separable(t) => Some(t.weight_1d(axis, d)),
            FilterTable::Full(_) => None,
        }
    }

    /// Whether the table is two 1D tables.
    pub fn is_separable(&self) -> bool {
        matches!(self, FilterTable::Separable(_))
    }

    /// The filter's radius `[rx, ry]`.
    pub fn radius(&self) -> [f32; 2] {
        match self {
            FilterTable::Separable(t) => t.radius(),
            FilterTable::Full(t) => t.radius(),
        }
    }

    /// The filter's integral (from [`Filter::integral`] at build time).
    pub fn integral(&self) -> f32 {
        match self {
            FilterTable::Separable(t) => t.integral(),
            FilterTable::Full(t) => t.integral(),
        }
    }

    /// A size-erased view.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Mitchell};
    /// let t: FilterTable = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// let v = t.view();
    /// assert_eq!((v.len(), v.weight(0.5, 0.5)), (16, t.weight(0.5, 0.5)));
    /// ```
    pub fn view(&self) -> TableView<'_> {
        match self {
            FilterTable::Separable(t) => t.view(),
            FilterTable::Full(t) => t.view(),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum ViewData<'a> {
    Separable(&'a [f32], &'a [f32]),
    Full(&'a [f32]),
}

/// A borrowed, size-erased view of any table ([`FilterTable`], [`SeparableTable`],
/// [`Table2d`]): the same lookups, without the const generic. `Copy`, two pointers and a few
/// floats.
///
/// ```
/// use nyquist::filter::{FilterTable, Interpolation, TableView, Triangle};
/// fn centre(view: TableView<'_>) -> f32 { view.weight(0.0, 0.0) }
/// let t: FilterTable<64> = FilterTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
/// assert_eq!(centre(t.view()), 4.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TableView<'a> {
    radius: [f32; 2],
    scale: [f32; 2],
    integral: f32,
    interp: Interpolation,
    grid: Grid,
    data: ViewData<'a>,
}

impl TableView<'_> {
    /// The weight at offset `(dx, dy)` from the pixel centre, identical to the table's.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Lanczos};
    /// let t: FilterTable = FilterTable::new(&Lanczos::default(), Interpolation::Linear).unwrap();
    /// assert_eq!(t.view().weight(f32::INFINITY, 0.0), 0.0);
    /// ```
    #[inline]
    pub fn weight(&self, dx: f32, dy: f32) -> f32 {
        let (ax, ay) = (dx.abs(), dy.abs());
        let inside = (ax <= self.radius[0]) & (ay <= self.radius[1]);
        let g = self.grid;
        let cx = g.coord(ax, self.scale[0]);
        let cy = g.coord(ay, self.scale[1]);
        let w = match self.data {
            ViewData::Separable(x, y) => {
                lookup_1d(x, g, cx, self.interp) * lookup_1d(y, g, cy, self.interp)
            }
            ViewData::Full(v) => lookup_2d(v, g, cx, cy, self.interp),
        };
        if inside { w } else { 0.0 }
    }

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
    #[inline]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        let ViewData::Separable(x, y) = self.data else {
            return None;
        };
        let a = axis.index();
        let v = if a == 0 { x } else { y };
        let ad = d.abs();
        if !(ad <= self.radius[a]) {
            return Some(0.0);
        }
        let g = self.grid;
        Some(lookup_1d(v, g, g.coord(ad, self.scale[a]), self.interp))
    }

    /// The weights of a whole footprint at once: `out[j·nx + i] = weight(d0[0] + i, d0[1] + j)`
    /// for `j < out.len() / nx` — the offsets from one sample to a block of pixel centres.
    /// Identical to calling [`weight`](Self::weight) per entry, but a separable table does
    /// `nx + ny` 1D lookups and one multiply per weight. This is the film's fast path.
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `out.len()` is a positive multiple of `nx`.
    ///
    /// ```
    /// use nyquist::filter::{FilterTable, Interpolation, Mitchell};
    /// let t: FilterTable = FilterTable::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    /// let mut w = [0.0f32; 16];
    /// t.view().footprint([-1.7, -1.2], 4, &mut w).unwrap();
    /// assert_eq!(w[2 * 4 + 3], t.weight(-1.7 + 3.0, -1.2 + 2.0));
    /// ```
    pub fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        if nx == 0 || out.is_empty() || !out.len().is_multiple_of(nx) {
            return Err(Error::BufferLength {
                multiple_of: nx,
                actual: out.len(),
            });
        }
        match self.data {
            ViewData::Separable(..) => {
                // Row 0 holds the x factors until it is scaled last.
                let (first, rest) = out.split_at_mut(nx);
                for (i, w) in first.iter_mut().enumerate() {
                    *w = self.weight_1d(Axis::X, d0[0] + i as f32).unwrap_or(0.0);
                }
                for (j, row) in rest.chunks_exact_mut(nx).enumerate() {
                    let wy = self
                        .weight_1d(Axis::Y, d0[1] + (j + 1) as f32)
                        .unwrap_or(0.0);
                    for (w, &wx) in row.iter_mut().zip(first.iter()) {
                        *w = wx * wy;
                    }
                }
                let wy = self.weight_1d(Axis::Y, d0[1]).unwrap_or(0.0);
                for w in first.iter_mut() {
                    *w *= wy;
                }
            }
            ViewData::Full(_) => {
                for (j, row) in out.chunks_exact_mut(nx).enumerate() {
                    let dy = d0[1] + j as f32;
                    for (i, w) in row.iter_mut().enumerate() {
                        *w = self.weight(d0[0] + i as f32, dy);
                    }
                }
            }
        }
        Ok(())
    }

    /// Whether the viewed table is two 1D tables.
    pub fn is_separable(&self) -> bool {
        matches!(self.data, ViewData::Separable(..))
    }

    /// Entries per axis (`N`).
    #[allow(clippy::len_without_is_empty)] // never empty: N ≥ 2
    pub fn len(&self) -> usize {
        self.grid.n
    }

    /// The offset of sample `i` along `axis` (`i ≥ len()` gives the radius).
    ///
    /// ```
    /// use nyquist::filter::{Axis, FilterTable, Interpolation, Triangle};
    /// let t: FilterTable = FilterTable::new(&Triangle::default(), Interpolation::Linear).unwrap();
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
    /// assert_eq!(t.view().entry(0, 0), 4.0);
    /// ```
    pub fn entry(&self, i: usize, j: usize) -> f32 {
        let n = self.len();
        let (i, j) = (i.min(n - 1), j.min(n - 1));
        match self.data {
            ViewData::Separable(x, y) => x[i] * y[j],
            ViewData::Full(v) => v[j * n + i],
        }
    }

    /// The filter's radius `[rx, ry]`.
    pub fn radius(&self) -> [f32; 2] {
        self.radius
    }

    /// The filter's integral (from [`Filter::integral`] at build time).
    pub fn integral(&self) -> f32 {
        self.integral
    }

    /// The interpolation chosen at build time.
    pub fn interpolation(&self) -> Interpolation {
        self.interp
    }
}
