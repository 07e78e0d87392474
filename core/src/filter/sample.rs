//! Filter importance sampling (pbrt-v4 style): offsets drawn with density ∝ `|f|`.

use super::Filter;
use super::table::table_radius;
use crate::error::Interval;
use crate::{Error, math::clamp_unit};

/// An offset drawn by [`FilterSampler::sample`] and its weight `f(offset)/pdf(offset)`.
///
/// ```
/// use nyquist::filter::FilterSample;
/// let s = FilterSample { offset: [0.25, -0.5], weight: 1.0 };
/// assert_eq!(s.offset[1], -0.5);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterSample {
    /// Offset `[x, y]` from the pixel centre, in pixels, inside the filter's support.
    pub offset: [f32; 2],
    /// `f(offset) / pdf(offset)`, sign included (negative in a negative lobe). Finite.
    pub weight: f32,
}

/// Importance sampling of a filter: a piecewise-constant 2D distribution over the support
/// `[−rx, rx] × [−ry, ry]` on an `N × N` grid (default 32 × 32), each cell's probability its
/// share of `∫|f|` (4 × 4-point Gauss–Legendre per cell; a cell where those points all read 0
/// uses the mean of its corners, so no part of the support where `f ≠ 0` gets zero density).
///
/// [`sample`](Self::sample) returns the weight `f(p)/pdf(p)` with `f` evaluated directly at the
/// drawn point, so the estimator `Σ weight·g(offset) / n` is unbiased for `∫∫ f·g` whatever `N`
/// is; `N` only changes the variance. A renderer can trace one camera ray per filter sample
/// instead of splatting each sample into all pixels the filter covers.
///
/// The tables live inline (`4·N·(N + 1)` bytes: 4.2 KB at the default size). Allocates: no.
/// The filter is stored by value; pass `&F` or `&dyn Filter` to borrow it. No symmetry is
/// assumed.
///
/// # Examples
///
/// ```
/// use nyquist::filter::{Filter, FilterSampler, Mitchell};
/// let m = Mitchell::default();
/// let sampler: FilterSampler<_> = FilterSampler::new(m).unwrap();
/// let s = sampler.sample([0.3, 0.7]);
/// assert!(s.offset[0].abs() <= 2.0 && s.offset[1].abs() <= 2.0);
/// // weight = f / pdf
/// let pdf = sampler.pdf(s.offset);
/// assert!((s.weight - m.eval(s.offset[0], s.offset[1]) / pdf).abs() < 1e-4);
/// ```
#[derive(Clone, Debug)]
pub struct FilterSampler<F, const N: usize = 32> {
    filter: F,
    radius: [f32; 2],
    /// Cell size `[hx, hy]`.
    cell: [f32; 2],
    /// Marginal CDF over rows (y): `marginal[j]` = mass of rows `0..=j`; the last is 1.
    marginal: [f32; N],
    /// Conditional CDF within each row: `conditional[j][i]` = share of cells `0..=i` in row `j`.
    conditional: [[f32; N]; N],
    /// Whether `|f|` had any mass at all.
    nonzero: bool,
}

