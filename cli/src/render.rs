//! `nyquist render`: render a built-in scene with a sampler and a reconstruction filter, write the
//! image, and measure it against a reference.

use crate::progress::Progress;
use anyhow::{Context, Result, bail};
use clap::Args;
use nyquist::filter::FilterKind;
use nyquist::sampler::Sampler;
use nyquist_film::adaptive::AdaptiveConfig;
use nyquist_film::output::png::{PngColor, PngLayout, write_png_pixels};
use nyquist_film::{Image, ImageFormat};
use nyquist_lab::error_spectrum::error_spectrum;
use nyquist_lab::scene::Scene;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

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
    Ok(traced_reference(scene, size, filter, threads)?.map(|(r, _)| r))
}

/// [`reference()`], with where it came from ([`ReferenceSource`]).
pub fn traced_reference(
    scene: Scene,
    size: [u32; 2],
    filter: Option<&FilterKind>,
    threads: usize,
) -> Result<Option<(Vec<f64>, ReferenceSource)>> {
    let bar = Progress::new(tile_count(size), "reference");
    let r = nyquist_lab::render::reference_with_source(scene, size, filter, threads, &mut || {
        bar.inc(1)
    });
    bar.finish();
    r
}

pub use crate::output::check_output;
pub use nyquist_lab::json::{json_number, json_string};
pub use nyquist_lab::render::{
    Aov, Layers, PROGRESSIVE_SAMPLERS, SamplerName, ScrambleName, build_sampler, check_spp_limit,
    parse_filter, parse_size, render_layers,
};
pub use nyquist_lab::render::{
    FILM_PIXEL_BYTES, IMAGE_PIXEL_BYTES, LARGE_WORK, MAX_PIXELS, MAX_SIDE, ReferenceSource,
    Rendered, TILE, channel0, default_threads, describe_reference, footprint_pixels, psnr,
    reference_kind, reference_with_progress, render, render_bytes, rmse, tile_count, warn_if_large,
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
    #[arg(long, default_value_t = 16, value_parser = nyquist_lab::flags::whole(1, nyquist_lab::study::MAX_SPP))]
    pub spp: u32,
    /// Reconstruction filter spec `name[:key=value,…]`: box, triangle, gaussian, mitchell,
    /// catmull-rom, blackman-harris, lanczos (e.g. gaussian:alpha=2, mitchell:b=0.5,c=0.25).
    #[arg(long, value_name = "SPEC", default_value = "box", value_parser = parse_filter)]
    pub filter: FilterKind,
    /// Image size in pixels.
    #[arg(long, value_name = "WxH", default_value = "256x256", value_parser = parse_size)]
    pub size: [u32; 2],
    /// Worker threads [default: the number of cores]. The image is the same for any count.
    #[arg(long, value_parser = nyquist_lab::flags::whole(1u16, 1024))]
    pub threads: Option<u16>,
    /// Seed of the sampler's random numbers and scrambles.
    #[arg(long, default_value_t = 0, value_parser = nyquist_lab::flags::whole(0, u64::MAX))]
    pub seed: u64,
    /// Scramble of halton, hammersley (its dimensions from 2 on), sobol and zsobol [default:
    /// each sampler's own: digit permutation for halton, hammersley and sobol (every seed),
    /// fast-owen for zsobol; none: the unscrambled sequences].
    #[arg(long, value_enum, value_name = "SCRAMBLE")]
    pub scramble: Option<ScrambleName>,
    /// Write the image here: .png (8-bit sRGB), .exr (32-bit float) or .pfm (32-bit float); `-`
    /// for stdout. A symbolic link is written through; a device or FIFO is written in place.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// The image format where --output has no extension to tell it (`-`, /dev/stdout, a FIFO);
    /// an extension that names another format is an error.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<OutputFormat>,
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
    /// Keep the variance of each pixel's value (the delta method with the effective sample
    /// count; docs/film.md) and write it as the layer `variance`; --metrics then prints the
    /// RMSE it predicts.
    #[arg(long)]
    pub variance: bool,
    /// Keep the means of the two sample classes A and B (by the parity of popcount(index &
    /// 0xaaaa…), as Cycles splits them) and write them as the layers `half_a` and `half_b`;
    /// --metrics then prints the RMSE |A − B|/2 predicts.
    #[arg(long)]
    pub ab: bool,
    /// Keep extra channels, comma-separated: albedo, normal (camera space), depth (along the
    /// view axis; 1e10 for the sky), filtered like the image.
    #[arg(long, value_enum, value_delimiter = ',', value_name = "LIST")]
    pub aov: Vec<Aov>,
    /// Adaptive sampling by error: --spp becomes the budget (samples per pixel on average); a
    /// first pass of a quarter of it (at least 16), then passes that double the samples of the
    /// pixels whose relative error, |A − B|/2 over the value (docs/film.md), is above THRESHOLD,
    /// worst first, up to 16 × --spp in a pixel. Progressive samplers only (random, halton,
    /// sobol, zero-two, owen-sobol, owen-sobol-bn, zsobol, pmj02, pmj02-bn, r2, lattice-bn).
    #[arg(long, value_name = "THRESHOLD", value_parser = nyquist_lab::flags::number(0.0, 1e6))]
    pub adaptive: Option<f64>,
    /// With --adaptive, also write where the samples went as a grey PNG: log₂ of each pixel's
    /// samples from the fewest (black) to the most (white).
    #[arg(long, value_name = "FILE.png")]
    pub spp_map: Option<PathBuf>,
    /// Make the sampler for this many samples per pixel and draw --spp of them, past it where
    /// --spp is larger: progressive rendering past the spp a sampler was set up with.
    /// Samplers whose every sample index is new only (random, halton, sobol, owen-sobol,
    /// zsobol, pmj02); not with --adaptive.
    #[arg(long, value_name = "N", conflicts_with = "adaptive",
          value_parser = nyquist_lab::flags::whole(1, nyquist_lab::study::MAX_SPP))]
    pub spp_hint: Option<u32>,
}

