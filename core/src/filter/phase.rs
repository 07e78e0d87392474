//! The polyphase filter table: every weight of a sample's footprint along one axis from one
//! interpolated table row, the film's fast path.
//!
//! A sample at `p` (pixel centres at integers + ½) reaches the pixels whose centres lie within
//! the radius `r`: along one axis, the first is `⌈p − ½ − r⌉`, whose centre sits `φ − r` from
//! the sample, with the *phase* `φ = ⌈p − ½ − r⌉ − (p − ½ − r) ∈ [0, 1)`; the next ones follow at
//! unit steps. So every weight of the footprint is a function of `φ` and of the pixel's place
//! `k` in it, the *tap*: `w_k(φ) = f(k + φ − r)`, `k = 0 … ⌊2r⌋`.
//!
//! The table stores those weights at [`PHASES`] + 1 phases `φ = j/64`, one row of taps per phase,
//! and interpolates linearly between two rows: a footprint's weights along an axis cost one
//! 4-wide multiply-add per four taps and no per-pixel index arithmetic — [`SeparableTable`]'s
//! footprint needs a lookup per pixel column. Row `j`, tap `k` holds `f(k + j/64 − r)`, so the
//! table is the linear interpolant of `f` on the uniform grid `−r + m/64` (spacing 1/64 pixel,
//! finer than a 64-entry [`SeparableTable`]'s `r/63` for any radius above 1), laid out
//! phase-major; [`weight`](PhaseTable::weight) reads the same grid for a single offset.
//!
//! Only separable filters with at most [`MAX_TAPS`] taps per axis (radius below 8 pixels) fit;
//! others use [`FilterTable`]. A table is 8.3 KB.
//!
//! Max abs error against direct evaluation over a 2001 × 2001 grid on `[−r, r]²`, defaults (the
//! test `phase_table_error_is_below_the_64_entry_tables` holds these bounds): box 0, triangle
//! 4.8·10⁻⁷ (rounding), gaussian 2.4·10⁻⁴, mitchell 2.1·10⁻⁴, lanczos 2.2·10⁻⁴ — a 64-entry
//! linear [`SeparableTable`] is 1.0·10⁻³, 8.7·10⁻⁴ and 3.7·10⁻³ there.
//!
//! The polyphase layout is the standard one of resampling filters (e.g. Smith, "Digital Audio
//! Resampling"); its use for a film's reconstruction filter is this crate's.
//!
//! [`SeparableTable`]: super::SeparableTable
//! [`FilterTable`]: super::FilterTable

use super::table::{MAGIC, MAGIC_BITS, constant_weight, finite_or_zero, mask, table_radius};
use super::{Axis, Filter, Weights};
use crate::Error;
use crate::error::Interval;

/// Phases per pixel of a [`PhaseTable`]: its grid spacing is 1/64 pixel.
///
/// ```
/// assert_eq!(nyquist::filter::PHASES, 64);
/// ```
pub const PHASES: usize = 64;

/// The most taps (footprint pixels along one axis, `⌊2r⌋ + 1`) a [`PhaseTable`] holds: radii
/// below 8 pixels.
///
/// ```
/// use nyquist::filter::{Gaussian, PhaseTable, MAX_TAPS};
/// assert_eq!(MAX_TAPS, 16);
/// assert!(PhaseTable::new(&Gaussian::new([7.9, 7.9], 2.0).unwrap()).is_ok());
/// assert!(PhaseTable::new(&Gaussian::new([8.0, 8.0], 2.0).unwrap()).is_err());
/// ```
pub const MAX_TAPS: usize = 16;

/// The largest shift of a footprint's first tap that [`PhaseAxis::locate`] forms exactly (2²²).
const SHIFT_LIMIT: f32 = 4_194_304.0;

