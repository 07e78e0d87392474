//! End-to-end tests of `nyquist points --spp` (pixel samplers) and `--format svg`.

mod common;

use common::{assert_one_line_error, nyquist, rows};

#[test]
fn every_pixel_sampler_prints_spp_points_in_the_unit_cube() {
    for (s, spp) in [
        ("random", 16),
        ("uniform", 16),
        ("stratified", 16),
        ("zero-two", 16),
        ("halton", 16),
        ("hammersley", 16),
        ("sobol", 16),
        ("best-candidate", 16),
        ("adaptive", 16),
        ("fibonacci", 21),
        ("r2", 16),
        ("korobov", 16),
    ] {
        let mut args = vec![
            "points",
            "--sampler",
            s,
            "--spp",
            "16",
            "--pixel",
            "3,2",
            "--dims",
            "5",
            "--seed",
            "1",
        ];
        if ["halton", "hammersley", "sobol"].contains(&s) {
            args.extend(["--resolution", "8x8"]);
        }
        let o = nyquist(&args);
        assert!(
            o.status.success(),
            "{s}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let r = rows(&o);
        assert_eq!(r.len(), spp, "{s}");
        assert!(r.iter().all(|p| p.len() == 5), "{s}");
        assert!(r.iter().flatten().all(|v| (0.0..1.0).contains(v)), "{s}");
    }
}

#[test]
fn stratified_pixel_samples_fill_one_stratum_each() {
    let o = nyquist(&[
        "points",
        "--sampler",
        "stratified",
        "--spp",
        "16",
        "--pixel",
        "5,5",
    ]);
    let mut seen = [false; 16];
    for p in rows(&o) {
        seen[(p[1] * 4.0) as usize * 4 + (p[0] * 4.0) as usize] = true;
    }
    assert!(seen.iter().all(|&b| b));
}

#[test]
fn zero_two_rounds_spp_with_a_notice() {
    let o = nyquist(&["points", "--sampler", "zero-two", "--spp", "6"]);
    assert!(o.status.success());
    assert_eq!(rows(&o).len(), 8);
    let err = String::from_utf8(o.stderr).unwrap();
    assert!(err.contains("rounded up to 8"), "{err}");
}

#[test]
fn svg_draws_points_and_strata() {
    let o = nyquist(&[
        "points",
        "--sampler",
        "stratified",
        "--spp",
        "12",
        "--grid",
        "4x3",
        "--format",
        "svg",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = String::from_utf8(o.stdout).unwrap();
    assert!(s.starts_with("<svg"));
    assert_eq!(s.matches("<circle").count(), 12);
    // The 4 × 3 strata: 3 inner vertical and 2 inner horizontal lines in the grid's path.
    let grid = s
        .lines()
        .find(|l| l.starts_with("<path"))
        .expect("a strata path");
    assert_eq!(
        (grid.matches('V').count(), grid.matches('H').count()),
        (3, 2)
    );
    let o = nyquist(&[
        "points",
        "--sampler",
        "halton",
        "--count",
        "20",
        "--format",
        "svg",
    ]);
    assert_eq!(
        String::from_utf8(o.stdout)
            .unwrap()
            .matches("<circle")
            .count(),
        20
    );
}

#[test]
fn pixel_sampler_bad_input_is_one_line_and_status_2() {
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "best-candidate"]),
        "--spp",
    );
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "hammersley", "--spp", "4"]),
        "--resolution",
    );
    assert_one_line_error(
        &nyquist(&[
            "points",
            "--sampler",
            "sobol",
            "--spp",
            "4",
            "--resolution",
            "4x4",
            "--pixel",
            "4,0",
        ]),
        "outside",
    );
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "lhs", "--spp", "4"]),
        "pixel sampler",
    );
    assert_one_line_error(
        &nyquist(&[
            "points",
            "--sampler",
            "stratified",
            "--spp",
            "10",
            "--grid",
            "3x3",
        ]),
        "--grid",
    );
    assert_one_line_error(
        &nyquist(&["points", "--spp", "4", "--pixel", "x"]),
        "--pixel",
    );
    assert_one_line_error(
        &nyquist(&["points", "--sampler", "best-candidate", "--spp", "5000"]),
        "best-candidate",
    );
}

/// `points --sampler korobov --spp N` prints the pixel sampler's N samples: every coordinate a
/// regular grid of spacing 1/N shifted modulo 1, and sample k − sample 0 equal to k·(1, a)/N
/// modulo 1 for one multiplier a (dimensions 0, 1 and again 2, 3 under another shift).
#[test]
fn korobov_pixel_samples_form_a_rotated_lattice() {
    let n = 50usize;
    let o = nyquist(&[
        "points",
        "--sampler",
        "korobov",
        "--spp",
        "50",
        "--pixel",
        "3,2",
        "--dims",
        "4",
        "--seed",
        "9",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let r = rows(&o);
    assert_eq!(r.len(), n);
    let wrap = |d: f64| {
        let d = d.rem_euclid(1.0);
        d.min(1.0 - d)
    };
    for d in 0..4 {
        let mut xs: Vec<f64> = r.iter().map(|p| f64::from(p[d])).collect();
        xs.sort_by(f64::total_cmp);
        let gaps = xs
            .windows(2)
            .map(|w| w[1] - w[0])
            .chain([xs[0] + 1.0 - xs[n - 1]]);
        assert!(
            gaps.into_iter().all(|g| (g - 1.0 / n as f64).abs() < 1e-5),
            "dim {d}"
        );
    }
    let step = |k: usize, d: usize| f64::from(r[k][d]) - f64::from(r[0][d]);
    let a = (step(1, 1).rem_euclid(1.0) * n as f64).round() as usize;
    for pair in [0, 2] {
        for k in 0..n {
            assert!(
                wrap(step(k, pair) - k as f64 / n as f64) < 1e-5,
                "pair {pair} k {k}"
            );
            let want = (k * a % n) as f64 / n as f64;
            assert!(wrap(step(k, pair + 1) - want) < 1e-5, "pair {pair} k {k}");
        }
    }
    assert_ne!(r[0][0], r[0][2], "each pair its own shift");
}

/// Without --grid, a non-square spp takes the core's strata grid (5 × 2 for 10): one sample in
/// every cell.
#[test]
fn stratified_pixel_samples_of_any_spp_fill_the_strata_grid() {
    let o = nyquist(&["points", "--sampler", "stratified", "--spp", "10"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut hit = [0u32; 10];
    for line in text.lines().filter(|l| !l.starts_with('x')) {
        let v: Vec<f64> = line.split(',').map(|t| t.trim().parse().unwrap()).collect();
        hit[(v[1] * 2.0) as usize * 5 + (v[0] * 5.0) as usize] += 1;
    }
    assert_eq!(hit, [1; 10]);
}
