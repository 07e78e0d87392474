//! The `zoneplate_scaling` example, whose stdout reader has gone away before it prints (as in
//! `… | head -0`), exits quietly with status 141 (128 + SIGPIPE) instead of panicking.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The example's binary: the one `cargo test` built beside this test (`target/<profile>/
/// examples/`), or, when only this test was built (`cargo test --test example_pipe`), one
/// built now. A nested `cargo build` of the package alone would compile the workspace again
/// with other features (some 30 s), so the first is preferred.
fn example_binary() -> PathBuf {
    let name = format!("zoneplate_scaling{}", std::env::consts::EXE_SUFFIX);
    let beside = std::env::current_exe()
        .ok()
        .and_then(|exe| Some(exe.parent()?.parent()?.join("examples").join(&name)));
    if let Some(path) = beside.filter(|p| p.exists()) {
        return path;
    }
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml");
    let out = Command::new(env!("CARGO"))
        .args(["build", "--quiet", "--example", "zoneplate_scaling"])
        .args(["--message-format", "json", "--manifest-path"])
        .arg(&manifest)
        .output()
        .expect("run cargo build");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The artifact message of the example names its executable.
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text
        .lines()
        .rfind(|l| l.contains("\"executable\":") && l.contains("zoneplate_scaling"))
        .expect("cargo reports the example's executable");
    let start = line.find("\"executable\":\"").expect("an executable path") + 14;
    let end = start + line[start..].find('"').expect("a closing quote");
    PathBuf::from(&line[start..end])
}

#[test]
fn zoneplate_scaling_exits_141_quietly_into_a_closed_pipe() {
    // The reader goes away before the example starts, so its first write meets a closed pipe.
    let (reader, writer) = std::io::pipe().expect("a pipe");
    drop(reader);
    let out = Command::new(example_binary())
        .args(["--size", "16", "--spp", "1"])
        .stdout(writer)
        .stderr(Stdio::piped())
        .output()
        .expect("run the example");
    assert_eq!(
        out.status.code(),
        Some(141),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
}
