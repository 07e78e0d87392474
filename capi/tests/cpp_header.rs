//! The C++ header `gpu/cpp/nyquist.hpp` against the core, bit for bit.
//!
//! `gpu/cpp/parity.cpp` is compiled with `g++` and with `clang++` (`-std=c++17 -O2 -Wall
//! -Wextra -Werror -Wconversion`; a compiler that is not installed is skipped with a printed
//! `SKIPPED: …`), linked with the static library, and run. It compares the header with the C
//! API over random (pixel, sample index, dimension, seed) queries, and with the values this
//! test writes from the core for what the C API cannot name (other scrambles, animation
//! frames, the Owen-Sobol sequence). Every sampler family gets at least 10⁶ values. The
//! blue-noise samplers read their tiles through the C API's `nyq_blue_tile`.
//!
//! A second test holds the header's generated block (the Joe–Kuo parameters) to the data file.

mod common;

use common::{staticlib, workspace};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use nyquist::sampler::{
    HaltonSampler, LatticeBlueSampler, OwenSobolBlueSampler, OwenSobolSampler, Pmj02BlueSampler,
    Sampler, SobolSampler, ZSobolSampler, camera_sample,
};
use nyquist::scramble::Scramble;
use nyquist::sequence::{OwenSobol, Pmj02, Sequence};

/// SplitMix64, the queries' source.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: u32) -> u32 {
        ((self.next() >> 32) % u64::from(n)) as u32
    }
}

/// (pixel x, pixel y, sample index, dimension): pixels small, medium or anywhere in `u32`;
/// indices inside spp, past it, below 2¹⁶ or anywhere; dimensions mostly small, some past
/// 1024, some next to `u32::MAX` (where the cursor wraps).
fn draw(r: &mut Rng, spp: u32) -> [u32; 4] {
    let pick = r.next() as u32;
    let size = [64u32, 4096, 0][(pick % 3) as usize];
    let coordinate = |r: &mut Rng| {
        if size == 0 {
            r.next() as u32
        } else {
            r.below(size)
        }
    };
    let (px, py) = (coordinate(r), coordinate(r));
    let index = match (pick >> 8) & 3 {
        0 => r.below(spp),
        1 => r.below(spp.saturating_mul(4)),
        2 => r.below(65536),
        _ => r.next() as u32,
    };
    let dim = match (pick >> 16) & 7 {
        0..=3 => r.below(8),
        4 | 5 => r.below(64),
        6 => r.below(2100),
        _ => u32::MAX - r.below(4),
    };
    [px, py, index, dim]
}

/// The 14 values `parity.cpp` reads per query (its `header_values`).
fn values<S: Sampler>(s: &mut S, [px, py, index, dim]: [u32; 4]) -> [f32; 14] {
    s.start_pixel_sample([px, py], index, dim);
    let a = s.get_1d();
    let b = s.get_2d();
    let c = s.get_pixel_2d();
    let d = s.get_1d();
    let e = s.get_2d();
    let cs = camera_sample(s, [px, py], index);
    let f = s.get_1d();
    [
        a,
        b[0],
        b[1],
        c[0],
        c[1],
        d,
        e[0],
        e[1],
        cs.p_film[0],
        cs.p_film[1],
        cs.time,
        cs.lens[0],
        cs.lens[1],
        f,
    ]
}

/// The expected file: per configuration a header (kind, scramble, width, height, spp, frame,
/// dims as `u32`, seed as `u64`, record count as `u32`), then its records, little-endian.
struct Expected {
    bytes: Vec<u8>,
    values: u64,
}

