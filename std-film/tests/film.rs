//! Film conservation laws, determinism across threads and schedules, and bad samples.

#[path = "support/temp_dir.rs"]
mod temp_dir;

use nyquist::filter::{Axis, Boxcar, Filter, Gaussian, Lanczos, Mitchell, Triangle};
use nyquist_film::{
    Bounds, Film, FilmConfig, FilmTile, TileContext, render_tiles, write_image_file,
};
use proptest::prelude::*;
use std::sync::Mutex;
use temp_dir::TempDir;

fn filters() -> Vec<(&'static str, Box<dyn Filter + Sync>)> {
    vec![
        ("box", Box::new(Boxcar::default())),
        ("triangle", Box::new(Triangle::default())),
        ("gaussian", Box::new(Gaussian::default())),
        ("mitchell", Box::new(Mitchell::default())),
        ("lanczos", Box::new(Lanczos::default())),
    ]
}

/// `k × k` stratified samples in every pixel of the tile, radiance from `l`.
fn fill_tile(tile: &mut FilmTile, k: u32, l: impl Fn(f32, f32) -> [f32; 3]) {
    let b = tile.bounds();
    for y in b.y0..b.y1 {
        for x in b.x0..b.x1 {
            for j in 0..k {
                for i in 0..k {
                    let p = [
                        x as f32 + (i as f32 + 0.5) / k as f32,
                        y as f32 + (j as f32 + 0.5) / k as f32,
                    ];
                    tile.add_sample(p, l(p[0], p[1]), 1.0);
                }
            }
        }
    }
}

fn bits(film: &mut Film) -> Vec<u32> {
    film.image().0.data().iter().map(|v| v.to_bits()).collect()
}

#[test]
fn constant_radiance_gives_that_constant_in_every_pixel_for_every_filter() {
    for (name, filter) in filters() {
        let mut film = Film::new(FilmConfig::new(13, 9), filter.as_ref()).unwrap();
        render_tiles(
            &mut film,
            4,
            2,
            |t, _| fill_tile(t, 3, |_, _| [0.3, 1.0, 7.5]),
            |_, _| {},
        )
        .unwrap();
        let (image, stats) = film.image();
        assert_eq!(stats.zero_weight_pixels, 0, "{name}");
        for px in image.data().chunks_exact(3) {
            for (v, want) in px.iter().zip([0.3f32, 1.0, 7.5]) {
                assert!(((v - want) / want).abs() < 1e-6, "{name}: {v} vs {want}");
            }
        }
    }
}

#[test]
fn a_single_sample_with_the_box_filter_lands_in_one_pixel_only() {
    let mut film = Film::new(FilmConfig::new(8, 8), &Boxcar::default()).unwrap();
    let spec = film.tiles(8).unwrap()[0];
    let mut tile = film.tile(spec);
    tile.add_sample([3.3, 5.9], [2.0, 2.0, 2.0], 1.0);
    film.merge(tile).unwrap();
    for y in 0..8 {
        for x in 0..8 {
            let p = film.pixel(x, y).unwrap();
            if (x, y) == (3, 5) {
                assert_eq!(p.weight_sum, 1.0);
                assert_eq!(p.rgb_sum, [2.0; 3]);
            } else {
                assert_eq!(p.weight_sum, 0.0, "({x}, {y})");
            }
        }
    }
}

/// A cone, `max(0, 1 − ρ²/r²)`: not separable, so the film's tables and its direct path weigh
/// each pixel of a footprint on its own instead of by an outer product.
#[derive(Debug)]
struct Cone(f32);

impl Filter for Cone {
    fn radius(&self) -> [f32; 2] {
        [self.0; 2]
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        let d = 1.0 - (x * x + y * y) / (self.0 * self.0);
        if d > 0.0 { d } else { 0.0 }
    }
}

/// Every pixel's weight and RGB sums are the sums of the filter weights that reach it, times
/// the radiance, on the common path (Mitchell's phase table) and on each of the film's paths
/// past it: a non-separable filter (its table, and direct evaluation, also on a film whose own
/// filter is separable), a separable one too wide for the phase table (footprints of 19 and of
/// 35 columns or rows, the latter past the outer product's 32), and one-pixel footprints of a
/// filter that is not a box.
#[test]
fn per_pixel_footprints_sum_the_weights_that_reach_each_pixel() {
    let cone = Cone(2.5);
    let wide = Gaussian::with_sigma([17.5, 3.0], 6.0).unwrap();
    let broad = Gaussian::with_sigma([9.5, 9.5], 3.0).unwrap();
    let small = Triangle::new([0.4, 0.45]).unwrap();
    let tall = Gaussian::with_sigma([3.0, 17.5], 6.0).unwrap();
    let gauss3 = Gaussian::with_sigma([3.0, 3.0], 1.0).unwrap();
    // (what, the film's filter, the filter `add_sample_direct` evaluates, if it is used).
    let mitchell = Mitchell::default();
    let cases: [(&str, &dyn Filter, Option<&dyn Filter>); 8] = [
        ("mitchell", &mitchell, None),
        ("cone, table", &cone, None),
        ("cone, direct", &cone, Some(&cone)),
        ("cone, direct on a separable film", &gauss3, Some(&cone)),
        ("gaussian 35 wide", &wide, None),
        ("gaussian 35 tall", &tall, None),
        ("gaussian 19 wide", &broad, None),
        ("triangle r < ½", &small, None),
    ];
    let samples = [
        [20.2f32, 9.7],
        [23.9, 3.1],
        [0.4, 14.5],
        [39.5, 8.5],
        [17.3, 33.6],
        [31.05, 29.9],
        [12.3, 20.2],
    ];
    let rgb = [1.0f32, 0.5, 0.25];
    for (name, filter, direct) in cases {
        let mut film = Film::new(FilmConfig::new(40, 40), filter).unwrap();
        let spec = film.tiles(64).unwrap()[0];
        let mut tile = film.tile(spec);
        for p in samples {
            match direct {
                Some(d) => tile.add_sample_direct(d, p, rgb, 1.0),
                None => tile.add_sample(p, rgb, 1.0),
            }
        }
        film.merge(tile).unwrap();
        for y in 0..40i64 {
            for x in 0..40i64 {
                let want: f64 = samples
                    .iter()
                    .map(|p| {
                        let (dx, dy) = (x as f32 + 0.5 - p[0], y as f32 + 0.5 - p[1]);
                        f64::from(match direct {
                            Some(d) => d.eval(dx, dy),
                            None => film.filter_weight(dx, dy),
                        })
                    })
                    .sum();
                let got = film.pixel(x, y).unwrap();
                assert!(
                    (got.weight_sum - want).abs() < 1e-6,
                    "{name} ({x},{y}): {} vs {want}",
                    got.weight_sum
                );
                for c in 0..3 {
                    let want = want * f64::from(rgb[c]);
                    assert!((got.rgb_sum[c] - want).abs() < 1e-6, "{name} ({x},{y}) {c}");
                }
            }
        }
    }
}

