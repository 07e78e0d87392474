//! The compact pixel samplers against the desktop ones, value for value.

use super::*;
use crate::hash::mix64;
use crate::sampler::{self, Sampler};
use crate::scramble::Scramble;
use proptest::prelude::*;

/// The float's bits, so that the comparisons below tell `-0.0` from `0.0`.
fn bits2(v: [f32; 2]) -> [u32; 2] {
    v.map(f32::to_bits)
}

/// `a` and `b` give the same bits for `pixel`'s sample `index`: its camera sample and the
/// values after it (dimensions 0 to 7), then the values from `dim` on (1D, 2D and the pixel
/// sample in turn), and an array there: dimensions `dim .. dim + 15`.
fn same_values(a: &mut impl Sampler, b: &mut impl Sampler, pixel: [u32; 2], index: u32, dim: u32) {
    let (ca, cb) = (a.camera_sample(pixel, index), b.camera_sample(pixel, index));
    let what = || std::format!("pixel {pixel:?} sample {index} dim {dim}");
    assert_eq!(bits2(ca.p_film), bits2(cb.p_film), "film, {}", what());
    assert_eq!(bits2(ca.lens), bits2(cb.lens), "lens, {}", what());
    assert_eq!(ca.time.to_bits(), cb.time.to_bits(), "time, {}", what());
    assert_eq!(
        a.get_1d().to_bits(),
        b.get_1d().to_bits(),
        "dim 5, {}",
        what()
    );
    assert_eq!(
        bits2(a.get_2d()),
        bits2(b.get_2d()),
        "dims 6, 7, {}",
        what()
    );
    a.start_pixel_sample(pixel, index, dim);
    b.start_pixel_sample(pixel, index, dim);
    for k in 0..3 {
        assert_eq!(
            a.get_1d().to_bits(),
            b.get_1d().to_bits(),
            "1d {k}, {}",
            what()
        );
        assert_eq!(bits2(a.get_2d()), bits2(b.get_2d()), "2d {k}, {}", what());
    }
    assert_eq!(
        bits2(a.get_pixel_2d()),
        bits2(b.get_pixel_2d()),
        "pixel 2d, {}",
        what()
    );
    assert_eq!(
        a.get_1d().to_bits(),
        b.get_1d().to_bits(),
        "after pixel, {}",
        what()
    );
    let (mut xa, mut xb) = ([0f32; 5], [0f32; 5]);
    a.get_array_1d(&mut xa);
    b.get_array_1d(&mut xb);
    assert_eq!(
        xa.map(f32::to_bits),
        xb.map(f32::to_bits),
        "array, {}",
        what()
    );
    assert_eq!(a.samples_per_pixel(), b.samples_per_pixel());
    assert_eq!(a.arrays_are_dimension_runs(), b.arrays_are_dimension_runs());
}

/// Pixels, sample indices and dimensions from small to the largest: `k` hashed and cut to
/// every bit length.
fn spread(k: u64) -> u32 {
    if k < 16 {
        return k as u32;
    }
    (mix64(k) >> 32) as u32 >> (k % 32)
}

/// Each scramble, from an integer.
fn scramble(k: u8) -> Scramble {
    Scramble::ALL[usize::from(k) % 4]
}

#[test]
fn owen_sobol_sampler_equals_the_desktop_sampler_on_a_sweep() {
    for seed in [0u64, 1, 7, u64::MAX] {
        for frame in [0u32, 3, u32::MAX] {
            let mut small = OwenSobolSampler::<32>::new(16, seed)
                .unwrap()
                .with_frame(frame);
            let mut all = OwenSobolSampler::<1024>::new(16, seed)
                .unwrap()
                .with_frame(frame);
            let mut desk = sampler::OwenSobolSampler::new(16, seed)
                .unwrap()
                .with_frame(frame);
            for k in 0..300u64 {
                let (pixel, index) = ([spread(k), spread(k + 7)], spread(3 * k));
                same_values(&mut small, &mut desk, pixel, index, (k % 16) as u32);
                same_values(&mut all, &mut desk, pixel, index, spread(k ^ 0x55));
            }
        }
    }
}

