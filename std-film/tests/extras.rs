//! Per-pixel extras: the variance against a two-pass computation, the halves' split, channels
//! filtered like radiance, the image unchanged by keeping them, and bit-identical results for
//! any thread count and merge order.

use nyquist::filter::{Axis, Boxcar, Filter, Gaussian, Lanczos, Mitchell, Triangle};
use nyquist_film::extras::sample_half;
use nyquist_film::{Film, FilmConfig, FilmSample, FilmTile, PixelExtras, render_tiles};
use proptest::prelude::*;

#[path = "../../core/src/tests/double_double.rs"]
mod double_double;
#[path = "support/temp_dir.rs"]
mod temp_dir;

fn filters() -> Vec<(&'static str, Box<dyn Filter + Sync>)> {
    vec![
        ("box", Box::new(Boxcar::default())),
        ("narrow box", Box::new(Boxcar::new([0.3, 0.5]).unwrap())),
        ("triangle", Box::new(Triangle::default())),
        ("gaussian", Box::new(Gaussian::default())),
        ("mitchell", Box::new(Mitchell::default())),
        ("lanczos", Box::new(Lanczos::default())),
    ]
}

const ALL: PixelExtras = PixelExtras {
    variance: true,
    halves: true,
    channels: 2,
};

/// A small deterministic generator (PCG-style LCG, top bits).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// `n` samples per pixel of the tile at pseudo-random positions (seeded by the tile's index, so
/// any schedule adds the same samples), radiance and two channels from the position.
fn fill(tile: &mut FilmTile, n: u64, with_extras: bool) {
    let b = tile.bounds();
    let mut rng = Lcg(tile.index() as u64 + 1);
    for y in b.y0..b.y1 {
        for x in b.x0..b.x1 {
            for i in 0..n {
                let p = [x as f32 + rng.next(), y as f32 + rng.next()];
                let v = 0.5 + 0.5 * (p[0] * 0.7).sin() * (p[1] * 0.45).cos();
                let rgb = [v, rng.next() * 2.0, 1.0 - v];
                let channels = [p[0] * 0.1, v];
                if with_extras {
                    tile.add(&FilmSample {
                        index: i,
                        channels: &channels,
                        ..FilmSample::new(p, rgb, 0.75)
                    });
                } else {
                    tile.add_sample(p, rgb, 0.75);
                }
            }
        }
    }
}

fn film(extras: PixelExtras, filter: &dyn Filter, clamp: Option<f32>) -> Film {
    let config = FilmConfig {
        extras,
        max_component: clamp,
        ..FilmConfig::new(23, 17)
    };
    Film::new(config, filter).unwrap()
}

fn render(film: &mut Film, tile: u32, threads: usize, with_extras: bool) {
    render_tiles(
        film,
        tile,
        threads,
        |t, _| fill(t, 6, with_extras),
        |_, _| {},
    )
    .unwrap();
}

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|v| v.to_bits()).collect()
}

/// Every layer of the film, as bits: the image, the variance, both halves, the channels.
fn all_bits(film: &mut Film) -> Vec<Vec<u32>> {
    let image = film.try_image().unwrap().0;
    let e = film.extra_images().unwrap();
    let [a, b] = e.halves.unwrap();
    vec![
        bits(image.data()),
        bits(e.variance.unwrap().data()),
        bits(a.data()),
        bits(b.data()),
        bits(e.channels.unwrap().data()),
    ]
}

