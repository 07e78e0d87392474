//! Point sets and pixel samplers by name: the points `nyquist points` prints, `analyze`
//! measures and the explorer draws, generated from one description ([`PointsSpec`]).
//!
//! ```
//! use nyquist_lab::points::{PointSetName, PointsSpec};
//! let spec = PointsSpec { sampler: PointSetName::Sobol, count: Some(4), ..PointsSpec::default() };
//! let p = spec.generate().unwrap();
//! // Natural order: the first coordinate is the van der Corput sequence 0, ½, ¼, ¾.
//! assert_eq!((p.values.as_slice(), p.dims), (&[0.0, 0.0, 0.5, 0.5, 0.25, 0.75, 0.75, 0.25][..], 2));
//! ```

use anyhow::{Result, bail};
use nyquist::analysis::Topology;
use nyquist::bluenoise::PoissonDisk;
use nyquist::lattice::Korobov;
use nyquist::rng::{default_rng, uniform_f32};
use nyquist::sequence::{NamedSequence, NamedSequenceError, Sequence, SequenceSpec, VanDerCorput};
use nyquist::stratify::{self, Jitter};

/// The most values (`count × dims`) one call generates: 2²⁸ (1 GiB of `f32`).
pub const MAX_VALUES: u64 = 1 << 28;

/// Point sets and pixel samplers by name (the command line's `--sampler` of `points` and
/// `analyze`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum PointSetName {
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
    /// Halton sequence (--seed permutes its digits).
    Halton,
    /// Hammersley set (needs --count).
    Hammersley,
    /// Halton sequence with the folded (Zaremba) radical inverse.
    HaltonZaremba,
    /// Hammersley set with the folded radical inverse (needs --count).
    HammersleyZaremba,
    /// The (0,2)-sequence (two dimensions; --seed adds a digital shift).
    ZeroTwo,
    /// Sobol sequence (Joe–Kuo, 1024 dimensions; --seed adds a digital shift).
    Sobol,
    /// Mitchell's best-candidate blue noise from the baked table (pixel sampler: --spp).
    BestCandidate,
    /// Adaptive: wraps zero-two, minimum spp/4, maximum spp (pixel sampler: --spp).
    Adaptive,
    /// Owen-scrambled Sobol (Burley's hash construction; --seed picks the scramble); with
    /// --spp, one independent scramble per pixel.
    #[cfg_attr(feature = "clap", value(alias = "sobol-owen"))]
    OwenSobol,
    /// Owen-scrambled Sobol with blue-noise error across pixels, its scrambles from an
    /// optimised 128 × 128 tile (pixel sampler: --spp).
    #[cfg_attr(feature = "clap", value(name = "owen-sobol-bn"))]
    OwenSobolBn,
    /// ZSobol: Sobol along a hash-permuted Morton curve over the image (pixel sampler: --spp,
    /// --resolution).
    #[cfg_attr(feature = "clap", value(name = "zsobol"))]
    ZSobol,
    /// Progressive multi-jittered (0,2) sequence (two dimensions: the baked table, or with
    /// --seed Owen-scrambled); with --spp, shuffled and scrambled per pixel.
    Pmj02,
    /// PMJ(0,2) with blue-noise error across pixels, its scrambles from an optimised
    /// 128 × 128 tile (pixel sampler: --spp).
    #[cfg_attr(feature = "clap", value(name = "pmj02-bn"))]
    Pmj02Bn,
    /// An extensible rank-1 lattice with blue-noise error across pixels, its shifts from an
    /// optimised 128 × 128 tile (pixel sampler: --spp).
    #[cfg_attr(feature = "clap", value(name = "lattice-bn"))]
    LatticeBn,
    /// Fibonacci lattice (two dimensions; --count a Fibonacci number, default 21; --seed picks
    /// a Cranley–Patterson rotation).
    Fibonacci,
    /// Korobov rank-1 lattice of --count points: the multiplier of Stroud's (1971) tables where
    /// they have --count and --dims (3 to 6 dimensions, primes 101 to 10007), else the minimiser
    /// of the P2 criterion (at most 4096 points; 2^24 in two dimensions); --seed picks a
    /// Cranley–Patterson rotation. With --spp, the pixel sampler korobov.
    Korobov,
    /// Roberts' R_d Kronecker sequence (R2 in two dimensions; --seed picks a Cranley–Patterson
    /// rotation in place of the start ½).
    #[cfg_attr(feature = "clap", value(name = "rd", alias = "r2"))]
    Rd,
    /// Blue-noise dithered sampling: the zero-two set of pixel (0, 0) shifted per pixel by the
    /// built-in 64 × 64 blue-noise mask (pixel sampler: --spp).
    #[cfg_attr(feature = "clap", value(name = "bluenoise-dithered"))]
    BluenoiseDithered,
    /// Maximal Poisson-disk set on the unit torus (Bridson's algorithm and a fill pass): about
    /// --count points, at least r = 0.78·√(2/(√3·count)) apart (two dimensions).
    PoissonDisk,
    /// Bridson's Poisson-disk set in the unit square, not maximal: the radius of poisson-disk
    /// for --count, so fewer points (two dimensions).
    Bridson,
}

