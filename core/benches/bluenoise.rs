//! Void-and-cluster masks: the incremental method (`generate`: energy updated over the 13 × 13
//! kernel footprint, clusters and voids from tournament trees) against the straightforward one
//! (`generate_straightforward`: every pixel's energy updated and every pixel scanned at each
//! step), one 128 × 128 channel per iteration; 64 × 64 for the scaling. Also Poisson-disk sets
//! of about 1000 points (Bridson alone and maximal), 4096 points of the Fibonacci lattice and
//! R2, and the two-dimensional Korobov search (`Korobov::searched_2d`).
//!
//! Medians (shared 2-core VM, thread CPU time, `nice -n 15 cargo bench -p nyquist --bench
//! bluenoise -- --warm-up-time 1 --measurement-time 3`): 128²: fast 162 ms, straightforward
//! 4.48 s (27.6×); 64²: fast 35.0 ms, straightforward 247 ms (7.1×). Poisson disk, about 1000
//! points on the torus: Bridson 5.6 ms, maximal 36 ms. 4096 × 2 values: Fibonacci 6.7 ns per
//! value, R2 0.72 ns (`--measurement-time 2`).

mod cpu_time;

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nyquist::analysis::Topology;
use nyquist::bluenoise::{PoissonDisk, VoidAndCluster};
use nyquist::lattice::{FibonacciLattice, Korobov, Kronecker};
use nyquist::sequence::Sequence;

fn bench_masks(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("void_and_cluster");
    g.sample_size(10);
    for size in [64u32, 128] {
        let vc = VoidAndCluster::new(size, size, 1).unwrap();
        let (el, sl) = vc.scratch_len();
        let (mut ranks, mut energy, mut scratch) =
            (vec![0u32; vc.pixels()], vec![0.0f32; el], vec![0u32; sl]);
        g.bench_function(format!("fast_{size}"), |b| {
            b.iter(|| {
                vc.generate(&mut ranks, &mut energy, &mut scratch).unwrap();
                black_box(&ranks);
            })
        });
        g.bench_function(format!("straightforward_{size}"), |b| {
            b.iter(|| {
                vc.generate_straightforward(&mut ranks, &mut energy, &mut scratch)
                    .unwrap();
                black_box(&ranks);
            })
        });
    }
    g.finish();
}

/// Poisson-disk sets of about 1000 points on the torus: Bridson alone and maximal.
fn bench_poisson(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("poisson_disk_1000");
    g.sample_size(10);
    let pd = PoissonDisk::with_count(1000, Topology::Torus, 1).unwrap();
    for (name, pd) in [("bridson", pd), ("maximal", pd.maximal())] {
        let (cells, active) = pd.scratch_len();
        let (mut pts, mut grid, mut act) = (vec![0.0; 2 * cells], vec![0; cells], vec![0; active]);
        g.bench_function(name, |b| {
            b.iter(|| black_box(pd.generate(&mut pts, &mut grid, &mut act).unwrap()))
        });
    }
    g.finish();
}

/// 4096 points of the Fibonacci lattice (F_18 = 2584 … wrapped) and of R2, both dimensions.
fn bench_lattices(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("lattice_4096x2");
    g.throughput(criterion::Throughput::Elements(8192));
    let fib = FibonacciLattice::new(18).unwrap();
    let r2 = Kronecker::new(2).unwrap();
    let mut out = vec![0.0f32; 8192];
    g.bench_function("fibonacci", |b| {
        b.iter(|| {
            for (k, p) in out.chunks_exact_mut(2).enumerate() {
                p[0] = fib.sample(k as u64, 0);
                p[1] = fib.sample(k as u64, 1);
            }
            black_box(&out);
        })
    });
    g.bench_function("r2", |b| {
        b.iter(|| {
            r2.fill(0, 2, &mut out).unwrap();
            black_box(&out);
        })
    });
    g.finish();
}

/// `Korobov::searched_2d(n)`, the two-dimensional P₂ search `LatticeSampler::korobov` runs once
/// per sampler, at 2¹², 2¹⁶ and 2²⁰ points.
fn bench_korobov_search(c: &mut Criterion<cpu_time::BenchClock>) {
    let mut g = c.benchmark_group("korobov_searched_2d");
    g.sample_size(10);
    for log2 in [12u32, 16, 20] {
        g.bench_function(format!("2^{log2}"), |b| {
            b.iter(|| Korobov::searched_2d(black_box(1 << log2)).unwrap())
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_masks, bench_poisson, bench_lattices, bench_korobov_search
}
criterion_main!(benches);