#[test]
fn keeping_extras_leaves_the_image_unchanged_bit_for_bit() {
    for (name, f) in filters() {
        for clamp in [None, Some(0.9)] {
            let mut plain = film(PixelExtras::default(), f.as_ref(), clamp);
            let mut kept = film(ALL, f.as_ref(), clamp);
            render(&mut plain, 8, 1, false);
            render(&mut kept, 8, 1, true);
            let (a, b) = (plain.try_image().unwrap(), kept.try_image().unwrap());
            assert_eq!(
                bits(a.0.data()),
                bits(b.0.data()),
                "{name}, clamp {clamp:?}"
            );
            assert_eq!(plain.stats(), kept.stats(), "{name}");
            // The film itself (no tiles) too.
            let mut plain = film(PixelExtras::default(), f.as_ref(), clamp);
            let mut kept = film(ALL, f.as_ref(), clamp);
            let mut rng = Lcg(7);
            for i in 0..2000 {
                let p = [rng.next() * 23.0, rng.next() * 17.0];
                let rgb = [rng.next(), rng.next(), rng.next()];
                plain.add_sample(p, rgb, 1.0);
                kept.add(&FilmSample {
                    index: i,
                    channels: &[0.0, 1.0],
                    ..FilmSample::new(p, rgb, 1.0)
                });
            }
            let (a, b) = (plain.try_image().unwrap(), kept.try_image().unwrap());
            assert_eq!(bits(a.0.data()), bits(b.0.data()), "{name}, film itself");
        }
    }
}

#[test]
fn extras_are_bit_identical_for_any_thread_count_and_merge_order() {
    let m = Mitchell::default();
    let reference = {
        let mut f = film(ALL, &m, None);
        render(&mut f, 5, 1, true);
        all_bits(&mut f)
    };
    for threads in [2, 3, 8] {
        let mut f = film(ALL, &m, None);
        render(&mut f, 5, threads, true);
        assert_eq!(all_bits(&mut f), reference, "threads {threads}");
    }
    // Merged in reverse and interleaved order.
    for reverse in [true, false] {
        let mut f = film(ALL, &m, None);
        let mut tiles: Vec<FilmTile> = f
            .tiles(5)
            .unwrap()
            .into_iter()
            .map(|s| {
                let mut t = f.tile(s);
                fill(&mut t, 6, true);
                t
            })
            .collect();
        if reverse {
            tiles.reverse();
        } else {
            let (even, odd): (Vec<_>, Vec<_>) = tiles.into_iter().partition(|t| t.index() % 2 == 0);
            tiles = odd.into_iter().chain(even).collect();
        }
        for t in tiles {
            f.merge(t).unwrap();
        }
        assert_eq!(all_bits(&mut f), reference, "reverse {reverse}");
    }
}

/// The variance of pixel `(px, py)`'s weighted mean, by two passes in double-double over the
/// samples that reach it (weights `f = fx·fy` from `eval_1d`, as the film's direct path takes
/// them).
fn two_pass(samples: &[([f32; 2], f64)], filter: &Mitchell, px: i64, py: i64) -> f64 {
    let reach: Vec<(f64, f64)> = samples
        .iter()
        .map(|&(p, x)| {
            let dx = (px as f32 + 0.5) - p[0];
            let dy = (py as f32 + 0.5) - p[1];
            let fx = filter.eval_1d(Axis::X, dx).unwrap();
            let fy = filter.eval_1d(Axis::Y, dy).unwrap();
            (f64::from(fx) * f64::from(fy), x)
        })
        .filter(|&(f, _)| f != 0.0)
        .collect();
    double_double::variance_of_mean(&reach)
}

