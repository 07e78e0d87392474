//! End-to-end tests of `nyquist points`, running the built binary.

mod common;

use common::{assert_one_line_error, nyquist, rows, stdout, temp_dir};

#[test]
fn halton_csv_is_the_published_sequence() {
    let o = nyquist(&[
        "points",
        "--sampler",
        "halton",
        "--count",
        "4",
        "--dims",
        "2",
    ]);
    assert!(o.status.success());
    let r = rows(&o);
    assert_eq!(r.len(), 4);
    assert_eq!(r[0], [0.0, 0.0]);
    assert_eq!(r[1][0], 0.5);
    assert_eq!(r[1][1], 1.0f32 / 3.0);
    assert_eq!(r[2], [0.25, 2.0f32 / 3.0]);
    assert_eq!(r[3][0], 0.75);
}

#[test]
fn csv_values_are_shortest_round_trip_decimals() {
    let o = nyquist(&["points", "--sampler", "vdc", "--count", "8", "--dims", "1"]);
    assert_eq!(
        stdout(&o),
        "0\n0.5\n0.25\n0.75\n0.125\n0.625\n0.375\n0.875\n"
    );
}

#[test]
fn skip_starts_later_in_the_sequence() {
    let all = rows(&nyquist(&[
        "points",
        "--sampler",
        "sobol",
        "--count",
        "8",
        "--dims",
        "3",
    ]));
    let tail = rows(&nyquist(&[
        "points",
        "--sampler",
        "sobol",
        "--count",
        "3",
        "--dims",
        "3",
        "--skip",
        "5",
    ]));
    assert_eq!(&all[5..], &tail[..]);
}

#[test]
fn every_sampler_prints_count_points_in_the_unit_cube() {
    for s in [
        "random",
        "uniform",
        "stratified",
        "lhs",
        "halton",
        "halton-zaremba",
        "sobol",
        "zero-two",
        "hammersley",
        "hammersley-zaremba",
    ] {
        let o = nyquist(&["points", "--sampler", s, "--count", "16", "--dims", "2"]);
        assert!(
            o.status.success(),
            "{s}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let r = rows(&o);
        assert_eq!(r.len(), 16, "{s}");
        assert!(r.iter().flatten().all(|v| (0.0..1.0).contains(v)), "{s}");
    }
}

#[test]
fn stratified_points_fill_one_cell_each() {
    let o = nyquist(&[
        "points",
        "--sampler",
        "stratified",
        "--count",
        "12",
        "--grid",
        "4x3",
    ]);
    let mut seen = [false; 12];
    for p in rows(&o) {
        let cell = (p[1] * 3.0) as usize * 4 + (p[0] * 4.0) as usize;
        assert!(!std::mem::replace(&mut seen[cell], true));
    }
    assert!(seen.iter().all(|&s| s));
}

#[test]
fn json_has_one_array_per_point() {
    let o = nyquist(&[
        "points",
        "--sampler",
        "vdc",
        "--count",
        "3",
        "--dims",
        "1",
        "--format",
        "json",
    ]);
    assert_eq!(stdout(&o), "[[0],[0.5],[0.25]]\n");
}

#[test]
fn bad_input_is_one_line_and_status_2() {
    assert_one_line_error(&nyquist(&["points", "--sampler", "nope"]), "--sampler");
    assert_one_line_error(&nyquist(&["points", "--sampler", "nope"]), "halton");
    assert_one_line_error(&nyquist(&["points", "--count", "x"]), "--count");
    assert_one_line_error(&nyquist(&["points", "--count", "0"]), "--count");
    assert_one_line_error(&nyquist(&["points", "--dims", "0"]), "--dims");
    assert_one_line_error(&nyquist(&["points", "--sampler", "hammersley"]), "--count");
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "stratified", "--count", "10"]),
        "--grid",
    );
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "vdc", "--dims", "2"]),
        "--dims",
    );
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "halton", "--dims", "1025"]),
        "halton",
    );
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "zero-two", "--dims", "3"]),
        "--dims",
    );
    assert_one_line_error(
        &nyquist(&["points", "--count", "18446744073709551615"]),
        "--count",
    );
    assert_one_line_error(
        &nyquist(&[
            "points",
            "--sampler",
            "sobol",
            "--skip",
            "18446744073709551615",
            "--count",
            "2",
        ]),
        "--skip",
    );
    assert_one_line_error(
        &nyquist(&["points", "--grid", "0x3", "--sampler", "uniform"]),
        "--grid",
    );
    assert_one_line_error(&nyquist(&["points", "--bogus"]), "--bogus");
}

#[test]
fn unwritable_output_leaves_nothing_behind() {
    let dir = temp_dir("points-output");
    let missing = dir.join("no-such-folder").join("p.csv");
    let o = nyquist(&["points", "--output", missing.to_str().unwrap()]);
    assert_one_line_error(&o, "--output");
    assert!(!missing.exists());
    let ok = dir.join("p.csv");
    let o = nyquist(&["points", "--count", "2", "--output", ok.to_str().unwrap()]);
    assert!(o.status.success());
    assert_eq!(std::fs::read_to_string(&ok).unwrap().lines().count(), 2);
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        1,
        "a temporary file was left behind"
    );
}

#[test]
fn help_has_an_example() {
    let o = nyquist(&["points", "--help"]);
    assert!(o.status.success());
    assert!(stdout(&o).contains("Example: nyquist points"));
}

/// `points --sampler korobov` takes Stroud's tabled multiplier where the table has --count and
/// --dims (1069 points in 4-D: a = 71, so point 1 is (1, 71, 71², 71³ mod 1069)/1069) and says
/// so on stderr; elsewhere the P2 search, also said; a count beyond both names the tabled sizes.
#[test]
fn korobov_points_use_the_table_or_the_search() {
    let o = nyquist(&[
        "points",
        "--sampler",
        "korobov",
        "--count",
        "1069",
        "--dims",
        "4",
    ]);
    assert!(o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("multiplier 71 from Stroud (1971)"), "{err}");
    let r = rows(&o);
    assert_eq!(r.len(), 1069);
    let want = [1u64, 71, 71 * 71 % 1069, 71 * 71 * 71 % 1069];
    for (d, g) in want.iter().enumerate() {
        assert!(
            (f64::from(r[1][d]) - *g as f64 / 1069.0).abs() < 1e-6,
            "dim {d}"
        );
    }
    let o = nyquist(&[
        "points",
        "--sampler",
        "korobov",
        "--count",
        "1024",
        "--dims",
        "4",
    ]);
    assert!(o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("minimising P2"));
    assert_one_line_error(
        &nyquist(&[
            "points",
            "--sampler",
            "korobov",
            "--count",
            "5000",
            "--dims",
            "6",
        ]),
        "2129, 3001, 4001, 5003, 6007, 8191, 10007",
    );
}
