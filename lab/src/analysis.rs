//! Analysis of a point set: quality measures (star and L2 discrepancies, minimum distance and
//! ρ) and its Fourier periodogram as a figure, what `nyquist analyze` prints and the explorer
//! shows.
//!
//! Points come from a CSV file or stdin (the format `nyquist points` writes, with an optional
//! header line) or are generated from a [`PointsSpec`]. Everything is validated and computed
//! before anything is written, so an error leaves no file. The front end supplies notes,
//! progress and figure files through [`Host`].

use crate::clock::Stopwatch;
#[cfg(feature = "clap")]
use crate::points::parse_grid;
use crate::points::{PointSetName, PointsSpec, ignores_seed, randomized_on_request};
use anyhow::{Context, Result, anyhow, bail};
use nyquist::analysis::{
    self, ENUMERATION_LIMIT, MAX_DIMS, PointSet, StarBounds, Topology, star_bounds_scratch_len,
    star_discrepancy_scratch_len,
};
use std::fmt::Write as _;
use std::io::{BufRead as _, IsTerminal, Read as _};
use std::path::{Path, PathBuf};

/// The most coordinates a CSV input may hold: 2²⁸ (as `points`).
const MAX_VALUES: usize = crate::points::MAX_VALUES as usize;
/// Largest set whose L2-star discrepancy (O(d·N²)) is among the default measures.
const DEFAULT_L2_LIMIT: usize = 1 << 16;
/// Largest set the automatic star method computes exactly in 2D (the sweep is O(N²)).
const AUTO_EXACT_2D: usize = 1 << 15;
/// Largest set `--star-method exact` sweeps in 2D: 2¹⁷ points, N² = 2³⁴ steps (about a minute
/// at the sweep rate below); larger sets are refused, as enumeration past [`ENUMERATION_LIMIT`] is.
pub const EXACT_2D_LIMIT: usize = 1 << 17;
/// Seconds per step of the 2D sweep (N² steps), from a release build on a 2-core x86-64 machine
/// (50 000 points in 8.1 s): the basis of the announcement, not a promise.
const SWEEP_SECONDS: f64 = 3.2e-9;
/// Seconds per `d·N²` term of the L2 discrepancies, measured the same way (200 000 2D points in
/// 16.6 s).
const PAIR_SECONDS: f64 = 2.1e-10;
/// Estimated work above which a measure is announced before it starts, with a progress bar.
const ANNOUNCE_SECONDS: f64 = 2.0;
/// Grid cells `(m + 1)^d` of the automatic bounds grid (32 MiB of counters).
const BOUNDS_CELLS: u64 = 1 << 22;
/// Largest automatic bounds grid per axis.
const BOUNDS_MAX_M: u32 = 1 << 16;
/// The periodogram's highest frequency unless --freq says otherwise.
const DEFAULT_FREQ: u32 = 64;
/// Most realisations one periodogram averages.
const MAX_REALISATIONS: u32 = 100_000;
/// Periodogram terms (realisations × points × frequencies) above which `--spectrum` warns.
const LARGE_SPECTRUM: f64 = 1e10;
/// Margin around and between the panels of the spectrum picture.
const MARGIN: u32 = 16;
/// Height of the spectrum picture's title block.
const HEADER: u32 = 58;
/// The periodogram panel (axes included), the colour bar beside it and the radial plot.
const PERIODOGRAM_AREA: (u32, u32) = (620, 640);
const COLORBAR_AREA: (u32, u32) = (120, 640);
const RADIAL_AREA: (u32, u32) = (600, 640);
/// Width of the spectrum picture.
pub const SPECTRUM_WIDTH: u32 = 4 * MARGIN + PERIODOGRAM_AREA.0 + COLORBAR_AREA.0 + RADIAL_AREA.0;
/// Height of the spectrum picture.
pub const SPECTRUM_HEIGHT: u32 = 2 * MARGIN + HEADER + PERIODOGRAM_AREA.1;
/// The periodogram's grey scale: power in dB from `LO_DB` (black) to `HI_DB` (white).
const LO_DB: f64 = -30.0;
const HI_DB: f64 = 10.0;

/// The measures `--measures` accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Measure {
    /// Star discrepancy D*: exact (1D sort, 2D sweep, enumeration in small d) or a grid bracket.
    Star,
    /// L2-star discrepancy (Warnock's formula, O(d·N²)).
    L2Star,
    /// Centered L2 discrepancy (Hickernell 1998, O(d·N²)).
    CenteredL2,
    /// Wrap-around L2 discrepancy (Hickernell 1998, O(d·N²)).
    WraparoundL2,
    /// Minimum distance in the unit square and its relative radius ρ (2D sets).
    MinDistance,
    /// Minimum distance on the unit torus and its ρ (2D sets).
    MinDistanceTorus,
}

impl Measure {
    /// The name as `--measures` takes it.
    ///
    /// ```
    /// assert_eq!(nyquist_lab::analysis::Measure::L2Star.name(), "l2-star");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Measure::Star => "star",
            Measure::L2Star => "l2-star",
            Measure::CenteredL2 => "centered-l2",
            Measure::WraparoundL2 => "wraparound-l2",
            Measure::MinDistance => "min-distance",
            Measure::MinDistanceTorus => "min-distance-torus",
        }
    }
}

/// How the star discrepancy is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum StarMethod {
    /// Exact in 1D, in 2D up to 32768 points and by enumeration while its cost is within the
    /// library's limit; otherwise the grid bracket.
    Auto,
    /// Always exact: an error when the work would pass its limit (2D: more than 131072 points;
    /// 3 or more dimensions: an enumeration of more than 2^32 steps).
    Exact,
    /// Always the grid bracket [lower, upper] (--star-grid cells per axis).
    Bounds,
}

