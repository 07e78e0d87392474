//! A run ended by SIGINT or SIGTERM while it writes an image removes its temporary file and exits
//! with 128 + the signal's number; a cached reference that is damaged or was made from other
//! parameters is rendered again, with a note on stderr.

mod common;

use common::{files, nyquist_cached, temp_dir};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Starts a quick render of a large PNG (2048², one sample a pixel, box filter) into `dir`,
/// waits until its temporary file appears (the encoder is then writing), sends `signal` with
/// `kill`, and returns the exit code and the folder's files afterwards.
fn interrupt_a_write(signal: &str, dir: &Path) -> (Option<i32>, Vec<String>) {
    interrupt_a_write_to(signal, &dir.join("big.png"), dir)
}

/// [`interrupt_a_write`] to `out`, whose temporary file appears in `dir` as `.big.png.tmp-PID`
/// (`out` may be a link to `dir/big.png`).
fn interrupt_a_write_to(signal: &str, out: &Path, dir: &Path) -> (Option<i32>, Vec<String>) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args([
            "render",
            "--size",
            "2048x2048",
            "--spp",
            "1",
            "--sampler",
            "uniform",
        ])
        .args(["--filter", "box", "-o"])
        .arg(out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("run nyquist");
    let deadline = Instant::now() + Duration::from_secs(120);
    loop {
        if files(dir).iter().any(|f| f.starts_with(".big.png.tmp-")) {
            break;
        }
        if let Some(status) = child.try_wait().unwrap() {
            panic!("the render ended ({status}) before its temporary file was seen");
        }
        assert!(Instant::now() < deadline, "no temporary file within 120 s");
        std::thread::sleep(Duration::from_millis(5));
    }
    let kill = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .expect("run kill");
    assert!(kill.success());
    let status = child.wait().unwrap();
    (status.code(), files(dir))
}

#[test]
fn sigterm_during_a_write_removes_the_temporary_file_and_exits_143() {
    let dir = temp_dir("sigterm");
    let (code, left) = interrupt_a_write("-TERM", &dir);
    assert_eq!(code, Some(143));
    assert!(left.is_empty(), "left behind: {left:?}");
}

#[test]
fn sigint_during_a_write_removes_the_temporary_file_and_exits_130() {
    let dir = temp_dir("sigint");
    let (code, left) = interrupt_a_write("-INT", &dir);
    assert_eq!(code, Some(130));
    assert!(left.is_empty(), "left behind: {left:?}");
}

#[test]
fn sigint_during_a_write_through_a_link_removes_the_temporary_file_in_the_targets_folder() {
    let dir = temp_dir("sigint-link");
    let target = temp_dir("sigint-link-target");
    let link = dir.join("link.png");
    std::os::unix::fs::symlink(target.join("big.png"), &link).unwrap();
    let (code, left) = interrupt_a_write_to("-INT", &link, &target);
    assert_eq!(code, Some(130));
    assert!(left.is_empty(), "left behind: {left:?}");
    assert_eq!(files(&dir), ["link.png"]);
}

/// The `rmse` value of a `render --metrics --json` run.
fn rmse(stdout: &[u8]) -> f64 {
    common::json_field(std::str::from_utf8(stdout).unwrap(), "rmse")
}

