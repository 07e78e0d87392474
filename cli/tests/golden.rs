//! Golden outputs: FNV-1a 64 hashes of fixed CLI runs, checked in as `tests/golden/hashes.txt`
//! (png's `results.txt` idea), so any change to generated values is a deliberate, reviewed
//! change. Covered: `nyquist points` for every point set and every pixel sampler, a small
//! zone-plate `nyquist render` (written as PFM, the file's bytes hashed) per filter and per
//! sampler, and the plots (`converge --plot`, `filter --plot`, `analyze --spectrum` as PNG and
//! SVG, a small `compare` sheet: the files' bytes, so the embedded font and the drawing are
//! pinned), `nyquist mask` as PNG and OpenEXR, all with fixed counts, dimensions, seeds and
//! thread counts.
//!
//! After an intended change, re-bless and review the diff of `hashes.txt`:
//! `NYQUIST_BLESS=1 cargo test -p nyquist-cli --test golden`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

const BLESS_HINT: &str = "if the change is intended, re-bless with \
    `NYQUIST_BLESS=1 cargo test -p nyquist-cli --test golden` and commit cli/tests/golden/hashes.txt";

/// FNV-1a, 64-bit (Fowler, Noll, Vo: offset basis 0xcbf29ce484222325, prime 0x100000001b3).
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

#[test]
fn fnv1a64_matches_the_published_test_vectors() {
    // From the FNV reference test suite (isthe.com/chongo/tech/comp/fnv).
    assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
    assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
    assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
}

/// One golden run: its name in `hashes.txt` and the `nyquist` arguments. Runs that write a file
/// name it `{out}` (a temporary `.pfm`), `{out.png}` or `{out.svg}`, and the file's bytes are
/// hashed; the others hash stdout.
struct Run {
    name: String,
    args: Vec<String>,
}

fn run(name: impl Into<String>, args: &[&str]) -> Run {
    Run {
        name: name.into(),
        args: args.iter().map(|s| s.to_string()).collect(),
    }
}

