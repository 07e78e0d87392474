//! The compact types against the table paths, value for value.

use super::*;
use crate::radical::{fast_class_of_table, radical_inverse};
use crate::sequence;
use proptest::prelude::*;

/// Every `(base, class)`'s digit count and reciprocal, recomputed for the compact path, equal the
/// fast path's.
#[test]
fn fast_class_constants_match_the_tables() {
    for d in 1..1024 {
        for c in 1..=8 {
            assert_eq!(
                fast_class(d, c),
                fast_class_of_table(d, c),
                "dim {d} class {c}"
            );
        }
    }
}

/// Indices of every bit length, and the edges around each base's fast-path limit.
fn indices(d: usize) -> impl Iterator<Item = u64> {
    let limit = if d == 0 { 1 << 32 } else { fast_limit(d) };
    (0..300u64)
        .chain((0..64).flat_map(|k| [1u64 << k, (1u64 << k) - 1, crate::hash::mix64(k) >> k]))
        .chain([limit - 1, limit, limit + 1, u64::MAX, u64::MAX - 1])
}

#[test]
fn halton_equals_the_table_path_in_every_dimension() {
    let h = Halton::<1024>::new();
    for d in 0..1024u32 {
        for i in indices(d as usize) {
            assert_eq!(
                h.sample(i, d).to_bits(),
                radical_inverse(d, i).to_bits(),
                "dim {d} index {i}"
            );
        }
    }
}

#[test]
fn runtime_halton_equals_the_table_path_in_every_dimension() {
    let h = RuntimeHalton::new(1024).unwrap();
    for d in 0..1024u32 {
        for i in indices(d as usize) {
            assert_eq!(
                h.sample(i, d).to_bits(),
                radical_inverse(d, i).to_bits(),
                "dim {d} index {i}"
            );
        }
    }
    // Dimensions past `dims` wrap modulo `dims`, as the table path's Halton does.
    let (small, table) = (
        RuntimeHalton::new(5).unwrap(),
        sequence::Halton::new(5).unwrap(),
    );
    for (i, d) in [(7u64, 5u32), (123_456, 13), (u64::MAX, 1029)] {
        assert_eq!(small.sample(i, d).to_bits(), table.sample(i, d).to_bits());
        assert_eq!(
            small.sample_f64(i, d).to_bits(),
            table.sample_f64(i, d).to_bits()
        );
    }
    assert_eq!(small.dims(), 5);
    assert_eq!(small.point_count(), None);
}

#[test]
fn runtime_halton_takes_the_table_paths_dimension_counts() {
    for dims in [0, 1, 2, 1024, 1025, u32::MAX] {
        assert_eq!(
            RuntimeHalton::new(dims).map(|h| h.dims()),
            sequence::Halton::new(dims).map(|h| h.dims()),
            "dims {dims}"
        );
    }
}

/// Base 3 at index 524 199 899 (`R' = 2 411 218 785` over 20 digits, just below an `f32`
/// midpoint; found with exact rationals): the fast path's two roundings (`R'·inv` to `f64`, then
/// to `f32`) land one `f32` above the correctly rounded `0x3f31_0829`, within the documented
/// ulp. The compact type, which below the fast-path limit rounds the same way and past it
/// correctly (its long path), must return the fast path's value there.
#[test]
fn halton_rounds_like_the_fast_path_where_that_is_not_correct_rounding() {
    let a = 524_199_899;
    assert!(a < fast_limit(1));
    let fast = radical_inverse(1, a);
    assert_eq!(fast.to_bits(), 0x3f31_082a);
    assert_eq!(phi_long(3, a).to_bits(), 0x3f31_0829);
    assert_eq!(Halton::<2>::new().sample(a, 1).to_bits(), fast.to_bits());
}

#[test]
fn sobol_and_owen_sobol_equal_the_table_paths_in_every_dimension() {
    let s = Sobol::<1024>::new();
    let shifted = Sobol::<1024>::with_digital_shift(11);
    let owen = OwenSobol::<1024>::new(5);
    let (ts, tshifted) = (
        sequence::Sobol::new(1024).unwrap(),
        sequence::Sobol::with_digital_shift(1024, 11).unwrap(),
    );
    let towen = sequence::OwenSobol::new(1024, 5).unwrap();
    for d in 0..1024u32 {
        for i in (0..64u64).chain((0..64).map(|k| crate::hash::mix64(k) >> (k / 2))) {
            assert_eq!(s.sample(i, d).to_bits(), ts.sample(i, d).to_bits());
            assert_eq!(shifted.sample_u32(i, d), tshifted.sample_u32(i, d));
            assert_eq!(owen.sample(i, d).to_bits(), towen.sample(i, d).to_bits());
            assert_eq!(owen.sample_u32(i, d), towen.sample_u32(i, d));
            assert_eq!(owen.sample_4d(i, d), towen.sample_4d(i, d));
        }
    }
}