impl Expected {
    fn u32(&mut self, v: u32) {
        self.bytes.extend_from_slice(&v.to_le_bytes());
    }
    fn f32s(&mut self, v: &[f32]) {
        for x in v {
            self.u32(x.to_bits());
        }
        self.values += v.len() as u64;
    }
    #[allow(clippy::too_many_arguments)]
    fn config(
        &mut self,
        kind: u32,
        scramble: Scramble,
        size: [u32; 2],
        spp: u32,
        frame: u32,
        dims: u32,
        seed: u64,
        count: u32,
    ) {
        let scramble = Scramble::ALL.iter().position(|&s| s == scramble).unwrap() as u32;
        for v in [kind, scramble, size[0], size[1], spp, frame, dims] {
            self.u32(v);
        }
        self.bytes.extend_from_slice(&seed.to_le_bytes());
        self.u32(count);
    }
    /// `queries` drawn queries of `s` and its values. `index_below` and `dims_below` keep the
    /// queries where the header follows the core (`docs/c.md`): the header's samplers wrap
    /// past the spp they were made for and past 1024 dimensions, where the core's continue
    /// progressively and pad.
    fn sampler<S: Sampler>(
        &mut self,
        s: &mut S,
        queries: u32,
        r: &mut Rng,
        index_below: Option<u32>,
        dims_below: Option<u32>,
    ) {
        let spp = s.samples_per_pixel();
        for _ in 0..queries {
            let mut q = draw(r, spp);
            if let Some(n) = index_below {
                q[2] %= n;
            }
            if let Some(n) = dims_below {
                q[3] %= n;
            }
            for v in q {
                self.u32(v);
            }
            let v = values(s, q);
            self.f32s(&v);
        }
    }
}

const OWEN_SOBOL_SAMPLER: u32 = 0;
const ZSOBOL_SAMPLER: u32 = 1;
const SOBOL_SAMPLER: u32 = 2;
const HALTON_SAMPLER: u32 = 3;
/// A blue-noise sampler; the configuration's `dims` names the family (0 owen-sobol-bn,
/// 1 pmj02-bn, 2 lattice-bn).
const BLUE_NOISE_SAMPLER: u32 = 4;
const OWEN_SOBOL_SEQUENCE: u32 = 10;
const PMJ02_SEQUENCE: u32 = 11;

