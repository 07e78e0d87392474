//! Integer hashing and hash-derived permutations: the stateless randomness behind scrambles,
//! per-pixel decorrelation and Latin-hypercube strata. Nothing here stores a table.
//!
//! Sources: the 64-bit finaliser is SplitMix64's (Steele, Lea & Flood 2014, constants from
//! Stafford's "Mix13"); the 32-bit one is Wellons' `lowbias32` (constants from his hash-prospector
//! results). The permutation follows the idea of Kensler's 2013 "Correlated Multi-Jittered
//! Sampling": a keyed bijection on the next power of two, cycle-walked into `[0, n)`.

/// A 64-bit avalanche finaliser (SplitMix64 / Mix13): every input bit affects every output bit.
///
/// ```
/// use nyquist::hash::mix64;
/// assert_ne!(mix64(1), mix64(2));
/// assert_eq!(mix64(0), 0); // a finaliser, not a keyed hash: zero is a fixed point
/// ```
#[inline]
pub const fn mix64(mut x: u64) -> u64 {
    x ^= x >> 30;
    x = x.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x ^= x >> 27;
    x = x.wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

/// A 32-bit avalanche finaliser (`lowbias32`).
///
/// ```
/// use nyquist::hash::mix32;
/// assert_ne!(mix32(1), mix32(2));
/// ```
#[inline]
pub const fn mix32(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^ (x >> 16)
}

/// The golden-ratio increment used to separate hashed fields (`⌊2⁶⁴/φ⌋`).
const GOLDEN: u64 = 0x9e37_79b9_7f4a_7c15;

/// Hashes two values into one; order matters (`hash2(a, b) != hash2(b, a)` in general).
///
/// ```
/// use nyquist::hash::hash2;
/// assert_ne!(hash2(1, 2), hash2(2, 1));
/// assert_ne!(hash2(0, 0), 0);
/// ```
#[inline]
pub const fn hash2(a: u64, b: u64) -> u64 {
    mix64(mix64(a.wrapping_add(GOLDEN)) ^ b.wrapping_add(GOLDEN.wrapping_mul(2)))
}

/// Hashes three values into one.
///
/// ```
/// use nyquist::hash::hash3;
/// assert_ne!(hash3(1, 2, 3), hash3(3, 2, 1));
/// ```
#[inline]
pub const fn hash3(a: u64, b: u64, c: u64) -> u64 {
    mix64(hash2(a, b) ^ c.wrapping_add(GOLDEN.wrapping_mul(3)))
}

/// Hashes any number of values (a fold of [`hash2`]); the empty slice hashes to a constant.
///
/// ```
/// use nyquist::hash::{hash2, hash_slice};
/// assert_eq!(hash_slice(&[4, 5]), hash2(hash_slice(&[4]), 5));
/// assert_ne!(hash_slice(&[1, 2, 3]), hash_slice(&[1, 2, 4]));
/// ```
#[inline]
pub const fn hash_slice(values: &[u64]) -> u64 {
    let mut h = GOLDEN;
    let mut i = 0;
    while i < values.len() {
        h = hash2(h, values[i]);
        i += 1;
    }
    h
}

/// A hash's top 24 bits as an `f32` in `[0, 1)`.
///
/// ```
/// use nyquist::hash::unit_f32;
/// assert_eq!(unit_f32(0), 0.0);
/// assert!(unit_f32(u32::MAX) < 1.0);
/// ```
#[inline]
pub const fn unit_f32(h: u32) -> f32 {
    (h >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// A hash's top 53 bits as an `f64` in `[0, 1)`.
///
/// ```
/// assert!(nyquist::hash::unit_f64(u64::MAX) < 1.0);
/// ```
#[inline]
pub const fn unit_f64(h: u64) -> f64 {
    (h >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
}

/// Element `i` of a pseudo-random permutation of `0..n` chosen by `seed`.
///
/// For a fixed `(n, seed)`, `i ↦ permute(i, n, seed)` is a bijection on `0..n`, computed without
/// any table, so every thread can evaluate any element. Total: `n == 0` or `n == 1` gives 0, and
/// `i >= n` is first reduced modulo `n`. Expected cost: fewer than two rounds of a keyed
/// bijection on `0..2^⌈log₂ n⌉`.
///
/// ```
/// use nyquist::hash::permute;
/// let mut seen = [false; 10];
/// for i in 0..10 {
///     seen[permute(i, 10, 42) as usize] = true;
/// }
/// assert!(seen.iter().all(|&s| s));
/// ```
#[inline]
pub fn permute(i: u32, n: u32, seed: u32) -> u32 {
    if n <= 1 {
        return 0;
    }
    let mask = u32::MAX >> (n - 1).leading_zeros();
    let bits = 32 - mask.leading_zeros();
    let half = bits.div_ceil(2);
    let key = mix32(seed ^ 0x5bd1_e995);
    let key2 = mix32(key.wrapping_add(0x68e3_1da4));
    let mut x = if i < n { i } else { i % n };
    loop {
        // Each step is a bijection on `bits`-bit words: xor with a constant, multiply by an odd
        // constant modulo 2^bits, xor-shift right.
        x ^= key & mask;
        x = x.wrapping_mul(0xe170_893d) & mask;
        x ^= x >> half;
        x = x.wrapping_add(key2) & mask;
        x = x.wrapping_mul(key | 1) & mask;
        x ^= x >> half;
        x ^= (key2 >> 7) & mask;
        x = x.wrapping_mul(0x0929_eb3f) & mask;
        x ^= x >> half.max(1);
        x = x.wrapping_mul(0x6935_fa69 ^ (key2 & 0xffff_fffe)) & mask;
        x ^= x >> (bits / 3).max(1);
        if x < n {
            return x;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permute_is_a_bijection_for_many_sizes_and_seeds() {
        let mut seen = std::vec![false; 1025];
        for n in 1..=1025u32 {
            for seed in [0u32, 1, 7, 0xdead_beef] {
                seen[..n as usize].fill(false);
                for i in 0..n {
                    let p = permute(i, n, seed) as usize;
                    assert!(p < n as usize);
                    assert!(!seen[p], "n={n} seed={seed}: {p} twice");
                    seen[p] = true;
                }
            }
        }
    }

    #[test]
    fn permute_depends_on_seed_and_wraps_large_indices() {
        let a: std::vec::Vec<u32> = (0..64).map(|i| permute(i, 64, 1)).collect();
        let b: std::vec::Vec<u32> = (0..64).map(|i| permute(i, 64, 2)).collect();
        assert_ne!(a, b);
        assert_eq!(permute(64 + 5, 64, 1), permute(5, 64, 1));
        assert_eq!(permute(3, 0, 9), 0);
        assert!(permute(u32::MAX, u32::MAX, 9) < u32::MAX);
    }

    #[test]
    fn permute_is_not_the_identity_on_average() {
        // A weak but falsifiable mixing check: over many seeds, fixed points are rare (≈ 1 per
        // permutation for a random permutation).
        let mut fixed = 0;
        for seed in 0..1000u32 {
            fixed += (0..256u32).filter(|&i| permute(i, 256, seed) == i).count();
        }
        assert!(
            fixed < 2000,
            "{fixed} fixed points in 1000 permutations of 256"
        );
    }
}
