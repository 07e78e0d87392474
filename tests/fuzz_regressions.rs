//! Replays fuzz inputs on stable through the same contract checks the cargo-fuzz targets run
//! (`nyquist_fuzz_checks`, in `fuzz/checks`): every minimised crash kept in
//! `fuzz/regressions/<target>/` and every seed in `fuzz/corpus/<target>/`. Fails when either
//! folder is missing or holds no input (a wrong path would otherwise replay nothing and pass), on
//! a target folder with no input, and on a folder that names no target. The folders are found
//! from this package's manifest directory, so the working directory and `CARGO_TARGET_DIR` do
//! not matter.

use std::fs;
use std::panic;
use std::path::{Path, PathBuf};

/// The fuzz crate's folder: `fuzz/` beside this package's folder `tests/`.
fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests package sits in the workspace root")
        .join("fuzz")
}

/// Every `(target, file)` under `root/<target>/`, sorted; `README*` and dot files are skipped.
/// Panics if `root` cannot be read, if a target folder holds no input, or if the whole tree
/// holds none.
fn inputs(root: &Path) -> Vec<(String, PathBuf)> {
    let mut out = Vec::new();
    let dirs = fs::read_dir(root).unwrap_or_else(|e| panic!("{}: {e}", root.display()));
    for dir in dirs {
        let dir = dir.unwrap().path();
        if !dir.is_dir() {
            continue;
        }
        let target = dir.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            nyquist_fuzz_checks::target(&target).is_some(),
            "{}: no fuzz target is called {target:?}",
            dir.display()
        );
        let before = out.len();
        for file in fs::read_dir(&dir).unwrap() {
            let file = file.unwrap().path();
            let name = file.file_name().unwrap().to_string_lossy();
            if file.is_file() && !name.starts_with("README") && !name.starts_with('.') {
                out.push((target.clone(), file));
            }
        }
        assert!(out.len() > before, "{}: no input in it", dir.display());
    }
    assert!(!out.is_empty(), "{}: no input under it", root.display());
    out.sort();
    out
}

/// Runs every input, collecting failures so one report lists them all.
fn replay(root: &Path) -> usize {
    let all = inputs(root);
    let mut failed = Vec::new();
    for (target, file) in &all {
        let check = nyquist_fuzz_checks::target(target).unwrap();
        let data = fs::read(file).unwrap();
        if panic::catch_unwind(|| check(&data)).is_err() {
            failed.push(file.display().to_string());
        }
    }
    assert!(
        failed.is_empty(),
        "fuzz inputs that fail their contract checks: {failed:#?}"
    );
    all.len()
}

#[test]
fn regressions_replay() {
    let n = replay(&fuzz_dir().join("regressions"));
    println!("replayed {n} regression inputs");
}

#[test]
fn seed_corpora_replay() {
    let n = replay(&fuzz_dir().join("corpus"));
    println!("replayed {n} corpus inputs");
    // Every target has a committed seed corpus.
    for (target, _) in nyquist_fuzz_checks::TARGETS {
        let dir = fuzz_dir().join("corpus").join(target);
        let seeds = fs::read_dir(&dir).map(|d| d.count()).unwrap_or(0);
        assert!(seeds > 0, "{}: no seed corpus", dir.display());
    }
}

#[test]
fn every_target_has_a_fuzz_binary() {
    let manifest = fs::read_to_string(fuzz_dir().join("Cargo.toml")).unwrap();
    for (target, _) in nyquist_fuzz_checks::TARGETS {
        assert!(
            manifest.contains(&format!("name = \"{target}\"")),
            "fuzz/Cargo.toml has no [[bin]] for {target}"
        );
        assert!(
            fuzz_dir()
                .join(format!("fuzz_targets/{target}.rs"))
                .is_file()
        );
    }
}

#[test]
fn empty_input_is_valid_for_every_target() {
    for (_, check) in nyquist_fuzz_checks::TARGETS {
        check(&[]);
    }
}
