//! Sobol by index: our `sobol_u32` beside the textbook kernels over the same direction numbers.
//!
//! Workloads: 64 dimensions (0..63) × 1024 indices, once with coherent indices `0..1024` (few set
//! bits, the case of a sampler walking a pixel's samples) and once with incoherent, hashed 32-bit
//! indices (16 set bits on average, the case of a global sequence over a large image). Every
//! kernel reads the same `[[u32; 32]; 64]` columns. Throughput is per value.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nyquist::hash::mix32;
use nyquist::sequence::{Sequence, Sobol, sobol_u32};

const DIMS: u32 = 64;
const POINTS: u32 = 1024;

/// The columns of dimensions `0..DIMS`, read back through the public API.
fn columns() -> Vec<[u32; 32]> {
    (0..DIMS)
        .map(|d| core::array::from_fn(|k| sobol_u32(1 << k, d)))
        .collect()
}

/// Peer 1: the naive product, one test per bit over all 32 bits.
#[inline(never)]
fn naive_all_bits(m: &[u32; 32], index: u32) -> u32 {
    let mut v = 0;
    for (k, &col) in m.iter().enumerate() {
        if (index >> k) & 1 == 1 {
            v ^= col;
        }
    }
    v
}

/// Peer 2: the classic loop (pbrt-v3 `MultiplyGenerator`): shift the index until it is zero.
#[inline(never)]
fn shift_loop(m: &[u32; 32], mut index: u32) -> u32 {
    let mut v = 0;
    let mut k = 0;
    while index != 0 {
        if index & 1 != 0 {
            v ^= m[k];
        }
        index >>= 1;
        k += 1;
    }
    v
}

/// Candidate: visit only the set bits via trailing zeros.
#[inline(never)]
fn trailing_zeros_loop(m: &[u32; 32], mut index: u32) -> u32 {
    let mut v = 0;
    while index != 0 {
        v ^= m[index.trailing_zeros() as usize];
        index &= index - 1;
    }
    v
}

fn indices(coherent: bool) -> Vec<u32> {
    (0..POINTS)
        .map(|i| if coherent { i } else { mix32(i ^ 0x9e37_79b9) })
        .collect()
}

fn bench_kernels(c: &mut Criterion) {
    let cols = columns();
    let ours = Sobol::new(DIMS).unwrap();
    for (name, coherent) in [("coherent", true), ("incoherent", false)] {
        let idx = indices(coherent);
        let mut g = c.benchmark_group(format!("sobol_by_index_64dims_{name}"));
        g.throughput(Throughput::Elements(u64::from(DIMS * POINTS)));
        g.bench_function("nyquist_sobol_u32", |b| {
            b.iter(|| {
                let mut acc = 0u32;
                for d in 0..DIMS {
                    for &i in &idx {
                        acc ^= sobol_u32(black_box(i), d);
                    }
                }
                acc
            })
        });
        g.bench_function("nyquist_sobol_sample_f32", |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for d in 0..DIMS {
                    for &i in &idx {
                        acc += ours.sample(u64::from(black_box(i)), d);
                    }
                }
                acc
            })
        });
        type Kernel = fn(&[u32; 32], u32) -> u32;
        let peers: [(&str, Kernel); 3] = [
            ("peer_naive_all_32_bits", naive_all_bits),
            ("peer_while_index_shift_loop", shift_loop),
            ("candidate_trailing_zeros_loop", trailing_zeros_loop),
        ];
        for (peer, kernel) in peers {
            g.bench_function(peer, |b| {
                b.iter(|| {
                    let mut acc = 0u32;
                    for m in &cols {
                        for &i in &idx {
                            acc ^= kernel(m, black_box(i));
                        }
                    }
                    acc
                })
            });
        }
        g.finish();
    }
}

fn bench_fill(c: &mut Criterion) {
    // Point-major fill of 1024 consecutive points × 64 dims: the trait's default (one `sample`
    // per value) against Sobol's incremental override.
    struct ViaSample(Sobol);
    impl Sequence for ViaSample {
        fn dims(&self) -> u32 {
            self.0.dims()
        }
        fn point_count(&self) -> Option<u64> {
            self.0.point_count()
        }
        fn sample(&self, index: u64, dim: u32) -> f32 {
            self.0.sample(index, dim)
        }
    }
    let sobol = Sobol::new(DIMS).unwrap();
    let default_fill = ViaSample(sobol);
    let mut buf = vec![0.0f32; (DIMS * POINTS) as usize];
    let mut g = c.benchmark_group("sobol_fill_1024pts_64dims");
    g.throughput(Throughput::Elements(u64::from(DIMS * POINTS)));
    g.bench_function("nyquist_sobol_fill", |b| {
        b.iter(|| sobol.fill(black_box(4096), DIMS, &mut buf).unwrap())
    });
    g.bench_function("peer_default_fill_via_sample", |b| {
        b.iter(|| default_fill.fill(black_box(4096), DIMS, &mut buf).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench_kernels, bench_fill);
criterion_main!(benches);
