//! `nyquist-film`: films of any small resolution and crop window, any filter, tiles from
//! `Film::tiles` or arbitrary rectangles, samples and splats with any `f32` (NaN, ±∞, huge,
//! negative), merges in any order.

use nyquist::filter::{
    BlackmanHarris, Boxcar, Filter, FilterKind, FilterTable, Gaussian, Lanczos, Mitchell, Triangle,
};
use nyquist::filter::{Interpolation, MAX_RADIUS};
use nyquist_film::{Bounds, Film, FilmConfig, FilmStats, FilmTile, TileSpec};

use crate::Bytes;

/// Largest side of a fuzzed film, so memory and time per input stay small.
const MAX_SIDE: u32 = 64;
/// Most sample and splat operations per input.
const MAX_OPS: usize = 256;

/// Film: `Film::new` accepts exactly the documented configurations (and reports the crop
/// window's pixels `⌈x0·W⌉ … ⌈x1·W⌉ − 1`); `tiles` partitions the pixels in index order;
/// a sample is rejected exactly when a radiance component, the weight or the position is NaN or
/// infinite (a splat: a component or the position), accepted ones are counted, and clamped ones
/// counted exactly; merging the same tiles in any order gives bit-identical sums, counters and
/// image to merging them in index order; a tile index merged twice is refused and changes
/// nothing, and so is a tile of another film; pixel sums stay finite; the resolved image is finite and ≥ 0 with exact
/// `zero_weight_pixels` (and `negative_components` without splats); when every sample lies in
/// its tile's bounds, the tiled film equals one whole-film tile up to summation order; with a
/// box, table and direct evaluation sum the same bits.
pub fn film(data: &[u8]) {
    let mut b = Bytes::new(data);
    let config = FilmConfig {
        resolution: [b.below(MAX_SIDE), b.below(MAX_SIDE)],
        crop_window: if b.bool() {
            [0.0, 1.0, 0.0, 1.0]
        } else {
            [crop(&mut b), crop(&mut b), crop(&mut b), crop(&mut b)]
        },
        max_component: b.bool().then(|| b.f32_mixed()),
        extras: nyquist_film::PixelExtras::default(),
    };
    let (filter, is_box) = pick_filter(&mut b);
    let filter: &dyn Filter = filter.as_ref();
    let made = Film::new(config, filter);
    let Some(want_bounds) = expected_bounds(&config) else {
        assert!(made.is_err(), "{config:?} was accepted");
        return;
    };
    let table_ok = FilterTable::<64>::new(filter, Interpolation::Linear).is_ok();
    let mut film = match made {
        Ok(film) => {
            assert!(
                table_ok,
                "{config:?}: film built on a filter the table refuses"
            );
            film
        }
        Err(nyquist_film::Error::Core(_)) if !table_ok => return,
        Err(e) => panic!("{config:?} refused: {e}"),
    };
    assert_eq!(film.pixel_bounds(), want_bounds, "{config:?}");
    let [rx, ry] = film.filter_radius();
    assert!(rx.is_finite() && ry.is_finite() && rx > 0.0 && ry > 0.0);

    // Tiles: the film's own partition, plus sometimes arbitrary rectangles.
    let size = b.below(70);
    let Ok(mut specs) = film.tiles(size) else {
        assert_eq!(size, 0, "tiles({size}) refused");
        return;
    };
    assert!(size > 0, "tiles(0) accepted");
    check_partition(&specs, want_bounds);
    if b.bool() {
        let extra = b.below(3) as usize;
        for _ in 0..extra {
            let bounds = Bounds::new(coord(&mut b), coord(&mut b), coord(&mut b), coord(&mut b));
            specs.push(TileSpec {
                index: specs.len(),
                bounds,
            });
        }
    }
    let n = specs.len();

    // Operations, decoded once and replayed on every film below.
    let count = (b.u16() as usize % (MAX_OPS + 1)).min(MAX_OPS);
    let mut ops = Vec::with_capacity(count);
    for _ in 0..count {
        if b.rest_is_empty() {
            break;
        }
        let tile = b.below(n as u32 - 1) as usize;
        let kind = match b.u8() % 8 {
            0 => Kind::Splat,
            1 => Kind::Direct,
            _ => Kind::Sample,
        };
        let p = position(&mut b, specs[tile].bounds);
        let rgb = [b.f32_mixed(), b.f32_mixed(), b.f32_mixed()];
        let weight = if b.bool() { 1.0 } else { b.f32_mixed() };
        ops.push(Op {
            tile,
            kind,
            p,
            rgb,
            weight,
        });
    }

    // Expected counters, from the documented rules.
    let mut want = FilmStats::default();
    for op in &ops {
        let finite_pos = op.p[0].is_finite() && op.p[1].is_finite();
        let finite_rgb = op.rgb.iter().all(|c| c.is_finite());
        match op.kind {
            Kind::Splat if finite_pos && finite_rgb => want.splats += 1,
            Kind::Splat => want.rejected += 1,
            _ if finite_pos && finite_rgb && op.weight.is_finite() => want.samples += 1,
            _ => want.rejected += 1,
        }
        if let Some(m) = config.max_component
            && op.accepted()
            && op.rgb[0].max(op.rgb[1]).max(op.rgb[2]) > m
        {
            want.clamped += 1;
        }
    }

    let fill = |film: &Film| -> Vec<FilmTile> {
        let mut tiles: Vec<FilmTile> = specs.iter().map(|s| film.tile(*s)).collect();
        for (t, s) in tiles.iter().zip(&specs) {
            assert_eq!(t.index(), s.index);
            assert_eq!(t.bounds(), s.bounds);
            let pb = t.pixel_bounds();
            assert!(
                pb.is_empty() || pb.intersect(&want_bounds) == pb,
                "{pb:?} outside the film"
            );
        }
        for op in &ops {
            let t = &mut tiles[op.tile];
            match op.kind {
                Kind::Sample => t.add_sample(op.p, op.rgb, op.weight),
                Kind::Direct => t.add_sample_direct(filter, op.p, op.rgb, op.weight),
                Kind::Splat => t.add_splat(op.p, op.rgb),
            }
        }
        tiles
    };

    // Reference: every tile merged in index order.
    let mut reference = Film::new(config, filter).expect("same config");
    let tiles = fill(&reference);
    let per_tile: u64 = tiles.iter().map(|t| t.rejected()).sum();
    assert_eq!(per_tile, want.rejected);
    for t in tiles {
        reference.merge(t).expect("in-order merge");
    }
    assert_eq!(reference.stats(), want, "counters");
    assert_eq!(reference.rejected(), want.rejected);
    if is_box {
        check_box_table_is_exact(&reference, config, filter, &specs, &ops, want);
    }

    // The same tiles merged in an arbitrary order, some possibly left out (a gap that `image`
    // flushes over).
    let mut order: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        let j = b.below(i as u32) as usize;
        order.swap(i, j);
    }
    let skip = if b.bool() {
        Some(b.below(n as u32 - 1) as usize)
    } else {
        None
    };
    let mut tiles: Vec<Option<FilmTile>> = fill(&film).into_iter().map(Some).collect();
    for &i in &order {
        if Some(i) == skip {
            continue;
        }
        film.merge(tiles[i].take().unwrap())
            .expect("first merge of a tile");
    }
    // A tile index merged (or held) twice is refused and changes nothing.
    let dup = b.below(n as u32 - 1) as usize;
    if Some(dup) != skip {
        let before = film.stats();
        let mut again = film.tile(specs[dup]);
        again.add_sample([0.5, 0.5], [1.0; 3], 1.0);
        assert!(film.merge(again).is_err(), "tile {dup} merged twice");
        assert_eq!(film.stats(), before);
    }
    // A tile of another film (even one configured alike) is refused and changes nothing.
    if b.bool() {
        let other = Film::new(config, filter).expect("same config");
        let before = film.stats();
        let mut foreign = other.tile(specs[dup]);
        foreign.add_sample([0.5, 0.5], [1.0; 3], 1.0);
        assert!(
            film.merge(foreign).is_err(),
            "a tile of another film was merged"
        );
        assert_eq!(film.stats(), before);
    }
    if skip.is_none() {
        assert_eq!(film.stats(), want, "counters after merging in {order:?}");
        let (a, sa) = film.image();
        let (r, sr) = reference.image();
        assert_eq!(sa, sr, "resolve stats depend on the merge order {order:?}");
        let same = a
            .data()
            .iter()
            .zip(r.data())
            .all(|(x, y)| x.to_bits() == y.to_bits());
        assert!(same, "image depends on the merge order {order:?}");
        for y in want_bounds.y0..want_bounds.y1 {
            for x in want_bounds.x0..want_bounds.x1 {
                let (p, q) = (film.pixel(x, y).unwrap(), reference.pixel(x, y).unwrap());
                assert_eq!(p.weight_sum.to_bits(), q.weight_sum.to_bits());
                for c in 0..3 {
                    assert_eq!(p.rgb_sum[c].to_bits(), q.rgb_sum[c].to_bits());
                }
            }
        }
    }
    check_resolved(&mut film, want_bounds, want.splats > 0);
    check_resolved(&mut reference, want_bounds, want.splats > 0);

    // Tile independence: when every sample lies in its own tile's bounds and the extra
    // rectangles took none, one whole-film tile sums the same values (in another order).
    let own = ops
        .iter()
        .all(|op| !op.accepted() || inside(op.p, specs[op.tile].bounds));
    if own && want.splats == 0 {
        let mut whole = Film::new(config, filter).expect("same config");
        let mut t = whole.tile(TileSpec {
            index: 0,
            bounds: want_bounds,
        });
        let mut scale = 0.0f64;
        let fmax = max_weight(&whole);
        for op in &ops {
            match op.kind {
                Kind::Sample => t.add_sample(op.p, op.rgb, op.weight),
                Kind::Direct => t.add_sample_direct(filter, op.p, op.rgb, op.weight),
                Kind::Splat => t.add_splat(op.p, op.rgb), // all rejected here
            }
            if op.rgb.iter().all(|c| c.is_finite()) && op.weight.is_finite() {
                let l = op.rgb.iter().fold(0.0f64, |m, c| m.max(f64::from(c.abs())));
                scale += (l * f64::from(op.weight.abs())).max(1.0);
            }
        }
        whole.merge(t).unwrap();
        let tol = 1e-9 * scale * fmax.max(1.0);
        for y in want_bounds.y0..want_bounds.y1 {
            for x in want_bounds.x0..want_bounds.x1 {
                let (p, q) = (whole.pixel(x, y).unwrap(), reference.pixel(x, y).unwrap());
                assert!(
                    (p.weight_sum - q.weight_sum).abs()
                        <= 1e-9 * ops.len().max(1) as f64 * fmax.max(1.0),
                    "pixel ({x}, {y}): weight sum {} whole vs {} tiled",
                    p.weight_sum,
                    q.weight_sum
                );
                for c in 0..3 {
                    assert!(
                        (p.rgb_sum[c] - q.rgb_sum[c]).abs() <= tol,
                        "pixel ({x}, {y}) channel {c}: {} whole vs {} tiled",
                        p.rgb_sum[c],
                        q.rgb_sum[c]
                    );
                }
            }
        }
    }
}

