//! The user docs agree with the code they describe: ranges in `docs/cli.md` with the flags'
//! parsers, the `filter --format csv` summary with what it prints, the crate features named in
//! `docs/embedded.md` with `core/Cargo.toml`, and one name for the Sobol direction numbers.

mod common;

use common::nyquist;

fn repo_file(path: &str) -> String {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    std::fs::read_to_string(format!("{root}/{path}")).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn dims_ranges_in_cli_md_are_the_parsers_ranges() {
    let doc = repo_file("docs/cli.md");
    let mut checked = 0;
    // Every "`nyquist CMD --dims D` (A … B)" in the page.
    for (at, _) in doc.match_indices("--dims D` (") {
        let head = &doc[..at];
        let cmd = head[head.rfind("`nyquist ").expect("a command before --dims") + 9..]
            .split_whitespace()
            .next()
            .unwrap();
        let range = &doc[at + "--dims D` (".len()..];
        let range = &range[..range.find(')').unwrap()];
        let (lo, hi) = range.split_once(" … ").expect("A … B");
        let (lo, hi): (u32, u32) = (lo.parse().unwrap(), hi.parse().unwrap());
        // The parser's refusal gives its range; the doc's must be the same.
        let o = nyquist(&[cmd, "--dims", &(hi + 1).to_string()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains(&format!("not in {lo} ..= {hi}")),
            "docs/cli.md says {cmd} --dims ({lo} … {hi}); the command says {err}"
        );
        checked += 1;
    }
    assert!(checked > 0, "no --dims range found in docs/cli.md");
}

#[test]
fn filter_csv_summary_is_the_two_lines_the_docs_name() {
    let o = nyquist(&["filter", "--filter", "box", "--format", "csv"]);
    assert!(o.status.success());
    assert_eq!(
        String::from_utf8_lossy(&o.stderr),
        "radius 0.5 0.5\nintegral 1\n"
    );
    let doc = repo_file("docs/cli.md");
    assert!(doc.contains("`radius <rx> <ry>` and `integral <value>`"));
}

#[test]
fn embedded_md_names_every_core_feature() {
    let manifest = repo_file("core/Cargo.toml");
    let features = &manifest[manifest.find("[features]").unwrap()..];
    let features = &features[..features[1..].find("\n[").map_or(features.len(), |i| i + 1)];
    let names: Vec<&str> = features
        .lines()
        .filter_map(|l| l.split_once(" = ").map(|(k, _)| k.trim()))
        .filter(|k| !k.starts_with('#'))
        .collect();
    assert!(!names.is_empty());
    let doc = repo_file("docs/embedded.md");
    for name in names {
        assert!(
            doc.contains(&format!("`{name}`")),
            "docs/embedded.md omits the feature {name}"
        );
    }
    assert!(!doc.contains("the crate has none"));
}

#[test]
fn the_sobol_direction_numbers_have_one_name() {
    for path in ["core/src/lib.rs", "docs/design.md", "scripts/gen_sobol.py"] {
        let text = repo_file(path);
        assert!(
            text.contains("new-joe-kuo-6.1024.txt") && text.contains("new-joe-kuo-6.21201"),
            "{path} should name the data file and the table it is cut from"
        );
    }
}
