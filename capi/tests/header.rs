//! The committed C header `capi/include/nyquist.h` is what cbindgen generates from the crate.
//!
//! `NYQUIST_BLESS=1 cargo test -p nyquist-capi --test header` rewrites it.

use std::path::Path;

fn generate() -> String {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config =
        cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("capi/cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut out = Vec::new();
    bindings.write(&mut out);
    strip_rust_examples(&String::from_utf8(out).expect("the header is UTF-8"))
}

/// Drops the doc comments' Rust examples (fenced ```` ``` ```` blocks, with the empty comment
/// line before each) from cbindgen's output: they are doctests for Rust callers, noise in a C
/// header. Everything else is cbindgen's output verbatim.
fn strip_rust_examples(header: &str) -> String {
    let mut out: Vec<&str> = Vec::new();
    let mut in_example = false;
    for line in header.lines() {
        let comment = line.trim_start().strip_prefix("//").map(str::trim);
        if comment.is_some_and(|c| c.starts_with("```")) {
            if !in_example && out.last().is_some_and(|l| l.trim() == "//") {
                out.pop();
            }
            in_example = !in_example;
            continue;
        }
        if !in_example {
            out.push(line);
        }
    }
    let mut text = out.join("\n");
    text.push('\n');
    text
}

#[test]
fn header_is_current() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("include/nyquist.h");
    let fresh = generate();
    if std::env::var_os("NYQUIST_BLESS").is_some_and(|v| v == "1") {
        std::fs::write(&path, &fresh).expect("write capi/include/nyquist.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    if committed == fresh {
        return;
    }
    let (old, new): (Vec<&str>, Vec<&str>) = (committed.lines().collect(), fresh.lines().collect());
    let first = old
        .iter()
        .zip(&new)
        .position(|(a, b)| a != b)
        .unwrap_or(old.len().min(new.len()));
    let mut diff = String::new();
    for i in first..(first + 8) {
        match (old.get(i), new.get(i)) {
            (Some(a), Some(b)) if a == b => diff.push_str(&format!("  {:>5} {a}\n", i + 1)),
            (a, b) => {
                if let Some(a) = a {
                    diff.push_str(&format!("- {:>5} {a}\n", i + 1));
                }
                if let Some(b) = b {
                    diff.push_str(&format!("+ {:>5} {b}\n", i + 1));
                }
            }
        }
    }
    panic!(
        "capi/include/nyquist.h is stale: it differs from what cbindgen generates from capi/src \
         (committed {} lines, generated {} lines), first difference at line {}:\n{diff}\
         Regenerate it with `NYQUIST_BLESS=1 cargo test -p nyquist-capi --test header` and commit it.",
        old.len(),
        new.len(),
        first + 1
    );
}

#[test]
fn header_declares_every_entry_point() {
    let header = generate();
    for name in [
        "nyq_status_message",
        "nyq_radical_inverse",
        "nyq_scrambled_radical_inverse_f64",
        "nyq_sequence_sample",
        "nyq_sequence_fill",
        "nyq_stratified_2d",
        "nyq_latin_hypercube",
        "nyq_shuffle",
        "nyq_sampler_create",
        "nyq_sampler_get_pixel_2d",
        "nyq_filter_create_callback",
        "nyq_filter_lookup",
        "nyq_filter_sample",
    ] {
        assert!(
            header.contains(&format!("{name}(")),
            "{name} missing from the header"
        );
    }
    for item in [
        "NYQ_OK = 0",
        "NYQ_ERR_PARSE = 7",
        "typedef struct NyqSampler NyqSampler",
        "NYQ_SEQ_SOBOL = 5",
        "#define NYQ_FILTER_TABLE_SIZE 16",
    ] {
        assert!(header.contains(item), "{item} missing from the header");
    }
}