/// Past `N` dimensions: the direction numbers of `d mod N`, the scramble of `d` itself.
#[test]
fn owen_sobol_sampler_past_n_wraps_the_matrix_and_keeps_the_scramble() {
    let mut s = OwenSobolSampler::<4>::new(8, 3).unwrap();
    let mut wide = OwenSobolSampler::<1024>::new(8, 3).unwrap();
    let mut values = std::vec::Vec::new();
    for i in 0..64 {
        s.start_pixel_sample([5, 9], i, 2);
        let below = s.get_1d();
        s.start_pixel_sample([5, 9], i, 6);
        let above = s.get_1d();
        wide.start_pixel_sample([5, 9], i, 6);
        values.push((below, above, wide.get_1d()));
    }
    // Dimension 6 here is dimension 2's Sobol points under another scramble: stratified as
    // dimension 2 is, and not the same values (nor the 1024-dimension sampler's dimension 6).
    assert!(values.iter().any(|v| v.0 != v.1));
    assert!(values.iter().any(|v| v.1 != v.2));
    let mut strata: std::vec::Vec<u32> = values.iter().map(|v| (v.1 * 64.0) as u32).collect();
    strata.sort_unstable();
    assert_eq!(strata, (0..64).collect::<std::vec::Vec<u32>>());
}

#[test]
fn zsobol_sampler_equals_the_desktop_sampler_on_a_sweep() {
    for (res, spp) in [
        ([64u32, 64u32], 16u32),
        ([1, 1], 1),
        ([1920, 1080], 8),
        ([65536, 3], 1),
        ([16384, 16384], 4096),
    ] {
        for how in Scramble::ALL {
            let mut small = ZSobolSampler::new(res, spp, how, 5).unwrap();
            let mut desk = sampler::ZSobolSampler::new(res, spp, how, 5).unwrap();
            for k in 0..200u64 {
                // Runs of samples in one pixel (the desktop sampler tables them) and jumps.
                let pixel = [spread(k / 4), spread(k / 4 + 9)];
                same_values(&mut small, &mut desk, pixel, spread(k), spread(k ^ 0xa5));
            }
        }
    }
}

#[test]
fn sobol_sampler_equals_the_desktop_sampler_on_a_sweep() {
    for (res, spp) in [
        ([64u32, 64u32], 16u32),
        ([1, 1], 1),
        ([1920, 1080], 64),
        ([65536, 3], 1),
    ] {
        for (how, seed) in [(Scramble::None, 0), (Scramble::PermuteDigits, 9)]
            .into_iter()
            .chain(Scramble::ALL.map(|how| (how, 5)))
        {
            let mut small = SobolSampler::<24>::new(res, spp, how, seed).unwrap();
            let mut all = SobolSampler::<1024>::new(res, spp, how, seed).unwrap();
            let mut desk = sampler::SobolSampler::new(res, spp, how, seed).unwrap();
            for k in 0..200u64 {
                let (pixel, index) = ([spread(k / 4), spread(k / 4 + 9)], spread(k));
                same_values(&mut small, &mut desk, pixel, index, (k % 8) as u32);
                same_values(&mut all, &mut desk, pixel, index, spread(k ^ 0xa5));
                assert_eq!(
                    small.sequence_index(pixel, index),
                    desk.sequence_index(pixel, index)
                );
            }
        }
    }
}

/// Past `N` dimensions: dimensions 2 and up again, never the pixel's 0 and 1, each under its
/// own scramble.
#[test]
fn sobol_sampler_past_n_wraps_into_the_dimensions_above_the_pixel() {
    let how = Scramble::PermuteDigits;
    let mut s = SobolSampler::<5>::new([4, 4], 64, how, 3).unwrap();
    let mut wide = SobolSampler::<1024>::new([4, 4], 64, how, 3).unwrap();
    // The 24-bit fraction of dimension `d` of sample `i` of pixel (1, 2).
    let at = |s: &mut dyn Sampler, i: u32, d: u32| {
        s.start_pixel_sample([1, 2], i, d);
        (s.get_1d() * 16_777_216.0) as u32
    };
    let mut xors = std::collections::BTreeSet::new();
    for i in 0..64 {
        // Dimension 6 reads dimension 3's direction numbers (2 + 4 mod 3) under its own
        // digital shift: the two differ by one XOR, the same for every sample.
        xors.insert(at(&mut s, i, 3) ^ at(&mut s, i, 6));
        assert_eq!(
            at(&mut s, i, 3),
            at(&mut wide, i, 3),
            "below N: the desktop's values"
        );
    }
    assert_eq!(xors.len(), 1, "{xors:?}");
    assert_ne!(xors.first(), Some(&0));
}