impl PointSetName {
    /// Every name, in the order above.
    pub const ALL: [PointSetName; 25] = [
        PointSetName::Random,
        PointSetName::Uniform,
        PointSetName::Stratified,
        PointSetName::Lhs,
        PointSetName::Vdc,
        PointSetName::Halton,
        PointSetName::Hammersley,
        PointSetName::HaltonZaremba,
        PointSetName::HammersleyZaremba,
        PointSetName::ZeroTwo,
        PointSetName::Sobol,
        PointSetName::BestCandidate,
        PointSetName::Adaptive,
        PointSetName::OwenSobol,
        PointSetName::OwenSobolBn,
        PointSetName::ZSobol,
        PointSetName::Pmj02,
        PointSetName::Pmj02Bn,
        PointSetName::LatticeBn,
        PointSetName::Fibonacci,
        PointSetName::Korobov,
        PointSetName::Rd,
        PointSetName::BluenoiseDithered,
        PointSetName::PoissonDisk,
        PointSetName::Bridson,
    ];

    /// The name as the command line spells it.
    ///
    /// ```
    /// use nyquist_lab::points::PointSetName;
    /// assert_eq!(PointSetName::ZSobol.name(), "zsobol");
    /// assert_eq!(PointSetName::HaltonZaremba.name(), "halton-zaremba");
    /// ```
    pub fn name(self) -> &'static str {
        use PointSetName as S;
        match self {
            S::Random => "random",
            S::Uniform => "uniform",
            S::Stratified => "stratified",
            S::Lhs => "lhs",
            S::Vdc => "vdc",
            S::Halton => "halton",
            S::Hammersley => "hammersley",
            S::HaltonZaremba => "halton-zaremba",
            S::HammersleyZaremba => "hammersley-zaremba",
            S::ZeroTwo => "zero-two",
            S::Sobol => "sobol",
            S::BestCandidate => "best-candidate",
            S::Adaptive => "adaptive",
            S::OwenSobol => "owen-sobol",
            S::OwenSobolBn => "owen-sobol-bn",
            S::ZSobol => "zsobol",
            S::Pmj02 => "pmj02",
            S::Pmj02Bn => "pmj02-bn",
            S::LatticeBn => "lattice-bn",
            S::Fibonacci => "fibonacci",
            S::Korobov => "korobov",
            S::Rd => "rd",
            S::BluenoiseDithered => "bluenoise-dithered",
            S::PoissonDisk => "poisson-disk",
            S::Bridson => "bridson",
        }
    }
}

