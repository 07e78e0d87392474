//! End-to-end tests of `nyquist filter`.

mod common;

use common::{assert_one_line_error, nyquist, stdout, temp_dir};

#[test]
fn grid_csv_has_n_squared_rows_over_the_closed_support() {
    let o = nyquist(&["filter", "--filter", "triangle", "--grid", "5"]);
    assert!(o.status.success());
    let rows: Vec<Vec<f64>> = stdout(&o)
        .lines()
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 25);
    // Triangle r = 2: corners at (±2, ±2) are 0, the centre is 2·2 = 4.
    assert_eq!(rows[0][..2], [-2.0, -2.0]);
    assert_eq!(rows[0][2], 0.0);
    assert_eq!(rows[12], [0.0, 0.0, 4.0]);
    assert_eq!(rows[24][..2], [2.0, 2.0]);
    let err = String::from_utf8(o.stderr).unwrap();
    let integral: f64 = err
        .lines()
        .find_map(|l| l.strip_prefix("integral "))
        .expect("an integral line on stderr")
        .trim()
        .parse()
        .unwrap();
    assert!((integral - 16.0).abs() < 1e-4, "{integral}");
}

#[test]
fn mitchell_centre_is_one_minus_b_over_three_squared() {
    let o = nyquist(&["filter", "--filter", "mitchell:b=0.5,c=0.25", "--grid", "3"]);
    assert!(o.status.success());
    let centre: f64 = stdout(&o)
        .lines()
        .nth(4)
        .unwrap()
        .rsplit(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let m0 = 1.0 - 0.5 / 3.0;
    assert!((centre - m0 * m0).abs() < 1e-6, "{centre}");
}

#[test]
fn plot_writes_a_png_and_bad_output_leaves_nothing() {
    let dir = temp_dir("filter-plot");
    let png = dir.join("f.png");
    let o = nyquist(&[
        "filter",
        "--filter",
        "lanczos",
        "--plot",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    let missing = dir.join("missing").join("f.png");
    let o = nyquist(&[
        "filter",
        "--filter",
        "box",
        "--plot",
        missing.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!missing.exists());
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        1,
        "stray temporary files"
    );
}

#[test]
fn bad_specs_are_one_line_errors_naming_the_flag() {
    for spec in [
        "nope",
        "mitchell:b=x",
        "gaussian:sigma=0",
        "box:radius=-1",
        "lanczos:tau=nan",
        "triangle:q=1",
    ] {
        assert_one_line_error(&nyquist(&["filter", "--filter", spec]), "--filter");
    }
    assert_one_line_error(
        &nyquist(&["filter", "--filter", "box", "--grid", "0"]),
        "--grid",
    );
}

#[test]
fn blackman_harris_and_catmull_rom_print_their_values_and_plot() {
    // Blackman–Harris at the centre is a₀ + a₁ + a₂ + a₃ = 1 per axis; at (±r, 0) it is
    // a₀ − a₁ + a₂ − a₃ = 6·10⁻⁵; its integral (3·a₀)² at radius 1.5.
    let o = nyquist(&["filter", "--filter", "blackman-harris", "--grid", "3"]);
    assert!(o.status.success());
    let rows: Vec<Vec<f64>> = stdout(&o)
        .lines()
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert!((rows[4][2] - 1.0).abs() < 1e-6, "{rows:?}");
    assert!((rows[3][2] - 6e-5).abs() < 1e-6, "{rows:?}");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err, "radius 1.5 1.5\nintegral 1.1583141\n");
    // Catmull–Rom interpolates: 1 at the centre, 0 at the other integers; integral 1.
    let o = nyquist(&["filter", "--filter", "catmull-rom", "--grid", "5"]);
    let rows: Vec<Vec<f64>> = stdout(&o)
        .lines()
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows[12], [0.0, 0.0, 1.0]);
    assert_eq!(rows[13], [1.0, 0.0, 0.0]);
    assert_eq!(
        String::from_utf8_lossy(&o.stderr),
        "radius 2 2\nintegral 1\n"
    );
    let dir = temp_dir("new-filters");
    for spec in ["blackman-harris", "catmull-rom"] {
        let png = dir.join(format!("{spec}.png"));
        let o = nyquist(&["filter", "--filter", spec, "--plot", png.to_str().unwrap()]);
        assert!(o.status.success(), "{spec}");
        assert!(common::png_size(&png).0 > 0, "{spec}");
    }
}
