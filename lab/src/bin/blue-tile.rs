//! Generates the screen-space blue-noise tile (`core/src/sampler/screen_blue_tile.in`) from
//! [`nyquist_lab::blue_tile::TileSpec::SHIPPED`], or with `--check` verifies that the shipped
//! file is what the optimiser makes (exit status 1 if not). `--out FILE` writes elsewhere.

use nyquist_lab::blue_tile::{HELD_OUT, TileSpec, held_out_ratios, level_ratios, optimise, source};
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = args.iter().any(|a| a == "--check");
    let shipped = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../core/src/sampler/screen_blue_tile.in"
    );
    let out = args
        .iter()
        .position(|a| a == "--out")
        .and_then(|i| args.get(i + 1))
        .map_or(shipped.to_owned(), Clone::clone);
    let mut spec = TileSpec::SHIPPED;
    if let Some(n) = args
        .iter()
        .position(|a| a == "--sweeps")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
    {
        spec.sweeps = n;
    }
    let start = std::time::Instant::now();
    let tile = optimise(&spec, &|done, total| {
        eprint!("\rblue-tile: sweep {done} of {total}");
    });
    eprintln!(
        "\rblue-tile: {}² in {:.1} s, {} swaps, energy {:.0} → {:.0}",
        spec.size,
        start.elapsed().as_secs_f64(),
        tile.swaps,
        tile.energy[0],
        tile.energy[1]
    );
    if !check {
        report(&spec, &tile.keys);
    }
    let text = source(&tile, &spec);
    if check {
        let on_disk = std::fs::read_to_string(shipped).unwrap_or_default();
        if on_disk != text {
            eprintln!("blue-tile: {shipped} is not the optimiser's output; run without --check");
            return ExitCode::FAILURE;
        }
        eprintln!("blue-tile: {shipped} is the optimiser's output");
        return ExitCode::SUCCESS;
    }
    if let Err(e) = std::fs::write(&out, text) {
        eprintln!("blue-tile: {out}: {e}");
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}

/// The low-frequency ratios of the training integrands, of other integrands of the same
/// families, and of the held-out ones, to standard error.
fn report(spec: &TileSpec, keys: &[u32]) {
    let trained = level_ratios(spec, keys);
    let held_out = level_ratios(
        &TileSpec {
            seed: spec.seed + 1000,
            ..*spec
        },
        keys,
    );
    for (level, (a, b)) in trained.iter().zip(&held_out).enumerate() {
        eprintln!(
            "blue-tile: {:>3} spp: low-frequency ratio {a:.3} (other integrands of the same families: {b:.3})",
            1u32 << level,
        );
    }
    for ((name, _), r) in HELD_OUT.iter().zip(held_out_ratios(spec, keys, 5)) {
        let cells: Vec<String> = r.iter().map(|v| format!("{v:.2}")).collect();
        eprintln!("blue-tile: {name:>14}, 1 … 32 spp: {}", cells.join(" "));
    }
}
