//! Helpers shared by the CLI end-to-end tests.
#![allow(dead_code)] // each test binary uses a subset

use std::process::{Command, Output};

pub fn nyquist(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .output()
        .expect("run nyquist")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

pub fn rows(o: &Output) -> Vec<Vec<f32>> {
    stdout(o)
        .lines()
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// One line on stderr, exit status 2, nothing on stdout.
pub fn assert_one_line_error(o: &Output, mentions: &str) {
    let err = String::from_utf8(o.stderr.clone()).unwrap();
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert_eq!(err.lines().count(), 1, "not one line: {err:?}");
    assert!(
        err.contains(mentions),
        "{err:?} does not mention {mentions:?}"
    );
    assert!(o.stdout.is_empty());
}

/// The scratch-folder guard, shared with the film's tests.
#[path = "../../../std-film/tests/support/temp_dir.rs"]
mod temp;
pub use temp::TempDir;

/// A fresh empty folder under the system temp folder, unique to this test and process, removed
/// when the returned guard drops.
pub fn temp_dir(name: &str) -> TempDir {
    TempDir::new(&format!("nyquist-cli-{name}"))
}

/// Runs nyquist with its reference cache in `cache` (never the user's).
pub fn nyquist_cached(args: &[&str], cache: &std::path::Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(args)
        .env("XDG_CACHE_HOME", cache)
        .output()
        .expect("run nyquist")
}

/// Reads a little-endian colour PFM: (width, height, first channel row-major from the top row).
pub fn read_pfm(path: &std::path::Path) -> (usize, usize, Vec<f32>) {
    let bytes = std::fs::read(path).unwrap();
    let mut fields = Vec::new();
    let mut pos = 0;
    while fields.len() < 4 {
        while bytes[pos].is_ascii_whitespace() {
            pos += 1;
        }
        let start = pos;
        while !bytes[pos].is_ascii_whitespace() {
            pos += 1;
        }
        fields.push(String::from_utf8(bytes[start..pos].to_vec()).unwrap());
    }
    pos += 1;
    assert_eq!(fields[0], "PF");
    assert_eq!(fields[3], "-1.0", "little-endian");
    let (w, h): (usize, usize) = (fields[1].parse().unwrap(), fields[2].parse().unwrap());
    let data = &bytes[pos..];
    assert_eq!(data.len(), w * h * 12);
    let mut out = vec![0.0f32; w * h];
    for row in 0..h {
        let y = h - 1 - row; // bottom row first
        for x in 0..w {
            let o = (row * w + x) * 12;
            out[y * w + x] = f32::from_le_bytes(data[o..o + 4].try_into().unwrap());
        }
    }
    (w, h, out)
}

/// The number after `"key":` in a flat JSON object.
pub fn json_field(json: &str, key: &str) -> f64 {
    let pat = format!("\"{key}\":");
    let at = json.find(&pat).unwrap_or_else(|| panic!("{key} in {json}")) + pat.len();
    let rest = &json[at..];
    let end = rest.find([',', '}']).unwrap();
    rest[..end].trim().parse().unwrap()
}

/// Width and height from a PNG's IHDR chunk.
pub fn png_size(path: &std::path::Path) -> (u32, u32) {
    let b = std::fs::read(path).unwrap();
    assert_eq!(&b[1..4], b"PNG");
    (
        u32::from_be_bytes(b[16..20].try_into().unwrap()),
        u32::from_be_bytes(b[20..24].try_into().unwrap()),
    )
}

/// Files in `dir` (names), sorted.
pub fn files(dir: &std::path::Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// A small convergence study (3 samplers × 2 integrands, 4 … 64 spp, 8 runs), for the converge
/// and plot tests.
pub const SMALL_STUDY: [&str; 13] = [
    "converge",
    "--samplers",
    "random,sobol,zero-two",
    "--integrands",
    "step,gaussian",
    "--min-spp",
    "4",
    "--max-spp",
    "64",
    "--runs",
    "8",
    "--seed",
    "3",
];