#[test]
fn table_weights_track_the_filter() {
    for (name, filter) in filters() {
        let film = Film::new(FilmConfig::new(4, 4), filter.as_ref()).unwrap();
        let [rx, ry] = filter.radius();
        for k in 0..50 {
            let (x, y) = (
                rx * (k as f32 / 25.0 - 1.0),
                ry * ((k * 7 % 50) as f32 / 25.0 - 1.0),
            );
            let (t, d) = (film.filter_weight(x, y), filter.eval(x, y));
            assert!(
                (t - d).abs() < 0.02,
                "{name} ({x},{y}): table {t} direct {d}"
            );
        }
    }
}

fn zoneplate(x: f32, y: f32) -> [f32; 3] {
    let (dx, dy) = (x - 20.0, y - 15.0);
    let v = 0.5 + 0.5 * (std::f32::consts::PI * (dx * dx + dy * dy) / 40.0).cos();
    [v, v * 0.5, 1.0 - v]
}

#[test]
fn image_is_bit_identical_for_any_thread_count_and_tile_order() {
    let reference = {
        let mut film = Film::new(FilmConfig::new(40, 30), &Mitchell::default()).unwrap();
        render_tiles(
            &mut film,
            7,
            1,
            |t, _| fill_tile(t, 2, zoneplate),
            |_, _| {},
        )
        .unwrap();
        bits(&mut film)
    };
    for threads in [1, 2, 8, 16] {
        for _ in 0..2 {
            let mut film = Film::new(FilmConfig::new(40, 30), &Mitchell::default()).unwrap();
            render_tiles(
                &mut film,
                7,
                threads,
                |t, _| fill_tile(t, 2, zoneplate),
                |_, _| {},
            )
            .unwrap();
            assert_eq!(bits(&mut film), reference, "threads {threads}");
        }
    }
    // Any merge order: reversed and interleaved.
    for order in [Order::Reversed, Order::Interleaved] {
        let mut film = Film::new(FilmConfig::new(40, 30), &Mitchell::default()).unwrap();
        let mut tiles: Vec<FilmTile> = film
            .tiles(7)
            .unwrap()
            .into_iter()
            .map(|s| {
                let mut t = film.tile(s);
                fill_tile(&mut t, 2, zoneplate);
                t
            })
            .collect();
        match order {
            Order::Reversed => tiles.reverse(),
            Order::Interleaved => {
                let (even, odd): (Vec<_>, Vec<_>) =
                    tiles.into_iter().partition(|t| t.index() % 2 == 0);
                tiles = odd.into_iter().chain(even).collect();
            }
        }
        for t in tiles {
            film.merge(t).unwrap();
        }
        assert_eq!(bits(&mut film), reference, "{order:?}");
    }
}

/// FNV-1a, to name the image bytes in failure messages.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

#[test]
fn exr_and_png_files_are_byte_identical_for_threads_1_2_8_and_repeated_runs() {
    let dir = TempDir::new("nyquist-film-det");
    let mut files: Vec<(String, Vec<u8>)> = Vec::new();
    for threads in [1usize, 2, 8] {
        for run in 0..2 {
            let mut film = Film::new(FilmConfig::new(40, 30), &Mitchell::default()).unwrap();
            render_tiles(
                &mut film,
                7,
                threads,
                |t, _| fill_tile(t, 2, zoneplate),
                |_, _| {},
            )
            .unwrap();
            let (image, _) = film.image();
            for ext in ["exr", "png", "pfm"] {
                let path = dir.join(format!("t{threads}-r{run}.{ext}"));
                write_image_file(&path, &image).unwrap();
                files.push((ext.to_string(), std::fs::read(&path).unwrap()));
            }
        }
    }
    for ext in ["exr", "png", "pfm"] {
        let same: Vec<&Vec<u8>> = files.iter().filter(|f| f.0 == ext).map(|f| &f.1).collect();
        assert_eq!(same.len(), 6);
        let hashes: Vec<u64> = same.iter().map(|b| fnv1a(b)).collect();
        assert!(same.iter().all(|b| *b == same[0]), "{ext}: {hashes:x?}");
        assert!(same[0].len() > 100, "{ext}");
    }
}

#[test]
fn render_tiles_hands_each_closure_its_tile_context_once() {
    let mut film = Film::new(FilmConfig::new(20, 10), &Boxcar::default()).unwrap();
    let specs = film.tiles(8).unwrap();
    let seen = Mutex::new(Vec::new());
    let mut progress = Vec::new();
    render_tiles(
        &mut film,
        8,
        2,
        |tile, ctx| {
            assert_eq!((tile.index(), tile.bounds()), (ctx.index, ctx.bounds));
            seen.lock().unwrap().push(*ctx);
        },
        |done, total| progress.push((done, total)),
    )
    .unwrap();
    let mut seen = seen.into_inner().unwrap();
    seen.sort_by_key(|c| c.index);
    let want: Vec<TileContext> = specs
        .iter()
        .map(|s| TileContext {
            index: s.index,
            count: specs.len(),
            bounds: s.bounds,
        })
        .collect();
    assert_eq!(seen, want);
    assert_eq!(progress, (1..=6).map(|d| (d, 6)).collect::<Vec<_>>());
    // Seeds: distinct per tile, a pure function of (base, index).
    let seeds: std::collections::BTreeSet<u64> = seen.iter().map(|c| c.seed(42)).collect();
    assert_eq!(seeds.len(), 6);
    assert_eq!(seen[3].seed(42), want[3].seed(42));
    assert_ne!(seen[3].seed(42), seen[3].seed(43));
    assert_eq!(seen[5].pixel_range(), Some(([16, 8], [20, 10])));
    assert!(render_tiles(&mut film, 8, 0, |_, _| {}, |_, _| {}).is_err());
    assert!(render_tiles(&mut film, 0, 1, |_, _| {}, |_, _| {}).is_err());
}

#[test]
fn table_and_direct_accumulation_agree_to_the_table_error() {
    // add_sample_direct evaluates the filter; add_sample reads the table. Box and triangle
    // tables are exact (piecewise linear) up to f32 rounding, so those agree closely.
    for (name, filter) in filters() {
        let mut a = Film::new(FilmConfig::new(12, 12), filter.as_ref()).unwrap();
        let mut b = Film::new(FilmConfig::new(12, 12), filter.as_ref()).unwrap();
        let spec = a.tiles(12).unwrap()[0];
        let (mut ta, mut tb) = (a.tile(spec), b.tile(spec));
        let mut rng = nyquist::rng::default_rng(5);
        for _ in 0..200 {
            let p = [
                12.0 * nyquist::rng::uniform_f32(&mut rng),
                12.0 * nyquist::rng::uniform_f32(&mut rng),
            ];
            ta.add_sample(p, [1.0, 0.5, 0.25], 1.0);
            tb.add_sample_direct(filter.as_ref(), p, [1.0, 0.5, 0.25], 1.0);
        }
        a.merge(ta).unwrap();
        b.merge(tb).unwrap();
        let tol = match name {
            "box" | "triangle" => 1e-7, // f32 rounding of the lerp only
            _ => 0.06, // per sample ≤ the documented linear-table error, a few samples per pixel
        };
        for y in 0..12 {
            for x in 0..12 {
                let (pa, pb) = (a.pixel(x, y).unwrap(), b.pixel(x, y).unwrap());
                let scale = pb.weight_sum.abs().max(1.0);
                assert!(
                    (pa.weight_sum - pb.weight_sum).abs() <= tol * scale * 8.0,
                    "{name} ({x},{y}): {} vs {}",
                    pa.weight_sum,
                    pb.weight_sum
                );
            }
        }
    }
}

