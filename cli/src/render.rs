//! `nyquist render`: render a built-in scene with a sampler and a reconstruction filter, write the
//! image, and measure it against a reference.

use crate::progress::Progress;
use anyhow::{Context, Result, anyhow, bail};
use clap::{Args, ValueEnum};
use nyquist::filter::FilterKind;
use nyquist::sampler::{NamedSampler, NamedSamplerError, Sampler};
use nyquist::scramble::Scramble;
use nyquist_film::{Image, ImageFormat};
use nyquist_lab::scene::Scene;
use std::fmt::Write as _;
use std::path::PathBuf;

/// Pixel samplers by their command-line names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SamplerName {
    /// One sample at the centre of each of √spp × √spp strata: the aliasing baseline.
    Uniform,
    /// Independent uniform random samples (PCG32).
    Random,
    /// Jittered strata, √spp × √spp per pixel.
    Stratified,
    /// One Halton sequence over the whole image (scrambled when --seed is not 0).
    Halton,
    /// Hammersley points per pixel block (scrambled when --seed is not 0).
    Hammersley,
    /// Scrambled (0,2)-sequence per pixel (spp rounded up to a power of two).
    ZeroTwo,
    /// One Sobol sequence over the whole image (spp rounded up to a power of two).
    Sobol,
    /// Mitchell's best-candidate blue noise.
    BestCandidate,
    /// Adaptive: zero-two, spp/4 samples, all spp where the first ones disagree.
    Adaptive,
    /// Owen-scrambled Sobol per pixel, hashed by pixel, frame and seed.
    #[value(alias = "sobol-owen")]
    OwenSobol,
    /// Sobol along a hash-permuted Morton curve: blue-noise error across pixels (spp rounded
    /// up to a power of two).
    #[value(name = "zsobol")]
    ZSobol,
    /// Progressive multi-jittered (0,2) points, shuffled and Owen-scrambled per pixel.
    Pmj02,
    /// Blue-noise dithered: one zero-two set for every pixel, toroidally shifted by a 64 × 64
    /// blue-noise mask, so the error is blue noise (spp rounded up to a power of two).
    #[value(name = "bluenoise-dithered")]
    BluenoiseDithered,
    /// The Fibonacci lattice per dimension pair, Cranley–Patterson rotated per pixel and pair
    /// (spp rounded up to a Fibonacci number).
    Fibonacci,
    /// Roberts' R2 per dimension pair, rotated per pixel and pair.
    #[value(name = "r2")]
    R2,
    /// The Korobov lattice of exactly spp points per dimension pair (multiplier minimising
    /// P2), Cranley–Patterson rotated per pixel and pair.
    Korobov,
}

impl SamplerName {
    /// The command-line name.
    pub fn name(self) -> String {
        self.to_possible_value()
            .map_or_else(String::new, |v| v.get_name().to_owned())
    }
}

/// The scrambles of `--scramble`: core's [`Scramble`], under the same names
/// ([`Scramble::name`]; a test holds them equal), and `permute` for `permute-digits`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ScrambleName {
    /// The plain sequence.
    None,
    /// A random permutation of the digits per digit position (and dimension).
    #[value(alias = "permute")]
    PermuteDigits,
    /// Burley's hash-based Owen scramble (Laine–Karras hash, Vegdahl's constants).
    FastOwen,
    /// The exact Owen scramble: one hash per digit.
    Owen,
}

impl ScrambleName {
    /// The core scramble.
    pub fn scramble(self) -> Scramble {
        match self {
            ScrambleName::None => Scramble::None,
            ScrambleName::PermuteDigits => Scramble::PermuteDigits,
            ScrambleName::FastOwen => Scramble::FastOwen,
            ScrambleName::Owen => Scramble::Owen,
        }
    }
}

/// The error for `spp` above [`nyquist::sampler::spp_limit`], naming `flag` (`--sampler`,
/// `--samplers`).
pub fn check_spp_limit(flag: &str, name: &str, spp: u32) -> Result<()> {
    match nyquist::sampler::spp_limit(name) {
        Some(max) if spp > max => {
            bail!("{flag} {name} --spp {spp}: {name} takes at most {max} samples per pixel")
        }
        _ => Ok(()),
    }
}

