//! A GPU client: the camera samples of a whole image filled by the `nyq_fill` kernel on
//! whatever adapter wgpu finds, checked against the CPU sampler bit for bit.
//!
//! ```sh
//! cargo run --release --manifest-path gpu/parity/Cargo.toml --example camera_image -- \
//!     [WIDTHxHEIGHT] [SPP] [SAMPLER]
//! ```
//!
//! Defaults: 1024x1024, 16 spp, owen-sobol (also zsobol, sobol, halton, pmj02, random,
//! stratified, fibonacci, korobov, r2; the ZSobol, Sobol and Halton samplers fast-Owen
//! scrambled). Each request is sample `i mod spp` of pixel `⌊i / spp⌋` in row-major
//! order; the kernel writes its camera sample and two more values (`get_1d`, `get_2d` from
//! dimension 5), 2²⁰ samples per dispatch.

use std::process::ExitCode;
use std::time::Instant;

use nyquist_gpu_parity::{Gpu, Job, Source};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let resolution = match args.first().map(|s| s.split_once('x')) {
        None => [1024, 1024],
        Some(Some((w, h))) => match (w.parse(), h.parse()) {
            (Ok(w), Ok(h)) if w > 0 && h > 0 => [w, h],
            _ => {
                eprintln!("camera_image: size {}: expected WIDTHxHEIGHT", args[0]);
                return ExitCode::from(2);
            }
        },
        Some(None) => {
            eprintln!("camera_image: size {}: expected WIDTHxHEIGHT", args[0]);
            return ExitCode::from(2);
        }
    };
    let spp: u32 = match args.get(1).map(|s| s.parse()) {
        None => 16,
        Some(Ok(n)) if n > 0 && n <= 65536 => n,
        _ => {
            eprintln!("camera_image: spp {}: expected 1 to 65536", args[1]);
            return ExitCode::from(2);
        }
    };
    let name = args.get(2).map_or("owen-sobol", String::as_str);
    let Some(job) = Job::by_name(name, resolution, spp, 7) else {
        eprintln!(
            "camera_image: sampler {name}: unknown, or stratified with a spp that is not a square"
        );
        return ExitCode::from(2);
    };
    let total = u64::from(resolution[0]) * u64::from(resolution[1]) * u64::from(spp);
    if total > u64::from(u32::MAX) {
        eprintln!("camera_image: {total} samples: at most 2^32 - 1 per image");
        return ExitCode::from(2);
    }
    let gpu = match Gpu::new() {
        Ok(gpu) => gpu,
        Err(why) => {
            eprintln!("camera_image: {why}");
            return ExitCode::from(2);
        }
    };
    let pipeline = match gpu.pipeline(Source::Wgsl) {
        Ok(p) => p,
        Err(why) => {
            eprintln!("camera_image: {why}");
            return ExitCode::from(2);
        }
    };
    println!("adapter: {}", gpu.adapter());
    let chunk = 1u32 << 20;
    let (mut gpu_seconds, mut cpu_seconds) = (0.0, 0.0);
    let mut first = 0u32;
    let total = total as u32;
    while first < total {
        let count = chunk.min(total - first);
        let t = Instant::now();
        let have = gpu.run_image(&pipeline, &job, resolution, spp, first, count);
        gpu_seconds += t.elapsed().as_secs_f64();
        let requests: Vec<[u32; 4]> = (first..first + count)
            .map(|n| {
                let pixel = n / spp;
                [pixel % resolution[0], pixel / resolution[0], n % spp, 5]
            })
            .collect();
        let t = Instant::now();
        let want = job.cpu(&requests);
        cpu_seconds += t.elapsed().as_secs_f64();
        if let Some(k) = (0..have.len()).find(|&k| have[k] != want[k]) {
            eprintln!(
                "camera_image: request {:?}: gpu {:08x?} cpu {:08x?}",
                requests[k], have[k], want[k]
            );
            return ExitCode::FAILURE;
        }
        first += count;
    }
    println!(
        "{name}: {}x{} at {spp} spp: {total} camera samples (+ get_1d, get_2d) equal to the CPU's; \
         GPU {gpu_seconds:.2} s with the copy back, CPU {cpu_seconds:.2} s (one thread)",
        resolution[0], resolution[1]
    );
    ExitCode::SUCCESS
}