#[test]
fn the_variance_equals_a_two_pass_computation_on_random_data() {
    // Mitchell's negative lobes and values far from 0 (mean 100, spread 1): the case a one-pass
    // Σx² form loses to cancellation. Positions on a 1/64 grid, so every offset to a pixel
    // centre is exact in f32 and the weights are the ones the reference computes.
    let m = Mitchell::default();
    let config = FilmConfig {
        extras: PixelExtras {
            variance: true,
            ..PixelExtras::default()
        },
        ..FilmConfig::new(6, 5)
    };
    let mut film = Film::new(config, &m).unwrap();
    let mut rng = Lcg(42);
    let mut samples = Vec::new();
    for _ in 0..3000 {
        let p = [
            (rng.next() * 6.0 * 64.0).floor() / 64.0,
            (rng.next() * 5.0 * 64.0).floor() / 64.0,
        ];
        samples.push((p, f64::from(100.0 + rng.next())));
    }
    // One tile holding every sample, added in order as the reference takes them.
    let spec = film.tiles(64).unwrap()[0];
    let mut tile = film.tile(spec);
    for &(p, v) in &samples {
        let v = v as f32;
        tile.add_sample_direct(&m, p, [v, v * 0.5, -v], 1.0);
    }
    film.merge(tile).unwrap();
    let mut worst = 0.0f64;
    for y in 0..5 {
        for x in 0..6 {
            let want = two_pass(&samples, &m, x, y);
            let got = film.estimate(x, y).unwrap().variance.unwrap()[0];
            worst = worst.max(double_double::ulps(got, want));
        }
    }
    // Measured: 781 ulps at most over the 30 pixels (about 100 samples each, values 100 ± 0.5,
    // a condition number near 10⁵); the bound is 2¹² ulps.
    assert!(worst <= 4096.0, "{worst} ulps");
}

#[test]
fn halves_split_the_samples_by_class_and_sum_to_the_whole() {
    let config = FilmConfig {
        extras: PixelExtras {
            halves: true,
            ..PixelExtras::default()
        },
        ..FilmConfig::new(3, 1)
    };
    let mut film = Film::new(config, &Boxcar::default()).unwrap();
    // In pixel 0, class A samples are 1 and class B samples 3; in pixel 1 every index is in A,
    // in pixel 2 every index is in B.
    for i in 0..64u64 {
        let v = [1.0, 3.0][sample_half(i)];
        film.add(&FilmSample {
            index: i,
            ..FilmSample::new([0.5, 0.5], [v; 3], 1.0)
        });
        film.add(&FilmSample {
            index: 0,
            ..FilmSample::new([1.5, 0.5], [v; 3], 1.0)
        });
        film.add(&FilmSample {
            index: 2,
            ..FilmSample::new([2.5, 0.5], [v; 3], 1.0)
        });
    }
    let e = film.estimate(0, 0).unwrap();
    assert_eq!(e.value, [2.0; 3]);
    assert_eq!(e.halves, Some([[1.0; 3], [3.0; 3]]));
    assert_eq!(e.half_difference(), Some([1.0; 3]));
    // An empty half, either one: no halves estimate, rather than a made-up one.
    assert_eq!(film.estimate(1, 0).unwrap().halves, None);
    assert_eq!(film.estimate(2, 0).unwrap().halves, None);
    let [a, b] = film.extra_images().unwrap().halves.unwrap();
    assert_eq!((a.get(0, 0), b.get(0, 0)), ([1.0; 3], [3.0; 3]));
    assert_eq!((a.get(1, 0), b.get(1, 0)), ([2.0; 3], [0.0; 3]));
}

#[test]
fn halves_of_a_stratified_sequence_estimate_the_error() {
    // Owen-scrambled Sobol points in a pixel over a step edge: each half is a (0, 2)-net of
    // half the points, so |A − B|/2 and the standard error are both small and of one scale.
    use nyquist::sequence::{OwenSobol, Sequence};
    let config = FilmConfig {
        extras: PixelExtras {
            variance: true,
            halves: true,
            channels: 0,
        },
        ..FilmConfig::new(1, 1)
    };
    let mut film = Film::new(config, &Boxcar::default()).unwrap();
    let s = OwenSobol::new(2, 7).unwrap();
    for i in 0..256u64 {
        let [u, v] = [s.sample(i, 0), s.sample(i, 1)];
        let l = if u * u + v * v < 0.5 { 1.0 } else { 0.0 };
        film.add(&FilmSample {
            index: i,
            ..FilmSample::new([u, v], [l; 3], 1.0)
        });
    }
    let e = film.estimate(0, 0).unwrap();
    let se = e.standard_error().unwrap()[0];
    let d = e.half_difference().unwrap()[0];
    // The exact coverage of the quarter disk of radius √½ is π/8: the value is within the
    // (i.i.d.) standard error of 256 samples, and the halves agree better than that, as
    // stratified halves do.
    let exact = std::f64::consts::PI / 8.0;
    assert!((e.value[0] - exact).abs() < se, "{} ± {se}", e.value[0]);
    assert!(d < se, "|A − B|/2 = {d}, s.e. = {se}");
}

