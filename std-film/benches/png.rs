//! PNG output of a render-like image at 1024² and 4096²: `write_png` (sRGB codes from its
//! table, deflate level 2 up to 4 MiB of pixel data and level 1 above) beside `powf_level6`, the
//! same file written the plain way (the sRGB formula with `powf` for every value, deflate level
//! 6, the `png` crate's default), in one process on the same image. The `png_stages_*` groups
//! time the two stages apart: the 8-bit sRGB conversion (formula against table) and the
//! encoding of the converted bytes at deflate levels 6, 2 and 1 and with the `png` crate's
//! `Compression::Fast` (fdeflate).
//!
//! The image is a 1-spp render of the zone plate L = ½ + ½·cos(π r²/W) (the CLI's default
//! scene): one jittered sample per pixel, so the pixels carry sampling noise as a real
//! `nyquist render --spp 1` does. Thread CPU time (the encoder is single-threaded); after the run
//! the bench prints the medians, the ratios and each setting's file size. Figures:
//! `docs/performance.md`, "PNG output".
//!
//! `cargo bench -p nyquist-film --bench png`

/// The core benches' clock (thread CPU time unless `NYQUIST_BENCH_CLOCK=wall`), shared.
#[path = "../../core/benches/cpu_time/mod.rs"]
mod cpu_time;
/// This run's medians, for the closing ratio report (shared with the core benches).
#[path = "../../core/benches/estimates/mod.rs"]
mod estimates;

use criterion::measurement::Measurement;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group};
use nyquist_film::Image;
use nyquist_film::output::png::{PngOptions, linear_to_srgb, srgb_byte, write_png};
use std::hint::black_box;

const SIDES: [u32; 2] = [1024, 4096];

/// A 1-spp zone plate on a `side × side` film: each pixel's value at one hashed position inside
/// it.
fn render(side: u32) -> Image {
    let w = side as f32;
    Image::from_fn(side, side, |x, y| {
        let h = nyquist::hash::hash2(1, u64::from(y) << 32 | u64::from(x));
        let (u, v) = (
            nyquist::hash::unit_f32(h as u32),
            nyquist::hash::unit_f32((h >> 32) as u32),
        );
        let (dx, dy) = (x as f32 + u - w / 2.0, y as f32 + v - w / 2.0);
        let l = 0.5 + 0.5 * (std::f32::consts::PI * (dx * dx + dy * dy) / w).cos();
        [l, l, l]
    })
}

/// The 8-bit code by the formula (`srgb_byte`'s definition), computed for every value.
fn srgb_formula(x: f32) -> u8 {
    (255.0 * linear_to_srgb(x)).round().clamp(0.0, 255.0) as u8
}

/// `rgb` (8-bit RGB, `side × side`) encoded with `compression` and the adaptive filter; `srgb`
/// adds the `sRGB` chunk as `write_png` does.
fn encode(rgb: &[u8], side: u32, compression: png::DeflateCompression, srgb: bool) -> Vec<u8> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, side, side);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    if srgb {
        enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    }
    enc.set_deflate_compression(compression);
    enc.set_filter(png::Filter::Adaptive);
    let mut writer = enc.write_header().unwrap();
    writer.write_image_data(rgb).unwrap();
    writer.finish().unwrap();
    out
}

/// The plain way: formula codes, deflate level 6.
fn powf_level6(image: &Image) -> Vec<u8> {
    let rgb: Vec<u8> = image.data().iter().map(|&v| srgb_formula(v)).collect();
    encode(&rgb, image.width(), png::DeflateCompression::Level(6), true)
}

fn after(image: &Image) -> Vec<u8> {
    let mut out = Vec::new();
    write_png(&mut out, image, &PngOptions::default()).unwrap();
    out
}

/// The encoder settings of the stage groups, by criterion function name.
const ENCODINGS: [(&str, png::DeflateCompression); 4] = [
    ("deflate_level6", png::DeflateCompression::Level(6)),
    ("deflate_level2", png::DeflateCompression::Level(2)),
    ("deflate_level1", png::DeflateCompression::Level(1)),
    ("fdeflate", png::DeflateCompression::FdeflateUltraFast),
];

