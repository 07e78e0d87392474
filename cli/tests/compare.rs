//! End-to-end tests of `nyquist compare`.

mod common;

use nyquist_lab::raster::text_width;

use common::{
    assert_one_line_error, files, json_field, nyquist_cached, png_size, stdout, temp_dir,
};

#[test]
fn compare_writes_one_sheet_of_the_expected_size_and_one_json_entry_per_cell() {
    let dir = temp_dir("compare-json");
    let out = dir.join("sheet.png");
    let o = nyquist_cached(
        &[
            "compare",
            "--size",
            "40x40",
            "--samplers",
            "uniform,stratified,sobol",
            "--filters",
            "box,mitchell:b=0.5,c=0.25",
            "--spp",
            "1,4",
            "--json",
            "-o",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j = stdout(&o);
    assert_eq!(j.lines().count(), 1);
    // 3 samplers × 2 filters × 2 spp.
    assert_eq!(j.matches("\"sampler\":").count(), 12);
    assert_eq!(j.matches("\"rmse\":").count(), 12);
    assert_eq!(j.matches("\"sampling_rmse\":").count(), 12);
    assert!(j.contains("\"filter\":\"mitchell:b=0.5,c=0.25\""));
    // Geometry: crop 20×20; the widest label is "mitchell:b=0.5,c=0.25 4spp" in the embedded
    // font; cells that wide plus 8 across 4 columns, 20 + 5 + 3 lines + 8 down 3 rows, 2 title
    // lines.
    let (w, h) = png_size(&out);
    let (label, line) = (
        text_width("mitchell:b=0.5,c=0.25 4spp"),
        nyquist_lab::raster::LINE,
    );
    assert_eq!(
        (w, h),
        (
            8 + 4 * (label + 8),
            8 + 2 * line + 8 + 3 * (20 + 5 + 3 * line + 8)
        )
    );
    assert_eq!(json_field(&j, "width"), f64::from(w));
    assert_eq!(json_field(&j, "height"), f64::from(h));
    // Only the sheet was written (the zone plate's reference needs no cache).
    assert_eq!(files(&dir), ["sheet.png"]);
}

#[test]
fn markdown_table_has_a_row_per_sampler_and_a_column_per_filter_and_spp() {
    let dir = temp_dir("compare-md");
    let out = dir.join("c.png");
    let o = nyquist_cached(
        &[
            "compare",
            "--size",
            "32x32",
            "--samplers",
            "random,halton",
            "--spp",
            "1,4,16",
            "-o",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = stdout(&o);
    let table: Vec<&str> = s.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(table.len(), 4, "{s}");
    assert_eq!(
        table[0],
        "| sampler | box 1 | box 4 | box 16 | mitchell 1 | mitchell 4 | mitchell 16 |"
    );
    assert!(table[2].starts_with("| random |") && table[3].starts_with("| halton |"));
    // RMSE of box-filtered halton falls with spp; cells read "rmse (sampling rmse)".
    let e: Vec<f64> = table[3]
        .split('|')
        .skip(2)
        .take(3)
        .map(|v| v.split_whitespace().next().unwrap().parse().unwrap())
        .collect();
    assert!(e[0] > e[1] && e[1] > e[2], "{e:?}");
    assert!(out.exists());
}

#[test]
fn other_scenes_compare_against_their_cached_reference() {
    let dir = temp_dir("compare-edge");
    let out = dir.join("e.png");
    let o = nyquist_cached(
        &[
            "compare",
            "--scene",
            "edge",
            "--size",
            "24x24",
            "--samplers",
            "stratified",
            "--filters",
            "box",
            "--spp",
            "1,16",
            "--json",
            "-o",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(stdout(&o).matches("\"rmse\":").count(), 2);
    assert_eq!(files(&dir.join("nyquist")).len(), 1);
}

#[test]
fn bad_input_is_one_line_exit_2_and_writes_nothing() {
    let dir = temp_dir("compare-errors");
    let out = dir.join("c.png");
    let o = out.to_str().unwrap();
    let missing = dir.join("none/c.png");
    // In the temporary folder, so that the check for files left behind can see one.
    let jpg = dir.join("c.jpg");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--samplers", "uniform,nope"], "--samplers"),
        (
            vec!["--samplers", "best-candidate", "--spp", "1,5000"],
            "best-candidate",
        ),
        (vec!["--spp", "0"], "--spp"),
        (vec!["--spp", "4,x"], "--spp"),
        (vec!["--filters", "box,sinc"], "--filters"),
        (vec!["--filters", "box,,mitchell"], "--filters"),
        (vec!["--size", "3"], "--size"),
        (vec!["--scene", "nope"], "--scene"),
        (vec!["--threads", "0"], "--threads"),
        (vec!["--size", "4096x4096"], "--size 4096x4096 × 60 renders"),
        (vec!["-o", jpg.to_str().unwrap()], "--output"),
        (vec!["-o", missing.to_str().unwrap()], "--output"),
    ];
    for (args, mentions) in cases {
        let mut all = vec!["compare", "-o", o];
        all.extend_from_slice(&args);
        assert_one_line_error(&nyquist_cached(&all, &dir), mentions);
        assert!(files(&dir).is_empty(), "{args:?} left {:?}", files(&dir));
    }
}

#[test]
fn help_has_an_example() {
    let o = common::nyquist(&["compare", "--help"]);
    assert!(o.status.success());
    assert!(stdout(&o).contains("Example: nyquist compare"));
}