/// The image formats of `render --format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum OutputFormat {
    /// 8-bit sRGB PNG.
    Png,
    /// OpenEXR, 32-bit float.
    Exr,
    /// Portable float map, 32-bit float.
    Pfm,
}

impl OutputFormat {
    /// The name, as the extension and the flag value.
    pub fn name(self) -> &'static str {
        match self {
            OutputFormat::Png => "png",
            OutputFormat::Exr => "exr",
            OutputFormat::Pfm => "pfm",
        }
    }
}

/// The image format of `render --output path`: by `--format`, else by the extension.
///
/// # Errors
/// As [`crate::output::choose_format`].
pub fn image_format(path: &Path, format: Option<OutputFormat>) -> Result<ImageFormat> {
    let name = crate::output::choose_format(
        path,
        "--output",
        &["png", "exr", "pfm"],
        format.map(OutputFormat::name),
        Some("--format"),
    )?;
    Ok(match name {
        "exr" => ImageFormat::Exr,
        "pfm" => ImageFormat::Pfm,
        _ => ImageFormat::Png,
    })
}

/// Gain of `render --error`: grey level `½ + ERROR_GAIN · error`.
pub const ERROR_GAIN: f64 = 4.0;

/// Writes `½ + ERROR_GAIN · (image − reference)` (first channel) as an 8-bit grey PNG.
fn write_error_png(path: &Path, image: &Image, reference: &[f64]) -> Result<()> {
    let bytes: Vec<u8> = image
        .data()
        .chunks_exact(3)
        .zip(reference)
        .map(|(p, r)| {
            let g = 0.5 + ERROR_GAIN * (f64::from(p[0]) - r);
            (g.clamp(0.0, 1.0) * 255.0).round() as u8
        })
        .collect();
    let layout = PngLayout::new(image.width(), image.height(), PngColor::Grey);
    crate::output::write_output(path, "--error", |out| {
        Ok(write_png_pixels(out, &layout, &bytes)?)
    })
}

/// The layers `render` keeps (`--variance`, `--ab`, `--aov`).
///
/// # Errors
/// An `--aov` group given twice.
fn layers(args: &RenderArgs) -> Result<Layers> {
    for (i, a) in args.aov.iter().enumerate() {
        if args.aov[..i].contains(a) {
            let list: Vec<&str> = args.aov.iter().map(|a| a.name()).collect();
            bail!("--aov {}: {} is given twice", list.join(","), a.name());
        }
    }
    Ok(Layers {
        variance: args.variance,
        halves: args.ab,
        aovs: args.aov.clone(),
        adaptive: None,
        spp: None,
    })
}