#[test]
fn a_damaged_cached_reference_is_rendered_again_with_a_note() {
    let cache = temp_dir("reference-cache");
    let args = [
        "render",
        "--scene",
        "disk",
        "--size",
        "24x16",
        "--spp",
        "4",
        "--metrics",
        "--json",
    ];
    let first = nyquist_cached(&args, &cache);
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&first.stderr), "");
    let want = rmse(&first.stdout);
    let dir = &cache.join("nyquist");
    let names = files(dir);
    assert_eq!(names.len(), 1, "{names:?}");
    let file = dir.join(&names[0]);
    let good = std::fs::read(&file).unwrap();
    let text = String::from_utf8_lossy(&good);
    assert!(
        text.starts_with("nyquist reference image\nscene disk\nsize 24x16\n"),
        "{text:.200}"
    );

    // A NaN pixel with the checksum recomputed, so only the finite check can catch it.
    let nan_pixel = {
        let at = good.windows(8).position(|w| w == b"fnv1a64 ").unwrap();
        let end = at + good[at..].iter().position(|&b| b == b'\n').unwrap();
        let mut pfm = good[end + 1..].to_vec();
        let n = pfm.len();
        pfm[n - 4..].copy_from_slice(&f32::NAN.to_le_bytes());
        let sum = pfm.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
        });
        let mut bytes = good[..at].to_vec();
        bytes.extend(format!("fnv1a64 {sum:016x} bytes {n}\n").bytes());
        bytes.extend(pfm);
        bytes
    };
    let mut flipped = good.clone();
    let last = flipped.len() - 1;
    flipped[last] ^= 0x40;
    let other_params = String::from_utf8_lossy(&good)
        .replacen("size 24x16", "size 16x24", 1)
        .into_bytes();
    for (damage, bytes, why) in [
        ("truncated", good[..good.len() - 7].to_vec(), "is truncated"),
        ("a flipped bit", flipped, "does not match its checksum"),
        ("a NaN pixel", nan_pixel, "has a non-finite pixel"),
        (
            "other parameters",
            other_params,
            "was made from other parameters",
        ),
    ] {
        std::fs::write(&file, &bytes).unwrap();
        let o = nyquist_cached(&args, &cache);
        assert!(
            o.status.success(),
            "{damage}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.starts_with("nyquist: note: the cached reference ")
                && err.contains(why)
                && err.trim_end().ends_with("rendering it again")
                && err.lines().count() == 1,
            "{damage}: {err:?}"
        );
        assert_eq!(
            rmse(&o.stdout),
            want,
            "{damage}: the regenerated reference differs"
        );
        assert_eq!(
            std::fs::read(&file).unwrap(),
            good,
            "{damage}: the cache was not rewritten"
        );
    }
}

/// Runs nyquist under an address-space limit of `kib` KiB (the shell's `ulimit -v`).
fn nyquist_under_ulimit(kib: u64, args: &str) -> std::process::Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v {kib} && exec '{}' {args}",
            env!("CARGO_BIN_EXE_nyquist")
        ))
        .output()
        .expect("run sh")
}

/// Under `ulimit -v 2000000` (2 GB) the default limit is half of it: an 8192² render with
/// metrics (4.3 GB by the estimate) is refused before it allocates, in one line naming the flags,
/// the estimate and the limit's source. With `--max-memory` raised past the address space, the
/// film's allocation itself fails and is reported in one line, not an abort.
#[test]
fn memory_estimates_and_failed_allocations_are_one_line_errors() {
    let dir = temp_dir("ulimit");
    let out = dir.join("big.pfm");
    let o = nyquist_under_ulimit(2_000_000, "render --size 8192x8192 --spp 1 --metrics");
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(
        err,
        "nyquist: --size 8192x8192 with --metrics: needs about 4.3 GB of memory, more than the \
         limit of 1.0 GB (half the address-space limit (ulimit -v)); give smaller values or a \
         larger --max-memory\n"
    );
    let o = nyquist_under_ulimit(
        2_000_000,
        &format!(
            "render --size 8192x8192 --spp 1 --max-memory 100G -o '{}'",
            out.display()
        ),
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(
        err,
        "nyquist: --size 8192x8192: out of memory: 2147483648 bytes for the film's pixels (try \
         a smaller --size)\n"
    );
    assert!(files(&dir).is_empty(), "{:?}", files(&dir));
    // The explicit limit, and the other commands' estimates.
    for (args, flags) in [
        (
            "points --count 100000000 --dims 2 --max-memory 100M",
            "--count 100000000 × --dims 2",
        ),
        (
            "filter --filter box --grid 4096 --max-memory 100M",
            "--grid 4096",
        ),
        (
            "analyze --sampler halton --count 64 --spectrum x.png --freq 4096 --max-memory 100M",
            "--spectrum with --freq 4096",
        ),
        (
            "compare --size 1024x1024 --max-memory 100M",
            "--size 1024x1024 × 60 renders",
        ),
    ] {
        let o = nyquist_under_ulimit(4_000_000, args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args}: {err}");
        assert!(
            err.starts_with(&format!("nyquist: {flags}: needs about "))
                && err.contains("(--max-memory)")
                && err.lines().count() == 1,
            "{args}: {err}"
        );
    }
}
