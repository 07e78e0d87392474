//! Uniform shuffles of blocks of values (pbrt's `Shuffle`).

use rand_core::Rng;

use crate::{
    Error,
    rng::{uniform_below, uniform_below_pair, uniform_below_u64},
};

/// Permutes `count` blocks of `dims` consecutive values of `buf` uniformly at random, keeping
/// every block intact (Fisher–Yates with unbiased bounded draws). `buf.len()` must be exactly
/// `count · dims`. One bounded draw from `rng` per step, or one per two steps for single values
/// where the two bounds' product is at most 2²⁴ (exactly uniform all the same; see the source).
/// Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] if `dims == 0`; [`Error::TooMany`] (`what: "count"`, the limit
/// `usize::MAX / dims`) if `count · dims` overflows; [`Error::BufferLength`] if `buf.len()` is
/// not a multiple of `dims`; [`Error::BufferTooShort`] if it is shorter than `count · dims`;
/// [`Error::NotInRange`] (`what: "count"`, `min = max = buf.len() / dims`) if it is longer.
///
/// ```
/// use nyquist::{rng::default_rng, stratify::shuffle};
/// let mut pairs = [0, 1, 10, 11, 20, 21];
/// shuffle(&mut pairs, 3, 2, &mut default_rng(4)).unwrap();
/// let mut blocks: Vec<[i32; 2]> = pairs.chunks_exact(2).map(|b| [b[0], b[1]]).collect();
/// blocks.sort();
/// assert_eq!(blocks, [[0, 1], [10, 11], [20, 21]]);
/// assert!(shuffle(&mut pairs, 4, 2, &mut default_rng(4)).is_err());
/// ```
pub fn shuffle<T, R: Rng + ?Sized>(
    buf: &mut [T],
    count: usize,
    dims: usize,
    rng: &mut R,
) -> Result<(), Error> {
    if dims == 0 {
        return Err(Error::ZeroSize { what: "dims" });
    }
    let needed = count.checked_mul(dims).ok_or(Error::TooMany {
        what: "count",
        value: count as u64,
        max: (usize::MAX / dims) as u64,
    })?;
    let len = buf.len();
    if !len.is_multiple_of(dims) {
        return Err(Error::BufferLength {
            multiple_of: dims,
            actual: len,
        });
    }
    if len < needed {
        return Err(Error::BufferTooShort {
            needed,
            actual: len,
        });
    }
    if len > needed {
        return Err(Error::NotInRange {
            what: "count",
            value: count as u64,
            min: (len / dims) as u64,
            max: (len / dims) as u64,
        });
    }
    // Draws straight from `rng` (a counter stream measured no faster here, unlike in
    // stratification and LHS).
    if dims == 1 && u32::try_from(count).is_ok() {
        // The common case, kept as a tight scalar loop: 32-bit draws throughout, and no check
        // that can panic on `j` (`j ≤ i` already; the `min` tells the compiler so), which lets
        // `rng`'s state stay in registers instead of being stored at every step (`peers`,
        // docs/performance.md).
        let mut i = count.saturating_sub(1);
        while i >= 1 && (i as u64 + 1) * i as u64 > PAIR_PRODUCT_LIMIT {
            let j = (uniform_below(rng, i as u32 + 1) as usize).min(i);
            buf.swap(i, j);
            i -= 1;
        }
        // Two steps per draw below the limit: the generator's state chain, which bounds the
        // loop, runs half as often.
        while i >= 2 {
            let (j, k) = uniform_below_pair(rng, i as u32 + 1, i as u32);
            buf.swap(i, (j as usize).min(i));
            buf.swap(i - 1, (k as usize).min(i - 1));
            i -= 2;
        }
        if i == 1 {
            let j = (uniform_below(rng, 2) as usize).min(1);
            buf.swap(1, j);
        }
    } else {
        // Blocks of any size, and single values past 2³² of them: the same draws.
        for i in (1..count).rev() {
            let j = below(rng, i + 1);
            if j != i {
                // j < i: split so the two blocks are disjoint borrows.
                let (head, tail) = buf.split_at_mut(i * dims);
                head[j * dims..(j + 1) * dims].swap_with_slice(&mut tail[..dims]);
            }
        }
    }
    Ok(())
}

