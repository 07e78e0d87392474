//! What the compact const-generic point sets (`nyquist::compact`) cost on the desktop beside the
//! table paths they equal bit for bit: one value per call, 1024 indices, coherent (`0..1024`, a
//! pixel's samples) and incoherent (hashed 32-bit indices, a global sequence over a large image).
//! And the compact pixel samplers beside the desktop ones: camera-sample loops (`camera_sample`,
//! `get_1d`, `get_2d`) over 64 pixels of a scanline, 16 samples each, pixel by pixel.

mod cpu_time;

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nyquist::compact;
use nyquist::hash::mix32;
use nyquist::sampler::{self, Sampler};
use nyquist::scramble::Scramble;
use nyquist::sequence::{Halton, OwenSobol, Sequence, Sobol};

const POINTS: u32 = 1024;

fn indices(coherent: bool) -> Vec<u64> {
    (0..POINTS)
        .map(|i| u64::from(if coherent { i } else { mix32(i ^ 0x5eed) }))
        .collect()
}

/// Sums `set.sample(i, d)` over the indices and dimensions `0..dims`.
fn bench_set(
    g: &mut criterion::BenchmarkGroup<'_, cpu_time::BenchClock>,
    name: &str,
    set: &impl Sequence,
    dims: u32,
    idx: &[u64],
) {
    g.bench_function(name, |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for &i in idx {
                for d in 0..dims {
                    acc += set.sample(black_box(i), d);
                }
            }
            acc
        })
    });
}

fn bench_compact(c: &mut Criterion<cpu_time::BenchClock>) {
    for (kind, coherent) in [("coherent", true), ("incoherent", false)] {
        let idx = indices(coherent);
        for (dims, name) in [(2u32, "halton_2d"), (16, "halton_16d")] {
            let mut g = c.benchmark_group(format!("compact_{name}_{kind}"));
            g.throughput(Throughput::Elements(u64::from(dims * POINTS)));
            bench_set(&mut g, "table", &Halton::new(dims).unwrap(), dims, &idx);
            if dims == 2 {
                bench_set(&mut g, "compact", &compact::Halton::<2>::new(), dims, &idx);
            } else {
                bench_set(&mut g, "compact", &compact::Halton::<16>::new(), dims, &idx);
            }
            g.finish();
        }
        let mut g = c.benchmark_group(format!("compact_sobol_4d_{kind}"));
        g.throughput(Throughput::Elements(u64::from(4 * POINTS)));
        bench_set(&mut g, "table", &Sobol::new(4).unwrap(), 4, &idx);
        bench_set(&mut g, "compact", &compact::Sobol::<4>::new(), 4, &idx);
        g.finish();
        let mut g = c.benchmark_group(format!("compact_owen_sobol_4d_{kind}"));
        g.throughput(Throughput::Elements(u64::from(4 * POINTS)));
        bench_set(&mut g, "table", &OwenSobol::new(4, 7).unwrap(), 4, &idx);
        bench_set(&mut g, "compact", &compact::OwenSobol::<4>::new(7), 4, &idx);
        let (table, small) = (
            OwenSobol::new(4, 7).unwrap(),
            compact::OwenSobol::<4>::new(7),
        );
        g.bench_function("table_sample_4d", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for &i in &idx {
                    acc += table
                        .sample_4d(u64::from(black_box(i) as u32), 0)
                        .iter()
                        .sum::<f32>();
                }
                acc
            })
        });
        g.bench_function("compact_sample_4d", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for &i in &idx {
                    acc += small
                        .sample_4d(u64::from(black_box(i) as u32), 0)
                        .iter()
                        .sum::<f32>();
                }
                acc
            })
        });
        g.finish();
    }
}

/// 1024 camera-sample loops: 64 pixels along a scanline, their 16 samples each in turn.
fn bench_camera(
    g: &mut criterion::BenchmarkGroup<'_, cpu_time::BenchClock>,
    name: &str,
    s: &mut impl Sampler,
) {
    g.bench_function(name, |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for k in 0..1024u32 {
                let c = s.camera_sample(black_box([100 + k / 16, 37]), k % 16);
                let [u, v] = s.get_2d();
                acc += c.p_film[0] + c.time + c.lens[1] + s.get_1d() + u + v;
            }
            acc
        })
    });
}

/// The group of one sampler's camera loops, 1024 per iteration.
fn group<'a>(
    c: &'a mut Criterion<cpu_time::BenchClock>,
    name: &str,
) -> criterion::BenchmarkGroup<'a, cpu_time::BenchClock> {
    let mut g = c.benchmark_group(format!("compact_camera_{name}"));
    g.throughput(Throughput::Elements(1024));
    g
}

fn bench_samplers(c: &mut Criterion<cpu_time::BenchClock>) {
    let (res, how) = ([1920, 1080], Scramble::FastOwen);
    let mut g = group(c, "owen_sobol");
    bench_camera(
        &mut g,
        "desktop",
        &mut sampler::OwenSobolSampler::new(16, 7).unwrap(),
    );
    bench_camera(
        &mut g,
        "compact",
        &mut compact::OwenSobolSampler::<8>::new(16, 7).unwrap(),
    );
    g.finish();
    let mut g = group(c, "zsobol");
    bench_camera(
        &mut g,
        "desktop",
        &mut sampler::ZSobolSampler::new(res, 16, how, 7).unwrap(),
    );
    bench_camera(
        &mut g,
        "compact",
        &mut compact::ZSobolSampler::new(res, 16, how, 7).unwrap(),
    );
    g.finish();
    let mut g = group(c, "sobol_owen");
    let desk = sampler::SobolSampler::new(res, 16, Scramble::Owen, 7);
    let small = compact::SobolSampler::<8>::new(res, 16, Scramble::Owen, 7);
    bench_camera(&mut g, "desktop", &mut desk.unwrap());
    bench_camera(&mut g, "compact", &mut small.unwrap());
    g.finish();
    let mut g = group(c, "pmj02");
    bench_camera(
        &mut g,
        "desktop",
        &mut sampler::Pmj02Sampler::new(16, 7).unwrap(),
    );
    bench_camera(
        &mut g,
        "compact",
        &mut compact::Pmj02Sampler::new(16, 7).unwrap(),
    );
    g.finish();
    for how in Scramble::ALL {
        let mut g = group(c, &format!("halton_{}", how.name()));
        let desk = sampler::HaltonSampler::new(res, 16, how, 7);
        bench_camera(&mut g, "desktop", &mut desk.unwrap());
        let small = compact::HaltonSampler::<8>::new(res, 16, how, 7);
        bench_camera(&mut g, "compact", &mut small.unwrap());
        g.finish();
    }
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_compact, bench_samplers
}
criterion_main!(benches);
