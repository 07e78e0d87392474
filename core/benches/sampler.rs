//! Samplers: one camera sample (5 values) on the stateless layer, and the request-and-fill layer
//! filling a pixel of 16 samples with two 2D arrays of 4.
//!
//! Peers in the same group: a bare PCG32 drawing 5 floats (the floor for any sampler) and, for
//! the request-and-fill layer, the same work done by hand through the stateless layer.
//! Targets (issue 4): ≤ 15 ns per camera sample for halton, stratified, zero-two, sobol;
//! ≤ 1 µs per 16-sample pixel with two 2D arrays of 4.

mod cpu_time;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use nyquist::rng::{default_rng, uniform_f32};
use nyquist::sampler::{
    BestCandidateSampler, HaltonSampler, HaltonScramble, Jitter, PixelRangeSampler, RandomSampler,
    Sample, SampleLayout, Sampler, SobolSampler, StratifiedSampler, ZeroTwoSampler, camera_sample,
};
use std::hint::black_box;

const SPP: u32 = 16;
/// Camera samples per iteration: 8 × 8 pixels × 16 samples (coherent pixel order).
const PIXELS: u32 = 8;

fn camera<S: Sampler>(s: &mut S) -> f32 {
    let mut acc = 0.0;
    for y in 0..PIXELS {
        for x in 0..PIXELS {
            for i in 0..SPP {
                let c = camera_sample(s, [x + 100, y + 50], i);
                acc += c.p_film[0] + c.p_film[1] + c.time + c.lens[0] + c.lens[1];
            }
        }
    }
    acc
}

fn camera_sample_bench(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("camera_sample");
    g.throughput(Throughput::Elements(u64::from(PIXELS * PIXELS * SPP)));
    g.bench_function("pcg32_5_floats_peer", |b| {
        let mut rng = default_rng(1);
        b.iter(|| {
            let mut acc = 0.0;
            for _ in 0..PIXELS * PIXELS * SPP {
                for _ in 0..5 {
                    acc += uniform_f32(&mut rng);
                }
            }
            black_box(acc)
        })
    });
    macro_rules! bench {
        ($name:expr, $s:expr) => {
            g.bench_function($name, |b| {
                let mut s = $s;
                b.iter(|| black_box(camera(&mut s)))
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
    bench!("sobol", SobolSampler::new([1024, 1024], SPP, 1).unwrap());
    bench!(
        "halton",
        HaltonSampler::new([1024, 1024], SPP, HaltonScramble::None, 1).unwrap()
    );
    g.finish();
}

fn fill_pixel<S: Sampler>(r: &mut PixelRangeSampler<S>, sample: &mut Sample<'_>) -> f32 {
    let mut acc = 0.0;
    while r.next_sample(sample) {
        acc += sample.as_slice().iter().sum::<f32>();
    }
    acc
}

fn by_hand<S: Sampler>(s: &mut S, pixel: [u32; 2], out: &mut [f32; 21]) -> f32 {
    let mut acc = 0.0;
    for i in 0..SPP {
        let c = camera_sample(s, pixel, i);
        out[..5].copy_from_slice(&[c.p_film[0], c.p_film[1], c.lens[0], c.lens[1], c.time]);
        s.get_array_2d(&mut out[5..13]);
        s.get_array_2d(&mut out[13..21]);
        acc += out.iter().sum::<f32>();
    }
    acc
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
                    black_box(fill_pixel(&mut r, &mut sample))
                })
            });
            g.bench_with_input(BenchmarkId::new("by_hand_peer", $name), &s, |b, s| {
                let mut s = s.clone();
                let mut out = [0.0f32; 21];
                b.iter(|| black_box(by_hand(&mut s, [7, 9], &mut out)))
            });
        };
    }
    bench!(
        "stratified",
        StratifiedSampler::new(4, 4, Jitter::Jittered, 1).unwrap()
    );
    bench!("random", RandomSampler::new(SPP, 1).unwrap());
    bench!("zero_two", ZeroTwoSampler::new(SPP, 1).unwrap());
    bench!("sobol", SobolSampler::new([1024, 1024], SPP, 1).unwrap());
    bench!(
        "halton",
        HaltonSampler::new([1024, 1024], SPP, HaltonScramble::None, 1).unwrap()
    );
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = camera_sample_bench, request_and_fill_bench
}
criterion_main!(benches);
