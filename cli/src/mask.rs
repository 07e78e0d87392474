//! `nyquist mask`: a blue-noise threshold mask by void-and-cluster, as PNG (8 or 16 bits per
//! channel) and OpenEXR (32-bit float values), and optionally the picture of its spectrum.

use crate::output::{check_output, write_atomic, write_output};
use anyhow::{Context, Result, bail};
use clap::Args;
use nyquist::bluenoise::{VoidAndCluster, rank_to_value};
use nyquist_film::output::png::{PngColor, PngDepth, PngLayout, write_png_pixels};
use std::path::{Path, PathBuf};

/// The largest side of a mask.
pub const MAX_MASK_SIDE: u32 = 1024;

/// The largest mask whose spectrum `--spectrum` draws (a direct DFT, `O(N·(W + H))`).
pub const MAX_SPECTRUM_PIXELS: u32 = 256 * 256;

/// Arguments of `nyquist mask`.
#[derive(Debug, Args)]
#[command(after_help = "Example: nyquist mask --size 128 --channels 4 -o mask.png -o mask.exr")]
pub struct MaskArgs {
    /// Mask size: `N` for N × N, or `WxH`; sides 1 to 1024.
    #[arg(long, value_parser = parse_mask_size, default_value = "64")]
    pub size: [u32; 2],
    /// Channels, 1 to 4 (PNG: grey, grey + alpha, RGB, RGBA; OpenEXR: Y or R, G, B, A), each an
    /// independent mask, decorrelated.
    #[arg(long, default_value_t = 1, value_parser = nyquist_lab::flags::whole(1u32, 4))]
    pub channels: u32,
    /// Seed: the same seed and size give the same mask.
    #[arg(long, default_value_t = 0, value_parser = nyquist_lab::flags::whole(0, u64::MAX))]
    pub seed: u64,
    /// Bits per PNG sample, 8 or 16: rank r of N pixels becomes ⌊r·2^bits/N⌋.
    #[arg(long, default_value_t = 8, value_parser = parse_bits)]
    pub bits: u8,
    /// Write the mask here: .png (integer levels) or .exr (values (r + ½)/N as 32-bit floats);
    /// repeat for both; `-` for stdout (with --format).
    #[arg(short, long, required = true, value_name = "FILE.png|FILE.exr")]
    pub output: Vec<PathBuf>,
    /// The format of an --output without an extension to tell it (`-`, /dev/stdout, a FIFO);
    /// an extension that names another format is an error.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<MaskFormat>,
    /// Also write the periodogram of channel 0's values (log scale, zero frequency at the
    /// centre) as a grey PNG; masks up to 256 × 256.
    #[arg(long, value_name = "FILE.png")]
    pub spectrum: Option<PathBuf>,
}

/// The formats of `mask --format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum MaskFormat {
    /// PNG, 8 or 16 bits per channel (--bits).
    Png,
    /// OpenEXR, 32-bit float.
    Exr,
}

impl MaskFormat {
    /// The name, as the extension and the flag value.
    pub fn name(self) -> &'static str {
        match self {
            MaskFormat::Png => "png",
            MaskFormat::Exr => "exr",
        }
    }
}

/// The format of `--output path`: by `--format`, else by the extension.
fn format_of(path: &Path, format: Option<MaskFormat>) -> Result<&'static str> {
    crate::output::choose_format(
        path,
        "--output",
        &["png", "exr"],
        format.map(MaskFormat::name),
        Some("--format"),
    )
}

/// Parses `N` or `WxH` into a mask size.
///
/// ```
/// use nyquist_cli::mask::parse_mask_size;
/// assert_eq!(parse_mask_size("128"), Ok([128, 128]));
/// assert_eq!(parse_mask_size("64x32"), Ok([64, 32]));
/// assert!(parse_mask_size("0").is_err());
/// assert!(parse_mask_size("1024x2048").is_err());
/// ```
pub fn parse_mask_size(s: &str) -> Result<[u32; 2], String> {
    let bad = || format!("not N or WxH with sides 1 to {MAX_MASK_SIDE} (e.g. 128)");
    let side = |t: &str| match t.trim().parse::<u32>() {
        Ok(v) if (1..=MAX_MASK_SIDE).contains(&v) => Ok(v),
        _ => Err(bad()),
    };
    // Sides up to 1024 keep every size within the core's MAX_MASK_PIXELS (2^20).
    Ok(match s.split_once(['x', 'X']) {
        Some((a, b)) => [side(a)?, side(b)?],
        None => [side(s)?; 2],
    })
}