/// What to generate: a point set (`count` points of `dims` dimensions) or, in pixel-sampler
/// mode (`spp`, `pixel`, `resolution`, or a sampler that exists only as one), one pixel's
/// samples from a renderer's sampler. With the `clap` feature it is also the command line's
/// argument group of `points` (errors name the fields as flags: `--count`, `--spp`, …).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct PointsSpec {
    /// Which point set or sampler.
    #[cfg_attr(feature = "clap", arg(long, value_enum, default_value = "halton"))]
    pub sampler: PointSetName,
    /// Number of points [default: 16; required for hammersley].
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1, MAX_VALUES)))]
    pub count: Option<u64>,
    /// Dimensions per point [default: 2, or the set's own count when it has fewer (vdc: 1)].
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1, MAX_VALUES as u32)))]
    pub dims: Option<u32>,
    /// Seed of the random sets and pixel samplers [default: 0]; for halton, sobol, zero-two,
    /// pmj02, fibonacci, korobov and rd it asks for their randomization (digit permutation,
    /// digital shift, Owen scramble, rotation; any seed, 0 included), which they lack without
    /// it. vdc, hammersley, the zaremba forms and uniform point sets take none.
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(0, u64::MAX)))]
    pub seed: Option<u64>,
    /// Index of the first point of a sequence (sequences and random only).
    #[cfg_attr(feature = "clap", arg(long, default_value_t = 0, value_parser = crate::flags::whole(0, u64::MAX)))]
    pub skip: u64,
    /// Grid `NXxNY` for 2D uniform/stratified sets whose count is not a square.
    #[cfg_attr(feature = "clap", arg(long, value_parser = parse_grid))]
    pub grid: Option<(u32, u32)>,
    /// Pixel-sampler mode: the SPP samples of one pixel (--pixel) from the sampler of the
    /// renderer instead of a sequence's points. Each point is the image sample (offset in the
    /// pixel) followed by dimensions 2, 3, … (time, lens u, lens v, …).
    #[cfg_attr(feature = "clap", arg(long, value_parser = crate::flags::whole(1, crate::study::MAX_SPP)))]
    pub spp: Option<u32>,
    /// The pixel `X,Y` whose samples --spp gives [default: 0,0].
    #[cfg_attr(feature = "clap", arg(long, value_parser = parse_pixel))]
    pub pixel: Option<(u32, u32)>,
    /// Image size `WxH` of the samplers that cover the whole image (halton, hammersley, sobol;
    /// required for them with --spp).
    #[cfg_attr(feature = "clap", arg(long, value_parser = parse_grid))]
    pub resolution: Option<(u32, u32)>,
}

impl Default for PointsSpec {
    /// 16 two-dimensional Halton points.
    fn default() -> PointsSpec {
        PointsSpec {
            sampler: PointSetName::Halton,
            count: None,
            dims: None,
            seed: None,
            skip: 0,
            grid: None,
            spp: None,
            pixel: None,
            resolution: None,
        }
    }
}

/// Generated points and what a front end should tell about them.
#[derive(Clone, Debug, PartialEq)]
pub struct Points {
    /// Point-major values.
    pub values: Vec<f32>,
    /// Dimensions per point.
    pub dims: usize,
    /// The strata grid to draw, where the set has one.
    pub grid: Option<(u32, u32)>,
    /// Notes for the user (a rounded spp, the chosen Korobov multiplier, …), one line each.
    pub notes: Vec<String>,
}

impl PointsSpec {
    /// Generates the points this spec describes: one pixel's samples in pixel-sampler mode
    /// ([`PointsSpec::pixel_mode`]), else the point set.
    ///
    /// # Errors
    /// One line naming the field at fault as a flag (`--count 0: need at least one point`).
    pub fn generate(&self) -> Result<Points> {
        let mut notes = Vec::new();
        let (values, dims, grid) = if self.pixel_mode() {
            pixel_samples(self, &mut notes)?
        } else {
            let (values, dims) = generate(self, &mut notes)?;
            let grid = match (self.sampler, self.grid) {
                (PointSetName::Uniform | PointSetName::Stratified, Some(g)) => Some(g),
                (PointSetName::Uniform | PointSetName::Stratified, None) if dims == 2 => {
                    let side = (values.len() / 2).isqrt() as u32;
                    Some((side, side))
                }
                (PointSetName::Uniform | PointSetName::Stratified, None) => {
                    Some(((values.len() / dims.max(1)) as u32, 1))
                }
                _ => None,
            };
            (values, dims, grid)
        };
        Ok(Points {
            values,
            dims,
            grid,
            notes,
        })
    }
}

