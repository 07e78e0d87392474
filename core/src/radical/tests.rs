use super::exact::*;
use super::fast::*;
use super::folded::*;
use super::scrambled::*;
use super::tables::*;
use super::*;
use crate::Error;
use crate::math::ONE_MINUS_EPSILON;
use proptest::prelude::*;

#[test]
fn primes_match_a_sieve() {
    let mut sieve = std::vec![true; 8162];
    sieve[0] = false;
    sieve[1] = false;
    for i in 2..sieve.len() {
        if sieve[i] {
            for j in (i * i..sieve.len()).step_by(i) {
                sieve[j] = false;
            }
        }
    }
    let primes: std::vec::Vec<u32> = (0..sieve.len() as u32)
        .filter(|&i| sieve[i as usize])
        .collect();
    assert_eq!(primes.len(), 1024);
    assert_eq!(&primes[..], &PRIMES[..]);
    assert_eq!(prime(0), 2);
    assert_eq!(prime(1023), 8161);
    assert_eq!(prime(1024), 2);
    assert_eq!(prime(u32::MAX), PRIMES[(u32::MAX % 1024) as usize]);
}

#[test]
fn tables_are_consistent() {
    let mut total = 0;
    for (d, info) in BASES.iter().enumerate() {
        let b = u64::from(PRIMES[d]);
        assert_eq!(info.b, b);
        assert!(
            info.big < 1 << 32 && info.big * b >= 1 << 32,
            "k of base {b}"
        );
        // b^(2k) < 2^64: the fixed-point digit extraction is exact.
        assert!(info.big.checked_mul(info.big).is_some());
        assert_eq!(info.off as usize, total);
        total += info.k as usize + 1;
        for n in 1..=info.k {
            let row = (info.off + n) as usize;
            let p = b.pow(n);
            assert_eq!(ROW[row].pow, p);
            assert_eq!(
                u128::from(ROW[row].magic),
                (1u128 << 64).div_ceil(u128::from(p))
            );
        }
        // The fast path's per-class rows: n digits hold every index of the class below b^k.
        let f = &FAST[d];
        assert_eq!((u64::from(f.b), u64::from(f.big)), (b, info.big));
        let c = u64::from(f.chunk);
        assert_eq!(u64::from(f.chunk2), c * c);
        assert_eq!(
            u64::from(f.chunk3),
            if c.pow(3) < 1 << 32 { c.pow(3) } else { 0 }
        );
        // Table chunks: 3⁸ for base 3, the largest b^j ≤ 4096 for 5 ..= 61, b² for 67 ..= 83,
        // none (the base itself) for base 2 and from 89 on.
        let want = match b {
            3 => 6561,
            5..=61 => (1..)
                .map(|j| b.pow(j))
                .take_while(|&p| p <= 4096)
                .last()
                .unwrap(),
            67..=83 => b * b,
            _ => b,
        };
        assert_eq!(u64::from(f.chunk), want, "base {b}");
        // Below MIN_BIG every base past base 2 is on its fast path, and 1627² is the least.
        assert!(d == 0 || info.big >= MIN_BIG, "base {b}");
        assert!(b != 1627 || info.big == MIN_BIG);
        for (c, class) in f.class.iter().enumerate().skip(1) {
            let n = u32::from(class.n);
            assert!(n <= info.k);
            let largest = ((1u64 << (4 * c)) - 1).min(info.big - 1);
            assert!(largest < b.pow(n), "base {b}, class {c}");
            // m steps of j digits cover the n digits with fewer than j to spare (pad), the
            // first step taking the j − pad digits left; the value is R·b^pad / b^(n + pad).
            let (j, m) = (j_of(f), u32::from(class.steps));
            let pad = m * j - n;
            assert!(pad < j, "base {b}, class {c}");
            assert_eq!(u64::from(class.first), b.pow(j - pad));
            // The first two multiplies folded into one (two steps or more).
            let lead = (1u128 << 64).div_ceil(u128::from(b.pow(n))) * u128::from(class.first);
            assert_eq!(u128::from(class.lead), if m >= 2 { lead } else { 0 });
            assert_eq!(class.inv, 1.0 / b.pow(n + pad) as f64);
        }
        for (len, &n) in DIGITS[d].iter().enumerate().skip(1) {
            // DIGITS[d][len] digits hold every chunk of that bit length below b^k.
            let n = u32::from(n);
            let largest = ((1u64 << len) - 1).min(info.big - 1);
            assert!(largest < b.pow(n), "base {b}, len {len}");
            // And no more: exactly the digit count of 2^len − 1, capped at k (the count of
            // big − 1), so a chunk takes at most one zero digit more than it needs.
            let (mut rest, mut count) = (largest, 0);
            while rest > 0 {
                rest /= b;
                count += 1;
            }
            assert_eq!(n, count, "base {b}, len {len}");
        }
    }
    assert_eq!(total, ROWS);
}

#[test]
fn van_der_corput_table_is_exact() {
    let expected = [
        0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875, 0.0625, 0.5625, 0.3125, 0.8125, 0.1875,
        0.6875, 0.4375, 0.9375,
    ];
    for (a, &e) in expected.iter().enumerate() {
        assert_eq!(radical_inverse(0, a as u64), e as f32);
        assert_eq!(radical_inverse_f64(0, a as u64), e);
    }
}

#[test]
fn base_two_equals_reverse_bits_times_two_pow_minus_32_for_every_a_below_2_16() {
    for a in 0..1u64 << 16 {
        let expected = ((a as u32).reverse_bits() as f64 * crate::math::TWO_POW_MINUS_32) as f32;
        assert_eq!(
            radical_inverse(0, a),
            expected.min(ONE_MINUS_EPSILON),
            "a={a}"
        );
        assert_eq!(
            radical_inverse_f64(0, a),
            (a as u32).reverse_bits() as f64 * crate::math::TWO_POW_MINUS_32
        );
    }
    // Large indices: the top bits of the 64-bit reversal.
    assert_eq!(radical_inverse_f64(0, 1 << 63), 2f64.powi(-64));
    assert_eq!(radical_inverse(0, u64::MAX), ONE_MINUS_EPSILON);
}

