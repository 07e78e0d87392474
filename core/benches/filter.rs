//! Filter evaluation: direct (concrete type and `&dyn Filter`) against table lookup (inline
//! table, size-erased view, nearest and linear, one at a time and in batches), table building,
//! and importance sampling.
//!
//! `cargo bench -p nyquist --bench filter -- --warm-up-time 1 --measurement-time 3`
//! The phase table (`PhaseTable`, the film's) runs beside the others in both groups.
//! Targets: table lookup ≤ 1 ns per weight; direct Mitchell ≤ 5 ns, Lanczos ≤ 20 ns; building
//! the default Lanczos table ≤ 50 µs. Every figure is per weight (`Throughput::Elements`).
//! The peer is pbrt-v3 (`pbrt_v3`: its Mitchell and Lanczos through a virtual call, its 16 × 16
//! table read as `AddSample` reads it), the code the targets are quoted against. After the run
//! the bench prints the table/direct ratios of each filter and how many times faster than
//! pbrt-v3 each of ours ran, from criterion's estimates of this run (median per weight).
//! Figures: `docs/performance.md`.
mod cpu_time;
mod estimates;
mod pbrt_v3;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group};
use estimates::median_ns;
use nyquist::filter::{
    Boxcar, Filter, FilterSampler, FilterTable, Gaussian, Interpolation, Lanczos, Mitchell,
    PhaseTable, Triangle,
};
use nyquist::rng::{default_rng, uniform_f32};
use pbrt_v3::{PbrtFilter, PbrtLanczos, PbrtMitchell, PbrtTable};
use std::hint::black_box;
use std::sync::Mutex;
use std::time::SystemTime;

const COUNT: usize = 1024;

/// Weights per iteration of each filter's footprint group, for the closing report.
static FOOTPRINT_WEIGHTS: Mutex<Vec<(String, u64)>> = Mutex::new(Vec::new());

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

fn run(c: &mut Criterion<cpu_time::BenchClock>, name: &str, f: &(impl Filter + ?Sized)) {
    let pts = offsets(f.radius());
    let dynamic: &dyn Filter = &f;
    let linear: FilterTable = FilterTable::new(f, Interpolation::Linear).unwrap();
    let nearest: FilterTable = FilterTable::new(f, Interpolation::Nearest).unwrap();
    let view = linear.view();
    let phase = PhaseTable::new(f).unwrap();
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
    // pbrt-v3's Evaluate through its virtual call, as pbrt-v3 calls it.
    let pbrt_filter: Option<Box<dyn PbrtFilter>> = match name {
        "mitchell" => Some(Box::new(PbrtMitchell::new())),
        "lanczos" => Some(Box::new(PbrtLanczos::new())),
        _ => None,
    };
    if let Some(pf) = &pbrt_filter {
        case!("pbrt_v3_dyn", |x, y| pf.evaluate([x, y]));
    }
    case!("table_linear", |x, y| linear.weight(x, y));
    case!("table_nearest", |x, y| nearest.weight(x, y));
    case!("table_view_linear", |x, y| view.weight(x, y));
    case!("phase", |x, y| phase.weight(x, y));
    // The batch form over the same offsets (structure of arrays).
    let (dx, dy): (Vec<f32>, Vec<f32>) = pts.iter().copied().unzip();
    for (id, table) in [
        ("table_batch_linear", &linear),
        ("table_batch_nearest", &nearest),
    ] {
        g.bench_function(id, |b| {
            b.iter(|| {
                table.weights(black_box(&dx), &dy, &mut out).unwrap();
                black_box(&out);
            })
        });
    }
    g.finish();

    // The film's pattern: every pixel centre in a sample's footprint, (2r)² weights per sample.
    // The offset of each sample to its footprint's first pixel is computed outside the timing.
    let [rx, ry] = f.radius();
    let (nx, ny) = ((2.0 * rx).ceil() as usize, (2.0 * ry).ceil() as usize);
    let d0s: Vec<[f32; 2]> = pts
        .iter()
        .take(COUNT / (nx * ny).max(1) + 1)
        .map(|&(sx, sy)| [-rx + sx.fract().abs(), -ry + sy.fract().abs()])
        .collect();
    let per_iter = (d0s.len() * nx * ny) as u64;
    FOOTPRINT_WEIGHTS
        .lock()
        .unwrap()
        .push((name.to_string(), per_iter));
    // Each sample's footprint goes to its own slot of one buffer, handed to `black_box` once per
    // batch, as the `weight` group hands its outputs: a `black_box` after every footprint would
    // be a memory clobber that makes the loop reload the table and the buffer each time, a cost
    // a caller never pays and, for a one-weight (box) footprint, larger than the lookup itself.
    let n = nx * ny;
    let mut all = vec![0.0f32; d0s.len() * n];
    let mut g = c.benchmark_group(format!("footprint/{name}"));
    g.throughput(Throughput::Elements(per_iter));
    g.bench_function("direct", |b| {
        b.iter(|| {
            let (n, nx) = (n, nx); // copies: a captured reference is reloaded every footprint
            for (&d0, buf) in black_box(&d0s).iter().zip(all.chunks_exact_mut(n)) {
                for (j, row) in buf.chunks_exact_mut(nx).enumerate() {
                    for (i, w) in row.iter_mut().enumerate() {
                        *w = f.eval(d0[0] + i as f32, d0[1] + j as f32);
                    }
                }
            }
            black_box(&all);
        })
    });
    macro_rules! footprint {
        ($id:expr, $table:expr) => {
            g.bench_function($id, |b| {
                b.iter(|| {
                    let (n, nx) = (n, nx); // as above
                    for (&d0, buf) in black_box(&d0s).iter().zip(all.chunks_exact_mut(n)) {
                        $table.footprint(d0, nx, buf).unwrap();
                    }
                    black_box(&all);
                })
            });
        };
    }
    footprint!("table_linear", linear);
    footprint!("table_nearest", nearest);
    footprint!("table_view_linear", view);
    footprint!("phase", phase);
    // pbrt-v3's AddSample pattern: a column and a row index, then one read per pixel.
    let pbrt_table = PbrtTable::new(dynamic);
    g.bench_function("pbrt_v3_table", |b| {
        b.iter(|| {
            let (n, nx) = (n, nx); // copies: a captured reference is reloaded every footprint
            for (&d0, buf) in black_box(&d0s).iter().zip(all.chunks_exact_mut(n)) {
                pbrt_table.footprint(d0, nx, buf);
            }
            black_box(&all);
        })
    });
    g.finish();
}

