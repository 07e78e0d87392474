//! Compiles the peers' own source files, with the shims in `shims/` that call them, for every
//! peer whose snapshot variable is set (`NYQUIST_OPENQMC`, `NYQUIST_PBRT_V4`, `NYQUIST_PBRT_V3`:
//! the root of an extracted source tree). A peer whose variable is unset is not built; the
//! benchmark then prints its rows as skipped. Each built peer sets `cfg(peer_NAME)`.
//!
//! Flags: the system C++ compiler (or `CXX`), `-std=c++17 -O3 -march=x86-64-v2 -DNDEBUG`, as a
//! release build of each peer; `CXX` and `CXXFLAGS` are read as the `cc` crate reads them.

use std::path::{Path, PathBuf};
use std::process::Command;

const FLAGS: &[&str] = &["-std=c++17", "-O3", "-march=x86-64-v2", "-DNDEBUG"];

fn main() {
    println!("cargo:rerun-if-changed=shims");
    println!("cargo:rerun-if-changed=build.rs");
    for cfg in [
        "peer_openqmc",
        "peer_pbrt_v4",
        "peer_pbrt_v4_substitute_tables",
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
    if let Some(root) = snapshot("NYQUIST_PBRT_V4", "src/pbrt/samplers.h") {
        pbrt_v4(&root, &mut built);
    }
    if let Some(root) = snapshot("NYQUIST_PBRT_V3", "src/core/film.h") {
        pbrt_v3(&root, &mut built);
    }
    for cfg in built {
        println!("cargo:rustc-cfg={cfg}");
    }
}

/// pbrt-v4: the shim, the source files that define what its samplers and Sobol tables call
/// (samplers.cpp for the `HaltonSampler` constructor, the Sobol and prime tables, the digit
/// permutations, checks, logging and printing), with the definitions pbrt-v4's CMake build sets
/// on Linux. `samplers.cpp` includes media.h, which needs NanoVDB's headers, and print.cpp
/// needs double-conversion: both from the snapshot's `src/ext` submodules when they are
/// checked out, otherwise from the system (Debian: libnanovdb-dev, libdouble-conversion-dev).
/// PMJ02BNSampler needs the data files `src/pbrt/util/pmj02tables.cpp` and `bluenoise.cpp`;
/// where a snapshot lacks them (pbrt-v4 keeps them in Git LFS, so a plain archive holds pointer
/// files), [`substitute_tables`] writes tables of the same shapes and the rows say so.
fn pbrt_v4(root: &Path, built: &mut Vec<&str>) {
    let src = root.join("src");
    let mut b = cxx();
    b.include(&src).include(src.join("ext"));
    let nanovdb = src.join("ext/openvdb/nanovdb");
    if nanovdb.join("nanovdb/NanoVDB.h").is_file() {
        b.include(nanovdb);
    }
    for d in [
        "PBRT_IS_LINUX",
        "PBRT_HAVE_MMAP",
        "PBRT_HAVE_POSIX_MEMALIGN",
        "PBRT_NOINLINE=__attribute__((noinline))",
        "PBRT_RESTRICT=__restrict__",
    ] {
        define(&mut b, d);
    }
    // pbrt-v3 and pbrt-v4 both use the namespace `pbrt`, with different definitions under the
    // same names (Primes, RadicalInverse, Point2…): each is compiled in its own namespace so
    // that the linker cannot mix them. (`#include <pbrt/…>` is not macro-expanded.)
    b.define("pbrt", "pbrt_v4");
    b.file("shims/pbrt_v4.cpp");
    for f in [
        "samplers.cpp",
        "util/lowdiscrepancy.cpp",
        "util/sobolmatrices.cpp",
        "util/primes.cpp",
        "util/check.cpp",
        "util/error.cpp",
        "util/log.cpp",
        "util/print.cpp",
        "util/pstd.cpp",
    ] {
        b.file(src.join("pbrt").join(f));
    }
    let tables = ["util/pmj02tables.cpp", "util/bluenoise.cpp"].map(|f| src.join("pbrt").join(f));
    if let Some(missing) = tables.iter().find(|f| !holds_source(f)) {
        println!(
            "cargo:warning=pbrt-v4: {} is missing or a Git LFS pointer; its PMJ02BNSampler rows \
             run on substitute tables of the same shapes",
            missing.display()
        );
        b.file(substitute_tables());
        built.push("peer_pbrt_v4_substitute_tables");
    } else {
        b.files(&tables);
    }
    let dc = src.join("ext/double-conversion");
    if dc.join("double-conversion/double-conversion.h").is_file() {
        b.include(&dc);
        for f in std::fs::read_dir(dc.join("double-conversion")).unwrap() {
            let f = f.unwrap().path();
            if f.extension().is_some_and(|e| e == "cc") {
                b.file(f);
            }
        }
    } else {
        println!("cargo:rustc-link-lib=double-conversion");
    }
    b.compile("peer_pbrt_v4");
    built.push("peer_pbrt_v4");
}

/// pbrt-v3: the shim and the source files of the film, the filters, the radical inverse and
/// what they call, with
/// the definitions pbrt-v3's CMake build sets for GCC on Linux. pbrt-v3 includes
/// `<glog/logging.h>`; `shims/glog-stub` stands in for it (CHECKs abort, DCHECKs compile out
/// under NDEBUG as in glog, logging is discarded).
fn pbrt_v3(root: &Path, built: &mut Vec<&str>) {
    let src = root.join("src");
    let mut b = cxx();
    b.include("shims/glog-stub")
        .include(&src)
        .include(src.join("core"));
    for d in [
        "PBRT_HAVE_ALLOCA_H",
        "PBRT_HAVE_MEMORY_H",
        "PBRT_HAVE_HEX_FP_CONSTANTS",
        "PBRT_HAVE_BINARY_CONSTANTS",
        "PBRT_HAVE_CONSTEXPR",
        "PBRT_CONSTEXPR=constexpr",
        "PBRT_HAVE_ALIGNAS",
        "PBRT_HAVE_ALIGNOF",
        "PBRT_HAVE_ITIMER",
        "PBRT_HAVE_NONPOD_IN_UNIONS",
        "PBRT_HAVE_MMAP",
        "PBRT_HAVE_POSIX_MEMALIGN",
        "PBRT_THREAD_LOCAL=thread_local",
        "PBRT_NOINLINE=__attribute__((noinline))",
    ] {
        define(&mut b, d);
    }
    // Its own namespace, as for pbrt-v4.
    b.define("pbrt", "pbrt_v3");
    b.file("shims/pbrt_v3.cpp");
    for f in [
        "core/film.cpp",
        "core/filter.cpp",
        "core/lowdiscrepancy.cpp",
        "core/stats.cpp",
        "core/spectrum.cpp",
        "core/error.cpp",
        "core/parallel.cpp",
        "filters/mitchell.cpp",
        "filters/box.cpp",
        "filters/sinc.cpp",
    ] {
        b.file(src.join(f));
    }
    b.compile("peer_pbrt_v3");
    built.push("peer_pbrt_v3");
}

/// Whether `f` is a source file rather than absent or a Git LFS pointer (a short text file that
/// starts `version https://git-lfs`).
fn holds_source(f: &Path) -> bool {
    std::fs::read(f).is_ok_and(|bytes| !bytes.starts_with(b"version https://git-lfs"))
}

/// Writes, into `OUT_DIR`, definitions of pbrt-v4's `pmj02bnSamples` (5 sets of 2¹⁶ points) and
/// `BlueNoiseTextures` (48 textures of 128 × 128) for snapshots without their data files: the
/// sets are nyquist's own PMJ(0,2) construction (`pmj02_build`, set 0 from the seed of
/// nyquist's table, so it is that table), which keeps the properties the sampler's constructor
/// checks (16 points in each 1/64 × 1/64 square); the textures are white noise from a
/// SplitMix64 stream, not blue. pbrt-v4's code reads them at the same addresses whatever they
/// hold, so its time is the same; its values are not pbrt-v4's.
fn substitute_tables() -> PathBuf {
    use std::fmt::Write;
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"))
        .join("pbrt_v4_substitute_tables.cpp");
    let mut s = String::with_capacity(16 << 20);
    s.push_str(
        "// Generated by peers/build.rs: pbrt-v4's table shapes with substitute data.\n\
         #include <pbrt/util/bluenoise.h>\n#include <pbrt/util/pmj02tables.h>\n\
         namespace pbrt {\n\
         PBRT_CONST uint32_t pmj02bnSamples[nPMJ02bnSets][nPMJ02bnSamples][2] = {\n",
    );
    let mut points = vec![[0u32; 2]; nyquist::sequence::PMJ02_MAX_POINTS];
    for set in 0..5u32 {
        let seed = nyquist::sequence::PMJ02_TABLE_SEED.wrapping_add(set);
        nyquist::sequence::pmj02_build(seed, &mut points).expect("a 2^16-point buffer");
        s.push('{');
        for [x, y] in &points {
            write!(s, "{{{x:#x},{y:#x}}},").unwrap();
        }
        s.push_str("},\n");
    }
    s.push_str(
        "};\nPBRT_CONST uint16_t BlueNoiseTextures[NumBlueNoiseTextures][BlueNoiseResolution]\
         [BlueNoiseResolution] = {\n",
    );
    let mut state = 0x626c_7565_6e6f_6973u64; // "bluenois"
    for _ in 0..48 {
        s.push('{');
        for _ in 0..128 {
            s.push('{');
            for _ in 0..128 {
                // SplitMix64 (Steele, Lea & Flood 2014), top 16 bits.
                state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
                let mut z = state;
                z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
                write!(s, "{},", (z ^ (z >> 31)) >> 48).unwrap();
            }
            s.push_str("},");
        }
        s.push_str("},\n");
    }
    s.push_str("};\n}  // namespace pbrt\n");
    std::fs::write(&out, s).expect("write the substitute tables into OUT_DIR");
    out
}

/// Adds `NAME` or `NAME=VALUE` to the build's definitions.
fn define(b: &mut cc::Build, d: &str) {
    match d.split_once('=') {
        Some((k, v)) => b.define(k, v),
        None => b.define(d, None),
    };
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