#[derive(Debug, Clone, Copy)]
enum Order {
    Reversed,
    Interleaved,
}

#[test]
fn non_finite_samples_never_reach_a_pixel_and_are_counted_exactly() {
    let mut film = Film::new(FilmConfig::new(4, 4), &Gaussian::default()).unwrap();
    let spec = film.tiles(4).unwrap()[0];
    let mut tile = film.tile(spec);
    let bad = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
    let mut expected = 0;
    for &b in &bad {
        tile.add_sample([1.5, 1.5], [b, 0.0, 0.0], 1.0);
        tile.add_sample([1.5, 1.5], [0.0, 0.0, b], 1.0);
        tile.add_sample([1.5, 1.5], [1.0, 1.0, 1.0], b);
        tile.add_sample([b, 1.5], [1.0, 1.0, 1.0], 1.0);
        tile.add_splat([1.5, 1.5], [b, 1.0, 1.0]);
        expected += 5;
    }
    tile.add_sample([1.5, 1.5], [0.5, 0.5, 0.5], 1.0);
    assert_eq!(tile.rejected(), expected);
    film.merge(tile).unwrap();
    assert_eq!(film.rejected(), expected);
    assert_eq!(film.stats().samples, 1);
    let (image, _) = film.image();
    assert!(image.data().iter().all(|v| v.is_finite()));
    assert!((image.get(1, 1)[0] - 0.5).abs() < 1e-6);
    // Bit for bit the film that only ever saw the good sample.
    let mut clean = Film::new(FilmConfig::new(4, 4), &Gaussian::default()).unwrap();
    let mut tile = clean.tile(spec);
    tile.add_sample([1.5, 1.5], [0.5, 0.5, 0.5], 1.0);
    clean.merge(tile).unwrap();
    for y in 0..4 {
        for x in 0..4 {
            assert_eq!(film.pixel(x, y), clean.pixel(x, y), "({x}, {y})");
        }
    }
    assert_eq!(image, clean.image().0);
    // A pixel nothing reached resolves to 0 (weight sum 0), not NaN.
    let mut empty = Film::new(FilmConfig::new(2, 2), &Boxcar::default()).unwrap();
    let (img, stats) = empty.image();
    assert_eq!(img.data(), [0.0; 12]);
    assert_eq!(stats.zero_weight_pixels, 4);
}

#[test]
fn negative_lobes_resolve_to_zero_and_are_counted() {
    // Lanczos has negative lobes: a sample 1.5 pixels away gives a negative weight.
    let mut film = Film::new(FilmConfig::new(8, 1), &Lanczos::default()).unwrap();
    let spec = film.tiles(8).unwrap()[0];
    let mut tile = film.tile(spec);
    tile.add_sample([5.0, 0.5], [1.0, 1.0, 1.0], 1.0);
    tile.add_sample([0.5, 0.5], [1.0, 1.0, 1.0], 1.0);
    // A dim blue sample on pixel 3's centre and a bright red one 1.5 pixels away, in its negative
    // lobe: pixel 3's red sum goes negative while its weight sum stays positive.
    tile.add_sample([3.5, 0.5], [0.1, 0.1, 5.0], 1.0);
    tile.add_sample([5.0, 0.5], [10.0, 0.1, 0.1], 1.0);
    film.merge(tile).unwrap();
    // The counts the resolve rule gives, from the pixel sums.
    let (mut negative, mut zero_weight) = (0, 0);
    for x in 0..8 {
        let p = film.pixel(x, 0).unwrap();
        if p.weight_sum > 0.0 {
            negative += p
                .rgb_sum
                .iter()
                .filter(|&&c| c / p.weight_sum < 0.0)
                .count();
        } else {
            zero_weight += 1;
        }
    }
    assert!(negative > 0, "the case has no negative component");
    let (image, stats) = film.image();
    assert_eq!(stats.negative_components as usize, negative);
    assert_eq!(stats.zero_weight_pixels as usize, zero_weight);
    assert!(image.data().iter().all(|&v| v >= 0.0 && v.is_finite()));
}

#[test]
fn max_component_clamp_scales_bright_samples() {
    let mut config = FilmConfig::new(2, 2);
    config.max_component = Some(2.0);
    let mut film = Film::new(config, &Boxcar::default()).unwrap();
    let spec = film.tiles(2).unwrap()[0];
    let mut tile = film.tile(spec);
    tile.add_sample([0.5, 0.5], [8.0, 4.0, 1.0], 1.0);
    tile.add_sample([1.5, 0.5], [1.0, 1.0, 1.0], 1.0);
    film.merge(tile).unwrap();
    assert_eq!(film.stats().clamped, 1);
    let (image, _) = film.image();
    assert_eq!(image.get(0, 0), [2.0, 1.0, 0.25]);
    assert_eq!(image.get(1, 0), [1.0, 1.0, 1.0]);
}

#[test]
fn crop_window_stores_only_its_pixels() {
    let mut config = FilmConfig::new(10, 10);
    config.crop_window = [0.2, 0.5, 0.0, 0.35];
    let film = Film::new(config, &Boxcar::default()).unwrap();
    assert_eq!(film.pixel_bounds(), Bounds::new(2, 0, 5, 4));
    for bad in [
        [0.5, 0.2, 0.0, 1.0],
        [-0.1, 1.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, f32::NAN],
    ] {
        config.crop_window = bad;
        assert!(Film::new(config, &Boxcar::default()).is_err(), "{bad:?}");
    }
    assert!(Film::new(FilmConfig::new(0, 3), &Boxcar::default()).is_err());
}

