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

/// Table coordinate of a folded offset `a = |d| ≤ r`: in `[0, n − 1]`.
#[inline(always)]
fn coord(a: f32, scale: f32, n: usize) -> f32 {
    (a * scale).min((n - 1) as f32)
}

/// The interpolation parameter `t = c − k` snapped to 0 or 1 when it is within a few rounding
/// errors of the coordinate (`(n − 1)·2⁻²¹`) of either: a sample point whose coordinate
/// `x·scale` rounded to just below or above its index still reads its entry exactly.
#[inline(always)]
fn snap(t: f32, n: usize) -> f32 {
    let eps = (n - 1) as f32 * (1.0 / 2_097_152.0);
    if t < eps {
        0.0
    } else if t > 1.0 - eps {
        1.0
    } else {
        t
    }
}

/// 1D lookup at table coordinate `c ∈ [0, n − 1]`; `v.len() ≥ 2`.
#[inline(always)]
fn lookup_1d(v: &[f32], c: f32, interp: Interpolation) -> f32 {
    let n = v.len();
    match interp {
        Interpolation::Nearest => v[((c + 0.5) as usize).min(n - 1)],
        Interpolation::Linear => {
            let k = (c as usize).min(n - 2);
            let t = snap(c - k as f32, n);
            // (1 − t)·a + t·b is exact at t = 0 and t = 1.
            (1.0 - t) * v[k] + t * v[k + 1]
        }
    }
}

/// 2D lookup in a row-major `n × n` grid (`v[j·n + i]`, `i` along x).
#[inline(always)]
fn lookup_2d(v: &[f32], n: usize, cx: f32, cy: f32, interp: Interpolation) -> f32 {
    match interp {
        Interpolation::Nearest => {
            let i = ((cx + 0.5) as usize).min(n - 1);
            let j = ((cy + 0.5) as usize).min(n - 1);
            v[j * n + i]
        }
        Interpolation::Linear => {
            let i = (cx as usize).min(n - 2);
            let j = (cy as usize).min(n - 2);
            let (tx, ty) = (snap(cx - i as f32, n), snap(cy - j as f32, n));
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
    /// stores [`Filter::integral`]. `N < 2` does not compile.
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
        const { assert!(N >= 2, "a filter table needs at least 2 entries per axis") };
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
        if !(ax <= self.radius[0] && ay <= self.radius[1]) {
            return 0.0;
        }
        let cx = coord(ax, self.scale[0], N);
        let cy = coord(ay, self.scale[1], N);
        lookup_1d(&self.values[0], cx, self.interp) * lookup_1d(&self.values[1], cy, self.interp)
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
        lookup_1d(&self.values[a], coord(ad, self.scale[a], N), self.interp)
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
    /// Tabulates `filter.eval` at `N × N` points and stores [`Filter::integral`]. `N < 2` does
    /// not compile.
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
        const { assert!(N >= 2, "a filter table needs at least 2 entries per axis") };
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
        if !(ax <= self.radius[0] && ay <= self.radius[1]) {
            return 0.0;
        }
        let cx = coord(ax, self.scale[0], N);
        let cy = coord(ay, self.scale[1], N);
        lookup_2d(self.values.as_flattened(), N, cx, cy, self.interp)
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
            data: ViewData::Full(self.values.as_flattened(), N),
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
    Full(&'a [f32], usize),
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
        if !(ax <= self.radius[0] && ay <= self.radius[1]) {
            return 0.0;
        }
        match self.data {
            ViewData::Separable(x, y) => {
                let cx = coord(ax, self.scale[0], x.len());
                let cy = coord(ay, self.scale[1], y.len());
                lookup_1d(x, cx, self.interp) * lookup_1d(y, cy, self.interp)
            }
            ViewData::Full(v, n) => {
                let cx = coord(ax, self.scale[0], n);
                let cy = coord(ay, self.scale[1], n);
                lookup_2d(v, n, cx, cy, self.interp)
            }
        }
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
        Some(lookup_1d(v, coord(ad, self.scale[a], v.len()), self.interp))
    }

    /// Whether the viewed table is two 1D tables.
    pub fn is_separable(&self) -> bool {
        matches!(self.data, ViewData::Separable(..))
    }

    /// Entries per axis (`N`).
    #[allow(clippy::len_without_is_empty)] // never empty: N ≥ 2
    pub fn len(&self) -> usize {
        match self.data {
            ViewData::Separable(x, _) => x.len(),
            ViewData::Full(_, n) => n,
        }
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
            ViewData::Full(v, n) => v[j * n + i],
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
