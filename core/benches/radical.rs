//! Radical-inverse throughput: ours against plain digit loops (base as a compile-time constant,
//! and base at run time), on the same random indices below 10⁷ and the same dimensions.
mod cpu_time;

use criterion::{
    BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main,
};
use nyquist::radical::{
    PRIMES, fast_owen_scrambled_radical_inverse, fill_radical_inverse, folded_radical_inverse,
    owen_scrambled_radical_inverse, radical_inverse, radical_inverse_at, scrambled_radical_inverse,
};
use nyquist::sequence::{Halton, Sequence};
use std::hint::black_box;

const DIMS: usize = 64;
const INDICES: usize = 256;

/// A plain digit loop with the base a compile-time constant (the compiler turns `/ B` into a
/// multiply-shift).
#[inline(always)]
fn ri_const<const B: u64>(mut a: u64) -> f32 {
    let inv_base = 1.0 / B as f32;
    let mut reversed = 0u64;
    let mut inv_base_n = 1.0f32;
    while a != 0 {
        let next = a / B;
        let digit = a - next * B;
        reversed = reversed * B + digit;
        inv_base_n *= inv_base;
        a = next;
    }
    (reversed as f32 * inv_base_n).min(nyquist::ONE_MINUS_EPSILON)
}

/// The same loop with the base known only at run time (hardware division).
#[inline(never)]
fn ri_runtime(base: u64, mut a: u64) -> f32 {
    let inv_base = 1.0 / base as f32;
    let mut reversed = 0u64;
    let mut inv_base_n = 1.0f32;
    while a != 0 {
        let next = a / base;
        let digit = a - next * base;
        reversed = reversed * base + digit;
        inv_base_n *= inv_base;
        a = next;
    }
    (reversed as f32 * inv_base_n).min(nyquist::ONE_MINUS_EPSILON)
}

macro_rules! dispatch {
    ($dim:expr, $a:expr; $($d:literal => $p:literal),* $(,)?) => {
        match $dim { $($d => ri_const::<$p>($a),)* _ => 0.0 }
    };
}

#[inline(never)]
fn ri_const_dispatch(dim: u32, a: u64) -> f32 {
    dispatch!(dim, a;
        0 => 2, 1 => 3, 2 => 5, 3 => 7, 4 => 11, 5 => 13, 6 => 17, 7 => 19, 8 => 23, 9 => 29,
        10 => 31, 11 => 37, 12 => 41, 13 => 43, 14 => 47, 15 => 53, 16 => 59, 17 => 61,
        18 => 67, 19 => 71, 20 => 73, 21 => 79, 22 => 83, 23 => 89, 24 => 97, 25 => 101,
        26 => 103, 27 => 107, 28 => 109, 29 => 113, 30 => 127, 31 => 131, 32 => 137, 33 => 139,
        34 => 149, 35 => 151, 36 => 157, 37 => 163, 38 => 167, 39 => 173, 40 => 179, 41 => 181,
        42 => 191, 43 => 193, 44 => 197, 45 => 199, 46 => 211, 47 => 223, 48 => 227, 49 => 229,
        50 => 233, 51 => 239, 52 => 241, 53 => 251, 54 => 257, 55 => 263, 56 => 269, 57 => 271,
        58 => 277, 59 => 281, 60 => 283, 61 => 293, 62 => 307, 63 => 311,
    )
}

fn indices() -> Vec<u64> {
    let mut state = 0x1234_5678_9abc_def0u64;
    (0..INDICES)
        .map(|_| {
            state = nyquist::hash::mix64(state.wrapping_add(0x9e37_79b9_7f4a_7c15));
            state % 10_000_000
        })
        .collect()
}

fn run(out: &mut [f32], idx: &[u64], f: impl Fn(u32, u64) -> f32) {
    for (row, &a) in out.chunks_exact_mut(DIMS).zip(idx) {
        for (dim, x) in row.iter_mut().enumerate() {
            *x = f(dim as u32, black_box(a));
        }
    }
}

