//! `pathtracer`: renders the analytic scenes with any nyquist sampler, and runs the camera ×
//! light samples experiment. See `docs/path-tracer.md`.

use std::io::IsTerminal;
use std::path::PathBuf;

use anyhow::Context;
use anyhow::{Result, anyhow, bail};
use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use nyquist::filter::FilterKind;
use nyquist_examples::experiment::{
    Experiment, contact_sheet, light_layouts_markdown, markdown, markdown_equal_time,
    pixel_reference, pixel_study,
};
use nyquist_examples::trace::{Derivation, LightSamples};
use nyquist_examples::{RenderConfig, adaptive_study, render};
use nyquist_film::adaptive::AdaptiveConfig;
use nyquist_film::{Image, write_image_file};

#[derive(Parser, Debug)]
#[command(
    name = "pathtracer",
    about = "A path tracer over nyquist's samplers and film"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Renders a scene to EXR, PNG or PFM (by the output's extension).
    ///
    /// Example: pathtracer render --scene cornell --sampler pmj02 --spp 64 --light-samples 4 -o c.exr
    Render(RenderArgs),
    /// 1 × 16, 16 × 1 and 4 × 4 camera × light samples per pixel for each sampler, against a
    /// cached converged reference: prints a Markdown table, optionally writes a contact sheet.
    Experiment(ExperimentArgs),
    /// The path tracer's estimate of one pixel as an integrand: RMSE over seeds against N
    /// camera samples (one light sample each) for each sampler, and the slope.
    ///
    /// Example: pathtracer converge --pixel 100,180 --samplers random,sobol,owen-sobol
    Converge(ConvergeArgs),
    /// Adaptive sampling by error against uniform spp and the contrast-test sampler at equal
    /// RMSE, against a cached converged reference: prints a Markdown table, optionally writes
    /// the spp map of the middle budget.
    ///
    /// Example: pathtracer adaptive --scene dof --budgets 32,64,128 --map dof-spp.png
    Adaptive(AdaptiveArgs),
    /// Light samples varying per vertex, three ways: pbrt-v2's arrays sized up front,
    /// pbrt-v4's dimension counter, and domains split per vertex; RMSE against the cached
    /// reference as a Markdown table.
    ///
    /// Example: pathtracer domains --light-samples 4,2,1 --spp 16
    Domains(DomainsArgs),
}

#[derive(clap::Args, Debug)]
struct DomainsArgs {
    /// Scene.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Image size WxH.
    #[arg(long, default_value = "128x128", value_parser = parse_size)]
    size: [u32; 2],
    /// Camera samples per pixel.
    #[arg(long, default_value_t = 16)]
    spp: u32,
    /// Light samples per vertex (N1,N2,…).
    #[arg(long, default_value = "4,2,1", value_parser = LightSamples::parse)]
    light_samples: LightSamples,
    /// Samplers of the arrays and counter rows (the domain row is owen-sobol's).
    #[arg(long, value_delimiter = ',', default_value = "owen-sobol,pmj02,zsobol")]
    samplers: Vec<String>,
    /// Renders (seeds) per configuration.
    #[arg(long, default_value_t = 8)]
    runs: u32,
    /// Base seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Camera samples per pixel of the reference (× 4 light samples).
    #[arg(long, default_value_t = 1024)]
    reference_spp: u32,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
}

#[derive(clap::Args, Debug)]
struct AdaptiveArgs {
    /// Scene.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Image size WxH.
    #[arg(long, default_value = "128x128", value_parser = parse_size)]
    size: [u32; 2],
    /// The progressive sampler of the uniform and adaptive renders.
    #[arg(long, default_value = "owen-sobol")]
    sampler: String,
    /// Budgets (samples per pixel on average), comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "32,64,128")]
    budgets: Vec<u32>,
    /// Relative errors at which a pixel stops, comma-separated: one adaptive render per
    /// budget and threshold.
    #[arg(long, value_delimiter = ',', default_value = "0.05,0.02")]
    thresholds: Vec<f64>,
    /// Added to a pixel's value in the relative error's denominator (large: the error is
    /// nearly absolute).
    #[arg(long, default_value_t = 1.0)]
    floor: f64,
    /// Seeds: every configuration is rendered with seeds 1 … N, its RMSE the root of the mean
    /// squared RMSE.
    #[arg(long, default_value_t = 4)]
    seeds: u32,
    /// Camera samples per pixel of the reference (× 4 light samples).
    #[arg(long, default_value_t = 65536)]
    reference_spp: u32,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Write the spp map of the middle budget's adaptive render (the first threshold, the first
    /// seed) here (PNG).
    #[arg(long)]
    map: Option<PathBuf>,
    /// Write the middle budget's uniform and adaptive renders side by side here.
    #[arg(long)]
    sheet: Option<PathBuf>,
}

