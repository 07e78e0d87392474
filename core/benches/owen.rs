//! Owen-scrambled Sobol per value: ours beside the `sobol_burley` crate (0.5, Burley's
//! construction with the same LK-hash constants), same indices, dimensions and seed, in the
//! same run.
//!
//! Workloads: indices `0..4096` (inside `sobol_burley`'s 2¹⁶ limit) × dimensions `0..64` (its
//! dimension sets 0..16), and × dimensions `64..256` (the rest of what `sobol_burley` has).
//! Single values: our `Sequence::sample` against `sobol_burley::sample`; four at a time: our
//! `OwenSobol::sample_4d` against `sobol_burley::sample_4d`. Throughput is per value.

mod cpu_time;

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nyquist::sequence::{OwenSobol, Sequence};

const POINTS: u32 = 4096;
const SEED: u32 = 0x5eed;

fn bench_owen_sobol(c: &mut Criterion<cpu_time::BenchClock>) {
    let ours = OwenSobol::new(1024, u64::from(SEED)).unwrap();
    for (label, dims) in [("dims_0_64", 0u32..64), ("dims_64_256", 64..256)] {
        let values = u64::from(POINTS) * u64::from(dims.end - dims.start);
        let mut g = c.benchmark_group(format!("owen_sobol_4096pts_{label}"));
        g.throughput(Throughput::Elements(values));
        let d = dims.clone();
        g.bench_function("nyquist_sample", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for i in 0..POINTS {
                    for dim in d.clone() {
                        acc += ours.sample(u64::from(black_box(i)), dim);
                    }
                }
                acc
            })
        });
        let d = dims.clone();
        g.bench_function("peer_sobol_burley_sample", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for i in 0..POINTS {
                    for dim in d.clone() {
                        acc += sobol_burley::sample(black_box(i), dim, SEED);
                    }
                }
                acc
            })
        });
        let d = dims.clone();
        g.bench_function("nyquist_sample_4d", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for i in 0..POINTS {
                    for set in d.clone().step_by(4) {
                        let v = ours.sample_4d(u64::from(black_box(i)), set);
                        acc += v[0] + v[1] + v[2] + v[3];
                    }
                }
                acc
            })
        });
        let d = dims.clone();
        g.bench_function("peer_sobol_burley_sample_4d", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for i in 0..POINTS {
                    for dim in d.clone().step_by(4) {
                        let v = sobol_burley::sample_4d(black_box(i), dim / 4, SEED);
                        acc += v[0] + v[1] + v[2] + v[3];
                    }
                }
                acc
            })
        });
        g.finish();
    }
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_owen_sobol
}
criterion_main!(benches);
