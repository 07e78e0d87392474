//! `nyquist points`: print the points of a sequence or sampler.

use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use nyquist::analysis::Topology;
use nyquist::bluenoise::PoissonDisk;
use nyquist::lattice::{FibonacciLattice, Korobov, Kronecker};
use nyquist::rng::{default_rng, uniform_f32};
use nyquist::sequence::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, OwenSobol, Pmj02, Sequence, Sobol,
    VanDerCorput, ZeroTwo,
};
use nyquist::stratify::{self, Jitter};
use std::io::Write;
use std::path::PathBuf;

/// The most values (`count × dims`) one call prints: 2²⁸ (1 GiB of `f32`).
const MAX_VALUES: u64 = 1 << 28;

/// Point sets and samplers by their command-line names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SamplerName {
    /// Independent uniform random points (PCG32).
    Random,
    /// Cell centres of a regular grid (stratified without jitter).
    Uniform,
    /// Jittered stratified points, one per grid cell.
    Stratified,
    /// Latin hypercube: every dimension's strata hit once.
    Lhs,
    /// Van der Corput sequence (base 2, one dimension).
    Vdc,
    /// Halton sequence.
    Halton,
    /// Hammersley set (needs --count).
    Hammersley,
    /// Halton sequence with the folded (Zaremba) radical inverse.
    HaltonZaremba,
    /// Hammersley set with the folded radical inverse (needs --count).
    HammersleyZaremba,
    /// Scrambled (0,2)-sequence (two dimensions).
    ZeroTwo,
    /// Sobol sequence (Joe–Kuo, 1024 dimensions).
    Sobol,
    /// Mitchell's best-candidate blue noise from the baked table (pixel sampler: --spp).
    BestCandidate,
    /// Adaptive: wraps zero-two, minimum spp/4, maximum spp (pixel sampler: --spp).
    Adaptive,
    /// Owen-scrambled Sobol (Burley's hash construction; --seed picks the scramble); with
    /// --spp, one independent scramble per pixel.
    #[value(alias = "sobol-owen")]
    OwenSobol,
    /// ZSobol: Sobol along a hash-permuted Morton curve over the image (pixel sampler: --spp,
    /// --resolution).
    #[value(name = "zsobol")]
    ZSobol,
    /// Progressive multi-jittered (0,2) sequence (two dimensions; --seed picks the Owen
    /// scramble, 0 the baked table itself); with --spp, shuffled and scrambled per pixel.
    Pmj02,
    /// Fibonacci lattice (two dimensions; --count a Fibonacci number, default 21; --seed not 0
    /// picks a Cranley–Patterson rotation).
    Fibonacci,
    /// Korobov rank-1 lattice of --count points: the multiplier of Stroud's (1971) tables where
    /// they have --count and --dims (3 to 6 dimensions, primes 101 to 10007), else the minimiser
    /// of the P2 criterion (at most 4096 points; 2^24 in two dimensions); --seed not 0 picks a
    /// Cranley–Patterson rotation. With --spp, the pixel sampler korobov.
    Korobov,
    /// Roberts' R_d Kronecker sequence (R2 in two dimensions; --seed not 0 picks a
    /// Cranley–Patterson rotation in place of the start ½).
    #[value(name = "rd", alias = "r2")]
    Rd,
    /// Blue-noise dithered sampling: the zero-two set of pixel (0, 0) shifted per pixel by the
    /// built-in 64 × 64 blue-noise mask (pixel sampler: --spp).
    #[value(name = "bluenoise-dithered")]
    BluenoiseDithered,
    /// Maximal Poisson-disk set on the unit torus (Bridson's algorithm and a fill pass): about
    /// --count points, at least r = 0.78·√(2/(√3·count)) apart (two dimensions).
    PoissonDisk,
    /// Bridson's Poisson-disk set in the unit square, not maximal: the radius of poisson-disk
    /// for --count, so fewer points (two dimensions).
    Bridson,
}