#[test]
fn channels_are_filtered_like_the_radiance() {
    for (name, f) in filters() {
        let config = FilmConfig {
            extras: PixelExtras {
                channels: 3,
                ..PixelExtras::default()
            },
            ..FilmConfig::new(9, 7)
        };
        let mut film = Film::new(config, f.as_ref()).unwrap();
        let mut rng = Lcg(3);
        for _ in 0..3000 {
            let p = [rng.next() * 9.0, rng.next() * 7.0];
            let rgb = [rng.next(), rng.next() + 1.0, rng.next() * 4.0];
            // Channels equal to the radiance (weight 1): their means are the pixel's value.
            film.add(&FilmSample {
                channels: &rgb,
                ..FilmSample::new(p, rgb, 1.0)
            });
        }
        let channels = film.extra_images().unwrap().channels.unwrap();
        assert_eq!(channels.channels(), 3);
        for y in 0..7 {
            for x in 0..9 {
                let value = film.estimate(x, y).unwrap().value;
                let got = channels.pixel(x as u32, y as u32);
                let via = film.channel_values(x, y).unwrap();
                for c in 0..3 {
                    let tol = 1e-6 * value[c].abs().max(1.0);
                    assert!(
                        (f64::from(got[c]) - value[c]).abs() <= tol,
                        "{name} ({x}, {y})"
                    );
                    assert!((via[c] - value[c]).abs() <= 1e-12 * value[c].abs().max(1.0));
                }
            }
        }
    }
}

#[test]
fn samples_with_the_wrong_channels_are_rejected_and_counted() {
    let config = FilmConfig {
        extras: PixelExtras {
            channels: 2,
            ..PixelExtras::default()
        },
        ..FilmConfig::new(4, 4)
    };
    let film = Film::new(config, &Mitchell::default()).unwrap();
    let mut tile = film.tile(film.tiles(4).unwrap()[0]);
    let s = FilmSample::new([1.5, 1.5], [1.0; 3], 1.0);
    tile.add(&FilmSample {
        channels: &[1.0, 2.0],
        ..s
    });
    tile.add(&FilmSample {
        channels: &[1.0],
        ..s
    });
    tile.add(&FilmSample {
        channels: &[1.0, 2.0, 3.0],
        ..s
    });
    tile.add(&FilmSample {
        channels: &[f32::NAN, 2.0],
        ..s
    });
    tile.add(&FilmSample {
        channels: &[1.0, f32::INFINITY],
        ..s
    });
    tile.add_sample([1.5, 1.5], [1.0; 3], 1.0);
    tile.add_sample_direct(&Mitchell::default(), [1.5, 1.5], [1.0; 3], 1.0);
    assert_eq!((tile.stats().samples, tile.rejected()), (1, 6));
    // And a film that keeps no channels refuses samples that carry some.
    let mut plain = Film::new(FilmConfig::new(4, 4), &Boxcar::default()).unwrap();
    plain.add(&FilmSample {
        channels: &[1.0],
        ..s
    });
    plain.add(&s);
    assert_eq!((plain.stats().samples, plain.rejected()), (1, 1));
}

#[test]
fn extras_cost_the_bytes_they_state() {
    let plain = Film::new(FilmConfig::new(10, 10), &Boxcar::default()).unwrap();
    let mut config = FilmConfig::new(10, 10);
    config.extras = ALL;
    let kept = Film::new(config, &Boxcar::default()).unwrap();
    assert_eq!(ALL.bytes_per_pixel(), 56 + 32 + 16);
    assert_eq!(
        kept.storage_bytes() - plain.storage_bytes(),
        100 * ALL.bytes_per_pixel()
    );
    config.extras.channels = nyquist_film::extras::MAX_CHANNELS + 1;
    let e = Film::new(config, &Boxcar::default()).unwrap_err();
    assert_eq!(e.to_string(), "extra channels 65 is outside 0..=64");
    // A film that keeps nothing has no extra images.
    let mut plain = plain;
    let e = plain.extra_images().unwrap();
    assert!(e.variance.is_none() && e.halves.is_none() && e.channels.is_none());
}