#[test]
fn base_three_and_five_known_values() {
    // 1 → 1/3, 2 → 2/3, 3 = 10₃ → 1/9, 4 = 11₃ → 4/9, 5 = 12₃ → 7/9.
    let thirds = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0 / 9.0, 4.0 / 9.0, 7.0 / 9.0];
    for (a, &e) in thirds.iter().enumerate() {
        assert_eq!(radical_inverse_f64(1, a as u64), e);
        assert_eq!(radical_inverse(1, a as u64), e as f32);
    }
    assert_eq!(radical_inverse_f64(2, 6), 6.0 / 25.0);
    // dims wrap modulo 1024
    assert_eq!(radical_inverse(1025, 5), radical_inverse(1, 5));
}

#[test]
fn folded_base_two_matches_published_values() {
    let expected = [
        1.0 / 3.0,
        5.0 / 6.0,
        1.0 / 12.0,
        7.0 / 12.0,
        11.0 / 24.0,
        23.0 / 24.0,
        5.0 / 24.0,
        17.0 / 24.0,
    ];
    for (a, &e) in expected.iter().enumerate() {
        let f = folded_radical_inverse_f64(0, a as u64);
        assert!((f - e).abs() <= e * f64::EPSILON, "Ψ₂({a}) = {f}, want {e}");
        let f = folded_radical_inverse(0, a as u64);
        assert!(
            (f - e as f32).abs() <= e as f32 * f32::EPSILON,
            "Ψ₂({a}) = {f}, want {e}"
        );
    }
}

#[test]
fn folded_tail_closed_form_matches_direct_sum() {
    // Compare the 128-bit tail with a direct f64 sum for a few large bases and every r.
    for d in [9usize, 10, 50, 500, 1023] {
        let b = BASES[d].b;
        for r in (0..b)
            .step_by((b as usize / 40).max(1))
            .chain([b - 1, b - 2])
        {
            let mut sum = 0.0f64;
            let mut w = 1.0 / b as f64;
            for i in 0..40 {
                sum += ((r + i) % b) as f64 * w;
                w /= b as f64;
            }
            let t = fold_tail(d, b, r) as f64 / 2f64.powi(128);
            assert!((t - sum).abs() < 1e-15, "b={b} r={r}: {t} vs {sum}");
        }
    }
}

/// `T_b(r)·2²⁵⁶`, truncated, as four 64-bit limbs (most significant first): Horner over the
/// digits `(r + i) mod b` from 400 digits out, each step `v ← (c·2²⁵⁶ + v)/b` by schoolbook
/// division of the limbs. Twice [`fold_tail`]'s precision, by another route than either of its
/// two (the const table's 128-bit Horner, the closed form): the digits cut off weigh less than
/// 2⁻⁴⁰⁰ and each step's truncation less than 2⁻²⁵⁶, so the result is within 2 of `T·2²⁵⁶`.
fn fold_tail_256(b: u64, r: u64) -> [u64; 4] {
    let mut v = [0u64; 4];
    for i in (0..400u64).rev() {
        // c < b, so the leading limb of c·2²⁵⁶ + v divides to 0 with remainder c.
        let mut rem = u128::from((r + i) % b);
        for limb in v.iter_mut() {
            let cur = (rem << 64) | u128::from(*limb);
            *limb = (cur / u128::from(b)) as u64;
            rem = cur % u128::from(b);
        }
    }
    v
}

/// `fold_tail` is documented within 2⁻¹²⁶ of `T_b(r)`: within 4 units of 2⁻¹²⁸ of the
/// double-precision oracle's top half, for every base (table and closed form) and, per base,
/// every `r` up to 64 and the ends and middle of the range (the largest error found is 2 units).
/// A tail that lost low bits (a step of the fixed-point division, the closed form's second term)
/// is far outside the bound.
#[test]
fn fold_tails_are_within_their_bound_of_a_double_precision_oracle() {
    let mut worst = 0u128;
    for d in 0..PRIME_COUNT as usize {
        let b = BASES[d].b;
        let ends = [
            b / 3,
            b / 2,
            b.saturating_sub(3),
            b.saturating_sub(2),
            b - 1,
        ];
        for r in (0..b.min(64)).chain(ends) {
            let v = fold_tail_256(b, r);
            let exact = (u128::from(v[0]) << 64) | u128::from(v[1]);
            let got = fold_tail(d, b, r);
            let err = got.abs_diff(exact);
            worst = worst.max(err);
            assert!(err <= 4, "base {b} r {r}: {got:#x} against {exact:#x}");
        }
    }
    std::println!("largest fold-tail error: {worst} units of 2^-128");
}

#[test]
fn inverse_radical_inverse_round_trips() {
    let mut r = crate::rng::default_rng(5);
    for dim in [0u32, 1, 2, 3, 63, 1023] {
        let b = u64::from(prime(dim));
        for _ in 0..200 {
            let a = rand_core::Rng::next_u64(&mut r) >> 40;
            let n = {
                let mut n = 0;
                let mut x = a;
                while x > 0 {
                    x /= b;
                    n += 1;
                }
                n
            };
            // Reverse a's digits as an integer, then undo it.
            let mut rev = 0u64;
            let mut x = a;
            for _ in 0..n {
                rev = rev * b + x % b;
                x /= b;
            }
            assert_eq!(inverse_radical_inverse(dim, rev, n), a);
            if n > 0 {
                assert_eq!(
                    radical_inverse_f64(dim, a),
                    rev as f64 / (b as f64).powi(n as i32)
                );
            }
        }
    }
    // Wrapping past 64 bits: 1 reversed over 70 binary digits is 2^69, which wraps to 0;
    // u64::MAX over 70 digits is (2^64 − 1)·2^6 modulo 2^64.
    assert_eq!(inverse_radical_inverse(0, 1, 70), 0);
    assert_eq!(inverse_radical_inverse(0, u64::MAX, 70), u64::MAX << 6);
    // A huge digit count is cheap and wraps like the digit loop would.
    let b = u64::from(prime(1023));
    let x = inverse_radical_inverse(1023, 12_345, 40);
    assert_eq!(inverse_radical_inverse(1023, 12_345, 41), x.wrapping_mul(b));
    assert_eq!(
        inverse_radical_inverse(1023, 12_345, u32::MAX),
        x.wrapping_mul(b.wrapping_pow(u32::MAX - 40))
    );
}

