//! Random-number helpers over any [`rand_core::Rng`]: unit floats and unbiased bounded
//! integers. [`rand_pcg::Pcg32`] is the default generator.

use core::convert::Infallible;

use rand_core::{Rng, TryRng};

/// The default generator: PCG32 (O'Neill 2014), small, fast and reproducible everywhere.
pub type DefaultRng = rand_pcg::Pcg32;

/// A [`DefaultRng`] seeded from any `u64` (every value is a valid seed).
///
/// ```
/// use nyquist::rng::{default_rng, uniform_f32};
/// let (mut a, mut b) = (default_rng(7), default_rng(7));
/// assert_eq!(uniform_f32(&mut a), uniform_f32(&mut b));
/// ```
pub fn default_rng(seed: u64) -> DefaultRng {
    rand_pcg::Pcg32::new(
        crate::hash::mix64(seed ^ 0x853c_49e6_748f_ea9b),
        0xda3e_39cb_94b9_5bdb,
    )
}

/// A counter-based generator: word `i` is [`crate::hash::wyrand`]`(key, i)`. Each word costs
/// one wide multiply and depends on no earlier word, so loops that draw from it are not held to
/// one generator step at a time the way a state-chained generator (PCG, xorshift) holds them.
///
/// The stratification routines key one from the caller's generator (one `u64` draw) and take
/// their per-element words from it, so they still take any [`Rng`] and still advance it.
/// `next_u32` returns the high half of a word.
///
/// ```
/// use nyquist::rng::CounterRng;
/// use rand_core::Rng;
/// let mut a = CounterRng::new(9);
/// let w0 = a.next_u64();
/// assert_eq!(w0, nyquist::hash::wyrand(9, 0));
/// assert_eq!(a.next_u32(), (nyquist::hash::wyrand(9, 1) >> 32) as u32);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CounterRng {
    /// The Weyl state `key + counter · increment`.
    state: u64,
}

impl CounterRng {
    /// The stream keyed by `key` (every key is valid), at word 0.
    ///
    /// ```
    /// use rand_core::Rng;
    /// let (mut a, mut b) = (nyquist::rng::CounterRng::new(1), nyquist::rng::CounterRng::new(2));
    /// assert_ne!(a.next_u64(), b.next_u64());
    /// ```
    pub const fn new(key: u64) -> CounterRng {
        CounterRng { state: key }
    }

    /// A stream keyed by one `u64` drawn from `rng`.
    ///
    /// ```
    /// use nyquist::rng::{CounterRng, default_rng};
    /// use rand_core::Rng;
    /// // The key is the generator's next u64, and exactly one is drawn.
    /// let mut rng = default_rng(3);
    /// let mut fresh = default_rng(3);
    /// assert_eq!(CounterRng::keyed_by(&mut rng), CounterRng::new(fresh.next_u64()));
    /// assert_eq!(rng.next_u64(), fresh.next_u64());
    /// ```
    pub fn keyed_by<R: Rng + ?Sized>(rng: &mut R) -> CounterRng {
        CounterRng::new(rng.next_u64())
    }
}

impl TryRng for CounterRng {
    type Error = Infallible;

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok((self.try_next_u64()? >> 32) as u32)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        self.state = self.state.wrapping_add(crate::hash::WYRAND_INC);
        Ok(crate::hash::wyrand_fold(self.state))
    }

    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        rand_core::utils::fill_bytes_via_next_word(dst, || self.try_next_u64())
    }
}

/// A uniform `f32` in `[0, 1)` with 24 random bits.
///
/// ```
/// let x = nyquist::rng::uniform_f32(&mut nyquist::rng::default_rng(1));
/// assert!((0.0..1.0).contains(&x));
/// ```
#[inline]
pub fn uniform_f32<R: Rng + ?Sized>(rng: &mut R) -> f32 {
    crate::hash::unit_f32(rng.next_u32())
}