/// What to analyse and how: the input (a CSV file, stdin, or a generated set), the measures,
/// and the optional periodogram figure. With the `clap` feature it is also the argument group of
/// `nyquist analyze` (errors name its fields as flags).
#[derive(Clone, Debug)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
#[cfg_attr(
    feature = "clap",
    command(after_help = "Examples:
  nyquist analyze --sampler sobol --count 1024
  nyquist points --sampler halton --count 256 | nyquist analyze --json
  nyquist analyze --sampler stratified --count 1024 --spectrum s.png --realisations 16")
)]
pub struct AnalyzeSpec {
    /// CSV of points, one per line as `nyquist points` writes them (an optional header line);
    /// `-` or nothing reads stdin. Values must lie in [0, 1); decimals are read as f64.
    #[cfg_attr(feature = "clap", arg(value_name = "FILE.csv"))]
    pub input: Option<PathBuf>,
    /// The same CSV input as a flag: `--input FILE` or `--input -`.
    #[cfg_attr(
        feature = "clap",
        arg(long = "input", value_name = "FILE|-", conflicts_with = "input")
    )]
    pub input_flag: Option<PathBuf>,
    /// Generate the points instead: which point set or sampler (names as in `points`).
    #[cfg_attr(
        feature = "clap",
        arg(long, visible_alias = "sequence", value_enum, value_name = "NAME")
    )]
    pub sampler: Option<PointSetName>,
    /// Number of points to generate [default: 16; required for hammersley].
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1, crate::points::MAX_VALUES)))]
    pub count: Option<u64>,
    /// Dimensions per generated point [default: 2]; with CSV input, the expected column count.
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1, crate::points::MAX_VALUES as u32)))]
    pub dims: Option<u32>,
    /// Seed of random and scrambled sets [default: 0].
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(0, u64::MAX)))]
    pub seed: Option<u64>,
    /// Index of the first point of a generated sequence.
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(0, u64::MAX)))]
    pub skip: Option<u64>,
    /// Grid `NXxNY` for 2D uniform/stratified sets whose count is not a square.
    #[cfg_attr(feature = "clap", arg(long, value_parser = parse_grid))]
    pub grid: Option<(u32, u32)>,
    /// Pixel-sampler mode (as in `points`): the SPP samples of pixel 0,0.
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1, crate::study::MAX_SPP)))]
    pub spp: Option<u32>,
    /// Image size `WxH` for halton, hammersley and sobol with --spp.
    #[cfg_attr(feature = "clap", arg(long, value_parser = parse_grid))]
    pub resolution: Option<(u32, u32)>,
    /// Analyse the projection onto these dimensions (0-based, comma-separated, each below the
    /// set's dimension count), e.g. `--dims 8 --project 3,7` for Halton's pair of bases 7 and 19.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_delimiter = ',', value_name = "LIST", value_parser = crate::flags::whole(0, crate::points::MAX_VALUES as u32 - 1))
    )]
    pub project: Vec<u32>,
    /// Comma-separated measures [default: star; l2-star up to 65536 points; min-distance for 2D
    /// sets].
    #[cfg_attr(
        feature = "clap",
        arg(
            long,
            visible_alias = "measure",
            value_enum,
            value_delimiter = ',',
            value_name = "LIST"
        )
    )]
    pub measures: Vec<Measure>,
    /// How to compute the star discrepancy.
    #[cfg_attr(feature = "clap", arg(long, value_enum, default_value = "auto"))]
    pub star_method: StarMethod,
    /// Cells per axis of the star-discrepancy bracket [default: the largest with at most 2^22
    /// grid points]; the bracket's width is at most 1 − (1 − 1/m)^d.
    #[cfg_attr(feature = "clap", arg(long, value_name = "M", value_parser = crate::flags::whole(1, u32::MAX)))]
    pub star_grid: Option<u32>,
    /// Print one JSON object instead of the table: each measure's number under its name
    /// (`star`, `l2-star`, `centered-l2`, `wraparound-l2`, `min-distance`, `rho`, and the
    /// `-torus` forms; `star-lower`/`star-upper` for a bracket), beside `points`, `dims`,
    /// `source`, `star-method` and `seconds`.
    #[cfg_attr(feature = "clap", arg(long))]
    pub json: bool,
    /// Write the periodogram (log scale, DC at the centre, with its dB scale bar) beside its
    /// radial mean power as one 1404×730 picture (2D sets; dimensions 0 and 1 of wider sets):
    /// PNG for FILE.png, SVG for FILE.svg (vector axes and text; the periodogram itself is a
    /// PNG image inside the SVG). Grey scale: −30 dB black, +10 dB white; white noise is 0 dB.
    #[cfg_attr(feature = "clap", arg(long, value_name = "FILE.png|FILE.svg"))]
    pub spectrum: Option<PathBuf>,
    /// Highest integer frequency F of the periodogram: the grid is (2F+1)² [default: 64]. Without
    /// --spectrum it changes nothing (a note says so).
    #[cfg_attr(feature = "clap", arg(long, value_name = "F", value_parser = crate::flags::whole(1, nyquist_film::periodogram::MAX_FREQ)))]
    pub freq: Option<u32>,
    /// Realisations averaged in the periodogram: generated sets use seeds seed..seed+M−1. The
    /// work is M × points × (2F+1)²; a warning gives it when it is large.
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 1, value_name = "M", value_parser = crate::flags::whole(1, MAX_REALISATIONS)))]
    pub realisations: u32,
}

impl Default for AnalyzeSpec {
    /// Read stdin; the default measures; one realisation; no figure; a table.
    fn default() -> AnalyzeSpec {
        AnalyzeSpec {
            input: None,
            input_flag: None,
            sampler: None,
            count: None,
            dims: None,
            seed: None,
            skip: None,
            grid: None,
            spp: None,
            resolution: None,
            project: Vec::new(),
            measures: Vec::new(),
            star_method: StarMethod::Auto,
            star_grid: None,
            json: false,
            spectrum: None,
            freq: None,
            realisations: 1,
        }
    }
}

