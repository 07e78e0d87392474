//! Integer hashing and hash-derived permutations: the stateless randomness behind scrambles,
//! per-pixel decorrelation and Latin-hypercube strata. The only table is the 32 permutations of
//! two to four elements, computed at compile time.
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

/// Word `i` of the WyRand stream seeded with `seed` (Wang Yi's wyhash, final version 4: a Weyl
/// sequence with increment `0xa0761d6478bd642f`, each state folded by one 64×64→128-bit multiply
/// with itself XOR `0xe7037ed1a0b428db`, high half XOR low half), computed directly from `i`,
/// so a block of words has no serial dependency. One wide multiply per word; the stream passes
/// PractRand and BigCrush per its author.
///
/// ```
/// use nyquist::hash::wyrand;
/// let s = 7u64.wrapping_add(0xa076_1d64_78bd_642f);
/// let t = u128::from(s) * u128::from(s ^ 0xe703_7ed1_a0b4_28db);
/// assert_eq!(wyrand(7, 0), (t >> 64) as u64 ^ t as u64);
/// assert_ne!(wyrand(7, 0), wyrand(7, 1));
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub const fn wyrand(seed: u64, i: u64) -> u64 {
    wyrand_fold(seed.wrapping_add(WYRAND_INC.wrapping_mul(i.wrapping_add(1))))
}

/// WyRand's Weyl increment.
pub(crate) const WYRAND_INC: u64 = 0xa076_1d64_78bd_642f;

/// WyRand's output fold of a Weyl state `s`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn wyrand_fold(s: u64) -> u64 {
    let t = (s as u128) * ((s ^ 0xe703_7ed1_a0b4_28db) as u128);
    (t >> 64) as u64 ^ t as u64
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

/// A pseudo-random permutation of `0..n` chosen by a seed, evaluated one element at a time
/// without a table: build it once, then [`apply`](Permutation::apply) it as often as needed.
///
/// - `n ≤ 16`: the whole permutation, packed as sixteen 4-bit entries in one `u64`, is drawn by
///   Fisher–Yates from one 64-bit hash (each step takes `⌊r·k⌋` and keeps `frac(r·k)`, which
///   spends only log₂ k bits, 44 for all of 16!): uniform over all `n!` permutations up to
///   `n!/2⁶⁴`, and [`apply`](Permutation::apply) is a shift and a mask. For `n ≤ 4` (the usual
///   integrator array sizes) the draw is one multiply, `⌊r·n!⌋`, choosing from a table of all
///   `n!` permutations in lexicographic order: the same uniformity for a tenth of the work.
/// - `n > 16`: a keyed bijection on `0..2^⌈log₂ n⌉` (xor, odd multiply and xor-shift rounds)
///   restricted to `0..n` by cycle walking — Kensler's construction (“Correlated Multi-Jittered
///   Sampling”, 2013) with our own rounds — followed by a rotation by a hashed offset. The
///   rotation makes every element's image exactly uniform over seeds (to within `n/2³²`):
///   `P(π(i) = j) = 1/n` for every `i`, `j`. Joint statistics (which of the `n!` permutations)
///   are not exactly uniform.
///
/// Total: `n == 0` behaves as `n == 1` (every element maps to 0); `apply(i)` with `i >= n`
/// reduces `i` modulo `n` first.
///
/// ```
/// use nyquist::hash::Permutation;
/// let p = Permutation::new(10, 42);
/// let mut seen = [false; 10];
/// for i in 0..10 {
///     seen[p.apply(i) as usize] = true;
/// }
/// assert!(seen.iter().all(|&s| s));
/// assert_eq!(p.apply(13), p.apply(3));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Permutation {
    n: u32,
    mask: u32,
    half: u32,
    third: u32,
    key: u32,
    key2: u32,
    offset: u32,
    /// For `n ≤ 16`: entry `i` in bits `4i .. 4i + 4`.
    table: u64,
}

/// Sizes up to this use the packed table.
pub(crate) const TABLE_MAX: u32 = 16;

/// A uniformly drawn permutation of `0..n` (`n ≤ 16`), packed in nibbles, from the 64-bit
/// fraction `r`.
#[inline]
fn packed_permutation(n: u32, r: u64) -> u64 {
    // The usual spp, 16, with the loop unrolled: its shifts become constants.
    if n == 16 {
        fisher_yates(16, r)
    } else {
        fisher_yates(n, r)
    }
}

