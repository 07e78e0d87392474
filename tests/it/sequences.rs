//! Cross-checks of the core's point sets against each other and against published structure.

use nyquist::radical;
use nyquist::sequence::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, ScrambledHalton, Sequence, Sobol,
    VanDerCorput, ZeroTwo,
};
use nyquist_tests::elementary_intervals;
use proptest::prelude::*;

fn all_sets() -> Vec<(&'static str, Box<dyn Sequence>)> {
    vec![
        ("vdc", Box::new(VanDerCorput)),
        ("halton", Box::new(Halton::new(1024).unwrap())),
        (
            "halton-zaremba",
            Box::new(HaltonZaremba::new(1024).unwrap()),
        ),
        (
            "scrambled-halton",
            Box::new(ScrambledHalton::new(1024, 9).unwrap()),
        ),
        ("hammersley", Box::new(Hammersley::new(1000, 1025).unwrap())),
        (
            "hammersley-zaremba",
            Box::new(HammersleyZaremba::new(1000, 1025).unwrap()),
        ),
        ("sobol", Box::new(Sobol::new(1024).unwrap())),
        ("zero-two", Box::new(ZeroTwo::from_seed(5))),
    ]
}

#[test]
fn first_dimension_of_halton_sobol_and_zero_two_is_van_der_corput() {
    let halton = Halton::new(1).unwrap();
    let sobol = Sobol::new(1).unwrap();
    let zero_two = ZeroTwo::new([0, 0]);
    for i in 0..4096u64 {
        let vdc = VanDerCorput.sample(i, 0);
        assert_eq!(halton.sample(i, 0), vdc, "halton {i}");
        assert_eq!(sobol.sample(i, 0), vdc, "sobol {i}");
        assert_eq!(zero_two.sample(i, 0), vdc, "zero-two {i}");
        assert_eq!(vdc, radical::radical_inverse(0, i));
    }
}

#[test]
fn halton_dimension_d_is_the_radical_inverse_in_the_dth_prime() {
    let h = Halton::new(1024).unwrap();
    for (dim, p) in [(0u32, 2u32), (1, 3), (2, 5), (9, 29), (1023, 8161)] {
        assert_eq!(radical::prime(dim), p);
        // Φ_p(1) = 1/p and Φ_p(p) = 1/p² exactly in rational terms.
        assert!((h.sample_f64(1, dim) - 1.0 / f64::from(p)).abs() < 1e-15);
        assert!((h.sample_f64(u64::from(p), dim) - 1.0 / f64::from(p).powi(2)).abs() < 1e-15);
    }
}

#[test]
fn hammersley_first_dimension_is_k_plus_half_over_n() {
    let n = 37u64;
    for set in [
        Box::new(Hammersley::new(n, 3).unwrap()) as Box<dyn Sequence>,
        Box::new(HammersleyZaremba::new(n, 3).unwrap()),
    ] {
        for k in 0..n {
            let expected = (k as f64 + 0.5) / n as f64;
            assert!((set.sample_f64(k, 0) - expected).abs() < 1e-15);
        }
        assert_eq!(set.point_count(), Some(n));
    }
}

#[test]
fn sobol_and_zero_two_are_0_2_nets_for_every_power_of_two() {
    let sobol = Sobol::new(2).unwrap();
    for m in 1..=12u32 {
        let n = 1u64 << m;
        let pts: Vec<(f64, f64)> = (0..n)
            .map(|i| (sobol.sample_f64(i, 0), sobol.sample_f64(i, 1)))
            .collect();
        assert_eq!(elementary_intervals(&pts, m), Ok(()), "sobol m={m}");
        for seed in [0u64, 1, 77] {
            let z = ZeroTwo::from_seed(seed);
            let pts: Vec<(f64, f64)> = (0..n)
                .map(|i| (z.sample_f64(i, 0), z.sample_f64(i, 1)))
                .collect();
            assert_eq!(
                elementary_intervals(&pts, m),
                Ok(()),
                "zero-two seed={seed} m={m}"
            );
        }
    }
}

#[test]
fn halton_and_zaremba_differ_but_both_stratify_base_2() {
    let h = Halton::new(2).unwrap();
    let z = HaltonZaremba::new(2).unwrap();
    let differ = (0..64)
        .filter(|&i| h.sample(i, 1) != z.sample(i, 1))
        .count();
    assert!(differ > 32);
    // The first 2^m points of any base-2 digit-wise form hit every 1/2^m stratum once.
    for set in [&h as &dyn Sequence, &z] {
        let mut seen = [false; 64];
        for i in 0..64u64 {
            let s = (set.sample(i, 0) * 64.0) as usize;
            assert!(!std::mem::replace(&mut seen[s], true));
        }
    }
}

proptest! {
    #[test]
    fn every_set_stays_in_the_unit_interval(index: u64, dim: u32) {
        for (name, set) in all_sets() {
            let x = set.sample(index, dim);
            prop_assert!((0.0..1.0).contains(&x), "{name}: {x}");
            let y = set.sample_f64(index, dim);
            prop_assert!((0.0..1.0).contains(&y), "{name}: {y}");
        }
    }

    #[test]
    fn fill_equals_repeated_sample(first in 0u64..1_000_000, dims in 1u32..8, n in 1usize..20) {
        for (name, set) in all_sets() {
            let dims = dims.min(set.dims());
            let mut buf = vec![0.0f32; n * dims as usize];
            let written = set.fill(first, dims, &mut buf);
            if let Some(count) = set.point_count() && first + n as u64 > count {
                prop_assert!(written.is_err(), "{name}");
                continue;
            }
            prop_assert_eq!(written, Ok(n as u64), "{}", name);
            for (k, p) in buf.chunks_exact(dims as usize).enumerate() {
                for (d, &v) in p.iter().enumerate() {
                    prop_assert_eq!(v.to_bits(), set.sample(first + k as u64, d as u32).to_bits(), "{}", name);
                }
            }
        }
    }

    #[test]
    fn fill_rejects_bad_buffers_without_panicking(dims in 0u32..2000, len in 0usize..50) {
        for (_, set) in all_sets() {
            let mut buf = vec![0.0f32; len];
            let r = set.fill(0, dims, &mut buf);
            let ok = dims >= 1 && dims <= set.dims() && len > 0 && len % dims as usize == 0
                && set.point_count().is_none_or(|c| (len / dims as usize) as u64 <= c);
            prop_assert_eq!(r.is_ok(), ok);
        }
    }
}
