//! Samplers: one camera sample (5 values) on the stateless layer, and the request-and-fill layer
//! filling a pixel of 16 samples with two 2D arrays of 4.
//!
//! Peers in the same group: a bare PCG32 drawing 5 floats (the floor for any sampler) and, for
//! the request-and-fill layer, the same work done by hand through the stateless layer.
//! Targets: ≤ 15 ns per camera sample for halton, stratified, zero-two, sobol; ≤ 1 µs per
//! 16-sample pixel with two 2D arrays of 4; ≤ 20 ns per ZSobol camera sample (owen_sobol is
//! measured beside it). Figures: `docs/performance.md`.

mod cpu_time;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use nyquist::rng::{default_rng, uniform_f32};
use nyquist::sampler::{
    BestCandidateSampler, HaltonSampler, Jitter, OwenSobolSampler, PixelRangeSampler,
    RandomSampler, Sample, SampleLayout, Sampler, SobolSampler, StratifiedSampler, ZSobolSampler,
    ZeroTwoSampler, camera_sample,
};
use nyquist::scramble::Scramble;
use std::hint::black_box;

const SPP: u32 = 16;
/// Camera samples per iteration: 8 × 8 pixels × 16 samples (coherent pixel order).
const PIXELS: u32 = 8;

/// Every camera sample of the 8 × 8 pixels, each handed to `black_box` as a renderer hands it
/// to its camera. (Not summed: a running `f32` sum is a serial chain of five 3-cycle adds per
/// sample, the consumer's latency timed with the sampler's work.)
fn camera<S: Sampler>(s: &mut S) {
    for y in 0..PIXELS {
        for x in 0..PIXELS {
            for i in 0..SPP {
                black_box(camera_sample(s, [x + 100, y + 50], i));
            }
        }
    }
}

fn camera_sample_bench(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("camera_sample");
    g.throughput(Throughput::Elements(u64::from(PIXELS * PIXELS * SPP)));
    g.bench_function("pcg32_5_floats_peer", |b| {
        let mut rng = default_rng(1);
        b.iter(|| {
            for _ in 0..PIXELS * PIXELS * SPP {
                black_box([(); 5].map(|_| uniform_f32(&mut rng)));
            }
        })
    });
    macro_rules! bench {
        ($name:expr, $s:expr) => {
            g.bench_function($name, |b| {
                let mut s = $s;
                b.iter(|| camera(&mut s))
            });
        };
    }
    bench!("random", RandomSampler::new(SPP, 1).unwrap());
    bench!(
        "stratified",
        StratifiedSampler::new(4, 4, Jitter::Jittered, 1).unwrap()
    );
    bench!("best_candidate", BestCandidateSampler::new(SPP, 1).unwrap());
    bench!("zero_two", ZeroTwoSampler::new(SPP, 1).unwrap());
    bench!(
        "sobol",
        SobolSampler::new([1024, 1024], SPP, Scramble::PermuteDigits, 1).unwrap()
    );
    bench!(
        "halton",
        HaltonSampler::new([1024, 1024], SPP, Scramble::None, 1).unwrap()
    );
    bench!(
        "zsobol",
        ZSobolSampler::new([1024, 1024], SPP, Scramble::FastOwen, 1).unwrap()
    );
    bench!("owen_sobol", OwenSobolSampler::new(SPP, 1).unwrap());
    bench!(
        "zsobol_unscrambled",
        ZSobolSampler::new([1024, 1024], SPP, Scramble::None, 1).unwrap()
    );
    g.finish();
}

/// Fills every sample of the pixel, each handed to `black_box` once filled. (Not summed: a
/// running sum of the 336 values is a serial chain of 3-cycle adds, about 0.35 µs of the
/// consumer measured as the fill.)
fn fill_pixel<S: Sampler>(r: &mut PixelRangeSampler<S>, sample: &mut Sample<'_>) {
    while r.next_sample(sample) {
        black_box(sample.as_slice());
    }
}

fn by_hand<S: Sampler>(s: &mut S, pixel: [u32; 2], out: &mut [f32; 21]) {
    for i in 0..SPP {
        let c = camera_sample(s, pixel, i);
        out[..5].copy_from_slice(&[c.p_film[0], c.p_film[1], c.lens[0], c.lens[1], c.time]);
        s.get_array_2d(&mut out[5..13]);
        s.get_array_2d(&mut out[13..21]);
        black_box(&out[..]);
    }
}

fn request_and_fill_bench(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("request_and_fill_pixel_16spp_two_2d_arrays_of_4");
    g.throughput(Throughput::Elements(1));
    macro_rules! bench {
        ($name:expr, $s:expr) => {
            let s = $s;
            let mut layout = SampleLayout::<2>::new();
            layout.add_2d(&s, 4).unwrap();
            layout.add_2d(&s, 4).unwrap();
            assert_eq!(layout.len(), 21);
            g.bench_with_input(BenchmarkId::new("layout", $name), &s, |b, s| {
                let mut buf = [0.0f32; 21];
                let mut sample = Sample::new(&layout, &mut buf).unwrap();
                b.iter(|| {
                    let mut r = PixelRangeSampler::new(s.clone(), [7, 9], [8, 10]).unwrap();
                    fill_pixel(&mut r, &mut sample)
                })
            });
            g.bench_with_input(BenchmarkId::new("by_hand_peer", $name), &s, |b, s| {
                let mut s = s.clone();
                let mut out = [0.0f32; 21];
                b.iter(|| by_hand(&mut s, [7, 9], &mut out))
            });
        };
    }
    bench!(
        "stratified",
        StratifiedSampler::new(4, 4, Jitter::Jittered, 1).unwrap()
    );
    bench!("random", RandomSampler::new(SPP, 1).unwrap());
    bench!("zero_two", ZeroTwoSampler::new(SPP, 1).unwrap());
    bench!(
        "sobol",
        SobolSampler::new([1024, 1024], SPP, Scramble::PermuteDigits, 1).unwrap()
    );
    bench!(
        "halton",
        HaltonSampler::new([1024, 1024], SPP, Scramble::None, 1).unwrap()
    );
    bench!(
        "zsobol",
        ZSobolSampler::new([1024, 1024], SPP, Scramble::FastOwen, 1).unwrap()
    );
    bench!("owen_sobol", OwenSobolSampler::new(SPP, 1).unwrap());
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = camera_sample_bench, request_and_fill_bench
}
criterion_main!(benches);
