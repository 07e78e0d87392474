//! Every subcommand's `--help` succeeds and shows an example.

mod common;

use common::{nyquist, stdout};

#[test]
fn every_subcommand_help_has_an_example() {
    for sub in [
        "points", "filter", "render", "compare", "analyze", "converge",
    ] {
        let o = nyquist(&[sub, "--help"]);
        assert!(o.status.success(), "{sub}");
        let s = stdout(&o);
        assert!(s.contains(&format!("Example: nyquist {sub}")), "{sub}: {s}");
    }
    let o = nyquist(&["--help"]);
    assert!(o.status.success());
    for sub in [
        "points", "filter", "render", "compare", "analyze", "converge",
    ] {
        assert!(stdout(&o).contains(sub));
    }
}

#[test]
fn unknown_subcommand_is_one_line_exit_2() {
    let o = nyquist(&["paint"]);
    common::assert_one_line_error(&o, "paint");
}

/// An unknown name is one line that lists what is allowed, for every enumerated flag.
#[test]
fn unknown_names_list_the_allowed_values() {
    let cases: [(&[&str], &[&str]); 5] = [
        (
            &["render", "--sampler", "nope"],
            &["--sampler", "owen-sobol", "zsobol", "pmj02", "halton"],
        ),
        (
            &["render", "--scene", "nope"],
            &["--scene", "zoneplate", "checkerboard", "stripes"],
        ),
        (
            &["render", "--filter", "sinc"],
            &["--filter", "box", "gaussian", "mitchell", "lanczos"],
        ),
        (
            &["points", "--sampler", "halton", "--format", "gif"],
            &["--format", "csv", "svg", "png"],
        ),
        (
            &["analyze", "--sampler", "halton", "--measures", "nope"],
            &["--measures", "star", "l2-star", "min-distance"],
        ),
    ];
    for (args, mentions) in cases {
        let o = nyquist(args);
        common::assert_one_line_error(&o, mentions[0]);
        let err = String::from_utf8_lossy(&o.stderr);
        for m in mentions {
            assert!(err.contains(m), "{args:?}: {err}");
        }
    }
}

/// The documented alternative spellings: `sobol-owen` names the Owen-scrambled Sobol sampler, and `analyze`
/// takes `--input FILE|-` and `--measure` as well as its positional file and `--measures`.
#[test]
fn design_spellings_are_accepted() {
    let a = nyquist(&["points", "--sampler", "sobol-owen", "--count", "8"]);
    let b = nyquist(&["points", "--sampler", "owen-sobol", "--count", "8"]);
    assert!(a.status.success() && a.stdout == b.stdout && !a.stdout.is_empty());
    let dir = std::env::temp_dir().join(format!("nyquist-design-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("h.csv");
    let pts = nyquist(&["points", "--sampler", "halton", "--count", "64"]);
    std::fs::write(&csv, &pts.stdout).unwrap();
    let csv = csv.to_str().unwrap();
    let flag = nyquist(&["analyze", "--input", csv, "--measure", "star", "--json"]);
    let positional = nyquist(&["analyze", csv, "--measures", "star", "--json"]);
    assert!(
        flag.status.success(),
        "{}",
        String::from_utf8_lossy(&flag.stderr)
    );
    let strip = |o: &std::process::Output| {
        let s = stdout(o);
        s[..s.find("\"seconds\"").unwrap()].to_string()
    };
    assert_eq!(strip(&flag), strip(&positional));
    // The expected D* from an independent brute force over the same points: every anchored box
    // [0, x) × [0, y) with x and y among the coordinates and 1, counted open and closed.
    let points: Vec<[f64; 2]> = String::from_utf8_lossy(&pts.stdout)
        .lines()
        .map(|l| {
            let (x, y) = l.split_once(',').unwrap();
            [x.parse().unwrap(), y.parse().unwrap()]
        })
        .collect();
    let n = points.len() as f64;
    let xs: Vec<f64> = points.iter().map(|p| p[0]).chain([1.0]).collect();
    let ys: Vec<f64> = points.iter().map(|p| p[1]).chain([1.0]).collect();
    let mut star = 0.0f64;
    for &x in &xs {
        for &y in &ys {
            let open = points.iter().filter(|p| p[0] < x && p[1] < y).count() as f64;
            let closed = points.iter().filter(|p| p[0] <= x && p[1] <= y).count() as f64;
            star = star.max(x * y - open / n).max(closed / n - x * y);
        }
    }
    let json = strip(&flag);
    let at = json.find("\"star\":").unwrap() + "\"star\":".len();
    let printed: f64 = json[at..]
        .split([',', '}'])
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        (printed - star).abs() < 1e-6,
        "analyze says {printed}, brute force {star}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
