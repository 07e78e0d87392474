//! Base-2 scrambles: the randomizations pbrt-v4 names for its Sobol and Halton samplers, and
//! Burley's nested uniform index shuffle.
//!
//! A 32-bit value `x` here is a binary fraction `x / 2³²`; bit 31 is its first digit.
//!
//! - **Permute digits**: every digit goes through a random permutation of `{0, 1}`, the same for
//!   every point; in base 2 that is an XOR with a random word (a digital shift).
//! - **Owen** (nested uniform scramble, Owen 1995): digit `k` is flipped or not by an independent
//!   random choice for every value of the digits before it. [`owen_scramble`] draws each choice
//!   from a hash of the prefix: exact, 32 hashes per value.
//! - **Fast Owen**: the same kind of scramble from one hash of the bit-reversed value in which
//!   every output bit depends only on the input bits below it (Laine & Karras 2011, "Stratified
//!   sampling for stochastic transparency"), with the constants Vegdahl published in "Building a
//!   better LK hash" (2021). [`fast_owen_scramble`]: four multiplies.
//! - **Nested uniform shuffle** of an index (Burley 2020, "Practical hash-based Owen
//!   scrambling"): the index read as a fraction and Owen-scrambled. It maps the first `2^k`
//!   indices onto one aligned block of `2^k` indices, so the first `2^k` points of a shuffled
//!   (t, s)-sequence are still a (t, k, s)-net.
//!
//! Owen scrambles map every elementary interval onto an elementary interval of the same shape,
//! so they keep every net and stratification property; a scrambled point is uniform on
//! `[0, 1)` for every seed draw.

use crate::hash::mix32;
use crate::lazy_table::baked_table;

/// How a sampler randomizes its values (pbrt-v4's `RandomizeStrategy`).
///
/// ```
/// use nyquist::scramble::Scramble;
/// assert_eq!(Scramble::from_name("fast-owen"), Some(Scramble::FastOwen));
/// assert_eq!(Scramble::Owen.name(), "owen");
/// assert_eq!(Scramble::from_name("xor"), None);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scramble {
    /// The plain sequence.
    None,
    /// One random digit permutation per dimension, the same for every point (in base 2 a
    /// random XOR).
    PermuteDigits,
    /// A hash-based approximation of the Owen scramble (one hash per value).
    FastOwen,
    /// The nested uniform (Owen) scramble, one hash per digit.
    Owen,
}

impl Scramble {
    /// Every strategy, in the order above.
    ///
    /// ```
    /// assert_eq!(nyquist::scramble::Scramble::ALL.len(), 4);
    /// ```
    pub const ALL: [Scramble; 4] = [
        Scramble::None,
        Scramble::PermuteDigits,
        Scramble::FastOwen,
        Scramble::Owen,
    ];

    /// The strategy's name as the CLI spells it: `none`, `permute-digits`, `fast-owen`, `owen`.
    ///
    /// ```
    /// assert_eq!(nyquist::scramble::Scramble::PermuteDigits.name(), "permute-digits");
    /// ```
    pub const fn name(self) -> &'static str {
        match self {
            Scramble::None => "none",
            Scramble::PermuteDigits => "permute-digits",
            Scramble::FastOwen => "fast-owen",
            Scramble::Owen => "owen",
        }
    }

    /// The strategy called `name` (see [`Scramble::name`]), `None` for any other string.
    ///
    /// ```
    /// use nyquist::scramble::Scramble;
    /// assert!(Scramble::ALL.iter().all(|&s| Scramble::from_name(s.name()) == Some(s)));
    /// ```
    pub fn from_name(name: &str) -> Option<Scramble> {
        Scramble::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// The Laine–Karras-style hash with Vegdahl's improved constants, on a **bit-reversed** value:
/// bit `k` of the result depends only on bits `0..=k` of `x_rev` (and on `seed`), so read
/// backwards it is an Owen scramble. `seed` must already be well mixed (a hash output); small
/// or structured seeds give poor scrambles.
///
/// ```
/// use nyquist::scramble::lk_hash;
/// // Bit k of the output ignores input bits above k.
/// let (a, b) = (lk_hash(0x0000_00ff, 0x9e37_79b9), lk_hash(0xffff_00ff, 0x9e37_79b9));
/// assert_eq!(a & 0xffff, b & 0xffff);
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub const fn lk_hash(x_rev: u32, seed: u32) -> u32 {
    lk_hash_by(x_rev, seed, lk_multiplier(seed))
}

/// The odd multiplier [`lk_hash`] derives from its seed.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lk_multiplier(seed: u32) -> u32 {
    (seed >> 16) | 1
}

