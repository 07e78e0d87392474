//! Generates the screen-space blue-noise tiles (`core/src/sampler/screen_blue/*_tile.in`) from
//! [`nyquist_lab::blue_tile::TileSpec::shipped`], or with `--check` verifies that the shipped
//! files are what the optimiser makes (exit status 1 if not).
//!
//! `--family NAME` (`owen-sobol-bn`, `pmj02-bn`, `lattice-bn`) does one family; the default is
//! all three. `--out FILE` writes one family's tile elsewhere; `--sweeps N` and `--seed N`
//! change the spec, and need `--out` (another seed gives another tile of the same quality: the
//! spread of its figures over seeds is how much of a difference between two tiles is the
//! draw).

use nyquist_lab::blue_tile::{
    Family, HELD_OUT, TileSpec, held_out_ratios, level_ratios, optimise, source,
};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .map(|i| args.get(i + 1).cloned().unwrap_or_default())
    };
    let check = args.iter().any(|a| a == "--check");
    let families = match value("--family") {
        None => Family::ALL.to_vec(),
        Some(name) => match Family::from_name(&name) {
            Some(f) => vec![f],
            None => {
                let names: Vec<&str> = Family::ALL.iter().map(|f| f.name()).collect();
                eprintln!(
                    "blue-tile: --family {name:?}: not a family (one of {})",
                    names.join(", ")
                );
                return ExitCode::from(2);
            }
        },
    };
    let out = value("--out");
    if out.is_some() && families.len() != 1 {
        eprintln!("blue-tile: --out writes one tile: give --family too");
        return ExitCode::from(2);
    }
    let sweeps = match value("--sweeps").map(|v| v.parse::<u32>()) {
        None => None,
        Some(Ok(n)) if n > 0 => Some(n),
        Some(_) => {
            eprintln!("blue-tile: --sweeps: a whole number from 1 is needed");
            return ExitCode::from(2);
        }
    };
    let seed = match value("--seed").map(|v| v.parse::<u64>()) {
        None => None,
        Some(Ok(n)) => Some(n),
        Some(_) => {
            eprintln!(
                "blue-tile: --seed: a whole number from 0 to {} is needed",
                u64::MAX
            );
            return ExitCode::from(2);
        }
    };
    // Another spec makes another tile: it goes to --out, never over the shipped one.
    if (sweeps.is_some() || seed.is_some()) && (out.is_none() || check) {
        eprintln!(
            "blue-tile: --sweeps and --seed make a tile other than the shipped one: give --out FILE, without --check"
        );
        return ExitCode::from(2);
    }
    for family in families {
        let shipped = format!(
            "{}/../core/src/sampler/screen_blue/{}",
            env!("CARGO_MANIFEST_DIR"),
            family.tile_file()
        );
        let mut spec = TileSpec::shipped(family);
        if let Some(n) = sweeps {
            spec.sweeps = n;
        }
        if let Some(n) = seed {
            spec.seed = n;
        }
        let name = family.name();
        let start = std::time::Instant::now();
        let tile = optimise(&spec, &|done, total| {
            eprint!("\rblue-tile: {name}: sweep {done} of {total}");
        });
        eprintln!(
            "\rblue-tile: {name}: {}² in {:.1} s, {} swaps, energy {:.0} → {:.0}",
            spec.size,
            start.elapsed().as_secs_f64(),
            tile.swaps,
            tile.energy[0],
            tile.energy[1]
        );
        let text = source(&tile, &spec);
        if check {
            let on_disk = std::fs::read_to_string(&shipped).unwrap_or_default();
            if on_disk != text {
                eprintln!(
                    "blue-tile: {shipped} is not the optimiser's output; run without --check"
                );
                return ExitCode::FAILURE;
            }
            eprintln!("blue-tile: {shipped} is the optimiser's output");
            continue;
        }
        report(&spec, &tile.keys);
        let path = out.clone().unwrap_or(shipped);
        if let Err(e) = std::fs::write(&path, text) {
            eprintln!("blue-tile: {path}: {e}");
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}

/// The low-frequency ratios of the training integrands, of other integrands of the same
/// families, and of the held-out ones.
fn report(spec: &TileSpec, keys: &[u32]) {
    let name = spec.family.name();
    let trained = level_ratios(spec, keys);
    let held_out = level_ratios(
        &TileSpec {
            seed: spec.seed.wrapping_add(1000),
            ..*spec
        },
        keys,
    );
    for (level, (a, b)) in trained.iter().zip(&held_out).enumerate() {
        eprintln!(
            "blue-tile: {name}: {:>3} spp: low-frequency ratio {a:.3} (other integrands of the same families: {b:.3})",
            1u32 << level,
        );
    }
    for ((integrand, _), r) in HELD_OUT.iter().zip(held_out_ratios(spec, keys, 5)) {
        let cells: Vec<String> = r.iter().map(|v| format!("{v:.3}")).collect();
        eprintln!(
            "blue-tile: {name}: {integrand:>14}, 1 … 32 spp: {}",
            cells.join(" ")
        );
    }
}
