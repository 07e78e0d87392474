//! Stratified 2D, Latin hypercube and shuffle over caller buffers, each beside a pbrt-v3-style
//! peer written here from pbrt-v3's published algorithm (same PCG32 generator for both):
//!
//! - pbrt-v3 `UniformFloat`: `min(next_u32 · 2⁻³², OneMinusEpsilon)`;
//! - pbrt-v3 `UniformUInt32(b)`: reject below `(2³² − b) mod b`, then `r mod b` (two integer
//!   divisions per draw);
//! - stratified 2D: `min((x + jitter) · dx, OneMinusEpsilon)` per coordinate;
//! - Latin hypercube: fill every dimension with `(i + u) / n`, then per dimension swap `j` with
//!   `j + UniformUInt32(n − j)`;
//! - shuffle: the same forward Fisher–Yates over blocks.

mod cpu_time;

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nyquist::ONE_MINUS_EPSILON;
use nyquist::rng::{DefaultRng, default_rng};
use nyquist::stratify::{Jitter, LatinHypercube, latin_hypercube, shuffle, stratified_2d};
use rand_core::Rng;

fn pbrt_uniform_float(rng: &mut DefaultRng) -> f32 {
    (rng.next_u32() as f32 * (1.0 / 4_294_967_296.0)).min(ONE_MINUS_EPSILON)
}

fn pbrt_uniform_u32(rng: &mut DefaultRng, b: u32) -> u32 {
    let threshold = b.wrapping_neg() % b;
    loop {
        let r = rng.next_u32();
        if r >= threshold {
            return r % b;
        }
    }
}

fn pbrt_stratified_2d(out: &mut [f32], nx: u32, ny: u32, rng: &mut DefaultRng) {
    let (dx, dy) = (1.0 / nx as f32, 1.0 / ny as f32);
    let mut k = 0;
    for y in 0..ny {
        for x in 0..nx {
            let jx = pbrt_uniform_float(rng);
            let jy = pbrt_uniform_float(rng);
            out[k] = ((x as f32 + jx) * dx).min(ONE_MINUS_EPSILON);
            out[k + 1] = ((y as f32 + jy) * dy).min(ONE_MINUS_EPSILON);
            k += 2;
        }
    }
}

fn pbrt_latin_hypercube(out: &mut [f32], n: usize, dims: usize, rng: &mut DefaultRng) {
    let inv = 1.0 / n as f32;
    for i in 0..n {
        for j in 0..dims {
            let sj = (i as f32 + pbrt_uniform_float(rng)) * inv;
            out[dims * i + j] = sj.min(ONE_MINUS_EPSILON);
        }
    }
    for i in 0..dims {
        for j in 0..n {
            let other = j + pbrt_uniform_u32(rng, (n - j) as u32) as usize;
            out.swap(dims * j + i, dims * other + i);
        }
    }
}

fn pbrt_shuffle<T>(buf: &mut [T], count: usize, dims: usize, rng: &mut DefaultRng) {
    for i in 0..count {
        let other = i + pbrt_uniform_u32(rng, (count - i) as u32) as usize;
        for j in 0..dims {
            buf.swap(dims * i + j, dims * other + j);
        }
    }
}

fn bench_stratified_2d(c: &mut Criterion<cpu_time::BenchClock>) {
    let (nx, ny) = (16u32, 16u32);
    let mut buf = vec![0.0f32; (2 * nx * ny) as usize];
    let mut g = c.benchmark_group("stratified_2d_16x16");
    g.throughput(Throughput::Elements(u64::from(nx * ny)));
    let mut rng = default_rng(1);
    g.bench_function("nyquist_stratified_2d_jittered", |b| {
        b.iter(|| stratified_2d(&mut buf, black_box(nx), ny, Jitter::Jittered, &mut rng).unwrap())
    });
    let mut rng = default_rng(1);
    g.bench_function("peer_pbrt_v3_stratified_2d", |b| {
        b.iter(|| pbrt_stratified_2d(&mut buf, black_box(nx), ny, &mut rng))
    });
    g.bench_function("nyquist_stratified_2d_centered", |b| {
        b.iter(|| stratified_2d(&mut buf, black_box(nx), ny, Jitter::Centered, &mut rng).unwrap())
    });
    g.finish();
}

fn bench_latin_hypercube(c: &mut Criterion<cpu_time::BenchClock>) {
    let (n, dims) = (256usize, 4u32);
    let mut buf = vec![0.0f32; n * dims as usize];
    let mut g = c.benchmark_group("latin_hypercube_256pts_4dims");
    g.throughput(Throughput::Elements((n * dims as usize) as u64));
    let mut rng = default_rng(2);
    g.bench_function("nyquist_latin_hypercube", |b| {
        b.iter(|| latin_hypercube(&mut buf, black_box(dims), &mut rng).unwrap())
    });
    let mut rng = default_rng(2);
    g.bench_function("peer_pbrt_v3_latin_hypercube", |b| {
        b.iter(|| pbrt_latin_hypercube(&mut buf, n, black_box(dims) as usize, &mut rng))
    });
    let lhs = LatinHypercube::new(dims, 2).unwrap();
    g.bench_function("nyquist_latin_hypercube_stateless_hash", |b| {
        b.iter(|| black_box(&lhs).fill(&mut buf).unwrap())
    });
    g.finish();
}

fn bench_shuffle(c: &mut Criterion<cpu_time::BenchClock>) {
    let n = 1024usize;
    let mut buf: Vec<f32> = (0..n).map(|i| i as f32).collect();
    let mut g = c.benchmark_group("shuffle_1024_f32");
    g.throughput(Throughput::Elements(n as u64));
    let mut rng = default_rng(3);
    g.bench_function("nyquist_shuffle", |b| {
        b.iter(|| shuffle(&mut buf, black_box(n), 1, &mut rng).unwrap())
    });
    let mut rng = default_rng(3);
    g.bench_function("peer_pbrt_v3_shuffle", |b| {
        b.iter(|| pbrt_shuffle(&mut buf, black_box(n), 1, &mut rng))
    });
    g.finish();

    let mut g = c.benchmark_group("shuffle_512_blocks_of_2_f32");
    g.throughput(Throughput::Elements(n as u64));
    let mut rng = default_rng(4);
    g.bench_function("nyquist_shuffle", |b| {
        b.iter(|| shuffle(&mut buf, black_box(n / 2), 2, &mut rng).unwrap())
    });
    let mut rng = default_rng(4);
    g.bench_function("peer_pbrt_v3_shuffle", |b| {
        b.iter(|| pbrt_shuffle(&mut buf, black_box(n / 2), 2, &mut rng))
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_stratified_2d,
    bench_latin_hypercube,
    bench_shuffle
}
criterion_main!(benches);
