//! Stratified sampling in one and two dimensions: one sample per stratum, jittered or centred.

use rand_core::Rng;

use super::{Strata, place};
use crate::{Error, hash, rng::CounterRng};

/// Where a stratified sample sits inside its stratum.
///
/// ```
/// use nyquist::rng::default_rng;
/// use nyquist::stratify::{Jitter, stratified_1d};
/// let mut xs = [0.0f32; 4];
/// stratified_1d(&mut xs, Jitter::Centered, &mut default_rng(0)).unwrap();
/// assert_eq!(xs, [0.125, 0.375, 0.625, 0.875]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Jitter {
    /// Uniformly random inside the stratum.
    Jittered,
    /// At the stratum's centre, `(k + ½) / n`: the unjittered baseline (pbrt-v2's
    /// `StratifiedSampler` with `jitter` off, the `uniform` sampler); draws nothing.
    Centered,
}

/// Fills `out` with `n = out.len()` stratified samples of `[0, 1)`: sample `k` lies in stratum
/// `[k/n, (k+1)/n)`, in stratum order (shuffle them with [`super::shuffle`] if needed).
/// Values are in `[0, 1)`. The jitter is quantised to `2^(22 − ⌈log₂ n⌉)` levels per stratum,
/// which keeps every value provably inside its stratum (see the module docs). Takes one `u64`
/// from `rng`, as the key of the [`CounterRng`] stream that supplies one word per sample.
/// Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] if `out` is empty; [`Error::TooMany`] if `out.len()` exceeds `u32::MAX`.
///
/// ```
/// use nyquist::rng::default_rng;
/// use nyquist::stratify::{Jitter, stratified_1d};
/// let mut xs = [0.0f32; 10];
/// stratified_1d(&mut xs, Jitter::Jittered, &mut default_rng(3)).unwrap();
/// for (k, &x) in xs.iter().enumerate() {
///     assert_eq!((x * 10.0) as usize, k);
/// }
/// assert!(stratified_1d(&mut [], Jitter::Jittered, &mut default_rng(3)).is_err());
/// ```
pub fn stratified_1d<R: Rng + ?Sized>(
    out: &mut [f32],
    jitter: Jitter,
    rng: &mut R,
) -> Result<(), Error> {
    if out.is_empty() {
        return Err(Error::ZeroSize { what: "samples" });
    }
    let n = u32::try_from(out.len()).map_err(|_| Error::TooMany {
        what: "samples",
        value: out.len() as u64,
        max: u64::from(u32::MAX),
    })?;
    let strata = Strata::new(n);
    match jitter {
        Jitter::Jittered => {
            // Jitters from a counter stream keyed by one draw of `rng`, as in 2D.
            let rng = &mut CounterRng::keyed_by(rng);
            // In 64 bits: at 2²² strata there are no jitter bits and the shift is 32.
            let shift = 32 - strata.jitter_bits();
            for (k, x) in (0..n).zip(out.iter_mut()) {
                *x = strata.jittered(k, (u64::from(rng.next_u32()) >> shift) as u32);
            }
        }
        Jitter::Centered => {
            for (k, x) in (0..n).zip(out.iter_mut()) {
                *x = strata.centre(k);
            }
        }
    }
    Ok(())
}

/// Points per block of a row whose jitter words are hashed before they are placed.
const HASH_BLOCK: usize = 16;

