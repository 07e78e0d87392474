//! Film accumulation: `FilmTile::add_sample` (table lookups) side by side with the same
//! accumulation evaluating the filter directly (`FilmTile::add_sample_direct`), for Mitchell
//! r = 2 and box r = ½, 4096 samples per iteration (uniform positions over a 64 × 64 tile, each
//! with its own radiance), and into a film that keeps the variance and A/B halves (`extras`); and the parallel render of a 1024 × 1024 zone plate at 16 spp on 1
//! and 2 threads.
//!
//! Beside both runs the peer the targets are quoted against, pbrt-v3's `FilmTile::AddSample`
//! (re-implemented in `core/benches/pbrt_v3`, `f32` sums and its 16 × 16 table); after the run the
//! bench prints the per-sample medians and the ratios. Figures: `docs/performance.md`.
//!
//! `add_sample` runs twice: `add_sample` in wall-clock time (criterion's default) and
//! `add_sample_cpu` in the thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), which other processes
//! on a shared machine do not inflate. Per-sample time = reported time / 4096 (throughput line).

/// The core benches' clock (thread CPU time unless `NYQUIST_BENCH_CLOCK=wall`), shared.
#[path = "../../core/benches/cpu_time/mod.rs"]
mod cpu_time;
/// This run's medians, for the closing ratio report (shared with the core benches).
#[path = "../../core/benches/estimates/mod.rs"]
mod estimates;
/// The peer: pbrt-v3's `FilmTile::AddSample`, re-implemented (shared with the filter bench).
#[path = "../../core/benches/pbrt_v3/mod.rs"]
mod pbrt_v3;

use criterion::measurement::Measurement;
use criterion::{Criterion, Throughput, criterion_group};
use nyquist::filter::{Boxcar, Filter, Mitchell};
use nyquist_film::{Film, FilmConfig, FilmSample, PixelExtras, render_tiles};
use std::hint::black_box;

const SAMPLES: usize = 4096;

fn positions() -> Vec<[f32; 2]> {
    let mut rng = nyquist::rng::default_rng(1);
    (0..SAMPLES)
        .map(|_| {
            [
                64.0 * nyquist::rng::uniform_f32(&mut rng),
                64.0 * nyquist::rng::uniform_f32(&mut rng),
            ]
        })
        .collect()
}

/// A radiance per sample in `[0, 1)³`, read beside its position as a renderer's would be (a
/// constant radiance lets the compiler fold the weight product and the finite check away once
/// `add_sample` is inlined).
fn radiances() -> Vec<[f32; 3]> {
    let mut rng = nyquist::rng::default_rng(2);
    (0..SAMPLES)
        .map(|_| [(); 3].map(|_| nyquist::rng::uniform_f32(&mut rng)))
        .collect()
}

fn add_sample_group<M: Measurement>(c: &mut Criterion<M>, group_name: &str) {
    let pos = positions();
    let rad = radiances();
    let filters: [(&str, &dyn Filter); 2] = [
        ("mitchell_r2", &Mitchell::default()),
        ("box_r0.5", &Boxcar::default()),
    ];
    let mut group = c.benchmark_group(group_name);
    group.throughput(Throughput::Elements(SAMPLES as u64));
    for (name, filter) in filters {
        let film = Film::new(FilmConfig::new(64, 64), filter).unwrap();
        let spec = film.tiles(64).unwrap()[0];
        // One tile per case, reused across iterations: a fresh tile each time would put its
        // first-touch page faults (≈140 KB of zeroed pixels) inside the timed loop.
        let mut tile = film.tile(spec);
        group.bench_function(format!("{name}/table"), |b| {
            b.iter(|| {
                for (&p, &l) in pos.iter().zip(&rad) {
                    tile.add_sample(black_box(p), l, 1.0);
                }
            })
        });
        let mut tile = film.tile(spec);
        group.bench_function(format!("{name}/direct"), |b| {
            b.iter(|| {
                for (&p, &l) in pos.iter().zip(&rad) {
                    tile.add_sample_direct(filter, black_box(p), l, 1.0);
                }
            })
        });
        // The same samples into a film that keeps the variance and the A/B halves (every
        // sample through `FilmTile::add`, with its index): what the extras cost per sample.
        let config = FilmConfig {
            extras: PixelExtras {
                variance: true,
                halves: true,
                channels: 0,
            },
            ..FilmConfig::new(64, 64)
        };
        let kept = Film::new(config, filter).unwrap();
        let mut tile = kept.tile(spec);
        group.bench_function(format!("{name}/extras"), |b| {
            b.iter(|| {
                for (i, (&p, &l)) in pos.iter().zip(&rad).enumerate() {
                    tile.add(&FilmSample {
                        index: i as u64,
                        ..FilmSample::new(black_box(p), l, 1.0)
                    });
                }
            })
        });
        // pbrt-v3's tile over the same pixels: the 64 × 64 tile grown by r + ½ and clipped to
        // the film, as `Film::GetFilmTile` does (the whole 64 × 64 film here, like ours).
        let mut peer = pbrt_v3::PbrtTile::new(filter, [0, 0, 64, 64]);
        group.bench_function(format!("{name}/pbrt_v3"), |b| {
            b.iter(|| {
                for (&p, &l) in pos.iter().zip(&rad) {
                    peer.add_sample(black_box(p), l, 1.0);
                }
            })
        });
    }
    group.finish();
}

