//! The `zoneplate_scaling` example, whose stdout reader has gone away before it prints (as in
//! `… | head -0`), exits quietly with status 141 (128 + SIGPIPE) instead of panicking.

use std::path::Path;
use std::process::{Command, Stdio};

#[test]
fn zoneplate_scaling_exits_141_quietly_into_a_closed_pipe() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml");
    // Build first, so the closed pipe below meets the example and not cargo.
    let build = Command::new(env!("CARGO"))
        .args([
            "build",
            "--quiet",
            "--example",
            "zoneplate_scaling",
            "--manifest-path",
        ])
        .arg(&manifest)
        .status()
        .expect("run cargo build");
    assert!(build.success());
    let mut child = Command::new(env!("CARGO"))
        .args([
            "run",
            "--quiet",
            "--example",
            "zoneplate_scaling",
            "--manifest-path",
        ])
        .arg(&manifest)
        .args(["--", "--size", "16", "--spp", "1"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run the example");
    drop(child.stdout.take()); // the reader goes away before anything is printed
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(141),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
}