#[test]
fn short_dimension_counts_wrap_like_the_table_paths() {
    let (h, th) = (Halton::<3>::new(), sequence::Halton::new(3).unwrap());
    let (o, to) = (
        OwenSobol::<5>::new(1),
        sequence::OwenSobol::new(5, 1).unwrap(),
    );
    for i in [0u64, 7, 1 << 40] {
        for d in 0..20 {
            assert_eq!(h.sample(i, d).to_bits(), th.sample(i, d).to_bits());
            assert_eq!(h.sample_f64(i, d).to_bits(), th.sample_f64(i, d).to_bits());
            assert_eq!(o.sample(i, d).to_bits(), to.sample(i, d).to_bits());
            assert_eq!(o.sample_4d(i, d), to.sample_4d(i, d));
        }
    }
}

proptest! {
    #[test]
    fn halton_matches_at_random(i in any::<u64>(), d in 0u32..1024, shift in 0u32..64) {
        let i = i >> shift;
        prop_assert_eq!(Halton::<1024>::new().sample(i, d).to_bits(), radical_inverse(d, i).to_bits());
    }

    #[test]
    fn sobols_match_at_random(i in any::<u64>(), d in 0u32..1024, seed in any::<u64>()) {
        let owen = OwenSobol::<1024>::new(seed);
        let towen = sequence::OwenSobol::new(1024, seed).unwrap();
        prop_assert_eq!(owen.sample(i, d).to_bits(), towen.sample(i, d).to_bits());
        prop_assert_eq!(owen.sample_4d(i, d), towen.sample_4d(i, d));
        let s = Sobol::<1024>::with_digital_shift(seed);
        let ts = sequence::Sobol::with_digital_shift(1024, seed).unwrap();
        prop_assert_eq!(s.sample(i, d).to_bits(), ts.sample(i, d).to_bits());
    }
}

/// The integer emulation of `((R' as f64) * inv) as f32` (what runs on single-precision FPUs)
/// against the `f64` expression itself, for every base's reciprocals and digit reversals of
/// every length, and at random.
#[test]
fn integer_rounding_equals_the_f64_expression() {
    let f64_form = |rev: u64, inv: u64| {
        ((rev as f64 * f64::from_bits(inv)) as f32).min(crate::math::ONE_MINUS_EPSILON)
    };
    let mut checked = 0;
    for d in 1..1024 {
        for c in 1..=8 {
            let (digits, inv) = fast_class(d, c);
            let b = u64::from(crate::radical::PRIMES[d]);
            let top = b.pow(digits);
            for k in 0..200u64 {
                let rev = match k {
                    0..=2 => k,
                    3..=5 => top - (k - 2),
                    _ => crate::hash::mix64(k ^ (d as u64) << 20 ^ (c as u64) << 40) % top,
                };
                assert_eq!(
                    narrow_int(rev, inv).to_bits(),
                    f64_form(rev, inv).to_bits(),
                    "dim {d} class {c} rev {rev}"
                );
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 1023 * 8 * 200);
}

/// Each type reports the table path's dimension count and point count: `N`; no end for Halton,
/// 2³² points for the Sobol types.
#[test]
fn dims_and_point_counts_equal_the_table_paths() {
    fn same(a: &impl Sequence, b: &impl Sequence, n: u32) {
        assert_eq!(
            (a.dims(), a.point_count()),
            (b.dims(), b.point_count()),
            "{n} dims"
        );
        assert_eq!(a.dims(), n);
    }
    same(&Halton::<3>::new(), &sequence::Halton::new(3).unwrap(), 3);
    same(
        &Halton::<1024>::new(),
        &sequence::Halton::new(1024).unwrap(),
        1024,
    );
    same(&Sobol::<5>::new(), &sequence::Sobol::new(5).unwrap(), 5);
    same(
        &Sobol::<7>::with_digital_shift(3),
        &sequence::Sobol::with_digital_shift(7, 3).unwrap(),
        7,
    );
    same(
        &OwenSobol::<6>::new(2),
        &sequence::OwenSobol::new(6, 2).unwrap(),
        6,
    );
}

/// `sample_f64` is the table paths' 32-bit fraction exactly (`value / 2³²`), for the plain and
/// the shifted Sobol sequence and for Owen-Sobol, and Owen-Sobol keeps its seed.
#[test]
fn sobol_sample_f64_and_seed_equal_the_table_paths() {
    for seed in [0u64, 5, u64::MAX] {
        let plain = (Sobol::<8>::new(), sequence::Sobol::new(8).unwrap());
        let shifted = (
            Sobol::<8>::with_digital_shift(seed),
            sequence::Sobol::with_digital_shift(8, seed).unwrap(),
        );
        let (o, to) = (
            OwenSobol::<8>::new(seed),
            sequence::OwenSobol::new(8, seed).unwrap(),
        );
        assert_eq!(o.seed(), seed);
        for i in (0..64u64).chain([1 << 31, u64::from(u32::MAX), 1 << 40]) {
            for d in 0..10 {
                for (s, ts) in [&plain, &shifted] {
                    let x = s.sample_f64(i, d);
                    assert_eq!(x.to_bits(), ts.sample_f64(i, d).to_bits(), "{i} {d}");
                    assert_eq!(x, f64::from(s.sample_u32(i, d)) / 4_294_967_296.0);
                }
                let x = o.sample_f64(i, d);
                assert_eq!(x.to_bits(), to.sample_f64(i, d).to_bits(), "{i} {d}");
                assert_eq!(x, f64::from(o.sample_u32(i, d)) / 4_294_967_296.0);
            }
        }
    }
}