/// [`packed_permutation`]'s shuffle (Fisher–Yates on nibbles).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn fisher_yates(n: u32, mut r: u64) -> u64 {
    // Identity: nibble i = i.
    let mut t = 0xfedc_ba98_7654_3210u64 & (u64::MAX >> (64 - 4 * n.max(1)));
    let mut k = n;
    while k > 1 {
        // j uniform in 0..k: the integer part of r·k; the fraction carries the rest.
        let p = u128::from(r) * u128::from(k);
        let j = (p >> 64) as u32;
        r = p as u64;
        let (hi, lo) = (4 * (k - 1), 4 * j);
        let x = ((t >> hi) ^ (t >> lo)) & 0xf;
        t ^= (x << hi) | (x << lo);
        k -= 1;
    }
    t
}

/// Sizes up to this draw from [`SMALL_PERMUTATIONS`].
const SMALL_MAX: usize = 4;
/// `n!` for `n ≤ SMALL_MAX`.
const FACTORIAL: [u64; SMALL_MAX + 1] = [1, 1, 2, 6, 24];
/// Where the permutations of `n` elements start in [`SMALL_PERMUTATIONS`].
const SMALL_START: [usize; SMALL_MAX + 1] = [0, 0, 0, 2, 8];

/// Every permutation of `0..n` for `n` = 2, 3, 4 (2 + 6 + 24), packed in nibbles like
/// [`packed_permutation`]'s, each size in lexicographic order.
const SMALL_PERMUTATIONS: [u64; 32] = small_permutations();

/// Permutation number `rank` (lexicographic, `rank < n!`) of `0..n`, `n ≤ 4`: the Lehmer code
/// of `rank` picks each entry from the elements not yet used.
const fn nth_permutation(n: usize, mut rank: u64) -> u64 {
    let mut unused = [true; SMALL_MAX];
    let mut packed = 0u64;
    let mut i = 0;
    while i < n {
        let f = FACTORIAL[n - 1 - i];
        let mut d = rank / f;
        rank %= f;
        let mut e = 0;
        loop {
            if unused[e] {
                if d == 0 {
                    break;
                }
                d -= 1;
            }
            e += 1;
        }
        unused[e] = false;
        packed |= (e as u64) << (4 * i);
        i += 1;
    }
    packed
}

const fn small_permutations() -> [u64; 32] {
    let mut out = [0u64; 32];
    let mut n = 2;
    while n <= SMALL_MAX {
        let mut rank = 0;
        while rank < FACTORIAL[n] {
            out[SMALL_START[n] + rank as usize] = nth_permutation(n, rank);
            rank += 1;
        }
        n += 1;
    }
    out
}

/// [`packed_permutation`]'s uniform draw for `n ≤ 4` by one multiply and a table read.
#[inline]
fn small_permutation(n: u32, r: u64) -> u64 {
    let n = (n as usize).min(SMALL_MAX);
    let rank = ((u128::from(r) * u128::from(FACTORIAL[n])) >> 64) as usize;
    if n < 2 {
        return 0;
    }
    SMALL_PERMUTATIONS[(SMALL_START[n] + rank) & 31]
}

/// A uniformly drawn permutation of `0..n` (`1 ≤ n ≤ 16`; larger `n` are taken as 16) packed in
/// nibbles, entry `i` in bits `4i .. 4i + 4`, from the 64-bit fraction `r` (a hash: its high
/// bits choose). What [`Permutation::new`] stores for `n ≤ 16` after mixing its seed; samplers
/// that already hold a mixed key call it directly.
#[inline]
pub(crate) fn packed_table(n: u32, r: u64) -> u64 {
    let n = n.min(TABLE_MAX);
    if n as usize <= SMALL_MAX {
        small_permutation(n, r)
    } else {
        packed_permutation(n, r)
    }
}

/// Entry `i` of a [`packed_table`] (`i < 16`; the table's own `n` is not checked).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn packed_entry(table: u64, i: u32) -> u32 {
    ((table >> (4 * (i & 15))) & 0xf) as u32
}

/// The order of an array's `n` values, drawn from an already mixed 64-bit key: a nibble table
/// read straight from the key for `n ≤ 16` (the usual array sizes: no set-up beyond one
/// multiply), else a keyed [`Permutation`] seeded with the key's low 32 bits.
#[derive(Clone, Copy, Debug)]
pub(crate) enum ArrayOrder {
    Table(u64),
    Keyed(Permutation),
}

