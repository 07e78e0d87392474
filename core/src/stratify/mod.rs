//! Stratified, Latin-hypercube and shuffled samples over caller buffers.
//!
//! Everything here fills a slice the caller owns and never allocates. The randomness comes from
//! any [`rand_core::Rng`] (`R: Rng + ?Sized`, so `&mut dyn Rng` works too); the crate's default is
//! [`crate::rng::DefaultRng`] (PCG32), seeded with [`crate::rng::default_rng`]. The stratified
//! and Latin-hypercube fills draw one `u64` from it, the key of a [`crate::rng::CounterRng`]
//! whose words (no serial chain between them) supply the per-element randomness; [`shuffle`]
//! draws from it directly. Bounded integers are drawn without modulo bias (Lemire's method).
//!
//! | function | what it writes |
//! |---|---|
//! | [`stratified_1d`] | `n` samples, one in each of `n` equal strata of `[0, 1)` |
//! | [`stratified_2d`] | `nx · ny` points `[x0, y0, x1, y1, …]`, one per grid cell, row by row |
//! | [`latin_hypercube`] | `n` points in `dims` dimensions; each dimension's `n` strata hit once |
//! | [`LatinHypercube`] | the same, stateless: a hash of `(seed, point, dim)`, no generator |
//! | [`shuffle`] | a uniform permutation of `count` blocks of `dims` values (pbrt's `Shuffle`) |
//!
//! Every value lies in `[0, 1)`, strictly inside its stratum. The textbook `(k + u) / n` can be
//! pushed by `f32` rounding into the next stratum or to 1 (`3.0 + (1 − 2⁻²⁴)` is `4.0` in
//! `f32`). Here, for `n ≤ 2²²` strata per axis, a sample is built in fixed point instead:
//! `(k · 2^(23−b) + 2j + 1) · 2^−(23−b) / n` with `b = ⌈log₂ n⌉` and a `(22 − b)`-bit jitter
//! `j`; the numerator is exact in `f32` and keeps a margin of at least `2⁻²³` from both stratum
//! edges, more than the two roundings can cover, so no check is needed. Jitters are therefore
//! quantised (at most 22 bits, 16 in 2D and Latin hypercubes, see each function). Beyond `2²²`
//! strata the value is checked against its stratum in `f64` and moved back by ulps; beyond
//! `2²⁴` neighbouring strata can share `f32` values, so one-per-stratum is only as fine as `f32`
//! allows.
//!
//! Sources: stratified (jittered) sampling, Cook 1986 "Stochastic sampling in computer
//! graphics"; Latin hypercube sampling, McKay, Beckman & Conover 1979; the shuffle is the
//! Fisher–Yates / Durstenfeld algorithm (Knuth, TAOCP vol. 2, Algorithm P).
//!
//! ```
//! use nyquist::rng::default_rng;
//! use nyquist::stratify::{Jitter, stratified_2d};
//! let mut pts = [0.0f32; 2 * 4 * 4];
//! stratified_2d(&mut pts, 4, 4, Jitter::Jittered, &mut default_rng(1)).unwrap();
//! // Point 5 is in cell (1, 1) of the 4 × 4 grid.
//! assert_eq!(((pts[10] * 4.0) as u32, (pts[11] * 4.0) as u32), (1, 1));
//! ```

mod jittered;
mod latin_hypercube;
mod shuffle;

pub use jittered::{Jitter, stratified_1d, stratified_2d};
pub use latin_hypercube::{LatinHypercube, latin_hypercube};
pub use shuffle::shuffle;

use crate::ONE_MINUS_EPSILON;

/// Stratum count up to which [`Strata`] places samples by the exact fixed-point route.
const EXACT_MAX: u32 = 1 << 22;

/// Placement of samples in `n` equal strata of `[0, 1)`, precomputed per axis.
///
/// For `n ≤ 2²²` (`b = ⌈log₂ n⌉`) a sample in stratum `k` is `s · scale` with the integer
/// `s = k · 2^(23−b) + (2j + 1)`, `j` a `(22 − b)`-bit jitter, and `scale = fl(1/n) · 2^−(23−b)`.
/// `s < 2²³` is exact in `f32`, and `s` sits at least `2^−(23−b)/n ≥ 2⁻²³` (relative to the
/// unit interval) inside its stratum, more than the two roundings (`fl(1/n)` and the product,
/// together under `2⁻²³ · x`) can move it; so the value is strictly inside the stratum, in exact
/// arithmetic, with no check. The price is a jitter quantised to `2^(22−b)` levels, i.e. about 23
/// significant bits per value. Larger `n` take the checked route ([`place`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Strata {
    n: u32,
    shift: u32,
    jitter_bits: u32,
    scale: f32,
    inv: f32,
}