/// Output formats of `points`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One point per line, values separated by commas, no header.
    Csv,
    /// One JSON array of points, each an array of numbers.
    Json,
    /// An SVG picture of dimensions 0 and 1 in the unit square (the pixel for --spp), with the
    /// strata grid where the sampler has one.
    Svg,
    /// The same picture as svg, as a PNG (needs --output FILE.png).
    Png,
}

/// Points, their dimension count, and the stratum grid to draw (if any).
pub type PixelPoints = (Vec<f32>, usize, Option<(u32, u32)>);

/// Arguments of `nyquist points`.
#[derive(Debug, Args)]
#[command(after_help = "Example: nyquist points --sampler sobol --count 8 --dims 3")]
pub struct PointsArgs {
    /// Which point set or sampler.
    #[arg(long, value_enum, default_value = "halton")]
    pub sampler: SamplerName,
    /// Number of points [default: 16; required for hammersley].
    #[arg(long)]
    pub count: Option<u64>,
    /// Dimensions per point [default: 2, or the set's own count when it has fewer (vdc: 1)].
    #[arg(long)]
    pub dims: Option<u32>,
    /// Seed of random and scrambled sets (plain vdc, halton, hammersley, their zaremba forms,
    /// sobol and uniform take none: a note says so).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Index of the first point of a sequence (sequences and random only).
    #[arg(long, default_value_t = 0)]
    pub skip: u64,
    /// Grid `NXxNY` for 2D uniform/stratified sets whose count is not a square.
    #[arg(long, value_parser = parse_grid)]
    pub grid: Option<(u32, u32)>,
    /// Pixel-sampler mode: print the SPP samples of one pixel (--pixel) from the sampler of
    /// the renderer instead of a sequence's points. Each point is the image sample (offset in
    /// the pixel) followed by dimensions 2, 3, … (time, lens u, lens v, …).
    #[arg(long)]
    pub spp: Option<u32>,
    /// The pixel `X,Y` whose samples --spp prints [default: 0,0].
    #[arg(long, value_parser = parse_pixel)]
    pub pixel: Option<(u32, u32)>,
    /// Image size `WxH` of the samplers that cover the whole image (halton, hammersley, sobol;
    /// required for them with --spp).
    #[arg(long, value_parser = parse_grid)]
    pub resolution: Option<(u32, u32)>,
    /// Output format.
    #[arg(long, value_enum, default_value = "csv")]
    pub format: Format,
    /// Write to this file instead of stdout (required for png). An extension that names
    /// another format than --format (.csv, .json, .svg, .png) is an error; an unknown one gets
    /// a note.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// Parses `NXxNY` (e.g. `4x3`) into positive grid sizes.
pub fn parse_grid(s: &str) -> Result<(u32, u32), String> {
    let (a, b) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("'{s}' is not NXxNY (e.g. 4x4)"))?;
    let parse = |t: &str| -> Result<u32, String> {
        match t.trim().parse::<u32>() {
            Ok(0) | Err(_) => Err(format!("'{s}' is not NXxNY with positive sizes (e.g. 4x4)")),
            Ok(v) => Ok(v),
        }
    };
    Ok((parse(a)?, parse(b)?))
}

/// Parses `X,Y` (e.g. `3,4`) into pixel coordinates.
pub fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("'{s}' is not X,Y with non-negative integers (e.g. 3,4)");
    let (a, b) = s.split_once(',').ok_or_else(bad)?;
    let x = a.trim().parse::<u32>().map_err(|_| bad())?;
    let y = b.trim().parse::<u32>().map_err(|_| bad())?;
    Ok((x, y))
}