#[test]
fn scrambled_first_digit_strata_are_hit_uniformly_over_seeds() {
    // For a fixed index, over many seeds the first digit π(a_0) is uniform on 0..b.
    for dim in [1u32, 2, 3] {
        let b = prime(dim) as usize;
        let mut counts = std::vec![0u32; b];
        let seeds = 3000u64;
        for seed in 0..seeds {
            let x = scrambled_radical_inverse(dim, 12, seed);
            counts[(x * b as f32) as usize] += 1;
        }
        let expect = seeds as f64 / b as f64;
        for &c in &counts {
            assert!(
                (f64::from(c) - expect).abs() < 5.0 * expect.sqrt(),
                "{counts:?}"
            );
        }
    }
}

#[test]
fn scrambled_points_keep_their_stratification() {
    // The first b^k points of each seed fall one per stratum of width b^−k, strictly inside it:
    // point a is (m + t)·b^−k with m its permuted digits and t = π(0)/(b−1) the common tail
    // (t = 1 would put it on the next stratum's edge; the result is then just below it).
    for (dim, k) in [(0u32, 10u32), (1, 6), (2, 4), (5, 2), (40, 1)] {
        let b = u64::from(prime(dim));
        let n = b.pow(k);
        for seed in [0u64, 1, 2, 3, 99, u64::MAX] {
            let t = f64::from(digit_permutation(seed, b).apply(0)) / (b - 1) as f64;
            let mut seen = std::vec![false; n as usize];
            for a in 0..n {
                let x = scrambled_radical_inverse_f64(dim, a, seed);
                let m = x * n as f64 - t;
                let s = m.round() as usize;
                assert!(
                    (m - s as f64).abs() < 1e-6 && s < n as usize,
                    "dim {dim}: {m}"
                );
                assert!(!seen[s], "dim {dim} seed {seed}: stratum {s} twice");
                seen[s] = true;
            }
        }
    }
}

#[test]
fn scrambled_depends_on_seed() {
    let a: std::vec::Vec<f32> = (0..32)
        .map(|i| scrambled_radical_inverse(3, i, 1))
        .collect();
    let b: std::vec::Vec<f32> = (0..32)
        .map(|i| scrambled_radical_inverse(3, i, 2))
        .collect();
    assert_ne!(a, b);
}

#[test]
fn multi_chunk_indices_are_continuous_with_single_chunk_ones() {
    // Φ(a + B) for a < B and B the chunk modulus: digit k is 1, so Φ(a + B) = Φ(a) + b^−(k+1).
    for d in [1usize, 2, 63, 1023] {
        let info = BASES[d];
        for a in [0u64, 1, 12345 % info.big, info.big - 1] {
            let x = radical_inverse_f64(d as u32, a + info.big);
            let full = radical_inverse_f64(d as u32, a);
            // full is Φ over a's own digits; padded to k digits the value is unchanged.
            let expect = full + (info.big as f64 * info.b as f64).recip();
            assert!(
                (x - expect).abs() <= 2.0 * f64::EPSILON * expect,
                "d={d} a={a}"
            );
        }
    }
}

#[test]
fn every_arm_equals_the_step_loop_in_every_base_and_class() {
    // The straight-line arms (weights c², c³ from the header) against the loop (weights by
    // repeated multiplication), bit for bit, at each class's smallest, largest and three random
    // indices below the base's limit; the limit compared exactly in the classes some index of
    // which reaches it, and there the value at the class's largest indices equal to the typed
    // path's (which always compares); every arm some class's.
    let mut r = crate::rng::default_rng(0x5eed_a4a5);
    let mut seen = [false; Arm::General as usize + 1];
    for (d, f) in FAST.iter().enumerate() {
        for (c, k) in f.class.iter().enumerate() {
            seen[usize::from(k.arm)] = true;
            if d == 0 || c == 0 {
                continue;
            }
            let last = c == CLASSES - 1;
            let top = if last {
                u64::MAX
            } else {
                (1u64 << (4 * c)) - 1
            };
            let reaches = top >= u64::from(f.big);
            assert_eq!(
                k.arm == Arm::Limit as u8,
                reaches,
                "base {}, class {c}",
                f.b
            );
            for a in [top, (1u64 << (4 * c)) - 1] {
                let want = radical_inverse_inlined(d as u32, a);
                assert_eq!(phi_class(f, c, a, d).to_bits(), want.to_bits(), "{a}");
            }
            let lo = 1u64 << (4 * c - 4);
            let hi = ((1u64 << (4 * c)) - 1).min(u64::from(f.big) - 1);
            if lo > hi {
                continue;
            }
            let mut indices = [lo, hi, 0, 0, 0];
            for a in &mut indices[2..] {
                *a = lo + crate::rng::uniform_below(&mut r, (hi - lo + 1) as u32) as u64;
            }
            for a in indices {
                let want = if f.chunk == f.b {
                    phi_any_steps::<false>(f, k, a)
                } else {
                    phi_any_steps::<true>(f, k, a)
                };
                let got = phi_class(f, c, a, d);
                assert_eq!(
                    got.to_bits(),
                    want.to_bits(),
                    "base {}, class {c}, index {a}",
                    f.b
                );
                assert_eq!(got, radical_inverse(d as u32, a));
            }
        }
        // Class 0 is the index 0, whose value is 0 in every base.
        assert_eq!(phi_class(f, 0, 0, d), 0.0);
    }
    assert!(seen.iter().all(|&s| s), "an arm no class takes: {seen:?}");
}

/// Digits per table chunk of a fast-path base (1 without a table).
fn j_of(f: &FastBase) -> u32 {
    let (mut j, mut p) = (0, 1u32);
    while p < f.chunk {
        p *= f.b;
        j += 1;
    }
    j
}