impl ArrayOrder {
    #[inline]
    pub(crate) fn new(n: u32, key: u64) -> ArrayOrder {
        if n <= TABLE_MAX {
            ArrayOrder::Table(packed_table(n, key))
        } else {
            ArrayOrder::Keyed(Permutation::new(n, key as u32))
        }
    }

    /// Where value `j < n` goes.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn apply(&self, j: u32) -> u32 {
        match self {
            ArrayOrder::Table(t) => packed_entry(*t, j),
            ArrayOrder::Keyed(p) => p.apply(j),
        }
    }
}

impl Permutation {
    /// The permutation of `0..n` for `seed`.
    ///
    /// ```
    /// use nyquist::hash::Permutation;
    /// assert_ne!(Permutation::new(64, 1), Permutation::new(64, 2));
    /// assert_eq!(Permutation::new(0, 5).apply(7), 0);
    /// ```
    #[inline]
    pub fn new(n: u32, seed: u32) -> Permutation {
        let n = n.max(1);
        if n <= TABLE_MAX {
            return Permutation {
                n,
                mask: 0,
                half: 0,
                third: 0,
                key: 0,
                key2: 0,
                offset: 0,
                table: packed_table(n, mix64(u64::from(seed) ^ 0x243f_6a88_85a3_08d3)),
            };
        }
        let mask = u32::MAX >> (n - 1).leading_zeros();
        let bits = 32 - mask.leading_zeros();
        let key = mix32(seed ^ 0x5bd1_e995);
        let key2 = mix32(key.wrapping_add(0x68e3_1da4));
        let key3 = mix32(key2 ^ 0x2545_f491);
        Permutation {
            n,
            mask,
            half: bits.div_ceil(2).max(1),
            third: (bits / 3).max(1),
            key,
            key2,
            offset: ((u64::from(key3) * u64::from(n)) >> 32) as u32,
            table: 0,
        }
    }

    /// The number of elements `n` (at least 1).
    ///
    /// ```
    /// assert_eq!(nyquist::hash::Permutation::new(0, 1).size(), 1);
    /// ```
    #[inline]
    pub fn size(&self) -> u32 {
        self.n
    }

    /// π(i): the image of element `i` (`i >= n` is reduced modulo `n` first).
    ///
    /// ```
    /// use nyquist::hash::Permutation;
    /// let p = Permutation::new(3, 9);
    /// let mut img = [p.apply(0), p.apply(1), p.apply(2)];
    /// img.sort();
    /// assert_eq!(img, [0, 1, 2]);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn apply(&self, i: u32) -> u32 {
        let (n, mask, half) = (self.n, self.mask, self.half);
        if n <= TABLE_MAX {
            return packed_entry(self.table, if i < n { i } else { i % n });
        }
        let mut x = if i < n { i } else { i % n };
        loop {
            // Each step is a bijection on `bits`-bit words: xor with a constant, multiply by an
            // odd constant modulo 2^bits, xor-shift right.
            x ^= self.key & mask;
            x = x.wrapping_mul(0xe170_893d) & mask;
            x ^= x >> half;
            x = x.wrapping_add(self.key2) & mask;
            x = x.wrapping_mul(self.key | 1) & mask;
            x ^= x >> half;
            x ^= (self.key2 >> 7) & mask;
            x = x.wrapping_mul(0x0929_eb3f) & mask;
            x ^= x >> half;
            x = x.wrapping_mul(0x6935_fa69 ^ (self.key2 & 0xffff_fffe)) & mask;
            x ^= x >> self.third;
            if x < n {
                break;
            }
        }
        // (x + offset) mod n, in 64 bits so n near 2³² cannot overflow.
        let q = u64::from(x) + u64::from(self.offset);
        let n = u64::from(n);
        (if q >= n { q - n } else { q }) as u32
    }
}

/// Element `i` of the pseudo-random permutation of `0..n` chosen by `seed`:
/// `Permutation::new(n, seed).apply(i)` (see [`Permutation`], which also saves the key set-up
/// when many elements of one permutation are needed).
///
/// For a fixed `(n, seed)`, `i ↦ permute(i, n, seed)` is a bijection on `0..n`; every element's
/// image is uniform over seeds. Total: `n == 0` or `n == 1` gives 0, and `i >= n` is first
/// reduced modulo `n`. Expected cost: fewer than two rounds of a keyed bijection.
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
    Permutation::new(n, seed).apply(i)
}