/// One axis of a [`PhaseTable`].
#[derive(Clone, Debug, PartialEq)]
struct PhaseAxis {
    /// `r`.
    radius: f32,
    /// `⌊2r⌋ + 1`, at most `MAX_TAPS`.
    taps: usize,
    /// `taps` rounded up to a multiple of 4: the row length (the padding holds 0).
    stride: usize,
    /// Row `j` (phase `j/64`): taps `0 … taps − 1`, then 0.
    values: [[f32; MAX_TAPS]; PHASES + 1],
    /// The one value every tap holds, if they all hold the same (a box).
    constant: Option<f32>,
}

impl PhaseAxis {
    fn new(r: f32, what: &'static str, eval: impl Fn(f32) -> f32) -> Result<PhaseAxis, Error> {
        // ⌊2r⌋ + 1 taps: k + φ − r ≤ r has solutions k = 0 … ⌊2r − φ⌋.
        // r is finite and > 0; below 8 the truncation is the floor.
        let span = 2.0 * f64::from(r);
        if span >= MAX_TAPS as f64 {
            return Err(Error::OutOfRange {
                what,
                value: f64::from(r),
                range: Interval::open(0.0, MAX_TAPS as f64 / 2.0),
            });
        }
        let taps = span as usize + 1;
        let stride = taps.next_multiple_of(4);
        let mut values = [[0.0f32; MAX_TAPS]; PHASES + 1];
        for (j, row) in values.iter_mut().enumerate() {
            let phase = j as f64 / PHASES as f64;
            for (k, v) in row[..taps].iter_mut().enumerate() {
                // The offset of tap k at this phase, formed in f64 and rounded once; past the
                // radius the edge value f(r), so that a row interpolates towards the edge, not
                // towards 0 (a box of radius 0.7 stays exactly 1 up to its edge).
                let d = (k as f64 + phase - f64::from(r)) as f32;
                *v = finite_or_zero(eval(if d <= r { d } else { r }));
            }
        }
        let first = values[0][0];
        let constant = values
            .iter()
            .all(|row| row[..taps].iter().all(|&v| v == first))
            .then_some(first);
        Ok(PhaseAxis {
            radius: r,
            taps,
            stride,
            values,
            constant,
        })
    }

    /// Row index `j ∈ [0, 63]` and position `t ∈ [0, 1]` between rows `j` and `j + 1` for a phase
    /// clamped to `[0, 1]` (NaN → 0): `j = round(min(64·phase − ½, 63))` by the `1.5·2²³` trick
    /// (no saturating float-to-int conversion), `t = 64·phase − j`. At a stored phase the tie
    /// gives `t = 0` or `t = 1`, both exact.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn cell(phase: f32) -> (usize, f32) {
        let u = (phase * PHASES as f32).max(0.0).min(PHASES as f32);
        let m = (u - 0.5).min((PHASES - 1) as f32) + MAGIC;
        let j = (m.to_bits().wrapping_sub(MAGIC_BITS) as usize).min(PHASES - 1);
        (j, u - (m - MAGIC))
    }

    /// Rows `j` and `j + 1` (`j < 64`), each [`MAX_TAPS`] long.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn rows(&self, j: usize) -> (&[f32; MAX_TAPS], &[f32; MAX_TAPS]) {
        let j = j.min(PHASES - 1);
        (&self.values[j], &self.values[j + 1])
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn row(&self, phase: f32, out: &mut [f32; MAX_TAPS]) -> usize {
        let (j, t) = Self::cell(phase);
        let (a, b) = self.rows(j);
        // Four lanes at a time over the padded row.
        for c in 0..MAX_TAPS / 4 {
            if 4 * c >= self.stride {
                break;
            }
            out[4 * c..4 * c + 4].copy_from_slice(&lerp4(a, b, t, 4 * c));
        }
        self.taps
    }

    /// Lanes 0–3 of [`row`](Self::row), computed the same way.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn row4(&self, phase: f32) -> [f32; 4] {
        let (j, t) = Self::cell(phase);
        let (a, b) = self.rows(j);
        lerp4(a, b, t, 0)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn tap(&self, phase: f32, k: usize) -> f32 {
        let (j, t) = Self::cell(phase);
        let (a, b) = self.rows(j);
        match (a.get(k), b.get(k)) {
            (Some(&a), Some(&b)) => (1.0 - t) * a + t * b,
            _ => 0.0,
        }
    }

    /// The weight at offset `d`: tap `⌊d + r⌋` at phase `frac(d + r)`, 0 past the radius. The
    /// grid index `64·(d + r)` splits into phase (low 6 bits) and tap (the rest), found by the
    /// rounding trick of [`cell`](Self::cell); at a phase of 1 it reads tap `k + 1`'s row 0,
    /// which holds the same value as tap `k`'s row 64. A constant axis (a box) answers its
    /// value, exactly, with no lookup (the interpolation `(1 − t)·c + t·c` can round off `c`).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight(&self, d: f32) -> f32 {
        const CELLS: usize = MAX_TAPS * PHASES;
        let inside = d.abs() <= self.radius;
        if let Some(c) = self.constant {
            return c * mask(inside);
        }
        let u = ((d + self.radius) * PHASES as f32)
            .max(0.0)
            .min(CELLS as f32);
        let m = (u - 0.5).min((CELLS - 1) as f32) + MAGIC;
        let g = m.to_bits().wrapping_sub(MAGIC_BITS) as usize % CELLS;
        let t = u - (m - MAGIC);
        let (j, k) = (g % PHASES, g / PHASES);
        ((1.0 - t) * self.values[j][k] + t * self.values[j + 1][k]) * mask(inside)
    }
}