proptest! {
    #[test]
    fn every_form_is_in_unit_interval(dim in any::<u32>(), a in any::<u64>(), seed in any::<u64>()) {
        for x in [
            radical_inverse(dim, a),
            folded_radical_inverse(dim, a),
            scrambled_radical_inverse(dim, a, seed),
        ] {
            prop_assert!((0.0..1.0).contains(&x));
        }
        for x in [
            radical_inverse_f64(dim, a),
            folded_radical_inverse_f64(dim, a),
            scrambled_radical_inverse_f64(dim, a, seed),
        ] {
            prop_assert!((0.0..1.0).contains(&x));
        }
    }

    #[test]
    fn f32_is_the_f64_value_to_within_one_f32_ulp(dim in any::<u32>(), a in any::<u64>()) {
        let f = radical_inverse(dim, a);
        let g = radical_inverse_f64(dim, a);
        prop_assert!((f64::from(f) - g).abs() <= f64::from(f32::EPSILON) * g.max(1e-30));
    }
}

#[test]
fn pair_split_is_exact_for_every_pair_of_small_bases_and_sampled_large_ones() {
    for (d, info) in BASES.iter().enumerate() {
        let b = info.b;
        let step = if d < 64 { 1 } else { (b * b / 5000).max(1) };
        for pair in (0..b * b).step_by(step as usize).chain([b * b - 1]) {
            assert_eq!((pair * info.split) >> 40, pair / b, "b={b} D={pair}");
        }
    }
}

/// The incremental fill equals random access bit for bit, across byte-class boundaries, the
/// fast-path limit `b^k`, and the `u64` wrap.
#[test]
fn fill_matches_random_access_across_boundaries() {
    let mut buf = [0.0f32; 600];
    for dim in [0u32, 1, 2, 5, 31, 63, 200, 1023, 1024 + 7] {
        let big = BASES[(dim % PRIME_COUNT) as usize].big;
        for first in [
            0u64,
            200,
            65_300,
            (1 << 24) - 300,
            (1 << 32) - 300,
            big - 300,
            u64::MAX - 299,
        ] {
            fill_radical_inverse(dim, first, &mut buf);
            for (i, &x) in buf.iter().enumerate() {
                let a = first.wrapping_add(i as u64);
                assert_eq!(
                    x.to_bits(),
                    radical_inverse(dim, a).to_bits(),
                    "dim {dim}, index {a}"
                );
            }
        }
    }
}

/// The strided fill (one dimension of interleaved points, as Halton's point sets write them):
/// slot `offset + i·stride` holds index `first + i`, every other slot is left alone, for strides
/// 0 (taken as 1) to 5, every offset, and starts at the same boundaries as above, including a
/// base-2 run that ends exactly at 2³² (the last index its vectorised route can take).
#[test]
fn strided_fill_writes_its_slots_only() {
    const UNTOUCHED: f32 = -1.0;
    let mut buf = [UNTOUCHED; 160];
    for dim in [0u32, 1, 2, 5, 63, 200, 1023] {
        let big = BASES[(dim % PRIME_COUNT) as usize].big;
        for stride in 0..=5usize {
            for offset in 0..stride.max(1) + 1 {
                for first in [
                    0u64,
                    77,
                    (1 << 16) - 9,
                    (1 << 32) - 30,
                    (1 << 32) - (160 - offset as u64).div_ceil(stride.max(1) as u64),
                    big - 20,
                    u64::MAX - 9,
                ] {
                    buf.fill(UNTOUCHED);
                    fill_consecutive(dim, first, &mut buf, offset, stride);
                    let step = stride.max(1);
                    for (k, &x) in buf.iter().enumerate() {
                        let want = if k >= offset && (k - offset) % step == 0 {
                            let a = first.wrapping_add(((k - offset) / step) as u64);
                            radical_inverse(dim, a)
                        } else {
                            UNTOUCHED
                        };
                        assert_eq!(
                            x.to_bits(),
                            want.to_bits(),
                            "dim {dim} stride {stride} offset {offset} first {first} slot {k}"
                        );
                    }
                }
            }
        }
    }
}

proptest! {
    #[test]
    fn fill_matches_random_access(dim in 0u32..1024, first in any::<u32>(), len in 1usize..300) {
        let mut buf = std::vec![0.0f32; len];
        fill_radical_inverse(dim, u64::from(first), &mut buf);
        for (i, &x) in buf.iter().enumerate() {
            prop_assert_eq!(x.to_bits(), radical_inverse(dim, u64::from(first) + i as u64).to_bits());
        }
    }
}

proptest! {
    #[test]
    fn batch_matches_random_access(
        dim in 0u32..2048,
        indices in proptest::collection::vec(
            prop_oneof![0u64..10_000_000, any::<u32>().prop_map(u64::from), any::<u64>()],
            0..200,
        ),
        extra in 0usize..3,
    ) {
        let mut out = std::vec![-1.0f32; indices.len() + extra];
        radical_inverse_at(dim, &indices, &mut out).unwrap();
        for (i, &a) in indices.iter().enumerate() {
            prop_assert_eq!(out[i].to_bits(), radical_inverse(dim, a).to_bits());
        }
        // Entries past the indices are untouched.
        prop_assert!(out[indices.len()..].iter().all(|&x| x == -1.0));
    }
}

#[test]
fn batch_base2_mixes_32_bit_and_wide_blocks() {
    // 64-index blocks: all below 2³² (the vectorised path), then one with a wide index.
    let mut indices: std::vec::Vec<u64> =
        (0..200u64).map(|i| crate::hash::mix64(i) >> 32).collect();
    indices[130] = u64::MAX;
    indices[131] = 1 << 32;
    let mut out = std::vec![0.0f32; 200];
    radical_inverse_at(0, &indices, &mut out).unwrap();
    for (&a, &x) in indices.iter().zip(&out) {
        assert_eq!(x.to_bits(), radical_inverse(0, a).to_bits());
    }
    assert_eq!(out[131], 2.0f32.powi(-33));
    assert_eq!(
        radical_inverse_at(0, &indices, &mut [0.0; 199]),
        Err(Error::BufferTooShort {
            needed: 200,
            actual: 199
        })
    );
}

