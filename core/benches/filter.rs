//! Filter evaluation: direct (concrete type and `&dyn Filter`) against table lookup (inline
//! table, size-erased view, nearest and linear), table building, and importance sampling.
//!
//! `cargo bench -p nyquist --bench filter -- --warm-up-time 1 --measurement-time 3`
//! Targets: table lookup ≤ 1 ns per weight; direct Mitchell ≤ 5 ns, Lanczos ≤ 20 ns; building
//! the default Lanczos table ≤ 50 µs.
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use nyquist::filter::{
    Boxcar, Filter, FilterSampler, FilterTable, Gaussian, Interpolation, Lanczos, Mitchell,
    Triangle,
};
use nyquist::rng::{default_rng, uniform_f32};
use std::hint::black_box;

const COUNT: usize = 1024;

/// Offsets over 1.1× the support, as a film sees them near a sample's footprint edge.
fn offsets(r: [f32; 2]) -> Vec<(f32, f32)> {
    let mut rng = default_rng(42);
    (0..COUNT)
        .map(|_| {
            let x = (uniform_f32(&mut rng) * 2.0 - 1.0) * 1.1 * r[0];
            let y = (uniform_f32(&mut rng) * 2.0 - 1.0) * 1.1 * r[1];
            (x, y)
        })
        .collect()
}

fn run(c: &mut Criterion, name: &str, f: &(impl Filter + ?Sized)) {
    let pts = offsets(f.radius());
    let dynamic: &dyn Filter = &f;
    let linear: FilterTable = FilterTable::new(f, Interpolation::Linear).unwrap();
    let nearest: FilterTable = FilterTable::new(f, Interpolation::Nearest).unwrap();
    let view = linear.view();
    let mut out = vec![0.0f32; COUNT];
    let mut g = c.benchmark_group(format!("weight/{name}"));
    g.throughput(Throughput::Elements(COUNT as u64));
    macro_rules! case {
        ($id:expr, |$x:ident, $y:ident| $e:expr) => {
            g.bench_function($id, |b| {
                b.iter(|| {
                    for (o, &($x, $y)) in out.iter_mut().zip(black_box(&pts)) {
                        *o = $e;
                    }
                    black_box(&out);
                })
            });
        };
    }
    case!("direct", |x, y| f.eval(x, y));
    case!("direct_dyn", |x, y| dynamic.eval(x, y));
    case!("table_linear", |x, y| linear.weight(x, y));
    case!("table_nearest", |x, y| nearest.weight(x, y));
    case!("table_view_linear", |x, y| view.weight(x, y));
    g.finish();

    // The film's pattern: every pixel centre in a sample's footprint, (2r)² weights per sample.
    let [rx, ry] = f.radius();
    let (nx, ny) = ((2.0 * rx).ceil() as usize, (2.0 * ry).ceil() as usize);
    let samples: Vec<(f32, f32)> = pts
        .iter()
        .take(COUNT / (nx * ny).max(1) + 1)
        .copied()
        .collect();
    let per_iter = (samples.len() * nx * ny) as u64;
    let mut buf = vec![0.0f32; nx * ny];
    let mut g = c.benchmark_group(format!("footprint/{name}"));
    g.throughput(Throughput::Elements(per_iter));
    g.bench_function("direct", |b| {
        b.iter(|| {
            for &(sx, sy) in black_box(&samples) {
                let d0 = [-rx + sx.fract().abs(), -ry + sy.fract().abs()];
                for (j, row) in buf.chunks_exact_mut(nx).enumerate() {
                    for (i, w) in row.iter_mut().enumerate() {
                        *w = f.eval(d0[0] + i as f32, d0[1] + j as f32);
                    }
                }
                black_box(&buf);
            }
        })
    });
    g.bench_function("table_linear", |b| {
        b.iter(|| {
            for &(sx, sy) in black_box(&samples) {
                let d0 = [-rx + sx.fract().abs(), -ry + sy.fract().abs()];
                view.footprint(d0, nx, &mut buf).unwrap();
                black_box(&buf);
            }
        })
    });
    g.finish();
}

fn weights(c: &mut Criterion) {
    run(c, "box", &Boxcar::default());
    run(c, "triangle", &Triangle::default());
    run(c, "gaussian", &Gaussian::default());
    run(c, "mitchell", &Mitchell::default());
    run(c, "lanczos", &Lanczos::default());
}

fn build(c: &mut Criterion) {
    let mut g = c.benchmark_group("build");
    g.throughput(Throughput::Elements(1));
    let l = Lanczos::default();
    g.bench_function(BenchmarkId::new("table16", "lanczos"), |b| {
        b.iter(|| FilterTable::<16>::new(black_box(&l), Interpolation::Linear).unwrap())
    });
    let m = Mitchell::default();
    g.bench_function(BenchmarkId::new("table16", "mitchell"), |b| {
        b.iter(|| FilterTable::<16>::new(black_box(&m), Interpolation::Linear).unwrap())
    });
    g.bench_function(BenchmarkId::new("sampler32", "lanczos"), |b| {
        b.iter(|| FilterSampler::<_, 32>::new(black_box(l)).unwrap())
    });
    g.finish();
}

fn sampling(c: &mut Criterion) {
    let mut g = c.benchmark_group("sample");
    g.throughput(Throughput::Elements(COUNT as u64));
    let mut rng = default_rng(7);
    let us: Vec<[f32; 2]> = (0..COUNT)
        .map(|_| [uniform_f32(&mut rng), uniform_f32(&mut rng)])
        .collect();
    let mut out = vec![0.0f32; COUNT];
    let m = FilterSampler::<_, 32>::new(Mitchell::default()).unwrap();
    let l = FilterSampler::<_, 32>::new(Lanczos::default()).unwrap();
    g.bench_function("mitchell32", |b| {
        b.iter(|| {
            for (o, &u) in out.iter_mut().zip(black_box(&us)) {
                *o = m.sample(u).weight;
            }
            black_box(&out);
        })
    });
    g.bench_function("lanczos32", |b| {
        b.iter(|| {
            for (o, &u) in out.iter_mut().zip(black_box(&us)) {
                *o = l.sample(u).weight;
            }
            black_box(&out);
        })
    });
    g.finish();
}

criterion_group!(benches, weights, build, sampling);
criterion_main!(benches);
