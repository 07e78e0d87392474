//! Void-and-cluster masks: the incremental method (`generate`: energy updated over the 13 × 13
//! kernel footprint, clusters and voids from tournament trees) against the straightforward one
//! (`generate_straightforward`: every pixel's energy updated and every pixel scanned at each
//! step), one 128 × 128 channel per iteration; 64 × 64 for the scaling.
//!
//! Medians (shared 2-core VM, thread CPU time, `nice -n 15 cargo bench -p nyquist --bench
//! bluenoise -- --warm-up-time 1 --measurement-time 3`): 128²: fast 162 ms, straightforward
//! 4.48 s (27.6×); 64²: fast 35.0 ms, straightforward 247 ms (7.1×).

mod cpu_time;

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nyquist::bluenoise::VoidAndCluster;

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

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_masks
}
criterion_main!(benches);