impl PointsSpec {
    /// Whether this spec asks for one pixel's samples from a renderer's sampler (`spp`,
    /// `pixel` or `resolution` given, or a sampler that exists only in that form).
    ///
    /// ```
    /// use nyquist_lab::points::{PointSetName, PointsSpec};
    /// assert!(PointsSpec { sampler: PointSetName::ZSobol, ..PointsSpec::default() }.pixel_mode());
    /// assert!(!PointsSpec::default().pixel_mode());
    /// ```
    pub fn pixel_mode(&self) -> bool {
        pixel_mode(self)
    }

    /// The dimension count asked for: `dims`, else 2, or the set's own count when it has
    /// fewer (vdc: 1).
    pub fn dims(&self) -> u32 {
        dims_of(self)
    }
}

/// Points, their dimension count, and the stratum grid to draw (if any).
type PixelPoints = (Vec<f32>, usize, Option<(u32, u32)>);

/// Parses `NXxNY` (e.g. `4x3`) into positive grid sizes.
pub fn parse_grid(s: &str) -> Result<(u32, u32), String> {
    let (a, b) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| "not NXxNY (e.g. 4x4)".to_owned())?;
    let parse = |t: &str| -> Result<u32, String> {
        match t.trim().parse::<u32>() {
            Ok(0) | Err(_) => Err("not NXxNY with positive sizes (e.g. 4x4)".to_owned()),
            Ok(v) => Ok(v),
        }
    };
    Ok((parse(a)?, parse(b)?))
}

/// Parses `X,Y` (e.g. `3,4`) into pixel coordinates.
pub fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let bad = || "not X,Y with non-negative integers (e.g. 3,4)".to_owned();
    let (a, b) = s.split_once(',').ok_or_else(bad)?;
    let x = a.trim().parse::<u32>().map_err(|_| bad())?;
    let y = b.trim().parse::<u32>().map_err(|_| bad())?;
    Ok((x, y))
}

/// Whether the point set `sampler` (without `--spp`) has no randomization, so that a seed is
/// refused: uniform, vdc, hammersley and the zaremba forms.
///
/// ```
/// use nyquist_lab::points::{PointSetName, ignores_seed};
/// assert!(ignores_seed(PointSetName::Hammersley));
/// assert!(!ignores_seed(PointSetName::Halton)); // a seed permutes its digits
/// ```
pub fn ignores_seed(sampler: PointSetName) -> bool {
    use PointSetName as S;
    matches!(
        sampler,
        S::Uniform | S::Vdc | S::Hammersley | S::HaltonZaremba | S::HammersleyZaremba
    )
}

/// Whether the point set `sampler` (without `--spp`) is deterministic unless a seed asks for
/// its randomization: halton, sobol, zero-two, pmj02 and the lattices. The other sets (random,
/// stratified, lhs, owen-sobol, the Poisson-disk sets) are always random (seed 0 by default),
/// or have no randomization ([`ignores_seed`]).
///
/// ```
/// use nyquist_lab::points::{PointSetName, randomized_on_request};
/// assert!(randomized_on_request(PointSetName::Sobol));
/// assert!(!randomized_on_request(PointSetName::Random));
/// ```
pub fn randomized_on_request(sampler: PointSetName) -> bool {
    use PointSetName as S;
    matches!(
        sampler,
        S::Halton | S::Sobol | S::ZeroTwo | S::Pmj02 | S::Fibonacci | S::Korobov | S::Rd
    )
}

/// The dimension count `args` asks for: `--dims`, else 2, or the set's own count when it has
/// fewer (vdc: 1).
pub fn dims_of(args: &PointsSpec) -> u32 {
    args.dims.unwrap_or(match args.sampler {
        PointSetName::Vdc if !pixel_mode(args) => VanDerCorput.dims(),
        _ => 2,
    })
}

/// The most dimensions a point set has (`None`: as many as memory allows).
fn max_dims(sampler: PointSetName) -> Option<u32> {
    use PointSetName as S;
    match sampler {
        S::Vdc => Some(VanDerCorput.dims()),
        S::ZeroTwo | S::Pmj02 | S::Fibonacci | S::PoissonDisk | S::Bridson => Some(2),
        S::Korobov | S::Rd => Some(1024),
        S::Halton | S::HaltonZaremba => Some(nyquist::radical::PRIME_COUNT),
        S::Hammersley | S::HammersleyZaremba => Some(nyquist::radical::PRIME_COUNT + 1),
        _ => None,
    }
}