fn parse_bits(s: &str) -> Result<u8, String> {
    match s.trim() {
        "8" => Ok(8),
        "16" => Ok(16),
        _ => Err("not 8 or 16".to_owned()),
    }
}

/// Seconds of void-and-cluster for `pixels` pixels and `channels` channels, estimated from a
/// release build on a 2-core x86-64 machine (one channel: 128² in 0.16 s, 256² in 0.60 s, 512²
/// in 3.0 s, 1024² in 14.8 s; four channels at 512² in 10.5 s): 3.0 s × (pixels/512²)^1.16 per
/// channel. The basis of the announcement, not a promise.
///
/// ```
/// let s = nyquist_cli::mask::estimated_seconds(1024 * 1024, 1);
/// assert!((14.0..16.0).contains(&s), "{s}");
/// ```
pub fn estimated_seconds(pixels: u64, channels: u32) -> f64 {
    3.0 * (pixels as f64 / 262_144.0).powf(1.16) * f64::from(channels)
}

/// Estimated work above which `mask` says so before it starts, with a progress bar.
const ANNOUNCE_SECONDS: f64 = 2.0;

/// Generates the mask's ranks, channel-major (`channels × W·H`).
pub fn ranks(size: [u32; 2], channels: u32, seed: u64) -> Result<Vec<u32>> {
    let vc = VoidAndCluster::new(size[0], size[1], seed).context("--size")?;
    let (el, sl) = vc.scratch_len();
    let mut ranks = vec![0u32; vc.pixels() * channels as usize];
    vc.generate_channels(&mut ranks, &mut vec![0.0; el], &mut vec![0; sl])
        .context("mask")?;
    Ok(ranks)
}

/// Runs the subcommand.
pub fn run(args: &MaskArgs) -> Result<()> {
    let [w, h] = args.size;
    let to_stdout = args
        .output
        .iter()
        .chain(&args.spectrum)
        .filter(|p| crate::output::is_stdout(p))
        .count();
    if to_stdout > 1 {
        bail!("--output -, --spectrum -: only one output can go to stdout");
    }
    let mut formats = Vec::with_capacity(args.output.len());
    for path in &args.output {
        formats.push(format_of(path, args.format)?);
        crate::output::check_target(path, "--output")?;
    }
    if let Some(path) = &args.spectrum {
        if w * h > MAX_SPECTRUM_PIXELS {
            bail!("--spectrum: --size {w}x{h} has more than {MAX_SPECTRUM_PIXELS} pixels");
        }
        check_output(path, "--spectrum", &["png"])?;
    }
    if args.bits != 8 && !formats.contains(&"png") {
        crate::output::note("--bits applies to PNG output only");
    }
    let n = (w * h) as usize;
    nyquist_lab::memory::check(
        &format!("--size {w}x{h} --channels {}", args.channels),
        nyquist_lab::memory::bytes(n as u64, 4 * u64::from(args.channels) + 24),
    )?;
    let seconds = estimated_seconds(u64::from(w) * u64::from(h), args.channels);
    let bar = crate::progress::Progress::with_unit(1, "mask", "masks");
    if seconds > ANNOUNCE_SECONDS {
        crate::output::warn(&format!(
            "--size {w}x{h} --channels {}: void-and-cluster over {} pixels: about {} of work; a \
             smaller --size or fewer --channels make it shorter",
            args.channels,
            w * h,
            nyquist_lab::analysis::duration(seconds)
        ));
        bar.show_now();
    }
    let ranks = ranks(args.size, args.channels, args.seed);
    bar.finish();
    let ranks = ranks?;
    for (path, format) in args.output.iter().zip(formats) {
        match format {
            "png" => write_png(path, &ranks, args, n)?,
            _ => write_exr(path, &ranks, args, n)?,
        }
    }
    if let Some(path) = &args.spectrum {
        write_spectrum(path, &ranks[..n], w as usize, h as usize)?;
    }
    Ok(())
}