/// [`lk_hash`] with its seed's multiplier ([`lk_multiplier`]) given: for keys used many times,
/// which keep the multiplier beside the seed.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lk_hash_by(x_rev: u32, seed: u32, multiplier: u32) -> u32 {
    lk_hash_premixed_by(lk_premix(x_rev), seed, multiplier)
}

/// The first step of [`lk_hash`], the one that does not read the seed: `x ^ x·0x3d20adea`. A
/// bijection (the even multiplier only carries lower bits upward), so a table whose words are
/// only ever hashed can store them premixed and save every read one multiply
/// ([`lk_hash_premixed_by`] does the remaining steps).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lk_premix(x_rev: u32) -> u32 {
    // Constants: Vegdahl, "Building a better LK hash" (psychopath.io, 2021).
    x_rev ^ x_rev.wrapping_mul(0x3d20_adea)
}

/// [`lk_hash`] of a word already passed through [`lk_premix`].
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lk_hash_premixed(premixed: u32, seed: u32) -> u32 {
    lk_hash_premixed_by(premixed, seed, lk_multiplier(seed))
}

/// [`lk_hash_by`] of a word already passed through [`lk_premix`]: the seeded steps.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lk_hash_premixed_by(premixed: u32, seed: u32, multiplier: u32) -> u32 {
    let mut x = premixed.wrapping_add(seed).wrapping_mul(multiplier);
    x ^= x.wrapping_mul(0x0552_6c56);
    x ^= x.wrapping_mul(0x53a2_2864);
    x
}

/// The fast (hash) Owen scramble of the binary fraction `x` under `seed` (any `u32`; it is
/// mixed first). A bijection on `u32` that maps each aligned block of `2^k` values onto an
/// aligned block of `2^k` values.
///
/// ```
/// use nyquist::scramble::fast_owen_scramble;
/// // The first digit depends on the seed only: x < 1/2 all land in the same half.
/// let half = |x: u32| fast_owen_scramble(x, 7) >> 31;
/// assert_eq!(half(0), half(0x7fff_ffff));
/// assert_ne!(half(0), half(0x8000_0000));
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub const fn fast_owen_scramble(x: u32, seed: u32) -> u32 {
    fast_owen_keyed(x, mix32(seed ^ 0x6a09_e667))
}

/// [`fast_owen_scramble`] with an already mixed key (a hash output): the LK hash on the
/// reversed digits, for callers that draw their keys from a hash anyway.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn fast_owen_keyed(x: u32, key: u32) -> u32 {
    lk_hash(x.reverse_bits(), key).reverse_bits()
}

/// `fraction_to_f32(fast_owen_keyed(x, key))` with one bit reversal fewer: the float is read
/// straight from the reversed word ([`reversed_to_f32`]). The reference the PMJ(0,2) readers,
/// which keep their points bit-reversed, are tested against.
#[cfg(test)]
pub(crate) fn fast_owen_keyed_f32(x: u32, key: u32) -> f32 {
    reversed_to_f32(lk_hash(x.reverse_bits(), key))
}