/// `radical_inverse_dims` against `radical_inverse` value by value, bit for bit: every index
/// class (its first and last index), runs inside the table bases (the per-class lanes), runs
/// that end at the last table base or one past it, runs past them, runs through base 2 and the
/// wrap, and indices past `MIN_BIG` and 2³².
#[test]
fn dims_equal_single_values_in_every_class_and_lane() {
    let mut indices = std::vec![0u64, 1, MIN_BIG - 1, MIN_BIG, u64::from(u32::MAX) + 7];
    for c in 1..=8u32 {
        indices.extend([1u64 << (4 * c - 4), (1u64 << (4 * c)) - 1]);
    }
    let mut out = [0.0f32; 40];
    for &a in &indices {
        for first in [1u32, 2, 5, 13, TABLE_DIMS as u32 - 3, 30, 1000, 1023] {
            // Runs that end at the last base with a digit-reversal table and one past it.
            let ends = match TABLE_DIMS.checked_sub(first as usize) {
                Some(len) if len > 0 => [len, len + 1],
                _ => [1, 1],
            };
            for len in [1usize, 3, 16, 40].into_iter().chain(ends) {
                radical_inverse_dims(first, a, &mut out[..len]);
                for (i, x) in out[..len].iter().enumerate() {
                    let want = radical_inverse(first + i as u32, a);
                    assert_eq!(x.to_bits(), want.to_bits(), "index {a} dim {first}+{i}");
                }
            }
        }
    }
}

proptest! {
    #[test]
    fn dims_equal_single_values(dim in prop_oneof![0u32..40, 0u32..1100], a in any::<u64>(), shift in 0u32..64, len in 0usize..40) {
        let a = a >> shift;
        let mut out = [0.0f32; 40];
        radical_inverse_dims(dim, a, &mut out[..len]);
        for (i, x) in out[..len].iter().enumerate() {
            prop_assert_eq!(x.to_bits(), radical_inverse(dim + i as u32, a).to_bits());
        }
    }
}

/// `num / den` (`0 < num < den < 2⁶⁴`, `num / den ≥ 2⁻⁸`) rounded to nearest, ties to even, with
/// `bits` significant bits, by one u128 division: an oracle independent of `long_divide`.
fn rounded_ratio(num: u64, den: u64, bits: u32) -> f64 {
    let q = (u128::from(num) << 64) / u128::from(den);
    let sticky = (u128::from(num) << 64) % u128::from(den) != 0;
    let len = 128 - q.leading_zeros(); // at least 56 bits, since num / den ≥ 2⁻⁸
    let drop = len - bits;
    let (mut m, rest) = (q >> drop, q & ((1u128 << drop) - 1));
    let half = 1u128 << (drop - 1);
    if rest > half || (rest == half && (sticky || m & 1 == 1)) {
        m += 1;
    }
    // m < 2^(bits + 1): exact in f64; the power of two is exact too.
    m as f64 * 2f64.powi(drop as i32 - 64)
}

/// `ratio_f32` and `ratio_f64` (Hammersley's first coordinate for n ≥ 2⁵², where `(k + ½)/n`
/// has no exact `f64` operands) are correctly rounded and clamped below 1, against the oracle
/// above: random fractions, ones just below 1, and halfway cases.
#[test]
fn ratios_are_correctly_rounded() {
    let mut rng = crate::rng::default_rng(77);
    let mut cases: std::vec::Vec<(u64, u64)> = (0..2000)
        .map(|_| {
            let den = (rng.next_u64() >> 1) | (1 << 62);
            let num = den - 1 - rng.next_u64() % (den - den / 256);
            (num, den)
        })
        .collect();
    // Just below 1; exactly halfway between two f64 (f32) values above ½ (ties to even), and a
    // third of an ulp of the division's remainder above and below that (the sticky bit decides).
    cases.push((u64::MAX - 1, u64::MAX));
    for bits in [53u32, 24] {
        let tie = (1u64 << bits) + 1; // / 2^(bits + 1): ½ + half an ulp
        let den = 1u64 << (bits + 1);
        cases.extend([
            (tie, den),
            (tie + 2, den),
            (3 * tie + 1, 3 * den),
            (3 * tie - 1, 3 * den),
        ]);
    }
    for (num, den) in cases {
        // Clamped below 1, as the ratios are documented to be.
        let want64 = rounded_ratio(num, den, 53).min(crate::math::ONE_MINUS_EPSILON_F64);
        let want32 = rounded_ratio(num, den, 24).min(f64::from(crate::math::ONE_MINUS_EPSILON));
        assert_eq!(ratio_f64(num.into(), den.into()), want64, "{num}/{den}");
        assert_eq!(
            f64::from(ratio_f32(num.into(), den.into())),
            want32,
            "{num}/{den}"
        );
    }
}

/// `num / den` rounded by `ratio_f64` (`f64`) or `ratio_f32` (`f32`, widened exactly).
fn ratio_in(f64_format: bool, num: u128, den: u128) -> f64 {
    if f64_format {
        ratio_f64(num, den)
    } else {
        f64::from(ratio_f32(num, den))
    }
}