/// Every golden run. Small enough for a debug build to finish in well under a second each.
fn runs() -> Vec<Run> {
    let mut out = Vec::new();
    // Point sets: 64 points, fixed dims; seed 7 for the random sets and the randomized
    // lattices, none for the deterministic sets (halton and sobol unscrambled).
    for (sampler, dims, seeded) in [
        ("random", "3", true),
        ("uniform", "2", false),
        ("stratified", "2", true),
        ("lhs", "3", true),
        ("vdc", "1", false),
        ("halton", "3", false),
        ("hammersley", "3", false),
        ("halton-zaremba", "3", false),
        ("hammersley-zaremba", "3", false),
        ("zero-two", "2", true),
        ("sobol", "3", false),
        ("korobov", "3", true),
        ("rd", "3", true),
        ("poisson-disk", "2", true),
        ("bridson", "2", true),
    ] {
        let mut args = vec![
            "points",
            "--sampler",
            sampler,
            "--count",
            "64",
            "--dims",
            dims,
        ];
        if seeded {
            args.extend(["--seed", "7"]);
        }
        out.push(run(format!("points/{sampler}"), &args));
    }
    out.push(run(
        "points/sobol-skip-8d",
        &[
            "points",
            "--sampler",
            "sobol",
            "--count",
            "32",
            "--dims",
            "8",
            "--skip",
            "1000",
        ],
    ));
    out.push(run(
        "points/fibonacci",
        &[
            "points",
            "--sampler",
            "fibonacci",
            "--count",
            "55",
            "--seed",
            "7",
        ],
    ));
    // Masks: a 16 × 16 two-channel mask as 8- and 16-bit PNG and as OpenEXR.
    for (name, bits, file) in [
        ("mask/png8", "8", "{out.png}"),
        ("mask/png16", "16", "{out.png}"),
        ("mask/exr", "8", "{out.exr}"),
    ] {
        out.push(run(
            name,
            &[
                "mask",
                "--size",
                "16",
                "--channels",
                "2",
                "--seed",
                "7",
                "--bits",
                bits,
                "-o",
                file,
            ],
        ));
    }
    // Pixel samplers: the 16 samples of pixel (3, 5), 4 dimensions each.
    // Every sampler the CLI accepts by name.
    for sampler in nyquist::sampler::NAMES {
        let mut args = vec![
            "points",
            "--sampler",
            sampler,
            "--spp",
            "16",
            "--pixel",
            "3,5",
            "--dims",
            "4",
            "--seed",
            "7",
        ];
        if matches!(sampler, "halton" | "hammersley" | "sobol" | "zsobol") {
            args.extend(["--resolution", "8x8"]);
        }
        out.push(run(format!("pixel/{sampler}"), &args));
    }
    // Renders: a 32 × 32 zone plate per filter, and a 16 × 16 one per sampler.
    for filter in [
        "box",
        "triangle",
        "gaussian",
        "mitchell",
        "lanczos",
        "mitchell:b=0.5,c=0.25",
        "gaussian:radius=1.5,sigma=0.5",
    ] {
        out.push(run(
            format!("render/filter-{filter}"),
            &[
                "render",
                "--scene",
                "zoneplate",
                "--sampler",
                "stratified",
                "--spp",
                "4",
                "--filter",
                filter,
                "--size",
                "32x32",
                "--seed",
                "7",
                "--threads",
                "2",
                "-o",
                "{out}",
            ],
        ));
    }
    // Every sampler the CLI accepts by name.
    for sampler in nyquist::sampler::NAMES {
        out.push(run(
            format!("render/sampler-{sampler}"),
            &[
                "render",
                "--scene",
                "zoneplate",
                "--sampler",
                sampler,
                "--spp",
                "4",
                "--filter",
                "box",
                "--size",
                "16x16",
                "--seed",
                "7",
                "--threads",
                "2",
                "-o",
                "{out}",
            ],
        ));
    }
    // Plots, each as PNG and SVG (JSON on stdout, not hashed: it holds timings).
    for ext in ["png", "svg"] {
        let file = format!("{{out.{ext}}}");
        let plots: [(&str, Vec<&str>); 3] = [
            (
                "converge",
                vec![
                    "converge",
                    "--samplers",
                    "random,stratified,sobol",
                    "--integrands",
                    "disk,gaussian",
                    "--min-spp",
                    "4",
                    "--max-spp",
                    "64",
                    "--runs",
                    "8",
                    "--seed",
                    "7",
                    "--threads",
                    "2",
                    "--json",
                    "--plot",
                ],
            ),
            ("filter", vec!["filter", "--filter", "mitchell", "--plot"]),
            (
                "spectrum",
                vec![
                    "analyze",
                    "--sampler",
                    "stratified",
                    "--count",
                    "64",
                    "--freq",
                    "8",
                    "--json",
                    "--spectrum",
                ],
            ),
        ];
        for (name, mut args) in plots {
            args.push(&file);
            out.push(run(format!("plot/{name}-{ext}"), &args));
        }
    }
    // A small contact sheet: crops and labels in the embedded font.
    out.push(run(
        "plot/compare-png",
        &[
            "compare",
            "--size",
            "16x16",
            "--samplers",
            "random,sobol",
            "--filters",
            "box",
            "--spp",
            "1,4",
            "--threads",
            "2",
            "--json",
            "-o",
            "{out.png}",
        ],
    ));
    out
}

/// Runs `nyquist` with `args` (`{out}` replaced by a fresh temporary `.pfm`, `{out.png}` and
/// `{out.svg}` by one with that extension) and hashes the output file when there is one, else
/// stdout. Panics with the command on failure.
fn hash_of(name: &str, args: &[String]) -> u64 {
    let mut file = None;
    let args: Vec<String> = args
        .iter()
        .map(|a| {
            let ext = match a.as_str() {
                "{out}" => "pfm",
                "{out.png}" => "png",
                "{out.svg}" => "svg",
                "{out.exr}" => "exr",
                _ => return a.clone(),
            };
            let path = temp_path(name, ext);
            file = Some(path.clone());
            path.to_string_lossy().into_owned()
        })
        .collect();
    let o = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(&args)
        .output()
        .expect("run nyquist");
    assert!(
        o.status.success(),
        "{name}: `nyquist {}` failed: {}",
        args.join(" "),
        String::from_utf8_lossy(&o.stderr)
    );
    match file {
        Some(path) => {
            let bytes = std::fs::read(&path).expect("output file");
            let _ = std::fs::remove_file(&path);
            fnv1a64(&bytes)
        }
        None => fnv1a64(&o.stdout),
    }
}