/// One computed measure, ready for the table and the JSON.
struct Row {
    /// Table label.
    label: &'static str,
    /// Flat JSON fields (key, value as JSON text).
    json: Vec<(&'static str, String)>,
    /// Value cell of the table.
    value: String,
    /// `N · value` where that is the customary scale (discrepancies), else empty.
    scaled: String,
    /// How it was computed.
    method: String,
    seconds: f64,
}

/// What a front end provides to an analysis: notes and warnings for the user, progress of long
/// work, and the figure file.
pub trait Host {
    /// A note for the user, one line (the command prints `nyquist: note: TEXT`).
    fn note(&mut self, text: &str);
    /// A warning that long work starts, one line.
    fn warn(&mut self, text: &str);
    /// Checks a figure's path before any work (`flag` names it in errors).
    ///
    /// # Errors
    /// A path the figure cannot be written to.
    fn check_figure(&mut self, path: &Path, flag: &str) -> Result<()>;
    /// Writes the periodogram figure to `path`.
    ///
    /// # Errors
    /// A failed drawing or write.
    fn save_spectrum(&mut self, figure: &SpectrumPlot<'_>, path: &Path, flag: &str) -> Result<()>;
    /// Long work of `total` units starts (`now`: show its progress at once).
    fn progress_start(&mut self, _total: u64, _what: &str, _unit: &str, _now: bool) {}
    /// One unit of the work started last is done.
    fn progress_inc(&mut self) {}
    /// The work started last is done.
    fn progress_finish(&mut self) {}
}

/// A host that keeps the notes and writes no figure (the explorer, tests).
#[derive(Debug, Default)]
pub struct Quiet {
    /// The notes and warnings, in order.
    pub notes: Vec<String>,
}

impl Host for Quiet {
    fn note(&mut self, text: &str) {
        self.notes.push(text.to_owned());
    }
    fn warn(&mut self, text: &str) {
        self.notes.push(text.to_owned());
    }
    fn check_figure(&mut self, path: &Path, flag: &str) -> Result<()> {
        bail!("{flag} {}: this front end writes no figure", path.display())
    }
    fn save_spectrum(&mut self, _: &SpectrumPlot<'_>, path: &Path, flag: &str) -> Result<()> {
        self.check_figure(path, flag)
    }
}

/// Everything `nyquist analyze` does but print: the table (or with `--json` the JSON object,
/// one line), after writing the `--spectrum` picture through `host` if one is asked for.
///
/// ```
/// use nyquist_lab::analysis::{AnalyzeSpec, Measure, Quiet, report};
/// use nyquist_lab::points::PointSetName;
/// let spec = AnalyzeSpec { sampler: Some(PointSetName::Hammersley), count: Some(16), json: true,
///                          measures: vec![Measure::Star], ..AnalyzeSpec::default() };
/// let json = report(&spec, &mut Quiet::default()).unwrap();
/// assert!(json.starts_with("{\"points\":16,\"dims\":2,"), "{json}");
/// assert!(json.contains("\"star-method\":\"exact-2d\""), "{json}");
/// ```
///
/// # Errors
/// One line naming the flag at fault, as the command prints it.
pub fn report(args: &AnalyzeSpec, host: &mut dyn Host) -> Result<String> {
    let start = Stopwatch::start();
    // `--input FILE` is the positional FILE under another spelling (clap keeps them exclusive).
    let merged;
    let args = match &args.input_flag {
        Some(path) => {
            merged = AnalyzeSpec {
                input: Some(path.clone()),
                input_flag: None,
                ..args.clone()
            };
            &merged
        }
        None => args,
    };
    check_args(args, host)?;
    let (coords, dims, source) = load_with(args, args.seed, host)?;
    let set = PointSet::new(&coords, dims).map_err(|e| anyhow!("points: {e}"))?;
    let measures = chosen_measures(args, set.len(), dims, host)?;
    let mut rows = Vec::new();
    for &m in &measures {
        rows.extend(measure(args, &set, m, host)?);
    }
    let spectrum = match &args.spectrum {
        Some(path) => Some(spectrum(args, &coords, dims, &source, path, host)?),
        None => None,
    };
    let seconds = start.seconds();
    let n = set.len();
    let text = if args.json {
        json(
            n,
            dims,
            &source,
            &measures,
            &rows,
            spectrum.as_ref(),
            seconds,
        )
    } else {
        table(n, dims, &source, &rows, spectrum.as_ref(), seconds)
    };
    Ok(text)
}

/// Rejects flag combinations before any work.
fn check_args(args: &AnalyzeSpec, host: &mut dyn Host) -> Result<()> {
    if args.sampler.is_some() {
        if args.input.is_some() {
            bail!("give either a CSV input or --sampler, not both");
        }
    } else {
        for (given, flag) in [
            (args.count.is_some(), "--count"),
            (args.seed.is_some(), "--seed"),
            (args.skip.is_some(), "--skip"),
            (args.grid.is_some(), "--grid"),
            (args.spp.is_some(), "--spp"),
            (args.resolution.is_some(), "--resolution"),
        ] {
            if given {
                bail!("{flag} applies to generated sets: give --sampler NAME");
            }
        }
        if args.realisations > 1 {
            bail!(
                "--realisations > 1 needs a generated set (--sampler NAME): CSV input is one realisation"
            );
        }
        if args.input.is_none() && std::io::stdin().is_terminal() {
            bail!("no points: give a CSV file, pipe one into stdin, or use --sampler NAME");
        }
    }
    if args.star_grid == Some(0) {
        bail!("--star-grid 0: need at least one cell per axis");
    }
    if let Some(m) = args.star_grid
        && args.star_method == StarMethod::Exact
    {
        bail!(
            "--star-grid {m}: --star-method exact uses no grid (give --star-method bounds or auto)"
        );
    }
    if args.spectrum.is_none() {
        if let Some(f) = args.freq {
            host.note(&format!(
                "--freq {f} changes nothing without --spectrum FILE.png"
            ));
        }
        if args.realisations > 1 {
            host.note(&format!(
                "--realisations {} changes nothing without --spectrum FILE.png",
                args.realisations
            ));
        }
    }
    if let Some(path) = &args.spectrum {
        host.check_figure(path, "--spectrum")?;
        let freq = args.freq.unwrap_or(DEFAULT_FREQ);
        if freq == 0 || freq > nyquist_film::periodogram::MAX_FREQ {
            bail!(
                "--freq {freq}: need 1 ..= {}",
                nyquist_film::periodogram::MAX_FREQ
            );
        }
        if args.realisations == 0 || args.realisations > MAX_REALISATIONS {
            bail!(
                "--realisations {}: need 1 ..= {MAX_REALISATIONS}",
                args.realisations
            );
        }
        // The (2F+1)² power sums in f64 and the picture drawn from them (4 bytes a cell).
        let side = 2 * u64::from(freq) + 1;
        crate::memory::check(
            &format!("--spectrum with --freq {freq}"),
            crate::memory::bytes(side * side, 8 + 4),
        )?;
    }
    Ok(())
}

/// The points `analyze` measures (flat `f64`), their dimension count and a description of where
/// they came from: generated (with `--sampler`) or read, then projected onto `--project`'s
/// dimensions if given.
///
/// ```
/// use nyquist_lab::{analysis::{AnalyzeSpec, load}, points::PointSetName};
/// let spec = AnalyzeSpec { sampler: Some(PointSetName::Halton), count: Some(4),
///                          project: vec![2, 0], ..AnalyzeSpec::default() };
/// let (coords, dims, source) = load(&spec, None).unwrap();
/// assert_eq!(dims, 2);
/// // Point 1 of Halton: bases 2, 3, 5 give (1/2, 1/3, 1/5); the projection keeps (1/5, 1/2).
/// assert_eq!(&coords[2..4], &[0.2f32 as f64, 0.5]);
/// assert!(source.ends_with("--project 2,0"), "{source}");
/// ```
///
/// # Errors
/// One line naming the flag at fault: an unreadable input, a bad CSV, a sampler that refuses
/// its flags, or a `--project` dimension the set does not have.
pub fn load(args: &AnalyzeSpec, seed: Option<u64>) -> Result<(Vec<f64>, usize, String)> {
    load_with(args, seed, &mut Quiet::default())
}

/// [`load`], with the generator's notes going to `host`.
fn load_with(
    args: &AnalyzeSpec,
    seed: Option<u64>,
    host: &mut dyn Host,
) -> Result<(Vec<f64>, usize, String)> {
    let (coords, dims, mut source) = load_all(args, seed, host)?;
    if args.project.is_empty() {
        return Ok((coords, dims, source));
    }
    for (i, &k) in args.project.iter().enumerate() {
        if k as usize >= dims {
            bail!(
                "--project {k}: the set has {dims} dimension{} (0 ..= {}){}",
                if dims == 1 { "" } else { "s" },
                dims - 1,
                if args.sampler.is_some() && args.dims.is_none() {
                    ""
                } else {
                    "; give a larger --dims"
                }
            );
        }
        if args.project[..i].contains(&k) {
            bail!("--project {k}: dimension {k} is given twice");
        }
    }
    let picked: Vec<f64> = coords
        .chunks_exact(dims)
        .flat_map(|p| args.project.iter().map(|&k| p[k as usize]))
        .collect();
    let list: Vec<String> = args.project.iter().map(u32::to_string).collect();
    let _ = write!(source, " --project {}", list.join(","));
    Ok((picked, args.project.len(), source))
}

/// The points before projection.
fn load_all(
    args: &AnalyzeSpec,
    seed: Option<u64>,
    host: &mut dyn Host,
) -> Result<(Vec<f64>, usize, String)> {
    if let Some(sampler) = args.sampler {
        let (pts, dims) = generate(args, sampler, seed, host)?;
        let mut source = format!("{} --count {}", sampler.name(), pts.len() / dims);
        if let Some(spp) = args.spp {
            source = format!("{} --spp {spp}", sampler.name());
        }
        let _ = write!(source, " --dims {dims}");
        // The seed the points were made with: given, or 0 for the always-random sets and the
        // pixel samplers; none for the deterministic sets.
        let always =
            args.spp.is_some() || !(ignores_seed(sampler) || randomized_on_request(sampler));
        if let Some(seed) = seed.or(always.then_some(0)) {
            let _ = write!(source, " --seed {seed}");
        }
        return Ok((pts.iter().map(|&v| f64::from(v)).collect(), dims, source));
    }
    if cfg!(all(target_arch = "wasm32", target_os = "unknown")) {
        // The browser explorer always names a sampler.
        bail!("give --sampler: points cannot be read from a file or stdin in WebAssembly");
    }
    let limit = crate::memory::limit();
    let (coords, dims, name) = match args.input.as_deref() {
        Some(p) if p != Path::new("-") => {
            let name = p.display().to_string();
            let file = std::fs::File::open(p).with_context(|| format!("{name}: cannot read"))?;
            let (c, d) = read_csv(&mut std::io::BufReader::new(file), &name, limit)?;
            (c, d, name)
        }
        _ => {
            let (c, d) = read_csv(&mut std::io::stdin().lock(), "stdin", limit)?;
            (c, d, "stdin".to_owned())
        }
    };
    if let Some(d) = args.dims
        && d as usize != dims
    {
        bail!("{name}: {dims} columns, but --dims is {d}");
    }
    Ok((coords, dims, name))
}

/// Generates one realisation (a [`PointsSpec`] of the spec's generator fields).
fn generate(
    args: &AnalyzeSpec,
    sampler: PointSetName,
    seed: Option<u64>,
    host: &mut dyn Host,
) -> Result<(Vec<f32>, usize)> {
    // Without --dims, a projection asks for as many dimensions as its largest index needs.
    let dims = args.dims.or_else(|| {
        args.project
            .iter()
            .max()
            .map(|&k| k.saturating_add(1).max(2))
    });
    let spec = PointsSpec {
        sampler,
        count: args.count,
        dims,
        seed,
        skip: args.skip.unwrap_or(0),
        grid: args.grid,
        spp: args.spp,
        pixel: None,
        resolution: args.resolution,
    };
    let points = spec.generate()?;
    points.notes.iter().for_each(|n| host.note(n));
    Ok((points.values, points.dims))
}

/// The longest CSV line [`read_csv`] accepts, in bytes: 1 MiB, room for more than 40 000
/// coordinates of 25 characters. A longer line (a file with no line breaks, `/dev/zero`) is
/// refused after reading this much, not after reading the whole input.
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// Parses CSV points held in memory: [`read_csv`] on `text`, under the memory limit in force.
///
/// ```
/// let (coords, dims) = nyquist_lab::analysis::parse_csv("x,y\n0.5,0.25\n", "t").unwrap();
/// assert_eq!((coords, dims), (vec![0.5, 0.25], 2));
/// ```
///
/// # Errors
/// As [`read_csv`].
pub fn parse_csv(text: &str, name: &str) -> Result<(Vec<f64>, usize)> {
    read_csv(&mut text.as_bytes(), name, crate::memory::limit())
}

/// Reads CSV points from `input` as it streams: comma-separated numbers, the same count on every
/// line, each finite and in `[0, 1)`. Blank lines are skipped; a first line none of whose
/// fields starts like a number (`x,y`, `dim 0,dim 1`) is a header, while a first line such as
/// `0.1;0.2` is an error like any other line.
///
/// Reading is bounded: a line longer than [`MAX_LINE_BYTES`], more than 2²⁸ coordinates, or
/// coordinates whose buffer would pass `limit` end the read with one line naming `name` and the
/// limit, after reading at most that much. So an endless stdin (`yes 0.5,0.25 | nyquist
/// analyze`) or `/dev/zero` is refused in bounded time and memory.
///
/// ```
/// use nyquist_lab::{analysis::read_csv, memory::Limit};
/// let limit = Limit { bytes: 64, source: "--max-memory".into() };
/// let ok = read_csv(&mut "0.5,0.25\n0,0.75\n".as_bytes(), "stdin", &limit).unwrap();
/// assert_eq!(ok, (vec![0.5, 0.25, 0.0, 0.75], 2));
/// // 64 bytes hold 8 coordinates: the fifth point is refused.
/// let many = "0.5,0.25\n".repeat(100);
/// let err = read_csv(&mut many.as_bytes(), "stdin", &limit).unwrap_err().to_string();
/// assert!(err.starts_with("stdin: the points pass the 64 bytes limit (--max-memory) after 8 values"), "{err}");
/// // An endless line of zeros ends after 1 MiB.
/// let mut zeros = std::io::BufReader::new(std::io::repeat(b'0'));
/// let err = read_csv(&mut zeros, "/dev/zero", &limit).unwrap_err().to_string();
/// assert!(err.starts_with("/dev/zero line 1: longer than 1048576 bytes"), "{err}");
/// ```
///
/// # Errors
/// One line naming the input and the line: a value that is not a number, not finite or outside
/// `[0, 1)`, a line with another count of values than the first point, text that is not UTF-8,
/// a line longer than [`MAX_LINE_BYTES`], too many points for `limit` or for 2²⁸ coordinates,
/// no points, or a read error.
pub fn read_csv(
    input: &mut dyn std::io::BufRead,
    name: &str,
    limit: &crate::memory::Limit,
) -> Result<(Vec<f64>, usize)> {
    let mut coords: Vec<f64> = Vec::new();
    let mut dims = 0usize;
    let mut first = true;
    let mut raw = Vec::new();
    let mut at = 0usize;
    loop {
        raw.clear();
        let read = (&mut *input)
            .take(MAX_LINE_BYTES as u64 + 1)
            .read_until(b'\n', &mut raw)
            .with_context(|| format!("{name}: cannot read"))?;
        if read == 0 {
            break;
        }
        at += 1;
        if raw.len() > MAX_LINE_BYTES && raw.last() != Some(&b'\n') {
            bail!(
                "{name} line {at}: longer than {MAX_LINE_BYTES} bytes, the longest line read \
                 (expected CSV of points)"
            );
        }
        let line = std::str::from_utf8(&raw)
            .map_err(|_| anyhow!("{name} line {at}: not UTF-8 text (expected CSV)"))?
            .trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if std::mem::take(&mut first) && !fields.iter().any(|f| starts_like_a_number(f)) {
            continue; // header
        }
        if dims == 0 {
            dims = fields.len();
        } else if fields.len() != dims {
            bail!(
                "{name} line {at}: {}, expected {dims} as on the first point",
                crate::words::count(fields.len() as u64, "value")
            );
        }
        if coords.len() + dims > coords.capacity() {
            grow(&mut coords, dims, name, limit, MAX_VALUES)?;
        }
        for f in fields {
            let shown = || f.chars().take(40).collect::<String>();
            let v: f64 = f
                .parse()
                .map_err(|_| anyhow!("{name} line {at}: '{}' is not a number", shown()))?;
            if !v.is_finite() {
                bail!("{name} line {at}: {} is not a finite number", shown());
            }
            if !(0.0..1.0).contains(&v) {
                bail!("{name} line {at}: {} is outside [0, 1)", shown());
            }
            coords.push(v);
        }
    }
    if coords.is_empty() {
        bail!("{name}: no points");
    }
    Ok((coords, dims))
}

/// Whether a CSV field begins as a number does (`0.5`, `-1`, `.5`, `+2e3`, `nan`, `inf`): a
/// first line with such a field is data, never a header.
fn starts_like_a_number(field: &str) -> bool {
    let t = field.trim_start_matches(['+', '-']);
    let mut chars = t.chars();
    match chars.next() {
        Some(c) if c.is_ascii_digit() => true,
        Some('.') => chars.next().is_some_and(|c| c.is_ascii_digit()),
        _ => {
            let lower = t.to_ascii_lowercase();
            lower.starts_with("nan") || lower.starts_with("inf")
        }
    }
}

/// Doubles the room of `coords` (at least one more point of `dims` values), refusing when the
/// new buffer would pass `limit` or hold more than `max_values` coordinates: the check is made
/// before the allocation, so reading never holds more than the limit.
fn grow(
    coords: &mut Vec<f64>,
    dims: usize,
    name: &str,
    limit: &crate::memory::Limit,
    max_values: usize,
) -> Result<()> {
    let len = coords.len();
    if len + dims > max_values {
        bail!(
            "{name}: more than {max_values} coordinates, the most analyze reads; give fewer points"
        );
    }
    let wanted = (2 * coords.capacity())
        .max(len + dims)
        .max(4096)
        .min(max_values);
    // The point that does not fit is the one being read: refuse once even the exact size would
    // not fit, else settle for what the limit allows.
    let fits = |n: usize| crate::memory::bytes(n as u64, 8) <= limit.bytes;
    let wanted = if fits(wanted) {
        wanted
    } else if fits(len + dims) {
        (limit.bytes / 8) as usize
    } else {
        bail!(
            "{name}: the points pass the {} limit ({}) after {} ({}); give fewer points or a \
             larger --max-memory",
            crate::memory::human(limit.bytes),
            limit.source,
            crate::words::count(len as u64, "value"),
            crate::words::count((len / dims) as u64, "point"),
        );
    };
    coords.try_reserve_exact(wanted - len).map_err(|_| {
        anyhow!(
            "{name}: out of memory after {}",
            crate::words::count(len as u64, "value")
        )
    })
}

/// The measures to compute: the explicit list (each must apply to `dims`), or the defaults that
/// apply (the quadratic L2-star only up to [`DEFAULT_L2_LIMIT`] points, with a note to `host`
/// when it is left out).
fn chosen_measures(
    args: &AnalyzeSpec,
    n: usize,
    dims: usize,
    host: &mut dyn Host,
) -> Result<Vec<Measure>> {
    if args.measures.is_empty() {
        let mut m = Vec::new();
        if dims <= MAX_DIMS {
            m.push(Measure::Star);
        }
        if n <= DEFAULT_L2_LIMIT {
            m.push(Measure::L2Star);
        } else {
            host.note(&format!(
                "l2-star is left out of the default measures above {DEFAULT_L2_LIMIT} points (its \
                 work grows as d·N²; {n} points would take about {}): name it in --measures to \
                 compute it",
                duration(PAIR_SECONDS * dims as f64 * (n as f64) * (n as f64))
            ));
        }
        if dims == 2 {
            m.push(Measure::MinDistance);
        }
        return Ok(m);
    }
    let mut out: Vec<Measure> = Vec::new();
    for &m in &args.measures {
        match m {
            Measure::Star if dims > MAX_DIMS => {
                bail!("--measures star: at most {MAX_DIMS} dimensions, the set has {dims}")
            }
            Measure::MinDistance | Measure::MinDistanceTorus if dims != 2 => bail!(
                "--measures {}: needs a 2D set, the set has {dims} dimension{}",
                measure_name(m),
                if dims == 1 { "" } else { "s" }
            ),
            _ => {}
        }
        if !out.contains(&m) {
            out.push(m);
        }
    }
    Ok(out)
}

fn measure_name(m: Measure) -> &'static str {
    m.name()
}

/// Computes one measure (one or two table rows).
fn measure(
    args: &AnalyzeSpec,
    set: &PointSet<'_>,
    m: Measure,
    host: &mut dyn Host,
) -> Result<Vec<Row>> {
    let t = Stopwatch::start();
    let n = set.len() as f64;
    let disc = |label, key, v: f64, method: &str| Row {
        label,
        json: vec![(key, num(v))],
        value: format!("{v:.6e}"),
        scaled: format!("{:.6}", v * n),
        method: method.to_owned(),
        seconds: t.seconds(),
    };
    let quadratic = matches!(
        m,
        Measure::L2Star | Measure::CenteredL2 | Measure::WraparoundL2
    );
    let d = set.dims() as f64;
    let announced = quadratic
        && announce(
            host,
            (&format!("--measures {}", m.name()), m.name()),
            &format!(
                "{} in {}, d·N² = {:.1e} terms",
                crate::words::count(set.len() as u64, "point"),
                crate::words::count(set.dims() as u64, "dimension"),
                d * n * n
            ),
            PAIR_SECONDS * d * n * n,
            "give fewer points, or leave it out of --measures",
        );
    let rows = match m {
        Measure::Star => vec![star(args, set, host)?],
        Measure::L2Star => vec![disc(
            "L2-star discrepancy",
            "l2-star",
            analysis::l2_star_discrepancy(set),
            "Warnock's formula",
        )],
        Measure::CenteredL2 => vec![disc(
            "centered L2",
            "centered-l2",
            analysis::centered_l2_discrepancy(set),
            "Hickernell 1998",
        )],
        Measure::WraparoundL2 => vec![disc(
            "wrap-around L2",
            "wraparound-l2",
            analysis::wraparound_l2_discrepancy(set),
            "Hickernell 1998",
        )],
        Measure::MinDistance | Measure::MinDistanceTorus => {
            let torus = m == Measure::MinDistanceTorus;
            let len = analysis::min_distance_scratch_len(set.len())
                .ok_or_else(|| anyhow!("min-distance: too many points"))?;
            let mut scratch = vec![0u64; len];
            let topology = if torus {
                Topology::Torus
            } else {
                Topology::Square
            };
            let d = analysis::min_distance(set, topology, &mut scratch)
                .map_err(|e| anyhow!("min-distance: {e}"))?;
            let seconds = t.seconds();
            let (dk, rk, where_) = if torus {
                ("min-distance-torus", "rho-torus", "torus")
            } else {
                ("min-distance", "rho", "square")
            };
            vec![
                Row {
                    label: if torus {
                        "min distance (torus)"
                    } else {
                        "min distance"
                    },
                    json: vec![(dk, num(d.distance))],
                    value: format!("{:.6e}", d.distance),
                    scaled: String::new(),
                    method: format!("grid search, unit {where_}"),
                    seconds,
                },
                Row {
                    label: if torus { "rho (torus)" } else { "rho" },
                    json: vec![(rk, num(d.relative_radius))],
                    value: format!("{:.6}", d.relative_radius),
                    scaled: String::new(),
                    method: "d_min / sqrt(2/(sqrt(3) N))".to_owned(),
                    seconds: 0.0,
                },
            ]
        }
    };
    if announced {
        host.progress_inc();
        host.progress_finish();
    }
    Ok(rows)
}

/// Announces long work before it starts: when `seconds`, the estimate, passes
/// [`ANNOUNCE_SECONDS`], one warning line `FLAGS: WHAT: about DURATION; SMALLER` and a progress
/// bar named after the measure, shown at once (one unit: the measure). Returns whether it did,
/// so that the caller ends the bar.
fn announce(
    host: &mut dyn Host,
    (flags, measure): (&str, &str),
    what: &str,
    seconds: f64,
    smaller: &str,
) -> bool {
    if !(seconds > ANNOUNCE_SECONDS) {
        return false;
    }
    host.warn(&format!(
        "{flags}: {what}: about {} of work; {smaller}",
        duration(seconds)
    ));
    host.progress_start(1, measure, "measures", true);
    true
}

/// A duration for people: `3 s`, `7 min`, `1.2 h`, `3 days`.
///
/// ```
/// # use nyquist_lab::analysis::duration;
/// assert_eq!(duration(2.6), "3 s");
/// assert_eq!(duration(420.0), "7 min");
/// assert_eq!(duration(4300.0), "1.2 h");
/// assert_eq!(duration(3.0 * 86400.0), "3.0 days");
/// ```
pub fn duration(seconds: f64) -> String {
    if seconds < 90.0 {
        format!("{seconds:.0} s")
    } else if seconds < 3600.0 {
        format!("{:.0} min", seconds / 60.0)
    } else if seconds < 86400.0 {
        format!("{:.1} h", seconds / 3600.0)
    } else {
        format!("{:.1} days", seconds / 86400.0)
    }
}

/// The star discrepancy by the method `--star-method` picks.
fn star(args: &AnalyzeSpec, set: &PointSet<'_>, host: &mut dyn Host) -> Result<Row> {
    let t = Stopwatch::start();
    let (n, d) = (set.len(), set.dims());
    let exact = |scratch_len: Option<usize>| -> Result<Option<(f64, &'static str)>> {
        let len = scratch_len.ok_or_else(|| anyhow!("star: too many points"))?;
        let mut scratch = vec![0.0f64; len];
        let (r, how) = match d {
            1 => (analysis::star_discrepancy_1d(set, &mut scratch), "exact-1d"),
            2 => (analysis::star_discrepancy_2d(set, &mut scratch), "exact-2d"),
            _ => (
                analysis::star_discrepancy_enumerate(set, &mut scratch),
                "exact-enumeration",
            ),
        };
        match r {
            Ok(v) => Ok(Some((v, how))),
            Err(nyquist::Error::TooMany { .. }) => Ok(None),
            Err(e) => Err(anyhow!("star: {e}")),
        }
    };
    if d == 2 && args.star_method == StarMethod::Exact && n > EXACT_2D_LIMIT {
        bail!(
            "--star-method exact: the 2D sweep of {n} points takes N² = {:.1e} steps, past its \
             limit of {EXACT_2D_LIMIT} points (about {}); use --star-method bounds or fewer \
             points",
            (n as f64) * (n as f64),
            duration(SWEEP_SECONDS * (EXACT_2D_LIMIT as f64).powi(2))
        );
    }
    let sweeps = d == 2
        && match args.star_method {
            StarMethod::Exact => true,
            StarMethod::Auto => n <= AUTO_EXACT_2D,
            StarMethod::Bounds => false,
        };
    let announced = sweeps
        && announce(
            host,
            ("--measures star", "star"),
            &format!(
                "exact 2D sweep of {}, N² = {:.1e} steps",
                crate::words::count(n as u64, "point"),
                (n as f64) * (n as f64)
            ),
            SWEEP_SECONDS * (n as f64) * (n as f64),
            "give fewer points, or --star-method bounds",
        );
    let result = match args.star_method {
        StarMethod::Bounds => None,
        StarMethod::Exact => Some(exact(star_discrepancy_scratch_len(n, d))?.ok_or_else(|| {
            anyhow!(
                "--star-method exact: enumerating {} in {d} dimensions exceeds the work limit \
                 ({ENUMERATION_LIMIT}); use --star-method bounds",
                crate::words::count(n as u64, "point")
            )
        })?),
        StarMethod::Auto if d == 2 && n > AUTO_EXACT_2D => None,
        StarMethod::Auto => exact(star_discrepancy_scratch_len(n, d))?,
    };
    if announced {
        host.progress_inc();
        host.progress_finish();
    }
    let n_f = n as f64;
    if let (Some(_), Some(m)) = (result, args.star_grid) {
        host.note(&format!(
            "--star-grid {m} unused: the star discrepancy of {} in {} is computed exactly (give \
             --star-method bounds for the bracket)",
            crate::words::count(n as u64, "point"),
            crate::words::count(d as u64, "dimension")
        ));
    }
    if let Some((v, how)) = result {
        let method = match how {
            "exact-1d" => "exact (1D, sorted; Niederreiter Thm 2.6)",
            "exact-2d" => "exact (2D sweep)",
            _ => "exact (critical-box enumeration)",
        };
        return Ok(Row {
            label: "star discrepancy",
            json: vec![("star", num(v)), ("star-method", format!("\"{how}\""))],
            value: format!("{v:.6e}"),
            scaled: format!("{:.6}", v * n_f),
            method: method.to_owned(),
            seconds: t.seconds(),
        });
    }
    let m = args.star_grid.unwrap_or_else(|| auto_grid(d));
    let len = star_bounds_scratch_len(d, m)
        .filter(|&l| l <= 1 << 30)
        .ok_or_else(|| anyhow!("--star-grid {m}: (m+1)^{d} grid points is too many"))?;
    let mut scratch = vec![0u32; len];
    let StarBounds { lower, upper } = analysis::star_discrepancy_bounds(set, m, &mut scratch)
        .map_err(|e| anyhow!("star bounds: {e}"))?;
    Ok(Row {
        label: "star discrepancy",
        json: vec![
            ("star-lower", num(lower)),
            ("star-upper", num(upper)),
            ("star-grid", m.to_string()),
            ("star-method", "\"bounds\"".to_owned()),
        ],
        value: format!("[{lower:.4e}, {upper:.4e}]"),
        scaled: format!("[{:.3}, {:.3}]", lower * n_f, upper * n_f),
        method: format!("bracket, grid {m}^{d} (large N·d)"),
        seconds: t.seconds(),
    })
}

/// The largest `m` with `(m + 1)^d ≤ 2^22` grid points (at least 1, at most 2^16).
fn auto_grid(d: usize) -> u32 {
    let fits = |m: u32| {
        let mut cells = 1u64;
        for _ in 0..d {
            cells = cells.saturating_mul(u64::from(m) + 1);
        }
        cells <= BOUNDS_CELLS
    };
    let mut m = 1;
    while m < BOUNDS_MAX_M && fits(m + 1) {
        m += 1;
    }
    m
}

/// What the spectrum step reports.
struct SpectrumInfo {
    path: PathBuf,
    max_freq: u32,
    realisations: u32,
    /// The generator ignores the seed: every realisation is the same set.
    identical: bool,
    /// Radial mean power, `r = 0..=F` (entry 0 is DC, the mean N).
    radial_mean: Vec<f64>,
    /// Ulichney anisotropy per annulus in dB (−∞ where the variance is 0).
    anisotropy_db: Vec<f64>,
    seconds: f64,
}

/// Computes the averaged periodogram and writes the picture.
fn spectrum(
    args: &AnalyzeSpec,
    coords: &[f64],
    dims: usize,
    source: &str,
    path: &Path,
    host: &mut dyn Host,
) -> Result<SpectrumInfo> {
    let t = Stopwatch::start();
    let freq = args.freq.unwrap_or(DEFAULT_FREQ);
    let total = if args.sampler.is_some() {
        args.realisations.max(1)
    } else {
        1
    };
    // A bar over the realisations, shown when the work passes a second (large sets or --freq).
    let side = 2 * u64::from(freq) + 1;
    let n = (coords.len() / dims.max(1)) as u64;
    let terms = u64::from(total) as f64 * n as f64 * (side * side) as f64;
    let large = terms > LARGE_SPECTRUM;
    if large {
        host.warn(&format!(
            "--spectrum: {} × {} × {side}² frequencies is about {terms:.1e} terms; this may take \
             minutes; fewer --realisations, a lower --freq or fewer points make it shorter",
            crate::words::count(total, "realisation"),
            crate::words::count(n, "point")
        ));
    }
    host.progress_start(u64::from(total), "spectrum", "realisations", large);
    let result = periodogram(args, coords, dims, &mut |_, _| host.progress_inc());
    host.progress_finish();
    let (s, identical) = result?;
    let n = coords.len() / dims;
    let title = match args.sampler {
        Some(_) => format!("nyquist analyze --sampler {source}"),
        None => format!("nyquist analyze {source}"),
    };
    let figure = SpectrumPlot {
        spectrum: &s,
        points: n,
        title: format!(
            "{title} --freq {} --realisations {}",
            s.max_freq, s.realisations
        ),
    };
    host.save_spectrum(&figure, path, "--spectrum")?;
    Ok(SpectrumInfo {
        path: path.to_path_buf(),
        max_freq: s.max_freq,
        realisations: s.realisations,
        identical,
        radial_mean: s.radial_mean.clone(),
        anisotropy_db: s.anisotropy_db.clone(),
        seconds: t.seconds(),
    })
}

/// The periodogram `--spectrum` draws: of the first two coordinates of `coords` (the points
/// [`load`] returned for `args`), averaged with `--realisations − 1` more generated sets (seeds
/// `seed + 1, …`), with `--freq`'s grid; and whether the second realisation equalled the first
/// (a set that ignores its seed). `progress(done, total)` is called after each realisation.
///
/// ```
/// use nyquist_lab::{analysis::{AnalyzeSpec, load, periodogram}, points::PointSetName};
/// let spec = AnalyzeSpec { sampler: Some(PointSetName::Random), count: Some(64), freq: Some(4),
///                          realisations: 3, ..AnalyzeSpec::default() };
/// let (coords, dims, _) = load(&spec, None).unwrap();
/// let (s, identical) = periodogram(&spec, &coords, dims, &mut |_, _| {}).unwrap();
/// assert_eq!((s.max_freq, s.realisations, identical), (4, 3, false));
/// assert_eq!(s.radial_mean[0], 64.0); // DC: the mean of |Σ 1|² / N = N
/// ```
///
/// # Errors
/// `--spectrum: …` for a 1-D set, `--freq …` for a grid the periodogram refuses.
pub fn periodogram(
    args: &AnalyzeSpec,
    coords: &[f64],
    dims: usize,
    progress: &mut dyn FnMut(u32, u32),
) -> Result<(nyquist_film::periodogram::Spectrum, bool)> {
    if dims < 2 {
        bail!("--spectrum: needs points with at least 2 dimensions, the set has 1");
    }
    let freq = args.freq.unwrap_or(DEFAULT_FREQ);
    let mut pg = nyquist_film::periodogram::Periodogram::new(freq)
        .map_err(|e| anyhow!("--freq {freq}: {e}"))?;
    let total = if args.sampler.is_some() {
        args.realisations.max(1)
    } else {
        1
    };
    pg.add(&pairs_of(coords, dims))
        .map_err(|e| anyhow!("--spectrum: {e}"))?;
    progress(1, total);
    let mut identical = false;
    if let Some(sampler) = args.sampler {
        // Realisation k takes seed + k; a set randomized only on request (halton, sobol, the
        // lattices, …) stays the deterministic set without --seed, so its realisations agree.
        let plain = ignores_seed(sampler)
            || (randomized_on_request(sampler) && args.seed.is_none() && args.spp.is_none());
        for k in 1..total {
            let seed = if plain {
                args.seed
            } else {
                Some(args.seed.unwrap_or(0).wrapping_add(u64::from(k)))
            };
            let (c, d, _) = load(args, seed)?;
            if k == 1 && c == coords {
                identical = true;
            }
            pg.add(&pairs_of(&c, d))
                .map_err(|e| anyhow!("--spectrum: {e}"))?;
            progress(k + 1, total);
        }
    }
    let s = pg.spectrum().map_err(|e| anyhow!("--spectrum: {e}"))?;
    Ok((s, identical))
}

fn pairs_of(c: &[f64], dims: usize) -> Vec<[f64; 2]> {
    c.chunks_exact(dims).map(|p| [p[0], p[1]]).collect()
}

/// The grey level of power `p` on the −30..+10 dB scale.
fn grey(p: f64) -> u8 {
    let t = if p > 0.0 {
        ((10.0 * p.log10() - LO_DB) / (HI_DB - LO_DB)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (255.0 * t).round() as u8
}

/// The periodogram as a `w × h` grey RGB picture, fy upwards: each pixel the mean power of the
/// frequency cells it covers.
fn periodogram_rgb(s: &nyquist_film::periodogram::Spectrum, w: u32, h: u32) -> Vec<u8> {
    let side = 2 * s.max_freq as usize + 1;
    let range = |px: usize, n: usize| {
        let a = px * side / n;
        let b = ((px + 1) * side / n).max(a + 1).min(side);
        (a.min(side - 1), b)
    };
    let (w, h) = (w as usize, h as usize);
    let mut rgb = Vec::with_capacity(3 * w * h);
    for py in 0..h {
        let (ya, yb) = range(h - 1 - py, h);
        for px in 0..w {
            let (xa, xb) = range(px, w);
            let mut sum = 0.0;
            for y in ya..yb {
                for x in xa..xb {
                    sum += s.power[y * side + x];
                }
            }
            let g = grey(sum / ((yb - ya) * (xb - xa)) as f64);
            rgb.extend_from_slice(&[g, g, g]);
        }
    }
    rgb
}

/// The spectrum picture: the periodogram with its dB scale bar (left) and the radial mean
/// power against the frequency (right).
#[derive(Debug)]
pub struct SpectrumPlot<'a> {
    spectrum: &'a nyquist_film::periodogram::Spectrum,
    points: usize,
    title: String,
}

#[cfg(not(target_family = "wasm"))]
impl crate::plot::Figure for SpectrumPlot<'_> {
    fn size(&self) -> (u32, u32) {
        (SPECTRUM_WIDTH, SPECTRUM_HEIGHT)
    }

    fn draw<DB: plotters::prelude::DrawingBackend>(
        &self,
        root: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<Vec<crate::plot::Raster>>
    where
        DB::ErrorType: 'static,
    {
        use crate::plot::{Axes, GUIDE, INK, Raster, color, font, panel, title};
        use plotters::prelude::*;
        use plotters::style::text_anchor::{HPos, Pos, VPos};
        let s = self.spectrum;
        let f = f64::from(s.max_freq);
        let m = MARGIN as i32;
        let (w, _) = self.size();
        let sizes = [(18.0, 1), (14.0, 2)];
        let used = title(root, &self.title, (m, m), w - 2 * MARGIN, &sizes)?;
        root.draw_text(
            &format!(
                "N = {}, {} averaged; power P(f) = |Σ exp(−2πi f·x)|² / N, white noise 1 (0 dB)",
                crate::words::count(self.points as u64, "point"),
                crate::words::count(s.realisations, "realisation")
            ),
            &font(14.0).color(&INK),
            (m, m + used + 3),
        )?;
        let top = m + HEADER as i32;
        let mut rasters = Vec::new();
        // The periodogram, one raster pixel per screen pixel of its plotting area.
        let area = root.clone().shrink((m, top), PERIODOGRAM_AREA);
        let mut axes = Axes::linear(-f - 0.5..f + 0.5, -f - 0.5..f + 0.5);
        axes.caption = "periodogram (DC at the centre)".to_owned();
        axes.x_desc = "frequency fx".to_owned();
        axes.y_desc = "frequency fy".to_owned();
        axes.image = true;
        let chart = panel(&area, &axes)?;
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        let (w, h) = ((xr.end - xr.start) as u32, (yr.end - yr.start) as u32);
        rasters.push(Raster {
            x: xr.start,
            y: yr.start,
            width: w,
            height: h,
            rgb: periodogram_rgb(s, w, h),
        });
        // Its scale bar.
        let x_bar = m + (PERIODOGRAM_AREA.0 + MARGIN) as i32;
        let area = root.clone().shrink((x_bar, top), COLORBAR_AREA);
        let mut axes = Axes::linear(0.0..1.0, LO_DB..HI_DB);
        axes.x_major.clear();
        axes.x_minor.clear();
        axes.caption = "dB".to_owned();
        axes.image = true;
        let chart = panel(&area, &axes)?;
        let (xr, yr) = chart.plotting_area().get_pixel_range();
        let (w, h) = ((xr.end - xr.start) as u32, (yr.end - yr.start) as u32);
        let mut rgb = Vec::with_capacity(3 * (w * h) as usize);
        for py in 0..h {
            let db = HI_DB - (HI_DB - LO_DB) * (f64::from(py) + 0.5) / f64::from(h.max(1));
            let g = grey(10f64.powf(db / 10.0));
            for _ in 0..w {
                rgb.extend_from_slice(&[g, g, g]);
            }
        }
        rasters.push(Raster {
            x: xr.start,
            y: yr.start,
            width: w,
            height: h,
            rgb,
        });
        // Radial mean power for r = 1..=F (DC is N, off the scale).
        let radial = &s.radial_mean;
        let peak = radial.iter().skip(1).cloned().fold(0.0f64, f64::max);
        let x_rad = x_bar + (COLORBAR_AREA.0 + MARGIN) as i32;
        let area = root.clone().shrink((x_rad, top), RADIAL_AREA);
        let mut axes = Axes::linear(0.0..f, 0.0..(1.08 * peak).max(1.5));
        axes.caption = "radial mean power".to_owned();
        axes.x_desc = "frequency |f|".to_owned();
        axes.y_desc = "mean power over the annulus".to_owned();
        let mut chart = panel(&area, &axes)?;
        chart.draw_series(DashedLineSeries::new(
            [(0.0, 1.0), (f, 1.0)],
            6,
            4,
            GUIDE.stroke_width(1),
        ))?;
        let at = chart.backend_coord(&(0.0, 1.0));
        root.draw_text(
            "white noise",
            &font(13.0)
                .color(&GUIDE)
                .pos(Pos::new(HPos::Left, VPos::Bottom)),
            (at.0 + 6, at.1 - 4),
        )?;
        let pts: Vec<(f64, f64)> = (1..radial.len()).map(|r| (r as f64, radial[r])).collect();
        chart.draw_series(LineSeries::new(
            pts.iter().copied(),
            color(0).stroke_width(2),
        ))?;
        if pts.len() == 1 {
            chart.draw_series(pts.iter().map(|&p| Circle::new(p, 3, color(0).filled())))?;
        }
        Ok(rasters)
    }
}

/// A finite number as JSON (shortest round-trip form).
fn num(v: f64) -> String {
    if v.is_finite() {
        format!("{v}")
    } else {
        "null".to_owned()
    }
}

/// A JSON string literal.
fn json_str(s: &str) -> String {
    let mut out = String::from("\"");
    for ch in s.chars() {
        match ch {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn json(
    n: usize,
    dims: usize,
    source: &str,
    measures: &[Measure],
    rows: &[Row],
    spectrum: Option<&SpectrumInfo>,
    seconds: f64,
) -> String {
    let mut out = format!(
        "{{\"points\":{n},\"dims\":{dims},\"source\":{},\"measures\":[{}]",
        json_str(source),
        measures
            .iter()
            .map(|&m| json_str(measure_name(m)))
            .collect::<Vec<_>>()
            .join(",")
    );
    for r in rows {
        for (k, v) in &r.json {
            let _ = write!(out, ",\"{k}\":{v}");
        }
    }
    if let Some(s) = spectrum {
        let _ = write!(
            out,
            ",\"spectrum\":{},\"spectrum_max_freq\":{},\"spectrum_realisations\":{},\"spectrum_identical_realisations\":{},\"spectrum_seconds\":{}",
            json_str(&s.path.display().to_string()),
            s.max_freq,
            s.realisations,
            s.identical,
            num(s.seconds)
        );
        let list = |v: &[f64]| v.iter().map(|&x| num(x)).collect::<Vec<_>>().join(",");
        let _ = write!(
            out,
            ",\"spectrum_radial_mean\":[{}],\"spectrum_anisotropy_db\":[{}]",
            list(&s.radial_mean),
            list(&s.anisotropy_db)
        );
    }
    let _ = writeln!(out, ",\"seconds\":{}}}", num(seconds));
    out
}

fn table(
    n: usize,
    dims: usize,
    source: &str,
    rows: &[Row],
    spectrum: Option<&SpectrumInfo>,
    seconds: f64,
) -> String {
    let mut out = format!(
        "{n} point{}, {dims} dimension{} ({source})\n",
        if n == 1 { "" } else { "s" },
        if dims == 1 { "" } else { "s" }
    );
    let _ = writeln!(
        out,
        "{:<22} {:<26} {:<20} {:>11}  method",
        "measure", "value", "N*value", "time"
    );
    for r in rows {
        let _ = writeln!(
            out,
            "{:<22} {:<26} {:<20} {:>11}  {}",
            r.label,
            r.value,
            r.scaled,
            ms(r.seconds),
            r.method
        );
    }
    if let Some(s) = spectrum {
        let _ = writeln!(
            out,
            "spectrum: {} (F = {}, {} realisation{}{}) in {}",
            s.path.display(),
            s.max_freq,
            s.realisations,
            if s.realisations == 1 { "" } else { "s" },
            if s.identical {
                ", all identical: this set ignores --seed"
            } else {
                ""
            },
            ms(s.seconds).trim()
        );
    }
    let _ = writeln!(out, "total time {}", ms(seconds).trim());
    out
}

fn ms(seconds: f64) -> String {
    format!("{:.3} ms", seconds * 1e3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_accepts_a_header_and_blank_lines() {
        let (c, d) = parse_csv("x,y\n0.5,0.25\n\n0,0.75\n", "t").unwrap();
        assert_eq!((c, d), (vec![0.5, 0.25, 0.0, 0.75], 2));
    }

    #[test]
    fn csv_lines_are_bounded_at_one_mebibyte() {
        let limit = crate::memory::Limit {
            bytes: 1 << 20,
            source: "t".into(),
        };
        let padded = |len: usize| format!("0.5{}\n", " ".repeat(len - 3));
        // A line of exactly MAX_LINE_BYTES before its line break is read; one byte more is not.
        let ok = read_csv(&mut padded(MAX_LINE_BYTES).as_bytes(), "t", &limit).unwrap();
        assert_eq!(ok, (vec![0.5], 1));
        let last = &padded(MAX_LINE_BYTES)[..MAX_LINE_BYTES];
        assert_eq!(
            read_csv(&mut last.as_bytes(), "t", &limit).unwrap().0,
            [0.5]
        );
        let err = read_csv(&mut padded(MAX_LINE_BYTES + 1).as_bytes(), "t", &limit).unwrap_err();
        assert!(
            err.to_string()
                .starts_with("t line 1: longer than 1048576 bytes")
        );
    }

    #[test]
    fn csv_buffers_stop_at_the_memory_and_count_limits() {
        let limit = |bytes| crate::memory::Limit {
            bytes,
            source: "--max-memory".into(),
        };
        let text = "0.5,0.25,0.125\n".repeat(10);
        // 48 bytes hold six coordinates, two points of three: the third is refused.
        let err = read_csv(&mut text.as_bytes(), "t", &limit(48))
            .unwrap_err()
            .to_string();
        assert!(
            err.starts_with(
                "t: the points pass the 48 bytes limit (--max-memory) after 6 values (2 points)"
            ),
            "{err}"
        );
        // 47 bytes hold one point; 240 bytes hold all ten, 239 all but the last.
        let err = read_csv(&mut text.as_bytes(), "t", &limit(47))
            .unwrap_err()
            .to_string();
        assert!(err.contains("after 3 values (1 point);"), "{err}");
        assert_eq!(
            read_csv(&mut text.as_bytes(), "t", &limit(240))
                .unwrap()
                .0
                .len(),
            30
        );
        let err = read_csv(&mut text.as_bytes(), "t", &limit(239))
            .unwrap_err()
            .to_string();
        assert!(err.contains("after 27 values (9 points)"), "{err}");
        // The coordinate cap, met exactly and passed by one point.
        let mut coords = vec![0.0; 6];
        grow(&mut coords, 3, "t", &limit(1 << 20), 9).unwrap();
        assert!(coords.capacity() >= 9);
        let mut coords = vec![0.0; 7];
        let err = grow(&mut coords, 3, "t", &limit(1 << 20), 9)
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "t: more than 9 coordinates, the most analyze reads; give fewer points"
        );
        // Below the limit, room doubles (amortised reading), never past the cap.
        let mut coords: Vec<f64> = Vec::with_capacity(5000);
        coords.resize(5000, 0.0);
        grow(&mut coords, 1, "t", &limit(1 << 20), 1 << 28).unwrap();
        assert!(coords.capacity() >= 10_000);
        let mut coords: Vec<f64> = Vec::with_capacity(5000);
        coords.resize(5000, 0.0);
        grow(&mut coords, 1, "t", &limit(1 << 20), 6000).unwrap();
        assert!(
            (5001..=6000).contains(&coords.capacity()),
            "{}",
            coords.capacity()
        );
    }

    #[test]
    fn a_header_is_a_first_line_where_no_field_starts_like_a_number() {
        for numeric in [
            "0.5", "-1", "+2e3", ".5", "-.5", "nan", "-inf", "Infinity", "7x",
        ] {
            assert!(starts_like_a_number(numeric), "{numeric}");
        }
        for name in ["x1", "u", "dim 0", ".", "-", "", ".x", "n"] {
            assert!(!starts_like_a_number(name), "{name}");
        }
        assert!(parse_csv("x1,0.5\n0.5,0.5\n", "t").is_err());
        assert!(parse_csv("0.1;0.2\n0.5\n", "t").is_err());
        assert_eq!(parse_csv("x1;x2\n0.5\n", "t").unwrap().0, [0.5]);
    }

    #[test]
    fn csv_rejects_bad_values() {
        for bad in [
            "0.5,0.2\n0.1\n",
            "0.5,abc\n",
            "1.0\n",
            "NaN\n",
            "-0.1\n",
            "x\n",
            "",
        ] {
            assert!(parse_csv(bad, "t").is_err(), "{bad:?}");
        }
    }

    #[test]
    fn auto_grid_fits_the_budget() {
        assert_eq!(auto_grid(2), 2047);
        assert_eq!(auto_grid(1), BOUNDS_MAX_M);
        assert_eq!(auto_grid(32), 1);
        let m = u64::from(auto_grid(3));
        assert!((m + 1).pow(3) <= BOUNDS_CELLS && (m + 2).pow(3) > BOUNDS_CELLS);
    }

    #[test]
    fn periodogram_pixels_follow_the_db_scale() {
        let s = nyquist_film::periodogram::periodogram(&[&[[0.1, 0.2], [0.6, 0.7]]], 3).unwrap();
        // One pixel per frequency cell: the centre shows DC, P = N = 2, on −30..+10 dB.
        let rgb = periodogram_rgb(&s, 7, 7);
        let at = |x: usize, y: usize| rgb[3 * (y * 7 + x)];
        let want = (255.0 * (10.0 * 2f64.log10() + 30.0) / 40.0).round() as u8;
        assert_eq!(at(3, 3), want);
        // The bottom-left pixel is f = (−3, −3) (fy grows upwards).
        assert_eq!(at(0, 6), grey(s.at(-3, -3)));
        assert_eq!(grey(1.0), (255.0 * 30.0 / 40.0f64).round() as u8);
        assert_eq!((grey(0.0), grey(1e-9), grey(1e9)), (0, 0, 255));
    }

    #[test]
    fn spectrum_picture_has_the_documented_size_in_png_and_svg() {
        use crate::plot::{Kind, render};
        let s = nyquist_film::periodogram::periodogram(&[&[[0.1, 0.2], [0.6, 0.7]]], 3).unwrap();
        let fig = SpectrumPlot {
            spectrum: &s,
            points: 2,
            title: "nyquist analyze t.csv --freq 3 --realisations 1".to_owned(),
        };
        assert_eq!((SPECTRUM_WIDTH, SPECTRUM_HEIGHT), (1404, 730));
        let png = render(&fig, Kind::Png).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(png))
            .read_info()
            .unwrap();
        assert_eq!(
            (reader.info().width, reader.info().height),
            (SPECTRUM_WIDTH, SPECTRUM_HEIGHT)
        );
        let svg = String::from_utf8(render(&fig, Kind::Svg).unwrap()).unwrap();
        assert_eq!(svg.matches("<image ").count(), 2);
        assert!(svg.contains("data:image/png;base64,iVBORw0KGgo"));
        assert!(svg.contains("nyquist analyze t.csv --freq 3"));
    }
}
