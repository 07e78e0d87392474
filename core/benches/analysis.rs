//! Analysis measures: exact 2D star discrepancy, L2 discrepancies and the minimum distance, each
//! beside a slower peer (the general enumerator, the O(N²) pair scan) in the same group.
mod cpu_time;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use nyquist::analysis::{
    PointSet, Topology, centered_l2_discrepancy, l2_star_discrepancy, min_distance,
    min_distance_scratch_len, star_discrepancy_2d, star_discrepancy_enumerate,
    star_discrepancy_scratch_len, wraparound_l2_discrepancy,
};
use nyquist::rng::{default_rng, uniform_f64};
use std::hint::black_box;

fn random(n: usize, seed: u64) -> Vec<f64> {
    let mut rng = default_rng(seed);
    (0..2 * n).map(|_| uniform_f64(&mut rng)).collect()
}

fn naive_min_distance(pts: &[f64]) -> f64 {
    let n = pts.len() / 2;
    let mut best = f64::INFINITY;
    for i in 0..n {
        let (x, y) = (pts[2 * i], pts[2 * i + 1]);
        for j in i + 1..n {
            let (dx, dy) = (x - pts[2 * j], y - pts[2 * j + 1]);
            best = best.min(dx * dx + dy * dy);
        }
    }
    best.sqrt()
}

fn star(c: &mut Criterion<cpu_time::BenchClock>) {
    const N: usize = 4096;
    let pts = random(N, 1);
    let set = PointSet::new(&pts, 2).unwrap();
    let mut scratch = vec![0.0; star_discrepancy_scratch_len(N, 2).unwrap()];
    let mut g = c.benchmark_group("star_2d_4096");
    g.throughput(Throughput::Elements(N as u64));
    g.sample_size(10);
    g.bench_function("sweep", |b| {
        b.iter(|| star_discrepancy_2d(black_box(&set), &mut scratch).unwrap())
    });
    g.bench_function("enumerate", |b| {
        b.iter(|| star_discrepancy_enumerate(black_box(&set), &mut scratch).unwrap())
    });
    g.finish();
}

fn l2(c: &mut Criterion<cpu_time::BenchClock>) {
    const N: usize = 4096;
    let pts = random(N, 2);
    let set = PointSet::new(&pts, 2).unwrap();
    let mut g = c.benchmark_group("l2_4096_d2");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("l2_star", |b| {
        b.iter(|| l2_star_discrepancy(black_box(&set)))
    });
    g.bench_function("centered", |b| {
        b.iter(|| centered_l2_discrepancy(black_box(&set)))
    });
    g.bench_function("wraparound", |b| {
        b.iter(|| wraparound_l2_discrepancy(black_box(&set)))
    });
    g.finish();
}

fn distance(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("min_distance");
    g.sample_size(10);
    for n in [4096usize, 1_000_000] {
        let pts = random(n, 3);
        let set = PointSet::new(&pts, 2).unwrap();
        let mut scratch = vec![0u64; min_distance_scratch_len(n).unwrap()];
        g.throughput(Throughput::Elements(n as u64));
        for (name, t) in [
            ("grid_square", Topology::Square),
            ("grid_torus", Topology::Torus),
        ] {
            g.bench_with_input(BenchmarkId::new(name, n), &n, |b, _| {
                b.iter(|| min_distance(black_box(&set), t, &mut scratch).unwrap())
            });
        }
        if n == 4096 {
            g.bench_with_input(BenchmarkId::new("naive_pairs", n), &n, |b, _| {
                b.iter(|| naive_min_distance(black_box(&pts)))
            });
        }
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = star, l2, distance
}
criterion_main!(benches);