#[derive(clap::Args, Debug)]
struct ConvergeArgs {
    /// Scene.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Image size WxH.
    #[arg(long, default_value = "256x256", value_parser = parse_size)]
    size: [u32; 2],
    /// The pixel X,Y.
    #[arg(long, default_value = "100,180", value_parser = parse_pixel)]
    pixel: [u32; 2],
    /// Samplers, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "random,stratified,halton-plain,halton,sobol-plain,sobol,owen-sobol,zsobol,pmj02,zero-two"
    )]
    samplers: Vec<String>,
    /// Smallest N (a power of four: N = 4, 16, 64, … so that stratified takes every N).
    #[arg(long, default_value_t = 4)]
    min_spp: u32,
    /// Largest N (a power of four).
    #[arg(long, default_value_t = 4096)]
    max_spp: u32,
    /// Seeds per N.
    #[arg(long, default_value_t = 32)]
    runs: u32,
}

#[derive(clap::Args, Debug)]
struct RenderArgs {
    /// Scene: cornell or dof.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Sampler name (nyquist's names, plus halton-plain and sobol-plain).
    #[arg(long, default_value = "owen-sobol")]
    sampler: String,
    /// Camera samples per pixel.
    #[arg(long, default_value_t = 16)]
    spp: u32,
    /// Light samples per camera sample at each vertex: N (at the first vertex, one at the
    /// others) or a list N1,N2,… (one per vertex from the first; one past the list).
    #[arg(long, default_value = "1", value_parser = LightSamples::parse)]
    light_samples: LightSamples,
    /// Image size WxH.
    #[arg(long, default_value = "256x256", value_parser = parse_size)]
    size: [u32; 2],
    /// Sampler seed (0 leaves halton and sobol unscrambled).
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Reconstruction filter spec (box, triangle, gaussian, mitchell, catmull-rom,
    /// blackman-harris, lanczos[:key=value,…]).
    #[arg(long, default_value = "box")]
    filter: String,
    /// Draw the values through the stateless layer (camera_sample, get_array_2d, get_2d, get_1d,
    /// only as far as each path goes) instead of SampleLayout and PixelRangeSampler.
    #[arg(long)]
    stateless: bool,
    /// With --stateless: make the sampler for this many samples per pixel and draw --spp of
    /// them, past it where --spp is larger (random, halton, sobol, owen-sobol, owen-sobol-bn, zsobol, pmj02, pmj02-bn, lattice-bn).
    #[arg(long, value_name = "N", requires = "stateless")]
    spp_hint: Option<u32>,
    /// With --stateless, draw the light points one get_2d each (pbrt-v4's counter) instead of
    /// one get_array_2d per vertex.
    #[arg(long, requires = "stateless")]
    counter: bool,
    /// Draw the values past the camera sample from the camera sample's domains, light sample j
    /// of vertex k by Domain::split(k, N_k, j), distribute(k, j) or chain(k, j) (owen-sobol
    /// only).
    #[arg(long, value_name = "split|distribute|chain", value_parser = Derivation::parse,
          conflicts_with_all = ["stateless", "adaptive"])]
    domains: Option<Derivation>,
    /// Adaptive sampling by error (docs/film.md): --spp becomes the budget; pixels whose
    /// relative error |A − B|/2 over the value is above THRESHOLD double their samples, worst
    /// first. Progressive samplers (owen-sobol, sobol, pmj02, zsobol, halton, random).
    #[arg(long, value_name = "THRESHOLD")]
    adaptive: Option<f64>,
    /// With --adaptive, also write the spp map (PNG: log₂ spp from the fewest, black, to the
    /// most, white).
    #[arg(long)]
    spp_map: Option<PathBuf>,
    /// Output image (.exr, .png or .pfm).
    #[arg(short, long)]
    output: PathBuf,
}

#[derive(clap::Args, Debug)]
struct ExperimentArgs {
    /// Scene.
    #[arg(long, default_value = "cornell")]
    scene: String,
    /// Samplers, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "random,stratified,halton-plain,halton,sobol,owen-sobol,zsobol,pmj02"
    )]
    samplers: Vec<String>,
    /// Image size WxH.
    #[arg(long, default_value = "128x128", value_parser = parse_size)]
    size: [u32; 2],
    /// Renders (seeds) per configuration.
    #[arg(long, default_value_t = 4)]
    runs: u32,
    /// Base seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Camera samples per pixel of the reference (× 4 light samples).
    #[arg(long, default_value_t = 1024)]
    reference_spp: u32,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Contact sheet PNG: a row per sampler, columns 1×16, 16×1, 4×4, reference.
    #[arg(long)]
    sheet: Option<PathBuf>,
}