/// A separable filter tabulated by phase. Along one axis, a sample at `p` reaches the pixels
/// from `⌈p − ½ − r⌉` on, the first sitting `φ − r` from it with the phase
/// `φ = ⌈p − ½ − r⌉ − (p − ½ − r) ∈ [0, 1)`, the others at unit steps, so pixel `k` of the
/// footprint (its *tap*) weighs `f(k + φ − r)`. The table stores those rows of taps at 65 phases
/// `j/64` and [`row`](PhaseTable::row) interpolates between two of them: all the footprint's
/// weights along an axis in one read. It is the linear interpolant of `f` on the grid
/// `−r + m/64`. The film's table for separable filters. Allocates: no (8.3 KB inline).
///
/// ```
/// use nyquist::filter::{Axis, Filter, Mitchell, PhaseTable, MAX_TAPS};
/// let m = Mitchell::default();
/// let t = PhaseTable::new(&m).unwrap();
/// // A sample at x = 10.3: the first pixel is ⌈10.3 − ½ − 2⌉ = 8, at phase 8 − 7.8 = 0.2.
/// let mut w = [0.0f32; MAX_TAPS];
/// let taps = t.row(Axis::X, 0.2, &mut w);
/// assert_eq!(taps, 5); // up to 5 pixels (8 … 11 here: the fifth only at phase 0)
/// for (k, &w) in w[..4].iter().enumerate() {
///     let d = (8 + k) as f32 + 0.5 - 10.3; // pixel centre − sample
///     assert!((w - m.eval_1d(Axis::X, d).unwrap()).abs() < 4e-4);
/// }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PhaseTable {
    axes: [PhaseAxis; 2],
    integral: f32,
    /// Both axes' constants when both are constant (a box), beside both radii: what
    /// [`weight`](PhaseTable::weight) reads for such a table, one test and no table memory.
    constant: Option<[f32; 2]>,
    radius: [f32; 2],
}