/// Fills `out` with one point per cell of an `nx × ny` grid over `[0, 1)²`, as
/// `[x0, y0, x1, y1, …]`, cell `(i, j)` (column `i`, row `j`) at point `j · nx + i`.
/// `out.len()` must be exactly `2 · nx · ny`. Values are in `[0, 1)`. Jittered points take one
/// 64-bit draw from `rng` per call, as the key of a WyRand stream ([`hash::wyrand`])
/// whose word `p` jitters point `p`: `22 − ⌈log₂ n⌉` jitter bits per axis (as
/// [`stratified_1d`]), 24 beyond `2²²` strata. Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] if `nx` or `ny` is 0; [`Error::TooMany`] (`what: "nx * ny"`, the
/// limit `usize::MAX / 2`) if `2 · nx · ny` overflows `usize`; [`Error::BufferTooShort`] if
/// `out` is shorter than `2 · nx · ny`; [`Error::BufferLength`] if it is longer.
///
/// ```
/// use nyquist::{Error, rng::default_rng, stratify::{Jitter, stratified_2d}};
/// let mut rng = default_rng(5);
/// let mut pts = [0.0f32; 2 * 3 * 2];
/// stratified_2d(&mut pts, 3, 2, Jitter::Centered, &mut rng).unwrap();
/// assert_eq!(&pts[..4], &[1.0 / 6.0, 0.25, 0.5, 0.25]);
/// assert_eq!(
///     stratified_2d(&mut pts, 4, 2, Jitter::Jittered, &mut rng),
///     Err(Error::BufferTooShort { needed: 16, actual: 12 })
/// );
/// ```
pub fn stratified_2d<R: Rng + ?Sized>(
    out: &mut [f32],
    nx: u32,
    ny: u32,
    jitter: Jitter,
    rng: &mut R,
) -> Result<(), Error> {
    if nx == 0 {
        return Err(Error::ZeroSize { what: "nx" });
    }
    if ny == 0 {
        return Err(Error::ZeroSize { what: "ny" });
    }
    let needed = (nx as usize)
        .checked_mul(ny as usize)
        .and_then(|c| c.checked_mul(2))
        .ok_or(Error::TooMany {
            what: "nx * ny",
            value: u64::from(nx) * u64::from(ny),
            max: (usize::MAX / 2) as u64,
        })?;
    if out.len() < needed {
        return Err(Error::BufferTooShort {
            needed,
            actual: out.len(),
        });
    }
    if out.len() > needed {
        return Err(Error::BufferLength {
            multiple_of: needed,
            actual: out.len(),
        });
    }
    let (sx, sy) = (Strata::new(nx), Strata::new(ny));
    let (points, _) = out.as_chunks_mut::<2>();
    match jitter {
        Jitter::Jittered => {
            // One 64-bit key from the caller's generator; point p's jitter is word p of the
            // WyRand stream with that key: x from its high 32 bits, y from the low 32. The
            // words have no serial dependency, so a block of them is hashed and then placed by
            // a loop that vectorises.
            let key = rng.next_u64();
            if sx.is_exact() && sy.is_exact() {
                // The top `jitter_bits` bits of each half land at bits `jitter_bits ..= 1` of
                // the fixed-point numerator (bit 0 is the always-set half step).
                let (shr_x, shr_y) = (31 - sx.jitter_bits(), 31 - sy.jitter_bits());
                let mask_x = ((1u32 << sx.jitter_bits()) - 1) << 1;
                let mask_y = ((1u32 << sy.jitter_bits()) - 1) << 1;
                let (scale_x, scale_y) = (sx.scale(), sy.scale());
                let place = |i: u32, base_y: u32, w: u64| {
                    let x = sx.base(i) | (((w >> 32) as u32 >> shr_x) & mask_x);
                    let y = base_y | ((w as u32 >> shr_y) & mask_y);
                    // Numerators are below 2²³: the signed conversion is exact and vectorises.
                    [x as i32 as f32 * scale_x, y as i32 as f32 * scale_y]
                };
                let mut p = 0u64;
                for (j, row) in (0..ny).zip(points.chunks_exact_mut(nx as usize)) {
                    let base_y = sy.base(j);
                    let (blocks, rest) = row.as_chunks_mut::<HASH_BLOCK>();
                    let mut i0 = 0u32;
                    for block in blocks {
                        let mut words = [0u64; HASH_BLOCK];
                        for (k, w) in (0u64..).zip(&mut words) {
                            *w = hash::wyrand(key, p + k);
                        }
                        for k in 0..HASH_BLOCK {
                            block[k] = place(i0 + k as u32, base_y, words[k]);
                        }
                        i0 += HASH_BLOCK as u32;
                        p += HASH_BLOCK as u64;
                    }
                    for (i, q) in (i0..).zip(rest) {
                        *q = place(i, base_y, hash::wyrand(key, p));
                        p += 1;
                    }
                }
            } else {
                // More than 2²² strata on an axis: 24 jitter bits per axis, placed and checked.
                let mut p = 0u64;
                for (j, row) in (0..ny).zip(points.chunks_exact_mut(nx as usize)) {
                    for (i, q) in (0..nx).zip(row) {
                        let w = hash::wyrand(key, p);
                        p += 1;
                        let (jx, jy) = ((w >> 40) as u32, (w as u32) >> 8);
                        *q = [
                            place(i, jx as f32 * (1.0 / 16_777_216.0), nx, sx.inv()),
                            place(j, jy as f32 * (1.0 / 16_777_216.0), ny, sy.inv()),
                        ];
                    }
                }
            }
        }
        Jitter::Centered => {
            for (j, row) in (0..ny).zip(points.chunks_exact_mut(nx as usize)) {
                let y = sy.centre(j);
                for (i, p) in (0..nx).zip(row) {
                    *p = [sx.centre(i), y];
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::default_rng;
    use proptest::prelude::*;

    fn stratum(x: f32, n: u32) -> u32 {
        (f64::from(x) * f64::from(n)) as u32
    }

    proptest! {
        #[test]
        fn one_sample_per_stratum_1d(n in 1usize..600, seed: u64, centered: bool) {
            let jitter = if centered { Jitter::Centered } else { Jitter::Jittered };
            let mut buf = std::vec![0.0f32; n];
            stratified_1d(&mut buf, jitter, &mut default_rng(seed)).unwrap();
            for (k, &x) in buf.iter().enumerate() {
                prop_assert!((0.0..1.0).contains(&x));
                prop_assert_eq!(stratum(x, n as u32), k as u32);
            }
        }

        #[test]
        fn one_point_per_cell_2d(nx in 1u32..50, ny in 1u32..50, seed: u64, centered: bool) {
            let jitter = if centered { Jitter::Centered } else { Jitter::Jittered };
            let mut buf = std::vec![0.0f32; (2 * nx * ny) as usize];
            stratified_2d(&mut buf, nx, ny, jitter, &mut default_rng(seed)).unwrap();
            for (c, p) in buf.chunks_exact(2).enumerate() {
                prop_assert!((0.0..1.0).contains(&p[0]) && (0.0..1.0).contains(&p[1]));
                prop_assert_eq!(stratum(p[0], nx), c as u32 % nx);
                prop_assert_eq!(stratum(p[1], ny), c as u32 / nx);
            }
        }

        #[test]
        fn bad_sizes_are_errors(len in 0usize..64, nx in 0u32..6, ny in 0u32..6) {
            let mut buf = std::vec![0.0f32; len];
            let r = stratified_2d(&mut buf, nx, ny, Jitter::Jittered, &mut default_rng(0));
            let needed = 2 * (nx * ny) as usize;
            let expected = if nx == 0 {
                Err(Error::ZeroSize { what: "nx" })
            } else if ny == 0 {
                Err(Error::ZeroSize { what: "ny" })
            } else if len < needed {
                Err(Error::BufferTooShort { needed, actual: len })
            } else if len > needed {
                Err(Error::BufferLength { multiple_of: needed, actual: len })
            } else {
                Ok(())
            };
            prop_assert_eq!(r, expected);
        }
    }

    #[test]
    fn overflowing_grid_is_too_many_not_a_panic() {
        let mut buf = [0.0f32; 4];
        let r = stratified_2d(
            &mut buf,
            u32::MAX,
            u32::MAX,
            Jitter::Jittered,
            &mut default_rng(0),
        );
        if usize::BITS <= 64 {
            assert_eq!(
                r,
                Err(Error::TooMany {
                    what: "nx * ny",
                    value: u64::from(u32::MAX) * u64::from(u32::MAX),
                    max: (usize::MAX / 2) as u64,
                })
            );
        }
        assert_eq!(
            stratified_1d(&mut [], Jitter::Centered, &mut default_rng(0)),
            Err(Error::ZeroSize { what: "samples" })
        );
    }

    #[test]
    fn jittered_2d_takes_one_key_and_uses_the_full_jitter_resolution() {
        // One u64 per call, whatever the grid: the next draw is the caller's third u32.
        let mut rng = default_rng(4);
        let mut pts = std::vec![0.0f32; 2 * 5 * 3];
        stratified_2d(&mut pts, 5, 3, Jitter::Jittered, &mut rng).unwrap();
        let mut fresh = default_rng(4);
        fresh.next_u64();
        assert_eq!(rng.next_u32(), fresh.next_u32());
        // Point p's jitter is WyRand word p of that key, at 22 − ⌈log₂ n⌉ bits per axis: for a
        // single cell the value is exactly (2·top22 + 1)/2²³, top22 the top 22 bits of the word's half.
        let key = default_rng(4).next_u64();
        let mut one = [0.0f32; 2];
        stratified_2d(&mut one, 1, 1, Jitter::Jittered, &mut default_rng(4)).unwrap();
        let w = hash::wyrand(key, 0);
        let expect = |half: u32| (((half >> 10) << 1) | 1) as f32 / 8_388_608.0;
        assert_eq!(one, [expect((w >> 32) as u32), expect(w as u32)]);
        // Jitters below a 2⁻¹⁶ cell step occur (the old 16-bit split could not make them).
        let mut fine = std::vec![0.0f32; 2 * 4 * 4];
        stratified_2d(&mut fine, 4, 4, Jitter::Jittered, &mut default_rng(8)).unwrap();
        assert!(fine.iter().any(|&v| (v * 4.0 * 65_536.0).fract() != 0.0));
    }

    #[test]
    fn centered_is_cell_centres_and_draws_nothing() {
        let mut rng = default_rng(9);
        let mut pts = [0.0f32; 2 * 2 * 2];
        stratified_2d(&mut pts, 2, 2, Jitter::Centered, &mut rng).unwrap();
        assert_eq!(pts, [0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75]);
        let mut untouched = default_rng(9);
        assert_eq!(rng.next_u32(), untouched.next_u32());
    }

    #[test]
    fn jittered_mean_is_unbiased() {
        // Within each of 4 strata the jitter is uniform: mean offset ≈ ½ (100000 draws).
        let mut rng = default_rng(4);
        let mut sum = 0.0f64;
        let mut buf = [0.0f32; 4];
        for _ in 0..25_000 {
            stratified_1d(&mut buf, Jitter::Jittered, &mut rng).unwrap();
            sum += buf
                .iter()
                .enumerate()
                .map(|(k, &x)| f64::from(x) * 4.0 - k as f64)
                .sum::<f64>();
        }
        let mean = sum / 100_000.0;
        assert!((mean - 0.5).abs() < 0.005, "mean {mean}");
    }

    /// At 2²² strata, the last count of the exact route, no jitter bits are left: every
    /// sample is its stratum's centre, one per stratum (the jitter word must be shifted out
    /// whole, not by a 32-bit shift of 32).
    #[test]
    fn two_pow_22_strata_in_1d_are_the_centres() {
        let n = 1usize << 22;
        let mut buf = std::vec![0.0f32; n];
        stratified_1d(&mut buf, Jitter::Jittered, &mut default_rng(12)).unwrap();
        let strata = Strata::new(n as u32);
        for (k, &x) in (0u32..).zip(&buf) {
            assert_eq!(x, strata.centre(k), "sample {k}");
            assert_eq!(stratum(x, n as u32), k);
        }
    }

    /// The jitter of point `p` (row-major) on an `nx × ny` grid, from an oracle written from the
    /// documented construction: WyRand word `p` of the caller's one key, x from its high half and
    /// y from its low half, the top `22 − ⌈log₂ n⌉` bits of each, placed at
    /// `(k + (bits + ½)/2^b)/n` in exact arithmetic; when either axis has more than 2²² strata,
    /// both axes take the top 24 bits at `(k + bits/2²⁴)/n`.
    fn oracle(key: u64, p: u64, i: u32, j: u32, nx: u32, ny: u32) -> [f64; 2] {
        let w = hash::wyrand(key, p);
        let checked = nx > 1 << 22 || ny > 1 << 22;
        let at = |half: u32, k: u32, n: u32| {
            if !checked {
                let b = 22 - (32 - (n - 1).leading_zeros());
                let bits = f64::from(half >> (32 - b));
                (f64::from(k) + (bits + 0.5) / f64::from(1u32 << b)) / f64::from(n)
            } else {
                (f64::from(k) + f64::from(half >> 8) / 16_777_216.0) / f64::from(n)
            }
        };
        [at((w >> 32) as u32, i, nx), at(w as u32, j, ny)]
    }

    /// `x` is `want` within two ulps (the placement rounds twice: the scale, then the product),
    /// and in stratum `k` of `n`.
    fn assert_placed(x: f32, want: f64, k: u32, n: u32, what: &str) {
        let ulp = f64::from(f32::from_bits(x.to_bits() + 1) - x);
        assert!(
            (f64::from(x) - want).abs() <= 2.0 * ulp,
            "{what}: {x} is not the jitter's value {want}"
        );
        assert_eq!(stratum(x, n), k, "{what}");
    }

    /// Every point takes its own word of the stream, in order: on grids whose rows are whole
    /// blocks of words, blocks plus a remainder, and single short rows, each point's x and y
    /// are the oracle's (a point that reused another's word, or skipped one, would be off by
    /// whole jitter steps: at least four ulps on these grids).
    #[test]
    fn every_point_takes_its_own_word_in_order() {
        for (nx, ny, seed) in [(16, 16, 3), (24, 5, 4), (40, 3, 5), (7, 9, 6), (1, 33, 7)] {
            let key = default_rng(seed).next_u64();
            let mut pts = std::vec![0.0f32; (2 * nx * ny) as usize];
            stratified_2d(&mut pts, nx, ny, Jitter::Jittered, &mut default_rng(seed)).unwrap();
            for (p, q) in (0u64..).zip(pts.chunks_exact(2)) {
                let (i, j) = (p as u32 % nx, p as u32 / nx);
                let [x, y] = oracle(key, p, i, j, nx, ny);
                let what = std::format!("{nx} x {ny}, point {p}");
                assert_placed(q[0], x, i, nx, &what);
                assert_placed(q[1], y, j, ny, &what);
            }
        }
    }

    /// More than 2²² strata on an axis take the checked route with 24 jitter bits: every point
    /// lies in its stratum and, for the first 4096 of each axis (where an ulp is far below a
    /// jitter step), is the oracle's value; the jitters are spread over the stratum (mean ½ and
    /// variance 1/12 within five standard errors over the first 2¹⁶ strata).
    #[test]
    fn more_than_2_pow_22_strata_take_the_checked_route() {
        let n = (1u32 << 22) + 1;
        const STATS: u32 = 1 << 16;
        for (nx, ny) in [(n, 1), (1, n)] {
            let key = default_rng(11).next_u64();
            let mut pts = std::vec![0.0f32; 2 * n as usize];
            stratified_2d(&mut pts, nx, ny, Jitter::Jittered, &mut default_rng(11)).unwrap();
            let (mut sum, mut sq) = (0.0f64, 0.0f64);
            for (p, q) in (0u64..).zip(pts.chunks_exact(2)) {
                let (i, j) = (p as u32 % nx, p as u32 / nx);
                let (k, v) = if nx == n { (i, q[0]) } else { (j, q[1]) };
                assert_eq!(stratum(v, n), k, "{nx} x {ny}, point {p}");
                if p < 4096 {
                    let [x, y] = oracle(key, p, i, j, nx, ny);
                    let what = std::format!("{nx} x {ny}, point {p}");
                    assert_placed(q[0], x, i, nx, &what);
                    assert_placed(q[1], y, j, ny, &what);
                }
                if k < STATS {
                    let u = f64::from(v) * f64::from(n) - f64::from(k);
                    sum += u;
                    sq += u * u;
                }
            }
            let m = f64::from(STATS);
            let (mean, var) = (sum / m, sq / m - (sum / m) * (sum / m));
            // Over the first 2¹⁶ strata (values below 1/64, where an f32 has over 250 levels per
            // stratum) the offsets are uniform: standard errors 1.1e-3 for the mean and 2.9e-4
            // for the variance; the bounds are five of them.
            assert!(
                (mean - 0.5).abs() < 0.0055,
                "{nx} x {ny}: mean offset {mean}"
            );
            assert!(
                (var - 1.0 / 12.0).abs() < 0.0015,
                "{nx} x {ny}: offset variance {var}"
            );
        }
    }
}