fn parse_size(s: &str) -> Result<[u32; 2], String> {
    let (w, h) = s.split_once('x').ok_or("expected WxH")?;
    let p = |v: &str| v.trim().parse::<u32>().map_err(|e| format!("{v:?}: {e}"));
    let size = [p(w)?, p(h)?];
    if size.contains(&0) {
        return Err("sizes must be positive".into());
    }
    Ok(size)
}

fn parse_pixel(s: &str) -> Result<[u32; 2], String> {
    let (x, y) = s.split_once(',').ok_or("expected X,Y")?;
    let p = |v: &str| v.trim().parse::<u32>().map_err(|e| format!("{v:?}: {e}"));
    Ok([p(x)?, p(y)?])
}

fn threads(t: Option<usize>) -> usize {
    t.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1)
}

/// A progress bar on stderr, drawn only when stderr is a terminal.
fn bar(message: &str, unit: &str) -> ProgressBar {
    let target = if std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    let bar = ProgressBar::with_draw_target(None, target);
    let style = ProgressStyle::with_template(&format!(
        "{{msg}} [{{elapsed_precise}}] {{wide_bar}} {{pos}}/{{len}} {unit} (eta {{eta}})"
    ))
    .unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style);
    bar.set_message(message.to_owned());
    bar
}

fn tick(bar: &ProgressBar) -> impl FnMut(usize, usize) + '_ {
    |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    }
}

fn main() -> Result<()> {
    match Cli::parse().command {
        Command::Render(a) => {
            let filter = FilterKind::parse(&a.filter).map_err(|e| anyhow!("--filter: {e}"))?;
            let mut config = RenderConfig::new(&a.scene);
            config.size = a.size;
            config.spp = a.spp;
            config.light_samples = a.light_samples;
            config.sampler = a.sampler;
            config.seed = a.seed;
            config.threads = threads(a.threads);
            config.filter = filter;
            config.stateless = a.stateless;
            config.counter = a.counter;
            config.spp_hint = a.spp_hint;
            config.domains = a.domains;
            if a.spp_map.is_some() && a.adaptive.is_none() {
                bail!("--spp-map: only with --adaptive");
            }
            if let Some(t) = a.adaptive {
                check_threshold("--adaptive", t)?;
                config.adaptive = Some(AdaptiveConfig::new(a.spp, t));
            }
            let bar = bar("render", "tiles");
            let out = render(&config, tick(&bar))?;
            bar.finish_and_clear();
            write_image_file(&a.output, &out.image)?;
            if let Some(report) = &out.adaptive {
                eprintln!(
                    "adaptive: {:.2} spp on average over {} passes, {} pixels converged",
                    report.mean_spp(),
                    report.passes,
                    report.converged
                );
                if let Some(p) = &a.spp_map {
                    write_image_file(p, &report.spp_image()?)?;
                }
            }
            let per_thread = out.samples as f64 / out.seconds / config.threads as f64;
            eprintln!(
                "{} camera samples in {:.3} s on {} threads: {:.0} samples/s, {:.0} per thread",
                out.samples,
                out.seconds,
                config.threads,
                out.samples as f64 / out.seconds,
                per_thread
            );
        }
        Command::Converge(a) => converge(a)?,
        Command::Adaptive(a) => adaptive(a)?,
        Command::Domains(a) => {
            if a.runs == 0 {
                bail!("--runs must be positive");
            }
            let e = Experiment {
                scene: a.scene,
                size: a.size,
                samplers: a.samplers,
                runs: a.runs,
                seed: a.seed,
                threads: threads(a.threads),
                reference_spp: a.reference_spp,
            };
            let bar1 = bar("reference", "tiles");
            let reference = e.reference(tick(&bar1))?;
            bar1.finish_and_clear();
            let bar2 = bar("domains", "renders");
            let rows = e.light_layouts(a.spp, &a.light_samples, &reference, tick(&bar2))?;
            bar2.finish_and_clear();
            print!("{}", light_layouts_markdown(&rows));
        }
        Command::Experiment(a) => {
            if a.runs == 0 {
                bail!("--runs must be positive");
            }
            let e = Experiment {
                scene: a.scene,
                size: a.size,
                samplers: a.samplers,
                runs: a.runs,
                seed: a.seed,
                threads: threads(a.threads),
                reference_spp: a.reference_spp,
            };
            let bar1 = bar("reference", "tiles");
            let reference = e.reference(tick(&bar1))?;
            bar1.finish_and_clear();
            let bar2 = bar("experiment", "renders");
            let cells = e.run(&reference, tick(&bar2))?;
            bar2.finish_and_clear();
            print!("{}", markdown(&cells));
            println!("\nMeasured at equal time (camera samples scaled to the time of 16×1):\n");
            print!("{}", markdown_equal_time(&cells));
            if let Some(p) = a.sheet {
                write_image_file(&p, &contact_sheet(&cells, &reference))?;
            }
        }
    }
    Ok(())
}

