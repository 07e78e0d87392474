//! Renders the zone plate (docs/cli.md: L = ½ + ½·cos(π r² / W), r the distance in pixels from the
//! image centre) through the film on N threads and prints the render time, the film's pixel
//! storage and the process's peak resident memory (VmHWM).
//!
//! ```text
//! cargo run --release -p nyquist-film --example zoneplate_scaling -- --threads 2 [--size 1024] [--spp 16] [--tile 32]
//! ```
//!
//! Samples: a 4 × 4 jittered stratified core sampler ([`StratifiedSampler`]) walked per tile by
//! a [`PixelRangeSampler`]; filter: Mitchell (r = 2, B = C = ⅓). Run it once per thread count
//! (peak memory is per process).

use nyquist::filter::Mitchell;
use nyquist::sampler::{Jitter, PixelRangeSampler, Sample, SampleLayout, StratifiedSampler};
use nyquist_film::{Film, FilmConfig, render_tiles};
use std::io::Write;
use std::time::Instant;

/// The zone plate at film position `(x, y)` on a `w × h` image (formula of docs/cli.md).
fn zoneplate(x: f32, y: f32, w: f32, h: f32) -> f32 {
    let (dx, dy) = (
        f64::from(x) - f64::from(w) / 2.0,
        f64::from(y) - f64::from(h) / 2.0,
    );
    (0.5 + 0.5 * (std::f64::consts::PI * (dx * dx + dy * dy) / f64::from(w)).cos()) as f32
}

/// Peak resident set size of this process in KiB, from `/proc/self/status`.
fn vm_hwm_kib() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

fn arg(args: &[String], name: &str, default: u32) -> u32 {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map_or(default, |v| v.parse().expect("a positive integer"))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let threads = arg(&args, "--threads", 1) as usize;
    let size = arg(&args, "--size", 1024);
    let spp = arg(&args, "--spp", 16);
    let tile = arg(&args, "--tile", 32);
    let strata = (spp as f64).sqrt().round() as u32;
    assert_eq!(strata * strata, spp, "--spp must be a square");
    let before = vm_hwm_kib().unwrap_or(0);

    let start = Instant::now();
    let sampler = StratifiedSampler::new(strata, strata, Jitter::Jittered, 1).unwrap();
    let layout = SampleLayout::<0>::new();
    let mut film = Film::new(FilmConfig::new(size, size), &Mitchell::default()).unwrap();
    let (w, h) = (size as f32, size as f32);
    render_tiles(
        &mut film,
        tile,
        threads,
        |tile, ctx| {
            let (lo, hi) = ctx.pixel_range().unwrap();
            let mut pixels = PixelRangeSampler::new(sampler.clone(), lo, hi).unwrap();
            let mut buf = vec![0.0f32; layout.len()];
            let mut sample = Sample::new(&layout, &mut buf).unwrap();
            while pixels.next_sample(&mut sample) {
                let [x, y] = sample.image();
                let l = zoneplate(x, y, w, h);
                tile.add_sample([x, y], [l, l, l], 1.0);
            }
        },
        |_, _| {},
    )
    .unwrap();
    let render = start.elapsed();
    let (image, _) = film.image();
    let total = start.elapsed();
    let checksum: f64 = image.data().iter().map(|&v| f64::from(v)).sum();

    let storage = film.storage_bytes() as u64;
    let peak = vm_hwm_kib().unwrap_or(0) * 1024;
    let mut out = std::io::stdout().lock();
    let written = writeln!(
        out,
        "threads {threads} size {size} spp {spp} tile {tile}: render {:.3} s, render+resolve {:.3} s, \
         {:.1} ns/sample",
        render.as_secs_f64(),
        total.as_secs_f64(),
        render.as_nanos() as f64 / (u64::from(size) * u64::from(size) * u64::from(spp)) as f64,
    )
    .and_then(|()| {
        writeln!(
            out,
        "pixel storage {storage} B ({:.1} MiB), image {} B, peak RSS {peak} B ({:.1} MiB, {:.3}x storage; \
         {:.1} MiB before the film), samples {}, checksum {checksum:.6}",
        storage as f64 / 1048576.0,
        image.data().len() * 4,
        peak as f64 / 1048576.0,
        peak as f64 / storage as f64,
        before as f64 / 1024.0,
        film.stats().samples,
        )
    })
    .and_then(|()| out.flush());
    match written {
        Ok(()) => {}
        // The reader of stdout went away (`| head -1`): stop quietly with 128 + SIGPIPE, as
        // Unix tools do, instead of println!'s panic.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(141),
        Err(e) => {
            eprintln!("zoneplate_scaling: stdout: {e}");
            std::process::exit(1);
        }
    }
}