/// Steps `i` and `i − 1` share one draw while `(i + 1) · i` is at most this: the pair's
/// rejection test then fails with probability at most 2⁻⁸.
const PAIR_PRODUCT_LIMIT: u64 = 1 << 24;

/// A uniform index in `0..n` for `1 ≤ n`, using the 32-bit draw whenever `n` fits.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn below<R: Rng + ?Sized>(rng: &mut R, n: usize) -> usize {
    match u32::try_from(n) {
        Ok(n) => uniform_below(rng, n) as usize,
        Err(_) => uniform_below_u64(rng, n as u64) as usize,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::default_rng;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn permutes_whole_blocks(count in 0usize..300, dims in 1usize..6, seed: u64) {
            let mut buf: std::vec::Vec<u32> = (0..(count * dims) as u32).collect();
            shuffle(&mut buf, count, dims, &mut default_rng(seed)).unwrap();
            let mut firsts = std::vec::Vec::new();
            for b in buf.chunks_exact(dims) {
                prop_assert!(b.windows(2).all(|w| w[1] == w[0] + 1), "block torn: {:?}", b);
                prop_assert_eq!(b[0] % dims as u32, 0);
                firsts.push(b[0]);
            }
            firsts.sort_unstable();
            let expected: std::vec::Vec<u32> = (0..count as u32).map(|k| k * dims as u32).collect();
            prop_assert_eq!(firsts, expected);
        }

        #[test]
        fn bad_sizes_are_errors_never_panics(len in 0usize..40, count in 0usize..40, dims in 0usize..6) {
            let mut buf = std::vec![0u8; len];
            let r = shuffle(&mut buf, count, dims, &mut default_rng(0));
            let expected = if dims == 0 {
                Err(Error::ZeroSize { what: "dims" })
            } else if len % dims != 0 {
                Err(Error::BufferLength { multiple_of: dims, actual: len })
            } else if len < count * dims {
                Err(Error::BufferTooShort { needed: count * dims, actual: len })
            } else if len > count * dims {
                Err(Error::NotInRange {
                    what: "count",
                    value: count as u64,
                    min: (len / dims) as u64,
                    max: (len / dims) as u64,
                })
            } else {
                Ok(())
            };
            prop_assert_eq!(r, expected);
        }
    }

    #[test]
    fn overflow_is_too_many() {
        let mut buf = [0u8; 4];
        assert_eq!(
            shuffle(&mut buf, usize::MAX, 2, &mut default_rng(0)),
            Err(Error::TooMany {
                what: "count",
                value: usize::MAX as u64,
                max: (usize::MAX / 2) as u64,
            })
        );
    }

    /// Four single values: the first two steps share a draw, the last has its own.
    #[test]
    fn four_elements_give_all_24_orders_uniformly() {
        // 48000 shuffles, chi-square with 23 dof: 49.73 is the 0.999 quantile.
        let mut rng = default_rng(41);
        let mut counts = std::collections::HashMap::new();
        for _ in 0..48_000 {
            let mut v = [0u8, 1, 2, 3];
            shuffle(&mut v, 4, 1, &mut rng).unwrap();
            *counts.entry(v).or_insert(0u32) += 1;
        }
        assert_eq!(counts.len(), 24);
        let counts: std::vec::Vec<u32> = counts.into_values().collect();
        let chi = crate::tests::chi_square_uniform(&counts);
        assert!(chi < 49.73, "chi2 {chi}");
    }

    /// A generator of `u32::MAX` words that counts them. Such a word is never rejected: a single
    /// draw's low word is `2³² − n ≥ n`, a pair's `2³² − a·b ≥ a·b` (products up to 2³¹), so
    /// the count is exactly the number of draws the steps make.
    struct CountingMax(usize);

    impl rand_core::TryRng for CountingMax {
        type Error = core::convert::Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Self::Error> {
            self.0 += 1;
            Ok(u32::MAX)
        }
        fn try_next_u64(&mut self) -> Result<u64, Self::Error> {
            unreachable!("single values draw 32-bit words")
        }
        fn try_fill_bytes(&mut self, _: &mut [u8]) -> Result<(), Self::Error> {
            unreachable!("single values draw 32-bit words")
        }
    }

    /// One word per step while `(i + 1)·i > 2²⁴`, then one per two steps: 4100 values take the
    /// steps i = 4099 … 4096 alone, 4095 … 2 in 2047 pairs and i = 1 alone.
    #[test]
    fn single_values_draw_once_per_two_steps_below_the_limit() {
        let mut v: std::vec::Vec<u32> = (0..4100).collect();
        let mut rng = CountingMax(0);
        shuffle(&mut v, 4100, 1, &mut rng).unwrap();
        assert_eq!(rng.0, 4 + 2047 + 1);
        let mut rng = CountingMax(0);
        shuffle(&mut v[..1000], 1000, 1, &mut rng).unwrap();
        assert_eq!(rng.0, 499 + 1); // i = 999 … 2 in pairs, then i = 1
        v.sort_unstable();
        assert!(v.iter().enumerate().all(|(k, &x)| k as u32 == x));
    }

    /// A generator that gives one scripted word, then `u32::MAX` for ever. A bounded draw from
    /// `u32::MAX` is never rejected and is its bound's largest value, so every step after the
    /// scripted one leaves its value in place (j = i; a pair's second value is i − 1).
    struct OneWordThenMax(Option<u32>);

    impl rand_core::TryRng for OneWordThenMax {
        type Error = core::convert::Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Self::Error> {
            Ok(self.0.take().unwrap_or(u32::MAX))
        }
        fn try_next_u64(&mut self) -> Result<u64, Self::Error> {
            unreachable!("single values draw 32-bit words")
        }
        fn try_fill_bytes(&mut self, _: &mut [u8]) -> Result<(), Self::Error> {
            unreachable!("single values draw 32-bit words")
        }
    }

    /// The first step of a 4100-value shuffle (i = 4099, a single draw) reaches every
    /// j ∈ 0..=4099, each from the words Lemire's method maps to it on the bound i + 1 = 4100:
    /// word r gives j = ⌊r · 4100 / 2³²⌋. The middle word of each j's range is never rejected
    /// (its low word is near 2³¹), and the later steps leave every value in place, so the result
    /// is the identity with 4099 and j exchanged (nothing exchanged for j = 4099).
    #[test]
    fn the_first_single_draw_reaches_every_index_from_its_own_words() {
        const N: u32 = 4100;
        let mut v: std::vec::Vec<u32> = (0..N).collect();
        for j in 0..N {
            let middle = ((2 * u64::from(j) + 1) << 31) / u64::from(N);
            let mut rng = OneWordThenMax(Some(middle as u32));
            v.iter_mut().zip(0..).for_each(|(x, k)| *x = k);
            shuffle(&mut v, N as usize, 1, &mut rng).unwrap();
            let expected = |k: u32| match k {
                _ if k == N - 1 => j,
                _ if k == j => N - 1,
                _ => k,
            };
            let wrong = (0..N).find(|&k| v[k as usize] != expected(k));
            assert_eq!(wrong, None, "j = {j}: first wrong position");
        }
    }

    /// The steps above the pair limit (i ≥ 4096 when `(i + 1)·i > 2²⁴`) draw j uniformly from
    /// `0..=i`. Fisher–Yates is a bijection, so the draws are read back from the result: step i
    /// leaves at position i the value then at position j, and undoing the steps from the top
    /// finds that position. Sixteen values of j spread over `0..=i`, from 0 to i itself, each
    /// have probability 1/(i + 1) at every step, so the draws that land on one of them are
    /// uniform over the sixteen: χ² with 15 degrees of freedom, 37.70 is the 0.999 quantile (a
    /// false-alarm rate of 10⁻³ for a seed picked at random). 128 shuffles of 8192 values,
    /// 4096 single draws each, put about 128 · ln 2 ≈ 89 draws in each cell.
    #[test]
    fn single_draws_above_the_pair_limit_are_uniform() {
        const N: usize = 8192;
        let single = |i: usize| (i as u64 + 1) * i as u64 > PAIR_PRODUCT_LIMIT;
        assert!(single(N / 2) && !single(N / 2 - 1));
        let cells = |i: usize| (0..16).map(move |c| c * i / 15); // 0, …, i
        let mut rng = default_rng(5);
        let mut counts = [0u32; 16];
        let mut v = std::vec![0u32; N];
        // The values' order and each value's position while the steps are undone.
        let (mut order, mut at) = (std::vec![0u32; N], std::vec![0u32; N]);
        for _ in 0..128 {
            v.iter_mut().zip(0..).for_each(|(x, k)| *x = k);
            shuffle(&mut v, N, 1, &mut rng).unwrap();
            order.iter_mut().zip(0..).for_each(|(x, k)| *x = k);
            at.iter_mut().zip(0..).for_each(|(x, k)| *x = k);
            for i in (N / 2..N).rev() {
                let j = at[v[i] as usize] as usize; // step i's draw
                let (a, b) = (order[i], order[j]);
                order.swap(i, j);
                (at[a as usize], at[b as usize]) = (j as u32, i as u32);
                if let Some(c) = cells(i).position(|x| x == j) {
                    counts[c] += 1;
                }
            }
        }
        let chi = crate::tests::chi_square_uniform(&counts);
        assert!(chi < 37.70, "chi2 {chi}, counts {counts:?}");
    }

    /// Past the pair limit the steps draw one at a time; the result is still a permutation.
    #[test]
    fn long_shuffles_cross_the_pair_limit_and_permute() {
        let n = 4100; // (i + 1) · i > 2^24 for the first four steps, i = 4099 down to 4096
        const { assert!(4097 * 4096 > PAIR_PRODUCT_LIMIT && 4096 * 4095 <= PAIR_PRODUCT_LIMIT) };
        let mut v: std::vec::Vec<u32> = (0..n).collect();
        shuffle(&mut v, n as usize, 1, &mut default_rng(2)).unwrap();
        let moved = v
            .iter()
            .enumerate()
            .filter(|&(k, &x)| k as u32 != x)
            .count();
        assert!(moved > 4000, "{moved} of {n} moved");
        v.sort_unstable();
        assert!(v.iter().enumerate().all(|(k, &x)| k as u32 == x));
    }

    #[test]
    fn three_elements_give_all_six_orders_uniformly() {
        // Chi-square over the 6 orders, 5 degrees of freedom: 20.52 is the 0.999 quantile.
        for (seed, dims) in [(99u64, 1usize), (7, 2)] {
            let mut rng = default_rng(seed);
            let mut counts = [0u32; 6];
            let orders = [
                [0, 1, 2],
                [0, 2, 1],
                [1, 0, 2],
                [1, 2, 0],
                [2, 0, 1],
                [2, 1, 0],
            ];
            for _ in 0..60_000 {
                let mut v = [0u8; 6];
                for (k, x) in v[..3 * dims].iter_mut().enumerate() {
                    *x = (k / dims) as u8;
                }
                shuffle(&mut v[..3 * dims], 3, dims, &mut rng).unwrap();
                let order = [v[0], v[dims], v[2 * dims]];
                counts[orders.iter().position(|o| *o == order).unwrap()] += 1;
            }
            let chi = crate::tests::chi_square_uniform(&counts);
            assert!(chi < 20.52, "dims {dims}: chi2 {chi}, counts {counts:?}");
        }
    }
}