// OpenQMC's generator for its PMJ(0,2) table (`lcg_draw`): the 32-bit LCG
// `T(s) = LCG_A·s + LCG_C` with the PCG-RXS-M-XS output (O'Neill 2014; the constants are
// OpenQMC's `pcg.h`).
const LCG_A: u32 = 747_796_405;
const LCG_C: u32 = 2_891_336_453;

/// `f ∘ g` for affine maps `(A, C)`, `s ↦ A·s + C`: `g` first.
const fn lcg_compose(f: (u32, u32), g: (u32, u32)) -> (u32, u32) {
    (
        f.0.wrapping_mul(g.0),
        f.0.wrapping_mul(g.1).wrapping_add(f.1),
    )
}

/// `T^(d · 64^w)` as `(A, C)` (`T^n(s) = A·s + C`) for windows `w` 0 … 2 and digits `d`
/// 0 … 63.
const LCG_WINDOWS: [[(u32, u32); 64]; 3] = lcg_windows();

const fn lcg_windows() -> [[(u32, u32); 64]; 3] {
    let mut t = [[(1u32, 0u32); 64]; 3];
    // The step of window w: T^(64^w).
    let mut step = (LCG_A, LCG_C);
    let mut w = 0;
    while w < 3 {
        let mut d = 1;
        while d < 64 {
            t[w][d] = lcg_compose(step, t[w][d - 1]);
            d += 1;
        }
        step = lcg_compose(step, t[w][63]);
        w += 1;
    }
    t
}

/// The PCG-RXS-M-XS output of an LCG state.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn rxs_m_xs(state: u32) -> u32 {
    let mut s = state;
    s ^= s >> (4 + (s >> 28));
    s = s.wrapping_mul(277_803_737);
    s ^ (s >> 22)
}

/// The generator's state for `seed`, before its first draw: `T(0) + seed`, OpenQMC's
/// `pcg::init(seed)`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lcg_state(seed: u32) -> u32 {
    LCG_C.wrapping_add(seed)
}

/// The generator's next draw: steps `state` once and returns its output.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lcg_next(state: &mut u32) -> u32 {
    *state = state.wrapping_mul(LCG_A).wrapping_add(LCG_C);
    rxs_m_xs(*state)
}

