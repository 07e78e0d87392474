//! Periodogram of 1024 random points: the rotating-phasor direct sum (rayon over rows) beside a
//! naive direct sum that calls sin/cos for every point and frequency, on the same 65×65 grid,
//! plus the 257×257 grid of the speed target (≤ 1 s).
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nyquist::rng::{default_rng, uniform_f64};
use nyquist_film::periodogram::periodogram;
use std::f64::consts::TAU;
use std::hint::black_box;

fn naive(points: &[[f64; 2]], f: i64) -> Vec<f64> {
    let mut out = Vec::new();
    for fy in -f..=f {
        for fx in -f..=f {
            let (mut re, mut im) = (0.0, 0.0);
            for p in points {
                let (s, c) = (TAU * (fx as f64 * p[0] + fy as f64 * p[1])).sin_cos();
                re += c;
                im -= s;
            }
            out.push((re * re + im * im) / points.len() as f64);
        }
    }
    out
}

fn bench(c: &mut Criterion) {
    let mut rng = default_rng(9);
    let pts: Vec<[f64; 2]> = (0..1024)
        .map(|_| [uniform_f64(&mut rng), uniform_f64(&mut rng)])
        .collect();
    let mut g = c.benchmark_group("periodogram_1024");
    g.sample_size(10);
    g.throughput(Throughput::Elements(65 * 65));
    g.bench_function("rotating_65x65", |b| {
        b.iter(|| periodogram(&[black_box(&pts)], 32).unwrap())
    });
    g.bench_function("naive_sincos_65x65", |b| {
        b.iter(|| naive(black_box(&pts), 32))
    });
    g.throughput(Throughput::Elements(257 * 257));
    g.bench_function("rotating_257x257", |b| {
        b.iter(|| periodogram(&[black_box(&pts)], 128).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