/// Builds sampler `name` for `spp` samples per pixel of a `size` image (core's
/// [`NamedSampler`]), with `scramble` if given (only the samplers of
/// [`SCRAMBLE_NAMES`](nyquist::sampler::SCRAMBLE_NAMES) take one: an error names `--scramble`
/// for the others). The error names the flag at fault. Samplers that round spp (zero-two,
/// sobol, adaptive) report the spp they use through [`Sampler::samples_per_pixel`].
pub fn build_sampler(
    name: SamplerName,
    spp: u32,
    size: [u32; 2],
    seed: u64,
    scramble: Option<ScrambleName>,
) -> Result<NamedSampler> {
    let n = name.name();
    if spp == 0 {
        bail!("--spp 0: need at least one sample per pixel");
    }
    if spp > 1 << 20 {
        bail!("--spp {spp}: at most {} samples per pixel", 1 << 20);
    }
    check_spp_limit("--sampler", &n, spp)?;
    let built = match scramble {
        Some(sc) => NamedSampler::with_scramble(&n, size, spp, seed, sc.scramble()),
        None => NamedSampler::new(&n, size, spp, seed),
    };
    built.map_err(|e| match e {
        NamedSamplerError::NoScramble => anyhow!("--scramble: --sampler {n}: {e}"),
        e => anyhow!("--sampler {n} --spp {spp}: {e}"),
    })
}

/// The reference image of `scene` seen through `filter` (`None`: the pixel means, i.e. the box).
///
/// The zone plate's references are exact: the Fresnel pixel means, or the filtered zone plate by
/// 1D quadrature ([`nyquist_lab::scene::zoneplate_filtered_reference`]; `None` for a non-separable
/// filter). For the other scenes it is a stratified `32 × 32` spp render through the filter,
/// cached under the user's cache folder (`$XDG_CACHE_HOME/nyquist`, else `~/.cache/nyquist`)
/// keyed by scene, size and filter spec.
pub fn reference(
    scene: Scene,
    size: [u32; 2],
    filter: Option<&FilterKind>,
    threads: usize,
) -> Result<Option<Vec<f64>>> {
    let bar = Progress::new(tile_count(size), "reference");
    let r = nyquist_lab::render::reference_with_progress(scene, size, filter, threads, &mut || {
        bar.inc(1)
    });
    bar.finish();
    r
}

/// Parses `WxH` (e.g. `256x256`) into an image size, each side 1 to [`MAX_SIDE`].
pub fn parse_size(s: &str) -> Result<[u32; 2], String> {
    let bad = || format!("'{s}' is not WxH with sides 1 to {MAX_SIDE} (e.g. 256x256)");
    let (a, b) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let side = |t: &str| match t.trim().parse::<u32>() {
        Ok(v) if (1..=MAX_SIDE).contains(&v) => Ok(v),
        _ => Err(bad()),
    };
    let size = [side(a)?, side(b)?];
    if u64::from(size[0]) * u64::from(size[1]) > MAX_PIXELS {
        return Err(format!("'{s}' has more than {MAX_PIXELS} pixels"));
    }
    Ok(size)
}

/// Parses a filter spec, the error listing the filters and keys.
pub fn parse_filter(s: &str) -> Result<FilterKind, String> {
    FilterKind::parse(s).map_err(|e| {
        format!(
            "{e} (filters: box, triangle, gaussian, mitchell, lanczos; e.g. mitchell:b=0.5,c=0.25)"
        )
    })
}

pub use crate::output::check_output;
pub use nyquist_lab::json::{json_number, json_string};
pub use nyquist_lab::render::{
    FILM_PIXEL_BYTES, IMAGE_PIXEL_BYTES, LARGE_WORK, MAX_PIXELS, MAX_SIDE, Rendered, TILE,
    channel0, default_threads, footprint_pixels, psnr, reference_kind, reference_with_progress,
    render, render_bytes, rmse, tile_count, warn_if_large,
};