/// Runs `nyquist points`.
pub fn run(args: &PointsArgs) -> Result<()> {
    match &args.output {
        Some(p) => check_extension(p, args.format)?,
        None if args.format == Format::Png => {
            bail!("--format png writes a picture: give --output FILE.png")
        }
        None => {}
    }
    if args.seed != 0 && !pixel_mode(args) && ignores_seed(args.sampler) {
        crate::output::note(&format!(
            "--seed {} changes nothing: {} points do not depend on a seed (with --spp, the \
             halton, hammersley and sobol pixel samplers are scrambled by it)",
            args.seed,
            name(args.sampler)
        ));
    }
    let (points, dims, grid) = if pixel_mode(args) {
        pixel_samples(args)?
    } else {
        let (points, dims) = generate(args)?;
        let grid = match (args.sampler, args.grid) {
            (SamplerName::Uniform | SamplerName::Stratified, Some(g)) => Some(g),
            (SamplerName::Uniform | SamplerName::Stratified, None) if dims == 2 => {
                let side = (points.len() / 2).isqrt() as u32;
                Some((side, side))
            }
            (SamplerName::Uniform | SamplerName::Stratified, None) => {
                Some(((points.len() / dims) as u32, 1))
            }
            _ => None,
        };
        (points, dims, grid)
    };
    let title = format!("nyquist points --sampler {}", name(args.sampler));
    if let (Format::Png, Some(path)) = (args.format, &args.output) {
        let canvas = nyquist_lab::svg::plot_points(&points, dims, grid, &title);
        return crate::pictures::write_bytes(path, "--output", &canvas.png()?);
    }
    crate::output::to_stdout_or_file(args.output.as_deref(), |w| match args.format {
        Format::Svg => nyquist_lab::svg::write_svg(w, &points, dims, grid, &title),
        f => write_points(w, &points, dims, f),
    })
}

/// Whether the point set `sampler` prints (without `--spp`) is the same for every seed.
pub fn ignores_seed(sampler: SamplerName) -> bool {
    use SamplerName as S;
    matches!(
        sampler,
        S::Uniform
            | S::Vdc
            | S::Halton
            | S::Hammersley
            | S::HaltonZaremba
            | S::HammersleyZaremba
            | S::Sobol
    )
}

/// The format each output extension names.
const EXTENSIONS: [(&str, Format); 5] = [
    ("csv", Format::Csv),
    ("txt", Format::Csv),
    ("json", Format::Json),
    ("svg", Format::Svg),
    ("png", Format::Png),
];

/// Checks `--output path` against `--format`: an extension that names another format is an
/// error, an unknown one a note; then the path's folder must take a file
/// ([`crate::output::check_output`]).
fn check_extension(path: &std::path::Path, format: Format) -> Result<()> {
    let fname = |f: Format| {
        f.to_possible_value()
            .map_or_else(String::new, |v| v.get_name().to_owned())
    };
    if let Some(ext) = crate::output::extension(path) {
        match EXTENSIONS.iter().find(|(e, _)| *e == ext) {
            Some(&(_, f)) if f != format => bail!(
                "--output {}: .{ext} names {} output but --format is {}: give --format {} or \
                 another extension",
                path.display(),
                fname(f),
                fname(format),
                fname(f)
            ),
            Some(_) => {}
            None if format == Format::Png => {}
            None => crate::output::note(&format!(
                "--output {}: unknown extension .{ext}, writing {} (--format)",
                path.display(),
                fname(format)
            )),
        }
    }
    let formats: &[&str] = if format == Format::Png { &["png"] } else { &[] };
    crate::output::check_output(path, "--output", formats)
}

/// The dimension count `args` asks for: `--dims`, else 2, or the set's own count when it has
/// fewer (vdc: 1).
pub fn dims_of(args: &PointsArgs) -> u32 {
    args.dims.unwrap_or(match args.sampler {
        SamplerName::Vdc if !pixel_mode(args) => VanDerCorput.dims(),
        _ => 2,
    })
}

