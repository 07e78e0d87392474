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
        let chi: f64 = bins
            .iter()
            .map(|&c| (f64::from(c) - 10_000.0).powi(2) / 10_000.0)
            .sum();
        assert!(chi < 20.5, "chi2 {chi} bins {bins:?}");
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