/// Refuses a `flag` value that is not a relative error threshold (finite, ≥ 0).
fn check_threshold(flag: &str, t: f64) -> Result<()> {
    if !(t.is_finite() && t >= 0.0) {
        bail!("{flag} {t}: not a threshold (a relative error ≥ 0)");
    }
    Ok(())
}

fn adaptive(a: AdaptiveArgs) -> Result<()> {
    if a.budgets.is_empty() || a.budgets.iter().any(|&b| b < 16) {
        bail!("--budgets: at least one, each at least 16 (the first pass takes 16)");
    }
    for &t in &a.thresholds {
        check_threshold("--thresholds", t)?;
    }
    if !(a.floor.is_finite() && a.floor >= 0.0) {
        bail!("--floor {}: must be finite and ≥ 0", a.floor);
    }
    if a.seeds == 0 {
        bail!("--seeds 0: at least 1");
    }
    let threads = threads(a.threads);
    let e = Experiment {
        scene: a.scene.clone(),
        size: a.size,
        samplers: Vec::new(),
        runs: 1,
        seed: 1,
        threads,
        reference_spp: a.reference_spp,
    };
    let bar1 = bar("reference", "tiles");
    let reference = e.reference(tick(&bar1))?;
    bar1.finish_and_clear();
    let mut base = RenderConfig::new(&a.scene);
    base.size = a.size;
    base.threads = threads;
    let study = adaptive_study::StudyConfig {
        sampler: a.sampler.clone(),
        budgets: a.budgets.clone(),
        thresholds: a.thresholds.clone(),
        floor: a.floor,
        seeds: (1..=u64::from(a.seeds)).collect(),
    };
    let bar2 = bar("study", "renders");
    let rows = adaptive_study::run(&base, &study, &reference, tick(&bar2))?;
    bar2.finish_and_clear();
    println!(
        "{} at {}x{}, {}, floor {}, {} seeds: RMSE against a {}x4-spp reference.\n",
        a.scene, a.size[0], a.size[1], a.sampler, a.floor, a.seeds, a.reference_spp
    );
    print!("{}", adaptive_study::markdown(&rows));
    let middle = a.budgets[a.budgets.len() / 2];
    let adaptive = rows
        .iter()
        .find(|r| r.report.is_some() && r.spp == middle)
        .context("the middle budget's adaptive render")?;
    if let (Some(p), Some(report)) = (&a.map, &adaptive.report) {
        write_image_file(p, &report.spp_image()?)?;
    }
    if let Some(p) = &a.sheet {
        let uniform = rows
            .iter()
            .find(|r| r.method == "uniform" && r.spp == middle)
            .context("the middle budget's uniform render")?;
        let (w, h) = (a.size[0], a.size[1]);
        let sheet = Image::from_fn(2 * w, h, |x, y| {
            if x < w {
                uniform.image.get(x, y)
            } else {
                adaptive.image.get(x - w, y)
            }
        });
        write_image_file(p, &sheet)?;
    }
    Ok(())
}

fn converge(a: ConvergeArgs) -> Result<()> {
    let pixel = a.pixel;
    if pixel[0] >= a.size[0] || pixel[1] >= a.size[1] {
        bail!(
            "--pixel {},{}: outside the {}x{} image",
            pixel[0],
            pixel[1],
            a.size[0],
            a.size[1]
        );
    }
    let power_of_4 = |n: u32| n.is_power_of_two() && n.trailing_zeros().is_multiple_of(2);
    if !power_of_4(a.min_spp) || !power_of_4(a.max_spp) || a.min_spp >= a.max_spp {
        bail!("--min-spp and --max-spp: powers of four (squares, for stratified), min < max");
    }
    let counts: Vec<u32> = (a.min_spp.trailing_zeros()..=a.max_spp.trailing_zeros())
        .step_by(2)
        .map(|k| 1 << k)
        .collect();
    let (reference, se) = pixel_reference(&a.scene, a.size, pixel)?;
    let rows = pixel_study(
        &a.scene,
        a.size,
        pixel,
        &a.samplers,
        &counts,
        a.runs,
        reference,
    )?;
    println!(
        "Pixel ({}, {}) of {} at {}x{}: reference {reference:.6} ± {se:.1e}; RMSE over {} seeds.\n",
        pixel[0], pixel[1], a.scene, a.size[0], a.size[1], a.runs
    );
    print!("| sampler | slope |");
    for n in &counts {
        print!(" N={n} |");
    }
    println!("\n|---|---|{}", "---|".repeat(counts.len()));
    for (name, rmse, slope) in rows {
        let slope = slope.map_or_else(|| "-".to_owned(), |s| format!("{s:.2}"));
        print!("| {name} | {slope} |");
        for e in rmse {
            print!(" {e:.1e} |");
        }
        println!();
    }
    Ok(())
}