/// Arguments of `nyquist render`.
#[derive(Debug, Args)]
#[command(
    after_help = "Example: nyquist render --scene zoneplate --sampler stratified --spp 16 \
    --filter mitchell --size 512x512 -o zoneplate.png --metrics"
)]
pub struct RenderArgs {
    /// The scene.
    #[arg(long, value_enum, default_value = "zoneplate")]
    pub scene: Scene,
    /// The pixel sampler.
    #[arg(long, value_enum, default_value = "stratified")]
    pub sampler: SamplerName,
    /// Samples per pixel (uniform and stratified: a √spp × √spp grid for a square, else the
    /// squarest rectangle of spp cells; zero-two, sobol and adaptive
    /// round up to a power of two).
    #[arg(long, default_value_t = 16)]
    pub spp: u32,
    /// Reconstruction filter spec `name[:key=value,…]`: box, triangle, gaussian, mitchell,
    /// lanczos (e.g. gaussian:alpha=2, mitchell:b=0.5,c=0.25).
    #[arg(long, value_name = "SPEC", default_value = "box", value_parser = parse_filter)]
    pub filter: FilterKind,
    /// Image size in pixels.
    #[arg(long, value_name = "WxH", default_value = "256x256", value_parser = parse_size)]
    pub size: [u32; 2],
    /// Worker threads [default: the number of cores]. The image is the same for any count.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=1024))]
    pub threads: Option<u16>,
    /// Seed of the sampler's random numbers and scrambles (0: unscrambled halton/hammersley).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Scramble of halton, sobol and zsobol [default: each sampler's own: digit permutation for
    /// halton when --seed is not 0, sobol's random digits, fast-owen for zsobol].
    #[arg(long, value_enum, value_name = "SCRAMBLE")]
    pub scramble: Option<ScrambleName>,
    /// Write the image here: .png (8-bit sRGB), .exr (32-bit float) or .pfm (32-bit float).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Compare with the reference and print RMSE, PSNR, samples per second and rejected samples.
    #[arg(long)]
    pub metrics: bool,
    /// Print the metrics as one JSON object (implies --metrics).
    #[arg(long)]
    pub json: bool,
    /// Also write the error image, the render minus the same filter's converged reference, as
    /// an 8-bit grey PNG: ½ + 4·error (mid grey is no error; ±0.125 reach white and black).
    #[arg(long, value_name = "FILE.png")]
    pub error: Option<PathBuf>,
}

/// Gain of `render --error`: grey level `½ + ERROR_GAIN · error`.
pub const ERROR_GAIN: f64 = 4.0;

/// Writes `½ + ERROR_GAIN · (image − reference)` (first channel) as an 8-bit grey PNG.
fn write_error_png(path: &std::path::Path, image: &Image, reference: &[f64]) -> Result<()> {
    let bytes: Vec<u8> = image
        .data()
        .chunks_exact(3)
        .zip(reference)
        .map(|(p, r)| {
            let g = 0.5 + ERROR_GAIN * (f64::from(p[0]) - r);
            (g.clamp(0.0, 1.0) * 255.0).round() as u8
        })
        .collect();
    crate::output::write_atomic(path, |w| {
        let mut enc = png::Encoder::new(w, image.width(), image.height());
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(png::BitDepth::Eight);
        let mut writer = enc.write_header().context("PNG header")?;
        writer.write_image_data(&bytes).context("PNG data")?;
        writer.finish().context("PNG end")?;
        Ok(())
    })
    .map_err(|e| anyhow!("{}", format!("{e:#}").replace("--output", "--error")))
}

