//! End-to-end tests of `nyquist analyze`, running the built binary.

mod common;

use common::{assert_one_line_error, files, json_field, nyquist, png_size, stdout, temp_dir};
use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Runs nyquist with `input` on stdin.
fn piped(args: &[&str], input: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run nyquist");
    let mut stdin = child.stdin.take().unwrap();
    // The process may exit before reading everything (an early error): ignore broken pipes.
    let _ = stdin.write_all(input);
    drop(stdin);
    child.wait_with_output().expect("wait for nyquist")
}

fn ok_json(o: &Output) -> String {
    assert!(
        o.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    stdout(o)
}

/// The raw items of the JSON array after `"key":`.
fn json_list(json: &str, key: &str) -> Vec<String> {
    let pat = format!("\"{key}\":[");
    let at = json.find(&pat).unwrap_or_else(|| panic!("{key} in {json}")) + pat.len();
    let end = at + json[at..].find(']').unwrap();
    json[at..end].split(',').map(str::to_owned).collect()
}

/// Φ₂(i) for i < 2^32.
fn vdc(i: u32) -> f64 {
    f64::from(i.reverse_bits()) / 4_294_967_296.0
}

#[test]
fn van_der_corput_16_generated_has_star_discrepancy_one_sixteenth() {
    let o = nyquist(&[
        "analyze",
        "--sampler",
        "vdc",
        "--count",
        "16",
        "--dims",
        "1",
        "--json",
    ]);
    let j = ok_json(&o);
    // N·D* = 1 for the first 16 van der Corput points {0, 1/16, …, 15/16} (Niederreiter Thm 2.6).
    assert_eq!(json_field(&j, "star"), 1.0 / 16.0);
    assert!(j.contains("\"star-method\":\"exact-1d\""), "{j}");
    assert_eq!(json_field(&j, "points"), 16.0);
    assert_eq!(json_field(&j, "dims"), 1.0);
}

#[test]
fn van_der_corput_16_piped_csv_has_star_discrepancy_one_sixteenth() {
    let pts = nyquist(&["points", "--sampler", "vdc", "--count", "16", "--dims", "1"]);
    assert!(pts.status.success());
    let o = piped(&["analyze", "--json"], &pts.stdout);
    assert_eq!(json_field(&ok_json(&o), "star"), 1.0 / 16.0);
    // The same with a header line and `-` for stdin.
    let mut with_header = b"x\n".to_vec();
    with_header.extend_from_slice(&pts.stdout);
    let o = piped(&["analyze", "-", "--json"], &with_header);
    assert_eq!(json_field(&ok_json(&o), "star"), 1.0 / 16.0);
    // L2-star: N·T_N = 1/√3 for N = 2^m van der Corput points (core's l2 docs).
    let t = json_field(&ok_json(&o), "l2-star");
    assert!((16.0 * t - 1.0 / 3f64.sqrt()).abs() < 1e-12, "{t}");
}

#[test]
fn hammersley_csv_file_matches_de_clerck() {
    // De Clerck (1986): for (i/N, Φ₂(i)), N = 2^m, N·D* = m/3 + 13/9 − (−1)^m·4/(9N).
    let dir = temp_dir("analyze-hammersley");
    for m in [3u32, 4, 5] {
        let n = 1u32 << m;
        let mut csv = String::from("x,y\n");
        for i in 0..n {
            csv.push_str(&format!("{},{}\n", f64::from(i) / f64::from(n), vdc(i)));
        }
        let path = dir.join(format!("h{m}.csv"));
        std::fs::write(&path, csv).unwrap();
        let o = nyquist(&["analyze", path.to_str().unwrap(), "--json"]);
        let j = ok_json(&o);
        let nf = f64::from(n);
        let sign = if m % 2 == 0 { 1.0 } else { -1.0 };
        let expected = (f64::from(m) / 3.0 + 13.0 / 9.0 - sign * 4.0 / (9.0 * nf)) / nf;
        let got = json_field(&j, "star");
        assert!(
            (got - expected).abs() < 1e-12,
            "m = {m}: {got} vs {expected}"
        );
        assert!(j.contains("\"star-method\":\"exact-2d\""), "{j}");
    }
}

#[test]
fn json_has_every_requested_measure() {
    let o = nyquist(&[
        "analyze",
        "--sampler",
        "stratified",
        "--count",
        "64",
        "--seed",
        "3",
        "--measures",
        "star,l2-star,centered-l2,wraparound-l2,min-distance,min-distance-torus",
        "--json",
    ]);
    let j = ok_json(&o);
    assert!(j.starts_with('{') && j.trim_end().ends_with('}'), "{j}");
    assert!(j.contains(
        "\"measures\":[\"star\",\"l2-star\",\"centered-l2\",\"wraparound-l2\",\"min-distance\",\"min-distance-torus\"]"
    ));
    for key in [
        "star",
        "l2-star",
        "centered-l2",
        "wraparound-l2",
        "min-distance",
        "rho",
        "min-distance-torus",
        "rho-torus",
        "seconds",
    ] {
        let v = json_field(&j, key);
        assert!(v.is_finite() && v >= 0.0, "{key} = {v}");
    }
    // Jittered 8×8 strata: D* ≤ 2·8/64 (each box edge crosses at most 8 + 8 strata) and ρ < 1.
    assert!(json_field(&j, "star") <= 0.25);
    assert!(json_field(&j, "rho") < 1.0);
    assert!(json_field(&j, "min-distance-torus") <= json_field(&j, "min-distance"));
}

#[test]
fn default_measures_and_table_say_how_and_how_long() {
    let o = nyquist(&["analyze", "--sampler", "halton", "--count", "64"]);
    let t = ok_json(&o);
    assert!(t.starts_with("64 points, 2 dimensions (halton"), "{t}");
    for want in [
        "star discrepancy",
        "exact (2D sweep)",
        "L2-star discrepancy",
        "min distance",
        "rho",
        " ms",
        "total time",
    ] {
        assert!(t.contains(want), "{want} missing in {t}");
    }
    // No min distance for 1D sets by default.
    let o = nyquist(&["analyze", "--sampler", "vdc", "--count", "8", "--dims", "1"]);
    assert!(!ok_json(&o).contains("min distance"));
}

#[test]
fn bounds_bracket_the_exact_value_and_are_named() {
    let exact = json_field(
        &ok_json(&nyquist(&[
            "analyze",
            "--sampler",
            "random",
            "--count",
            "200",
            "--json",
        ])),
        "star",
    );
    let j = ok_json(&nyquist(&[
        "analyze",
        "--sampler",
        "random",
        "--count",
        "200",
        "--json",
        "--star-method",
        "bounds",
        "--star-grid",
        "64",
    ]));
    assert!(j.contains("\"star-method\":\"bounds\""), "{j}");
    let (lo, up) = (json_field(&j, "star-lower"), json_field(&j, "star-upper"));
    assert!(lo <= exact && exact <= up, "{lo} <= {exact} <= {up}");
    assert!(up - lo <= 2.0 / 64.0);
    assert_eq!(json_field(&j, "star-grid"), 64.0);
    // 3D enumeration for a small set.
    let j = ok_json(&nyquist(&[
        "analyze",
        "--sampler",
        "sobol",
        "--count",
        "32",
        "--dims",
        "3",
        "--json",
    ]));
    assert!(j.contains("\"star-method\":\"exact-enumeration\""), "{j}");
}

#[test]
fn spectrum_writes_one_png_of_the_documented_size() {
    let dir = temp_dir("analyze-spectrum");
    let png = dir.join("s.png");
    let o = nyquist(&[
        "analyze",
        "--sampler",
        "stratified",
        "--count",
        "256",
        "--spectrum",
        png.to_str().unwrap(),
        "--freq",
        "24",
        "--realisations",
        "3",
        "--json",
    ]);
    let j = ok_json(&o);
    assert_eq!(png_size(&png), (1404, 730));
    assert_eq!(files(&dir), ["s.png"]);
    assert_eq!(json_field(&j, "spectrum_max_freq"), 24.0);
    assert_eq!(json_field(&j, "spectrum_realisations"), 3.0);
    assert!(
        j.contains("\"spectrum_identical_realisations\":false"),
        "{j}"
    );
    // The radial mean has F + 1 entries, DC first (the mean power there is N); the anisotropy
    // has one entry per annulus, null where the variance is 0 (DC).
    let radial = json_list(&j, "spectrum_radial_mean");
    assert_eq!(radial.len(), 25);
    assert!((radial[0].parse::<f64>().unwrap() - 256.0).abs() < 1e-9);
    let aniso = json_list(&j, "spectrum_anisotropy_db");
    assert_eq!((aniso.len(), aniso[0].as_str()), (25, "null"));
    // Unscrambled Halton ignores the seed: the output says the realisations are identical.
    let o = nyquist(&[
        "analyze",
        "--sampler",
        "halton",
        "--count",
        "64",
        "--spectrum",
        png.to_str().unwrap(),
        "--freq",
        "8",
        "--realisations",
        "2",
    ]);
    assert!(ok_json(&o).contains("all identical"));
    // From piped CSV too (one realisation).
    let pts = nyquist(&["points", "--sampler", "sobol", "--count", "64"]);
    let png2 = dir.join("t.png");
    let o = piped(
        &["analyze", "--spectrum", png2.to_str().unwrap()],
        &pts.stdout,
    );
    assert!(ok_json(&o).contains("spectrum:"));
    assert_eq!(png_size(&png2), (1404, 730));
}

#[test]
fn bad_input_is_one_line_exit_2_and_writes_nothing() {
    let dir = temp_dir("analyze-errors");
    let png = dir.join("bad.png");
    let png = png.to_str().unwrap();
    // In the temporary folder, so that the check for files left behind can see one.
    let gif = dir.join("x.gif");
    let gif = gif.to_str().unwrap();
    let cases: [(&[u8], &[&str], &str); 9] = [
        (b"0.5,0.5\n0.25,oops\n", &[], "not a number"),
        (b"0.5,0.5\n0.25\n", &[], "1 value, expected 2"),
        (b"0.5,0.5\n0.25,1.0\n", &[], "outside [0, 1)"),
        (b"0.5,-0.1\n", &[], "outside [0, 1)"),
        (b"0.5,NaN\n", &[], "not a finite number"),
        (b"", &[], "no points"),
        (b"x,y\n\n", &[], "no points"),
        (b"0.5,0.5\n", &["--measures", "star,bogus"], "bogus"),
        (
            b"0.5\n0.25\n",
            &["--measures", "min-distance"],
            "needs a 2D set",
        ),
    ];
    for (input, extra, mentions) in cases {
        let mut args = vec!["analyze", "--spectrum", png];
        args.extend_from_slice(extra);
        let o = piped(&args, input);
        assert_one_line_error(&o, mentions);
        assert!(files(&dir).is_empty(), "{mentions}: {:?}", files(&dir));
    }
    for (args, mentions) in [
        (
            &[
                "analyze",
                "--sampler",
                "vdc",
                "--dims",
                "1",
                "--spectrum",
                png,
            ][..],
            "at least 2 dimensions",
        ),
        (
            &[
                "analyze",
                "--sampler",
                "halton",
                "--spectrum",
                png,
                "--freq",
                "0",
            ][..],
            "--freq 0",
        ),
        (
            &["analyze", "--sampler", "halton", "--count", "0"][..],
            "--count 0",
        ),
        (
            &["analyze", "--sampler", "halton", "--spectrum", gif][..],
            "unknown image extension",
        ),
        (&["analyze", "/nonexistent/p.csv"][..], "cannot read"),
        (
            &[
                "analyze",
                "--sampler",
                "vdc",
                "--dims",
                "1",
                "--measures",
                "min-distance",
            ][..],
            "needs a 2D set",
        ),
        (
            &["analyze", "--sampler", "halton", "--star-grid", "0"][..],
            "--star-grid 0",
        ),
    ] {
        assert_one_line_error(&nyquist(args), mentions);
        assert!(files(&dir).is_empty());
    }
    for (args, mentions) in [
        (
            &["analyze", "--realisations", "2", "--spectrum", png][..],
            "needs a generated set",
        ),
        (
            &["analyze", "--dims", "3", "--spectrum", png][..],
            "--dims is 3",
        ),
        (
            &["analyze", "--count", "4"][..],
            "--count applies to generated sets",
        ),
        (&["analyze", "-", "--sampler", "halton"][..], "not both"),
    ] {
        assert_one_line_error(&piped(args, b"0.5,0.5\n"), mentions);
        assert!(files(&dir).is_empty());
    }
}

#[test]
fn generated_and_piped_sets_give_the_same_measures() {
    // points' CSV holds the shortest decimals of the f32 values; analyze reads decimals as f64,
    // so non-dyadic values differ from the generated f32 by up to half an f32 ulp (~3e-8).
    // Hammersley takes no seed; Sobol's seed asks for its digital shift.
    for (sampler, dims, seed) in [
        ("hammersley", "2", None),
        ("sobol", "3", Some("7")),
        ("lhs", "4", Some("7")),
    ] {
        let mut gen_args = vec!["--sampler", sampler, "--count", "32", "--dims", dims];
        if let Some(seed) = seed {
            gen_args.extend(["--seed", seed]);
        }
        let mut a = vec![
            "analyze",
            "--json",
            "--measures",
            "star,l2-star,centered-l2",
        ];
        a.extend_from_slice(&gen_args);
        let generated = ok_json(&nyquist(&a));
        let mut p = vec!["points"];
        p.extend_from_slice(&gen_args);
        let csv = nyquist(&p);
        let piped = ok_json(&piped(
            &[
                "analyze",
                "--json",
                "--measures",
                "star,l2-star,centered-l2",
            ],
            &csv.stdout,
        ));
        for key in ["star", "l2-star", "centered-l2"] {
            let (g, p) = (json_field(&generated, key), json_field(&piped, key));
            assert!((g - p).abs() <= 1e-7, "{sampler} {key}: {g} vs {p}");
            if sampler == "hammersley" {
                assert_eq!(g, p, "dyadic values are exact in both");
            }
        }
    }
}