/// Whether `args` asks for one pixel's samples from a renderer's sampler (`--spp`, or a sampler
/// that exists only in that form).
fn pixel_mode(args: &PointsSpec) -> bool {
    args.spp.is_some()
        || args.pixel.is_some()
        || args.resolution.is_some()
        || matches!(
            args.sampler,
            PointSetName::BestCandidate
                | PointSetName::Adaptive
                | PointSetName::ZSobol
                | PointSetName::BluenoiseDithered
        )
}

/// The samples of one pixel from a [`nyquist::sampler::Sampler`]: point-major values, their
/// dimension count and the strata grid to draw (if any).
fn pixel_samples(args: &PointsSpec, notes: &mut Vec<String>) -> Result<PixelPoints> {
    use PointSetName as S;
    use nyquist::sampler::{NamedSampler, Sampler, StratifiedSampler};
    let n = args.sampler.name();
    let dims = dims_of(args);
    if dims == 0 {
        bail!("--dims 0: a point needs at least one dimension");
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
    if let Some(max) = nyquist::sampler::spp_limit(n)
        && spp > max
    {
        bail!("--sampler {n} --spp {spp}: {n} takes at most {max} samples per pixel");
    }
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
    let seed = args.seed.unwrap_or(0);
    let name = match args.sampler {
        S::Rd => "r2",
        S::Lhs | S::Vdc | S::HaltonZaremba | S::HammersleyZaremba | S::PoissonDisk | S::Bridson => {
            bail!(
                "{n} is a point set, not a pixel sampler: drop --spp/--pixel/--resolution and use --count"
            )
        }
        other => other.name(),
    };
    let mut grid = None;
    let mut sampler: Box<dyn Sampler> = match (args.sampler, args.grid) {
        (S::Uniform | S::Stratified, Some((nx, ny))) => {
            if u64::from(nx) * u64::from(ny) != u64::from(spp) {
                bail!(
                    "--grid {nx}x{ny} has {} cells but --spp is {spp}",
                    u64::from(nx) * u64::from(ny)
                );
            }
            grid = Some((nx, ny));
            let jitter = if args.sampler == S::Uniform {
                nyquist::sampler::Jitter::Centered
            } else {
                nyquist::sampler::Jitter::Jittered
            };
            Box::new(
                StratifiedSampler::new(nx, ny, jitter, seed)
                    .map_err(|e| anyhow::anyhow!("{n}: {e}"))?,
            )
        }
        _ => {
            let s = NamedSampler::new(name, resolution, spp, seed)
                .map_err(|e| anyhow::anyhow!("--sampler {n}: {e}"))?;
            if matches!(args.sampler, S::Uniform | S::Stratified) {
                let [nx, ny] = nyquist::sampler::strata(spp);
                grid = Some((nx, ny));
            }
            if s.samples_per_pixel() != spp {
                let why = match args.sampler {
                    S::Fibonacci => "a Fibonacci number of samples",
                    _ => "a power-of-two spp",
                };
                notes.push(format!(
                    "{n} uses {why}: --spp {spp} rounded up to {}",
                    s.samples_per_pixel()
                ));
            }
            Box::new(s)
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

/// The core's [`NamedSequence`] for the sequence `args` names: `count` is the set's size for
/// hammersley, its zaremba form, fibonacci and korobov; `--seed` asks for the randomization.
/// Notes which Korobov multiplier was taken.
fn named_sequence(
    args: &PointsSpec,
    count: u64,
    dims: u32,
    notes: &mut Vec<String>,
) -> Result<NamedSequence> {
    use PointSetName as S;
    let name = match args.sampler {
        S::Rd => "rd",
        other => other.name(),
    };
    let tabled = args.sampler == S::Korobov && Korobov::tabled(count, dims).is_ok();
    let spec = SequenceSpec {
        dims,
        points: nyquist::sequence::takes_points(name).then_some(count),
        seed: args.seed,
        multiplier: None,
    };
    let set = NamedSequence::new(name, spec).map_err(|e| match (e, args.seed) {
        (
            NamedSequenceError::Sequence(nyquist::Error::Invalid {
                what: "points",
                other: next,
                ..
            }),
            _,
        ) if args.sampler == S::Fibonacci => {
            anyhow::anyhow!("--count {count} is not a Fibonacci number (the next is {next})")
        }
        // Above the multiplier search's limit: say which sizes Stroud's table has instead.
        (
            NamedSequenceError::Sequence(nyquist::Error::NotInRange {
                what: "n",
                value,
                max,
                ..
            }),
            _,
        ) if args.sampler == S::Korobov && value > max => {
            let sizes: Vec<String> = Korobov::tabled_sizes(dims).map(|n| n.to_string()).collect();
            let table = if sizes.is_empty() {
                String::new()
            } else {
                format!(
                    "; Stroud's table has {} for {dims} dimensions",
                    sizes.join(", ")
                )
            };
            anyhow::anyhow!(
                "--count {count}: korobov searches its multiplier for at most {max} points in \
                 {dims} dimensions{table}"
            )
        }
        (NamedSequenceError::NotRandomized { .. }, Some(seed)) => anyhow::anyhow!(
            "--seed {seed}: {} has no randomization, its points do not depend on a seed (drop \
             --seed; halton, sobol, zero-two, pmj02, fibonacci, korobov and rd take one)",
            args.sampler.name()
        ),
        (e, _) => anyhow::anyhow!("--sampler {}: {e}", args.sampler.name()),
    })?;
    if let NamedSequence::Korobov(k) = &set {
        let how = if tabled {
            "from Stroud (1971), Tables 6.2–6.5"
        } else {
            "minimising P2"
        };
        notes.push(format!(
            "korobov: {count} points, multiplier {} {how}",
            k.multiplier()
        ));
    }
    Ok(set)
}

/// Generates the points `args` asks for, point-major, and their dimension count.
fn generate(args: &PointsSpec, notes: &mut Vec<String>) -> Result<(Vec<f32>, usize)> {
    use PointSetName as S;
    let dims = dims_of(args);
    if dims == 0 {
        bail!("--dims 0: a point needs at least one dimension");
    }
    if let Some(max) = max_dims(args.sampler)
        && dims > max
    {
        bail!(
            "--dims {dims}: {} has at most {max} dimension{}",
            args.sampler.name(),
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
                args.sampler.name()
            )
        }
        (None, _, Some((nx, ny))) => u64::from(nx) * u64::from(ny),
        (None, ..) => 16,
    };
    // The flags the count came from: --count, or the grid when it gave the count.
    let count_flags = match (args.count, args.grid) {
        (None, Some((nx, ny))) => format!("--grid {nx}x{ny} ({count} points)"),
        _ => format!("--count {count}"),
    };
    let values = count
        .checked_mul(u64::from(dims))
        .filter(|&v| v <= MAX_VALUES)
        .ok_or_else(|| {
            anyhow::anyhow!("{count_flags} × --dims {dims} is more than {MAX_VALUES} values")
        })?;
    if args.skip != 0 && matches!(args.sampler, S::Uniform | S::Stratified | S::Lhs) {
        bail!(
            "--skip applies to sequences and random, not to {}",
            args.sampler.name()
        );
    }
    if args.grid.is_some() && !matches!(args.sampler, S::Uniform | S::Stratified) {
        bail!(
            "--grid applies to uniform and stratified, not to {}",
            args.sampler.name()
        );
    }
    crate::memory::check(
        &format!("{count_flags} × --dims {dims}"),
        crate::memory::bytes(values, 4),
    )?;
    if let Some(seed) = args.seed
        && ignores_seed(args.sampler)
    {
        bail!(
            "--seed {seed}: {} has no randomization, its points do not depend on a seed (drop \
             --seed; halton, sobol, zero-two, pmj02, fibonacci, korobov and rd take one)",
            args.sampler.name()
        );
    }
    let mut out = crate::memory::try_filled(values as usize, 0.0f32, "the points")?;
    let set_error = |e: nyquist::Error| anyhow::anyhow!("{}: {e}", args.sampler.name());
    match args.sampler {
        S::Random => {
            let mut rng = default_rng(args.seed.unwrap_or(0));
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
            let mut rng = default_rng(args.seed.unwrap_or(0));
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
                                    args.sampler.name()
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
                    args.sampler.name()
                ),
            }
        }
        S::Lhs => {
            stratify::latin_hypercube(&mut out, dims, &mut default_rng(args.seed.unwrap_or(0)))
                .map_err(set_error)?;
        }
        S::Vdc
        | S::Halton
        | S::HaltonZaremba
        | S::Hammersley
        | S::HammersleyZaremba
        | S::ZeroTwo
        | S::Sobol
        | S::OwenSobol
        | S::Pmj02
        | S::Fibonacci
        | S::Korobov => fill(&named_sequence(args, count, dims, notes)?, args, &mut out)?,
        S::PoissonDisk | S::Bridson => {
            if args.skip != 0 {
                bail!(
                    "--skip applies to sequences and random, not to {}",
                    args.sampler.name()
                );
            }
            let (topology, maximal) = match args.sampler {
                S::PoissonDisk => (Topology::Torus, true),
                _ => (Topology::Square, false),
            };
            let count = u32::try_from(count)
                .map_err(|_| anyhow::anyhow!("--count {count}: too many for a Poisson-disk set"))?;
            let pd =
                PoissonDisk::with_count(count, topology, args.seed.unwrap_or(0)).map_err(|e| {
                    anyhow::anyhow!(
                        "--count {count}: {}: {e} (at most about 1.2 million points)",
                        args.sampler.name()
                    )
                })?;
            let pd = if maximal { pd.maximal() } else { pd };
            let (g, a) = pd.scratch_len();
            let mut pts = vec![0.0f64; 2 * g];
            let n = pd
                .generate(&mut pts, &mut vec![0; g], &mut vec![0; a])
                .map_err(set_error)?;
            notes.push(format!(
                "{}: {n} points at least {} apart",
                args.sampler.name(),
                pd.radius()
            ));
            out = pts[..2 * n].iter().map(|&v| v as f32).collect();
        }
        S::Rd => fill(&named_sequence(args, count, dims, notes)?, args, &mut out)?,
        S::BestCandidate
        | S::Adaptive
        | S::ZSobol
        | S::OwenSobolBn
        | S::Pmj02Bn
        | S::LatticeBn
        | S::BluenoiseDithered => {
            bail!("{} is a pixel sampler: give --spp", args.sampler.name())
        }
    }
    Ok((out, dims as usize))
}

fn fill(set: &dyn Sequence, args: &PointsSpec, out: &mut [f32]) -> Result<()> {
    let dims = dims_of(args);
    if dims > set.dims() {
        bail!(
            "--dims {dims}: {} has at most {} dimension{}",
            args.sampler.name(),
            set.dims(),
            if set.dims() == 1 { "" } else { "s" }
        );
    }
    let count = (out.len() / dims.max(1) as usize) as u64;
    set.fill(args.skip, dims, out)
        .map_err(|e| index_error(e, args.sampler.name(), args.skip, count))?;
    Ok(())
}

/// The sequence's refusal of `--skip`/`--count` in the flags' terms, with the set's index limit.
fn index_error(e: nyquist::Error, name: &str, skip: u64, count: u64) -> anyhow::Error {
    use nyquist::Error::TooMany;
    match e {
        TooMany {
            what: "index range",
            max,
            ..
        } if skip == 0 => anyhow::anyhow!("--count {count}: {name} has at most {max} points"),
        TooMany {
            what: "index range",
            max,
            ..
        } => anyhow::anyhow!(
            "--skip {skip} --count {count}: {name} has {max} points (indices 0 ..= {}); these \
             would end at index {}",
            max.saturating_sub(1),
            skip.saturating_add(count - 1)
        ),
        TooMany {
            what: "first", max, ..
        } => anyhow::anyhow!("--skip {skip}: {name}'s first index is at most {max}"),
        other => anyhow::anyhow!("--skip {skip} --count {count}: {name}: {other}"),
    }
}