/// The exact Owen scramble of the binary fraction `x` under `seed`: digit `k` (bit `31 − k`) is
/// flipped when a hash of `(seed, k, the k digits before it)` says so. 32 hashes per value.
///
/// The hash: with `K = mix32(seed ^ 0xbb67_ae85)` and `p` the number the `k` digits before
/// digit `k` form (0 for the first), the digit flips when the top bit of
/// [`mix64`](crate::hash::mix64)`(K · 2³² + 2ᵏ + p)` is set. The marker `2ᵏ` keeps prefixes of
/// different lengths apart, so every node of the binary tree has its own coin.
///
/// ```
/// use nyquist::scramble::owen_scramble;
/// let y: Vec<u32> = (0..4u32).map(|q| owen_scramble(q << 30, 11) >> 30).collect();
/// let mut sorted = y.clone();
/// sorted.sort();
/// assert_eq!(sorted, [0, 1, 2, 3]); // quarters go to quarters
/// ```
#[inline]
pub const fn owen_scramble(x: u32, seed: u32) -> u32 {
    let key = (mix32(seed ^ 0xbb67_ae85) as u64) << 32;
    let mut out = x;
    let mut k = 0;
    while k < 32 {
        // The digits before digit k, with a marker bit above them so prefixes of different
        // lengths never collide.
        let prefix = if k == 0 { 0 } else { x >> (32 - k) };
        let word = key | ((1u64 << k) | prefix as u64);
        if crate::hash::mix64(word) >> 63 == 1 {
            out ^= 1 << (31 - k);
        }
        k += 1;
    }
    out
}

/// Burley's nested uniform shuffle of `index` under `seed`: the index read as a binary fraction
/// and fast-Owen-scrambled. For every `k`, the indices `0..2^k` go to one aligned block
/// `c·2^k .. (c + 1)·2^k`, in an order that depends on the seed.
///
/// ```
/// use nyquist::scramble::nested_uniform_shuffle;
/// let block: Vec<u32> = (0..8).map(|i| nested_uniform_shuffle(i, 3)).collect();
/// let base = block[0] & !7;
/// let mut low: Vec<u32> = block.iter().map(|&j| {
///     assert_eq!(j & !7, base);
///     j & 7
/// }).collect();
/// low.sort();
/// assert_eq!(low, [0, 1, 2, 3, 4, 5, 6, 7]);
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub const fn nested_uniform_shuffle(index: u32, seed: u32) -> u32 {
    fast_owen_scramble(index, seed)
}

/// `x` scrambled by `how` under `seed`: [`Scramble::None`] returns `x`,
/// [`Scramble::PermuteDigits`] `x ^ mix(seed)`, [`Scramble::FastOwen`]
/// [`fast_owen_scramble`], [`Scramble::Owen`] [`owen_scramble`].
///
/// ```
/// use nyquist::scramble::{scramble_u32, Scramble};
/// assert_eq!(scramble_u32(12345, 9, Scramble::None), 12345);
/// let d = scramble_u32(0, 9, Scramble::PermuteDigits);
/// assert_eq!(scramble_u32(12345, 9, Scramble::PermuteDigits), 12345 ^ d);
/// ```
#[inline]
pub const fn scramble_u32(x: u32, seed: u32, how: Scramble) -> u32 {
    match how {
        Scramble::None => x,
        Scramble::PermuteDigits => x ^ mix32(seed ^ 0x3c6e_f372),
        Scramble::FastOwen => fast_owen_scramble(x, seed),
        Scramble::Owen => owen_scramble(x, seed),
    }
}

baked_table! {
    /// `REVERSED_F32[j][b]`: byte `j` of a bit-reversed word's share of [`reversed_to_f32`],
    /// `reverse8(b) · 2^(−8(j+1))`. Baked ([`baked_table!`]); 3 KiB.
    static REVERSED_F32: [[f32; 256]; 3] = [[0.0; 256]; 3], fill_reversed_f32,
        reversed_f32_at_first_use_equals_the_baked_table;
}

const fn fill_reversed_f32(t: &mut [[f32; 256]; 3]) {
    let scale = [1.0 / 256.0, 1.0 / 65_536.0, 1.0 / 16_777_216.0];
    let mut j = 0;
    while j < 3 {
        let mut b = 0;
        while b < 256 {
            t[j][b] = (b as u8).reverse_bits() as f32 * scale[j];
            b += 1;
        }
        j += 1;
    }
}

/// The `f32` of the binary fraction `reverse(w_rev)` (its top 24 bits, truncated: never 1) from
/// the bit-reversed word, by three table reads instead of a bit reversal (which x86-64 has no
/// instruction for): the three entries have disjoint bits, so their sum is exact.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn reversed_to_f32(w_rev: u32) -> f32 {
    let [b0, b1, b2, _] = w_rev.to_le_bytes();
    (REVERSED_F32[0][b0 as usize] + REVERSED_F32[1][b1 as usize]) + REVERSED_F32[2][b2 as usize]
}

