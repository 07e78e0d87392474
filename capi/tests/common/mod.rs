//! Helpers shared by the capi test binaries.

use std::path::{Path, PathBuf};
use std::process::Command;

use nyquist::filter::Filter;

/// A C callback filter written again in Rust, as `nyq_filter_create_callback` sees it: `eval`
/// inside the support `[-radius, radius]²` (the only place the handle calls the callback),
/// 0 outside.
#[allow(dead_code)] // not every test binary tabulates a callback filter
pub struct Clipped {
    /// Half-width of the support on both axes, in pixels.
    pub radius: f32,
    /// The callback's formula.
    pub eval: fn(f32, f32) -> f32,
}

impl Filter for Clipped {
    fn radius(&self) -> [f32; 2] {
        [self.radius; 2]
    }
    fn eval(&self, x: f32, y: f32) -> f32 {
        if !(x.abs() <= self.radius && y.abs() <= self.radius) {
            return 0.0;
        }
        (self.eval)(x, y)
    }
}

/// The workspace's root folder.
#[allow(dead_code)] // not every test binary builds C
pub fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Builds the staticlib with the cargo running this test (same target directory, so
/// `CARGO_TARGET_DIR` is respected, and the test profile, which `cargo test` already built it
/// with) and returns the path cargo reports for it.
#[allow(dead_code)] // not every test binary builds C
pub fn staticlib() -> PathBuf {
    let out = Command::new(env!("CARGO"))
        .current_dir(workspace())
        .args([
            "build",
            "--profile",
            "test",
            "-p",
            "nyquist-capi",
            "--lib",
            "--message-format=json-render-diagnostics",
        ])
        .output()
        .expect("run cargo build -p nyquist-capi");
    assert!(
        out.status.success(),
        "cargo build -p nyquist-capi failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    for line in stdout.lines() {
        if !line.contains("\"compiler-artifact\"") || !line.contains("\"name\":\"nyquist_capi\"") {
            continue;
        }
        let Some(start) = line.find("\"filenames\":[") else {
            continue;
        };
        let rest = &line[start + "\"filenames\":[".len()..];
        let list = &rest[..rest.find(']').unwrap_or(rest.len())];
        for name in list.split(',') {
            let name = name.trim().trim_matches('"');
            if name.ends_with(".a") {
                return PathBuf::from(name);
            }
        }
    }
    panic!("cargo build -p nyquist-capi reported no .a artifact:\n{stdout}");
}