/// A uniform `f64` in `[0, 1)` with 53 random bits.
///
/// ```
/// let x = nyquist::rng::uniform_f64(&mut nyquist::rng::default_rng(1));
/// assert!((0.0..1.0).contains(&x));
/// ```
#[inline]
pub fn uniform_f64<R: Rng + ?Sized>(rng: &mut R) -> f64 {
    crate::hash::unit_f64(rng.next_u64())
}

/// A uniform integer in `0..n`, without modulo bias (Lemire 2019, "Fast random integer
/// generation in an interval"). Total: `n == 0` returns 0.
///
/// ```
/// let mut rng = nyquist::rng::default_rng(3);
/// assert!(nyquist::rng::uniform_below(&mut rng, 6) < 6);
/// assert_eq!(nyquist::rng::uniform_below(&mut rng, 0), 0);
/// ```
#[inline]
pub fn uniform_below<R: Rng + ?Sized>(rng: &mut R, n: u32) -> u32 {
    if n == 0 {
        return 0;
    }
    let first = rng.next_u32();
    uniform_below_from(first, n, rng)
}

/// [`uniform_below`] for `n ≥ 1` with its first 32-bit word already drawn (`first`); the rare
/// rejected words are replaced by fresh draws from `rng`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn uniform_below_from<R: Rng + ?Sized>(first: u32, n: u32, rng: &mut R) -> u32 {
    let mut m = u64::from(first) * u64::from(n);
    if (m as u32) < n {
        let threshold = n.wrapping_neg() % n;
        while (m as u32) < threshold {
            m = u64::from(rng.next_u32()) * u64::from(n);
        }
    }
    (m >> 32) as u32
}

/// Two independent uniform integers in `0..a` and `0..b` from one 32-bit draw (Brackett-Rozinsky
/// & Lemire 2024, "Batched ranged random integer generation"), for `a, b ≥ 1` with
/// `a · b ≤ 2³²`: the draw times `a` gives the first in its high word, the low word times `b`
/// the second. Then `r·a·b = (j·b + k)·2³² + low`, so `(j, k)` is the mixed-radix form of
/// Lemire's bounded draw on `a · b`, and the same rejection (`low < 2³² mod a·b`, drawn again)
/// makes the pair exactly uniform. Rejection is rare when `a · b` is small against 2³²: the
/// test that can lead to it fails with probability `a·b / 2³²`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn uniform_below_pair<R: Rng + ?Sized>(rng: &mut R, a: u32, b: u32) -> (u32, u32) {
    let product = u64::from(a) * u64::from(b);
    let (mut j, mut k, mut low) = split_pair(rng.next_u32(), a, b);
    if u64::from(low) < product {
        let threshold = ((1u64 << 32) - product) % product;
        while u64::from(low) < threshold {
            (j, k, low) = split_pair(rng.next_u32(), a, b);
        }
    }
    (j, k)
}

/// `r` split by [`uniform_below_pair`]'s bounds: the two values and the final low word.
#[cfg_attr(not(feature = "small-code"), inline(always))]
const fn split_pair(r: u32, a: u32, b: u32) -> (u32, u32, u32) {
    let m = r as u64 * a as u64;
    let n = (m as u32) as u64 * b as u64;
    ((m >> 32) as u32, (n >> 32) as u32, n as u32)
}