#[test]
fn halton_sampler_equals_the_desktop_sampler_on_a_sweep() {
    for (res, spp) in [
        ([64u32, 64u32], 16u32),
        ([1, 1], 1),
        ([1920, 1080], 64),
        ([7, 300], 3),
    ] {
        for how in Scramble::ALL {
            for seed in [0u64, 5, u64::MAX] {
                let mut small = HaltonSampler::<24>::new(res, spp, how, seed).unwrap();
                let mut desk = sampler::HaltonSampler::new(res, spp, how, seed).unwrap();
                for k in 0..100u64 {
                    let (pixel, index) = ([spread(k / 4), spread(k / 4 + 9)], spread(k));
                    same_values(&mut small, &mut desk, pixel, index, (k % 8) as u32);
                }
            }
            // Every base, through the dimensions of a 1024-dimension sampler.
            let mut all = HaltonSampler::<1024>::new(res, spp, how, 9).unwrap();
            let mut desk = sampler::HaltonSampler::new(res, spp, how, 9).unwrap();
            for k in 0..70u64 {
                let (pixel, index) = ([spread(k), spread(k + 9)], spread(k ^ 0x77));
                same_values(&mut all, &mut desk, pixel, index, 16 * k as u32);
            }
        }
    }
}

/// Past `N` dimensions: the bases above the pixel's again, under scrambles of their own.
#[test]
fn halton_sampler_past_n_takes_the_bases_above_the_pixel_under_new_scrambles() {
    for how in Scramble::ALL {
        let mut s = HaltonSampler::<5>::new([8, 8], 64, how, 3).unwrap();
        // Dimension 6 takes base 7 (dimension 3's, 2 + 4 mod 3): 49 consecutive samples of a
        // pixel step its index by the stride, coprime to 7, so they fall one per 1/49 as
        // dimension 3's do, whatever the scramble.
        for d in [3u32, 6] {
            let mut cells: std::vec::Vec<u32> = (0..49)
                .map(|i| {
                    s.start_pixel_sample([2, 5], i, d);
                    (s.get_1d() * 49.0) as u32
                })
                .collect();
            cells.sort_unstable();
            assert_eq!(
                cells,
                (0..49).collect::<std::vec::Vec<u32>>(),
                "{how:?} dim {d}"
            );
        }
        let values = |s: &mut HaltonSampler<5>, d: u32| -> std::vec::Vec<u32> {
            (0..16)
                .map(|i| {
                    s.start_pixel_sample([2, 5], i, d);
                    s.get_1d().to_bits()
                })
                .collect()
        };
        let (three, six) = (values(&mut s, 3), values(&mut s, 6));
        // Unscrambled, dimension 6 repeats dimension 3; scrambled, it has its own scramble.
        assert_eq!(three == six, how == Scramble::None, "{how:?}");
    }
}

/// Unscrambled, dimension `d ≥ N` is exactly dimension `2 + (d − 2) mod (N − 2)` (dimension
/// `N` itself included), and the scales are the desktop sampler's.
#[test]
fn halton_sampler_dimensions_from_n_on_wrap_onto_the_bases_above_the_pixel() {
    let mut s = HaltonSampler::<8>::new([8, 8], 16, Scramble::None, 0).unwrap();
    let value = |s: &mut HaltonSampler<8>, d: u32, i: u32| {
        s.start_pixel_sample([3, 6], i, d);
        s.get_1d().to_bits()
    };
    for d in 8u32..40 {
        let same = 2 + (d - 2) % 6;
        for i in [0u32, 5, 15] {
            assert_eq!(
                value(&mut s, d, i),
                value(&mut s, same, i),
                "dim {d} vs {same}"
            );
        }
    }
    for res in [[1u32, 1u32], [100, 30], [640, 480], [7, 300]] {
        let small = HaltonSampler::<8>::new(res, 4, Scramble::None, 0).unwrap();
        let desk = sampler::HaltonSampler::new(res, 4, Scramble::None, 0).unwrap();
        assert_eq!(small.scales(), desk.scales(), "{res:?}");
    }
}

