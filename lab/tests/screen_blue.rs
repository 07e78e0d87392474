//! The blue-noise samplers' error, measured as a user would, through the `Sampler` interface:
//! error images over the 128 × 128 tile for integrands the optimiser never saw
//! ([`HELD_OUT`]: a disk and a Gaussian over two pairs of dimensions, a Heaviside and a
//! Gaussian over four) at 1, 4 and 16 spp, in the first 4-D block (dimensions 0 … 3) and the
//! second (4 … 7), for each family (`owen-sobol-bn`, `pmj02-bn`, `lattice-bn`). The plain
//! counterpart is the same family with one hashed key per pixel and rank 0: the scrambled
//! sampler the tile lays out.
//!
//! Thresholds: white error's low-frequency ratio has mean 1 and, over the band's 800
//! frequencies (400 independent ones: the image is real, its periodogram symmetric), a standard
//! deviation near 1/√400 = 0.05, so 0.8 is four deviations below it and 0.75 … 1.25 five either
//! side (a false alarm about once in 30000 runs per check); the shipped tile's figures are in
//! `docs/blue-noise.md`.

use nyquist::hash::mix32;
use nyquist::sampler::screen_blue::{
    BlueFamily, LatticeBlue, OwenSobolBlue, Pmj02Blue, TILE_SIZE, initial_entry,
};
use nyquist::sampler::{BlueNoiseSampler, OwenSobolSampler, Sampler};
use nyquist_lab::blue_tile::{HELD_OUT, low_frequency_ratio};

const SIDE: u32 = 128;

/// Each pixel's estimate of `f` from `spp` samples of the 4-D block at `dim`.
fn estimates<S: Sampler>(s: &mut S, spp: u32, dim: u32, f: fn(&[f32; 4]) -> f64) -> Vec<f64> {
    let mut out = Vec::with_capacity((SIDE * SIDE) as usize);
    for y in 0..SIDE {
        for x in 0..SIDE {
            let mut sum = 0.0;
            for i in 0..spp {
                s.start_pixel_sample([x, y], i, dim);
                sum += f(&[s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()]);
            }
            out.push(sum / f64::from(spp));
        }
    }
    out
}

/// Each pixel's estimate of `f` from `spp` samples of family `F` with a hashed key per pixel
/// and rank 0 (white across pixels).
fn plain_estimates<F: BlueFamily>(spp: u32, f: fn(&[f32; 4]) -> f64) -> Vec<f64> {
    (0..SIDE * SIDE)
        .map(|p| {
            let e = initial_entry(mix32(p ^ 0x5eed) % (TILE_SIZE * TILE_SIZE));
            (0..spp).map(|i| f(&F::values(e, i))).sum::<f64>() / f64::from(spp)
        })
        .collect()
}

/// The first pair's integrands are blue at 1, 4 and 16 spp in both blocks (ratio below 0.8),
/// the other pair's and the 4-D ones below 1, where the plain family's error is white.
/// `white_first_pair` names the first-pair cells (integrand, spp) held only below 1: those
/// where the family's table leaves an error the tile cannot move (`pmj02-bn`'s centred disk
/// at 16 spp, 0.965 here, as white as OpenQMC's `pmjbn` with the same table, .93 on the peer
/// harness's image; `docs/blue-noise.md`).
fn the_error_is_blue_where_the_plain_family_is_white<F: BlueFamily>(
    white_first_pair: &[(&str, u32)],
) {
    for spp in [1, 4, 16] {
        for (k, (name, f)) in HELD_OUT.iter().enumerate() {
            let w = low_frequency_ratio(&plain_estimates::<F>(spp, *f), SIDE as usize);
            assert!(
                (0.75..1.25).contains(&w),
                "{} {name}, {spp} spp: {w}",
                F::NAME
            );
            for dim in [0, 4] {
                let mut blue = BlueNoiseSampler::<F>::new(spp, 0).unwrap();
                let b = low_frequency_ratio(&estimates(&mut blue, spp, dim, *f), SIDE as usize);
                eprintln!(
                    "{} {name}, dimensions from {dim}, {spp} spp: blue {b:.3}, plain {w:.3}",
                    F::NAME
                );
                let bound = if k < 2 && !white_first_pair.contains(&(*name, spp)) {
                    0.8
                } else {
                    1.0
                };
                assert!(
                    b < bound,
                    "{} {name}, dimensions from {dim}, {spp} spp: {b}",
                    F::NAME
                );
            }
        }
    }
}