fn weights(c: &mut Criterion<cpu_time::BenchClock>) {
    run(c, "box", &Boxcar::default());
    run(c, "triangle", &Triangle::default());
    run(c, "gaussian", &Gaussian::default());
    run(c, "mitchell", &Mitchell::default());
    run(c, "lanczos", &Lanczos::default());
}

fn build(c: &mut Criterion<cpu_time::BenchClock>) {
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

fn sampling(c: &mut Criterion<cpu_time::BenchClock>) {
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

criterion_group! {
    name = benches;
    config = cpu_time::config();
    targets = weights, build, sampling
}

/// Prints per-weight medians and table/direct ratios for every filter this run measured.
fn report(since: SystemTime) {
    let mut lines = Vec::new();
    for name in ["box", "triangle", "gaussian", "mitchell", "lanczos"] {
        let [w, fp] = [format!("weight/{name}"), format!("footprint/{name}")];
        let Some(direct) = median_ns(&w, "direct", since) else {
            continue;
        };
        let per = |group: &str, id: &str| median_ns(group, id, since);
        let fp = fp.as_str();
        let mut line = format!("{name:9} direct {:6.2} ns", direct / COUNT as f64);
        for (label, group, id) in [
            ("dyn", &w, "direct_dyn"),
            ("nearest", &w, "table_nearest"),
            ("linear", &w, "table_linear"),
            ("view", &w, "table_view_linear"),
            ("batch nearest", &w, "table_batch_nearest"),
            ("batch linear", &w, "table_batch_linear"),
            ("phase", &w, "phase"),
            ("pbrt-v3 dyn", &w, "pbrt_v3_dyn"),
        ] {
            if let Some(t) = per(group, id) {
                let ratio = t / direct;
                line += &format!(" | {label} {:6.2} ns ×{ratio:.2}", t / COUNT as f64);
            }
        }
        let n = FOOTPRINT_WEIGHTS
            .lock()
            .unwrap()
            .iter()
            .find(|(f, _)| f == name)
            .map_or(1.0, |&(_, n)| n as f64);
        if let (Some(d), Some(t)) = (per(fp, "direct"), per(fp, "table_linear")) {
            line += &format!(
                " | footprint direct {:.2} ns, table {:.2} ns ×{:.2}",
                d / n,
                t / n,
                t / d
            );
        }
        if let (Some(d), Some(p)) = (per(fp, "direct"), per(fp, "phase")) {
            line += &format!(", phase {:.2} ns ×{:.2}", p / n, p / d);
        }
        // Ours against pbrt-v3's lookups in the same run: how many times faster.
        if let Some(peer) = per(fp, "pbrt_v3_table") {
            line += &format!(" | pbrt-v3 table {:.2} ns; faster ×", peer / n);
            for id in ["table_nearest", "table_linear", "phase"] {
                if let Some(t) = per(fp, id) {
                    line += &format!(" {id} {:.2}", peer / t);
                }
            }
        }
        if let (Some(peer), Some(d)) = (per(&w, "pbrt_v3_dyn"), per(&w, "direct")) {
            line += &format!(" | direct faster than pbrt-v3's ×{:.2}", peer / d);
        }
        lines.push(line);
    }
    estimates::print_report(
        "per weight (median) and ratio to direct evaluation, this run:",
        &lines,
    );
}

fn main() {
    let since = SystemTime::now();
    benches();
    cpu_time::config().configure_from_args().final_summary();
    report(since);
}