/// A uniform integer in `0..n` for 64-bit ranges (same method with 128-bit products).
/// Total: `n == 0` returns 0.
///
/// ```
/// let mut rng = nyquist::rng::default_rng(3);
/// assert!(nyquist::rng::uniform_below_u64(&mut rng, 1 << 40) < 1 << 40);
/// ```
#[inline]
pub fn uniform_below_u64<R: Rng + ?Sized>(rng: &mut R, n: u64) -> u64 {
    if n == 0 {
        return 0;
    }
    if let Ok(small) = u32::try_from(n) {
        return u64::from(uniform_below(rng, small));
    }
    let mut m = u128::from(rng.next_u64()) * u128::from(n);
    if (m as u64) < n {
        let threshold = n.wrapping_neg() % n;
        while (m as u64) < threshold {
            m = u128::from(rng.next_u64()) * u128::from(n);
        }
    }
    (m >> 64) as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_below_is_unbiased_chi_square() {
        // 6 bins, 60000 draws: chi-square with 5 dof; 20.5 is the 0.999 quantile.
        let mut rng = default_rng(11);
        let mut bins = [0u32; 6];
        for _ in 0..60_000 {
            bins[uniform_below(&mut rng, 6) as usize] += 1;
        }
        let chi = crate::tests::chi_square_uniform(&bins);
        assert!(chi < 20.5, "chi2 {chi} bins {bins:?}");
    }

    /// A generator that replays `words`, for the rejection path.
    struct Scripted<'a>(&'a [u32]);

    impl TryRng for Scripted<'_> {
        type Error = Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Infallible> {
            let (first, rest) = self.0.split_first().expect("script too short");
            self.0 = rest;
            Ok(*first)
        }
        fn try_next_u64(&mut self) -> Result<u64, Infallible> {
            unreachable!("the pair draws 32-bit words")
        }
        fn try_fill_bytes(&mut self, _: &mut [u8]) -> Result<(), Infallible> {
            unreachable!("the pair draws 32-bit words")
        }
    }

    proptest::proptest! {
        /// The pair is the mixed-radix form of Lemire's draw on `a · b`: `r·a·b = (j·b + k)·2³²
        /// + low`, with `j < a` and `k < b`. With the same rejection as the single draw, that
        /// makes the pair exactly uniform.
        #[test]
        fn the_pair_split_is_the_single_draw_on_the_product(
            r: u32,
            a in 1u32..=u32::MAX,
            b_raw: u32,
        ) {
            let b = (b_raw % ((1u64 << 32) / u64::from(a)) as u32).max(1);
            let (j, k, low) = split_pair(r, a, b);
            let whole = u128::from(r) * u128::from(a) * u128::from(b);
            proptest::prop_assert!(j < a && k < b);
            proptest::prop_assert_eq!(u128::from(j) * u128::from(b) + u128::from(k), whole >> 32);
            proptest::prop_assert_eq!(u128::from(low), whole & 0xffff_ffff);
        }
    }

    #[test]
    fn the_pair_redraws_exactly_the_rejected_words() {
        // a·b = 15: 2³² mod 15 = 1, so only a low word of 0 (the draw 0) is rejected.
        let good = split_pair(0x9e37_79b9, 3, 5);
        assert_eq!(
            uniform_below_pair(&mut Scripted(&[0, 0, 0x9e37_79b9]), 3, 5),
            (good.0, good.1)
        );
        // A low word of 1 is the threshold itself: kept. (15 · 0xeeee_eeef = 1 mod 2³², so that
        // word's low word, r·15 mod 2³², is 1.)
        assert_eq!(split_pair(0xeeee_eeef, 3, 5).2, 1);
        let kept = split_pair(0xeeee_eeef, 3, 5);
        assert_eq!(
            uniform_below_pair(&mut Scripted(&[0xeeee_eeef, 0x9e37_79b9]), 3, 5),
            (kept.0, kept.1)
        );
        assert_ne!((kept.0, kept.1), (good.0, good.1));
        // a·b = 2³² − 2¹⁶: the threshold is 2¹⁶; a word whose low word falls under it is redrawn.
        let (a, b) = (65_536, 65_535);
        let threshold = (1u64 << 32) % (u64::from(a) * u64::from(b));
        assert_eq!(threshold, 65_536);
        let low_of = |r: u32| u64::from(split_pair(r, a, b).2);
        let rejected = (0..1 << 16).find(|&r| low_of(r) < threshold).unwrap();
        let accepted = (rejected + 1..1 << 17)
            .find(|&r| low_of(r) >= threshold)
            .unwrap();
        let want = split_pair(accepted, a, b);
        assert_eq!(
            uniform_below_pair(&mut Scripted(&[rejected, accepted]), a, b),
            (want.0, want.1)
        );
    }

    #[test]
    fn uniform_below_pair_is_uniform_chi_square() {
        // 3 × 5 cells, 150000 pairs: chi-square with 14 dof; 36.12 is the 0.999 quantile.
        let mut rng = default_rng(12);
        let mut cells = [0u32; 15];
        for _ in 0..150_000 {
            let (j, k) = uniform_below_pair(&mut rng, 3, 5);
            cells[(j * 5 + k) as usize] += 1;
        }
        let chi = crate::tests::chi_square_uniform(&cells);
        assert!(chi < 36.12, "chi2 {chi} cells {cells:?}");
    }

    /// Distinct seeds give distinct streams (every bit of a seed reaches the generator's
    /// state), and the stream each seed picks is pinned: seeded output is what a render
    /// reproduces. The values are golden, recorded from `default_rng`'s seeding.
    #[test]
    fn default_rng_streams_differ_by_seed_and_are_pinned() {
        let mut firsts: std::vec::Vec<u64> = (0..4096).map(|s| default_rng(s).next_u64()).collect();
        firsts.extend([1 << 63, u64::MAX].map(|s| default_rng(s).next_u64()));
        firsts.sort_unstable();
        firsts.dedup();
        assert_eq!(firsts.len(), 4098);
        let golden = [0, 1, 7, u64::MAX].map(|s| default_rng(s).next_u32());
        assert_eq!(golden, [0x1b05_d99d, 0x2ca7_0f69, 0xb65f_118c, 0xbf25_3d98]);
    }

    /// Word i of a `CounterRng` is `wyrand(key, i)`; `next_u32` is its high half, and
    /// `fill_bytes` lays the words down little-endian, the last one cut short.
    #[test]
    fn counter_rng_words_are_wyrand_by_index() {
        for key in [0u64, 9, u64::MAX] {
            let mut rng = CounterRng::new(key);
            for i in 0..8 {
                assert_eq!(rng.next_u64(), crate::hash::wyrand(key, i));
            }
            let mut rng = CounterRng::new(key);
            for i in 0..8 {
                assert_eq!(rng.next_u32(), (crate::hash::wyrand(key, i) >> 32) as u32);
            }
            let mut bytes = [0u8; 20];
            CounterRng::new(key).fill_bytes(&mut bytes);
            let words = [0, 1, 2].map(|i| crate::hash::wyrand(key, i).to_le_bytes());
            assert_eq!(bytes, *words.as_flattened().first_chunk::<20>().unwrap());
        }
    }

    /// The unit floats take one word each and keep its top 24 or 53 bits.
    #[test]
    fn unit_floats_are_the_top_bits_of_one_word() {
        assert_eq!(
            uniform_f32(&mut Scripted(&[u32::MAX])),
            1.0 - f32::EPSILON / 2.0
        );
        assert_eq!(uniform_f32(&mut Scripted(&[0x8000_00ff])), 0.5);
        assert_eq!(uniform_f32(&mut Scripted(&[0xff])), 0.0);
        assert_eq!(
            uniform_f64(&mut Scripted64(&[u64::MAX])),
            1.0 - f64::EPSILON / 2.0
        );
        assert_eq!(uniform_f64(&mut Scripted64(&[0x4000_0000_0000_07ff])), 0.25);
        let (mut a, mut b) = (default_rng(8), default_rng(8));
        for _ in 0..100 {
            assert_eq!(uniform_f32(&mut a), crate::hash::unit_f32(b.next_u32()));
            assert_eq!(uniform_f64(&mut a), crate::hash::unit_f64(b.next_u64()));
        }
    }

    /// A generator that replays 64-bit `words`.
    struct Scripted64<'a>(&'a [u64]);

    impl TryRng for Scripted64<'_> {
        type Error = Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Infallible> {
            unreachable!("64-bit draws only")
        }
        fn try_next_u64(&mut self) -> Result<u64, Infallible> {
            let (first, rest) = self.0.split_first().expect("script too short");
            self.0 = rest;
            Ok(*first)
        }
        fn try_fill_bytes(&mut self, _: &mut [u8]) -> Result<(), Infallible> {
            unreachable!("64-bit draws only")
        }
    }

    /// Lemire's rejection, word by word. For n = 3, 2³² mod 3 = 1: only a word whose low word
    /// `r·3 mod 2³²` is 0 (the word 0) is redrawn, and the redraw's high word is the value. The
    /// word `0xaaaa_aaab` (3⁻¹ mod 2³²) has the low word 1, the threshold itself: kept, value 2.
    /// The 64-bit draw on n = 3·2³² has the same words shifted: threshold 2³², the word 0
    /// redrawn, a low word of exactly 2³² kept; on n = 2⁶³ + 1 the threshold is most of the
    /// range.
    #[test]
    fn uniform_below_redraws_exactly_the_rejected_words() {
        let value = |r: u32| ((u64::from(r) * 3) >> 32) as u32;
        let w = 0x9e37_79b9; // value 1
        assert_eq!(value(w), 1);
        assert_eq!(uniform_below(&mut Scripted(&[0, w]), 3), 1);
        assert_eq!(uniform_below(&mut Scripted(&[0, 0, w]), 3), 1);
        assert_eq!(0xaaaa_aaabu32.wrapping_mul(3), 1);
        assert_eq!(uniform_below(&mut Scripted(&[0xaaaa_aaab, w]), 3), 2);
        // The 64-bit path: n above u32::MAX.
        let n = 3u64 << 32;
        assert_eq!(n.wrapping_neg() % n, 1 << 32);
        let w64 = 0x9e37_79b9_7f4a_7c15; // value (w64 · n) >> 64
        let want = ((u128::from(w64) * u128::from(n)) >> 64) as u64;
        assert!(want > 0 && want != n - 1);
        assert_eq!(uniform_below_u64(&mut Scripted64(&[0, w64]), n), want);
        assert_eq!(uniform_below_u64(&mut Scripted64(&[0, 0, w64]), n), want);
        // Low word (0xaaaa_aaab · 3 mod 2³²) · 2³² = 2³²: the threshold, kept.
        let kept = 0xaaaa_aaab;
        let kept_value = ((u128::from(kept) * u128::from(n)) >> 64) as u64;
        assert_eq!(
            uniform_below_u64(&mut Scripted64(&[kept, w64]), n),
            kept_value
        );
        assert_ne!(kept_value, want);
        // n = 2⁶³ + 1: the threshold 2⁶⁴ mod n = 2⁶³ − 1 is most of the range. The word 2 (low
        // word 2) is redrawn; u64::MAX has the low word 2⁶³ − 1, the threshold itself: kept, and
        // its value is n − 1.
        let n: u64 = (1 << 63) + 1;
        assert_eq!(n.wrapping_neg() % n, (1 << 63) - 1);
        assert_eq!(
            uniform_below_u64(&mut Scripted64(&[2, u64::MAX]), n),
            1 << 63
        );
    }

    #[test]
    fn uniform_below_u64_is_unbiased_chi_square() {
        // n = 6·2⁴⁰, binned by the top digit j >> 40: 6 bins, 60000 draws, chi-square with 5
        // dof; 20.52 is the 0.999 quantile. Below 2³² it is the 32-bit draw, word for word.
        let mut rng = default_rng(13);
        let mut bins = [0u32; 6];
        for _ in 0..60_000 {
            bins[(uniform_below_u64(&mut rng, 6 << 40) >> 40) as usize] += 1;
        }
        let chi = crate::tests::chi_square_uniform(&bins);
        assert!(chi < 20.52, "chi2 {chi} bins {bins:?}");
        let (mut a, mut b) = (default_rng(14), default_rng(14));
        for n in [1u32, 6, u32::MAX] {
            assert_eq!(
                uniform_below_u64(&mut a, u64::from(n)),
                u64::from(uniform_below(&mut b, n))
            );
        }
        assert_eq!(uniform_below_u64(&mut a, 0), 0);
    }

    #[test]
    fn uniform_below_u64_stays_in_range() {
        let mut rng = default_rng(5);
        for n in [1u64, 2, 3, u64::from(u32::MAX) + 1, u64::MAX / 3, u64::MAX] {
            for _ in 0..100 {
                assert!(uniform_below_u64(&mut rng, n) < n);
            }
        }
    }
}