/// Halfway cases with denominators past the `u64` oracle above: `(2t + 1)/2^(bits + 2)` (with
/// `2^bits ≤ t < 2^(bits + 1)`) lies exactly halfway between two floats of `bits + 1` significant
/// bits above ½, and `((2t + 1)·k ± 1) / (2^(bits + 2)·k)` lies `1/den` above or below it, with
/// `den` up to 2⁹⁴ (`ratio_*` take up to 2⁹⁶). Expected values by construction: up above, down
/// below, to even at the tie.
#[test]
fn ratios_round_ties_with_wide_denominators() {
    for bits in [52u32, 23] {
        let scale = 2f64.powi(-(bits as i32 + 1));
        for t in [
            1u64 << bits,
            (1 << bits) + 2,
            (1 << bits) + 3,
            (2 << bits) - 2,
        ] {
            // The two neighbours of the tie, t/2^(bits+1) and (t+1)/2^(bits+1).
            let (low, high) = (t as f64 * scale, (t + 1) as f64 * scale);
            let even = if t.is_multiple_of(2) { low } else { high };
            for k in [3u128, (1 << 20) + 1, (1 << 40) - 3] {
                let den = (1u128 << (bits + 2)) * k;
                let tie = u128::from(2 * t + 1) * k;
                for (num, want) in [(tie - 1, low), (tie, even), (tie + 1, high)] {
                    let got = ratio_in(bits >= 52, num, den);
                    assert_eq!(got, want, "bits {bits} t {t} k {k} num {num}");
                }
            }
        }
    }
}

/// Ties that only the division's remainder breaks: `num/den = T/2^(bits+1) + 2^−(bits+1)/den`
/// with `T` odd (halfway between two floats of `bits` significant bits above ½) and `den`
/// between 2⁷¹ and 2⁷², so the excess lies below 2⁻⁹⁶, past every quotient bit `long_divide`
/// keeps. `T ≡ −den⁻¹ (mod 2^(bits+1))` makes `num` an integer. The exact value is above the tie,
/// so it rounds up, away from even for half the cases.
#[test]
fn ratios_round_up_ties_hidden_past_the_kept_quotient_bits() {
    let mut rng = crate::rng::default_rng(2024);
    let (mut up_from_odd, mut up_from_even) = (0, 0);
    for bits in [53u32, 24] {
        let modulus = 1u128 << (bits + 1);
        let mut cases = 0;
        while cases < 200 {
            let den =
                u128::from(rng.next_u64()) << 8 | u128::from(rng.next_u64() & 0xff) | 1 << 71 | 1;
            // den⁻¹ mod 2^64 by Newton's iteration (den odd), then T = −den⁻¹ mod 2^(bits+1).
            let d = den as u64;
            let mut inv = d;
            for _ in 0..6 {
                inv = inv.wrapping_mul(2u64.wrapping_sub(d.wrapping_mul(inv)));
            }
            let t = (modulus - u128::from(inv) % modulus) % modulus;
            if t < modulus / 2 {
                continue; // below ½: another exponent; draw again
            }
            let num = (t * den + 1) / modulus;
            assert_eq!(num * modulus, t * den + 1);
            let up = (t + 1) as f64 / modulus as f64;
            if (t >> 1).is_multiple_of(2) {
                up_from_even += 1;
            } else {
                up_from_odd += 1;
            }
            let got = ratio_in(bits >= 52, num, den);
            assert_eq!(got, up, "bits {bits} den {den} t {t}");
            cases += 1;
        }
    }
    // Both parities of the lower neighbour occurred: to-even would have gone down for one.
    assert!(up_from_even > 0 && up_from_odd > 0);
}

/// Ties that only the quotient bits past the 64-bit mantissa break: with `den = 2^k` the
/// division is exact (no remainder to set the sticky bit) and `long_divide` keeps `k − 64`
/// quotient bits below the mantissa, which must be folded into its sticky bit. `M·2^(k−64)` with
/// `M = 2⁶³ + 2^(63 − bits)` is halfway between two floats of `bits` significant bits above ½;
/// one more unit (a bit far below the mantissa) rounds it up, one less down, and a set lowest
/// mantissa bit plus that unit is above the tie too (the sticky bit is or-ed in, not flipped).
#[test]
fn ratios_round_ties_broken_below_the_mantissa() {
    for bits in [53u32, 24] {
        let tie = (1u128 << 63) + (1 << (63 - bits));
        let (low, high) = (0.5, 0.5 + 2f64.powi(-(bits as i32)));
        for k in [70u32, 90, 95] {
            let den = 1u128 << k;
            let at = tie << (k - 64);
            let lowest = 1u128 << (k - 64); // the mantissa's lowest bit
            for (num, want) in [
                (at - 1, low),
                (at, low), // to even
                (at + 1, high),
                (at + lowest + 1, high),
            ] {
                let got = ratio_in(bits >= 52, num, den);
                assert_eq!(got, want, "bits {bits} k {k} num {num:#x}");
            }
        }
    }
}

/// `inexact` says the true value lies above `num/den` (the folded inverse passes a truncated
/// tail): an exact tie then rounds up, not to even, and the mantissa's sticky bit is set even
/// when the division leaves no remainder.
#[test]
fn inexact_quotients_round_ties_up() {
    for (bits, f64_format) in [(24u32, false), (53, true)] {
        // ½ + 2^−(bits+1): halfway between ½ and the float above it.
        let (num, den) = ((1u128 << bits) + 1, 1u128 << (bits + 1));
        let up = 0.5 + 2f64.powi(-(bits as i32));
        let round = |inexact: bool| {
            if f64_format {
                fraction_f64(num, den, 0, inexact)
            } else {
                f64::from(fraction_f32(num, den, 0, inexact))
            }
        };
        assert_eq!(round(false), 0.5, "bits {bits}: an exact tie goes to even");
        assert_eq!(round(true), up, "bits {bits}: above the tie");
    }
    // ½ divides exactly: only `inexact` sets the sticky bit.
    assert_eq!(long_divide(1, 2, 0, false).0 & 1, 0);
    assert_eq!(long_divide(1, 2, 0, true).0 & 1, 1);
}

/// A zero quotient is 0 at every denominator (the division stops at its word bound, since no
/// number of quotient words reaches a leading bit).
#[test]
fn zero_quotients_are_zero() {
    for den in [1u128, 3, 1 << 40, (1 << 95) + 7] {
        assert_eq!(ratio_f32(0, den), 0.0);
        assert_eq!(ratio_f64(0, den), 0.0);
        assert_eq!(long_divide(0, den, 0, false).0, 0);
    }
}