fn add_sample(c: &mut Criterion) {
    add_sample_group(c, "add_sample");
}

fn add_sample_cpu(c: &mut Criterion<cpu_time::BenchClock>) {
    add_sample_group(c, "add_sample_cpu");
}

/// The zone plate of docs/cli.md, L = ½ + ½·cos(π r² / W), on a `size × size` film.
fn zoneplate(x: f32, y: f32, size: f32) -> f32 {
    let (dx, dy) = (x - size / 2.0, y - size / 2.0);
    0.5 + 0.5 * (std::f32::consts::PI * (dx * dx + dy * dy) / size).cos()
}

fn zoneplate_render(c: &mut Criterion) {
    let mut group = c.benchmark_group("render_zoneplate_1024_16spp_mitchell");
    group.sample_size(10);
    group.throughput(Throughput::Elements(1024 * 1024 * 16));
    for threads in [1usize, 2] {
        group.bench_function(format!("threads_{threads}"), |b| {
            b.iter(|| {
                let mut film =
                    Film::new(FilmConfig::new(1024, 1024), &Mitchell::default()).unwrap();
                render_tiles(
                    &mut film,
                    32,
                    threads,
                    |tile, _ctx| {
                        let bounds = tile.bounds();
                        for y in bounds.y0..bounds.y1 {
                            for x in bounds.x0..bounds.x1 {
                                for s in 0..16u32 {
                                    let (u, v) = ((s % 4) as f32 + 0.5, (s / 4) as f32 + 0.5);
                                    let (fx, fy) = (x as f32 + u / 4.0, y as f32 + v / 4.0);
                                    let l = zoneplate(fx, fy, 1024.0);
                                    tile.add_sample([fx, fy], [l, l, l], 1.0);
                                }
                            }
                        }
                    },
                    |_, _| {},
                )
                .unwrap();
                black_box(film.image());
            })
        });
    }
    group.finish();
}

criterion_group!(wall, add_sample, zoneplate_render);
criterion_group! {
    name = cpu;
    config = cpu_time::config();
    targets = add_sample_cpu
}
/// Per-sample medians of this run and the ratios: table against direct evaluation, and how
/// many times faster than pbrt-v3's `AddSample` ours ran.
fn report(since: std::time::SystemTime) {
    let mut lines = Vec::new();
    for group in ["add_sample", "add_sample_cpu"] {
        for name in ["mitchell_r2", "box_r0.5"] {
            let per = |id: &str| {
                estimates::median_ns(group, &format!("{name}/{id}"), since)
                    .map(|t| t / SAMPLES as f64)
            };
            let Some(table) = per("table") else {
                continue;
            };
            let mut line = format!("{group:15} {name:12} table {table:6.2} ns");
            if let Some(e) = per("extras") {
                line += &format!(" | extras {e:6.2} ns (×{:.2} the table)", e / table);
            }
            if let Some(d) = per("direct") {
                line += &format!(" | direct {d:6.2} ns (table ×{:.2} faster)", d / table);
            }
            if let Some(p) = per("pbrt_v3") {
                line += &format!(" | pbrt-v3 {p:6.2} ns (table ×{:.2} faster)", p / table);
            }
            lines.push(line);
        }
    }
    estimates::print_report("per sample (median), this run:", &lines);
}

fn main() {
    let since = std::time::SystemTime::now();
    wall();
    cpu();
    Criterion::default().configure_from_args().final_summary();
    report(since);
}
