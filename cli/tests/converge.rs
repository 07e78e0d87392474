//! End-to-end tests of `nyquist converge`.

mod common;

use common::{
    SMALL_STUDY, assert_one_line_error, files, json_field, nyquist, png_size, stdout, temp_dir,
};
use nyquist_lab::study::figure::plot_size;

#[test]
fn table_has_a_row_per_sampler_and_a_column_per_integrand() {
    let o = nyquist(&[
        "converge",
        "--samplers",
        "random,stratified",
        "--integrands",
        "disk,bilinear",
        "--max-spp",
        "256",
        "--runs",
        "16",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = stdout(&o);
    let table: Vec<&str> = s.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(table.len(), 4, "{s}");
    assert_eq!(table[0], "| sampler | disk | bilinear |");
    assert!(table[2].starts_with("| random | -0."), "{s}");
    assert!(table[3].starts_with("| stratified | -"), "{s}");
    assert!(s.contains("2 samplers × 5 N × 16 runs"), "{s}");
    assert!(s.contains("disk 0.500000, bilinear 0.250000"), "{s}");
}

#[test]
fn plot_is_a_valid_png_and_json_has_every_curve() {
    let dir = temp_dir("converge-plot");
    let out = dir.join("conv.png");
    let o = nyquist(
        &[
            &SMALL_STUDY[..],
            &["--json"],
            &["--plot", out.to_str().unwrap()],
        ]
        .concat(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j = stdout(&o);
    assert_eq!(j.lines().count(), 1);
    assert_eq!(j.matches("\"sampler\":").count(), 6);
    assert_eq!(j.matches("\"spp\":[4,8,16,32,64]").count(), 6);
    assert_eq!(json_field(&j, "runs"), 8.0);
    assert_eq!(
        json_field(&j, "samples"),
        f64::from(3 * 8 * (4 + 8 + 16 + 32 + 64))
    );
    // The PNG decodes, at the documented size.
    let [w, h] = plot_size(2);
    assert_eq!(png_size(&out), (w, h));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&out).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (w, h));
    assert!(buf[..info.buffer_size()].iter().any(|&b| b < 128));
    assert_eq!(files(&dir), ["conv.png"]);
    // Same flags, same numbers (the JSON differs only in its timing).
    let again = nyquist(&[&SMALL_STUDY[..], &["--json"], &["--threads", "1"]].concat());
    let curves = |s: &str| s[s.find("\"curves\"").unwrap()..].to_owned();
    assert_eq!(curves(&stdout(&again)), curves(&j));
}

#[test]
fn bad_flags_are_one_line_exit_2_and_write_nothing() {
    let dir = temp_dir("converge-bad");
    let plot = dir.join("p.png");
    let plot = plot.to_str().unwrap();
    for (args, mentions) in [
        (&["--samplers", "random,nope"][..], "--samplers nope"),
        (&["--samplers", "random,random"][..], "given twice"),
        (&["--integrands", "disk,cube"][..], "cube"),
        (&["--max-spp", "1000"][..], "--max-spp 1000"),
        (&["--min-spp", "0"][..], "--min-spp 0"),
        (
            &["--min-spp", "4096", "--max-spp", "16"][..],
            "two sample counts",
        ),
        (
            &["--min-spp", "64", "--max-spp", "64"][..],
            "two sample counts",
        ),
        (
            &["--max-spp", "2097152"][..],
            "--max-spp 2097152: not in 1 ..= 1048576",
        ),
        (&["--runs", "0"][..], "--runs"),
        (
            &["--max-spp", "1048576", "--runs", "100000"][..],
            "samples; at most",
        ),
        (
            &["--samplers", "best-candidate", "--max-spp", "8192"][..],
            "best-candidate at 8192",
        ),
        (&["--threads", "0"][..], "--threads"),
    ] {
        let mut all = vec!["converge", "--plot", plot];
        all.extend_from_slice(args);
        let o = nyquist(&all);
        assert_one_line_error(&o, mentions);
        assert!(files(&dir).is_empty(), "{args:?} left {:?}", files(&dir));
    }
    let o = nyquist(&["converge", "--plot", &dir.join("p.jpg").to_string_lossy()]);
    assert_one_line_error(&o, "--plot");
    let o = nyquist(&[
        "converge",
        "--plot",
        &dir.join("no/p.png").to_string_lossy(),
    ]);
    assert_one_line_error(&o, "does not exist");
    assert!(files(&dir).is_empty());
}

/// `--dims D` runs Genz's six families instead: one row per sampler, a slope and an error per
/// family; the flags of the 2-D study's outputs are refused, and D outside 2 … 64 too.
#[test]
fn dims_study_has_a_row_per_sampler_and_a_column_per_genz_family() {
    let o = nyquist(&[
        "converge",
        "--dims",
        "6",
        "--samplers",
        "random,owen-sobol,halton-plain",
        "--min-spp",
        "16",
        "--max-spp",
        "256",
        "--runs",
        "8",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = stdout(&o);
    let table: Vec<&str> = s.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(table.len(), 5, "{s}");
    assert_eq!(
        table[0],
        "| sampler | oscillatory | product-peak | corner-peak | gaussian | continuous | discontinuous |"
    );
    assert!(table[2].starts_with("| random | -0."), "{s}");
    assert!(s.contains("6 dimensions, 8 runs"), "{s}");
    for args in [
        &["converge", "--dims", "4", "--json"][..],
        &["converge", "--dims", "65"][..],
        &["converge", "--dims", "1"][..],
    ] {
        let o = nyquist(args);
        assert!(!o.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("--dims") || err.contains("--json"), "{err}");
    }
}

/// `--spp-hint H`: every sampler is made for H and draws each N. Owen-Sobol's samples do not
/// depend on its spp, so its curve is the one without the hint; ZSobol's past the hint come
/// from new epochs, which are not one net with the hint's own samples, so its error on the
/// smooth Gaussian falls more slowly than ZSobol made for each N. A sampler that wraps at
/// its spp is refused in one line.
#[test]
fn spp_hint_makes_the_samplers_for_the_hint_and_draws_past_it() {
    let run = |samplers: &str, hint: Option<&str>| -> String {
        let mut args = vec![
            "converge",
            "--samplers",
            samplers,
            "--integrands",
            "gaussian",
            "--min-spp",
            "16",
            "--max-spp",
            "1024",
            "--runs",
            "16",
            "--json",
        ];
        if let Some(h) = hint {
            args.extend(["--spp-hint", h]);
        }
        let o = nyquist(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        stdout(&o)
    };
    let curves = |s: &str| s[s.find("\"curves\"").unwrap()..].to_owned();
    let plain = run("owen-sobol", None);
    let hinted = run("owen-sobol", Some("16"));
    assert_eq!(curves(&plain), curves(&hinted));
    assert_eq!(json_field(&hinted, "spp_hint"), 16.0);
    assert!(plain.contains("\"spp_hint\":null,"), "{plain}");
    let slope = |s: &str| json_field(s, "slope");
    let made_for_each = slope(&run("zsobol", None));
    let past_the_hint = slope(&run("zsobol", Some("16")));
    assert!(made_for_each < -1.3, "{made_for_each}");
    assert!(
        (-1.2..-0.6).contains(&past_the_hint),
        "{past_the_hint} (made for each N: {made_for_each})"
    );
    let o = nyquist(&["converge", "--samplers", "zero-two", "--spp-hint", "16"]);
    assert_one_line_error(&o, "zero-two at 16 spp: made for 16, it wraps past its spp");
}