impl<F: Filter, const N: usize> FilterSampler<F, N> {
    /// Tabulates `∫|filter|` over an `N × N` grid of cells (`16·N²` evaluations). `N = 0` does
    /// not compile.
    ///
    /// # Errors
    /// [`Error::OutOfRange`] if the filter's radius is not finite and `> 0` (`what` is
    /// `"filter radius rx"` or `"filter radius ry"`, the range `(0, ∞)`), or so small that a
    /// cell's area `(2rx/N)·(2ry/N)` (in `f32`) is below the smallest normal `f32` (the density
    /// `1/area` would not be finite: only plugin filters can get there, built-ins need
    /// `r ≥ 2⁻¹⁶`).
    ///
    /// ```
    /// use nyquist::filter::{Filter, FilterSampler, Lanczos};
    /// let l = Lanczos::default();
    /// let s = FilterSampler::<&dyn Filter, 64>::new(&l).unwrap();
    /// assert_eq!(s.radius(), [4.0, 4.0]);
    /// ```
    pub fn new(filter: F) -> Result<FilterSampler<F, N>, Error> {
        const { assert!(N >= 1, "a filter sampler needs at least one cell per axis") };
        let [rx, ry] = table_radius(&filter)?;
        let hx = 2.0 * f64::from(rx) / N as f64;
        let hy = 2.0 * f64::from(ry) / N as f64;
        // `pdf` divides by the f32 cell area: it must be a normal f32 so that every density is
        // finite (found by the fuzzer: a subnormal radius gave a zero cell and a NaN pdf).
        let area = (hx as f32) * (hy as f32);
        if !(area >= f32::MIN_POSITIVE) {
            return Err(Error::OutOfRange {
                what: "filter sampler cell area (2rx/N)·(2ry/N)",
                value: f64::from(area),
                range: Interval::at_least(f64::from(f32::MIN_POSITIVE)),
            });
        }
        let at = |i: f64, j: f64| -> f64 {
            let x = (-f64::from(rx) + i * hx) as f32;
            let y = (-f64::from(ry) + j * hy) as f32;
            let v = f64::from(filter.eval(x, y)).abs();
            if v.is_finite() { v } else { 0.0 }
        };
        // A cell's mass is ∫|f| over it by 4 × 4-point Gauss–Legendre quadrature (exact for
        // polynomials of degree 7 per axis), not |f| at the centre: where |f| bends inside a
        // cell (Lanczos' lobes at 32 cells over r = 4) the centre value misjudges the cell by
        // far more than sampling noise, and the drawn points would not follow |f|.
        const NODES: [f64; 4] = [
            0.5 - 0.430_568_155_797_026_3,
            0.5 - 0.169_990_521_792_428_1,
            0.5 + 0.169_990_521_792_428_1,
            0.5 + 0.430_568_155_797_026_3,
        ];
        const WEIGHTS: [f64; 4] = [
            0.173_927_422_568_726_9,
            0.326_072_577_431_273_1,
            0.326_072_577_431_273_1,
            0.173_927_422_568_726_9,
        ];
        let mass = |fi: f64, fj: f64| -> f64 {
            let mut m = 0.0;
            for (&v, &wv) in NODES.iter().zip(&WEIGHTS) {
                for (&u, &wu) in NODES.iter().zip(&WEIGHTS) {
                    m += wu * wv * at(fi + u, fj + v);
                }
            }
            m
        };
        let mut conditional = [[0.0f32; N]; N];
        let mut row_mass = [0.0f64; N];
        for (j, row) in conditional.iter_mut().enumerate() {
            let mut sum = 0.0f64;
            // First pass: cumulative |f| in f64, stored temporarily as f32 after normalising.
            let mut cum = [0.0f64; N];
            for (i, c) in cum.iter_mut().enumerate() {
                let (fi, fj) = (i as f64, j as f64);
                let mut v = mass(fi, fj);
                if v == 0.0 {
                    v = 0.25
                        * (at(fi, fj)
                            + at(fi + 1.0, fj)
                            + at(fi, fj + 1.0)
                            + at(fi + 1.0, fj + 1.0));
                }
                sum += v;
                *c = sum;
            }
            row_mass[j] = sum;
            if sum > 0.0 {
                for (r, c) in row.iter_mut().zip(cum) {
                    *r = (c / sum) as f32;
                }
            } else {
                for (i, r) in row.iter_mut().enumerate() {
                    *r = (i + 1) as f32 / N as f32;
                }
            }
            row[N - 1] = 1.0;
        }
        let total: f64 = row_mass.iter().sum();
        let mut marginal = [0.0f32; N];
        let nonzero = total > 0.0 && total.is_finite();
        let mut cum = 0.0f64;
        for (m, mass) in marginal.iter_mut().zip(row_mass) {
            cum += mass;
            *m = if nonzero { (cum / total) as f32 } else { 0.0 };
        }
        if nonzero {
            marginal[N - 1] = 1.0;
        }
        Ok(FilterSampler {
            filter,
            radius: [rx, ry],
            cell: [hx as f32, hy as f32],
            marginal,
            conditional,
            nonzero,
        })
    }

