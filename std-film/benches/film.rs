//! Film accumulation: `FilmTile::add_sample` (table lookup) side by side with the same
//! accumulation evaluating the filter directly, for Mitchell r = 2 and box r = ½; and the
//! parallel render of a 1024 × 1024 zone plate at 16 spp on 1 and 2 threads.

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};
use nyquist::filter::{Boxcar, Filter, Mitchell};
use nyquist_film::{Film, FilmConfig, Pixel, render_tiles};
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

/// The peer: the same footprint and f64 accumulation, with `filter.eval` per pixel.
fn add_direct(pixels: &mut [Pixel], w: usize, filter: &dyn Filter, p: [f32; 2], rgb: [f32; 3]) {
    let [rx, ry] = filter.radius();
    let (px, py) = (p[0] - 0.5, p[1] - 0.5);
    let x0 = ((px - rx).ceil() as i64).max(0);
    let x1 = ((px + rx).floor() as i64 + 1).min(w as i64);
    let y0 = ((py - ry).ceil() as i64).max(0);
    let y1 = ((py + ry).floor() as i64 + 1).min((pixels.len() / w) as i64);
    for y in y0..y1 {
        for x in x0..x1 {
            let f = filter.eval(x as f32 + 0.5 - p[0], y as f32 + 0.5 - p[1]);
            let px = &mut pixels[y as usize * w + x as usize];
            let f = f64::from(f);
            for c in 0..3 {
                px.rgb_sum[c] += f * f64::from(rgb[c]);
            }
            px.weight_sum += f;
        }
    }
}

fn add_sample(c: &mut Criterion) {
    let pos = positions();
    let filters: [(&str, &dyn Filter); 2] = [
        ("mitchell_r2", &Mitchell::default()),
        ("box_r0.5", &Boxcar::default()),
    ];
    let mut group = c.benchmark_group("add_sample");
    group.throughput(Throughput::Elements(SAMPLES as u64));
    for (name, filter) in filters {
        let film = Film::new(FilmConfig::new(64, 64), filter).unwrap();
        let spec = film.tiles(64).unwrap()[0];
        group.bench_function(format!("{name}/table"), |b| {
            b.iter_batched_ref(
                || film.tile(spec),
                |tile| {
                    for &p in &pos {
                        tile.add_sample(black_box(p), [0.5, 0.25, 1.0], 1.0);
                    }
                },
                BatchSize::LargeInput,
            )
        });
        group.bench_function(format!("{name}/direct"), |b| {
            b.iter_batched_ref(
                || vec![Pixel::default(); 64 * 64],
                |pixels| {
                    for &p in &pos {
                        add_direct(pixels, 64, filter, black_box(p), [0.5, 0.25, 1.0]);
                    }
                },
                BatchSize::LargeInput,
            )
        });
    }
    group.finish();
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
                    |tile| {
                        let bounds = tile.bounds();
                        for y in bounds.y0..bounds.y1 {
                            for x in bounds.x0..bounds.x1 {
                                for s in 0..16u32 {
                                    let (u, v) = ((s % 4) as f32 + 0.5, (s / 4) as f32 + 0.5);
                                    let (fx, fy) = (x as f32 + u / 4.0, y as f32 + v / 4.0);
                                    let (dx, dy) = (fx - 512.0, fy - 512.0);
                                    let l = 0.5
                                        + 0.5
                                            * (std::f32::consts::PI * (dx * dx + dy * dy) / 1024.0)
                                                .cos();
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

criterion_group!(benches, add_sample, zoneplate_render);
criterion_main!(benches);