fn small_samples<M: Measurement>(group: &mut BenchmarkGroup<'_, M>) {
    // Level 6 takes seconds on the 4096² image: ten samples of one iteration are enough.
    group.sample_size(10);
    group.warm_up_time(std::time::Duration::from_millis(500));
    group.measurement_time(std::time::Duration::from_secs(2));
}

fn png_output(c: &mut Criterion<cpu_time::BenchClock>) {
    for side in SIDES {
        let image = render(side);
        // The two writers give the same pixels: checked here, once, before any timing.
        assert_eq!(decode(&powf_level6(&image)), decode(&after(&image)));
        let mut group = c.benchmark_group(format!("png_{side}"));
        small_samples(&mut group);
        group.throughput(Throughput::Elements(u64::from(side) * u64::from(side)));
        group.bench_function("powf_level6", |b| b.iter(|| powf_level6(black_box(&image))));
        group.bench_function("write_png", |b| b.iter(|| after(black_box(&image))));
        group.finish();

        let rgb: Vec<u8> = image.data().iter().map(|&v| srgb_formula(v)).collect();
        let mut group = c.benchmark_group(format!("png_stages_{side}"));
        small_samples(&mut group);
        group.throughput(Throughput::Elements(u64::from(side) * u64::from(side)));
        group.bench_function("srgb_formula", |b| {
            b.iter(|| -> Vec<u8> {
                black_box(&image)
                    .data()
                    .iter()
                    .map(|&v| srgb_formula(v))
                    .collect()
            })
        });
        group.bench_function("srgb_table", |b| {
            b.iter(|| -> Vec<u8> {
                black_box(&image)
                    .data()
                    .iter()
                    .map(|&v| srgb_byte(v, None))
                    .collect()
            })
        });
        for (name, compression) in ENCODINGS {
            group.bench_function(name, |b| {
                b.iter(|| encode(black_box(&rgb), side, compression, true))
            });
        }
        group.finish();
    }
}

/// The decoded 8-bit RGB pixels of a PNG.
fn decode(png: &[u8]) -> Vec<u8> {
    let mut reader = png::Decoder::new(std::io::Cursor::new(png))
        .read_info()
        .unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    buf
}

criterion_group! {
    name = cpu;
    config = cpu_time::config();
    targets = png_output
}

/// Medians of this run (ms per image), the ratios, and each setting's file size.
fn report(since: std::time::SystemTime) {
    let mut lines = Vec::new();
    for side in SIDES {
        let image = render(side);
        let ms = |group: &str, id: &str| {
            estimates::median_ns(&format!("{group}_{side}"), id, since).map(|t| t / 1e6)
        };
        let rgb: Vec<u8> = image.data().iter().map(|&v| srgb_formula(v)).collect();
        let (old_len, new_len) = (powf_level6(&image).len(), after(&image).len());
        if let (Some(old), Some(new)) = (ms("png", "powf_level6"), ms("png", "write_png")) {
            lines.push(format!(
                "{side}²: powf_level6 {old:8.1} ms {old_len:>10} B | write_png {new:7.1} ms \
                 {new_len:>10} B | {:.2}× faster, {:+.1} % bytes",
                old / new,
                100.0 * (new_len as f64 / old_len as f64 - 1.0)
            ));
        }
        if let (Some(f), Some(t)) = (
            ms("png_stages", "srgb_formula"),
            ms("png_stages", "srgb_table"),
        ) {
            lines.push(format!(
                "{side}²: sRGB codes: formula {f:7.1} ms | table {t:6.1} ms | {:.1}× faster",
                f / t
            ));
        }
        for (name, compression) in ENCODINGS {
            if let Some(t) = ms("png_stages", name) {
                let len = encode(&rgb, side, compression, true).len();
                lines.push(format!("{side}²: {name:15} {t:8.1} ms {len:>10} B"));
            }
        }
    }
    estimates::print_report("PNG output (median per image), this run:", &lines);
}

fn main() {
    let since = std::time::SystemTime::now();
    cpu();
    Criterion::default().configure_from_args().final_summary();
    report(since);
}