/// The path of layer `name` beside `path`: `out.png` → `out.variance.png`.
fn layer_path(path: &Path, name: &str, ext: &str) -> PathBuf {
    let stem = path
        .file_stem()
        .map_or_else(Default::default, |s| s.to_os_string());
    let mut file = stem;
    file.push(format!(".{name}.{ext}"));
    path.with_file_name(file)
}

/// Writes the image and its layers: one OpenEXR file of named planes for `.exr`; else the image
/// to `path` and each layer group beside it (`out.variance.png`, `out.half_a.png`, …,
/// `out.depth.png`; a group of one channel as grey), each file whole or not at all. Returns the
/// layer files written.
fn write_layers(
    path: &Path,
    format: ImageFormat,
    r: &Rendered,
    layers: &Layers,
) -> Result<Vec<PathBuf>> {
    let names = layers.channel_names();
    if matches!(format, ImageFormat::Exr | ImageFormat::ExrHalf) {
        let planes = r.extras.planes(&r.image, &names)?;
        let borrowed: Vec<(&str, &[f32])> = planes
            .iter()
            .map(|(n, p)| (n.as_str(), p.as_slice()))
            .collect();
        let (w, h) = (r.image.width(), r.image.height());
        crate::output::write_atomic(path, |out| {
            Ok(nyquist_film::output::exr::write_exr_planes(
                out, w, h, &borrowed,
            )?)
        })?;
        return Ok(Vec::new());
    }
    if crate::output::is_stdout(path) {
        bail!(
            "--output -: the layers of --variance, --ab and --aov go to files beside the image, or into one --format exr stream"
        );
    }
    crate::output::write_atomic(path, |w| {
        Ok(nyquist_film::output::write_image(w, &r.image, format)?)
    })?;
    let ext = if format == ImageFormat::Pfm {
        "pfm"
    } else {
        "png"
    };
    let mut groups: Vec<(String, Image)> = Vec::new();
    if let Some(v) = &r.extras.variance {
        groups.push(("variance".into(), v.clone()));
    }
    if let Some([a, b]) = &r.extras.halves {
        groups.push(("half_a".into(), a.clone()));
        groups.push(("half_b".into(), b.clone()));
    }
    if let Some(c) = &r.extras.channels {
        let mut k = 0;
        for a in &layers.aovs {
            let n = a.channels().len();
            let image = Image::from_fn(c.width(), c.height(), |x, y| {
                let p = &c.pixel(x, y)[k..k + n];
                if n == 1 {
                    [p[0]; 3]
                } else {
                    [p[0], p[1], p[2]]
                }
            });
            groups.push((a.name().into(), image));
            k += n;
        }
    }
    let mut written = Vec::new();
    for (name, image) in groups {
        let file = layer_path(path, &name, ext);
        crate::output::write_output(&file, "--output", |w| {
            Ok(nyquist_film::output::write_image(w, &image, format)?)
        })?;
        written.push(file);
    }
    Ok(written)
}

/// The RMSE a render's kept estimates predict, over the first channel: from the variance,
/// √(mean Var), and from the halves, √(mean ((A − B)/2)²); `None` for an estimate not kept or
/// undefined in every pixel (one sample per pixel has no variance).
fn predicted_rmse(r: &Rendered) -> [Option<f64>; 2] {
    let mean_sqrt = |values: &mut dyn Iterator<Item = f64>| {
        let (mut sum, mut n) = (0.0, 0u64);
        for v in values.filter(|v| v.is_finite()) {
            sum += v;
            n += 1;
        }
        (n > 0).then(|| (sum / n as f64).sqrt())
    };
    let variance = r
        .extras
        .variance
        .as_ref()
        .and_then(|v| mean_sqrt(&mut v.data().iter().step_by(3).map(|&v| f64::from(v))));
    let halves = r.extras.halves.as_ref().and_then(|[a, b]| {
        mean_sqrt(
            &mut a
                .data()
                .iter()
                .zip(b.data())
                .step_by(3)
                .map(|(&a, &b)| (0.5 * (f64::from(a) - f64::from(b))).powi(2)),
        )
    });
    [variance, halves]
}