/// A cropped film stores its pixels at their film coordinates: a box-filtered sample at the
/// centre of pixel (x, y) lands in `pixel(x, y)` and in the image's pixel (x − x0, y − y0),
/// whatever tile size splits the crop (tiles then start away from the film's corner).
#[test]
fn a_cropped_film_keeps_each_sample_at_its_film_coordinates() {
    let mut config = FilmConfig::new(10, 10);
    config.crop_window = [0.2, 0.7, 0.3, 0.9];
    let value = |x: i64, y: i64| (10 * x + y) as f32;
    for size in [1, 2, 3, 16] {
        let mut film = Film::new(config, &Boxcar::default()).unwrap();
        let b = film.pixel_bounds();
        assert_eq!(b, Bounds::new(2, 3, 7, 9));
        for spec in film.tiles(size).unwrap() {
            let mut tile = film.tile(spec);
            for y in spec.bounds.y0..spec.bounds.y1 {
                for x in spec.bounds.x0..spec.bounds.x1 {
                    let p = [x as f32 + 0.5, y as f32 + 0.5];
                    tile.add_sample(p, [value(x, y), 0.0, 0.0], 1.0);
                }
            }
            film.merge(tile).unwrap();
        }
        for y in b.y0..b.y1 {
            for x in b.x0..b.x1 {
                let p = film.pixel(x, y).unwrap();
                assert_eq!((p.rgb_sum[0], p.weight_sum), (f64::from(value(x, y)), 1.0));
            }
        }
        for (x, y) in [(1, 3), (7, 3), (2, 2), (2, 9)] {
            assert!(film.pixel(x, y).is_none(), "({x}, {y}) is outside the crop");
        }
        let (image, _) = film.image();
        assert_eq!((image.width(), image.height()), (5, 6));
        for y in b.y0..b.y1 {
            for x in b.x0..b.x1 {
                assert_eq!(image.get((x - 2) as u32, (y - 3) as u32)[0], value(x, y));
            }
        }
    }
}

/// Tiles partition the pixels: ⌈w/s⌉ · ⌈h/s⌉ of them, none empty, in row order, their areas
/// summing to the film's, also where `s` divides the sides.
#[test]
fn tiles_partition_the_film_with_no_empty_tile() {
    let film = Film::new(FilmConfig::new(12, 8), &Boxcar::default()).unwrap();
    for size in [1u32, 2, 3, 4, 5, 8, 12, 13] {
        let tiles = film.tiles(size).unwrap();
        assert_eq!(
            tiles.len() as u32,
            12u32.div_ceil(size) * 8u32.div_ceil(size),
            "{size}"
        );
        assert!(
            tiles.iter().all(|t| t.bounds.area() > 0),
            "{size}: an empty tile"
        );
        assert_eq!(tiles.iter().map(|t| t.bounds.area()).sum::<u64>(), 96);
        assert!(tiles.iter().enumerate().all(|(i, t)| t.index == i));
    }
    assert!(film.tiles(0).is_err());
}

/// A held tile (its predecessors missing) is applied by `image`, and counted; after that the
/// film has moved past it: merging it, or any tile before it, again is refused.
#[test]
fn image_applies_held_tiles_and_the_film_moves_past_them() {
    let mut film = Film::new(FilmConfig::new(4, 4), &Boxcar::default()).unwrap();
    let specs = film.tiles(2).unwrap();
    let mut tile = film.tile(specs[2]);
    let b = specs[2].bounds;
    tile.add_sample([b.x0 as f32 + 0.5, b.y0 as f32 + 0.5], [3.0, 0.0, 0.0], 1.0);
    film.merge(tile).unwrap();
    assert_eq!(film.stats().samples, 0, "held, not applied yet");
    let (image, _) = film.image();
    assert_eq!(image.get(b.x0 as u32, b.y0 as u32)[0], 3.0);
    assert_eq!(film.stats().samples, 1);
    assert!(film.merge(film.tile(specs[2])).is_err(), "merged twice");
    assert!(film.merge(film.tile(specs[1])).is_err(), "behind the film");
    film.merge(film.tile(specs[3])).unwrap();
}

/// Counters add over tiles, each one separately; storage is 32 bytes a pixel, plus 24 a pixel
/// once splats arrive; the filter radius is the filter's.
#[test]
fn stats_add_over_tiles_and_storage_counts_splats() {
    let mut film = Film::new(FilmConfig::new(10, 5), &Mitchell::default()).unwrap();
    assert_eq!(film.filter_radius(), [2.0, 2.0]);
    assert_eq!(film.storage_bytes(), 50 * 32);
    for spec in film.tiles(5).unwrap() {
        let mut tile = film.tile(spec);
        let c = [spec.bounds.x0 as f32 + 0.5, 2.5];
        tile.add_sample(c, [1.0; 3], 1.0);
        tile.add_sample(c, [f32::NAN; 3], 1.0);
        tile.add_splat(c, [1.0; 3]);
        tile.add_splat(c, [2.0; 3]);
        film.merge(tile).unwrap();
    }
    let s = film.stats();
    assert_eq!((s.samples, s.rejected, s.splats), (2, 2, 4));
    assert_eq!(film.storage_bytes(), 50 * 32 + 50 * 24);
    let wide = Film::new(FilmConfig::new(3, 3), &Boxcar::new([1.5, 0.25]).unwrap()).unwrap();
    assert_eq!(wide.filter_radius(), [1.5, 0.25]);
}

/// A filter whose integral is 0 (an odd plugin: f(x, y) = x) cannot normalise splats: they
/// resolve to 0 instead of an infinite or NaN pixel.
#[test]
fn a_filter_whose_integral_is_zero_is_refused_by_the_film() {
    // An odd filter integrates to 0: splats, normalised by the integral, would divide by 0.
    #[derive(Debug)]
    struct Odd;
    impl Filter for Odd {
        fn radius(&self) -> [f32; 2] {
            [1.0, 1.0]
        }
        fn eval(&self, x: f32, _: f32) -> f32 {
            x
        }
    }
    let e = Film::new(FilmConfig::new(4, 4), &Odd)
        .unwrap_err()
        .to_string();
    assert!(e.contains("filter integral"), "{e}");
}

#[test]
fn merging_a_tile_twice_is_an_error() {
    let mut film = Film::new(FilmConfig::new(4, 4), &Boxcar::default()).unwrap();
    let spec = film.tiles(2).unwrap()[0];
    film.merge(film.tile(spec)).unwrap();
    assert!(film.merge(film.tile(spec)).is_err());
    let later = film.tiles(2).unwrap()[3];
    film.merge(film.tile(later)).unwrap();
    assert!(film.merge(film.tile(later)).is_err());
}

#[test]
fn splats_are_normalised_by_the_filter_integral() {
    // A uniform grid of splats, one per pixel with value v: each pixel gets Σ f·v ≈ v·∫f.
    let mut film = Film::new(FilmConfig::new(16, 16), &Triangle::default()).unwrap();
    let spec = film.tiles(16).unwrap()[0];
    let mut tile = film.tile(spec);
    for y in 0..16 {
        for x in 0..16 {
            for (i, j) in [(0.25f32, 0.25f32), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)] {
                tile.add_splat([x as f32 + i, y as f32 + j], [0.25, 0.25, 0.25]);
            }
        }
    }
    film.merge(tile).unwrap();
    let (image, _) = film.image();
    // Away from the edges (radius 2), the splat sum equals the value.
    let v = image.get(8, 8)[0];
    assert!((v - 1.0).abs() < 1e-3, "{v}");
}