impl PhaseTable {
    /// Tabulates `filter`'s separable form ([`Filter::eval_1d`]) at 65 phases per axis and stores
    /// [`Filter::integral`].
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if a radius is not finite and `> 0` (the range `(0, ∞)`) or is 8
    /// or more (more than [`MAX_TAPS`] taps; the range `(0, 8)`), `what` being
    /// `"filter radius rx"` or `"filter radius ry"`; [`Error::NotSeparable`] if the filter is
    /// not separable. Non-finite values from a plugin filter are stored as 0, magnitudes above
    /// 2⁶² as ±2⁶².
    ///
    /// ```
    /// use nyquist::filter::{Lanczos, PhaseTable, Triangle};
    /// assert_eq!(PhaseTable::new(&Lanczos::default()).unwrap().radius(), [4.0, 4.0]);
    /// let wide = Triangle::new([2.0, 8.0]).unwrap();
    /// assert_eq!(
    ///     PhaseTable::new(&wide).unwrap_err().to_string(),
    ///     "filter radius ry 8 is outside (0, 8)"
    /// );
    /// ```
    pub fn new<F: Filter + ?Sized>(filter: &F) -> Result<PhaseTable, Error> {
        let [rx, ry] = table_radius(filter)?;
        let integral = super::check_integral(filter.integral())?;
        if !filter.is_separable() {
            return Err(Error::NotSeparable {
                what: "phase table",
            });
        }
        let axis = |a: Axis, r: f32, what| {
            PhaseAxis::new(r, what, |d| filter.eval_1d(a, d).unwrap_or(0.0))
        };
        let axes = [
            axis(Axis::X, rx, "filter radius rx")?,
            axis(Axis::Y, ry, "filter radius ry")?,
        ];
        let constant = match (axes[0].constant, axes[1].constant) {
            (Some(x), Some(y)) => Some([x, y]),
            _ => None,
        };
        Ok(PhaseTable {
            axes,
            integral,
            constant,
            radius: [rx, ry],
        })
    }