/// The bytes `0..256`, each with its 8 bits reversed.
const REVERSED_BYTE: [u8; 256] = {
    let mut t = [0; 256];
    let mut b = 0;
    while b < 256 {
        t[b] = (b as u8).reverse_bits();
        b += 1;
    }
    t
};

/// The low 16 bits of `m` reversed (bit 0 to bit 15; the bits above are ignored): a 16-bit
/// index as the reversed word the fast Owen scrambles and shuffles read (shifted up by 16), and
/// the row of the PMJ(0,2) reversed table that holds a point. Two byte-table reads: x86-64 has
/// no bit-reversal instruction, and the dozen shifts and masks of `reverse_bits` cost more on
/// the scrambled reads' critical path (docs/design.md).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn reverse16(m: u32) -> u32 {
    ((REVERSED_BYTE[(m & 0xff) as usize] as u32) << 8)
        | REVERSED_BYTE[((m >> 8) & 0xff) as usize] as u32
}

/// The top 24 bits of a reversed, scrambled word, as an `f32` in `[0, 1)`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn rev_to_f32(w_rev: u32) -> f32 {
    (w_rev.reverse_bits() >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// [`lk_hash`] then [`rev_to_f32`] on four lanes: the SSE2 kernel on x86-64, else
/// [`scramble_rev_f32x4_lanes`]. What the four-wide Owen-Sobol values and the batched PMJ(0,2)
/// reads end in.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_rev_f32x4(x: [u32; 4], seeds: [u32; 4]) -> [f32; 4] {
    scramble_rev_f32x4_from::<false>(x, seeds)
}

/// [`scramble_rev_f32x4`] of words stored premixed ([`lk_premix`]): one multiply fewer per lane.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_premixed_rev_f32x4(premixed: [u32; 4], seeds: [u32; 4]) -> [f32; 4] {
    scramble_rev_f32x4_from::<true>(premixed, seeds)
}

#[cfg_attr(not(feature = "small-code"), inline(always))]
fn scramble_rev_f32x4_from<const PREMIXED: bool>(x: [u32; 4], seeds: [u32; 4]) -> [f32; 4] {
    #[cfg(target_arch = "x86_64")]
    {
        crate::simd::scramble_rev_f32x4_x86::<PREMIXED>(x, seeds)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        scramble_rev_f32x4_lanes::<PREMIXED>(x, seeds)
    }
}