/// Every configuration the C API cannot build, with the core's values.
fn expected() -> Expected {
    let mut e = Expected {
        bytes: Vec::new(),
        values: 0,
    };
    let mut r = Rng(0x6578_7065_6374_6564);
    let queries = 4000;
    for k in 0..6u32 {
        let (spp, seed, frame) = ([16u32, 1, 1000][k as usize % 3], r.next(), 1 + k * 7919);
        let mut s = OwenSobolSampler::new(spp, seed).unwrap().with_frame(frame);
        e.config(
            OWEN_SOBOL_SAMPLER,
            Scramble::FastOwen,
            [1, 1],
            spp,
            frame,
            0,
            seed,
            queries,
        );
        e.sampler(&mut s, queries, &mut r, None, Some(1000));
    }
    for scramble in [Scramble::None, Scramble::PermuteDigits, Scramble::Owen] {
        for (k, (size, spp)) in [([64u32, 64], 16u32), ([1920, 1080], 8), ([3, 1], 1)]
            .into_iter()
            .enumerate()
        {
            let seed = if k == 0 { 0 } else { r.next() };
            let mut s = ZSobolSampler::new(size, spp, scramble, seed).unwrap();
            let spp = s.samples_per_pixel();
            e.config(ZSOBOL_SAMPLER, scramble, size, spp, 0, 0, seed, queries);
            e.sampler(&mut s, queries, &mut r, Some(spp), None);
        }
    }
    for scramble in [Scramble::FastOwen, Scramble::Owen, Scramble::PermuteDigits] {
        for (k, (size, spp)) in [([64u32, 48], 16u32), ([1024, 1024], 64), ([3, 1], 1)]
            .into_iter()
            .enumerate()
        {
            let seed = if k == 0 { 0 } else { r.next() };
            let mut s = SobolSampler::new(size, spp, scramble, seed).unwrap();
            let spp = s.samples_per_pixel();
            e.config(SOBOL_SAMPLER, scramble, size, spp, 0, 0, seed, queries);
            e.sampler(&mut s, queries, &mut r, Some(spp), Some(1000));
        }
    }
    for scramble in [Scramble::FastOwen, Scramble::Owen, Scramble::PermuteDigits] {
        for (k, (size, spp)) in [([64u32, 48], 16u32), ([1920, 1080], 64), ([3, 1], 1)]
            .into_iter()
            .enumerate()
        {
            let seed = if k == 0 { 0 } else { r.next() };
            let mut s = HaltonSampler::new(size, spp, scramble, seed).unwrap();
            e.config(HALTON_SAMPLER, scramble, size, spp, 0, 0, seed, queries);
            e.sampler(&mut s, queries, &mut r, None, Some(1000));
        }
    }
    // The blue-noise samplers in frames the C API cannot ask for (up to u32::MAX, where the R2
    // offsets wrap); pixels, indices and dimensions anywhere in u32.
    for family in 0..3u32 {
        for (k, frame) in [1u32, 7919, u32::MAX].into_iter().enumerate() {
            let (spp, seed) = ([16u32, 1, 256][k], r.next());
            e.config(
                BLUE_NOISE_SAMPLER,
                Scramble::FastOwen,
                [1, 1],
                spp,
                frame,
                family,
                seed,
                queries,
            );
            match family {
                0 => {
                    let s = OwenSobolBlueSampler::new(spp, seed).unwrap();
                    e.sampler(&mut s.with_frame(frame), queries, &mut r, None, None);
                }
                1 => {
                    let s = Pmj02BlueSampler::new(spp, seed).unwrap();
                    e.sampler(&mut s.with_frame(frame), queries, &mut r, None, None);
                }
                _ => {
                    let s = LatticeBlueSampler::new(spp, seed).unwrap();
                    e.sampler(&mut s.with_frame(frame), queries, &mut r, None, None);
                }
            }
        }
    }
    for k in 0..4 {
        let seed = r.next();
        let (s, scramble) = if k < 2 {
            (Pmj02::new(), Scramble::None)
        } else {
            (Pmj02::scrambled(seed), Scramble::FastOwen)
        };
        let count = 130_000;
        e.config(PMJ02_SEQUENCE, scramble, [1, 1], 0, 0, 2, seed, count);
        for _ in 0..count {
            let (index, dim) = (r.next() as u32, r.below(4));
            e.u32(index);
            e.u32(dim);
            e.f32s(&[s.sample(u64::from(index), dim)]);
        }
    }
    for (dims, count) in [(1024u32, 150_000u32), (5, 60_000)] {
        for k in 0..2 {
            let seed = if k == 0 { 0 } else { r.next() };
            let s = OwenSobol::new(dims, seed).unwrap();
            e.config(
                OWEN_SOBOL_SEQUENCE,
                Scramble::FastOwen,
                [1, 1],
                0,
                0,
                dims,
                seed,
                count,
            );
            for _ in 0..count {
                let index = if r.next() & 1 == 0 {
                    r.below(1 << 16)
                } else {
                    r.next() as u32
                };
                let dim = r.below(dims + 8);
                e.u32(index);
                e.u32(dim);
                let four = s.sample_4d(u64::from(index), dim);
                e.f32s(&[s.sample(u64::from(index), dim)]);
                e.f32s(&four);
            }
        }
    }
    e
}

/// The expected file, written once per test binary run.
fn expected_file() -> PathBuf {
    static ONCE: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    ONCE.get_or_init(|| {
        let e = expected();
        let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cpp_header_expected.bin");
        let mut f = std::fs::File::create(&path).expect("create the expected file");
        f.write_all(&e.bytes).expect("write the expected file");
        eprintln!("expected file: {} core values", e.values);
        path
    })
    .clone()
}

