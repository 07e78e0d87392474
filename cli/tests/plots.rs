//! End-to-end tests of the plots (`converge --plot`, `filter --plot`, `analyze --spectrum`):
//! the format follows the extension, the same command gives the same bytes, an SVG has the
//! expected structure, and an unknown extension is refused before any file is written.

mod common;

use common::{SMALL_STUDY as STUDY, assert_one_line_error, files, nyquist, png_size, temp_dir};
use std::path::Path;

/// Runs `args` with `flag out` appended and returns the file's bytes.
fn plot(args: &[&str], flag: &str, out: &Path) -> Vec<u8> {
    let mut all = args.to_vec();
    all.extend([flag, out.to_str().unwrap()]);
    let o = nyquist(&all);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::read(out).unwrap()
}

/// Every command that plots, with its flag.
fn commands() -> Vec<(Vec<&'static str>, &'static str)> {
    vec![
        (STUDY.to_vec(), "--plot"),
        (vec!["filter", "--filter", "mitchell"], "--plot"),
        (
            vec![
                "analyze",
                "--sampler",
                "stratified",
                "--count",
                "256",
                "--freq",
                "16",
                "--realisations",
                "2",
            ],
            "--spectrum",
        ),
    ]
}

#[test]
fn the_same_command_writes_the_same_bytes_in_png_and_svg() {
    let dir = temp_dir("plots-determinism");
    for (k, (args, flag)) in commands().into_iter().enumerate() {
        for ext in ["png", "svg"] {
            let a = plot(&args, flag, &dir.join(format!("{k}a.{ext}")));
            let b = plot(&args, flag, &dir.join(format!("{k}b.{ext}")));
            assert!(a == b, "{args:?} {ext}: two runs differ");
            if ext == "png" {
                assert!(a.starts_with(b"\x89PNG\r\n\x1a\n"), "{args:?}");
            } else {
                let s = String::from_utf8(a).unwrap();
                assert!(s.starts_with("<svg") && s.trim_end().ends_with("</svg>"));
            }
        }
    }
    // Only the plots: no temporary file left behind.
    assert_eq!(files(&dir).len(), 12);
}

/// The attribute `name` of every `<tag …>` element of `svg`.
fn elements<'a>(svg: &'a str, tag: &str) -> Vec<&'a str> {
    svg.split(&format!("<{tag} "))
        .skip(1)
        .map(|rest| &rest[..rest.find('>').unwrap_or(rest.len())])
        .collect()
}

#[test]
fn converge_svg_has_a_curve_per_sampler_and_integrand_and_the_command_as_title() {
    let dir = temp_dir("plots-converge-svg");
    let svg = String::from_utf8(plot(&STUDY, "--plot", &dir.join("c.svg"))).unwrap();
    let (w, h) = {
        let [w, h] = nyquist_lab::study::figure::plot_size(2);
        (w, h)
    };
    assert!(svg.starts_with(&format!(
        "<svg width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\""
    )));
    // The title names the command with every flag.
    assert!(svg.contains(
        ">\nnyquist converge --samplers random,sobol,zero-two --integrands step,gaussian \
         --min-spp 4 --max-spp 64 --runs 8 --seed 3\n</text>"
    ));
    // One 2-pixel line per curve and one per legend swatch: 3 samplers × 2 panels each, in
    // the samplers' colours.
    let thick: Vec<&str> = elements(&svg, "polyline")
        .into_iter()
        .filter(|e| e.contains("stroke-width=\"2\""))
        .collect();
    assert_eq!(thick.len(), 2 * 3 * 2);
    for colour in ["#1F77B4", "#FF7F0E", "#2CA02C"] {
        let n = thick.iter().filter(|e| e.contains(colour)).count();
        assert_eq!(n, 2 * 2, "{colour}");
    }
    // Curves have a point per sample count (4, 8, …, 64).
    assert!(thick.iter().filter(|e| e.matches(',').count() == 5).count() >= 6);
    // Panel captions, legend names, decade labels, text in the embedded font's family.
    for text in [
        "step: 1 where x &lt; 1/π",
        "gaussian: exp(−x² − y²)",
        "zero-two",
        "10⁻¹",
    ] {
        assert!(svg.contains(text), "{text}");
    }
    assert!(
        elements(&svg, "text")
            .iter()
            .all(|e| e.contains("font-family=\"DejaVu Sans\""))
    );
}

#[test]
fn filter_and_spectrum_svgs_have_their_curves_and_titles() {
    let dir = temp_dir("plots-svgs");
    let svg = String::from_utf8(plot(
        &["filter", "--filter", "gaussian"],
        "--plot",
        &dir.join("f.svg"),
    ))
    .unwrap();
    assert!(svg.contains(">\nnyquist filter --filter gaussian:rx=2,ry=2,alpha=2\n</text>"));
    let curves = elements(&svg, "polyline")
        .into_iter()
        .filter(|e| e.contains("stroke-width=\"2\""))
        .count();
    assert_eq!(curves, 2, "profile and frequency response");
    assert!(svg.contains("Nyquist ν = ½"));

    let args = commands().remove(2).0;
    let svg = String::from_utf8(plot(&args, "--spectrum", &dir.join("s.svg"))).unwrap();
    assert!(svg.contains(
        ">\nnyquist analyze --sampler stratified --count 256 --dims 2 --seed 0 --freq 16 \
         --realisations 2\n</text>"
    ));
    // The periodogram and its scale bar as PNG images under the drawing, one radial curve.
    let images = elements(&svg, "image");
    assert_eq!(images.len(), 2);
    assert!(
        images
            .iter()
            .all(|e| e.contains("href=\"data:image/png;base64,iVBOR"))
    );
    assert!(svg.find("<image").unwrap() < svg.find("<text").unwrap());
    let curves = elements(&svg, "polyline")
        .into_iter()
        .filter(|e| e.contains("stroke-width=\"2\""))
        .count();
    assert_eq!(curves, 1);
    // The PNG has the documented size.
    let png = dir.join("s.png");
    plot(&args, "--spectrum", &png);
    assert_eq!(
        png_size(&png),
        (
            nyquist_cli::analyze::SPECTRUM_WIDTH,
            nyquist_cli::analyze::SPECTRUM_HEIGHT
        )
    );
}

#[test]
fn unknown_extensions_are_one_line_exit_2_and_leave_no_file() {
    let dir = temp_dir("plots-bad-extension");
    for (args, flag) in commands() {
        for name in ["p.jpg", "p.pdf", "p", "p.svg.txt"] {
            let mut all = args.clone();
            let out = dir.join(name);
            all.extend([flag, out.to_str().unwrap()]);
            let o = nyquist(&all);
            assert_one_line_error(&o, flag);
            let err = String::from_utf8_lossy(&o.stderr);
            assert!(err.contains(".png, .svg"), "{err}");
            assert!(files(&dir).is_empty(), "{all:?} left {:?}", files(&dir));
        }
    }
}
