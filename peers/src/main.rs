//! nyquist beside pbrt-v3, pbrt-v4 and OpenQMC built from their own sources (see README.md):
//! for each workload, nyquist and every built peer do the same computation, timed in rotation
//! within each run by the thread's CPU time, after a check of each peer's output.
//!
//! `cargo run --release --manifest-path peers/Cargo.toml -- [--samples N] [--runs N]
//! [--sample-ms MS] [--only TEXT]`

mod blue_noise;
mod check;
mod harness;
#[cfg(peer_openqmc)]
mod openqmc;
#[cfg(peer_pbrt_v3)]
mod pbrt_v3;
#[cfg(peer_pbrt_v4)]
mod pbrt_v4;
mod workloads;

use harness::{Settings, print_table};

fn main() {
    let mut settings = Settings {
        samples: 61,
        runs: 3,
        sample_ns: 2_000_000,
    };
    let mut only: Vec<String> = Vec::new();
    let (mut blue, mut size, mut frame, mut images) = (false, 256u32, 0u32, None);
    let mut pmj_tables = nyquist_lab::pmj02_seed::SEEDS;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = || {
            args.next()
                .unwrap_or_else(|| usage(&format!("{a} needs a value")))
        };
        match a.as_str() {
            "--samples" => settings.samples = number(&value()).max(1),
            "--runs" => settings.runs = number(&value()).max(1),
            "--sample-ms" => {
                let ms: f64 = value().parse().unwrap_or_else(|_| usage("bad --sample-ms"));
                settings.sample_ns = (ms * 1e6).max(1e3) as u64;
            }
            "--only" => only.push(value()),
            "--blue-noise" => blue = true,
            "--size" => size = number(&value()) as u32,
            "--frame" => frame = number(&value()) as u32,
            "--images" => images = Some(std::path::PathBuf::from(value())),
            "--pmj-tables" => {
                pmj_tables = u32::try_from(number(&value()).max(1))
                    .unwrap_or_else(|_| usage("--pmj-tables: at most 4294967295"))
            }
            "-h" | "--help" => usage(""),
            _ => usage(&format!("unknown argument {a}")),
        }
    }
    if blue {
        blue_noise::run(size, frame, images.as_deref(), pmj_tables);
        return;
    }
    println!(
        "nyquist peer benchmark: {} runs × {} rotated samples of ≈ {:.1} ms CPU time per \
         contender; thread CPU time (CLOCK_THREAD_CPUTIME_ID).",
        settings.runs,
        settings.samples,
        settings.sample_ns as f64 / 1e6
    );
    println!(
        "Peers: {} {}. Ratio = peer time ÷ nyquist time per run (> 1: nyquist is faster); \
         median of the runs; nyquist and peer columns are medians over all samples.\n",
        env!("PEERS_CXX"),
        env!("PEERS_CXX_FLAGS"),
    );
    let mut rows = Vec::new();
    for (name, make) in workloads::ALL {
        if !only.is_empty() && !only.iter().any(|o| name.contains(o.as_str())) {
            continue;
        }
        eprintln!("measuring {name}");
        rows.extend(harness::measure(make(), settings));
    }
    print_table(&mut rows, settings);
}

fn number(s: &str) -> usize {
    s.parse()
        .unwrap_or_else(|_| usage(&format!("not a number: {s}")))
}

fn usage(err: &str) -> ! {
    if !err.is_empty() {
        eprintln!("error: {err}");
    }
    eprintln!(
        "usage: nyquist-peers [--samples N (61)] [--runs N (3)] [--sample-ms MS (2)] \
         [--only TEXT]…\n       nyquist-peers --blue-noise [--size N (256)] [--frame F (0)] \
         [--images DIR] [--pmj-tables N (1024)]"
    );
    std::process::exit(if err.is_empty() { 0 } else { 2 })
}
