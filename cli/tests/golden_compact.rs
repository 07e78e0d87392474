//! The golden point-set hashes of `tests/golden/hashes.txt` (written by `nyquist points`, which
//! uses the table paths) recomputed from the compact const-generic types: the same CSV text,
//! the same FNV-1a 64, so the compact paths reproduce the golden outputs to the bit.

use nyquist::compact::{Halton, Sobol};
use nyquist::sequence::Sequence;
use std::fmt::Write;
use std::path::Path;

/// FNV-1a, 64-bit (as `golden.rs`).
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The golden hash of run `name`.
fn golden(name: &str) -> u64 {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden/hashes.txt");
    let text = std::fs::read_to_string(path).expect("hashes.txt");
    let hex = text
        .lines()
        .find_map(|l| l.strip_prefix(name)?.strip_prefix(' '))
        .unwrap_or_else(|| panic!("no golden hash for {name}"));
    u64::from_str_radix(hex.trim(), 16).unwrap()
}

/// What `nyquist points --format csv` prints for points `first .. first + count` of `set`'s
/// first `dims` dimensions.
fn csv(set: &impl Sequence, first: u64, count: u64, dims: u32) -> String {
    let mut out = String::new();
    for i in first..first + count {
        for d in 0..dims {
            let sep = if d > 0 { "," } else { "" };
            write!(out, "{sep}{}", set.sample(i, d)).unwrap();
        }
        out.push('\n');
    }
    out
}

#[test]
fn compact_point_sets_reproduce_the_golden_hashes() {
    let cases = [
        ("points/halton", csv(&Halton::<3>::new(), 0, 64, 3)),
        ("points/vdc", csv(&Halton::<1>::new(), 0, 64, 1)),
        ("points/sobol", csv(&Sobol::<3>::new(), 0, 64, 3)),
        ("points/sobol-skip-8d", csv(&Sobol::<8>::new(), 1000, 32, 8)),
    ];
    for (name, text) in cases {
        assert_eq!(
            fnv1a64(text.as_bytes()),
            golden(name),
            "{name}: the compact path's CSV hashes differently"
        );
    }
}
