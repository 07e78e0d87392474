//! pmj02: the baked table by index, the sampler, and the construction.
//!
//! Workloads, each reported per value (criterion's element throughput):
//! - `pmj02_by_index`: 4096 hashed (incoherent) indices over the whole 2^16-point table, both
//!   dimensions (8192 values), plain and Owen-scrambled; a sequential run for contrast. Target:
//!   ≤ 2 ns per value.
//! - `pmj02_sampler`: `get_pixel_2d` over an 8 × 8-pixel tile at 16 spp (2 values per call),
//!   and the camera sample (5 values per call).
//! - `pmj02_build`: the in-place construction of 2^16 points, per point.
//!
//! The Owen-scrambled `sample` hands one value per call to `black_box`; `sample_2d` runs its two
//! scrambles side by side. Figures: `docs/performance.md`.

mod cpu_time;

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nyquist::hash::mix32;
use nyquist::sampler::{Pmj02Sampler, Sampler, camera_sample};
use nyquist::sequence::{PMJ02_MAX_POINTS, Pmj02, Sequence, pmj02_build};

const POINTS: u32 = 4096;
const SPP: u32 = 16;
const PIXELS: u32 = 8;

fn bench_by_index(c: &mut Criterion<cpu_time::BenchClock>) {
    let hashed: Vec<u32> = (0..POINTS)
        .map(|i| mix32(i ^ 0x9e37_79b9) & 0xffff)
        .collect();
    let sequential: Vec<u32> = (0..POINTS).collect();
    let mut g = c.benchmark_group("pmj02_by_index");
    g.throughput(Throughput::Elements(u64::from(2 * POINTS)));
    for (name, p) in [("plain", Pmj02::new()), ("owen", Pmj02::scrambled(7))] {
        for (order, idx) in [("hashed", &hashed), ("sequential", &sequential)] {
            g.bench_function(format!("{name}_{order}_sample_f32"), |b| {
                b.iter(|| {
                    for &i in idx {
                        let i = u64::from(black_box(i));
                        black_box(p.sample(i, 0));
                        black_box(p.sample(i, 1));
                    }
                })
            });
        }
        g.bench_function(format!("{name}_hashed_sample_u32"), |b| {
            b.iter(|| {
                for &i in &hashed {
                    let i = black_box(i);
                    black_box(p.sample_u32(i, 0));
                    black_box(p.sample_u32(i, 1));
                }
            })
        });
        g.bench_function(format!("{name}_hashed_sample_2d"), |b| {
            b.iter(|| {
                for &i in &hashed {
                    black_box(p.sample_2d(black_box(i)));
                }
            })
        });
        // The same points through the batch read.
        let mut out = vec![[0.0f32; 2]; hashed.len()];
        g.bench_function(format!("{name}_hashed_fill_2d"), |b| {
            b.iter(|| {
                p.fill_2d(black_box(&hashed), &mut out).unwrap();
                black_box(&mut out);
            })
        });
    }
    g.finish();
}

fn bench_sampler(c: &mut Criterion<cpu_time::BenchClock>) {
    let calls = u64::from(PIXELS * PIXELS * SPP);
    let mut g = c.benchmark_group("pmj02_sampler");
    g.throughput(Throughput::Elements(2 * calls));
    g.bench_function("get_pixel_2d", |b| {
        let mut s = Pmj02Sampler::new(SPP, 1).unwrap();
        b.iter(|| {
            for y in 0..PIXELS {
                for x in 0..PIXELS {
                    for i in 0..SPP {
                        s.start_pixel_sample([x + 100, y + 50], i, 0);
                        black_box(s.get_pixel_2d());
                    }
                }
            }
        })
    });
    g.throughput(Throughput::Elements(5 * calls));
    g.bench_function("camera_sample", |b| {
        let mut s = Pmj02Sampler::new(SPP, 1).unwrap();
        b.iter(|| {
            for y in 0..PIXELS {
                for x in 0..PIXELS {
                    for i in 0..SPP {
                        black_box(camera_sample(&mut s, [x + 100, y + 50], i));
                    }
                }
            }
        })
    });
    g.finish();
}

fn bench_build(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut buf = vec![[0u32; 2]; PMJ02_MAX_POINTS];
    let mut g = c.benchmark_group("pmj02_build");
    g.throughput(Throughput::Elements(PMJ02_MAX_POINTS as u64));
    g.bench_function("65536_points", |b| {
        b.iter(|| pmj02_build(black_box(3), &mut buf).unwrap())
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_by_index, bench_sampler, bench_build
}
criterion_main!(benches);