/// Base 2 past 2³²: Φ₂(a) = ½ + 2⁻²⁵ (halfway between two `f32`s) plus the bits of `a` above 2³²,
/// each far below `f32`'s rounding step. Any of them makes the value round up; the 64-bit path
/// halves the reversal and folds the bit it drops (`a`'s bit 63) into the lowest kept one (bit
/// 62), so both set must still round up. The same for `radical_inverse_f64` at its own tie.
#[test]
fn base2_ties_are_broken_by_the_high_index_bits() {
    let tie = 1u64 | 1 << 24;
    let up = 0.5 + 2f32.powi(-24);
    for high in [1u64 << 62, 1 << 63, 3 << 62, 1 << 32, 1 << 40 | 1 << 63] {
        assert_eq!(radical_inverse(0, tie | high), up, "{:#x}", tie | high);
    }
    assert_eq!(radical_inverse(0, tie), 0.5); // the tie itself: to even
    // The same in f64, which keeps 53 bits: Φ₂(a) = ½ + 2⁻⁵⁴ is its tie. With bits 62 and 63
    // both set, the bit folded in (63) lands on a set bit (62): or-ed, not flipped.
    let tie = 1u64 | 1 << 53;
    let up = 0.5 + 2f64.powi(-53);
    for high in [1u64 << 62, 1 << 63, 3 << 62] {
        assert_eq!(radical_inverse_f64(0, tie | high), up, "{:#x}", tie | high);
    }
    assert_eq!(radical_inverse_f64(0, tie), 0.5);
}

/// The batch and run forms agree with `radical_inverse` at the edges of their fast paths: each
/// base's limit `b^k` and its neighbours, and for base 2 whole batches of indices whose low 32
/// bits are all zero (their values are not the 32-bit reversal of those bits).
#[test]
fn batch_and_run_forms_agree_at_the_fast_path_edges() {
    let mut out = [0.0f32; 64];
    // 253 ..= 257: runs that reach base 1627 (dimension 257), whose limit 1627² is MIN_BIG.
    for d in (0..1024u32)
        .step_by(7)
        .chain([1, 2, 3, 253, 254, 255, 256, 257, 1022, 1023])
    {
        let big = if d == 0 {
            1u64 << 32
        } else {
            BASES[d as usize].big
        };
        let idx = [
            big - 2,
            big - 1,
            big,
            big + 1,
            2 * big,
            0,
            1,
            MIN_BIG - 1,
            MIN_BIG,
        ];
        radical_inverse_at(d, &idx, &mut out).unwrap();
        for (k, &a) in idx.iter().enumerate() {
            assert_eq!(out[k], radical_inverse(d, a), "at: dim {d} index {a}");
            let mut run = [0.0f32; 5];
            radical_inverse_dims(d, a, &mut run);
            for (j, &v) in run.iter().enumerate() {
                let dj = (d + j as u32) % 1024;
                assert_eq!(v, radical_inverse(dj, a), "dims: dim {dj} index {a}");
            }
        }
    }
    let high: std::vec::Vec<u64> = (1..=64u64).map(|k| k << 32).collect();
    radical_inverse_at(0, &high, &mut out).unwrap();
    for (k, &a) in high.iter().enumerate() {
        assert_eq!(out[k], radical_inverse(0, a), "base 2, index {a}");
        assert!(out[k] > 0.0);
    }
}

/// The column writer against the value-by-value function, bit for bit: carries through every
/// digit, the switch to more digits, the stride, and the indices past 2⁵³/b where it falls
/// back to the one-by-one path.
fn column_matches(dim: u32, first: u64, count: usize, seed: u64, stride: usize) {
    let mut out = std::vec![f64::NAN; count * stride];
    let written = scrambled_radical_inverse_column_f64(dim, first, seed, &mut out, stride);
    assert_eq!(written, Ok(count as u64));
    for (k, chunk) in out.chunks(stride).enumerate() {
        let want = scrambled_radical_inverse_f64(dim, first + k as u64, seed);
        assert_eq!(
            chunk[0].to_bits(),
            want.to_bits(),
            "dim {dim} first {first} k {k}"
        );
        assert!(
            chunk[1..].iter().all(|x| x.is_nan()),
            "stride {stride} wrote between"
        );
    }
}

#[test]
fn columns_cross_every_carry_and_the_exactness_limit() {
    // Base 2 (dim 0) from 0 through 2^12, base 3 across 3^7, base 8161 (dim 1023) across
    // one carry, and indices where (b−1)·b^K reaches 2^53.
    column_matches(0, 0, 4097, 5, 1);
    column_matches(1, 3u64.pow(7) - 40, 100, 6, 3);
    column_matches(1023, 8161 * 3 - 5, 20, 7, 2);
    column_matches(0, (1 << 52) - 10, 20, 8, 1);
    column_matches(5, u64::MAX - 9, 10, 9, 1);
    // Seeds that put π(0) = b − 1 (the stratum-edge rule) in base 2 and 3.
    for seed in 0..40 {
        column_matches(0, 0, 9, seed, 1);
        column_matches(1, 0, 30, seed, 2);
    }
}

#[test]
fn columns_refuse_a_zero_stride_and_an_overflowing_index() {
    let mut out = [0.0; 4];
    assert_eq!(
        scrambled_radical_inverse_column_f64(0, 0, 1, &mut out, 0),
        Err(Error::ZeroSize { what: "stride" })
    );
    assert_eq!(
        scrambled_radical_inverse_column_f64(0, u64::MAX - 2, 1, &mut out, 1),
        Err(Error::TooMany {
            what: "first",
            value: u64::MAX - 2,
            max: u64::MAX - 3
        })
    );
    assert_eq!(
        scrambled_radical_inverse_column_f64(0, 5, 1, &mut [], 3),
        Ok(0)
    );
    // A partial last stride still holds a value: 5 slots at stride 2 are 3 values.
    assert_eq!(
        scrambled_radical_inverse_column_f64(0, 0, 1, &mut [0.0; 5], 2),
        Ok(3)
    );
}

proptest! {
    #[test]
    fn columns_equal_the_values_one_by_one(
        dim in 0u32..1100,
        first in prop_oneof![0u64..100_000, any::<u64>().prop_map(|a| a >> 20)],
        count in 1usize..300,
        seed in any::<u64>(),
        stride in 1usize..5,
    ) {
        column_matches(dim, first, count, seed, stride);
    }
}