/// [`lk_hash`] then [`rev_to_f32`] on four lanes, written lane-parallel so that it compiles to
/// vector code where the target has it (past x86-64, and the SSE2 kernel's oracle in tests).
#[cfg_attr(all(target_arch = "x86_64", not(test)), allow(dead_code))]
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_rev_f32x4_lanes<const PREMIXED: bool>(
    x: [u32; 4],
    seeds: [u32; 4],
) -> [f32; 4] {
    let mut x = x;
    if !PREMIXED {
        x = x.map(lk_premix);
    }
    for k in 0..4 {
        x[k] = x[k].wrapping_add(seeds[k]);
    }
    for k in 0..4 {
        x[k] = x[k].wrapping_mul(lk_multiplier(seeds[k]));
    }
    for k in 0..4 {
        x[k] ^= x[k].wrapping_mul(0x0552_6c56);
    }
    for k in 0..4 {
        x[k] ^= x[k].wrapping_mul(0x53a2_2864);
    }
    x.map(rev_to_f32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// Owen scrambles are nested: two values that share their first `k` digits still do after
    /// the scramble, and the map is a bijection on every aligned block.
    #[test]
    fn owen_scrambles_keep_prefixes_and_blocks() {
        for how in [Scramble::FastOwen, Scramble::Owen, Scramble::PermuteDigits] {
            for seed in [0u32, 1, 0xdead_beef] {
                for k in 1..=10u32 {
                    let n = 1u32 << k;
                    // Block c of size 2^(32−k) maps to one block: the first k digits of every
                    // image agree.
                    let mut seen = std::vec![false; n as usize];
                    for c in 0..n {
                        let lo = c << (32 - k);
                        let first = scramble_u32(lo, seed, how) >> (32 - k);
                        for off in [1u32, 12345, (1 << (32 - k)) - 1] {
                            let y = scramble_u32(lo | (off & ((1 << (32 - k)) - 1)), seed, how);
                            assert_eq!(y >> (32 - k), first, "{how:?} seed {seed} k {k}");
                        }
                        assert!(!std::mem::replace(&mut seen[first as usize], true));
                    }
                }
            }
        }
    }

    /// The exact scramble from its documented definition, digit by digit: the prefix is built
    /// up as the digits are read, and each node's word is a sum.
    #[test]
    fn owen_flips_follow_the_documented_hash() {
        fn oracle(x: u32, seed: u32) -> u32 {
            let key = u64::from(crate::hash::mix32(seed ^ 0xbb67_ae85)) * (1 << 32);
            let (mut prefix, mut out) = (0u64, 0u32);
            for k in 0..32 {
                let digit = (x >> (31 - k)) & 1;
                let flip = crate::hash::mix64(key + (1 << k) + prefix) >= 1 << 63;
                out = 2 * out + (digit ^ u32::from(flip));
                prefix = 2 * prefix + u64::from(digit);
            }
            out
        }
        for seed in [0u32, 1, 11, 0xdead_beef, u32::MAX] {
            for x in [0u32, 1, 0x8000_0000, 0x1234_5678, 0xffff_ffff, 0x5555_5555] {
                assert_eq!(
                    owen_scramble(x, seed),
                    oracle(x, seed),
                    "x {x:#x} seed {seed}"
                );
            }
        }
    }

    /// Different nodes of the tree flip independently: over 4096 seeds, the coins of two
    /// nodes agree about half the time (6σ = 192 around 2048, a false alarm below 10⁻⁸ per
    /// pair). Nodes are (k, p): digit k under prefix p; node (k, p)'s coin is read from any
    /// `x` whose first k digits are p.
    #[test]
    fn owen_coins_of_different_nodes_are_independent() {
        let coin = |seed: u32, k: u32, p: u32| {
            let x = if k == 0 { 0 } else { p << (32 - k) };
            ((owen_scramble(x, seed) ^ x) >> (31 - k)) & 1
        };
        let nodes = [
            (0u32, 0u32),
            (1, 0),
            (1, 1),
            (2, 1),
            (2, 3),
            (5, 1),
            (31, 1),
        ];
        for (i, &(k1, p1)) in nodes.iter().enumerate() {
            for &(k2, p2) in &nodes[i + 1..] {
                let agree = (0..4096u32)
                    .filter(|&s| coin(s, k1, p1) == coin(s, k2, p2))
                    .count();
                assert!(
                    agree.abs_diff(2048) < 192,
                    "({k1}, {p1}) vs ({k2}, {p2}): {agree}"
                );
            }
        }
    }

    /// Digit permutation in base 2 is one random XOR word per seed: a bijection that maps
    /// `x ^ z` to `y ^ z`; and no two seeds share a word (the word is a bijective hash of the
    /// seed), checked over the first 4096 seeds.
    #[test]
    fn permuted_digits_are_an_xor_with_one_word() {
        for seed in [0u32, 3, u32::MAX] {
            let word = scramble_u32(0, seed, Scramble::PermuteDigits);
            for x in [1u32, 0x8000_0000, 0x1234_5678, u32::MAX] {
                assert_eq!(scramble_u32(x, seed, Scramble::PermuteDigits), x ^ word);
            }
        }
        let words: std::collections::BTreeSet<u32> = (0..4096)
            .map(|seed| scramble_u32(0, seed, Scramble::PermuteDigits))
            .collect();
        assert_eq!(words.len(), 4096);
    }

    #[test]
    fn scrambles_depend_on_the_seed_and_are_not_the_identity() {
        for how in [Scramble::FastOwen, Scramble::Owen, Scramble::PermuteDigits] {
            let a: Vec<u32> = (0..64).map(|i| scramble_u32(i << 26, 1, how)).collect();
            let b: Vec<u32> = (0..64).map(|i| scramble_u32(i << 26, 2, how)).collect();
            assert_ne!(a, b, "{how:?}");
            assert_ne!(a, (0..64).map(|i| i << 26).collect::<Vec<u32>>(), "{how:?}");
        }
    }

    /// Under the exact Owen scramble every digit of a fixed point is a fair coin over seeds;
    /// the fast one is held to the same for its first 24 digits (what an `f32` keeps).
    #[test]
    fn every_digit_is_fair_over_seeds() {
        const SEEDS: u32 = 20_000;
        for how in [Scramble::FastOwen, Scramble::Owen] {
            for x in [0u32, 0x8000_0000, 0x1234_5678] {
                let mut ones = [0u32; 24];
                for seed in 0..SEEDS {
                    let y = scramble_u32(x, seed, how);
                    for (k, c) in ones.iter_mut().enumerate() {
                        *c += (y >> (31 - k)) & 1;
                    }
                }
                for (k, &c) in ones.iter().enumerate() {
                    // 6 standard deviations of a binomial(20000, 1/2) is 424.
                    assert!(
                        c.abs_diff(SEEDS / 2) < 425,
                        "{how:?} x {x:#x} digit {k}: {c}"
                    );
                }
            }
        }
    }

    #[test]
    fn nested_uniform_shuffle_maps_prefixes_to_aligned_blocks() {
        for seed in [0u32, 5, 0x8765_4321] {
            for k in 0..=12u32 {
                let n = 1u32 << k;
                let base = nested_uniform_shuffle(0, seed) >> k;
                let mut seen = std::vec![false; n as usize];
                for i in 0..n {
                    let j = nested_uniform_shuffle(i, seed);
                    assert_eq!(j >> k, base, "seed {seed} k {k} i {i}");
                    assert!(!std::mem::replace(&mut seen[(j & (n - 1)) as usize], true));
                }
            }
        }
    }

    #[test]
    fn reversed_to_f32_is_the_float_of_the_reversed_word() {
        for w in (0..1u32 << 16).chain((0..1u32 << 16).map(|i| mix32(i ^ 0x5a5a))) {
            let want = (w.reverse_bits() >> 8) as f32 / 16_777_216.0;
            assert_eq!(reversed_to_f32(w).to_bits(), want.to_bits(), "{w:#x}");
        }
        assert!(reversed_to_f32(u32::MAX) < 1.0);
    }

    /// `lk_hash` is the hash of Vegdahl's "Building a better LK hash" (psychopath.io, 2021),
    /// transcribed here step by step from the post as the reference; a scramble with any step
    /// changed is still nested but no longer that hash.
    #[test]
    fn lk_hash_is_the_published_hash() {
        fn published(mut x: u32, seed: u32) -> u32 {
            x ^= x.wrapping_mul(0x3d20_adea);
            x = x.wrapping_add(seed);
            x = x.wrapping_mul((seed >> 16) | 1);
            x ^= x.wrapping_mul(0x0552_6c56);
            x ^= x.wrapping_mul(0x53a2_2864);
            x
        }
        for seed in [0u32, 1, 0x0001_0000, 0x8765_4321, u32::MAX] {
            for x in (0..4096u32).map(|i| i.wrapping_mul(0x9e37_79b9)) {
                assert_eq!(
                    lk_hash(x, seed),
                    published(x, seed),
                    "x {x:#x}, seed {seed:#x}"
                );
            }
        }
    }

    /// The float route of the fast Owen scramble reads the same top 24 digits as the integer
    /// route: `fast_owen_keyed_f32` is the fraction of `fast_owen_keyed`.
    #[test]
    fn fast_owen_float_is_the_fraction_of_the_integer_scramble() {
        for key in [0u32, 3, 0xdead_beef] {
            for x in (0..1u32 << 14).map(|i| i.wrapping_mul(0x0004_0003) ^ (i << 18)) {
                let want = crate::math::fraction_to_f32(fast_owen_keyed(x, key));
                assert_eq!(
                    fast_owen_keyed_f32(x, key).to_bits(),
                    want.to_bits(),
                    "{x:#x}"
                );
            }
        }
    }

    #[test]
    fn names_round_trip() {
        for s in Scramble::ALL {
            assert_eq!(Scramble::from_name(s.name()), Some(s));
        }
        assert_eq!(Scramble::from_name(""), None);
        assert_eq!(Scramble::from_name("Owen"), None);
    }

    /// The byte-table reversal is the 32-bit one's top half, whatever the bits above 16.
    #[test]
    fn reverse16_is_the_top_half_of_the_32_bit_reversal() {
        for m in (0..1u32 << 16).flat_map(|m| [m, m | 0xffff_0000, m | mix32(m) << 16]) {
            assert_eq!(reverse16(m), m.reverse_bits() >> 16, "m {m:#x}");
        }
    }

    /// The four-lane scramble is the scalar hash and the table conversion on every lane, and
    /// the arithmetic conversion equals the table one.
    #[test]
    fn four_lane_scramble_is_the_scalar_one_per_lane() {
        for (n, w) in (0..4096u32).map(|i| mix32(i ^ 0x3c3c)).enumerate() {
            let x = [w, !w, w.rotate_left(13), mix32(w)];
            let seeds = [mix32(n as u32), 0, u32::MAX, 0x0001_0000];
            let got = scramble_rev_f32x4(x, seeds);
            let premixed = scramble_premixed_rev_f32x4(x.map(lk_premix), seeds);
            for k in 0..4 {
                let want = reversed_to_f32(lk_hash(x[k], seeds[k]));
                assert_eq!(got[k].to_bits(), want.to_bits(), "w {w:#x} lane {k}");
                assert_eq!(premixed[k].to_bits(), want.to_bits(), "w {w:#x} lane {k}");
                let by_steps = lk_hash_premixed(lk_premix(x[k]), seeds[k]);
                assert_eq!(by_steps, lk_hash(x[k], seeds[k]));
            }
            assert_eq!(
                rev_to_f32(w).to_bits(),
                reversed_to_f32(w).to_bits(),
                "w {w:#x}"
            );
        }
    }

    /// The run-time choice of kernel agrees with std's feature detection (first call and the
    /// kept answer).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn sse41_detection_agrees_with_std() {
        let std_says =
            std::is_x86_feature_detected!("ssse3") && std::is_x86_feature_detected!("sse4.1");
        assert_eq!(crate::simd::has_sse41(), std_says);
        assert_eq!(crate::simd::has_sse41(), std_says);
    }

    /// On x86-64 the SSE2 kernel, and the SSSE3 + SSE4.1 one where the CPU has them, equal the
    /// portable lane code bit for bit: words and seeds over edge values and hashed ones, every
    /// lane different.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn x86_kernels_equal_the_portable_lanes() {
        use crate::simd::{has_sse41, scramble_rev_f32x4_sse2, scramble_rev_f32x4_sse41};
        let mut sse41_ran = false;
        let edges = [0, 1, 0x8000_0000, u32::MAX, 0xffff_0000, 0x0000_ffff];
        let words = edges
            .into_iter()
            .chain((0..if cfg!(miri) { 200 } else { 20_000 }).map(|i| mix32(i ^ 0xa5a5)));
        for (n, w) in words.enumerate() {
            let x = [w, w.rotate_left(7), !w, mix32(w)];
            let s = mix32(n as u32);
            let seeds = [s, s ^ 0xffff_0000, edges[n % 6], mix32(s)];
            let got = scramble_rev_f32x4_sse2::<false>(x, seeds).map(f32::to_bits);
            let want = scramble_rev_f32x4_lanes::<false>(x, seeds).map(f32::to_bits);
            assert_eq!(got, want, "x {x:x?} seeds {seeds:x?}");
            let got = scramble_rev_f32x4_sse2::<true>(x, seeds).map(f32::to_bits);
            let want_premixed = scramble_rev_f32x4_lanes::<true>(x, seeds).map(f32::to_bits);
            assert_eq!(got, want_premixed, "premixed x {x:x?} seeds {seeds:x?}");
            if let Some(got) = scramble_rev_f32x4_sse41::<false>(x, seeds) {
                assert_eq!(
                    got.map(f32::to_bits),
                    want,
                    "sse4.1 x {x:x?} seeds {seeds:x?}"
                );
                let got = scramble_rev_f32x4_sse41::<true>(x, seeds).unwrap();
                assert_eq!(got.map(f32::to_bits), want_premixed, "sse4.1 premixed");
                sse41_ran = true;
            }
        }
        assert_eq!(sse41_ran, has_sse41());
    }
}