/// A film with every extra, rendered, as named planes.
fn rendered_planes() -> (u32, u32, Vec<nyquist_film::output::exr::Plane>) {
    let mut f = film(ALL, &Mitchell::default(), None);
    render(&mut f, 8, 2, true);
    let image = f.try_image().unwrap().0;
    let planes = f
        .extra_images()
        .unwrap()
        .planes(&image, &["depth.Z", "id.Y"])
        .unwrap();
    (image.width(), image.height(), planes)
}

fn exr_bytes(w: u32, h: u32, planes: &[nyquist_film::output::exr::Plane]) -> Vec<u8> {
    let borrowed: Vec<(&str, &[f32])> = planes
        .iter()
        .map(|(n, p)| (n.as_str(), p.as_slice()))
        .collect();
    let mut bytes = Vec::new();
    nyquist_film::output::exr::write_exr_planes(&mut bytes, w, h, &borrowed).unwrap();
    bytes
}

#[test]
fn layers_round_trip_through_openexr_bit_for_bit() {
    let (w, h, mut planes) = rendered_planes();
    assert_eq!(planes.len(), 3 + 3 + 6 + 2);
    let bytes = exr_bytes(w, h, &planes);
    let (rw, rh, read) = nyquist_film::output::exr::read_exr_planes(&mut bytes.as_slice()).unwrap();
    assert_eq!((rw, rh), (w, h));
    // The file holds the channels in OpenEXR's alphabetical order.
    planes.sort_by(|a, b| a.0.cmp(&b.0));
    let names = |p: &[nyquist_film::output::exr::Plane]| -> Vec<String> {
        p.iter().map(|(n, _)| n.clone()).collect()
    };
    assert_eq!(names(&read), names(&planes));
    for ((name, got), (_, want)) in read.iter().zip(&planes) {
        assert_eq!(bits(got), bits(want), "{name}");
    }
    // Undefined variance is stored as NaN, not as a number.
    let variance = &read.iter().find(|(n, _)| n == "variance.R").unwrap().1;
    assert!(variance.iter().all(|v| v.is_nan() || *v >= 0.0));
}