    /// The footprint's weights along `axis` at phase `phase`: `out[k] ≈ f(k + phase − r)` for the
    /// taps `k < taps`, returned. Lanes from `taps` to the next multiple of 4 hold 0; the rest
    /// are not written. `phase` is clamped to `[0, 1]` (NaN reads as 0). Tap `k`'s pixel is in
    /// the footprint only while `k + phase ≤ 2r`: the caller counts its pixels (past that point
    /// the last tap holds the edge value `f(r)`, not a weight).
    ///
    /// ```
    /// use nyquist::filter::{Axis, Boxcar, PhaseTable, MAX_TAPS};
    /// let t = PhaseTable::new(&Boxcar::default()).unwrap();
    /// let mut w = [9.0f32; MAX_TAPS];
    /// assert_eq!(t.row(Axis::Y, 0.5, &mut w), 2);
    /// // Tap 1 is in the footprint only at phase 0; past the edge it holds f(r) = 1.
    /// assert_eq!(w[..4], [1.0, 1.0, 0.0, 0.0]);
    /// assert_eq!(w[4], 9.0);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn row(&self, axis: Axis, phase: f32, out: &mut [f32; MAX_TAPS]) -> usize {
        self.axes[axis.index()].row(phase, out)
    }

    /// The first four lanes of [`row`](PhaseTable::row), bit for bit, with one 4-lane
    /// interpolation instead of the whole padded row: for footprints of four pixels or fewer
    /// along `axis` (a radius-2 filter's, except at phase 0), the film's usual case. Lanes past
    /// the taps hold 0.
    ///
    /// ```
    /// use nyquist::filter::{Axis, Mitchell, PhaseTable, MAX_TAPS};
    /// let t = PhaseTable::new(&Mitchell::default()).unwrap();
    /// let mut w = [0.0f32; MAX_TAPS];
    /// t.row(Axis::Y, 0.3, &mut w);
    /// assert_eq!(t.row4(Axis::Y, 0.3), w[..4]);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn row4(&self, axis: Axis, phase: f32) -> [f32; 4] {
        self.axes[axis.index()].row4(phase)
    }

    /// One tap of [`row`](PhaseTable::row): `row(axis, phase, ..)[k]` without the others, 0 for
    /// `k` past the padded row.
    ///
    /// ```
    /// use nyquist::filter::{Axis, PhaseTable, Triangle, MAX_TAPS};
    /// let t = PhaseTable::new(&Triangle::default()).unwrap();
    /// let mut w = [0.0f32; MAX_TAPS];
    /// t.row(Axis::X, 0.3, &mut w);
    /// assert_eq!(t.tap(Axis::X, 0.3, 2), w[2]);
    /// assert_eq!(t.tap(Axis::X, 0.3, 99), 0.0);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn tap(&self, axis: Axis, phase: f32, k: usize) -> f32 {
        self.axes[axis.index()].tap(phase, k)
    }

    /// The weight of every pixel in any footprint, if the filter is constant on its support (a
    /// box): then a footprint needs no lookups at all. `None` otherwise.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, PhaseTable, Triangle};
    /// assert_eq!(PhaseTable::new(&Boxcar::new([0.7, 1.5]).unwrap()).unwrap().constant(), Some(1.0));
    /// assert_eq!(PhaseTable::new(&Triangle::default()).unwrap().constant(), None);
    /// ```
    pub fn constant(&self) -> Option<f32> {
        self.constant.map(|[x, y]| x * y)
    }

    /// Taps per footprint along `axis`, `⌊2r⌋ + 1`.
    ///
    /// ```
    /// use nyquist::filter::{Axis, Mitchell, PhaseTable};
    /// assert_eq!(PhaseTable::new(&Mitchell::default()).unwrap().taps(Axis::X), 5);
    /// ```
    pub fn taps(&self, axis: Axis) -> usize {
        self.axes[axis.index()].taps
    }

    /// The 1D factor along `axis` at offset `d` from the same grid: tap `⌊d + r⌋` at phase
    /// `frac(d + r)`; exactly 0 past the radius and for NaN or ∞. It equals the footprint's
    /// value for that pixel up to the rounding of `d`.
    ///
    /// ```
    /// use nyquist::filter::{Axis, Boxcar, PhaseTable};
    /// let t = PhaseTable::new(&Boxcar::default()).unwrap();
    /// assert_eq!(t.weight_1d(Axis::X, 0.5), 1.0);
    /// assert_eq!(t.weight_1d(Axis::X, 0.51), 0.0);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn weight_1d(&self, axis: Axis, d: f32) -> f32 {
        self.axes[axis.index()].weight(d)
    }

    /// The weight at offset `(dx, dy)`: `weight_1d(X, dx)·weight_1d(Y, dy)`.
    ///
    /// ```
    /// use nyquist::filter::{Filter, Gaussian, PhaseTable};
    /// let g = Gaussian::default();
    /// let t = PhaseTable::new(&g).unwrap();
    /// assert!((t.weight(0.3, -1.1) - g.eval(0.3, -1.1)).abs() < 1e-3);
    /// assert_eq!(t.weight(f32::NAN, 0.0), 0.0);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn weight(&self, dx: f32, dy: f32) -> f32 {
        if let Some(c) = self.constant {
            // What the two constant axes answer, from the header: a box's one-weight
            // footprint touches no table memory.
            return constant_weight(c, self.radius, dx.abs(), dy.abs());
        }
        self.weight_1d(Axis::X, dx) * self.weight_1d(Axis::Y, dy)
    }

    /// Fills `out` (row-major, `nx` columns) with the weights of the pixels at offsets
    /// `(d0[0] + i, d0[1] + j)`, as [`FilterTable::footprint`](super::FilterTable::footprint):
    /// one [`row`](PhaseTable::row) per axis (at the phase of `d0 + r`) and an outer product.
    /// Pixels past the radius get 0. Each weight equals `weight(d0[0] + i, d0[1] + j)` up to the
    /// rounding of those sums; a one-weight footprint is `weight(d0[0], d0[1])`.
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `out.len()` is a positive multiple of `nx`;
    /// [`Error::TooMany`] for more than 2²² columns or rows (the first pixel's tap is formed
    /// exactly up to that distance from the support).
    ///
    /// ```
    /// use nyquist::filter::{Mitchell, PhaseTable};
    /// let t = PhaseTable::new(&Mitchell::default()).unwrap();
    /// let mut w = [0.0f32; 16];
    /// t.footprint([-1.75, -1.5], 4, &mut w).unwrap();
    /// assert_eq!(w[2 * 4 + 3], t.weight(-1.75 + 3.0, -1.5 + 2.0));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        if let Some(w) = super::table::one_weight(nx, &mut *out) {
            *w = self.weight(d0[0], d0[1]);
            return Ok(());
        }
        self.footprint_many(d0, nx, out)
    }

    /// [`footprint`](Self::footprint) past the one-weight case.
    #[inline]
    fn footprint_many(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        let ny = super::table::check_footprint(nx, out)?;
        if nx.max(ny) > SHIFT_LIMIT as usize {
            return Err(Error::TooMany {
                what: "footprint side",
                value: nx.max(ny) as u64,
                max: SHIFT_LIMIT as u64,
            });
        }
        let (sx, px) = self.axes[0].locate(d0[0]);
        let (sy, py) = self.axes[1].locate(d0[1]);
        if nx <= 4 && out.len() <= 4 * nx && sx == 0 && sy == 0 {
            // Up to 4 × 4 starting at the first taps (radius ≤ 2, the usual filters): four
            // taps per axis (`0 − shift` is exactly 0 in the mask) and their outer product.
            let fx4 = self.axes[0].factors4(d0[0], px);
            let fy4 = self.axes[1].factors4(d0[1], py);
            super::table::narrow_outer_product(&fx4, &fy4, nx, out);
            return Ok(());
        }
        let mut fx = [0.0f32; MAX_TAPS];
        let mut fy = [0.0f32; MAX_TAPS];
        let kx = self.axes[0].factors(d0[0], (sx, px), &mut fx);
        let ky = self.axes[1].factors(d0[1], (sy, py), &mut fy);
        // Row 0 holds the x factors until it is scaled last; every other row is row 0 times
        // its y factor. A footprint that starts at its first tap (shift 0, the usual case)
        // copies the taps straight.
        let (first, rest) = out.split_at_mut(nx);
        match (kx, fx.get(..nx)) {
            (0, Some(taps)) => first.copy_from_slice(taps),
            _ => {
                for (i, w) in first.iter_mut().enumerate() {
                    *w = tap_or_zero(&fx, kx, i);
                }
            }
        }
        for (j, row) in rest.chunks_exact_mut(nx).enumerate() {
            let wy = tap_or_zero(&fy, ky, j + 1);
            for (w, &x) in row.iter_mut().zip(first.iter()) {
                *w = x * wy;
            }
        }
        let wy0 = tap_or_zero(&fy, ky, 0);
        for w in first.iter_mut() {
            *w *= wy0;
        }
        Ok(())
    }

    /// The filter's radius `[rx, ry]`.
    ///
    /// ```
    /// use nyquist::filter::{Gaussian, PhaseTable};
    /// assert_eq!(PhaseTable::new(&Gaussian::default()).unwrap().radius(), [2.0, 2.0]);
    /// ```
    pub fn radius(&self) -> [f32; 2] {
        self.radius
    }

    /// The filter's integral (from [`Filter::integral`] at build time).
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, PhaseTable};
    /// assert_eq!(PhaseTable::new(&Boxcar::default()).unwrap().integral(), 1.0);
    /// ```
    pub fn integral(&self) -> f32 {
        self.integral
    }
}

