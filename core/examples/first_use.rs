//! What the first use of each lazily built table costs (the `lazy-tables` feature): every
//! workload runs twice, and the first run's time minus the second's is the fill it paid for.
//!
//! ```sh
//! CARGO_PROFILE_RELEASE_OPT_LEVEL=z cargo run -p nyquist --release --features lazy-tables \
//!     --example first_use
//! ```
//!
//! Each run is one process, so every table starts unfilled; the workloads run in the order
//! printed, and a table two workloads share is paid for by the first (the Sobol matrices, by
//! Sobol's). Times are the thread's CPU time, as in the criterion benches, so other load on the
//! machine moves them less. Without the feature the tables are stored in the binary and both
//! runs cost the same.

use std::hint::black_box;
use std::time::Duration;

use rustix::time::{ClockId, clock_gettime};

use nyquist::sampler::MaskView;
use nyquist::sampler::best_candidate::table_row;
use nyquist::sequence::{Halton, OwenSobol, Pmj02, Sequence, Sobol};

/// One value in each of a set's dimensions, at an index with digits in every base's tables.
fn every_dim(set: &dyn Sequence) -> f32 {
    (0..set.dims())
        .map(|d| set.sample(black_box(123_456_789), d))
        .sum()
}

/// The thread's CPU time that `f` takes.
fn time(f: &mut dyn FnMut()) -> Duration {
    let now = || {
        let t = clock_gettime(ClockId::ThreadCPUTime);
        Duration::new(t.tv_sec as u64, t.tv_nsec as u32)
    };
    let start = now();
    f();
    now() - start
}

fn main() {
    if !cfg!(feature = "lazy-tables") {
        println!(
            "built without `lazy-tables`: the tables are stored, nothing is filled at first use"
        );
    }
    let halton = Halton::new(1024).unwrap();
    let sobol = Sobol::new(1024).unwrap();
    let owen = OwenSobol::new(1024, 7).unwrap();
    let pmj = Pmj02::scrambled(7);
    let workloads: [(&str, &mut dyn FnMut()); 5] = [
        ("radical inverse (Halton, 1024 dims)", &mut || {
            black_box(every_dim(&halton));
        }),
        ("Sobol (1024 dims)", &mut || {
            black_box(every_dim(&sobol));
        }),
        ("Owen-Sobol (1024 dims)", &mut || {
            black_box(every_dim(&owen));
        }),
        ("PMJ(0,2), Owen-scrambled", &mut || {
            black_box(pmj.sample_2d(black_box(40_000)));
        }),
        ("best-candidate table", &mut || {
            black_box(table_row(black_box(17)));
        }),
    ];
    println!("{:<40} {:>12} {:>12}", "workload", "first", "second");
    for (name, f) in workloads {
        let (first, second) = (time(f), time(f));
        println!("{name:<40} {first:>12.2?} {second:>12.2?}");
    }
    let mut mask = || {
        black_box(MaskView::builtin().value(black_box(5), 9, 1));
    };
    let (first, second) = (time(&mut mask), time(&mut mask));
    println!("{:<40} {first:>12.2?} {second:>12.2?}", "dither mask");
}