#[test]
fn openexrs_own_tools_read_the_layers() {
    // Debian's `openexr` package (installed by .ci/run where it can be); skipped, loudly,
    // without it.
    let probe = std::process::Command::new("exrheader")
        .arg("--help")
        .output();
    if probe.is_err() {
        println!(
            "SKIPPED: exrheader (Debian openexr) is not installed; the layers were not read by OpenEXR itself"
        );
        return;
    }
    let (w, h, planes) = rendered_planes();
    let dir = temp_dir::TempDir::new("extras-exr");
    let path = dir.join("layers.exr");
    std::fs::write(&path, exr_bytes(w, h, &planes)).unwrap();
    let out = std::process::Command::new("exrheader")
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    for (name, _) in &planes {
        let line = format!("{name}, 32-bit floating-point");
        assert!(
            text.contains(&line),
            "exrheader does not list {name}:\n{text}"
        );
    }
    assert!(
        text.contains(&format!("(0 0) - ({} {})", w - 1, h - 1)),
        "{text}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Tiles merged in any split give the variance the film itself gives from the same samples,
    /// to the rounding of Chan's merge.
    #[test]
    fn any_tiling_gives_the_variance_of_the_whole(seed in any::<u64>(), size in 1u32..6) {
        let config = FilmConfig { extras: ALL, ..FilmConfig::new(7, 6) };
        let t = Triangle::default();
        let mut whole = Film::new(config, &t).unwrap();
        let mut tiled = Film::new(config, &t).unwrap();
        let mut rng = Lcg(seed);
        let samples: Vec<([f32; 2], [f32; 3])> = (0..400)
            .map(|_| ([rng.next() * 7.0, rng.next() * 6.0], [rng.next() * 3.0, rng.next(), 1.0]))
            .collect();
        for (i, &(p, rgb)) in samples.iter().enumerate() {
            whole.add(&FilmSample { index: i as u64, channels: &[1.0, 2.0], ..FilmSample::new(p, rgb, 1.0) });
        }
        for spec in tiled.tiles(size).unwrap() {
            let mut tile = tiled.tile(spec);
            let b = spec.bounds;
            for (i, &(p, rgb)) in samples.iter().enumerate() {
                let inside = (b.x0 as f32..b.x1 as f32).contains(&p[0]) && (b.y0 as f32..b.y1 as f32).contains(&p[1]);
                if inside {
                    tile.add(&FilmSample { index: i as u64, channels: &[1.0, 2.0], ..FilmSample::new(p, rgb, 1.0) });
                }
            }
            tiled.merge(tile).unwrap();
        }
        for y in 0..6 {
            for x in 0..7 {
                let (a, b) = (whole.estimate(x, y).unwrap(), tiled.estimate(x, y).unwrap());
                match (a.variance, b.variance) {
                    (Some(va), Some(vb)) => for c in 0..3 {
                        prop_assert!((va[c] - vb[c]).abs() <= 1e-9 * va[c].max(1e-12), "({x}, {y}): {va:?} against {vb:?}");
                    },
                    (va, vb) => prop_assert_eq!(va.is_some(), vb.is_some()),
                }
                prop_assert_eq!(a.halves.is_some(), b.halves.is_some());
            }
        }
    }
}

#[test]
fn a_cropped_film_answers_for_its_own_pixels() {
    // Crop to pixels 2..6 × 1..4 of an 8 × 4 film: estimates and channels are looked up by
    // film coordinates, not from the crop's corner.
    let config = FilmConfig {
        crop_window: [0.25, 0.75, 0.25, 1.0],
        extras: PixelExtras {
            variance: true,
            halves: false,
            channels: 1,
        },
        ..FilmConfig::new(8, 4)
    };
    let mut film = Film::new(config, &Boxcar::default()).unwrap();
    for y in 1..4 {
        for x in 2..6 {
            let v = (10 * y + x) as f32;
            for (i, d) in [0.0, 2.0].into_iter().enumerate() {
                film.add(&FilmSample {
                    index: i as u64,
                    channels: &[v],
                    ..FilmSample::new([x as f32 + 0.5, y as f32 + 0.5], [v + d; 3], 1.0)
                });
            }
        }
    }
    for y in 1..4i64 {
        for x in 2..6i64 {
            let v = (10 * y + x) as f64;
            let e = film.estimate(x, y).unwrap();
            assert_eq!(e.value, [v + 1.0; 3], "({x}, {y})");
            assert_eq!(e.variance, Some([1.0; 3]));
            assert_eq!(film.channel_values(x, y).unwrap(), [v]);
        }
    }
    assert_eq!(film.estimate(1, 1), None);
    assert_eq!(film.channel_values(6, 1), None);
}

#[test]
fn a_pixel_without_samples_has_channel_values_of_zero() {
    let config = FilmConfig {
        extras: PixelExtras {
            channels: 2,
            ..PixelExtras::default()
        },
        ..FilmConfig::new(2, 1)
    };
    let mut film = Film::new(config, &Boxcar::default()).unwrap();
    film.add(&FilmSample {
        channels: &[1.0, 2.0],
        ..FilmSample::new([0.5, 0.5], [1.0; 3], 1.0)
    });
    assert_eq!(film.channel_values(1, 0).unwrap(), [0.0, 0.0]);
    let c = film.extra_images().unwrap().channels.unwrap();
    assert_eq!(c.pixel(1, 0), [0.0, 0.0]);
    assert_eq!(c.pixel(0, 0), [1.0, 2.0]);
}

/// A filter that is not separable: the cone 1 − r/1.5 over the disk of radius 1.5.
#[derive(Debug)]
struct Cone;

impl Filter for Cone {
    fn radius(&self) -> [f32; 2] {
        [1.5, 1.5]
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        (1.0 - (x * x + y * y).sqrt() / 1.5).max(0.0)
    }
}

#[test]
fn a_half_that_has_every_sample_is_the_whole_bit_for_bit() {
    // Every sample with radiance in half B: B's RGB sums must be the film's own, bit for bit,
    // in every pixel. So
    // the extras see every pixel a sample reaches, with the weights and the arithmetic the sums
    // use, for every kind of footprint: one pixel, rows of one, the phase tables' rows, the 2D
    // tables, wide and narrow, and the direct path.
    let mut all = filters();
    all.push(("wide box", Box::new(Boxcar::new([1.0, 0.5]).unwrap())));
    all.push(("tall box", Box::new(Boxcar::new([0.5, 1.5]).unwrap())));
    all.push((
        "wide gaussian",
        Box::new(Gaussian::new([6.0, 3.0], 0.5).unwrap()),
    ));
    // Wider than the phase tables reach (separable linear tables, up to 32 columns and more),
    // and a filter that is not separable (a 2D table of `eval`).
    all.push((
        "wide table",
        Box::new(Gaussian::new([10.0, 2.0], 0.05).unwrap()),
    ));
    all.push((
        "very wide table",
        Box::new(Gaussian::new([20.0, 0.6], 0.01).unwrap()),
    ));
    all.push(("radial cone", Box::new(Cone)));
    for (name, f) in all {
        for direct in [false, true] {
            let config = FilmConfig {
                extras: PixelExtras {
                    halves: true,
                    ..PixelExtras::default()
                },
                ..FilmConfig::new(48, 40)
            };
            let mut film = Film::new(config, f.as_ref()).unwrap();
            let mut tile = film.tile(film.tiles(64).unwrap()[0]);
            let mut rng = Lcg(11);
            for _ in 0..3000 {
                let p = [rng.next() * 48.0, rng.next() * 40.0];
                let rgb = [rng.next(), rng.next() * 3.0, rng.next() + 0.5];
                if direct {
                    tile.add_sample_direct(f.as_ref(), p, rgb, 1.0);
                } else {
                    // A sample weight with a full mantissa: weight·rgb then has 48 bits, so
                    // the two ways of forming f·l round differently.
                    let w = 0.5 + rng.next();
                    tile.add(&FilmSample {
                        index: 2,
                        ..FilmSample::new(p, rgb, w)
                    });
                    // A twin in A with sample weight 0: it adds its filter weight to the sums'
                    // weight and exactly +0 to their RGB, so A's RGB, the whole less B's, is
                    // exactly 0 when B's sums are formed as the whole's are, and A's mean (an
                    // f64) shows any difference in the last bit.
                    tile.add(&FilmSample {
                        index: 0,
                        ..FilmSample::new(p, rgb, 0.0)
                    });
                }
            }
            film.merge(tile).unwrap();
            let [a, _] = film.extra_images().unwrap().halves.unwrap();
            for y in 0..40 {
                for x in 0..48 {
                    let e = film.estimate(x, y).unwrap();
                    let value = e.value.map(|v| v as f32);
                    if direct {
                        // The direct path adds as index 0: everything in A.
                        assert_eq!(a.get(x as u32, y as u32), value, "{name} direct ({x}, {y})");
                    } else if film.pixel(x, y).unwrap().weight_sum > 0.0 {
                        // A's weight is its twins', B's the same: both halves are there.
                        let [a, _] = e.halves.unwrap_or_else(|| panic!("{name} ({x}, {y})"));
                        assert_eq!(a, [0.0; 3], "{name} ({x}, {y})");
                    }
                }
            }
        }
    }
}
