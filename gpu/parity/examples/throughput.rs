//! Throughput of every pixel sampler: camera samples per second (each with one `get_1d` and one
//! `get_2d` after it: 8 values) on the CPU, one thread and all threads, and on the GPU adapter
//! wgpu finds, as a Markdown table.
//!
//! ```sh
//! cargo run --release --manifest-path gpu/parity/Cargo.toml --example throughput
//! ```
//!
//! - CPU, one thread: the core's sampler over 2¹⁸ samples of a 1920 × 1080 image at 16 spp, in
//!   the order a renderer takes them (a pixel's samples in turn), one at a time.
//! - CPU, all threads: the same samples split across `available_parallelism` threads.
//! - GPU: `nyq_fill` over 2²⁰ samples per dispatch, timed from submission to completion, no
//!   read-back. On a software adapter (lavapipe) this is a CPU figure; the table says so.
//!
//! Each figure is the median of five runs.

use std::time::Instant;

use nyquist_gpu_parity::{Gpu, Job, SAMPLER_NAMES, Source};

const RESOLUTION: [u32; 2] = [1920, 1080];
const SPP: u32 = 16;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Requests per second of `job.cpu` over `requests` split across `threads`.
fn cpu_rate(job: &Job, requests: &[[u32; 4]], threads: usize) -> f64 {
    let runs = (0..5)
        .map(|_| {
            let t = Instant::now();
            std::thread::scope(|scope| {
                for chunk in requests.chunks(requests.len().div_ceil(threads)) {
                    scope.spawn(move || std::hint::black_box(job.cpu(chunk)));
                }
            });
            requests.len() as f64 / t.elapsed().as_secs_f64()
        })
        .collect();
    median(runs)
}

fn main() {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let requests: Vec<[u32; 4]> = (0..1u32 << 18)
        .map(|n| {
            let pixel = n / SPP;
            [pixel % RESOLUTION[0], pixel / RESOLUTION[0], n % SPP, 5]
        })
        .collect();
    let gpu = Gpu::new().and_then(|gpu| {
        let pipeline = gpu.pipeline(Source::Wgsl)?;
        Ok((gpu, pipeline))
    });
    match &gpu {
        Ok((gpu, _)) => println!(
            "GPU adapter: {}{}",
            gpu.adapter(),
            if gpu.is_cpu() {
                " — a software rasteriser: its column is a CPU figure"
            } else {
                ""
            }
        ),
        Err(why) => println!("GPU: none ({why})"),
    }
    println!(
        "\nM camera samples per second (× 8 for values), {}x{} at {SPP} spp:\n",
        RESOLUTION[0], RESOLUTION[1]
    );
    println!("| sampler | CPU, 1 thread | CPU, {threads} threads | GPU |");
    println!("|---|---:|---:|---:|");
    for name in SAMPLER_NAMES {
        let job = Job::by_name(name, RESOLUTION, SPP, 7).expect("a known sampler");
        let one = cpu_rate(&job, &requests, 1);
        let all = cpu_rate(&job, &requests, threads);
        let on_gpu = match &gpu {
            Ok((gpu, pipeline)) => {
                let count = 1u32 << 20;
                let seconds = gpu.time_image(pipeline, &job, RESOLUTION, SPP, count, 5);
                format!("{:.1}", f64::from(count) / seconds / 1e6)
            }
            Err(_) => "–".into(),
        };
        println!(
            "| {name} | {:.1} | {:.1} | {on_gpu} |",
            one / 1e6,
            all / 1e6
        );
    }
}
