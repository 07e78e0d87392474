//! Ranks the pmj02 tables of seeds `0 … 1023` ([`nyquist_lab::pmj02_seed`]) and prints where
//! the shipped table ([`nyquist::sequence::PMJ02_TABLE_SEED`]) stands, with its RMSE beside the
//! average table's on the training and the held-out integrands.

use nyquist::sequence::PMJ02_TABLE_SEED;
use nyquist_lab::pmj02_seed::{
    COUNTS, SEEDS, TRAINING, TRIALS, held_out, rmse, root_mean_square, search, table, training,
};
use std::process::ExitCode;

fn main() -> ExitCode {
    if let Some(flag) = std::env::args().nth(1) {
        eprintln!("pmj02-seed: {flag:?}: not a flag (the command takes none)");
        return ExitCode::from(2);
    }
    let start = std::time::Instant::now();
    let found = search(0..SEEDS, TRIALS).expect("SEEDS is not 0");
    eprintln!(
        "pmj02-seed: {SEEDS} tables scored in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    let mut ranked = found.scores.clone();
    ranked.sort_by(|a, b| a.1.total_cmp(&b.1));
    for (seed, s) in ranked.iter().take(5) {
        eprintln!("pmj02-seed: seed {seed:>4}: score {s:.2}");
    }
    let shipped = rmse(&table(PMJ02_TABLE_SEED), &training(), TRIALS);
    let (s, lower) = found.standing(&shipped);
    eprintln!(
        "pmj02-seed: the shipped table (seed {PMJ02_TABLE_SEED}): score {s:.2}, {lower} seeds lower"
    );
    let counts: Vec<String> = COUNTS.iter().map(u32::to_string).collect();
    eprintln!(
        "pmj02-seed: RMSE of the shipped table / of the average table, at {} spp:",
        counts.join(", ")
    );
    // One line per integrand: the chosen table's RMSE / the average table's, per count.
    let print = |name: &str, best: &[f64; 5], reference: &[f64; 5]| {
        let cells: Vec<String> = best
            .iter()
            .zip(reference)
            .map(|(b, r)| format!("{b:.4}/{r:.4}"))
            .collect();
        eprintln!("pmj02-seed: {name:>20}: {}", cells.join(" "));
    };
    for ((t, best), reference) in TRAINING.iter().zip(&shipped).zip(&found.reference) {
        print(t.name, best, reference);
    }
    // The held-out integrands, which the search did not see, against the average table of the
    // first 64 seeds.
    let held = held_out();
    let integrands: Vec<_> = held.iter().map(|&(_, f, i)| (f, i)).collect();
    let chosen = rmse(&table(PMJ02_TABLE_SEED), &integrands, TRIALS);
    let tables: Vec<_> = (0..64)
        .map(|s| rmse(&table(s), &integrands, TRIALS))
        .collect();
    eprintln!("pmj02-seed: held-out integrands, the same columns (the average of seeds 0 … 63):");
    for ((name, _, _), (best, reference)) in held
        .iter()
        .zip(chosen.iter().zip(&root_mean_square(&tables)))
    {
        print(name, best, reference);
    }
    println!("{}", found.best);
    ExitCode::SUCCESS
}