/// The most dimensions a point set has (`None`: as many as memory allows).
fn max_dims(sampler: SamplerName) -> Option<u32> {
    use SamplerName as S;
    match sampler {
        S::Vdc => Some(VanDerCorput.dims()),
        S::ZeroTwo | S::Pmj02 | S::Fibonacci | S::PoissonDisk | S::Bridson => Some(2),
        S::Korobov | S::Rd => Some(1024),
        S::Halton | S::HaltonZaremba => Some(nyquist::radical::PRIME_COUNT),
        S::Hammersley | S::HammersleyZaremba => Some(nyquist::radical::PRIME_COUNT + 1),
        S::Sobol | S::OwenSobol => Some(nyquist::sequence::SOBOL_DIMS),
        _ => None,
    }
}

/// Whether `args` asks for one pixel's samples from a renderer's sampler (`--spp`, or a sampler
/// that exists only in that form).
pub fn pixel_mode(args: &PointsArgs) -> bool {
    args.spp.is_some()
        || args.pixel.is_some()
        || args.resolution.is_some()
        || matches!(
            args.sampler,
            SamplerName::BestCandidate
                | SamplerName::Adaptive
                | SamplerName::ZSobol
                | SamplerName::BluenoiseDithered
        )
}

/// The samples of one pixel from a [`nyquist::sampler::Sampler`]: point-major values, their
/// dimension count and the strata grid to draw (if any).
pub fn pixel_samples(args: &PointsArgs) -> Result<PixelPoints> {
    use SamplerName as S;
    use nyquist::sampler::{
        AdaptiveSampler, BestCandidateSampler, HaltonSampler, HaltonScramble, HammersleySampler,
        OwenSobolSampler, Pmj02Sampler, RandomSampler, Sampler, SobolSampler, StratifiedSampler,
        ZSobolSampler, ZeroTwoSampler,
    };
    let n = name(args.sampler);
    let dims = dims_of(args);
    if dims == 0 {
        bail!("--dims 0: a point needs at least one dimension");
    }
    if dims > 1024 {
        bail!("--dims {dims}: samplers have at most 1024 dimensions");
    }
    if let Some(count) = args.count {
        if args.spp.is_none() {
            bail!(
                "--count {count}: {n} is a pixel sampler: give --spp N (samples per pixel) \
                 instead of --count"
            );
        }
        bail!("--count {count} does not apply with --spp: a pixel takes spp samples");
    }
    if args.skip != 0 {
        bail!("--skip does not apply with --spp");
    }
    let Some(spp) = args.spp else {
        bail!("--spp is required for {n}: it samples pixels");
    };
    if spp == 0 {
        bail!("--spp 0: need at least one sample per pixel");
    }
    crate::render::check_spp_limit("--sampler", &n, spp)?;
    if u64::from(spp) * u64::from(dims) > MAX_VALUES {
        bail!("--spp {spp} × --dims {dims} is more than {MAX_VALUES} values");
    }
    let (px, py) = args.pixel.unwrap_or((0, 0));
    let global = matches!(
        args.sampler,
        S::Halton | S::Hammersley | S::Sobol | S::ZSobol
    );
    let resolution = match (args.resolution, global) {
        (Some((w, h)), _) => {
            if px >= w || py >= h {
                bail!("--pixel {px},{py} is outside --resolution {w}x{h}");
            }
            [w, h]
        }
        (None, true) => bail!(
            "--resolution WxH is required for {n} with --spp: its samples cover the whole image"
        ),
        (None, false) => [px.saturating_add(1), py.saturating_add(1)],
    };
    if args.resolution.is_some() && !global {
        bail!("--resolution applies to halton, hammersley, sobol and zsobol, not to {n}");
    }
    if args.grid.is_some() && !matches!(args.sampler, S::Uniform | S::Stratified) {
        bail!("--grid applies to uniform and stratified, not to {n}");
    }
    let err = |e: nyquist::Error| anyhow::anyhow!("{n}: {e}");
    let notice = |rounded: (u32, bool)| {
        if rounded.1 {
            eprintln!(
                "nyquist: note: {n} uses a power-of-two spp: --spp {spp} rounded up to {}",
                rounded.0
            );
        }
    };
    let mut grid = None;
    let mut sampler: Box<dyn Sampler> = match args.sampler {
        S::Random => Box::new(RandomSampler::new(spp, args.seed).map_err(err)?),
        S::Uniform | S::Stratified => {
            let (nx, ny) = match args.grid {
                Some((nx, ny)) if u64::from(nx) * u64::from(ny) == u64::from(spp) => (nx, ny),
                Some((nx, ny)) => bail!(
                    "--grid {nx}x{ny} has {} cells but --spp is {spp}",
                    u64::from(nx) * u64::from(ny)
                ),
                None => {
                    let side = spp.isqrt();
                    if side * side != spp {
                        bail!("--spp {spp} is not a square: give --grid NXxNY for {n}");
                    }
                    (side, side)
                }
            };
            grid = Some((nx, ny));
            Box::new(if args.sampler == S::Uniform {
                StratifiedSampler::uniform(nx, ny, args.seed).map_err(err)?
            } else {
                StratifiedSampler::new(nx, ny, nyquist::sampler::Jitter::Jittered, args.seed)
                    .map_err(err)?
            })
        }
        S::ZeroTwo => {
            notice(ZeroTwoSampler::rounded_spp(spp));
            Box::new(ZeroTwoSampler::new(spp, args.seed).map_err(err)?)
        }
        S::Sobol => {
            notice(SobolSampler::rounded_spp(spp));
            Box::new(SobolSampler::new(resolution, spp, args.seed).map_err(err)?)
        }
        S::Halton => Box::new(
            HaltonSampler::new(
                resolution,
                spp,
                if args.seed == 0 {
                    HaltonScramble::None
                } else {
                    HaltonScramble::PermuteDigits
                },
                args.seed,
            )
            .map_err(err)?,
        ),
        S::Hammersley => Box::new(
            HammersleySampler::new(resolution, spp, args.seed != 0, args.seed).map_err(err)?,
        ),
        S::BestCandidate => Box::new(BestCandidateSampler::new(spp, args.seed).map_err(err)?),
        S::OwenSobol => Box::new(OwenSobolSampler::new(spp, args.seed).map_err(err)?),
        S::Pmj02 => Box::new(Pmj02Sampler::new(spp, args.seed).map_err(err)?),
        S::ZSobol => {
            notice(ZSobolSampler::rounded_spp(spp));
            Box::new(
                ZSobolSampler::new(
                    resolution,
                    spp,
                    nyquist::scramble::Scramble::FastOwen,
                    args.seed,
                )
                .map_err(err)?,
            )
        }
        S::Adaptive => {
            notice(ZeroTwoSampler::rounded_spp(spp));
            let inner = ZeroTwoSampler::new(spp, args.seed).map_err(err)?;
            let min = (inner.samples_per_pixel() / 4).max(1);
            Box::new(AdaptiveSampler::new(inner, min, 0.1).map_err(err)?)
        }
        S::Fibonacci | S::Rd | S::Korobov => {
            let which = match args.sampler {
                S::Fibonacci => "fibonacci",
                S::Korobov => "korobov",
                _ => "r2",
            };
            let s = nyquist::sampler::NamedSampler::new(which, [1, 1], spp, args.seed)
                .map_err(|e| anyhow::anyhow!("--sampler {n}: {e}"))?;
            if s.samples_per_pixel() != spp {
                crate::output::note(&format!(
                    "{n} uses a Fibonacci number of samples: --spp {spp} rounded up to {}",
                    s.samples_per_pixel()
                ));
            }
            Box::new(s)
        }
        S::BluenoiseDithered => {
            notice(ZeroTwoSampler::rounded_spp(spp));
            Box::new(nyquist::sampler::DitheredSampler::new(
                ZeroTwoSampler::new(spp, args.seed).map_err(err)?,
                nyquist::sampler::MaskView::builtin(),
            ))
        }
        S::Lhs | S::Vdc | S::HaltonZaremba | S::HammersleyZaremba | S::PoissonDisk | S::Bridson => {
            bail!(
                "{n} is a point set, not a pixel sampler: drop --spp/--pixel/--resolution and use --count"
            )
        }
    };
    let spp = sampler.samples_per_pixel();
    let mut out = Vec::with_capacity(spp as usize * dims as usize);
    for i in 0..spp {
        sampler.start_pixel_sample([px, py], i, 0);
        let [x, y] = sampler.get_pixel_2d();
        out.push(x);
        if dims >= 2 {
            out.push(y);
        }
        for _ in 2..dims {
            out.push(sampler.get_1d());
        }
    }
    Ok((out, dims as usize, grid))
}