fn temp_path(name: &str, ext: &str) -> PathBuf {
    let safe: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    std::env::temp_dir().join(format!(
        "nyquist-golden-{}-{safe}.{ext}",
        std::process::id()
    ))
}

fn hashes_file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden/hashes.txt")
}

/// `name hash` lines; `#` comments and blank lines skipped.
fn read_hashes(path: &Path) -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .map(|(n, h)| (n.to_owned(), h.trim().to_owned()))
        .collect()
}

#[test]
fn cli_outputs_match_the_golden_hashes() {
    let runs = runs();
    let got: Vec<(String, String, String)> = runs
        .iter()
        .map(|r| {
            let h = format!("{:016x}", hash_of(&r.name, &r.args));
            (r.name.clone(), h, r.args.join(" "))
        })
        .collect();
    let path = hashes_file();
    if std::env::var_os("NYQUIST_BLESS").is_some_and(|v| v == "1") {
        let mut text = String::from(
            "# FNV-1a 64 of fixed `nyquist` runs (cli/tests/golden.rs): stdout of `points`, the PFM\n\
             # file of `render`, the PNG and SVG files of the plots. Re-bless:\n\
             # NYQUIST_BLESS=1 cargo test -p nyquist-cli --test golden\n",
        );
        for (name, h, _) in &got {
            text.push_str(&format!("{name} {h}\n"));
        }
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, text).unwrap();
        eprintln!("blessed {} hashes into {}", got.len(), path.display());
        return;
    }
    let want = read_hashes(&path);
    let mut problems = Vec::new();
    for (name, h, args) in &got {
        match want.get(name) {
            Some(w) if w == h => {}
            Some(w) => problems.push(format!(
                "{name}: `nyquist {args}` now hashes to {h}, golden {w}"
            )),
            None => problems.push(format!("{name}: `nyquist {args}` has no golden hash")),
        }
    }
    for name in want.keys() {
        if !got.iter().any(|(n, _, _)| n == name) {
            problems.push(format!("{name}: in hashes.txt but no longer run"));
        }
    }
    assert!(
        problems.is_empty(),
        "golden outputs changed ({} of {}):\n  {}\n{BLESS_HINT}",
        problems.len(),
        got.len(),
        problems.join("\n  ")
    );
}

#[test]
fn renders_hash_the_same_for_1_2_and_3_threads() {
    let args = |threads: &str| -> Vec<String> {
        [
            "render",
            "--scene",
            "zoneplate",
            "--sampler",
            "sobol",
            "--spp",
            "4",
            "--filter",
            "mitchell",
            "--size",
            "40x24",
            "--seed",
            "3",
            "--threads",
            threads,
            "-o",
            "{out}",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect()
    };
    let one = hash_of("threads-1", &args("1"));
    assert_eq!(one, hash_of("threads-2", &args("2")), "1 vs 2 threads");
    assert_eq!(one, hash_of("threads-3", &args("3")), "1 vs 3 threads");
}

#[test]
fn every_golden_run_has_a_distinct_name_and_output() {
    let runs = runs();
    let mut names: Vec<&str> = runs.iter().map(|r| r.name.as_str()).collect();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), runs.len(), "duplicate golden run names");
    // Distinct hashes in the file: two runs hashing alike would mean one of them ignores its
    // arguments (e.g. a filter spec that did not reach the film). The one exception: the
    // adaptive sampler's samples are those of the (0,2) sampler it wraps.
    let mut want = read_hashes(&hashes_file());
    assert_eq!(want.get("pixel/adaptive"), want.get("pixel/zero-two"));
    want.remove("pixel/adaptive");
    let mut hashes: Vec<&String> = want.values().collect();
    hashes.sort_unstable();
    hashes.dedup();
    assert_eq!(hashes.len(), want.len(), "two golden runs share a hash");
}