proptest! {
    #[test]
    fn any_tile_rectangle_and_any_sample_keeps_pixels_finite(
        x0 in -5i64..20, y0 in -5i64..20, w in 0i64..12, h in 0i64..12,
        samples in proptest::collection::vec((-10.0f32..30.0, -10.0f32..30.0, -1e30f32..1e30, any::<bool>()), 0..30),
    ) {
        let mut film = Film::new(FilmConfig::new(16, 12), &Mitchell::default()).unwrap();
        let spec = nyquist_film::TileSpec { index: 0, bounds: Bounds::new(x0, y0, x0 + w, y0 + h) };
        let mut tile = film.tile(spec);
        for (x, y, l, nan) in samples {
            let l = if nan { f32::NAN } else { l };
            tile.add_sample([x, y], [l, l.abs(), 1.0], 1.0);
        }
        film.merge(tile).unwrap();
        let (image, _) = film.image();
        prop_assert!(image.data().iter().all(|v| v.is_finite() && *v >= 0.0));
    }
}

#[test]
fn huge_finite_samples_keep_pixel_sums_finite() {
    // Found by the `film` fuzz target: f32::MAX × 4 overflowed to ∞ when the radiance was
    // scaled by the sample weight in f32, and a second, negative sample then made the sum NaN.
    let mut film = Film::new(FilmConfig::new(2, 2), &Boxcar::default()).unwrap();
    let spec = film.tiles(2).unwrap()[0];
    let mut tile = film.tile(spec);
    tile.add_sample([0.5, 0.5], [f32::MAX, 1.0, 1.0], 4.0);
    tile.add_sample([0.5, 0.5], [-f32::MAX, 1.0, 1.0], 2.0);
    assert_eq!((tile.stats().samples, tile.rejected()), (2, 0));
    film.merge(tile).unwrap();
    let p = film.pixel(0, 0).unwrap();
    assert_eq!(p.rgb_sum, [2.0 * f64::from(f32::MAX), 6.0, 6.0]);
    assert_eq!(p.weight_sum, 2.0);
    let (image, _) = film.image();
    assert_eq!(image.get(0, 0), [f32::MAX, 3.0, 3.0]);
}

#[test]
fn a_tile_rectangle_reaching_i64_max_stores_the_films_pixels() {
    // Found by the `film` fuzz target: `⌊x1 − ½ + r⌋ + 1` overflowed for x1 = i64::MAX.
    let mut film = Film::new(FilmConfig::new(3, 2), &Triangle::default()).unwrap();
    let spec = nyquist_film::TileSpec {
        index: 0,
        bounds: Bounds::new(i64::MIN, i64::MIN, i64::MAX, i64::MAX),
    };
    let mut tile = film.tile(spec);
    assert_eq!(tile.pixel_bounds(), film.pixel_bounds());
    tile.add_sample([1.5, 0.5], [1.0; 3], 1.0);
    film.merge(tile).unwrap();
    assert_eq!(film.pixel(1, 0).unwrap().weight_sum, 4.0);
}

#[test]
fn merging_a_tile_of_another_film_is_an_error() {
    // Any FilmTile is a valid argument to `merge`; one made by a bigger film must be refused,
    // not index past this film's pixels.
    let big = Film::new(FilmConfig::new(16, 16), &Boxcar::default()).unwrap();
    let mut small = Film::new(FilmConfig::new(4, 4), &Boxcar::default()).unwrap();
    let mut tile = big.tile(big.tiles(16).unwrap()[0]);
    tile.add_sample([10.5, 10.5], [1.0; 3], 1.0);
    assert!(small.merge(tile).is_err());
    assert_eq!(small.stats(), nyquist_film::FilmStats::default());
    // The small film still takes its own tiles.
    small.merge(small.tile(small.tiles(4).unwrap()[0])).unwrap();
}

/// Filters whose phase tables take the 4 × 4 path: the defaults with radius 2, others with
/// 4 or 5 taps per axis, and one heavy at its edge (a 5-pixel footprint's last pixel weighs
/// f(r) ≠ 0, so taking a 5-pixel footprint as 4 × 4 would lose it).
fn block4_filters() -> [Box<dyn Filter>; 8] {
    [
        Box::new(Mitchell::default()),
        Box::new(Triangle::default()),
        Box::new(Gaussian::default()),
        Box::new(Mitchell::new([1.5, 2.4], 0.3, 0.35).unwrap()),
        Box::new(Triangle::new([1.7, 2.0]).unwrap()),
        Box::new(Gaussian::new([2.2, 1.6], 0.6).unwrap()),
        Box::new(EdgeHeavy([2.0, 1.75])),
        Box::new(EdgeHeavy([1.5, 2.0])),
    ]
}

/// How a test adds sample number `k` (position, radiance, weight) to a tile.
type Add<'a> = &'a dyn Fn(&mut FilmTile, usize, [f32; 2], [f32; 3], f32);

/// `add_sample`, whatever the sample's number.
fn add_sample(t: &mut FilmTile, _k: usize, p: [f32; 2], rgb: [f32; 3], w: f32) {
    t.add_sample(p, rgb, w);
}