/// The Korobov lattice of `count` points in `dims` dimensions: Stroud's tabled multiplier where
/// the table has (`count`, `dims`), else the exhaustive P2 search up to 4096 points, and the
/// two-dimensional one above. A note on stderr says which.
fn korobov_lattice(count: u64, dims: u32) -> Result<Korobov, nyquist::Error> {
    let (lattice, how) = match Korobov::tabled(count, dims) {
        Ok(k) => (k, "from Stroud (1971), Tables 6.2–6.5"),
        Err(_) if dims == 2 && count > 4096 => (Korobov::searched_2d(count)?, "minimising P2"),
        Err(_) => (Korobov::searched(count, dims)?, "minimising P2"),
    };
    crate::output::note(&format!(
        "korobov: {count} points, multiplier {} {how}",
        lattice.multiplier()
    ));
    Ok(lattice)
}

/// Generates the points `args` asks for, point-major, and their dimension count.
pub fn generate(args: &PointsArgs) -> Result<(Vec<f32>, usize)> {
    use SamplerName as S;
    let dims = dims_of(args);
    if dims == 0 {
        bail!("--dims 0: a point needs at least one dimension");
    }
    if let Some(max) = max_dims(args.sampler)
        && dims > max
    {
        bail!(
            "--dims {dims}: {} has at most {max} dimension{}",
            name(args.sampler),
            if max == 1 { "" } else { "s" }
        );
    }
    let count = match (args.count, args.sampler, args.grid) {
        (Some(0), ..) => bail!("--count 0: need at least one point"),
        (Some(c), ..) => c,
        (None, S::Fibonacci, _) => 21,
        (None, S::Hammersley | S::HammersleyZaremba | S::Korobov, _) => {
            bail!(
                "--count is required for {}: the set's size is part of its definition",
                name(args.sampler)
            )
        }
        (None, _, Some((nx, ny))) => u64::from(nx) * u64::from(ny),
        (None, ..) => 16,
    };
    let values = count
        .checked_mul(u64::from(dims))
        .filter(|&v| v <= MAX_VALUES)
        .ok_or_else(|| {
            anyhow::anyhow!("--count {count} × --dims {dims} is more than {MAX_VALUES} values")
        })?;
    if args.skip != 0 && matches!(args.sampler, S::Uniform | S::Stratified | S::Lhs) {
        bail!(
            "--skip applies to sequences and random, not to {}",
            name(args.sampler)
        );
    }
    if args.grid.is_some() && !matches!(args.sampler, S::Uniform | S::Stratified) {
        bail!(
            "--grid applies to uniform and stratified, not to {}",
            name(args.sampler)
        );
    }
    nyquist_lab::memory::check(
        &format!("--count {count} × --dims {dims}"),
        nyquist_lab::memory::bytes(values, 4),
    )?;
    let mut out = nyquist_lab::memory::try_filled(values as usize, 0.0f32, "the points")?;
    let set_error = |e: nyquist::Error| anyhow::anyhow!("{}: {e}", name(args.sampler));
    match args.sampler {
        S::Random => {
            let mut rng = default_rng(args.seed);
            for _ in 0..args.skip.saturating_mul(u64::from(dims)) {
                uniform_f32(&mut rng);
            }
            out.iter_mut().for_each(|x| *x = uniform_f32(&mut rng));
        }
        S::Uniform | S::Stratified => {
            let jitter = if args.sampler == S::Uniform {
                Jitter::Centered
            } else {
                Jitter::Jittered
            };
            let mut rng = default_rng(args.seed);
            match dims {
                1 => stratify::stratified_1d(&mut out, jitter, &mut rng).map_err(set_error)?,
                2 => {
                    let (nx, ny) = match args.grid {
                        Some((nx, ny)) if u64::from(nx) * u64::from(ny) == count => (nx, ny),
                        Some((nx, ny)) => bail!(
                            "--grid {nx}x{ny} has {} cells but --count is {count}",
                            u64::from(nx) * u64::from(ny)
                        ),
                        None => {
                            let side = count.isqrt();
                            if side * side != count {
                                bail!(
                                    "--count {count} is not a square: give --grid NXxNY for 2D {}",
                                    name(args.sampler)
                                );
                            }
                            (side as u32, side as u32)
                        }
                    };
                    stratify::stratified_2d(&mut out, nx, ny, jitter, &mut rng)
                        .map_err(set_error)?;
                }
                _ => bail!(
                    "--dims {dims}: {} supports 1 or 2 dimensions (use lhs for more)",
                    name(args.sampler)
                ),
            }
        }
        S::Lhs => {
            stratify::latin_hypercube(&mut out, dims, &mut default_rng(args.seed))
                .map_err(set_error)?;
        }
        S::Vdc => fill(&VanDerCorput, args, &mut out)?,
        S::Halton => fill(&Halton::new(dims).map_err(set_error)?, args, &mut out)?,
        S::HaltonZaremba => fill(
            &HaltonZaremba::new(dims).map_err(set_error)?,
            args,
            &mut out,
        )?,
        S::Hammersley => fill(
            &Hammersley::new(count, dims).map_err(set_error)?,
            args,
            &mut out,
        )?,
        S::HammersleyZaremba => fill(
            &HammersleyZaremba::new(count, dims).map_err(set_error)?,
            args,
            &mut out,
        )?,
        S::ZeroTwo => fill(&ZeroTwo::from_seed(args.seed), args, &mut out)?,
        S::Sobol => fill(&Sobol::new(dims).map_err(set_error)?, args, &mut out)?,
        S::OwenSobol => fill(
            &OwenSobol::new(dims, args.seed).map_err(set_error)?,
            args,
            &mut out,
        )?,
        S::Pmj02 => {
            let set = if args.seed == 0 {
                Pmj02::new()
            } else {
                Pmj02::scrambled(args.seed)
            };
            fill(&set, args, &mut out)?
        }
        S::Fibonacci => {
            let lattice = FibonacciLattice::at_least(count).map_err(set_error)?;
            let n = lattice.point_count().unwrap_or(count);
            if n != count {
                bail!("--count {count} is not a Fibonacci number (the next is {n})");
            }
            let lattice = if args.seed == 0 {
                lattice
            } else {
                lattice.rotated(args.seed)
            };
            fill(&lattice, args, &mut out)?
        }
        S::Korobov => {
            let lattice = korobov_lattice(count, dims).map_err(|e| match e {
                nyquist::Error::OutOfRange { what: "n" } => {
                    let tabled: Vec<String> =
                        Korobov::tabled_sizes(dims).map(|n| n.to_string()).collect();
                    let tabled = if tabled.is_empty() {
                        String::new()
                    } else {
                        format!(
                            "; Stroud's table has {} for {dims} dimensions",
                            tabled.join(", ")
                        )
                    };
                    anyhow::anyhow!(
                        "--count {count}: korobov searches its multiplier for at most {} points \
                         in {dims} dimensions{tabled}",
                        if dims == 2 {
                            nyquist::lattice::KOROBOV_MAX_SEARCHED_2D
                        } else {
                            4096
                        }
                    )
                }
                e => set_error(e),
            })?;
            let lattice = if args.seed == 0 {
                lattice
            } else {
                lattice.rotated(args.seed)
            };
            fill(&lattice, args, &mut out)?
        }
        S::PoissonDisk | S::Bridson => {
            if args.skip != 0 {
                bail!(
                    "--skip applies to sequences and random, not to {}",
                    name(args.sampler)
                );
            }
            let (topology, maximal) = match args.sampler {
                S::PoissonDisk => (Topology::Torus, true),
                _ => (Topology::Square, false),
            };
            let count = u32::try_from(count)
                .map_err(|_| anyhow::anyhow!("--count {count}: too many for a Poisson-disk set"))?;
            let pd = PoissonDisk::with_count(count, topology, args.seed).map_err(|e| {
                anyhow::anyhow!(
                    "--count {count}: {}: {e} (at most about 1.2 million points)",
                    name(args.sampler)
                )
            })?;
            let pd = if maximal { pd.maximal() } else { pd };
            let (g, a) = pd.scratch_len();
            let mut pts = vec![0.0f64; 2 * g];
            let n = pd
                .generate(&mut pts, &mut vec![0; g], &mut vec![0; a])
                .map_err(set_error)?;
            crate::output::note(&format!(
                "{}: {n} points at least {} apart",
                name(args.sampler),
                pd.radius()
            ));
            out = pts[..2 * n].iter().map(|&v| v as f32).collect();
        }
        S::Rd => {
            let seq = Kronecker::new(dims).map_err(set_error)?;
            let seq = if args.seed == 0 {
                seq
            } else {
                seq.rotated(args.seed)
            };
            fill(&seq, args, &mut out)?
        }
        S::BestCandidate | S::Adaptive | S::ZSobol | S::BluenoiseDithered => {
            bail!("{} is a pixel sampler: give --spp", name(args.sampler))
        }
    }
    Ok((out, dims as usize))
}

