//! The checked-in shaders in `gpu/shaders/` are what `emit` writes today: a change to the WGSL
//! (or to naga) that is not regenerated fails here. Regenerate with
//! `cargo run -p nyquist-cli -- shaders -o gpu/shaders` (every language), or set
//! `NYQUIST_UPDATE_SHADERS=1` when running this test.

use std::path::Path;

use nyquist_gpu::{Language, emit};

#[test]
fn checked_in_shaders_are_current() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let update = std::env::var_os("NYQUIST_UPDATE_SHADERS").is_some();
    let mut stale = Vec::new();
    for language in Language::ALL {
        let want = emit(language).unwrap_or_else(|e| panic!("{}: {e}", language.name()));
        let path = dir.join(language.file_name());
        if update {
            std::fs::write(&path, &want).unwrap();
        }
        let have = std::fs::read(&path).unwrap_or_default();
        if have != want {
            stale.push(language.file_name());
        }
    }
    assert!(
        stale.is_empty(),
        "stale shaders in gpu/shaders: {stale:?}; regenerate with \
         `cargo run -p nyquist-cli -- shaders -o gpu/shaders`"
    );
}

#[test]
fn emission_is_deterministic_and_every_language_names_the_entry_point() {
    for language in Language::ALL {
        let a = emit(language).unwrap();
        assert_eq!(a, emit(language).unwrap(), "{}", language.name());
        if language != Language::SpirV {
            let text = String::from_utf8(a).unwrap();
            assert!(text.contains("nyq_fill"), "{}", language.name());
        } else {
            // SPIR-V's magic number, little-endian, and the entry point's name as a literal.
            assert_eq!(&a[..4], &0x0723_0203u32.to_le_bytes());
            assert!(a.windows(8).any(|w| w == b"nyq_fill"));
        }
    }
}

/// The costs table in docs/gpu.md is what `nyquist shaders --costs` prints today.
#[test]
fn docs_cost_table_is_current() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/gpu.md");
    let doc = std::fs::read_to_string(&path).unwrap();
    let (begin, end) = ("<!-- costs: begin -->\n", "<!-- costs: end -->");
    let start = doc.find(begin).expect("begin marker") + begin.len();
    let stop = doc.find(end).expect("end marker");
    let table = nyquist_gpu::costs::sampler_table().unwrap();
    if std::env::var_os("NYQUIST_UPDATE_SHADERS").is_some() {
        let updated = format!("{}{table}{}", &doc[..start], &doc[stop..]);
        std::fs::write(&path, updated).unwrap();
        return;
    }
    assert_eq!(
        &doc[start..stop],
        table,
        "docs/gpu.md's cost table is stale: NYQUIST_UPDATE_SHADERS=1 cargo test -p nyquist-gpu --test shaders"
    );
}