/// Runs `nyquist render`.
pub fn run(args: &RenderArgs) -> Result<()> {
    let metrics = args.metrics || args.json;
    if args.output.is_none() && !metrics && args.error.is_none() {
        bail!("nothing to do: give --output FILE.png|.exr|.pfm, --metrics, --error FILE.png");
    }
    if let Some(p) = &args.error {
        check_output(p, "--error", &["png"])?;
    }
    if let Some(p) = &args.output {
        check_output(p, "--output", &["png", "exr", "pfm"])?;
        ImageFormat::from_path(p).map_err(|e| anyhow!("--output: {e}"))?;
    }
    let sampler = build_sampler(args.sampler, args.spp, args.size, args.seed, args.scramble)?;
    if sampler.samples_per_pixel() != args.spp {
        eprintln!(
            "nyquist: note: --sampler {} uses {}: --spp {} rounded up to {}",
            args.sampler.name(),
            if args.sampler == SamplerName::Fibonacci {
                "a Fibonacci number of samples"
            } else {
                "a power-of-two spp"
            },
            args.spp,
            sampler.samples_per_pixel()
        );
    }
    let threads = args.threads.map_or_else(default_threads, usize::from);
    nyquist_lab::memory::check(
        &format!(
            "--size {}x{}{}",
            args.size[0],
            args.size[1],
            if metrics { " with --metrics" } else { "" }
        ),
        render_bytes(args.scene, args.size, metrics),
    )?;
    let footprint = footprint_pixels(args.size, &args.filter);
    let pixels = f64::from(args.size[0]) * f64::from(args.size[1]);
    let large = warn_if_large(
        pixels * f64::from(sampler.samples_per_pixel()) * footprint,
        &format!(
            "--filter {} adds each of {} samples to up to {footprint} pixels",
            args.filter,
            pixels * f64::from(sampler.samples_per_pixel())
        ),
    );
    let bar = Progress::new(tile_count(args.size), "render");
    if large {
        bar.show_now();
    }
    let r = render(
        args.scene,
        args.size,
        &sampler,
        &args.filter,
        threads,
        &mut || bar.inc(1),
    )?;
    bar.finish();
    if let Some(p) = &args.output {
        let format = ImageFormat::from_path(p).map_err(|e| anyhow!("--output: {e}"))?;
        crate::output::write_atomic(p, |w| {
            Ok(nyquist_film::output::write_image(w, &r.image, format)?)
        })?;
    }
    if let Some(p) = &args.error {
        let filtered = reference(args.scene, args.size, Some(&args.filter), threads)?
            .with_context(|| format!("--error: no reference for --scene {}", args.scene.name()))?;
        write_error_png(p, &r.image, &filtered)?;
    }
    if metrics {
        let means = reference(args.scene, args.size, None, threads)?
            .context("no reference for this scene")?;
        let filtered = reference(args.scene, args.size, Some(&args.filter), threads)?;
        let e = rmse(&r.image, &means);
        let sampling = filtered.as_ref().map_or(f64::NAN, |f| rmse(&r.image, f));
        let rate = r.stats.samples as f64 / r.seconds.max(1e-9);
        let mut out = String::new();
        if args.json {
            writeln!(
                out,
                "{{\"scene\":{},\"size\":[{},{}],\"sampler\":{},\"spp\":{},\"filter\":{},\"threads\":{threads},\"seed\":{},\"reference\":{},\"rmse\":{},\"psnr\":{},\"sampling_rmse\":{},\"samples\":{},\"rejected\":{},\"seconds\":{},\"samples_per_second\":{}}}",
                json_string(args.scene.name()),
                args.size[0],
                args.size[1],
                json_string(&args.sampler.name()),
                sampler.samples_per_pixel(),
                json_string(&args.filter.to_string()),
                args.seed,
                json_string(&reference_kind(args.scene)),
                json_number(e),
                json_number(psnr(e)),
                json_number(sampling),
                r.stats.samples,
                r.stats.rejected,
                json_number(r.seconds),
                json_number(rate),
            )?;
        } else {
            writeln!(
                out,
                "{} {}x{}, {} {} spp, filter {}, {threads} thread{}",
                args.scene.name(),
                args.size[0],
                args.size[1],
                args.sampler.name(),
                sampler.samples_per_pixel(),
                args.filter,
                if threads == 1 { "" } else { "s" }
            )?;
            writeln!(out, "reference      {}", reference_kind(args.scene))?;
            writeln!(out, "rmse           {e:.6}")?;
            writeln!(out, "psnr           {:.2} dB", psnr(e))?;
            writeln!(
                out,
                "sampling rmse  {sampling:.6} (against the same filter's converged image)"
            )?;
            writeln!(out, "samples/s      {rate:.0}")?;
            writeln!(out, "samples        {}", r.stats.samples)?;
            writeln!(out, "rejected       {}", r.stats.rejected)?;
            writeln!(out, "time           {:.3} s", r.seconds)?;
        }
        crate::output::print(&out)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `--scramble`'s names are core's, each mapping to the scramble of that name.
    #[test]
    fn scramble_names_are_cores() {
        for v in ScrambleName::value_variants() {
            let name = v.to_possible_value().unwrap().get_name().to_owned();
            assert_eq!(Scramble::from_name(&name), Some(v.scramble()), "{name}");
        }
        assert_eq!(ScrambleName::value_variants().len(), Scramble::ALL.len());
    }
}
