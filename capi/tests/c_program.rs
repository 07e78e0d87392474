//! Compiles `capi/tests/c/capi_test.c` with the system C compiler (`cc -std=c99 -Wall -Wextra
//! -Werror`) against the committed header and the static library, runs it, and compares every
//! line it prints with the same values computed here from the `nyquist` crate: floats bit for
//! bit, counts exactly, and the status code of each bad call.

mod common;

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

use common::{Clipped, staticlib, workspace};
use nyquist::filter::{Filter, FilterKind, FilterSampler, FilterTable, Interpolation};
use nyquist::radical;
use nyquist::rng::default_rng;
use nyquist::sampler::{Jitter, NAMES, NamedSampler, Sampler, camera_sample};
use nyquist::sequence::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, ScrambledHalton, Sequence, Sobol,
    VanDerCorput, ZeroTwo,
};
use nyquist::stratify;
use nyquist_capi::{NyqStatus, TabulatedFilter};

/// How a C program is built: plain (`-Wall -Wextra -Werror -O1`), or also with AddressSanitizer
/// and UndefinedBehaviorSanitizer, which abort on the first report.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Build {
    Plain,
    Sanitized,
}

/// Compiles and runs the C program in `source`; returns its standard output. A sanitized run
/// fails on any sanitizer report (address errors, leaks, undefined behaviour) on stderr.
fn run_c_program(source: &Path, name: &str, build: Build) -> String {
    let lib = staticlib();
    let suffix = if build == Build::Sanitized {
        "-sanitized"
    } else {
        ""
    };
    let exe = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}{suffix}"));
    let ws = workspace();
    let mut cc = Command::new("cc");
    cc.args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-O1", "-I"])
        .arg(ws.join("capi/include"));
    if build == Build::Sanitized {
        cc.args([
            "-g",
            "-fsanitize=address,undefined",
            "-fno-sanitize-recover=all",
            "-fno-omit-frame-pointer",
        ]);
    }
    cc.arg(source)
        .arg(&lib)
        .args(["-lm", "-lpthread", "-ldl", "-o"])
        .arg(&exe);
    let out = match cc.output() {
        Ok(out) => out,
        Err(e) => {
            panic!("the C test needs a C compiler named `cc` on PATH (install gcc or clang): {e}")
        }
    };
    assert!(
        out.status.success(),
        "cc failed to compile or link {} (sanitized builds need the compiler's libasan and \
         libubsan, part of Debian's gcc):\n{}{}",
        source.display(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let run = Command::new(&exe)
        .env(
            "ASAN_OPTIONS",
            "detect_leaks=1:abort_on_error=0:exitcode=86",
        )
        .env("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
        .output()
        .expect("run the C test program");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        run.status.success(),
        "the C test program failed ({}):\n{}{stderr}",
        run.status,
        String::from_utf8_lossy(&run.stdout)
    );
    for report in [
        "ERROR: AddressSanitizer",
        "ERROR: LeakSanitizer",
        "runtime error:",
    ] {
        assert!(!stderr.contains(report), "sanitizer report:\n{stderr}");
    }
    String::from_utf8(run.stdout).expect("the C program prints UTF-8")
}

/// The lines the C program must print, computed from the `nyquist` crate.
struct Expected(String);

impl Expected {
    fn floats(&mut self, key: &str, v: &[f32]) {
        self.0.push_str(key);
        for x in v {
            write!(self.0, " {:08x}", x.to_bits()).unwrap();
        }
        self.0.push('\n');
    }
    fn doubles(&mut self, key: &str, v: &[f64]) {
        self.0.push_str(key);
        for x in v {
            write!(self.0, " {:016x}", x.to_bits()).unwrap();
        }
        self.0.push('\n');
    }
    fn double(&mut self, key: &str, v: f64) {
        writeln!(self.0, "{key} {:016x}", v.to_bits()).unwrap();
    }
    fn line(&mut self, s: &str) {
        self.0.push_str(s);
        self.0.push('\n');
    }
    fn status(&mut self, key: &str, s: NyqStatus) {
        writeln!(self.0, "err {key} {}", s as i32).unwrap();
    }
}

fn radical_lines(e: &mut Expected) {
    let cases: [(u32, u64); 7] = [
        (0, 0),
        (0, 1),
        (0, 5),
        (1, 5),
        (2, 1_234_567),
        (7, 1 << 40),
        (1023, u64::MAX),
    ];
    for (d, a) in cases {
        e.floats(&format!("ri {d} {a}"), &[radical::radical_inverse(d, a)]);
        e.double(&format!("ri64 {d} {a}"), radical::radical_inverse_f64(d, a));
        e.floats(
            &format!("folded {d} {a}"),
            &[radical::folded_radical_inverse(d, a)],
        );
        e.double(
            &format!("folded64 {d} {a}"),
            radical::folded_radical_inverse_f64(d, a),
        );
        e.floats(
            &format!("scrambled {d} {a}"),
            &[radical::scrambled_radical_inverse(d, a, 42)],
        );
        e.double(
            &format!("scrambled64 {d} {a}"),
            radical::scrambled_radical_inverse_f64(d, a, 42),
        );
    }
    e.line(&format!("prime 0 {}", radical::prime(0)));
    e.line(&format!("prime 1023 {}", radical::prime(1023)));
    let mut buf = [0.0f32; 8];
    for (i, x) in buf.iter_mut().enumerate() {
        *x = radical::radical_inverse(3, 1000 + i as u64);
    }
    e.floats("fill_ri 3 1000", &buf);
    e.line(&format!(
        "inverse_ri 1 5 2 {}",
        radical::inverse_radical_inverse(1, 5, 2)
    ));
}

fn sequence_lines(e: &mut Expected) {
    let seqs: [(u32, Box<dyn Sequence>); 10] = [
        (0, Box::new(VanDerCorput)),
        (1, Box::new(Halton::new(3).unwrap())),
        (2, Box::new(HaltonZaremba::new(3).unwrap())),
        (3, Box::new(ScrambledHalton::new(3, 42).unwrap())),
        (4, Box::new(Hammersley::new(16, 3).unwrap())),
        (9, Box::new(HammersleyZaremba::new(16, 2).unwrap())),
        (5, Box::new(Sobol::new(4).unwrap())),
        (6, Box::new(Sobol::with_digital_shift(4, 7).unwrap())),
        (7, Box::new(ZeroTwo::new([0, 0]))),
        (8, Box::new(ZeroTwo::from_seed(9))),
    ];
    for (kind, s) in &seqs {
        let dims = s.dims();
        for i in [0u64, 1, 7, 13] {
            let v: Vec<f32> = (0..dims).map(|d| s.sample(i, d)).collect();
            e.floats(&format!("seq {kind} {i}"), &v);
        }
        e.double(&format!("seq64 {kind} 13"), s.sample_f64(13, dims - 1));
        // The fill is checked against per-value samples, not against `fill` itself.
        let v: Vec<f32> = (5..9u64)
            .flat_map(|i| (0..dims).map(move |d| (i, d)))
            .map(|(i, d)| s.sample(i, d))
            .collect();
        e.floats(&format!("seqfill {kind} 4"), &v);
        e.line(&format!("seqcount {kind} {}", s.point_count().unwrap_or(0)));
    }
    // The Halton functions (nyq_halton_sample, nyq_halton_fill) against the table path.
    let h = Halton::new(300).unwrap();
    for i in [0u64, 13, 4_000_000_000, u64::MAX] {
        let v: Vec<f32> = (297..300).map(|d| h.sample(i, d)).collect();
        e.floats(&format!("halton {i}"), &v);
    }
    let h = Halton::new(3).unwrap();
    let v: Vec<f32> = (5..9u64)
        .flat_map(|i| (0..3).map(move |d| (i, d)))
        .map(|(i, d)| h.sample(i, d))
        .collect();
    e.floats("haltonfill 4", &v);
}

fn stratify_lines(e: &mut Expected) {
    let mut buf = [0.0f32; 16];
    stratify::stratified_1d(&mut buf[..7], Jitter::Jittered, &mut default_rng(3)).unwrap();
    e.floats("strat1d jittered", &buf[..7]);
    stratify::stratified_1d(&mut buf[..4], Jitter::Centered, &mut default_rng(3)).unwrap();
    e.floats("strat1d centred", &buf[..4]);
    stratify::stratified_2d(&mut buf[..12], 3, 2, Jitter::Jittered, &mut default_rng(5)).unwrap();
    e.floats("strat2d jittered", &buf[..12]);
    let n = stratify::latin_hypercube(&mut buf[..15], 3, &mut default_rng(2)).unwrap();
    e.floats(&format!("lhs {n}"), &buf[..15]);
    let mut xs = [0.0f32, 1.0, 2.0, 3.0, 4.0, 5.0];
    stratify::shuffle(&mut xs, 3, 2, &mut default_rng(4)).unwrap();
    e.floats("shuffle", &xs);
}

/// The sampler the C API builds for `name` (16 × 16 image, 16 spp).
fn sampler(name: &str, seed: u64) -> NamedSampler {
    NamedSampler::new(name, [16, 16], 16, seed).unwrap()
}

/// The lines `sampler_values` prints for the named sampler `name` under `label`.
fn sampler_value_lines(e: &mut Expected, label: &str, name: &str, seed: u64) {
    let mut s = sampler(name, seed);
    s.start_pixel_sample([3, 5], 2, 0);
    let p = s.get_pixel_2d();
    let t = s.get_1d();
    let uv = s.get_2d();
    e.floats(
        &format!("sampler {label} {seed} {}", s.samples_per_pixel()),
        &[p[0], p[1], t, uv[0], uv[1]],
    );
    let mut c = sampler(name, seed);
    c.start_pixel_sample([9, 2], 11, 6);
    let mut v = [0.0f32; 8];
    c.get_array_1d(&mut v[..4]);
    c.get_array_2d(&mut v[4..]);
    e.floats(&format!("arrays {label} {seed}"), &v);
    let cs = camera_sample(&mut s, [7, 1], 3);
    e.floats(
        &format!("camera {label} {seed}"),
        &[cs.p_film[0], cs.p_film[1], cs.lens[0], cs.lens[1], cs.time],
    );
}

fn sampler_lines(e: &mut Expected) {
    for name in NAMES {
        for seed in [0u64, 7] {
            sampler_value_lines(e, name, name, seed);
        }
    }
    // nyq_sampler_create_owen_sobol gives the named sampler's values.
    for seed in [0u64, 7] {
        sampler_value_lines(e, "owen-sobol-by-kind", "owen-sobol", seed);
    }
}

/// The C program's plugin filter, written again in Rust.
const CONE: Clipped = Clipped {
    radius: 1.5,
    eval: |x, y| {
        let v = 2.0f32 * (1.0 - (x * x + y * y) / 2.25);
        if v > 0.0 { v } else { 0.0 }
    },
};

fn filter_values<F: Filter>(e: &mut Expected, label: &str, f: F, exact: &dyn Filter) {
    const PROBES: [[f32; 2]; 4] = [[0.0, 0.0], [0.3, -1.1], [1.7, 0.2], [-0.45, 0.05]];
    let nearest: FilterTable = FilterTable::new(exact, Interpolation::Nearest).unwrap();
    let linear: FilterTable = FilterTable::new(exact, Interpolation::Linear).unwrap();
    e.floats(&format!("filter {label}"), &f.radius());
    e.floats(&format!("integral {label}"), &[f.integral()]);
    let mut w = Vec::new();
    for [x, y] in PROBES {
        w.extend([f.eval(x, y), nearest.weight(x, y), linear.weight(x, y)]);
    }
    e.floats(&format!("weights {label}"), &w);
    let sampler: FilterSampler<F> = FilterSampler::new(f).unwrap();
    let s = sampler.sample([0.3, 0.7]);
    let pdf = sampler.pdf(s.offset);
    e.floats(
        &format!("fsample {label}"),
        &[s.offset[0], s.offset[1], s.weight, pdf],
    );
}

fn filter_lines(e: &mut Expected) {
    for spec in [
        "box",
        "triangle",
        "gaussian:sigma=0.5",
        "mitchell:b=0.5,c=0.25",
        "lanczos",
    ] {
        let k = FilterKind::parse(spec).unwrap();
        filter_values(e, spec, k, &k);
    }
    let linear: FilterTable = FilterTable::new(&CONE, Interpolation::Linear).unwrap();
    assert_eq!(linear.integral(), CONE.integral());
    filter_values(e, "cone", TabulatedFilter(linear), &CONE);
    e.line("cone calls after lookups unchanged");
}

/// The lines of the C program's `pixel_stats`: four pixels of 16 samples, kept by two threads
/// and merged, against the core's `PixelStats`.
fn pixel_stats_lines(e: &mut Expected) {
    use nyquist::pixel_stats::{ErrorEstimate, PixelStats, sample_half};
    for p in 0..4i32 {
        let (mut a, mut b) = (PixelStats::default(), PixelStats::default());
        for k in 0..16i32 {
            let w = f64::from((k * 3 + p) % 5) / 4.0 - 0.25;
            let v0 = f64::from((k * 7 + p) % 11) / 8.0;
            let half = if k < 9 { &mut a } else { &mut b };
            half.add(k as u64, w, [v0, 2.0 - v0, f64::from(k % 3)])
                .unwrap();
        }
        a.merge(&b);
        let m = &a.moments;
        let mut fields = a.sum.to_vec();
        fields.extend([a.weight, m.weight2_sum()]);
        fields.extend(m.mean());
        fields.extend(m.deviation_sum());
        fields.extend(a.half_b_sum);
        fields.push(a.half_b_weight);
        e.doubles(&format!("stats {p}"), &fields);
        let est = a.estimate();
        let [half_a, half_b] = est.halves.unwrap_or_default();
        let mut values = est.value.to_vec();
        values.extend(est.variance.unwrap_or_default());
        values.extend(half_a);
        values.extend(half_b);
        e.doubles(
            &format!(
                "estimate {p} {} {}",
                u8::from(est.variance.is_some()),
                u8::from(est.halves.is_some())
            ),
            &values,
        );
        let r = [ErrorEstimate::Halves, ErrorEstimate::Variance]
            .map(|k| est.relative_error(k, 0.01).unwrap_or(f64::INFINITY));
        e.doubles(&format!("relerr {p}"), &r);
    }
    let halves: Vec<String> = (0..8u64)
        .map(|i| sample_half(i * 5 + (1 << 40)).to_string())
        .collect();
    e.line(&format!("halves {}", halves.join(" ")));
    let mut os = nyquist::sampler::OwenSobolSampler::new(16, 7).unwrap();
    os.start_pixel_sample([3, 5], 2, 0);
    let root = os.pixel_domain();
    let mut dv: Vec<f32> = (0..4)
        .flat_map(|k| root.split(1, 4, k).unwrap().get_2d(0))
        .collect();
    dv.push(root.branch(2).get_1d(1030));
    dv.push(root.chain(3, 1).get_1d(0));
    e.floats("domain", &dv);
    e.status("domain_random", NyqStatus::NYQ_ERR_NULL);
    use NyqStatus::*;
    for (key, code) in [
        ("stats_nan_weight", NYQ_ERR_NON_FINITE),
        ("stats_null_value", NYQ_ERR_NULL),
        ("stats_bad_struct", NYQ_ERR_OUT_OF_RANGE),
        ("stats_bad_kind", NYQ_ERR_OUT_OF_RANGE),
        ("stats_negative_floor", NYQ_ERR_OUT_OF_RANGE),
    ] {
        e.status(key, code);
    }
}

fn error_lines(e: &mut Expected) {
    use NyqStatus::*;
    let codes = [
        ("ri_null_out", NYQ_ERR_NULL),
        ("ri_dim_1024", NYQ_ERR_OUT_OF_RANGE),
        ("ri64_null_out", NYQ_ERR_NULL),
        ("scrambled_dim", NYQ_ERR_OUT_OF_RANGE),
        ("fill_ri_zero", NYQ_ERR_ZERO_SIZE),
        ("fill_ri_null", NYQ_ERR_NULL),
        ("seq_null_seq", NYQ_ERR_NULL),
        ("seq_null_out", NYQ_ERR_NULL),
        ("seq_bad_kind", NYQ_ERR_OUT_OF_RANGE),
        ("seq_zero_dims", NYQ_ERR_ZERO_SIZE),
        ("seq_sobol_2000", NYQ_OK),
        ("seq_dim_past", NYQ_ERR_OUT_OF_RANGE),
        ("seq_index_past", NYQ_ERR_OUT_OF_RANGE),
        ("seq_hammersley_n0", NYQ_ERR_ZERO_SIZE),
        ("seq_vdc_dims2", NYQ_ERR_OUT_OF_RANGE),
        ("seq64_null", NYQ_ERR_NULL),
        ("fill_zero_len", NYQ_ERR_ZERO_SIZE),
        ("fill_odd_len", NYQ_ERR_BUFFER),
        ("fill_null_written", NYQ_ERR_NULL),
        ("fill_dims0", NYQ_ERR_ZERO_SIZE),
        ("fill_dims_past", NYQ_ERR_OUT_OF_RANGE),
        ("fill_past_end", NYQ_ERR_TOO_MANY),
        ("strat1d_null", NYQ_ERR_NULL),
        ("strat1d_zero", NYQ_ERR_ZERO_SIZE),
        ("strat2d_len", NYQ_ERR_BUFFER),
        ("strat2d_nx0", NYQ_ERR_ZERO_SIZE),
        ("lhs_dims0", NYQ_ERR_ZERO_SIZE),
        ("lhs_len", NYQ_ERR_BUFFER),
        ("lhs_null_written", NYQ_ERR_NULL),
        ("shuffle_long", NYQ_ERR_OUT_OF_RANGE),
        ("shuffle_short", NYQ_ERR_BUFFER),
        ("sampler_bad_name", NYQ_ERR_PARSE),
        ("sampler_null_name", NYQ_ERR_NULL),
        ("sampler_null_out", NYQ_ERR_NULL),
        ("sampler_spp0", NYQ_ERR_ZERO_SIZE),
        ("sampler_width0", NYQ_ERR_ZERO_SIZE),
        ("sampler_above_limit", NYQ_ERR_OUT_OF_RANGE),
        ("sampler_bad_utf8", NYQ_ERR_PARSE),
        ("sampler_null_handle", NYQ_ERR_NULL),
        ("sampler_start_null", NYQ_ERR_NULL),
        ("sampler_get2d_null_out", NYQ_ERR_NULL),
        ("sampler_array2d_odd", NYQ_ERR_BUFFER),
        ("sampler_array1d_zero", NYQ_ERR_ZERO_SIZE),
        ("sampler_report_zero", NYQ_ERR_ZERO_SIZE),
        ("filter_bad_number", NYQ_ERR_PARSE),
        ("filter_unknown", NYQ_ERR_PARSE),
        ("filter_empty", NYQ_ERR_PARSE),
        ("filter_bad_radius", NYQ_ERR_PARSE),
        ("filter_null_spec", NYQ_ERR_NULL),
        ("filter_null_out", NYQ_ERR_NULL),
        ("callback_null_eval", NYQ_ERR_NULL),
        ("callback_nan_radius", NYQ_ERR_NON_FINITE),
        ("callback_zero_radius", NYQ_ERR_OUT_OF_RANGE),
        ("callback_huge_radius", NYQ_ERR_OUT_OF_RANGE),
    ];
    for (key, code) in codes {
        e.status(key, code);
    }
    e.line("callback_rejected_calls 0");
    for (key, code) in [
        ("lookup_bad_interp", NYQ_ERR_OUT_OF_RANGE),
        ("lookup_null_out", NYQ_ERR_NULL),
        ("eval_null_filter", NYQ_ERR_NULL),
        ("sample_null_out", NYQ_ERR_NULL),
    ] {
        e.status(key, code);
    }
    e.line("message name or spec does not parse");
    e.line("message unknown status");
    e.line(&format!("version {}", env!("CARGO_PKG_VERSION")));
}

/// The lines of `blue_tiles()`: per name, entries (0, 0), (127, 0), (5, 77) and (127, 127) of
/// the core's tile, that its keys are a permutation of 0 … 16383 and that the entry past the
/// tile was left alone; then the bad calls' statuses.
fn blue_tile_lines(e: &mut Expected) {
    use nyquist::sampler::screen_blue::{BlueFamily, LatticeBlue, OwenSobolBlue, Pmj02Blue};
    fn line<F: BlueFamily>(e: &mut Expected, name: &str) {
        let mut keys: Vec<u32> = (0..128 * 128)
            .map(|i| F::entry(i % 128, i / 128) >> 8)
            .collect();
        keys.sort_unstable();
        let permutation = keys.iter().copied().eq(0..128 * 128);
        e.line(&format!(
            "blue {name} {} {} {} {} {} 1",
            F::entry(0, 0),
            F::entry(127, 0),
            F::entry(5, 77),
            F::entry(127, 127),
            i32::from(permutation)
        ));
    }
    line::<OwenSobolBlue>(e, "owen-sobol-bn");
    line::<Pmj02Blue>(e, "pmj02-bn");
    line::<LatticeBlue>(e, "lattice-bn");
    line::<LatticeBlue>(e, "LATTICE-BN");
    for (key, code) in [
        ("blue_null_name", NyqStatus::NYQ_ERR_NULL),
        ("blue_null_out", NyqStatus::NYQ_ERR_NULL),
        ("blue_bad_name", NyqStatus::NYQ_ERR_PARSE),
        ("blue_short", NyqStatus::NYQ_ERR_BUFFER),
        ("blue_zero", NyqStatus::NYQ_ERR_ZERO_SIZE),
    ] {
        e.status(key, code);
    }
}

/// A C program of this package's tests, `capi/tests/c/NAME`.
fn c_source(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/c")
        .join(name)
}

/// Every line `capi/tests/c/capi_test.c` must print, from the Rust side.
fn expected_c_output() -> String {
    let mut e = Expected(String::new());
    radical_lines(&mut e);
    sequence_lines(&mut e);
    stratify_lines(&mut e);
    sampler_lines(&mut e);
    filter_lines(&mut e);
    pixel_stats_lines(&mut e);
    blue_tile_lines(&mut e);
    error_lines(&mut e);
    e.line("done");
    e.0
}

/// Runs `capi/tests/c/capi_test.c` built as `build` and compares its output line by line.
fn check_c_program(build: Build) {
    let want = expected_c_output();
    let actual = run_c_program(&c_source("capi_test.c"), "capi_test", build);
    let (want, got): (Vec<&str>, Vec<&str>) = (want.lines().collect(), actual.lines().collect());
    for (i, (w, g)) in want.iter().zip(&got).enumerate() {
        assert_eq!(
            g,
            w,
            "line {} of the C program's output differs from the Rust result (left: C, right: Rust)",
            i + 1
        );
    }
    assert_eq!(
        got.len(),
        want.len(),
        "the C program printed {} lines, the Rust side expects {}",
        got.len(),
        want.len()
    );
}

#[test]
fn c_program_matches_rust_results() {
    check_c_program(Build::Plain);
}

/// The same program under AddressSanitizer and UndefinedBehaviorSanitizer: every pointer the
/// API reads or writes from C stays inside its buffer, and nothing leaks.
#[test]
fn c_program_is_clean_under_sanitizers() {
    check_c_program(Build::Sanitized);
}

/// `capi/tests/c/capi_misuse.c` misuses the API on purpose (null handles and out-pointers, zero and
/// wrong lengths, misaligned buffers, bad enums and specs, a double destroy through the
/// null guard): every call gets its documented status, no output is touched, and the
/// sanitizers report nothing.
#[test]
fn misuse_gets_error_codes_and_no_sanitizer_report() {
    let out = run_c_program(&c_source("capi_misuse.c"), "capi_misuse", Build::Sanitized);
    assert_eq!(out, "misuse ok\n");
}

#[test]
fn readme_c_example_compiles_and_runs() {
    let readme = std::fs::read_to_string(workspace().join("README.md")).expect("README.md");
    let start = readme.find("```c\n").expect("README has a ```c example") + "```c\n".len();
    let len = readme[start..]
        .find("```")
        .expect("the ```c block is closed");
    let source = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme_example.c");
    std::fs::write(&source, &readme[start..start + len]).unwrap();
    let out = run_c_program(&source, "readme_example", Build::Plain);
    let words: Vec<&str> = out.split_whitespace().collect();
    assert_eq!(words.len(), 2, "{out}");
    assert_eq!(
        words[0].parse::<f32>(),
        Ok(Halton::new(2).unwrap().sample(3, 0))
    );
    let k = FilterKind::parse("mitchell:b=0.5,c=0.25").unwrap();
    let t: FilterTable = FilterTable::new(&k, Interpolation::Linear).unwrap();
    let w: f32 = words[1].parse().unwrap();
    // printf's %g keeps 6 significant digits.
    assert!(
        (w - t.weight(0.5, -0.25)).abs() <= 1e-6 * w.abs().max(1.0),
        "{w}"
    );
}

#[test]
fn header_compiles_as_cpp() {
    let probe = Path::new(env!("CARGO_TARGET_TMPDIR")).join("header_probe.cpp");
    std::fs::write(
        &probe,
        "#include \"nyquist.h\"\nint main() { float x; return nyq_radical_inverse(1, 5, &x) == NYQ_OK ? 0 : 1; }\n",
    )
    .unwrap();
    let out = match Command::new("c++")
        .args([
            "-std=c++11",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-fsyntax-only",
            "-I",
        ])
        .arg(workspace().join("capi/include"))
        .arg(&probe)
        .output()
    {
        Ok(out) => out,
        Err(e) => {
            // C++ is a bonus; the C test above is the contract.
            eprintln!(
                "SKIPPED: no `c++` compiler on PATH ({e}); the header was not checked as C++"
            );
            return;
        }
    };
    assert!(
        out.status.success(),
        "capi/include/nyquist.h does not compile as C++11:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