/// Ours value by value (`name`) and the two digit-loop peers, on the same indices and dims.
fn per_value_and_peers(
    g: &mut BenchmarkGroup<'_, cpu_time::BenchClock>,
    name: &str,
    out: &mut [f32],
    idx: &[u64],
) {
    g.bench_function(name, |b| {
        b.iter(|| run(out, black_box(idx), radical_inverse))
    });
    // The same values a dimension at a time over the batch of indices (dimension-major).
    g.bench_function(format!("{name}_batch_per_dim"), |b| {
        b.iter(|| {
            for (dim, xs) in out.chunks_exact_mut(idx.len()).enumerate() {
                radical_inverse_at(dim as u32, black_box(idx), xs).unwrap();
            }
        })
    });
    g.bench_function("const_base_loop", |b| {
        b.iter(|| run(out, black_box(idx), ri_const_dispatch))
    });
    g.bench_function("runtime_base_loop", |b| {
        b.iter(|| {
            run(out, black_box(idx), |d, a| {
                ri_runtime(u64::from(PRIMES[d as usize]), a)
            })
        })
    });
}

fn halton(c: &mut Criterion<cpu_time::BenchClock>) {
    // Sanity: the const-generic table matches the primes.
    assert_eq!(PRIMES[63], 311);
    assert_eq!(ri_const_dispatch(63, 12345), ri_runtime(311, 12345));
    let idx = indices();
    let mut out = vec![0.0f32; DIMS * INDICES];
    let mut g = c.benchmark_group("halton_f32_dims0-63");
    g.throughput(Throughput::Elements((DIMS * INDICES) as u64));
    per_value_and_peers(&mut g, "nyquist", &mut out, &idx);
    g.finish();

    // Whole points: 256 consecutive indices from an offset below 10⁷, all 64 dimensions, through
    // `Sequence::fill` (incremental digits), against the same values from the two loops.
    let halton = Halton::new(DIMS as u32).unwrap();
    let first = 9_876_543u64;
    let consecutive: Vec<u64> = (first..first + INDICES as u64).collect();
    let mut g = c.benchmark_group("halton_f32_fill_256pts_x_64dims");
    g.throughput(Throughput::Elements((DIMS * INDICES) as u64));
    g.bench_function("nyquist_fill", |b| {
        b.iter(|| {
            halton
                .fill(black_box(first), DIMS as u32, &mut out)
                .unwrap()
        })
    });
    per_value_and_peers(&mut g, "nyquist_random_access", &mut out, &consecutive);
    g.finish();

    // Base 2 over random indices below 2³² (a renderer's range), random access and a contiguous
    // fill, against the plain digit loop.
    let mut out = vec![0.0f32; INDICES * 4];
    let small: Vec<u64> = (0..INDICES * 4)
        .map(|i| nyquist::hash::mix64(i as u64 + 1) >> 32)
        .collect();
    let mut g = c.benchmark_group("base2");
    g.throughput(Throughput::Elements(small.len() as u64));
    g.bench_function("nyquist", |b| {
        b.iter(|| {
            for (x, &a) in out.iter_mut().zip(black_box(&small)) {
                *x = radical_inverse(0, a);
            }
        })
    });
    g.bench_function("nyquist_batch", |b| {
        b.iter(|| radical_inverse_at(0, black_box(&small), &mut out).unwrap())
    });
    g.bench_function("nyquist_fill", |b| {
        b.iter(|| fill_radical_inverse(0, black_box(123_456_789), &mut out))
    });
    g.bench_function("naive_loop", |b| {
        b.iter(|| {
            for (x, &a) in out.iter_mut().zip(black_box(&small)) {
                *x = ri_const::<2>(a);
            }
        })
    });
    g.finish();

    let mut out = vec![0.0f32; DIMS * INDICES];
    let mut g = c.benchmark_group("forms_f32_dims0-63_info");
    g.throughput(Throughput::Elements((DIMS * INDICES) as u64));
    for (name, f) in [
        ("folded", folded_radical_inverse as fn(u32, u64) -> f32),
        ("scrambled", |d, a| scrambled_radical_inverse(d, a, 7)),
        ("owen", |d, a| owen_scrambled_radical_inverse(d, a, 7)),
        ("fast_owen", |d, a| {
            fast_owen_scrambled_radical_inverse(d, a, 7)
        }),
    ] {
        g.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| run(&mut out, black_box(&idx), f))
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = halton
}
criterion_main!(benches);