/// Compiles `parity.cpp` with `compiler` (and `defines`) and runs it, with an eighth of the C
/// API queries if `quick`; `SKIPPED` if the compiler is missing.
fn parity_with(compiler: &str, defines: &[&str], quick: bool) {
    match Command::new(compiler).arg("--version").output() {
        Ok(out) if out.status.success() => {}
        _ => {
            println!("SKIPPED: {compiler} not found");
            eprintln!("SKIPPED: {compiler} not found");
            return;
        }
    }
    let lib = staticlib();
    let ws = workspace();
    let exe = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "cpp_parity_{compiler}{}",
        defines.concat().replace('-', "_")
    ));
    let out = Command::new(compiler)
        .args([
            "-std=c++17",
            "-O2",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-Wconversion",
            "-ffp-contract=off",
        ])
        .args(defines)
        .arg("-I")
        .arg(ws.join("gpu/cpp"))
        .arg("-I")
        .arg(ws.join("capi/include"))
        .arg(ws.join("gpu/cpp/parity.cpp"))
        .arg(&lib)
        .args(["-lm", "-lpthread", "-ldl", "-o"])
        .arg(&exe)
        .output()
        .unwrap_or_else(|e| panic!("run {compiler}: {e}"));
    assert!(
        out.status.success(),
        "{compiler} failed to compile gpu/cpp/parity.cpp:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let run = Command::new(&exe)
        .arg(expected_file())
        .args(quick.then_some("--quick"))
        .output()
        .expect("run the parity program");
    let stdout = String::from_utf8_lossy(&run.stdout);
    println!("{compiler} {defines:?}:\n{stdout}");
    assert!(
        run.status.success(),
        "the header differs from the core under {compiler} ({}):\n{stdout}{}",
        run.status,
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(stdout.contains("parity ok"), "{stdout}");
}

#[test]
fn header_matches_the_core_under_gpp() {
    parity_with("g++", &[], false);
}

#[test]
fn header_matches_the_core_under_clangpp() {
    parity_with("clang++", &[], false);
}

/// The portable 128-bit arithmetic (32-bit limbs and binary long division), which compilers
/// without `__int128` (MSVC) take: the same bits, on every expected value and an eighth of the
/// C API queries.
#[test]
fn header_matches_the_core_without_int128() {
    parity_with("g++", &["-DNYQ_NO_INT128"], true);
}

/// `(s, a, m_1 .. m_s)` per dimension 1 .. 1023 from Joe and Kuo's file.
fn joe_kuo_from_data() -> Vec<Vec<u32>> {
    let text = std::fs::read_to_string(workspace().join("data/sobol/new-joe-kuo-6.1024.txt"))
        .expect("data/sobol/new-joe-kuo-6.1024.txt");
    text.lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            l.split_whitespace()
                .skip(1)
                .map(|x| x.parse().unwrap())
                .collect()
        })
        .collect()
}

/// The header's generated block holds exactly the data file's parameters, in order (what
/// `python3 scripts/gen_cpp_header.py --check` checks too, without needing Python).
#[test]
fn generated_block_is_current() {
    let header = std::fs::read_to_string(workspace().join("gpu/cpp/nyquist.hpp")).unwrap();
    let start = header.find("// @generated begin").expect("begin marker");
    let end = header.find("// @generated end").expect("end marker");
    let block = &header[start..end];
    let array = &block[block.find("kJoeKuo[").expect("kJoeKuo")..];
    let body = &array[array.find('{').unwrap() + 1..array.find("};").unwrap()];
    let mut fields = Vec::new();
    for line in body.lines() {
        let line = line.split("//").next().unwrap();
        fields.extend(
            line.split(',')
                .map(str::trim)
                .filter(|x| !x.is_empty())
                .map(|x| x.parse::<u32>().unwrap()),
        );
    }
    let want: Vec<u32> = joe_kuo_from_data().into_iter().flatten().collect();
    assert_eq!(
        fields, want,
        "gpu/cpp/nyquist.hpp is stale: run python3 scripts/gen_cpp_header.py"
    );
    assert!(
        block.contains(&format!("kJoeKuo[{}]", want.len())),
        "declared length"
    );
    assert!(block.contains("kJoeKuoDims = 1024;"), "dimension count");
}
