//! Chooses the pmj02 table's seed ([`nyquist_lab::pmj02_seed`]): scores the tables of seeds
//! `0 … 1023` and prints the best, with its RMSE beside the average table's. `--check` exits
//! with status 1 unless the best is the shipped [`nyquist::sequence::PMJ02_TABLE_SEED`].

use nyquist::sequence::PMJ02_TABLE_SEED;
use nyquist_lab::pmj02_seed::{
    COUNTS, SEEDS, TRAINING, TRIALS, held_out, rmse, root_mean_square, search, table,
};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = match args.as_slice() {
        [] => false,
        [flag] if flag == "--check" => true,
        _ => {
            let (other, what) = match args.iter().find(|a| *a != "--check") {
                Some(a) => (a.as_str(), "not a flag"),
                None => ("--check", "given twice"),
            };
            eprintln!("pmj02-seed: {other:?}: {what} (the only flag is --check)");
            return ExitCode::from(2);
        }
    };
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
    let counts: Vec<String> = COUNTS.iter().map(u32::to_string).collect();
    eprintln!(
        "pmj02-seed: RMSE of seed {} / of the average table, at {} spp:",
        found.best,
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
    for ((t, best), reference) in TRAINING.iter().zip(&found.best_rmse).zip(&found.reference) {
        print(t.name, best, reference);
    }
    // The held-out integrands, which the search did not see, against the average table of the
    // first 64 seeds.
    let held = held_out();
    let integrands: Vec<_> = held.iter().map(|&(_, f, i)| (f, i)).collect();
    let chosen = rmse(&table(found.best), &integrands, TRIALS);
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
    if check && found.best != PMJ02_TABLE_SEED {
        eprintln!(
            "pmj02-seed: the shipped PMJ02_TABLE_SEED is {PMJ02_TABLE_SEED}, the search's best {}",
            found.best
        );
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}