/// Runs `nyquist render`.
pub fn run(args: &RenderArgs) -> Result<()> {
    let metrics = args.metrics || args.json;
    let mut layers = layers(args)?;
    if args.output.is_none() && !metrics && args.error.is_none() {
        bail!("nothing to do: give --output FILE.png|.exr|.pfm, --metrics, --error FILE.png");
    }
    let stdout = |p: &Option<PathBuf>| p.as_deref().is_some_and(crate::output::is_stdout);
    if stdout(&args.output) && stdout(&args.error) {
        bail!("--output - and --error -: only one of them can go to stdout");
    }
    for (flag, p) in [("--output", &args.output), ("--error", &args.error)] {
        if metrics && stdout(p) {
            bail!(
                "{flag} -: stdout carries the {}: give {flag} FILE",
                if args.json {
                    "JSON (--json)"
                } else {
                    "metrics (--metrics)"
                }
            );
        }
    }
    if let Some(p) = &args.error {
        check_output(p, "--error", &["png"])?;
    }
    let format = match &args.output {
        Some(p) => {
            let format = image_format(p, args.format)?;
            crate::output::check_target(p, "--output")?;
            Some(format)
        }
        None => {
            if let Some(f) = args.format {
                crate::output::note(&format!("--format {} applies to --output only", f.name()));
            }
            None
        }
    };
    if let Some(p) = &args.spp_map {
        if args.adaptive.is_none() {
            bail!("--spp-map {}: only with --adaptive", p.display());
        }
        check_output(p, "--spp-map", &["png"])?;
    }
    let adaptive = match args.adaptive {
        Some(threshold) => {
            if !PROGRESSIVE_SAMPLERS.contains(&args.sampler) {
                let names: Vec<&str> = PROGRESSIVE_SAMPLERS.iter().map(|s| s.name()).collect();
                bail!(
                    "--adaptive {threshold}: --sampler {} lays out a fixed set for its spp; adaptive sampling takes one of {}",
                    args.sampler.name(),
                    names.join(", ")
                );
            }
            let mut config = AdaptiveConfig::new(args.spp, threshold);
            config.max_spp = config.max_spp.min(nyquist_lab::study::MAX_SPP);
            if config.initial_spp < 2 {
                bail!(
                    "--adaptive {threshold}: --spp {} leaves no second sample to compare the first with; give --spp 2 or more",
                    args.spp
                );
            }
            Some(config)
        }
        None => None,
    };
    if let Some(hint) = args.spp_hint
        && !args.sampler.continues()
    {
        bail!(
            "--spp-hint {hint}: --sampler {} lays out a fixed set for its spp; drawing past it takes one of {}",
            args.sampler.name(),
            nyquist::sampler::CONTINUING_NAMES.join(", ")
        );
    }
    // Adaptive sampling draws up to max_spp samples in a pixel: the sampler is made for them.
    let sampler_spp = adaptive.map_or(args.spp_hint.unwrap_or(args.spp), |a| a.max_spp);
    let sampler = build_sampler(
        args.sampler,
        sampler_spp,
        args.size,
        args.seed,
        args.scramble,
    )?;
    if adaptive.is_none() && args.spp_hint.is_none() && sampler.samples_per_pixel() != args.spp {
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
    // The samples each pixel takes: the sampler's, or --spp past its --spp-hint.
    let spp_drawn = args
        .spp_hint
        .map_or(sampler.samples_per_pixel(), |_| args.spp);
    let threads = args.threads.map_or_else(default_threads, usize::from);
    // The layers: the film's extra sums, and their images (4 bytes a value).
    layers.adaptive = adaptive;
    layers.spp = args.spp_hint.map(|_| args.spp);
    let extras = layers.extras();
    let values = 3 * (u64::from(extras.variance) + 2 * u64::from(extras.halves))
        + u64::from(extras.channels);
    let layer_bytes = (extras.bytes_per_pixel() as u64 + 4 * values)
        * u64::from(args.size[0])
        * u64::from(args.size[1]);
    nyquist_lab::memory::check(
        &format!(
            "--size {}x{}{}{}",
            args.size[0],
            args.size[1],
            if metrics { " with --metrics" } else { "" },
            if extras.any() { " and its layers" } else { "" }
        ),
        render_bytes(args.scene, args.size, metrics) + layer_bytes,
    )?;
    let footprint = footprint_pixels(args.size, &args.filter);
    let pixels = f64::from(args.size[0]) * f64::from(args.size[1]);
    let large = warn_if_large(
        pixels * f64::from(spp_drawn) * footprint,
        &format!(
            "--filter {} adds each of {} samples to up to {footprint} pixels",
            args.filter,
            pixels * f64::from(spp_drawn)
        ),
    );
    // Adaptive rendering counts samples against its budget (each pass reports its own).
    let bar = match &adaptive {
        Some(a) => Progress::with_unit(
            u64::from(a.budget_spp) * u64::from(args.size[0]) * u64::from(args.size[1]),
            "adaptive",
            "samples",
        ),
        None => Progress::new(tile_count(args.size), "render"),
    };
    if large {
        bar.show_now();
    }
    let r = render_layers(
        args.scene,
        args.size,
        &sampler,
        &args.filter,
        threads,
        &layers,
        &mut |n| bar.inc(n),
    )?;
    bar.finish();
    if let (Some(p), Some(report)) = (&args.spp_map, &r.adaptive) {
        let map = report.spp_image()?;
        crate::output::write_output(p, "--spp-map", |w| {
            Ok(nyquist_film::output::write_image(
                w,
                &map,
                ImageFormat::Png,
            )?)
        })?;
    }
    match (&args.output, format) {
        (Some(p), Some(format)) if layers.any() => {
            let written = write_layers(p, format, &r, &layers)?;
            if !written.is_empty() {
                let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
                crate::output::note(&format!("layers written to {}", names.join(", ")));
            }
        }
        (Some(p), Some(format)) => {
            crate::output::write_atomic(p, |w| {
                Ok(nyquist_film::output::write_image(w, &r.image, format)?)
            })?;
        }
        _ => {}
    }
    if let Some(p) = &args.error {
        let filtered = reference(args.scene, args.size, Some(&args.filter), threads)?
            .with_context(|| format!("--error: no reference for --scene {}", args.scene.name()))?;
        write_error_png(p, &r.image, &filtered)?;
    }
    if metrics {
        let (means, source) = traced_reference(args.scene, args.size, None, threads)?
            .context("no reference for this scene")?;
        let described = describe_reference(args.scene, source);
        let filtered = reference(args.scene, args.size, Some(&args.filter), threads)?;
        let e = rmse(&r.image, &means);
        let sampling = filtered.as_ref().map_or(f64::NAN, |f| rmse(&r.image, f));
        let rate = r.stats.samples as f64 / r.seconds.max(1e-9);
        let [by_variance, by_halves] = predicted_rmse(&r);
        // The sampling error's spectrum: how blue the error is (docs/blue-noise.md).
        let spectrum = filtered.as_ref().and_then(|f| {
            let error: Vec<f64> = r
                .image
                .data()
                .chunks_exact(3)
                .zip(f)
                .map(|(p, r)| f64::from(p[0]) - r)
                .collect();
            error_spectrum(&error, r.image.width(), r.image.height()).ok()
        });
        let mut out = String::new();
        if args.json {
            // A number, or null where there is none (no prediction, no spectrum).
            let or_null = |p: Option<f64>| p.map_or_else(|| "null".to_string(), json_number);
            writeln!(
                out,
                "{{\"scene\":{},\"size\":[{},{}],\"sampler\":{},\"spp\":{},\"filter\":{},\"threads\":{threads},\"seed\":{},\"reference\":{},\"rmse\":{},\"psnr\":{},\"sampling_rmse\":{},\"predicted_rmse_variance\":{},\"predicted_rmse_halves\":{},\"adaptive\":{},\"error_low_frequency_ratio\":{},\"error_low_frequency_ratio_se\":{},\"error_low_frequency_rmse\":{},\"error_radial_spectrum\":{},\"samples\":{},\"rejected\":{},\"seconds\":{},\"samples_per_second\":{}}}",
                json_string(args.scene.name()),
                args.size[0],
                args.size[1],
                json_string(args.sampler.name()),
                spp_drawn,
                json_string(&args.filter.to_string()),
                args.seed,
                json_string(&described),
                json_number(e),
                json_number(psnr(e)),
                json_number(sampling),
                or_null(by_variance),
                or_null(by_halves),
                match (&adaptive, &r.adaptive) {
                    (Some(a), Some(report)) => format!(
                        "{{\"threshold\":{},\"mean_spp\":{},\"passes\":{},\"converged\":{},\"largest_spp\":{}}}",
                        json_number(a.threshold),
                        json_number(report.mean_spp()),
                        report.passes,
                        report.converged,
                        report.spp.iter().max().copied().unwrap_or(0)
                    ),
                    _ => "null".to_string(),
                },
                or_null(spectrum.as_ref().map(|s| s.low_frequency_ratio)),
                or_null(spectrum.as_ref().map(|s| s.low_frequency_ratio_se)),
                or_null(spectrum.as_ref().map(|s| s.low_frequency_rmse)),
                spectrum.as_ref().map_or_else(
                    || "null".to_string(),
                    |s| {
                        let cells: Vec<String> = s.radial.iter().map(|&v| json_number(v)).collect();
                        format!("[{}]", cells.join(","))
                    }
                ),
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
                spp_drawn,
                args.filter,
                if threads == 1 { "" } else { "s" }
            )?;
            writeln!(out, "reference      {described}")?;
            writeln!(out, "rmse           {e:.6}")?;
            writeln!(out, "psnr           {:.2} dB", psnr(e))?;
            writeln!(
                out,
                "sampling rmse  {sampling:.6} (against the same filter's converged image)"
            )?;
            if let Some(s) = &spectrum {
                // An image of sides 8 or less has no frequency in the band: "-", as an annulus.
                let ratio = if s.low_frequency_ratio.is_finite() {
                    format!(
                        "{:.3} ± {:.3}",
                        s.low_frequency_ratio, s.low_frequency_ratio_se
                    )
                } else {
                    "-".into()
                };
                writeln!(
                    out,
                    "error spectrum low-frequency ratio {ratio} (mean power below ¼ Nyquist over white noise's: 1 white, below 1 blue; ± its standard error)"
                )?;
                writeln!(
                    out,
                    "error spectrum low-frequency rmse {:.6} (the error an ideal low-pass at ¼ Nyquist leaves)",
                    s.low_frequency_rmse
                )?;
                let cells: Vec<String> = s
                    .radial
                    .iter()
                    .map(|v| {
                        if v.is_finite() {
                            format!("{v:.2}")
                        } else {
                            "-".into()
                        }
                    })
                    .collect();
                writeln!(
                    out,
                    "radial power   {} (annuli of 1/32 cycle per pixel up to Nyquist, over white's)",
                    cells.join(" ")
                )?;
            }
            let kept = |flag: &str, on: bool, p: Option<f64>, how: &str| match (on, p) {
                (false, _) => None,
                (true, Some(p)) => Some(format!("predicted rmse {p:.6} ({how}, {flag})")),
                (true, None) => Some(format!(
                    "predicted rmse - ({how}, {flag}: no pixel has two samples in it)"
                )),
            };
            for line in [
                kept("--variance", args.variance, by_variance, "√ mean variance"),
                kept("--ab", args.ab, by_halves, "√ mean ((A − B)/2)²"),
            ]
            .into_iter()
            .flatten()
            {
                writeln!(out, "{line}")?;
            }
            if let (Some(a), Some(report)) = (&adaptive, &r.adaptive) {
                writeln!(
                    out,
                    "adaptive       {:.2} spp on average ({} samples), {} passes, {} of {} pixels converged at relative error {} (largest {} spp)",
                    report.mean_spp(),
                    report.samples,
                    report.passes,
                    report.converged,
                    report.spp.len(),
                    a.threshold,
                    report.spp.iter().max().copied().unwrap_or(0)
                )?;
            }
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
    use clap::ValueEnum;
    use nyquist::scramble::Scramble;

    /// `--sampler`'s names are the lab's `name()` and core's `NAMES`, in the same order.
    #[test]
    fn sampler_names_are_cores() {
        let flags: Vec<String> = SamplerName::value_variants()
            .iter()
            .map(|v| v.to_possible_value().unwrap().get_name().to_owned())
            .collect();
        let names: Vec<&str> = SamplerName::value_variants()
            .iter()
            .map(|v| v.name())
            .collect();
        assert_eq!(flags, names);
        let mut core = nyquist::sampler::NAMES.to_vec();
        let mut ours = names.clone();
        core.sort_unstable();
        ours.sort_unstable();
        assert_eq!(ours, core);
    }

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