#[test]
fn owen_sobol_bn_error_is_blue() {
    the_error_is_blue_where_the_plain_family_is_white::<OwenSobolBlue>(&[]);
}

#[test]
fn pmj02_bn_error_is_blue() {
    the_error_is_blue_where_the_plain_family_is_white::<Pmj02Blue>(&[("disk 0-1", 16)]);
}

#[test]
fn lattice_bn_error_is_blue() {
    the_error_is_blue_where_the_plain_family_is_white::<LatticeBlue>(&[]);
}

/// Each pixel's estimate has the variance of the plain family: the mean squared error over
/// the 16384 pixels agrees within 6 % (the two means' sampling error is a few per cent on the
/// disk's 0/1 values), at 1 spp too, where the rank stage picks which sample a pixel's first
/// one is. The ratios printed range from 0.950 to 1.016 (`cargo test -p nyquist-lab --test
/// screen_blue per_pixel -- --nocapture`); with the last rank bit chosen on the errors rather
/// than their deviations, `lattice-bn`'s Gaussian at 1 spp was 1.080.
fn per_pixel_error_is_the_plain_familys<F: BlueFamily>() {
    for spp in [1, 4, 16] {
        for (name, f) in HELD_OUT.iter().take(2) {
            let exact = {
                let mut s = OwenSobolSampler::new(1 << 16, 1).unwrap();
                let n = 1 << 16;
                (0..n)
                    .map(|i| {
                        s.start_pixel_sample([0, 0], i, 0);
                        f(&[s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()])
                    })
                    .sum::<f64>()
                    / f64::from(n)
            };
            let mse =
                |e: Vec<f64>| e.iter().map(|v| (v - exact).powi(2)).sum::<f64>() / e.len() as f64;
            let b = mse(estimates(
                &mut BlueNoiseSampler::<F>::new(spp, 0).unwrap(),
                spp,
                0,
                *f,
            ));
            let w = mse(plain_estimates::<F>(spp, *f));
            eprintln!(
                "{} {name}, {spp} spp: mean squared error {:.4} of the plain family's",
                F::NAME,
                b / w
            );
            assert!(
                (b / w - 1.0).abs() < 0.06,
                "{} {name}, {spp} spp: {b} against {w}",
                F::NAME
            );
        }
    }
}

#[test]
fn per_pixel_error_is_the_plain_samplers() {
    per_pixel_error_is_the_plain_familys::<OwenSobolBlue>();
    per_pixel_error_is_the_plain_familys::<Pmj02Blue>();
    per_pixel_error_is_the_plain_familys::<LatticeBlue>();
}

/// Frames: frame 1 is blue as frame 0 is, and its error is uncorrelated with frame 0's.
fn each_frame_is_blue_and_frames_are_uncorrelated<F: BlueFamily>() {
    let (_, disk) = HELD_OUT[0];
    let mut f0 = BlueNoiseSampler::<F>::new(4, 0).unwrap();
    let mut f1 = f0.clone().with_frame(1);
    let a = estimates(&mut f0, 4, 0, disk);
    let b = estimates(&mut f1, 4, 0, disk);
    assert!(low_frequency_ratio(&b, SIDE as usize) < 0.8, "{}", F::NAME);
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let (ma, mb) = (mean(&a), mean(&b));
    let cov: f64 = a.iter().zip(&b).map(|(x, y)| (x - ma) * (y - mb)).sum();
    let va: f64 = a.iter().map(|x| (x - ma).powi(2)).sum();
    let vb: f64 = b.iter().map(|y| (y - mb).powi(2)).sum();
    let r = cov / (va * vb).sqrt();
    // 16384 pixels: |r| of independent images is below 4/√16384 = 0.031 but once in 15000.
    assert!(r.abs() < 0.031, "{} {r}", F::NAME);
}

#[test]
fn each_frame_is_blue_and_frames_are_uncorrelated_in_every_family() {
    each_frame_is_blue_and_frames_are_uncorrelated::<OwenSobolBlue>();
    each_frame_is_blue_and_frames_are_uncorrelated::<Pmj02Blue>();
    each_frame_is_blue_and_frames_are_uncorrelated::<LatticeBlue>();
}