fn fill(set: &dyn Sequence, args: &PointsArgs, out: &mut [f32]) -> Result<()> {
    let dims = dims_of(args);
    if dims > set.dims() {
        bail!(
            "--dims {dims}: {} has at most {} dimension{}",
            name(args.sampler),
            set.dims(),
            if set.dims() == 1 { "" } else { "s" }
        );
    }
    set.fill(args.skip, dims, out).map_err(|e| {
        anyhow::anyhow!("--skip {} --count: {}: {e}", args.skip, name(args.sampler))
    })?;
    Ok(())
}

/// The command-line name of a sampler.
pub fn name(s: SamplerName) -> String {
    s.to_possible_value()
        .map_or_else(String::new, |v| v.get_name().to_owned())
}

/// Writes points in `format`; each value is the shortest decimal that reads back to the same `f32`.
pub fn write_points(w: &mut dyn Write, points: &[f32], dims: usize, format: Format) -> Result<()> {
    match format {
        Format::Csv => {
            for p in points.chunks_exact(dims) {
                for (i, v) in p.iter().enumerate() {
                    if i > 0 {
                        w.write_all(b",")?;
                    }
                    write!(w, "{v}")?;
                }
                w.write_all(b"\n")?;
            }
        }
        Format::Json => {
            w.write_all(b"[")?;
            for (k, p) in points.chunks_exact(dims).enumerate() {
                w.write_all(if k == 0 { b"[" } else { b",[" })?;
                for (i, v) in p.iter().enumerate() {
                    if i > 0 {
                        w.write_all(b",")?;
                    }
                    write!(w, "{v}")?;
                }
                w.write_all(b"]")?;
            }
            w.write_all(b"]\n")?;
        }
        Format::Svg => nyquist_lab::svg::write_svg(w, points, dims, None, "nyquist points")?,
        Format::Png => bail!("--format png writes a picture: give --output FILE.png"),
    }
    Ok(())
}
