//! Compiles the peers' own source files, with the shims in `shims/` that call them, for every
//! peer whose snapshot variable is set (`NYQUIST_OPENQMC`, `NYQUIST_PBRT_V4`, `NYQUIST_PBRT_V3`:
//! the root of an extracted source tree). A peer whose variable is unset is not built; the
//! benchmark then prints its rows as skipped. Each built peer sets `cfg(peer_NAME)`.
//!
//! Flags: the system C++ compiler (or `CXX`), `-std=c++17 -O3 -march=x86-64-v2 -DNDEBUG`, as a
//! release build of each peer; `CXXFLAGS` is appended by the `cc` crate.

use std::path::{Path, PathBuf};
use std::process::Command;

const FLAGS: &[&str] = &["-std=c++17", "-O3", "-march=x86-64-v2", "-DNDEBUG"];

fn main() {
    println!("cargo:rerun-if-changed=shims");
    println!("cargo:rerun-if-changed=build.rs");
    for cfg in [
        "peer_openqmc",
        "peer_pbrt_v4",
        "peer_pbrt_v4_pmj02bn",
        "peer_pbrt_v3",
    ] {
        println!("cargo:rustc-check-cfg=cfg({cfg})");
    }
    let compiler = cxx().get_compiler();
    let version = Command::new(compiler.path())
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .and_then(|s| s.lines().next().map(str::to_owned))
        .unwrap_or_else(|| compiler.path().display().to_string());
    println!("cargo:rustc-env=PEERS_CXX={version}");
    println!("cargo:rustc-env=PEERS_CXX_FLAGS={}", FLAGS.join(" "));

    let mut built = Vec::new();
    if let Some(root) = snapshot("NYQUIST_OPENQMC", "include/oqmc/oqmc.h") {
        cxx()
            .include(root.join("include"))
            .file("shims/openqmc.cpp")
            .compile("peer_openqmc");
        built.push("peer_openqmc");
    }
    for cfg in built {
        println!("cargo:rustc-cfg={cfg}");
    }
}

/// A C++ build with the peers' flags (the `cc` crate's own optimisation flags replaced).
fn cxx() -> cc::Build {
    let mut b = cc::Build::new();
    b.cpp(true).opt_level(3).debug(false).warnings(false);
    for f in FLAGS {
        b.flag(f);
    }
    b
}

/// The snapshot root named by `var`, if set; a set variable must name a tree holding `probe`.
fn snapshot(var: &str, probe: &str) -> Option<PathBuf> {
    println!("cargo:rerun-if-env-changed={var}");
    let root = PathBuf::from(std::env::var_os(var).filter(|v| !v.is_empty())?);
    assert!(
        root.join(probe).is_file(),
        "{var}={} does not hold {probe}: point it at the root of the peer's source tree \
         (peers/fetch-snapshots.sh extracts one)",
        root.display()
    );
    println!(
        "cargo:rerun-if-changed={}",
        Path::new(&root).join(probe).display()
    );
    Some(root)
}
