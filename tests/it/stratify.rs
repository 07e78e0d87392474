//! Stratification, Latin hypercube and shuffle properties over caller buffers.

use nyquist::rng::default_rng;
use nyquist::stratify::{Jitter, latin_hypercube, shuffle, stratified_1d, stratified_2d};
use nyquist_tests::one_per_stratum;
use proptest::prelude::*;

proptest! {
    #[test]
    fn stratified_2d_puts_one_sample_in_each_cell(nx in 1u32..40, ny in 1u32..40, seed: u64, centered: bool) {
        let jitter = if centered { Jitter::Centered } else { Jitter::Jittered };
        let mut buf = vec![0.0f32; 2 * (nx * ny) as usize];
        stratified_2d(&mut buf, nx, ny, jitter, &mut default_rng(seed)).unwrap();
        let mut seen = vec![false; (nx * ny) as usize];
        for p in buf.chunks_exact(2) {
            prop_assert!((0.0..1.0).contains(&p[0]) && (0.0..1.0).contains(&p[1]));
            let cx = (f64::from(p[0]) * f64::from(nx)) as u32;
            let cy = (f64::from(p[1]) * f64::from(ny)) as u32;
            prop_assert!(!std::mem::replace(&mut seen[(cy * nx + cx) as usize], true));
        }
    }

    #[test]
    fn stratified_1d_is_one_per_stratum(n in 1usize..500, seed: u64) {
        let mut buf = vec![0.0f32; n];
        stratified_1d(&mut buf, Jitter::Jittered, &mut default_rng(seed)).unwrap();
        prop_assert!(one_per_stratum(&buf, n));
    }

    #[test]
    fn latin_hypercube_hits_every_stratum_of_every_dimension_once(n in 1usize..300, dims in 1u32..9, seed: u64) {
        let mut buf = vec![0.0f32; n * dims as usize];
        prop_assert_eq!(latin_hypercube(&mut buf, dims, &mut default_rng(seed)), Ok(n as u32));
        for d in 0..dims as usize {
            let column: Vec<f32> = buf.chunks_exact(dims as usize).map(|p| p[d]).collect();
            prop_assert!(one_per_stratum(&column, n), "dim {}", d);
        }
    }

    #[test]
    fn shuffle_permutes_whole_blocks(count in 0usize..200, dims in 1usize..5, seed: u64) {
        let mut buf: Vec<u32> = (0..(count * dims) as u32).collect();
        shuffle(&mut buf, count, dims, &mut default_rng(seed)).unwrap();
        let mut firsts: Vec<u32> = buf.chunks_exact(dims).map(|b| {
            // Blocks stay intact: consecutive values.
            assert!(b.windows(2).all(|w| w[1] == w[0] + 1));
            b[0]
        }).collect();
        firsts.sort_unstable();
        prop_assert_eq!(firsts, (0..count as u32).map(|k| k * dims as u32).collect::<Vec<_>>());
    }

    #[test]
    fn bad_sizes_are_errors_not_panics(len in 0usize..40, a in 0u32..7, b in 0u32..7, c in 0usize..9) {
        let mut buf = vec![0.0f32; len];
        let mut rng = default_rng(1);
        let ok2 = a > 0 && b > 0 && len == 2 * (a * b) as usize;
        prop_assert_eq!(stratified_2d(&mut buf, a, b, Jitter::Jittered, &mut rng).is_ok(), ok2);
        let ok_lhs = a > 0 && len > 0 && len % a as usize == 0;
        prop_assert_eq!(latin_hypercube(&mut buf, a, &mut rng).is_ok(), ok_lhs);
        let ok_shuffle = c > 0 && len % c == 0;
        prop_assert_eq!(shuffle(&mut buf, len / c.max(1), c, &mut rng).is_ok(), ok_shuffle);
    }
}

#[test]
fn shuffle_of_three_gives_all_six_orders_uniformly() {
    // 60000 shuffles; chi-square with 5 dof, 0.999 quantile 20.5.
    let mut rng = default_rng(99);
    let mut counts = std::collections::HashMap::new();
    for _ in 0..60_000 {
        let mut v = [0u8, 1, 2];
        shuffle(&mut v, 3, 1, &mut rng).unwrap();
        *counts.entry(v).or_insert(0u32) += 1;
    }
    assert_eq!(counts.len(), 6);
    let chi: f64 = counts
        .values()
        .map(|&c| (f64::from(c) - 10_000.0).powi(2) / 10_000.0)
        .sum();
    assert!(chi < 20.5, "chi2 = {chi}");
}