impl Strata {
    /// Constants for `n ≥ 1` strata.
    pub(crate) fn new(n: u32) -> Strata {
        let n = n.max(1);
        let inv = 1.0 / n as f32;
        if n <= EXACT_MAX {
            let b = 32 - (n - 1).leading_zeros();
            let shift = 23 - b;
            Strata {
                n,
                shift,
                jitter_bits: 22 - b,
                scale: inv / (1u32 << shift) as f32,
                inv,
            }
        } else {
            Strata {
                n,
                shift: 0,
                jitter_bits: 24,
                scale: 0.0,
                inv,
            }
        }
    }

    /// How many random bits [`Strata::jittered`] uses.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn jitter_bits(&self) -> u32 {
        self.jitter_bits
    }

    /// A sample in stratum `k < n` jittered by the low [`Strata::jitter_bits`] bits of `bits`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn jittered(&self, k: u32, bits: u32) -> f32 {
        if self.n <= EXACT_MAX {
            let s = (k << self.shift) | (bits << 1) | 1;
            s as f32 * self.scale
        } else {
            place(k, bits as f32 * (1.0 / 16_777_216.0), self.n, self.inv)
        }
    }

    /// `fl(1/n)`, for the checked route ([`place`]).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn inv(&self) -> f32 {
        self.inv
    }

    /// Whether the exact fixed-point route applies (`n ≤ 2²²`).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn is_exact(&self) -> bool {
        self.n <= EXACT_MAX
    }

    /// For the exact route: the fixed-point numerator of stratum `k`'s lower edge, with the
    /// always-set lowest bit; OR the jitter bits, shifted left by one, into it and multiply by
    /// [`Strata::scale`].
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn base(&self, k: u32) -> u32 {
        (k << self.shift) | 1
    }

    /// For the exact route: the scale from the fixed-point numerator to `[0, 1)`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn scale(&self) -> f32 {
        self.scale
    }

    /// The centre of stratum `k < n` (rounded to `f32`, inside the stratum).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn centre(&self, k: u32) -> f32 {
        if self.n <= EXACT_MAX {
            let s = ((k << 1) | 1) << (self.shift - 1);
            s as f32 * self.scale
        } else {
            place(k, 0.5, self.n, self.inv)
        }
    }
}

/// `(k + u) / n` as an `f32` inside stratum `k` of `n`, for a jitter `u` in `[0, 1)`, given
/// `inv_n = 1 / n`. The fast product is checked against the stratum in `f64` (exact for
/// `n ≤ 2²⁹`) and, on the rare miss, stepped back inside; the result is in `[0, 1)`. Used for
/// `n > 2²²`, where [`Strata`]'s exact route has no jitter bits left.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn place(k: u32, u: f32, n: u32, inv_n: f32) -> f32 {
    let x = (k as f32 + u) * inv_n;
    let t = f64::from(x) * f64::from(n);
    if t >= f64::from(k) && t < f64::from(k) + 1.0 && x < 1.0 {
        x
    } else {
        place_slow(k, x, n)
    }
}