impl Weights for PhaseTable {
    fn radius(&self) -> [f32; 2] {
        self.radius
    }

    fn integral(&self) -> f32 {
        self.integral
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight(&self, dx: f32, dy: f32) -> f32 {
        PhaseTable::weight(self, dx, dy)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn weight_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        Some(PhaseTable::weight_1d(self, axis, d))
    }

    fn is_separable(&self) -> bool {
        true
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn footprint(&self, d0: [f32; 2], nx: usize, out: &mut [f32]) -> Result<(), Error> {
        PhaseTable::footprint(self, d0, nx, out)
    }
}

impl PhaseAxis {
    /// Where a footprint whose first pixel is at offset `d0` starts in the taps: the shift
    /// `⌊d0 + r⌋` (0 when the first pixel is the footprint's first) and the phase `c − shift`
    /// at which the tap row is read.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn locate(&self, d0: f32) -> (isize, f32) {
        let s = d0 + self.radius;
        // ⌊s⌋ by the rounding trick, exact for |c| ≤ 2²² (where c + MAGIC is an integer-spaced
        // f32). A first pixel further than that from the support is 2²² pixels or more from
        // it: to the right every tap is 0 either way; to the left a footprint would need more
        // than 2²² columns (or rows) to reach it, which `footprint` refuses.
        // max/min rather than clamp: a NaN `s` becomes −SHIFT_LIMIT (every tap 0), not NaN.
        #[allow(clippy::manual_clamp)]
        let c = s.max(-SHIFT_LIMIT).min(SHIFT_LIMIT);
        // ⌊c⌋ by the rounding trick: round c to an integer, step back when that passed c.
        let m = c + MAGIC;
        let r = m - MAGIC;
        let shift = (m.to_bits().wrapping_sub(MAGIC_BITS) as i32 as isize) - isize::from(r > c);
        (shift, c - shift as f32)
    }

    /// The taps of a footprint whose first pixel is at offset `d0`, masked to the radius, given
    /// its [`locate`](Self::locate)d `(shift, phase)`: `out[k]` is the weight of the pixel at
    /// `d0 + i` for `i = k − shift`; returns `shift = ⌊d0 + r⌋` (0 when the first pixel is the
    /// footprint's first).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn factors(&self, d0: f32, (shift, phase): (isize, f32), out: &mut [f32; MAX_TAPS]) -> isize {
        self.row(phase, out);
        // Mask every tap whose pixel is past the radius: |d0 + (k − shift)| > r, with k − shift
        // formed exactly in floats so the loop vectorises.
        // Only the padded row (taps past it are 0 already), four lanes at a time.
        let sf = shift as f32;
        for c in 0..MAX_TAPS / 4 {
            if 4 * c >= self.stride {
                break;
            }
            for k in 4 * c..4 * c + 4 {
                let d = (TAP_INDEX[k] - sf) + d0;
                out[k] *= mask(d.abs() <= self.radius);
            }
        }
        shift
    }