/// Adds `samples` `(x, y, red, weight)` to the tile `bounds` of two 10 × 9 films with `f`, the
/// film configured `cfg[i]` through `add[i]`. The first difference in counters or in any
/// pixel's bits, if any.
fn paths_mismatch(
    f: &dyn Filter,
    cfg: [FilmConfig; 2],
    bounds: Bounds,
    samples: &[(f32, f32, f32, f32)],
    add: [Add<'_>; 2],
) -> Option<String> {
    let mut a = Film::new(cfg[0], f).unwrap();
    let mut b = Film::new(cfg[1], f).unwrap();
    let spec = nyquist_film::TileSpec { index: 0, bounds };
    let (mut ta, mut tb) = (a.tile(spec), b.tile(spec));
    for (k, &(x, y, l, wt)) in samples.iter().enumerate() {
        add[0](&mut ta, k, [x, y], [l, 0.5, 2.0], wt);
        add[1](&mut tb, k, [x, y], [l, 0.5, 2.0], wt);
    }
    if ta.stats() != tb.stats() {
        return Some(format!("stats {:?} != {:?}", ta.stats(), tb.stats()));
    }
    a.merge(ta).unwrap();
    b.merge(tb).unwrap();
    for y in 0..9 {
        for x in 0..10 {
            let (pa, pb) = (a.pixel(x, y).unwrap(), b.pixel(x, y).unwrap());
            let bits = |p: nyquist_film::Pixel| {
                p.rgb_sum
                    .map(f64::to_bits)
                    .into_iter()
                    .chain([p.weight_sum.to_bits()])
                    .collect::<Vec<_>>()
            };
            if bits(pa) != bits(pb) {
                return Some(format!("pixel ({x}, {y}): {pa:?} != {pb:?}"));
            }
        }
    }
    None
}

/// The two configurations [`block4_mismatch`] compares: 10 × 9 as is (the 4 × 4 path where it
/// applies) and with a clamp that never bites (`max_component = f32::MAX`), which forces the
/// general path.
fn block4_and_general() -> [FilmConfig; 2] {
    let general = FilmConfig {
        max_component: Some(f32::MAX),
        ..FilmConfig::new(10, 9)
    };
    [FilmConfig::new(10, 9), general]
}

/// [`paths_mismatch`] of `add_sample` on the 4 × 4 path against the general path
/// ([`block4_and_general`]).
fn block4_mismatch(
    f: &dyn Filter,
    bounds: Bounds,
    samples: &[(f32, f32, f32, f32)],
) -> Option<String> {
    paths_mismatch(
        f,
        block4_and_general(),
        bounds,
        samples,
        [&add_sample, &add_sample],
    )
}

/// Samples `(x, y, red, weight)` at every position of an eighth-pixel grid over a 10 × 9 film
/// and a 3-pixel border (pixel edges and centres among them), and of the same grid shifted by
/// 1/512 pixel either way: positions just off the edges and off the phase tables' own grid.
fn eighth_pixel_grids() -> Vec<(f32, f32, f32, f32)> {
    [0.0, 1.0 / 512.0, -1.0 / 512.0]
        .into_iter()
        .flat_map(|shift| {
            (-24..96).flat_map(move |ky| {
                (-24..104)
                    .map(move |kx| (kx as f32 / 8.0 + shift, ky as f32 / 8.0 + shift, 0.75, 1.5))
            })
        })
        .collect()
}

/// The 4 × 4 path against the general path at every position of [`eighth_pixel_grids`]: every
/// phase-0 footprint (5 pixels along an axis with 5 taps) and every 4-or-3 boundary of a 4-tap
/// axis is among them.
#[test]
fn block4_path_matches_the_general_path_on_an_eighth_pixel_grid() {
    // The shifted grids give phases between the phase table's own (1/64 pixel apart), whose
    // taps are interpolated, also from a tap at the radius.
    let samples = eighth_pixel_grids();
    for (i, f) in block4_filters().iter().enumerate() {
        if let Some(m) = block4_mismatch(&**f, Bounds::new(0, 0, 10, 9), &samples) {
            panic!("filter {i}: {m}");
        }
    }
}

/// A one-pixel footprint of a filter that is not a box adds its weight `f` and exactly `f·l`:
/// with one sample per pixel, every pixel's RGB sums are its weight sum times the sample's
/// `rgb · w`, bit for bit (radiances that are not powers of two, so another order of the
/// products would round differently).
#[test]
fn one_pixel_footprints_add_the_weight_times_the_radiance_exactly() {
    let small = Triangle::new([0.45, 0.4]).unwrap();
    let mut film = Film::new(FilmConfig::new(12, 12), &small).unwrap();
    let spec = film.tiles(12).unwrap()[0];
    let mut tile = film.tile(spec);
    let (rgb, w) = ([0.7f32, 0.3, 0.1], 0.9f32);
    let mut rng = nyquist::rng::default_rng(3);
    for y in 0..12 {
        for x in 0..12 {
            // Within 0.35 of the centre on each axis: inside both radii, one pixel reached.
            let mut u = || 0.15 + 0.7 * nyquist::rng::uniform_f32(&mut rng);
            tile.add_sample([x as f32 + u(), y as f32 + u()], rgb, w);
        }
    }
    film.merge(tile).unwrap();
    for y in 0..12 {
        for x in 0..12 {
            let p = film.pixel(x, y).unwrap();
            assert!(p.weight_sum > 0.0, "({x},{y})");
            for c in 0..3 {
                let l = f64::from(rgb[c]) * f64::from(w);
                assert_eq!(p.rgb_sum[c], p.weight_sum * l, "({x},{y}) channel {c}");
            }
        }
    }
}

/// The one-pixel path of box filters (radius ½, and narrower ones that can miss a pixel's
/// centre) against the general path, bit for bit, at every position of [`eighth_pixel_grids`],
/// in the film's tile and in a tile inside it; also NaN, ∞ and weights of 0.
#[test]
fn one_pixel_path_matches_the_general_path() {
    let mut samples = eighth_pixel_grids();
    samples.extend([
        (f32::NAN, 2.0, 1.0, 1.0),
        (2.5, f32::INFINITY, 1.0, 1.0),
        (3.5, 3.5, f32::INFINITY, 1.0),
        (4.5, 4.5, 1.0, 0.0),
    ]);
    let general = FilmConfig {
        max_component: Some(f32::MAX),
        ..FilmConfig::new(10, 9)
    };
    for radius in [[0.5, 0.5], [0.3, 0.45], [0.5, 0.2]] {
        let f = Boxcar::new(radius).unwrap();
        for bounds in [Bounds::new(0, 0, 10, 9), Bounds::new(2, 3, 7, 8)] {
            let mismatch = paths_mismatch(
                &f,
                [FilmConfig::new(10, 9), general],
                bounds,
                &samples,
                [&add_sample, &add_sample],
            );
            assert_eq!(mismatch, None, "radius {radius:?}, tile {bounds:?}");
        }
    }
}

/// `add_sample_direct` on a tile that holds 4 × 4 samples in its queue adds after them: a run
/// mixing the two calls gives the counters and sums, bit for bit, of a film that holds nothing
/// (the general path, [`block4_and_general`]). Radiances spread over many magnitudes, so any
/// change in the order of a pixel's additions changes its bits.
#[test]
fn direct_samples_are_added_after_the_queued_ones() {
    let f = Mitchell::default();
    let samples: Vec<_> = (0..45u16)
        .map(|k| {
            let (x, y) = (2.6 + f32::from(k % 5) * 0.9, 2.3 + f32::from(k % 4) * 1.1);
            (x, y, 1.37f32.powi(i32::from(k % 23)), 1.0)
        })
        .collect();
    let mixed = |t: &mut FilmTile, k: usize, p, rgb, w| {
        if k % 6 == 5 {
            t.add_sample_direct(&f, p, rgb, w);
        } else {
            t.add_sample(p, rgb, w);
        }
    };
    let bounds = Bounds::new(0, 0, 10, 9);
    let mismatch = paths_mismatch(&f, block4_and_general(), bounds, &samples, [&mixed, &mixed]);
    assert_eq!(mismatch, None);
}

/// A separable plugin filter that is largest at its edge: `1 + |d|/4` inside its radius, so a
/// pixel at exactly the radius, or a tap interpolated from there, weighs more than any other.
struct EdgeHeavy([f32; 2]);

impl Filter for EdgeHeavy {
    fn radius(&self) -> [f32; 2] {
        self.0
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        match (self.eval_1d(Axis::X, x), self.eval_1d(Axis::Y, y)) {
            (Some(a), Some(b)) => a * b,
            _ => 0.0,
        }
    }
    fn eval_1d(&self, axis: Axis, d: f32) -> Option<f32> {
        let r = self.0[axis.index()];
        Some(if d.abs() <= r {
            1.0 + d.abs() / 4.0
        } else {
            0.0
        })
    }
}

proptest! {
    /// Boxes of radius ≤ ½ take `add_sample`'s one-pixel path; everything it declines (pixel
    /// edges, the stored area's border, non-finite input) goes through the footprint. Either
    /// way the sums and counters are those of the footprint path with the filter evaluated
    /// directly, bit for bit. Positions on a quarter-pixel lattice hit the edges often.
    #[test]
    fn one_pixel_box_path_matches_the_footprint_path_bit_for_bit(
        radius in prop_oneof![Just([0.5f32, 0.5]), Just([0.3, 0.3]), Just([0.5, 0.2]), Just([0.1, 0.45])],
        x0 in -3i64..10, y0 in -3i64..10, w in 0i64..8, h in 0i64..8,
        samples in proptest::collection::vec(
            (
                prop_oneof![(-12i32..60).prop_map(|k| k as f32 / 4.0), -3.0f32..15.0, Just(f32::NAN), Just(f32::INFINITY)],
                prop_oneof![(-12i32..60).prop_map(|k| k as f32 / 4.0), -3.0f32..15.0],
                prop_oneof![-1e30f32..1e30, Just(f32::NAN), Just(f32::NEG_INFINITY), Just(f32::MAX)],
                prop_oneof![0.0f32..4.0, Just(f32::INFINITY), Just(0.0)],
            ),
            0..40,
        ),
    ) {
        let filter = Boxcar::new(radius).unwrap();
        let cfg = FilmConfig::new(10, 9);
        let mismatch = paths_mismatch(
            &filter,
            [cfg, cfg],
            Bounds::new(x0, y0, x0 + w, y0 + h),
            &samples,
            [&add_sample, &|t, _, p, rgb, wt| t.add_sample_direct(&filter, p, rgb, wt)],
        );
        prop_assert_eq!(mismatch, None);
    }

    /// Phase-table filters whose footprints are often 4 × 4 take `add_sample`'s 4 × 4 path;
    /// what it declines (other widths, the stored area's border, phase 0, non-finite input)
    /// goes through the footprint. Either way the sums and counters are those of the general
    /// path, which a clamp that never bites (`max_component = f32::MAX`) forces on the second
    /// film, bit for bit. Positions on 1/8- and 1/64-pixel lattices hit the table's grid, phase 0
    /// and the 4-or-5-pixel boundary often.
    #[test]
    fn block4_path_matches_the_general_path_bit_for_bit(
        filter in 0usize..7,
        x0 in -3i64..10, y0 in -3i64..10, w in 0i64..9, h in 0i64..9,
        samples in proptest::collection::vec(
            (
                prop_oneof![(-24i32..120).prop_map(|k| k as f32 / 8.0), (-200i32..1000).prop_map(|k| k as f32 / 64.0), -3.0f32..15.0, Just(f32::NAN), Just(f32::INFINITY)],
                prop_oneof![(-24i32..120).prop_map(|k| k as f32 / 8.0), (-200i32..1000).prop_map(|k| k as f32 / 64.0), -3.0f32..15.0, Just(f32::NEG_INFINITY)],
                prop_oneof![-1e30f32..1e30, Just(f32::NAN), Just(f32::MAX)],
                prop_oneof![0.0f32..4.0, Just(f32::INFINITY), Just(0.0)],
            ),
            0..40,
        ),
    ) {
        let bounds = Bounds::new(x0, y0, x0 + w, y0 + h);
        let mismatch = block4_mismatch(&*block4_filters()[filter], bounds, &samples);
        prop_assert_eq!(mismatch, None);
    }
}

/// A film or image larger than the allocator can give is an `OutOfMemory` error naming the
/// bytes, not an abort: 2³² × 2³² pixels cannot be allocated anywhere.
#[test]
fn films_and_images_larger_than_memory_are_errors() {
    match Film::new(
        FilmConfig::new(u32::MAX, u32::MAX),
        &nyquist::filter::Boxcar::default(),
    ) {
        Err(nyquist_film::Error::OutOfMemory { what, bytes }) => {
            assert_eq!(what, "the film's pixels");
            assert_eq!(bytes, usize::MAX);
        }
        other => panic!("{:?}", other.map(|_| ())),
    }
    match nyquist_film::Image::new(1 << 31, 1 << 20) {
        Err(e @ nyquist_film::Error::OutOfMemory { .. }) => {
            assert_eq!(
                e.to_string(),
                format!("out of memory: {} bytes for an image", 12usize << 51)
            );
        }
        other => panic!("{:?}", other.map(|_| ())),
    }
}

/// Samples added to the film itself (`Film::add_sample`, `Film::add_splat`) sum exactly what
/// the same samples sum through one tile over the whole film, merged: every pixel's bits, the
/// counters and the storage, for filters on every path (box, 4 × 4 block, general phase table,
/// the 64-entry fallback for a wide filter and for a non-separable one), at positions on and
/// off pixel edges and outside the film.
#[test]
fn the_film_itself_sums_what_one_whole_film_tile_sums() {
    let mut filters: Vec<Box<dyn Filter>> = block4_filters().into_iter().collect();
    filters.push(Box::new(Boxcar::default()));
    filters.push(Box::new(Boxcar::new([0.3, 1.5]).unwrap()));
    filters.push(Box::new(Lanczos::default()));
    filters.push(Box::new(Gaussian::new([9.0, 8.5], 2.0).unwrap()));
    filters.push(Box::new(Cone(1.5)));
    let samples = eighth_pixel_grids();
    for (i, f) in filters.iter().enumerate() {
        for max_component in [None, Some(1.0)] {
            let config = FilmConfig {
                max_component,
                ..FilmConfig::new(10, 9)
            };
            let mut itself = Film::new(config, &**f).unwrap();
            let mut tiled = Film::new(config, &**f).unwrap();
            let spec = nyquist_film::TileSpec {
                index: 0,
                bounds: tiled.pixel_bounds(),
            };
            let mut tile = tiled.tile(spec);
            for (k, &(x, y, l, w)) in samples.iter().enumerate() {
                let rgb = [l, 0.5, 2.0];
                if k % 7 == 3 {
                    itself.add_splat([x, y], rgb);
                    tile.add_splat([x, y], rgb);
                } else {
                    itself.add_sample([x, y], rgb, w);
                    tile.add_sample([x, y], rgb, w);
                }
            }
            tiled.merge(tile).unwrap();
            assert_eq!(itself.stats(), tiled.stats(), "filter {i}");
            assert_eq!(itself.storage_bytes(), tiled.storage_bytes(), "filter {i}");
            for y in 0..9 {
                for x in 0..10 {
                    let (a, b) = (itself.pixel(x, y).unwrap(), tiled.pixel(x, y).unwrap());
                    assert_eq!(
                        (a.rgb_sum.map(f64::to_bits), a.weight_sum.to_bits()),
                        (b.rgb_sum.map(f64::to_bits), b.weight_sum.to_bits()),
                        "filter {i}, pixel ({x}, {y})"
                    );
                }
            }
            assert_eq!(bits(&mut itself), bits(&mut tiled), "filter {i}");
        }
    }
}

/// `try_image` refuses a film while a tile is missing (after the last merged one, or before a
/// held one), says how many pixels no merged tile covers and how many tiles wait, and leaves
/// the film as it was, so the missing tile can still be merged; then it gives the image of the
/// film merged in order. `image` resolves the partial film anyway and counts the uncovered
/// pixels.
#[test]
fn try_image_refuses_a_film_with_a_missing_tile() {
    let make = || Film::new(FilmConfig::new(6, 4), &Mitchell::default()).unwrap();
    let filled = |film: &Film, spec| {
        let mut t = film.tile(spec);
        fill_tile(&mut t, 2, zoneplate);
        t
    };
    let mut reference = make();
    let specs = reference.tiles(2).unwrap(); // 3 × 2 tiles of 2 × 2
    for &s in &specs {
        let t = filled(&reference, s);
        reference.merge(t).unwrap();
    }
    let want = bits(&mut reference);

    // The last tile missing: nothing held, its 4 pixels uncovered.
    let mut film = make();
    for &s in &specs[..5] {
        let t = filled(&film, s);
        film.merge(t).unwrap();
    }
    match film.try_image() {
        Err(nyquist_film::Error::Incomplete {
            uncovered,
            pixels,
            held,
        }) => assert_eq!((uncovered, pixels, held), (4, 24, 0)),
        other => panic!("{:?}", other.map(|_| ())),
    }
    let t = filled(&film, specs[5]);
    film.merge(t).unwrap();
    let (image, stats) = film.try_image().unwrap();
    assert_eq!(stats.uncovered_pixels, 0);
    assert_eq!(
        image.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        want
    );

    // Tile 1 missing, tiles 2 … 5 held behind it: the error counts what is missing without
    // applying the held tiles, so tile 1 can still be merged and the film ends bit-identical.
    let mut film = make();
    for &s in specs.iter().filter(|s| s.index != 1) {
        let t = filled(&film, s);
        film.merge(t).unwrap();
    }
    let e = film.try_image().unwrap_err();
    assert!(
        matches!(
            e,
            nyquist_film::Error::Incomplete {
                uncovered: 4,
                pixels: 24,
                held: 4
            }
        ),
        "{e:?}"
    );
    assert!(e.to_string().contains("4 of its 24 pixels"), "{e}");
    assert_eq!(film.stats().samples, 16, "the held tiles are still held");
    let t = filled(&film, specs[1]);
    film.merge(t).unwrap();
    assert_eq!(bits(&mut film), want);

    // `image` resolves a partial film and counts its uncovered pixels.
    let mut partial = make();
    let t = filled(&partial, specs[0]);
    partial.merge(t).unwrap();
    assert_eq!(partial.image().1.uncovered_pixels, 20);
    // A film that took its samples itself is one whole-film tile: complete.
    let mut itself = make();
    itself.add_sample([0.5, 0.5], [1.0; 3], 1.0);
    assert_eq!(itself.try_image().unwrap().1.uncovered_pixels, 0);
}

/// Bad parameters are errors whose message names the parameter, the value and the range or
/// the value it had to exceed.
#[test]
fn film_errors_name_the_value_and_the_limit() {
    let boxcar = Boxcar::default();
    let msg = |config: FilmConfig| Film::new(config, &boxcar).unwrap_err().to_string();
    assert_eq!(
        msg(FilmConfig::new(0, 4)),
        "width 0 is outside 1..=4294967295"
    );
    assert_eq!(
        msg(FilmConfig::new(4, 0)),
        "height 0 is outside 1..=4294967295"
    );
    let crop = |c: [f32; 4]| FilmConfig {
        crop_window: c,
        ..FilmConfig::new(4, 4)
    };
    assert_eq!(
        msg(crop([0.0, 1.5, 0.0, 1.0])),
        "crop window x1 1.5 is outside 0..=1"
    );
    assert_eq!(
        msg(crop([0.0, 1.0, f32::NAN, 1.0])),
        "crop window y0 NaN is outside 0..=1"
    );
    assert!(msg(crop([0.0, 1.0, 0.75, 0.5])).contains("y0 0.75 is not below y1 0.5"));
    assert!(msg(crop([0.1, 0.2, 0.0, 1.0])).contains("covers no pixel of 4x4"));
    let clamp = FilmConfig {
        max_component: Some(-2.0),
        ..FilmConfig::new(4, 4)
    };
    assert!(msg(clamp).contains("max component -2 must be finite and above 0"));
    let film = Film::new(FilmConfig::new(4, 4), &boxcar).unwrap();
    assert_eq!(
        film.tiles(0).unwrap_err().to_string(),
        "tile size 0 is outside 1..=4294967295"
    );
    let e = nyquist_film::Image::new(3, 0).unwrap_err().to_string();
    assert_eq!(e, "image height 0 is outside 1..=4294967295");
    let e = nyquist_film::Image::new(u32::MAX, u32::MAX)
        .unwrap_err()
        .to_string();
    assert!(e.contains("4294967295x4294967295 needs"), "{e}");
}

/// A splat whose footprint holds no column (a box of radius 0.3 at x = 1.0: the pixel centres
/// 0.5 and 1.5 are both 0.5 away) reaches no pixel, so it allocates no splat sums: the film's
/// storage stays 32 bytes a pixel, and the splat is counted. (A footprint test that let zero
/// columns through would allocate 24 more bytes a pixel: 896 bytes instead of 512.)
#[test]
fn a_splat_that_reaches_no_column_allocates_no_splat_sums() {
    let boxcar = Boxcar::new([0.3, 0.3]).unwrap();
    let mut film = Film::new(FilmConfig::new(4, 4), &boxcar).unwrap();
    let spec = film.tiles(4).unwrap()[0];
    let mut tile = film.tile(spec);
    tile.add_splat([1.0, 2.5], [1.0; 3]);
    film.merge(tile).unwrap();
    assert_eq!(film.storage_bytes(), 16 * 32);
    assert_eq!(film.stats().splats, 1);
    // The same through the film itself.
    film.add_splat([1.0, 2.5], [1.0; 3]);
    assert_eq!(film.storage_bytes(), 16 * 32);
    // A splat that reaches a pixel allocates the splat sums.
    film.add_splat([1.5, 2.5], [1.0; 3]);
    assert_eq!(film.storage_bytes(), 16 * (32 + 24));
}