/// The rare path of [`place`]: walk `x` by ulps into stratum `k` (at most 64 steps, then clamp).
#[cold]
#[inline(never)]
fn place_slow(k: u32, x: f32, n: u32) -> f32 {
    let (lo, hi) = (f64::from(k), f64::from(k) + 1.0);
    let mut x = crate::math::clamp_unit(x);
    for _ in 0..64 {
        let t = f64::from(x) * f64::from(n);
        if t >= hi && x > 0.0 {
            x = x.next_down();
        } else if t < lo && x < ONE_MINUS_EPSILON {
            x = x.next_up();
        } else {
            break;
        }
    }
    crate::math::clamp_unit(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn place_keeps_the_stratum_at_its_edges() {
        let u_max = 1.0 - 1.0 / 16_777_216.0;
        for n in (1..3000u32).chain([65_535, 1 << 20, 10_000_019]) {
            let inv = 1.0 / n as f32;
            for k in [0, 1, n / 3, n / 2, n.saturating_sub(2), n - 1].map(|k| k.min(n - 1)) {
                for u in [0.0, 0.5, u_max] {
                    let x = place(k, u, n, inv);
                    assert!((0.0..1.0).contains(&x), "n={n} k={k} u={u}: {x}");
                    if n <= 1 << 24 {
                        let t = f64::from(x) * f64::from(n);
                        assert!(
                            t >= f64::from(k) && t < f64::from(k + 1),
                            "n={n} k={k} u={u}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn place_keeps_stratum_0_where_the_fast_product_rounds_past_it() {
        // Past 2²⁴ strata, fl(1/n) can exceed 1/n by enough that the largest jitter's product
        // fl(u · fl(1/n)) reaches 1/n: stratum 1. These n (found by a search over n ≤ 2²⁹, where
        // the f64 check is exact) are such cases; `place` must step the value back.
        let u_max = 1.0 - 1.0 / 16_777_216.0;
        for n in [16_780_117u32, 33_560_234, 67_120_459, 268_481_833] {
            let inv = 1.0 / n as f32;
            let fast = u_max * inv;
            assert!(f64::from(fast) * f64::from(n) >= 1.0, "n={n}: not a case");
            let x = place(0, u_max, n, inv);
            assert!(x < fast && f64::from(x) * f64::from(n) < 1.0, "n={n}: {x}");
        }
    }

    #[test]
    fn place_stops_stepping_at_the_stratum_edge() {
        // Where the fast product misses and the walk reaches the stratum's lower edge exactly,
        // the edge is the value: (41 + 0)/5373952 = 2⁻¹⁷, and k = 24887007 of 3·2²³ centred,
        // whose stratum holds one f32, its lower edge (one more step up leaves the stratum).
        let n = 5_373_952u32;
        assert_eq!(place(41, 0.0, n, 1.0 / n as f32), 2f32.powi(-17));
        let (n, k) = (25_165_824u32, 24_887_007u32);
        let x = place(k, 0.5, n, 1.0 / n as f32);
        let t = f64::from(x) * f64::from(n);
        assert!(t >= f64::from(k) && t < f64::from(k) + 1.0, "{x}: t = {t}");
    }

    #[test]
    fn strata_values_are_strictly_inside_for_extreme_jitters() {
        let ns = (1..5000u32).chain((12..=23).flat_map(|e| {
            let p = 1u32 << e;
            [p - 3, p - 1, p, p + 1, p + 7]
        }));
        for n in ns.chain([10_000_019, u32::MAX]) {
            let st = Strata::new(n);
            let all = if st.jitter_bits() >= 32 {
                u32::MAX
            } else {
                (1 << st.jitter_bits()) - 1
            };
            let ks = [0, 1, 2, n / 3, n / 2, n / 2 + 1, n.saturating_sub(2), n - 1];
            for k in ks.map(|k| k.min(n - 1)) {
                for x in [
                    st.jittered(k, 0),
                    st.jittered(k, all),
                    st.jittered(k, all / 3),
                    st.centre(k),
                ] {
                    assert!((0.0..1.0).contains(&x), "n={n} k={k}: {x}");
                    if n <= 1 << 22 {
                        // Exact: x·n has at most 24 + 23 significant bits.
                        let t = f64::from(x) * f64::from(n);
                        assert!(t > f64::from(k) && t < f64::from(k + 1), "n={n} k={k}: {x}");
                    }
                }
            }
        }
    }

    /// Beyond 2²² strata the 24 jitter bits map linearly onto the stratum: bits `b` put the
    /// value at `(k + b/2²⁴)/n`, within two ulps (checked near 0, where an ulp is far below a
    /// jitter step).
    #[test]
    fn checked_route_places_the_jitter_linearly() {
        for n in [(1u32 << 22) + 1, 10_000_019] {
            let st = Strata::new(n);
            assert_eq!(st.jitter_bits(), 24);
            for k in [0u32, 1, 1000] {
                for bits in [0u32, 1, 1 << 22, 1 << 23, 3 << 22, (1 << 24) - 1] {
                    let want = (f64::from(k) + f64::from(bits) / 16_777_216.0) / f64::from(n);
                    let x = st.jittered(k, bits);
                    let ulp = f64::from(f32::from_bits(x.to_bits() + 1) - x);
                    assert!(
                        (f64::from(x) - want).abs() <= 2.0 * ulp,
                        "n={n} k={k} bits={bits}: {x} is not {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn centre_is_the_rounded_midpoint() {
        for n in [1u32, 2, 3, 7, 10, 1000, 1 << 22] {
            let st = Strata::new(n);
            for k in [0, n / 2, n - 1] {
                let exact = (f64::from(k) + 0.5) / f64::from(n);
                assert!(
                    (f64::from(st.centre(k)) - exact).abs() <= exact * 1.2e-7,
                    "n={n} k={k}"
                );
            }
        }
        assert_eq!(Strata::new(4).centre(1), 0.375);
    }

    #[test]
    fn pbrt_style_rounding_would_leave_the_stratum() {
        // The reason for `place`: with k = 3, u = 1 - 2^-24, k + u rounds to 4 in f32.
        let u = 1.0f32 - 1.0 / 16_777_216.0;
        assert_eq!(3.0f32 + u, 4.0);
        let x = place(3, u, 5, 0.2);
        assert!(f64::from(x) * 5.0 < 4.0);
    }
}