/// A box's weights are all exactly 1, in its table as in its definition, so the table path of
/// `add_sample` (for radii ≤ ½ its one-pixel path) sums bit for bit what `add_sample_direct`
/// sums: the same ops replayed with direct evaluation give `reference`'s counters and pixels.
fn check_box_table_is_exact(
    reference: &Film,
    config: FilmConfig,
    filter: &dyn Filter,
    specs: &[TileSpec],
    ops: &[Op],
    want: FilmStats,
) {
    let mut direct = Film::new(config, filter).expect("same config");
    let mut tiles: Vec<FilmTile> = specs.iter().map(|s| direct.tile(*s)).collect();
    for op in ops {
        let t = &mut tiles[op.tile];
        match op.kind {
            Kind::Splat => t.add_splat(op.p, op.rgb),
            _ => t.add_sample_direct(filter, op.p, op.rgb, op.weight),
        }
    }
    for t in tiles {
        direct.merge(t).expect("in-order merge");
    }
    assert_eq!(direct.stats(), want, "counters, direct box");
    let b = reference.pixel_bounds();
    for y in b.y0..b.y1 {
        for x in b.x0..b.x1 {
            let (p, q) = (direct.pixel(x, y).unwrap(), reference.pixel(x, y).unwrap());
            assert_eq!(
                p.weight_sum.to_bits(),
                q.weight_sum.to_bits(),
                "box pixel ({x}, {y}): direct {} vs table {}",
                p.weight_sum,
                q.weight_sum
            );
            for c in 0..3 {
                assert_eq!(
                    p.rgb_sum[c].to_bits(),
                    q.rgb_sum[c].to_bits(),
                    "box pixel ({x}, {y})"
                );
            }
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Sample,
    Direct,
    Splat,
}

#[derive(Clone, Copy, Debug)]
struct Op {
    tile: usize,
    kind: Kind,
    p: [f32; 2],
    rgb: [f32; 3],
    weight: f32,
}

/// A crop coordinate: usually a multiple of 1/8 in `[0, 1]`, sometimes anything.
fn crop(b: &mut Bytes) -> f32 {
    if b.bool() {
        f32::from(b.u8() % 9) / 8.0
    } else {
        b.f32_mixed()
    }
}

/// A tile rectangle coordinate: usually near the film, sometimes extreme.
fn coord(b: &mut Bytes) -> i64 {
    match b.u8() % 8 {
        0 => i64::MIN,
        1 => i64::MAX,
        2 => b.u64() as i64,
        _ => i64::from(b.u8() as i8) + 32,
    }
}

/// A film position: usually inside the tile's rectangle, sometimes anything.
fn position(b: &mut Bytes, t: Bounds) -> [f32; 2] {
    if !b.u8().is_multiple_of(4) && !t.is_empty() && t.width() < 1 << 20 && t.height() < 1 << 20 {
        let u = f64::from(b.u16()) / 65536.0;
        let v = f64::from(b.u16()) / 65536.0;
        let x = (t.x0 as f64 + u * t.width() as f64) as f32;
        let y = (t.y0 as f64 + v * t.height() as f64) as f32;
        [x, y]
    } else {
        [b.f32_mixed(), b.f32_mixed()]
    }
}

impl Op {
    /// Whether the film must take this operation (finite values), per the docs.
    fn accepted(&self) -> bool {
        self.p.iter().all(|v| v.is_finite())
            && self.rgb.iter().all(|c| c.is_finite())
            && (self.kind == Kind::Splat || self.weight.is_finite())
    }
}

fn inside(p: [f32; 2], b: Bounds) -> bool {
    let (x, y) = (f64::from(p[0]), f64::from(p[1]));
    x >= b.x0 as f64 && x < b.x1 as f64 && y >= b.y0 as f64 && y < b.y1 as f64
}

/// The pixels `Film::new` must store for `c`, or `None` when it must refuse `c`.
fn expected_bounds(c: &FilmConfig) -> Option<Bounds> {
    let [w, h] = c.resolution;
    let k = c.crop_window;
    let crop_ok = k.iter().all(|v| (0.0..=1.0).contains(v)) && k[0] < k[1] && k[2] < k[3];
    let max_ok = c.max_component.is_none_or(|m| m.is_finite() && m > 0.0);
    if w == 0 || h == 0 || !crop_ok || !max_ok {
        return None;
    }
    let ceil = |v: f32, n: u32| (v * n as f32).ceil() as i64;
    let b = Bounds::new(ceil(k[0], w), ceil(k[2], h), ceil(k[1], w), ceil(k[3], h));
    (!b.is_empty()).then_some(b)
}

/// `specs` are indexed 0, 1, … and tile `film` exactly: disjoint, inside, covering every pixel.
fn check_partition(specs: &[TileSpec], film: Bounds) {
    let mut seen = vec![false; film.area() as usize];
    for (i, s) in specs.iter().enumerate() {
        assert_eq!(s.index, i);
        assert!(!s.bounds.is_empty() && s.bounds.intersect(&film) == s.bounds);
        for y in s.bounds.y0..s.bounds.y1 {
            for x in s.bounds.x0..s.bounds.x1 {
                let k = ((y - film.y0) * film.width() as i64 + (x - film.x0)) as usize;
                assert!(
                    !std::mem::replace(&mut seen[k], true),
                    "pixel ({x}, {y}) twice"
                );
            }
        }
    }
    assert!(seen.iter().all(|&s| s), "tiles leave a pixel out");
}

/// Pixel sums finite; image the crop's size, finite and ≥ 0; resolve counters exact.
fn check_resolved(film: &mut Film, fb: Bounds, splats: bool) {
    // First: resolving applies any held tiles.
    let (image, stats) = film.image();
    let mut zero = 0;
    let mut negative = 0;
    for y in fb.y0..fb.y1 {
        for x in fb.x0..fb.x1 {
            let p = film.pixel(x, y).expect("pixel inside the film");
            assert!(
                p.weight_sum.is_finite() && p.rgb_sum.iter().all(|c| c.is_finite()),
                "pixel ({x}, {y}) sums {p:?}"
            );
            let inv = if p.weight_sum > 0.0 {
                1.0 / p.weight_sum
            } else {
                zero += 1;
                0.0
            };
            negative += p.rgb_sum.iter().filter(|&&c| !(c * inv >= 0.0)).count() as u64;
        }
    }
    assert_eq!(
        (u64::from(image.width()), u64::from(image.height())),
        (fb.width(), fb.height())
    );
    assert!(
        image.data().iter().all(|v| v.is_finite() && *v >= 0.0),
        "resolved image has a negative or non-finite value"
    );
    assert_eq!(stats.zero_weight_pixels, zero);
    if !splats {
        assert_eq!(stats.negative_components, negative);
    }
    assert!(film.pixel(fb.x1, fb.y0).is_none() && film.pixel(fb.x0 - 1, fb.y0).is_none());
}

/// The largest |weight| the film's table gives on a grid over its support (a bound for the
/// summation-order tolerance).
fn max_weight(film: &Film) -> f64 {
    let [rx, ry] = film.filter_radius();
    let mut m = 0.0f64;
    for j in -16..=16 {
        for i in -16..=16 {
            let w = film.filter_weight(rx * i as f32 / 16.0, ry * j as f32 / 16.0);
            m = m.max(f64::from(w.abs()));
        }
    }
    2.0 * m
}

/// A built-in filter with arbitrary parameters (the default when they are refused), or a plugin
/// filter with negative lobes; `true` with a box.
fn pick_filter(b: &mut Bytes) -> (Box<dyn Filter>, bool) {
    let r = [radius(b), radius(b)];
    let (p, q) = (b.f32_mixed(), b.f32_mixed());
    let pick = b.u8() % 8;
    let filter: Box<dyn Filter> = match pick {
        0 => Box::new(Boxcar::new(r).unwrap_or_default()),
        1 => Box::new(Triangle::new(r).unwrap_or_default()),
        2 => Box::new(Gaussian::new(r, p).unwrap_or_default()),
        3 => Box::new(Mitchell::new(r, p, q).unwrap_or_default()),
        4 => Box::new(Lanczos::new(r, p).unwrap_or_default()),
        6 => Box::new(BlackmanHarris::new(r).unwrap_or_default()),
        5 => {
            let text = String::from_utf8_lossy(b.take(24)).into_owned();
            Box::new(FilterKind::parse(&text).unwrap_or(FilterKind::Mitchell(Mitchell::default())))
        }
        _ => Box::new(Lobed {
            radius: r.map(|v| {
                if v.is_finite() && v > 0.0 {
                    v.min(8.0)
                } else {
                    1.0
                }
            }),
            a: if p.is_finite() {
                p.clamp(-1e30, 1e30)
            } else {
                1.0
            },
            c: if q.is_finite() {
                q.clamp(-1e30, 1e30)
            } else {
                0.5
            },
        }),
    };
    (filter, pick == 0)
}

/// A filter radius: usually small, sometimes anything (refused values fall back to defaults).
fn radius(b: &mut Bytes) -> f32 {
    if b.bool() {
        f32::from(b.u8()) / 16.0
    } else {
        let v = b.f32_mixed();
        if v.is_finite() && v > MAX_RADIUS {
            MAX_RADIUS
        } else {
            v
        }
    }
}

/// A plugin filter that keeps the `Filter` contract (finite, 0 past the radius and for NaN)
/// with a negative region: `a·(1 − |x|/rx − |y|/ry) − c` inside the support.
#[derive(Debug)]
struct Lobed {
    radius: [f32; 2],
    a: f32,
    c: f32,
}

impl Filter for Lobed {
    fn radius(&self) -> [f32; 2] {
        self.radius
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        if !(x.abs() <= self.radius[0] && y.abs() <= self.radius[1]) {
            return 0.0;
        }
        let v = self.a * (1.0 - x.abs() / self.radius[0] - y.abs() / self.radius[1]) - self.c;
        if v.is_finite() { v } else { 0.0 }
    }
}