/// The backward construction rebuilds the baked table point for point, and the buffer
/// construction's points for other seeds.
#[test]
fn pmj02_points_rebuilt_alone_equal_the_construction() {
    use super::pmj02_sampler::pmj02_point;
    use crate::sequence::{PMJ02_TABLE, PMJ02_TABLE_SEED, pmj02_build};
    for (j, p) in PMJ02_TABLE.iter().enumerate() {
        let j = j as u32;
        let point = [0, 1].map(|d| pmj02_point(PMJ02_TABLE_SEED, j, d));
        assert_eq!(point, *p, "point {j}");
        // The index wraps modulo 2^16.
        assert_eq!(pmj02_point(PMJ02_TABLE_SEED, j | 0xabc << 16, 1), p[1]);
    }
    let mut built = std::vec![[0u32; 2]; 4096];
    for seed in [0u32, 1, 0xdead_beef, u32::MAX] {
        pmj02_build(seed, &mut built).unwrap();
        for (j, p) in built.iter().enumerate() {
            assert_eq!(
                [0, 1].map(|d| pmj02_point(seed, j as u32, d)),
                *p,
                "seed {seed} {j}"
            );
        }
    }
}

#[test]
fn pmj02_sampler_equals_the_desktop_sampler_on_a_sweep() {
    for spp in [1u32, 16, 100, 65_536] {
        for seed in [0u64, 7, u64::MAX] {
            let mut small = Pmj02Sampler::new(spp, seed).unwrap();
            let mut desk = sampler::Pmj02Sampler::new(spp, seed).unwrap();
            for k in 0..300u64 {
                let (pixel, index) = ([spread(k / 4), spread(k / 4 + 9)], spread(k));
                same_values(&mut small, &mut desk, pixel, index, spread(k ^ 0x3c));
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn halton_sampler_equals_the_desktop_sampler(
        res in [1u32..5000, 1u32..5000], spp in 1u32.., how: u8, seed: u64, pixel: [u32; 2],
        index: u32, dim in 0u32..16, far_dim: u32,
    ) {
        let mut desk = sampler::HaltonSampler::new(res, spp, scramble(how), seed).unwrap();
        let mut small = HaltonSampler::<32>::new(res, spp, scramble(how), seed).unwrap();
        same_values(&mut small, &mut desk, pixel, index, dim);
        prop_assert_eq!(small.sequence_index(pixel, index), desk.sequence_index(pixel, index));
        let mut all = HaltonSampler::<1024>::new(res, spp, scramble(how), seed).unwrap();
        same_values(&mut all, &mut desk, pixel, index, far_dim);
    }

    #[test]
    fn pmj02_sampler_equals_the_desktop_sampler(
        spp in 1u32..=65_536, seed: u64, pixel: [u32; 2], index: u32, dim: u32,
    ) {
        let mut small = Pmj02Sampler::new(spp, seed).unwrap();
        let mut desk = sampler::Pmj02Sampler::new(spp, seed).unwrap();
        same_values(&mut small, &mut desk, pixel, index, dim);
        same_values(&mut small, &mut desk, pixel, index.wrapping_add(1), dim % 8);
    }

    #[test]
    fn owen_sobol_sampler_equals_the_desktop_sampler(
        spp in 1u32.., seed: u64, frame: u32, pixel: [u32; 2], index: u32, dim in 0u32..16,
        far_dim: u32,
    ) {
        let mut desk = sampler::OwenSobolSampler::new(spp, seed).unwrap().with_frame(frame);
        let mut small = OwenSobolSampler::<32>::new(spp, seed).unwrap().with_frame(frame);
        same_values(&mut small, &mut desk, pixel, index, dim);
        let mut all = OwenSobolSampler::<1024>::new(spp, seed).unwrap().with_frame(frame);
        same_values(&mut all, &mut desk, pixel, index, far_dim);
    }

    #[test]
    fn sobol_sampler_equals_the_desktop_sampler(
        log2_res in 0u32..=16, log2_spp in 0u32..=32, aspect in 1u32..=8, how: u8, seed: u64,
        pixel: [u32; 2], index: u32, dim in 0u32..16, far_dim: u32,
    ) {
        let side = 1u32 << log2_res;
        let res = [(side / aspect).max(1), side];
        let spp = (1u64 << log2_spp).min(u64::from(u32::MAX)) as u32;
        let (small, all, desk) = (
            SobolSampler::<32>::new(res, spp, scramble(how), seed),
            SobolSampler::<1024>::new(res, spp, scramble(how), seed),
            sampler::SobolSampler::new(res, spp, scramble(how), seed),
        );
        prop_assert_eq!(small.is_ok(), desk.is_ok());
        if let (Ok(mut small), Ok(mut all), Ok(mut desk)) = (small, all, desk) {
            same_values(&mut small, &mut desk, pixel, index, dim);
            same_values(&mut all, &mut desk, pixel, index, far_dim);
            prop_assert_eq!(small.sequence_index(pixel, index), desk.sequence_index(pixel, index));
        }
    }

    #[test]
    fn zsobol_sampler_equals_the_desktop_sampler(
        log2_res in 0u32..=16, log2_spp in 0u32..=32, aspect in 1u32..=8, how: u8, seed: u64,
        pixel: [u32; 2], index: u32, dim: u32,
    ) {
        let side = 1u32 << log2_res;
        let res = [side, (side / aspect).max(1)];
        let spp = (1u64 << log2_spp).min(u64::from(u32::MAX)) as u32;
        let (small, desk) = (
            ZSobolSampler::new(res, spp, scramble(how), seed),
            sampler::ZSobolSampler::new(res, spp, scramble(how), seed),
        );
        prop_assert_eq!(small.is_ok(), desk.is_ok());
        if let (Ok(mut small), Ok(mut desk)) = (small, desk) {
            same_values(&mut small, &mut desk, pixel, index, dim);
            // A second sample of the same pixel, where the desktop sampler tables its digits.
            same_values(&mut small, &mut desk, pixel, index ^ 1, dim);
        }
    }
}

/// The accessors report what the desktop samplers report (and what they were built with): the
/// seed and frame, the scramble, the rounded spp and, for ZSobol, the permuted index.
#[test]
fn accessors_equal_the_desktop_samplers() {
    for seed in [0u64, 3, u64::MAX] {
        for frame in [0u32, 9, u32::MAX] {
            let small = OwenSobolSampler::<8>::new(4, seed)
                .unwrap()
                .with_frame(frame);
            let desk = sampler::OwenSobolSampler::new(4, seed)
                .unwrap()
                .with_frame(frame);
            assert_eq!((small.frame(), small.seed()), (frame, seed));
            assert_eq!((desk.frame(), desk.seed()), (frame, seed));
        }
        let (small, desk) = (
            Pmj02Sampler::new(16, seed).unwrap(),
            sampler::Pmj02Sampler::new(16, seed).unwrap(),
        );
        assert_eq!((small.seed(), desk.seed()), (seed, seed));
    }
    for requested in [
        0u32,
        1,
        2,
        3,
        5,
        12,
        16,
        1000,
        1 << 31,
        (1 << 31) + 1,
        u32::MAX,
    ] {
        let want = sampler::SobolSampler::rounded_spp(requested);
        assert_eq!(
            SobolSampler::<8>::rounded_spp(requested),
            want,
            "{requested}"
        );
        assert_eq!(ZSobolSampler::rounded_spp(requested), want, "{requested}");
    }
    for how in Scramble::ALL {
        let small = SobolSampler::<8>::new([16, 16], 4, how, 2).unwrap();
        assert_eq!(small.scramble(), how);
        let (small, desk) = (
            ZSobolSampler::new([16, 8], 4, how, 2).unwrap(),
            sampler::ZSobolSampler::new([16, 8], 4, how, 2).unwrap(),
        );
        assert_eq!(small.scramble(), how);
        for k in 0..64u64 {
            let (pixel, index, dim) = (
                [spread(k) % 16, spread(k + 3) % 8],
                spread(k),
                spread(k ^ 9),
            );
            assert_eq!(
                small.sequence_index(pixel, index, dim),
                desk.sequence_index(pixel, index, dim),
                "{how:?} {pixel:?} {index} {dim}"
            );
        }
    }
}

/// Unscrambled, dimension `d ≥ N` is exactly dimension `2 + (d − 2) mod (N − 2)`, dimension
/// `N` itself included.
#[test]
fn sobol_sampler_dimensions_from_n_on_wrap_onto_the_dimensions_above_the_pixel() {
    let mut s = SobolSampler::<5>::new([8, 8], 16, Scramble::None, 0).unwrap();
    let value = |s: &mut SobolSampler<5>, d: u32, i: u32| {
        s.start_pixel_sample([3, 6], i, d);
        s.get_1d().to_bits()
    };
    for d in 5u32..40 {
        let same = 2 + (d - 2) % 3;
        for i in [1u32, 5, 15] {
            assert_eq!(
                value(&mut s, d, i),
                value(&mut s, same, i),
                "dim {d} vs {same}"
            );
        }
    }
}

/// Pixels at the top of the `u32` range, as the desktop sampler reads them: each axis's digits
/// are those of the pixel modulo its scale (`3^k` does not divide 2³², so a sum that wraps
/// would not give them).
#[test]
fn halton_sampler_equals_the_desktop_sampler_at_the_largest_pixels() {
    for how in Scramble::ALL {
        let mut small = HaltonSampler::<24>::new([1920, 1080], 16, how, 5).unwrap();
        let mut desk = sampler::HaltonSampler::new([1920, 1080], 16, how, 5).unwrap();
        for k in 0..300u32 {
            let pixel = [u32::MAX - k, u32::MAX - (k * 7) % 300];
            assert_eq!(
                small.sequence_index(pixel, 3),
                desk.sequence_index(pixel, 3),
                "{pixel:?}"
            );
            same_values(&mut small, &mut desk, pixel, k % 16, k % 8);
        }
    }
}

/// From dimension 1024 on, the compact samplers give the desktop samplers' padding, whatever
/// `N`: the four dimensions' constants reproduce the tables bit for bit.
#[test]
fn padding_dimensions_equal_the_desktop_samplers() {
    for how in Scramble::ALL {
        let mut small = SobolSampler::<5>::new([64, 48], 4, how, 3).unwrap();
        let mut desk = crate::sampler::SobolSampler::new([64, 48], 4, how, 3).unwrap();
        let mut owen = OwenSobolSampler::<4>::new(8, 3).unwrap();
        let mut owen_desk = crate::sampler::OwenSobolSampler::new(8, 3).unwrap();
        let mut halton = HaltonSampler::<5>::new([64, 48], 4, how, 3).unwrap();
        let mut halton_desk = crate::sampler::HaltonSampler::new([64, 48], 4, how, 3).unwrap();
        for (pixel, i) in [([0u32, 0u32], 0u32), ([63, 47], 9), ([5, 9], 1 << 20)] {
            for d in [1024u32, 1027, 2000, 1 << 20, u32::MAX - 1] {
                for (a, b) in [
                    (
                        &mut small as &mut dyn Sampler,
                        &mut desk as &mut dyn Sampler,
                    ),
                    (&mut owen, &mut owen_desk),
                    (&mut halton, &mut halton_desk),
                ] {
                    a.start_pixel_sample(pixel, i, d);
                    b.start_pixel_sample(pixel, i, d);
                    assert_eq!(a.get_2d(), b.get_2d(), "{how:?} {pixel:?} {i} {d}");
                }
            }
        }
    }
}

proptest::proptest! {
    /// The compact padding equals the desktop's for any key, index and dimension.
    #[test]
    fn compact_padding_equals_the_desktop_padding(key: u32, index: u64, dim in 1024u32..) {
        proptest::prop_assert_eq!(
            super::padded_u32(key, index, dim),
            crate::sequence::padded_u32(key, index, dim)
        );
    }
}