    /// Lanes 0–3 of [`factors`](Self::factors) for a footprint at shift 0 (`phase` from
    /// [`locate`](Self::locate)), bit for bit: one 4-lane interpolation and mask instead of the
    /// whole padded row, for footprints of at most four pixels along this axis.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn factors4(&self, d0: f32, phase: f32) -> [f32; 4] {
        let mut out = self.row4(phase);
        // At shift 0, `d0 + r ∈ [0, 1)`: the four pixels lie at `d0 + k ∈ [−r, 4 − r)`, all
        // inside the radius once `r ≥ 2` (the radius-2 defaults), where the mask would keep
        // every tap.
        if self.radius < 2.0 {
            for (k, w) in out.iter_mut().enumerate() {
                *w *= mask((TAP_INDEX[k] + d0).abs() <= self.radius);
            }
        }
        out
    }
}

/// Lanes `k … k + 3` (`k ≤ MAX_TAPS − 4`) of two tap rows interpolated at `t`:
/// `(1 − t)·a + t·b`, exact at `t = 0` and `1`. Plain indices into fixed arrays: no iterator
/// adapters for the inliner to give up on.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn lerp4(a: &[f32; MAX_TAPS], b: &[f32; MAX_TAPS], t: f32, k: usize) -> [f32; 4] {
    let k = k.min(MAX_TAPS - 4);
    let mut out = [0.0f32; 4];
    for (l, o) in out.iter_mut().enumerate() {
        *o = (1.0 - t) * a[k + l] + t * b[k + l];
    }
    out
}

/// `0.0, 1.0, …, 15.0`: tap indices as floats.
const TAP_INDEX: [f32; MAX_TAPS] = {
    let mut k = [0.0f32; MAX_TAPS];
    let mut i = 0;
    while i < MAX_TAPS {
        k[i] = i as f32;
        i += 1;
    }
    k
};

/// Tap `i + shift` of `f` (0 outside the taps), the weight of footprint pixel `i`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn tap_or_zero(f: &[f32; MAX_TAPS], shift: isize, i: usize) -> f32 {
    let k = (i as isize).wrapping_add(shift);
    if k < 0 {
        return 0.0;
    }
    f.get(k as usize).copied().unwrap_or(0.0)
}