    /// Draws an offset from `u ∈ [0, 1)²` (values outside are clamped into it; NaN counts as
    /// 0) with density `pdf(offset)` ∝ the tabulated `|f|`, and returns it with the weight
    /// `f(offset)/pdf(offset)`. A filter that is zero everywhere gives offset `[0, 0]` and
    /// weight 0.
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterSampler};
    /// let s: FilterSampler<_> = FilterSampler::new(Boxcar::default()).unwrap();
    /// let fs = s.sample([0.5, 0.25]);
    /// assert_eq!(fs.weight, 1.0); // box: pdf = 1/area = 1
    /// assert_eq!(fs.offset, [0.0, -0.25]);
    /// ```
    #[inline]
    pub fn sample(&self, u: [f32; 2]) -> FilterSample {
        if !self.nonzero {
            return FilterSample {
                offset: [0.0, 0.0],
                weight: 0.0,
            };
        }
        let (j, fy, py) = invert(&self.marginal, clamp_unit(u[1]));
        let (i, fx, px) = invert(&self.conditional[j], clamp_unit(u[0]));
        let x = (-self.radius[0] + (i as f32 + fx) * self.cell[0])
            .clamp(-self.radius[0], self.radius[0]);
        let y = (-self.radius[1] + (j as f32 + fy) * self.cell[1])
            .clamp(-self.radius[1], self.radius[1]);
        // Rounding can put the offset on the next cell's edge, where `pdf` would read that
        // cell: step it back into the cell it was drawn from (found by the fuzzer). With a
        // subnormal radius the cell's centre itself can round past the radius: clamp again
        // (also found by the fuzzer; such supports have no f32 density anyway).
        let x = snap_into_cell(x, i, self.radius[0], self.cell[0])
            .clamp(-self.radius[0], self.radius[0]);
        let y = snap_into_cell(y, j, self.radius[1], self.cell[1])
            .clamp(-self.radius[1], self.radius[1]);
        let pdf = px * py / (self.cell[0] * self.cell[1]);
        let w = self.filter.eval(x, y) / pdf;
        FilterSample {
            offset: [x, y],
            weight: if w.is_finite() { w } else { 0.0 },
        }
    }

    /// The density [`sample`](Self::sample) draws `offset` with (0 outside the support, for
    /// NaN, and for a filter that is zero everywhere).
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterSampler};
    /// let s: FilterSampler<_> = FilterSampler::new(Boxcar::default()).unwrap();
    /// assert_eq!(s.pdf([0.1, 0.1]), 1.0);
    /// assert_eq!(s.pdf([0.6, 0.1]), 0.0);
    /// ```
    pub fn pdf(&self, offset: [f32; 2]) -> f32 {
        let [rx, ry] = self.radius;
        let [x, y] = offset;
        if !(self.nonzero && x.abs() <= rx && y.abs() <= ry) {
            return 0.0;
        }
        let (i, j) = (
            cell_of::<N>(x, rx, self.cell[0]),
            cell_of::<N>(y, ry, self.cell[1]),
        );
        let mass = |cdf: &[f32; N], k: usize| cdf[k] - if k == 0 { 0.0 } else { cdf[k - 1] };
        mass(&self.marginal, j) * mass(&self.conditional[j], i) / (self.cell[0] * self.cell[1])
    }

    /// The filter's radius `[rx, ry]`.
    pub fn radius(&self) -> [f32; 2] {
        self.radius
    }

    /// The filter being sampled.
    pub fn filter(&self) -> &F {
        &self.filter
    }
}

/// The table cell `pdf` reads for offset `v` along an axis of radius `r` and cell width `h`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn cell_of<const N: usize>(v: f32, r: f32, h: f32) -> usize {
    (((v + r) / h) as usize).min(N - 1)
}

/// `v` moved to the nearest value that [`cell_of`] maps to cell `k`, where `v` was drawn (so
/// only rounding can have moved it out, and only to a neighbouring cell): a bisection between
/// `v` and the cell's centre, which `cell_of` maps to `k`. `v` itself when it already maps there.
#[inline]
fn snap_into_cell(v: f32, k: usize, r: f32, h: f32) -> f32 {
    // No cap: the drawn `k` is at most N − 1, and the top cell's own edge is `r`.
    let cell = |x: f32| cell_of::<{ usize::MAX }>(x, r, h);
    let c = cell(v);
    if c == k {
        return v;
    }
    let centre = -r + (k as f32 + 0.5) * h;
    if cell(centre) != k {
        return v;
    }
    // Invariant: `inside` maps to k, `outside` does not.
    let (mut inside, mut outside) = (centre, v);
    for _ in 0..64 {
        let mid = inside + (outside - inside) * 0.5;
        if mid == inside || mid == outside {
            break;
        }
        if cell(mid) == k {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    inside
}

/// Inverts a CDF (`cdf[N − 1] = 1`, non-decreasing) at `u ∈ [0, 1)`: the cell `k` with
/// `cdf[k − 1] ≤ u < cdf[k]`, the position `[0, 1)` within it, and its probability.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn invert<const N: usize>(cdf: &[f32; N], u: f32) -> (usize, f32, f32) {
    let k = cdf.partition_point(|&c| c <= u).min(N - 1);
    let lo = if k == 0 { 0.0 } else { cdf[k - 1] };
    let p = cdf[k] - lo;
    let t = if p > 0.0 {
        clamp_unit((u - lo) / p)
    } else {
        0.0
    };
    (k, t, p)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A value that rounding pushed one step past an edge of its cell comes back to the nearest
    /// values inside: within a few `f32` steps of where it was, on the cell's side.
    #[test]
    fn snap_into_cell_returns_a_value_beside_the_one_pushed_out() {
        let (r, h) = (1.5f32, 0.75f32); // cells [−1.5, −0.75), [−0.75, 0), [0, 0.75), [0.75, 1.5]
        for k in 0..4usize {
            for edge in [-r + k as f32 * h, -r + (k + 1) as f32 * h] {
                for v in [edge.next_down(), edge, edge.next_up()] {
                    if !(-r..=r).contains(&v) {
                        continue;
                    }
                    let s = snap_into_cell(v, k, r, h);
                    assert_eq!(cell_of::<4>(s, r, h), k, "v {v}, cell {k}: {s}");
                    assert!(
                        (s - v).abs() <= 4.0 * f32::EPSILON * 2.0,
                        "v {v}, cell {k}: {s}"
                    );
                }
            }
        }
    }
}
