//! Sobol by index: our `sobol_u32` beside the textbook kernels over the same direction numbers.
//!
//! Workloads: 64 dimensions (0..63) × 1024 indices, once with coherent indices `0..1024` (few set
//! bits, the case of a sampler walking a pixel's samples) and once with incoherent, hashed 32-bit
//! indices (16 set bits on average, the case of a global sequence over a large image). The peers
//! and candidates read the same `[[u32; 32]; 64]` columns (or tables built from them); throughput
//! is per value. `sobol_by_index_dims_64_127_*` times `sobol_u32` on the next 64 dimensions,
//! which have no byte tables (the masked XOR over 32 columns). Figures: `docs/performance.md`.

mod cpu_time;

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
#[inline]
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
#[inline]
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
#[inline]
fn trailing_zeros_loop(m: &[u32; 32], mut index: u32) -> u32 {
    let mut v = 0;
    while index != 0 {
        v ^= m[index.trailing_zeros() as usize];
        index &= index - 1;
    }
    v
}

/// Candidate: branch-free masks from a compare (SSE2-friendly: and + cmpeq per 4 columns).
#[inline]
fn compare_mask(m: &[u32; 32], index: u32) -> u32 {
    let mut v = 0;
    for (k, &col) in m.iter().enumerate() {
        let bit = 1u32 << k;
        let mask = if index & bit == bit { u32::MAX } else { 0 };
        v ^= col & mask;
    }
    v
}

/// Candidate: the 32 columns as 8 nibble tables of 16 precomputed XORs (512 bytes per dim).
#[inline]
fn nibble_tables(t: &[[u32; 16]; 8], index: u32) -> u32 {
    let mut v = 0;
    for (j, tab) in t.iter().enumerate() {
        v ^= tab[((index >> (4 * j)) & 15) as usize];
    }
    v
}

/// Candidate: 4 byte tables of 256 precomputed XORs (4 KiB per dim).
#[inline]
fn byte_tables(t: &[[u32; 256]; 4], index: u32) -> u32 {
    t[0][(index & 255) as usize]
        ^ t[1][((index >> 8) & 255) as usize]
        ^ t[2][((index >> 16) & 255) as usize]
        ^ t[3][(index >> 24) as usize]
}

fn indices(coherent: bool) -> Vec<u32> {
    (0..POINTS)
        .map(|i| if coherent { i } else { mix32(i ^ 0x9e37_79b9) })
        .collect()
}

/// Runs `kernel` over every dimension's table and every index; generic so the kernel inlines
/// exactly as our own `sobol_u32` does.
fn bench_kernel<T>(
    g: &mut criterion::BenchmarkGroup<'_, cpu_time::BenchClock>,
    name: &str,
    tables: &[T],
    idx: &[u32],
    kernel: impl Fn(&T, u32) -> u32,
) {
    g.bench_function(name, |b| {
        b.iter(|| {
            let mut acc = 0u32;
            for t in tables {
                for &i in idx {
                    acc ^= kernel(t, black_box(i));
                }
            }
            acc
        })
    });
}

fn bench_kernels(c: &mut Criterion<cpu_time::BenchClock>) {
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
        bench_kernel(
            &mut g,
            "peer_naive_all_32_bits",
            &cols,
            &idx,
            naive_all_bits,
        );
        bench_kernel(
            &mut g,
            "peer_while_index_shift_loop",
            &cols,
            &idx,
            shift_loop,
        );
        bench_kernel(
            &mut g,
            "candidate_trailing_zeros_loop",
            &cols,
            &idx,
            trailing_zeros_loop,
        );
        bench_kernel(&mut g, "candidate_compare_mask", &cols, &idx, compare_mask);
        let nib: Vec<[[u32; 16]; 8]> = cols
            .iter()
            .map(|m| {
                core::array::from_fn(|j| {
                    core::array::from_fn(|x| trailing_zeros_loop(m, (x as u32) << (4 * j)))
                })
            })
            .collect();
        bench_kernel(&mut g, "candidate_nibble_tables", &nib, &idx, nibble_tables);
        let bytes: Vec<[[u32; 256]; 4]> = cols
            .iter()
            .map(|m| {
                core::array::from_fn(|j| {
                    core::array::from_fn(|x| trailing_zeros_loop(m, (x as u32) << (8 * j)))
                })
            })
            .collect();
        bench_kernel(&mut g, "candidate_byte_tables", &bytes, &idx, byte_tables);
        g.finish();
    }
}

/// `sobol_u32` on dimensions 64..128, past the byte tables: the path of every dimension from 64
/// to 1023, beside the byte-table dimensions' figure above.
fn bench_upper_dims(c: &mut Criterion<cpu_time::BenchClock>) {
    for (name, coherent) in [("coherent", true), ("incoherent", false)] {
        let idx = indices(coherent);
        let mut g = c.benchmark_group(format!("sobol_by_index_dims_64_127_{name}"));
        g.throughput(Throughput::Elements(u64::from(DIMS * POINTS)));
        g.bench_function("nyquist_sobol_u32", |b| {
            b.iter(|| {
                let mut acc = 0u32;
                for d in DIMS..2 * DIMS {
                    for &i in &idx {
                        acc ^= sobol_u32(black_box(i), d);
                    }
                }
                acc
            })
        });
        g.finish();
    }
}

fn bench_fill(c: &mut Criterion<cpu_time::BenchClock>) {
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

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = bench_kernels, bench_upper_dims, bench_fill
}
criterion_main!(benches);
