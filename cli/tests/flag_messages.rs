//! What the CLI says about its flags: a bad value is one line naming the flag, the value and
//! the limit (exit status 2, no output); a contradiction is refused; a flag that changes nothing
//! gets a one-line note; long work gets a warning with its estimated size first.

mod common;

use common::{nyquist, stdout, temp_dir};
use std::io::{BufRead, BufReader};
use std::process::{Command, Output, Stdio};

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// Exactly `line` (plus its newline) on stderr, exit status 2, nothing on stdout.
fn assert_error(args: &[&str], line: &str) {
    let o = nyquist(args);
    assert_eq!(stderr(&o), format!("nyquist: {line}\n"), "{args:?}");
    assert_eq!(o.status.code(), Some(2), "{args:?}");
    assert!(o.stdout.is_empty(), "{args:?}");
}

/// Exit status 0 and exactly `note` as a note line on stderr.
fn assert_note(args: &[&str], note: &str) -> Output {
    let o = nyquist(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    assert_eq!(stderr(&o), format!("nyquist: note: {note}\n"), "{args:?}");
    o
}

#[test]
fn vdc_points_default_to_its_one_dimension() {
    let o = nyquist(&["points", "--sampler", "vdc", "--count", "4"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o), "0\n0.5\n0.25\n0.75\n");
    assert_error(
        &["points", "--sampler", "vdc", "--dims", "2"],
        "--dims 2: vdc has at most 1 dimension",
    );
}

#[test]
fn a_pixel_sampler_given_count_asks_for_spp() {
    assert_error(
        &["points", "--sampler", "best-candidate", "--count", "256"],
        "--count 256: best-candidate is a pixel sampler: give --spp N (samples per pixel) \
         instead of --count",
    );
}

#[test]
fn dims_above_a_sets_limit_name_the_limit() {
    assert_error(
        &["points", "--dims", "1025"],
        "--dims 1025: halton has at most 1024 dimensions",
    );
    assert_error(
        &["points", "--sampler", "sobol", "--dims", "1025"],
        "--dims 1025: sobol has at most 1024 dimensions",
    );
    assert_error(
        &[
            "points",
            "--sampler",
            "hammersley",
            "--count",
            "4",
            "--dims",
            "2000",
        ],
        "--dims 2000: hammersley has at most 1025 dimensions",
    );
}

#[test]
fn filter_values_out_of_range_give_the_range() {
    assert_error(
        &["filter", "--filter", "box:radius=0"],
        "invalid value 'box:radius=0' for '--filter <SPEC>': filter spec: invalid value `0` for \
         key `radius`: rx must be in [0.000015258789, 1024] (2^-16 to 1024 pixels)",
    );
    assert_error(
        &["filter", "--filter", "mitchell:b=1e308"],
        "invalid value 'mitchell:b=1e308' for '--filter <SPEC>': filter spec: invalid value \
         `1e308` for key `b`: b must be in [-1000, 1000]",
    );
}

#[test]
fn a_filter_key_given_twice_is_refused() {
    assert_error(
        &["filter", "--filter", "mitchell:b=0.5,c=0.25,b=1"],
        "invalid value 'mitchell:b=0.5,c=0.25,b=1' for '--filter <SPEC>': filter spec: key `b` \
         is given twice",
    );
}

#[test]
fn an_empty_list_item_names_the_flag_and_the_list() {
    let o = nyquist(&["compare", "--samplers", "halton,,sobol"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.starts_with(
            "nyquist: --samplers 'halton,,sobol': an empty item in the comma-separated list \
             (possible values: uniform, random,"
        ),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1);
    assert_error(
        &["compare", "--spp", "1,,4"],
        "--spp '1,,4': an empty item in the comma-separated list",
    );
}

#[test]
fn a_missing_required_flag_reads_as_one_sentence() {
    assert_error(
        &["filter"],
        "the following required arguments were not provided: --filter <SPEC>",
    );
}

/// A seed asks for a set's randomization: refused by the sets without one, and it changes the
/// points of those that have one (seed 0 included: there is no seed that means "none").
#[test]
fn a_seed_randomizes_or_is_refused() {
    for s in ["hammersley", "vdc", "uniform", "halton-zaremba"] {
        assert_error(
            &["points", "--sampler", s, "--count", "4", "--seed", "5"],
            &format!(
                "--seed 5: {s} has no randomization, its points do not depend on a \
                 seed (drop --seed; halton, sobol, zero-two, pmj02, fibonacci, korobov and rd \
                 take one)"
            ),
        );
    }
    for s in ["halton", "sobol", "zero-two", "pmj02", "rd"] {
        let plain = nyquist(&["points", "--sampler", s, "--count", "4"]);
        for seed in ["0", "5"] {
            let o = nyquist(&["points", "--sampler", s, "--count", "4", "--seed", seed]);
            assert_eq!(stderr(&o), "", "{s}");
            assert_ne!(o.stdout, plain.stdout, "{s} --seed {seed}");
        }
    }
}

#[test]
fn analyze_notes_flags_that_change_nothing() {
    assert_note(
        &["analyze", "--sampler", "halton", "--freq", "3"],
        "--freq 3 changes nothing without --spectrum FILE.png",
    );
    assert_note(
        &["analyze", "--sampler", "halton", "--star-grid", "3"],
        "--star-grid 3 unused: the star discrepancy of 16 points in 2 dimensions is computed \
         exactly (give --star-method bounds for the bracket)",
    );
    assert_error(
        &[
            "analyze",
            "--sampler",
            "halton",
            "--star-grid",
            "3",
            "--star-method",
            "exact",
        ],
        "--star-grid 3: --star-method exact uses no grid (give --star-method bounds or auto)",
    );
}

#[test]
fn filter_prints_zero_not_negative_zero() {
    for args in [
        &["filter", "--filter", "lanczos", "--table"][..],
        &["filter", "--filter", "mitchell", "--grid", "9"],
        &[
            "filter", "--filter", "lanczos", "--table", "--format", "json",
        ],
    ] {
        let o = nyquist(args);
        assert_eq!(o.status.code(), Some(0));
        let text = stdout(&o);
        let fields: Vec<&str> = text
            .split([',', '\n', ':', '}', '{', '[', ']'])
            .map(str::trim)
            .collect();
        assert!(fields.contains(&"0"), "{args:?}");
        assert!(!fields.contains(&"-0"), "{args:?}: {text}");
    }
}

#[test]
fn converge_leaves_out_a_default_sampler_above_its_limit() {
    let o = assert_note(
        &[
            "converge",
            "--min-spp",
            "32768",
            "--max-spp",
            "65536",
            "--runs",
            "1",
            "--integrands",
            "disk",
        ],
        "--max-spp 65536: best-candidate takes at most 4096 samples per pixel; left out of the \
         study",
    );
    let text = stdout(&o);
    assert!(
        !text.contains("best-candidate") && text.contains("| pmj02 |"),
        "{text}"
    );
    assert_error(
        &[
            "converge",
            "--samplers",
            "best-candidate",
            "--max-spp",
            "8192",
            "--runs",
            "1",
        ],
        "--samplers best-candidate at 8192 spp: best-candidate takes at most 4096 samples per \
         pixel (give --max-spp 4096 or less)",
    );
    assert_error(
        &[
            "render",
            "--sampler",
            "best-candidate",
            "--spp",
            "8192",
            "--metrics",
        ],
        "--sampler best-candidate --spp 8192: best-candidate takes at most 4096 samples per pixel",
    );
    let help = stdout(&nyquist(&["converge", "--help"]));
    assert!(
        help.contains("best-candidate takes at most 4096 spp"),
        "{help}"
    );
}

/// Spawns `args`, returns the first line of stderr and kills the process: for work that would
/// take minutes.
fn first_stderr_line(args: &[&str], cache: &std::path::Path) -> String {
    let mut child = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .env("XDG_CACHE_HOME", cache)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stderr.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let _ = child.kill();
    let _ = child.wait();
    line
}

#[test]
fn long_work_is_announced_with_its_size() {
    let dir = temp_dir("long-work");
    let out = dir.join("r.png");
    let line = first_stderr_line(
        &[
            "render",
            "--filter",
            "box:radius=1000",
            "-o",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: --filter box:rx=1000,ry=1000 adds each of 1048576 samples to up to \
         65536 pixels: about 6.9e10 pixel updates; this may take minutes\n"
    );
    assert!(!out.exists());
    let line = first_stderr_line(
        &[
            "analyze",
            "--sampler",
            "random",
            "--count",
            "64",
            "--measures",
            "l2-star",
            "--spectrum",
            dir.join("s.png").to_str().unwrap(),
            "--realisations",
            "100000",
        ],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: --spectrum: 100000 realisations × 64 points × 129² frequencies is \
         about 1.1e11 terms; this may take minutes\n"
    );
    let sheet = dir.join("sheet.png");
    let line = first_stderr_line(
        &[
            "compare",
            "--samplers",
            "random,stratified",
            "--filters",
            "box:radius=1000",
            "--spp",
            "16",
            "-o",
            sheet.to_str().unwrap(),
        ],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: 2 renders: about 1.4e11 pixel updates; this may take minutes\n"
    );
    assert!(!sheet.exists());
    // Ordinary work: no warning.
    let o = nyquist(&["render", "--size", "16x16", "--spp", "4", "--metrics"]);
    assert_eq!(stderr(&o), "");
}

/// A lattice's size errors say what would be accepted: the next Fibonacci number, the Korobov
/// search's limit and the sizes Stroud's table has.
#[test]
fn lattice_sizes_name_what_is_accepted() {
    assert_error(
        &["points", "--sampler", "fibonacci", "--count", "20"],
        "--count 20 is not a Fibonacci number (the next is 21)",
    );
    assert_error(
        &[
            "points",
            "--sampler",
            "korobov",
            "--count",
            "5000",
            "--dims",
            "3",
        ],
        "--count 5000: korobov searches its multiplier for at most 4096 points in 3 dimensions; \
         Stroud's table has 101, 199, 307, 523, 701, 1069, 1543, 2129, 3001, 4001, 5003, 6007, \
         8191, 10007 for 3 dimensions",
    );
}
