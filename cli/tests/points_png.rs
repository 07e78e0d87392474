//! End-to-end tests of `nyquist points --format png`.

mod common;

use common::{assert_one_line_error, files, nyquist, png_size, temp_dir};

#[test]
fn png_pictures_have_the_svg_geometry() {
    let dir = temp_dir("points-png");
    for (args, name) in [
        (vec!["--sampler", "stratified", "--count", "16"], "s.png"),
        (vec!["--sampler", "best-candidate", "--spp", "64"], "b.png"),
        (
            vec!["--sampler", "vdc", "--count", "8", "--dims", "1"],
            "v.png",
        ),
    ] {
        let out = dir.join(name);
        let mut all = vec!["points", "--format", "png", "-o", out.to_str().unwrap()];
        all.extend_from_slice(&args);
        let o = nyquist(&all);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(o.stdout.is_empty());
        // 512 + 2·16 square, one 16-pixel text line under it.
        assert_eq!(png_size(&out), (544, 560));
    }
}

#[test]
fn png_needs_a_png_output_and_leaves_nothing_on_error() {
    let dir = temp_dir("points-png-errors");
    assert_one_line_error(&nyquist(&["points", "--format", "png"]), "--output");
    let svg = dir.join("x.svg");
    assert_one_line_error(
        &nyquist(&["points", "--format", "png", "-o", svg.to_str().unwrap()]),
        "--output",
    );
    let missing = dir.join("a/b.png");
    assert_one_line_error(
        &nyquist(&["points", "--format", "png", "-o", missing.to_str().unwrap()]),
        "--output",
    );
    let out = dir.join("x.png");
    assert_one_line_error(
        &nyquist(&[
            "points",
            "--format",
            "png",
            "--sampler",
            "stratified",
            "--count",
            "8",
            "-o",
            out.to_str().unwrap(),
        ]),
        "--count 8 is not a square",
    );
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
}