/// Draw `m` (`m < 2¹⁸ − 1`) of OpenQMC's generator from `seed`: the output of `T^(m+1)`
/// applied to [`lcg_state`]`(seed)`, what the `(m + 1)`-th call of [`lcg_next`] returns. It
/// jumps there in three 6-bit windows of `m + 1`, so any draw costs three multiply-adds.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) const fn lcg_draw(seed: u32, m: u32) -> u32 {
    let mut s = lcg_state(seed);
    let n = m + 1;
    let mut w = 0;
    while w < 3 {
        let (a, c) = LCG_WINDOWS[w][((n >> (6 * w)) & 63) as usize];
        s = a.wrapping_mul(s).wrapping_add(c);
        w += 1;
    }
    rxs_m_xs(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// OpenQMC's generator as its own header draws it (`pcg.h` at commit 294d656: `pcg::rng`
    /// from `pcg::init()` and from `pcg::init(12345)`, printed by a C++ program): the first
    /// draws, and draw 2¹⁷ − 1, the last a pmj02 table of 2¹⁶ points takes.
    #[test]
    fn the_lcg_draws_are_openqmcs() {
        let mut s = lcg_state(0); // pcg::init(): the state after one step from 0
        let first = [
            0x22b6_b6bc,
            0x3bf6_e0b1,
            0x572f_7439,
            0x86fc_4ddc,
            0x3465_9162,
            0x6879_4667,
        ];
        for (m, v) in (0u32..).zip(first) {
            assert_eq!(lcg_next(&mut s), v, "draw {m}");
            assert_eq!(lcg_draw(0, m), v, "draw {m}");
        }
        let seeded = [0xc3f5_1e88, 0x6bee_3fec, 0x69d2_bcac, 0xb72e_164e];
        for (m, v) in (0u32..).zip(seeded) {
            assert_eq!(lcg_draw(12345, m), v, "seed 12345, draw {m}");
        }
        assert_eq!(lcg_draw(0, (1 << 17) - 1), 0x41af_cda3);
    }

    /// The jump through the three windows lands where stepping does at every draw it is
    /// documented for (`m < 2¹⁸ − 1`: every digit of every window), from three seeds.
    #[test]
    fn the_lcg_jump_is_the_stepped_generator() {
        for seed in [0u32, 1, 0x9e37_79b9] {
            let mut s = lcg_state(seed);
            for m in 0..(1u32 << 18) - 1 {
                assert_eq!(lcg_draw(seed, m), lcg_next(&mut s), "seed {seed}, draw {m}");
            }
        }
    }

    /// Golden values: which permutation a seed picks is part of what a seeded render reproduces,
    /// and the keyed rounds past `TABLE_MAX` are this crate's own, so these images come from this
    /// code. A change to them must be deliberate (as for the CLI's golden hashes,
    /// `docs/reliability.md`); each round's constants, shifts and masks are pinned by them.
    #[test]
    fn keyed_permutations_are_pinned() {
        for (n, seed, want) in [
            (17u32, 0u32, [7u32, 13, 14, 1, 0, 12, 5, 11]),
            (17, 1, [5, 1, 3, 12, 14, 15, 8, 6]),
            (1000, 0xdead_beef, [280, 509, 307, 669, 253, 559, 327, 170]),
            (
                1 << 20,
                7,
                [
                    328_618, 138_539, 647_007, 43_722, 729_865, 378_030, 179_042, 173_105,
                ],
            ),
            (
                u32::MAX,
                42,
                [
                    1_681_410_046,
                    980_232_434,
                    1_444_710_851,
                    1_766_413_444,
                    771_531_654,
                    4_180_287_992,
                    2_173_803_724,
                    3_029_265_320,
                ],
            ),
        ] {
            let p = Permutation::new(n, seed);
            let got: [u32; 8] = core::array::from_fn(|i| p.apply(3 * i as u32));
            assert_eq!(got, want, "n {n} seed {seed}");
        }
    }

    /// SplitMix64 (Steele, Lea & Flood 2014) is `mix64` applied to a Weyl sequence with
    /// increment `GOLDEN`; its published first outputs from state 0 pin every step of the
    /// finaliser.
    #[test]
    fn mix64_reproduces_splitmix64s_published_outputs() {
        let mut state = 0u64;
        for want in [
            0xe220_a839_7b1d_cdaf,
            0x6e78_9e6a_a1b9_65f4,
            0x06c4_5d18_8009_454f,
        ] {
            state = state.wrapping_add(GOLDEN);
            assert_eq!(mix64(state), want);
        }
    }

    /// `lowbias32` is a bijection, and Wellons publishes its inverse (`lowbias32_r`: the
    /// xor-shifts undone, multiplied by the constants' inverses modulo 2³²). Composing the two
    /// is the identity, which pins each of the five steps.
    #[test]
    fn mix32_is_undone_by_the_published_inverse() {
        let inverse = |mut x: u32| {
            x ^= x >> 16;
            x = x.wrapping_mul(0x4302_1123);
            x ^= (x >> 15) ^ (x >> 30);
            x = x.wrapping_mul(0x1d69_e2a5);
            x ^ (x >> 16)
        };
        for x in (0..1u32 << 16).map(|k| k.wrapping_mul(0x9e37_79b9) ^ k) {
            assert_eq!(inverse(mix32(x)), x, "{x:#x}");
        }
        // And it mixes: one flipped input bit flips about half the output bits.
        let flips: u32 = (0..32)
            .map(|b| (mix32(12_345) ^ mix32(12_345 ^ (1 << b))).count_ones())
            .sum();
        assert!((8 * 32..24 * 32).contains(&flips), "{flips}");
    }

    /// Each field of `hash2` and `hash3` is hashed bijectively: for fixed other fields, distinct
    /// values of one field give distinct hashes (a field combined with `|` or `&`, or dropped,
    /// would collide).
    #[test]
    fn hashes_are_injective_in_each_field() {
        let distinct = |f: &dyn Fn(u64) -> u64| {
            let mut v: std::vec::Vec<u64> = (0..1u64 << 14)
                .map(|x| f(x.wrapping_mul(0x1_0001)))
                .collect();
            v.sort_unstable();
            v.dedup();
            v.len()
        };
        let all = 1 << 14;
        assert_eq!(distinct(&|x| hash2(x, 77)), all);
        assert_eq!(distinct(&|x| hash2(77, x)), all);
        assert_eq!(distinct(&|x| hash3(x, 5, 6)), all);
        assert_eq!(distinct(&|x| hash3(5, x, 6)), all);
        assert_eq!(distinct(&|x| hash3(5, 6, x)), all);
        assert_ne!(hash2(1, 2), hash2(2, 1));
        assert_ne!(hash3(1, 2, 3), hash3(1, 3, 2));
        assert_ne!(hash3(1, 2, 3), hash2(1, 2));
    }

    /// `hash_slice` is the documented fold of `hash2` from `GOLDEN`, over every element.
    #[test]
    fn hash_slice_folds_hash2_over_every_element() {
        assert_eq!(hash_slice(&[]), GOLDEN);
        let values = [3u64, 1, 4, 1, 5, 9, 2, 6];
        for len in 0..=values.len() {
            let fold = values[..len].iter().fold(GOLDEN, |h, &v| hash2(h, v));
            assert_eq!(hash_slice(&values[..len]), fold, "{len} values");
        }
    }

    /// WyRand word `i` is the `i + 1`-th output of the sequential generator from the wyhash
    /// reference (`state += 0xa0761d6478bd642f`, then fold `state · (state ^
    /// 0xe7037ed1a0b428db)` as 128 bits, high half XOR low half).
    #[test]
    fn wyrand_is_the_sequential_generator_addressed_by_index() {
        for seed in [0u64, 7, u64::MAX] {
            let mut state = seed;
            for i in 0..100 {
                state = state.wrapping_add(0xa076_1d64_78bd_642f);
                let t = u128::from(state) * u128::from(state ^ 0xe703_7ed1_a0b4_28db);
                assert_eq!(
                    wyrand(seed, i),
                    (t >> 64) as u64 ^ t as u64,
                    "seed {seed}, {i}"
                );
            }
        }
    }

    /// The unit floats are the top 24 (53) bits over 2²⁴ (2⁵³): exact at the ends and halfway,
    /// and one step of the kept bits is one ulp of the result's spacing.
    #[test]
    fn unit_floats_are_the_top_bits_scaled() {
        assert_eq!(unit_f32(0), 0.0);
        assert_eq!(unit_f32(0xff), 0.0);
        assert_eq!(unit_f32(0x100), 1.0 / 16_777_216.0);
        assert_eq!(unit_f32(0x8000_0000), 0.5);
        assert_eq!(unit_f32(u32::MAX), 1.0 - 1.0 / 16_777_216.0);
        assert_eq!(unit_f64(0), 0.0);
        assert_eq!(unit_f64(0x7ff), 0.0);
        assert_eq!(unit_f64(0x800), 1.0 / 9_007_199_254_740_992.0);
        assert_eq!(unit_f64(1 << 63), 0.5);
        assert_eq!(unit_f64(u64::MAX), 1.0 - 1.0 / 9_007_199_254_740_992.0);
    }

    /// `apply(i)` with `i >= n` is `apply(i mod n)`, on the table route (`n ≤ 16`) as on the
    /// keyed one, from `i = n` itself up to `u32::MAX`.
    #[test]
    fn indices_past_n_wrap_on_both_routes() {
        for n in 1..=40u32 {
            for seed in [3u32, 0xffff_fff0] {
                let p = Permutation::new(n, seed);
                for i in [n, n + 1, 2 * n - 1, 5 * n + 2, u32::MAX] {
                    assert_eq!(p.apply(i), p.apply(i % n), "n {n}, seed {seed}, i {i}");
                }
            }
        }
    }

    /// `ArrayOrder` is the documented choice: for `n ≤ 16` the nibble table read from the key,
    /// beyond it the keyed `Permutation` of the key's low half; either way a bijection on `0..n`.
    #[test]
    fn array_order_is_the_table_up_to_16_then_the_keyed_permutation() {
        for n in 1..=40u32 {
            for key in [0u64, 0x0123_4567_89ab_cdef, u64::MAX - 5] {
                let order = ArrayOrder::new(n, key);
                let mut seen = std::vec![false; n as usize];
                for j in 0..n {
                    let want = if n <= 16 {
                        packed_entry(packed_table(n, key), j)
                    } else {
                        Permutation::new(n, key as u32).apply(j)
                    };
                    let to = order.apply(j);
                    assert_eq!(to, want, "n {n}, key {key:#x}, value {j}");
                    assert!(!core::mem::replace(&mut seen[to as usize], true));
                }
            }
        }
    }

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
    fn permutation_size_is_n_and_at_least_one() {
        for n in [1u32, 2, 4, 5, 16, 17, 1000, u32::MAX] {
            assert_eq!(Permutation::new(n, 7).size(), n);
        }
        assert_eq!(Permutation::new(0, 7).size(), 1);
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

    /// Every element's image is uniform over seeds, for the small sizes where the bare keyed
    /// bijection was visibly biased (e.g. π(0) = 0 for 25% of seeds with n = 3): a chi-square
    /// test per element at a false-alarm rate far below 10⁻⁶.
    #[test]
    fn every_image_is_uniform_over_seeds() {
        const SEEDS: u32 = 30_000;
        for n in [2u32, 3, 4, 5, 7, 9, 16, 31] {
            let mut counts = std::vec![0u32; (n * n) as usize];
            for seed in 0..SEEDS {
                let p = Permutation::new(n, seed);
                for i in 0..n {
                    counts[(i * n + p.apply(i)) as usize] += 1;
                }
            }
            for i in 0..n {
                let row = &counts[(i * n) as usize..((i + 1) * n) as usize];
                let chi2 = crate::tests::chi_square_uniform(row);
                // dof = n − 1 ≤ 30; mean n − 1, sd √(2(n−1)); 6 sd above the mean plus slack.
                let df = f64::from(n - 1);
                let limit = df + 6.0 * (2.0 * df).sqrt() + 10.0;
                assert!(
                    chi2 < limit,
                    "n={n}, element {i}: chi2 {chi2:.1} > {limit:.1}"
                );
            }
        }
    }

    /// Every one of the 3! permutations of three elements occurs, none rarer than 1/12.
    #[test]
    fn all_permutations_of_three_occur() {
        let mut counts = std::collections::HashMap::new();
        for seed in 0..12_000u32 {
            let p = Permutation::new(3, seed);
            *counts
                .entry([p.apply(0), p.apply(1), p.apply(2)])
                .or_insert(0u32) += 1;
        }
        assert_eq!(counts.len(), 6, "{counts:?}");
        assert!(counts.values().all(|&c| c > 1000), "{counts:?}");
    }

    /// The compile-time table holds, for each of n = 2, 3, 4, every permutation once, in
    /// lexicographic order, and the small-size draw agrees with Fisher–Yates on the law: both
    /// pick every permutation of four elements about equally often.
    #[test]
    fn small_permutation_table_is_every_permutation_in_order() {
        for n in 2..=SMALL_MAX {
            let perms: std::vec::Vec<std::vec::Vec<u64>> = SMALL_PERMUTATIONS
                [SMALL_START[n]..SMALL_START[n] + FACTORIAL[n] as usize]
                .iter()
                .map(|&t| (0..n).map(|i| (t >> (4 * i)) & 0xf).collect())
                .collect();
            for p in &perms {
                let mut sorted = p.clone();
                sorted.sort_unstable();
                assert_eq!(sorted, (0..n as u64).collect::<std::vec::Vec<_>>(), "{p:?}");
            }
            assert!(perms.windows(2).all(|w| w[0] < w[1]), "n={n}: {perms:?}");
        }
        assert_eq!(
            SMALL_PERMUTATIONS[SMALL_START[3]..8],
            [0x210, 0x120, 0x201, 0x021, 0x102, 0x012]
        );
        let mut counts = std::collections::HashMap::new();
        for seed in 0..24_000u32 {
            *counts
                .entry(Permutation::new(4, seed).table)
                .or_insert(0u32) += 1;
        }
        assert_eq!(counts.len(), 24);
        assert!(
            counts.values().all(|&c| (800..1200).contains(&c)),
            "{counts:?}"
        );
    }

    #[test]
    fn permute_equals_the_reusable_object() {
        for (n, seed) in [(1u32, 3u32), (2, 0), (10, 42), (1000, 7), (u32::MAX, 9)] {
            let p = Permutation::new(n, seed);
            for i in [0u32, 1, 5, 999, u32::MAX] {
                assert_eq!(permute(i, n, seed), p.apply(i));
            }
        }
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
