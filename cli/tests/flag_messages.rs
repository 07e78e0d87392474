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
    // Sobol pads past 1024 dimensions: any count memory allows.
    let o = nyquist(&[
        "points",
        "--sampler",
        "sobol",
        "--dims",
        "1025",
        "--count",
        "4",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
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
        "--filter box:radius=0: filter spec: invalid value `0` for key `radius`: rx must be in \
         [0.000015258789, 1024] (2^-16 to 1024 pixels)",
    );
    assert_error(
        &["filter", "--filter", "mitchell:b=1e308"],
        "--filter mitchell:b=1e308: filter spec: invalid value `1e308` for key `b`: b must be in \
         [-1000, 1000]",
    );
}

#[test]
fn a_filter_key_given_twice_is_refused() {
    assert_error(
        &["filter", "--filter", "mitchell:b=0.5,c=0.25,b=1"],
        "--filter mitchell:b=0.5,c=0.25,b=1: filter spec: key `b` is given twice",
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
         65536 pixels: about 6.9e10 pixel updates; this may take a while; a smaller --size, \
         fewer --spp or a narrower --filter make it shorter\n"
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
         about 1.1e11 terms; this may take minutes; fewer --realisations, a lower --freq or \
         fewer points make it shorter\n"
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
        "nyquist: warning: 2 renders: about 1.4e11 pixel updates; this may take a while; a \
         smaller --size, fewer --spp or a narrower --filter make it shorter\n"
    );
    assert!(!sheet.exists());
    // The quadratic measures and the exact 2D sweep, estimated from the point count.
    let line = first_stderr_line(
        &[
            "analyze",
            "--sampler",
            "random",
            "--count",
            "300000",
            "--measures",
            "l2-star",
        ],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: --measures l2-star: 300000 points in 2 dimensions, d·N² = 1.8e11 \
         terms: about 38 s of work; give fewer points, or leave it out of --measures\n"
    );
    let line = first_stderr_line(
        &[
            "analyze",
            "--sampler",
            "random",
            "--count",
            "100000",
            "--measures",
            "star",
            "--star-method",
            "exact",
        ],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: --measures star: exact 2D sweep of 100000 points, N² = 1.0e10 steps: \
         about 32 s of work; give fewer points, or --star-method bounds\n"
    );
    let line = first_stderr_line(
        &[
            "converge",
            "--samplers",
            "random,sobol",
            "--runs",
            "200000",
            "--max-spp",
            "1024",
        ],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: 2 samplers × 7 N × --runs 200000: about 8.1e8 samples; this may take \
         a while; fewer --runs or --samplers, or a lower --max-spp, make it shorter\n"
    );
    let mask = dir.join("m.png");
    let line = first_stderr_line(
        &["mask", "--size", "1024", "-o", mask.to_str().unwrap()],
        &dir,
    );
    assert_eq!(
        line,
        "nyquist: warning: --size 1024x1024 --channels 1: void-and-cluster over 1048576 pixels: \
         about 15 s of work; a smaller --size or fewer --channels make it shorter\n"
    );
    assert!(!mask.exists());
    // Past its stated limit the exact sweep is refused, as its help says.
    assert_error(
        &[
            "analyze",
            "--sampler",
            "random",
            "--count",
            "131073",
            "--measures",
            "star",
            "--star-method",
            "exact",
        ],
        "--star-method exact: the 2D sweep of 131073 points takes N² = 1.7e10 steps, past its \
         limit of 131072 points (about 55 s); use --star-method bounds or fewer points",
    );
    // Above 65536 points l2-star leaves the defaults with a note.
    let o = nyquist(&[
        "analyze",
        "--sampler",
        "random",
        "--count",
        "70000",
        "--json",
    ]);
    assert_eq!(
        stderr(&o),
        "nyquist: note: l2-star is left out of the default measures above 65536 points (its \
         work grows as d·N²; 70000 points would take about 2 s): name it in --measures to \
         compute it\n"
    );
    // Ordinary work: no warning.
    let o = nyquist(&["render", "--size", "16x16", "--spp", "4", "--metrics"]);
    assert_eq!(stderr(&o), "");
    let o = nyquist(&["mask", "--size", "256", "-o", mask.to_str().unwrap()]);
    assert_eq!((o.status.code(), stderr(&o).as_str()), (Some(0), ""));
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

#[test]
fn numeric_flags_name_the_flag_the_value_and_the_real_range() {
    for (args, line) in [
        // Negative values reach the flag's parser instead of reading as an unknown flag.
        (
            &["render", "--spp", "-1"][..],
            "--spp -1: not in 1 ..= 1048576",
        ),
        // The real limit, not the type's 0..=4294967295.
        (
            &["render", "--spp", "4294967296"],
            "--spp 4294967296: not in 1 ..= 1048576",
        ),
        (
            &["render", "--spp", "1.5"],
            "--spp 1.5: not a whole number in 1 ..= 1048576",
        ),
        (
            &["render", "--size", "-5x5"],
            "--size -5x5: not WxH with sides 1 to 16384 (e.g. 256x256)",
        ),
        (
            &["points", "--count", "0"],
            "--count 0: not in 1 ..= 268435456",
        ),
        (
            &["points", "--seed", "-3"],
            "--seed -3: not in 0 ..= 18446744073709551615",
        ),
        (&["converge", "--dims", "1"], "--dims 1: not in 2 ..= 64"),
        (
            &["converge", "--runs", "0"],
            "--runs 0: not in 1 ..= 1048576",
        ),
        (
            &["compare", "--spp", "1,-4"],
            "--spp -4: not in 1 ..= 65536",
        ),
        (
            &["compare", "--threads", "0"],
            "--threads 0: not in 1 ..= 1024",
        ),
        (
            &["filter", "--filter", "box", "--grid", "5000"],
            "--grid 5000: not in 1 ..= 4096",
        ),
        (&["mask", "--channels", "5"], "--channels 5: not in 1 ..= 4"),
        (&["mask", "--bits", "7"], "--bits 7: not 8 or 16"),
        (
            &["analyze", "--sampler", "sobol", "--freq", "5000"],
            "--freq 5000: not in 1 ..= 4096",
        ),
        (
            &["analyze", "--sampler", "sobol", "--realisations", "0"],
            "--realisations 0: not in 1 ..= 100000",
        ),
        (
            &["web", "--port", "70000"],
            "--port 70000: not in 0 ..= 65535",
        ),
        (
            &["points", "--max-memory", "3X"],
            "--max-memory 3X: not a size such as 512M, 2G or 1.5GiB",
        ),
        // A flag without its value: no empty list of possible values.
        (&["render", "--spp"], "--spp: a value is required"),
    ] {
        assert_error(args, line);
    }
}

#[test]
fn set_limits_are_named_in_the_flags_terms() {
    for (args, line) in [
        (
            &["points", "--sampler", "pmj02", "--count", "65537"][..],
            "--count 65537: pmj02 has at most 65536 points",
        ),
        (
            &[
                "points",
                "--sampler",
                "pmj02",
                "--count",
                "10",
                "--skip",
                "65530",
            ],
            "--skip 65530 --count 10: pmj02 has 65536 points (indices 0 ..= 65535); these would \
             end at index 65539",
        ),
        (
            &["points", "--sampler", "stratified", "--grid", "65536x65536"],
            "--grid 65536x65536 (4294967296 points) × --dims 2 is more than 268435456 values",
        ),
        (
            &["filter", "--filter", "box:radius=1,rx=2"],
            "--filter box:radius=1,rx=2: filter spec: keys `radius` and `rx` cannot both be given",
        ),
        (
            &["filter", "--filter", "gaussian:sigma=1e10"],
            "--filter gaussian:sigma=1e10: filter spec: invalid value `1e10` for key `sigma`: the \
             filter's integral 2.844444e-39 is below 1e-12, so every sample would weigh almost \
             nothing",
        ),
        (
            &["converge", "--dims", "4", "--integrands", "disk"],
            "--dims 4 --integrands: Genz's six families replace the 2-D integrands (give one or \
             the other)",
        ),
    ] {
        assert_error(args, line);
    }
}

#[test]
fn counts_of_one_are_singular() {
    let o = nyquist(&[
        "converge",
        "--samplers",
        "random",
        "--integrands",
        "disk",
        "--runs",
        "1",
        "--min-spp",
        "16",
        "--max-spp",
        "32",
    ]);
    let text = stdout(&o);
    assert!(text.contains("; 1 independent run per N,"), "{text}");
    assert!(text.contains("1 sampler × 2 N × 1 run:"), "{text}");
    let dir = temp_dir("singular");
    let sheet = dir.join("sheet.png");
    let o = nyquist(&[
        "compare",
        "--samplers",
        "random",
        "--filters",
        "box",
        "--spp",
        "1",
        "--size",
        "8x8",
        "-o",
        sheet.to_str().unwrap(),
    ]);
    assert!(stdout(&o).contains("\n1 render, "), "{}", stdout(&o));
}

#[test]
fn a_missing_slope_says_why() {
    // The uniform grid integrates the bilinear function exactly at every square count.
    let o = nyquist(&[
        "converge",
        "--samplers",
        "uniform",
        "--integrands",
        "bilinear",
        "--runs",
        "2",
        "--min-spp",
        "16",
        "--max-spp",
        "64",
    ]);
    let text = stdout(&o);
    assert!(text.contains("| uniform | - ("), "{text}");
    assert!(
        text.contains("No slope (-): uniform on bilinear, RMSE 0 at N = 16 (exact there;"),
        "{text}"
    );
}

#[test]
fn converge_honours_the_memory_limit() {
    let o = nyquist(&["converge", "--max-memory", "1K", "--threads", "1"]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--runs 64 on 1 thread: needs about ") && err.contains("--max-memory"),
        "{err}"
    );
}