fn positional_column_matches(dim: u32, first: u64, count: usize, seed: u64, stride: usize) {
    let mut out = std::vec![f64::NAN; count * stride];
    let written = positional_radical_inverse_column_f64(dim, first, seed, &mut out, stride);
    assert_eq!(written, Ok(count as u64));
    for (k, chunk) in out.chunks(stride).enumerate() {
        let want = positional_radical_inverse_f64(dim, first + k as u64, seed);
        assert_eq!(
            chunk[0].to_bits(),
            want.to_bits(),
            "dim {dim} first {first} k {k}"
        );
        assert!((0.0..1.0).contains(&want));
        assert!(
            chunk[1..].iter().all(|x| x.is_nan()),
            "stride {stride} wrote between"
        );
    }
}

#[test]
fn positional_columns_cross_carries_and_wrap_after_k_digits() {
    positional_column_matches(0, 0, 4097, 5, 1);
    positional_column_matches(1, 3u64.pow(7) - 40, 100, 6, 3);
    positional_column_matches(1023, 8161 * 8161 - 5, 20, 7, 2);
    // Base 2 keeps 53 digits: index 2^53 wraps to the value of index 0.
    positional_column_matches(0, (1 << 53) - 3, 6, 8, 1);
    assert_eq!(
        positional_radical_inverse_f64(0, 1 << 53, 8),
        positional_radical_inverse_f64(0, 0, 8)
    );
    // Base 1553 keeps 4 digits (1553^5 > 2^53): index 1553^4 wraps to 0.
    let b4 = 1553u64.pow(4);
    let dim = PRIMES.iter().position(|&p| p == 1553).unwrap() as u32;
    assert_eq!(
        positional_radical_inverse_f64(dim, b4, 8),
        positional_radical_inverse_f64(dim, 0, 8)
    );
    assert_ne!(
        positional_radical_inverse_f64(dim, b4 - 1, 8),
        positional_radical_inverse_f64(dim, 0, 8)
    );
    positional_column_matches(dim, b4 - 4, 8, 2, 1);
    positional_column_matches(5, u64::MAX - 9, 10, 9, 1);
    let mut out = [0.0; 4];
    assert_eq!(
        positional_radical_inverse_column_f64(0, 0, 1, &mut out, 0),
        Err(Error::ZeroSize { what: "stride" })
    );
    assert_eq!(
        positional_radical_inverse_column_f64(0, u64::MAX - 2, 1, &mut out, 1),
        Err(Error::TooMany {
            what: "first",
            value: u64::MAX - 2,
            max: u64::MAX - 3
        })
    );
    assert_eq!(
        positional_radical_inverse_column_f64(0, 5, 1, &mut [], 3),
        Ok(0)
    );
}

#[test]
fn positional_permutations_keep_strata_and_differ_by_position() {
    // b^m consecutive points from a multiple of b^m fall one per cell of side b^−m.
    for (dim, b, m) in [(0u32, 2u64, 6u32), (1, 3, 4), (2, 5, 3), (9, 29, 2)] {
        for seed in [1u64, 77] {
            let n = b.pow(m);
            let mut cells: std::vec::Vec<u64> = (3 * n..4 * n)
                .map(|a| (positional_radical_inverse_f64(dim, a, seed) * n as f64) as u64)
                .collect();
            cells.sort_unstable();
            assert!(cells.iter().copied().eq(0..n), "dim {dim} seed {seed}");
        }
    }
    // One permutation per base gives base 2 two randomizations; one per position gives each
    // seed its own: the first four base-2 values of 64 seeds are 64 distinct sets.
    let mut sets: std::vec::Vec<[u64; 4]> = (0..64)
        .map(|seed| {
            core::array::from_fn(|a| positional_radical_inverse_f64(0, a as u64, seed).to_bits())
        })
        .collect();
    sets.sort_unstable();
    sets.dedup();
    assert_eq!(sets.len(), 64);
    let per_base: std::collections::BTreeSet<u64> = (0..64)
        .map(|seed| scrambled_radical_inverse_f64(0, 1, seed).to_bits())
        .collect();
    assert_eq!(per_base.len(), 2);
}

#[test]
fn positional_values_are_stable_across_versions() {
    // A seed's stream is part of the contract (a seeded render or study repeats across
    // versions): these bits pin the per-position keys, hash3(seed, base, position) folded to
    // 32 bits.
    for (dim, a, seed, bits) in [
        (0u32, 1u64, 7u64, 0x3fd6_f595_83e8_37ccu64),
        (1, 5, 7, 0x3fe7_16ed_642b_0032),
        (4, 123, 99, 0x3fef_4172_1354_4306),
        (1023, 77_777, 3, 0x3fb3_779e_13a7_da21),
    ] {
        let v = positional_radical_inverse_f64(dim, a, seed);
        assert_eq!(v.to_bits(), bits, "dim {dim} a {a} seed {seed}: {v}");
    }
}

#[test]
fn positional_values_are_uniform_over_seeds() {
    // The mean of 4000 seeds' values of one index is 1/2 within 0.02: the standard error is
    // sqrt(1/12/4000) = 0.0046, so the bound is 4.3 standard errors (false alarm about 2e-5).
    for (dim, a) in [(0u32, 5u64), (1, 1000), (40, 123_456)] {
        let mean = (0..4000u64)
            .map(|seed| positional_radical_inverse_f64(dim, a, seed))
            .sum::<f64>()
            / 4000.0;
        assert!((mean - 0.5).abs() < 0.02, "dim {dim} a {a}: {mean}");
    }
}

proptest! {
    #[test]
    fn positional_columns_equal_the_values_one_by_one(
        dim in 0u32..1100,
        first in prop_oneof![0u64..100_000, any::<u64>().prop_map(|a| a >> 20)],
        count in 1usize..300,
        seed in any::<u64>(),
        stride in 1usize..5,
    ) {
        positional_column_matches(dim, first, count, seed, stride);
    }
}
