//! Stratified, Latin-hypercube and shuffled samples over caller buffers.
//!
//! Everything here fills a slice the caller owns and never allocates. The randomness comes from
//! any [`rand_core::Rng`] (`R: Rng + ?Sized`, so `&mut dyn Rng` works too); the crate's default is
//! [`crate::rng::DefaultRng`] (PCG32), seeded with [`crate::rng::default_rng`]. Bounded integers
//! are drawn without modulo bias ([`crate::rng::uniform_below`]).
//!
//! | function | what it writes |
//! |---|---|
//! | [`stratified_1d`] | `n` samples, one in each of `n` equal strata of `[0, 1)` |
//! | [`stratified_2d`] | `nx · ny` points `[x0, y0, x1, y1, …]`, one per grid cell, row by row |
//! | [`latin_hypercube`] | `n` points in `dims` dimensions; each dimension's `n` strata hit once |
//! | [`LatinHypercube`] | the same, stateless: a hash of `(seed, point, dim)`, no generator |
//! | [`shuffle`] | a uniform permutation of `count` blocks of `dims` values (pbrt's `Shuffle`) |
//!
//! Every value lies in `[0, 1)`. A jittered coordinate is `(k + u) / n`, which `f32` rounding
//! can push to the next stratum or to 1; each value is checked against its stratum (exactly, in
//! `f64`, for `n ≤ 2²⁹`) and moved back by a few ulps when needed, and clamped to
//! [`crate::ONE_MINUS_EPSILON`]. For `n > 2²⁴` neighbouring strata may share `f32` values, so
//! the one-per-stratum property is only as fine as `f32` allows.
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

/// `(k + u) / n` as an `f32` inside stratum `k` of `n`, for a jitter `u` in `[0, 1)`, given
/// `inv_n = 1 / n`. The fast product is checked against the stratum in `f64` (exact for
/// `n ≤ 2²⁹`) and, on the rare miss, stepped back inside; the result is in `[0, 1)`.
#[inline(always)]
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
    fn pbrt_style_rounding_would_leave_the_stratum() {
        // The reason for `place`: with k = 3, u = 1 - 2^-24, k + u rounds to 4 in f32.
        let u = 1.0f32 - 1.0 / 16_777_216.0;
        assert_eq!(3.0f32 + u, 4.0);
        let x = place(3, u, 5, 0.2);
        assert!(f64::from(x) * 5.0 < 4.0);
    }
}