fn write_png(path: &Path, ranks: &[u32], args: &MaskArgs, n: usize) -> Result<()> {
    let [w, h] = args.size;
    let channels = args.channels as usize;
    let bits = u32::from(args.bits);
    let mut data = Vec::with_capacity(n * channels * (bits as usize / 8));
    for i in 0..n {
        for c in 0..channels {
            let r = u64::from(ranks[c * n + i]);
            let level = (r << bits) / n as u64;
            if bits == 8 {
                data.push(level as u8);
            } else {
                data.extend_from_slice(&(level as u16).to_be_bytes());
            }
        }
    }
    let color = match channels {
        1 => PngColor::Grey,
        2 => PngColor::GreyAlpha,
        3 => PngColor::Rgb,
        _ => PngColor::Rgba,
    };
    let layout = PngLayout {
        depth: if bits == 8 {
            PngDepth::Eight
        } else {
            PngDepth::Sixteen
        },
        ..PngLayout::new(w, h, color)
    };
    write_atomic(path, |out| Ok(write_png_pixels(out, &layout, &data)?))
}

fn write_exr(path: &Path, ranks: &[u32], args: &MaskArgs, n: usize) -> Result<()> {
    let names: &[&str] = match args.channels {
        1 => &["Y"],
        2 => &["R", "G"],
        3 => &["R", "G", "B"],
        _ => &["R", "G", "B", "A"],
    };
    let planes: Vec<Vec<f32>> = ranks
        .chunks_exact(n)
        .map(|c| c.iter().map(|&r| rank_to_value(r, n as u32)).collect())
        .collect();
    let list: Vec<(&str, &[f32])> = names
        .iter()
        .zip(&planes)
        .map(|(name, p)| (*name, p.as_slice()))
        .collect();
    write_atomic(path, |out| {
        nyquist_film::output::exr::write_exr_planes(out, args.size[0], args.size[1], &list)?;
        Ok(())
    })
}

/// The periodogram `|DFT(v − mean)|²/N` of a `w × h` mask's values, zero frequency at the centre.
pub fn spectrum(ranks: &[u32], w: usize, h: usize) -> Vec<f64> {
    let n = ranks.len();
    let mean = (n as f64 - 1.0) / 2.0;
    let v: Vec<f64> = ranks
        .iter()
        .map(|&r| (f64::from(r) - mean) / n as f64)
        .collect();
    let twiddle = |k: usize, m: usize| {
        let a = -2.0 * std::f64::consts::PI * k as f64 / m as f64;
        (a.cos(), a.sin())
    };
    // Rows: rows[y][fx] = Σ_x v(x, y) e^{−2πi fx x / w}.
    let mut rows = vec![(0.0, 0.0); n];
    for y in 0..h {
        for fx in 0..w {
            let (mut re, mut im) = (0.0, 0.0);
            for x in 0..w {
                let (c, s) = twiddle(fx * x % w, w);
                re += v[y * w + x] * c;
                im += v[y * w + x] * s;
            }
            rows[y * w + fx] = (re, im);
        }
    }
    let mut power = vec![0.0; n];
    for fy in 0..h {
        for fx in 0..w {
            let (mut re, mut im) = (0.0, 0.0);
            for y in 0..h {
                let (c, s) = twiddle(fy * y % h, h);
                let (a, b) = rows[y * w + fx];
                re += a * c - b * s;
                im += a * s + b * c;
            }
            let (cx, cy) = ((fx + w / 2) % w, (fy + h / 2) % h);
            power[cy * w + cx] = (re * re + im * im) / n as f64;
        }
    }
    power
}

fn write_spectrum(path: &Path, ranks: &[u32], w: usize, h: usize) -> Result<()> {
    let power = spectrum(ranks, w, h);
    let peak = power.iter().copied().fold(0.0f64, f64::max).max(1e-300);
    // 40 dB of range below the peak, black at −40 dB and below.
    let data: Vec<u8> = power
        .iter()
        .map(|&p| {
            let db = 10.0 * (p.max(1e-300) / peak).log10();
            (((db + 40.0) / 40.0).clamp(0.0, 1.0) * 255.0).round() as u8
        })
        .collect();
    let layout = PngLayout::new(w as u32, h as u32, PngColor::Grey);
    write_output(path, "--spectrum", |out| {
        Ok(write_png_pixels(out, &layout, &data)?)
    })
}
