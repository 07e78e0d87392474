//! Rendering the test scenes: the sample loop over a film, the references an image is
//! measured against (exact, or a cached stratified render), and the image error.
//!
//! ```
//! use nyquist::{filter::FilterKind, sampler::NamedSampler};
//! use nyquist_lab::{render, scene::Scene};
//! let sampler = NamedSampler::new("stratified", [16, 16], 16, 1).unwrap();
//! let filter = FilterKind::parse("box").unwrap();
//! let r = render::render(Scene::Zoneplate, [16, 16], &sampler, &filter, 1, &mut || {}).unwrap();
//! let exact = render::reference_with_progress(Scene::Zoneplate, [16, 16], None, 1, &mut || {})
//!     .unwrap()
//!     .unwrap();
//! assert!(render::rmse(&r.image, &exact) < 0.1);
//! ```

use crate::clock::Stopwatch;
use crate::scene::Scene;
use anyhow::bail;
use anyhow::{Result, anyhow};
use nyquist::filter::FilterKind;
use nyquist::sampler::{NamedSampler, NamedSamplerError, Sampler, film_coordinate};
use nyquist::scramble::Scramble;
use nyquist_film::adaptive::{AdaptiveConfig, AdaptiveReport, ErrorEstimate, render_adaptive};
use nyquist_film::extras::ExtraImages;
use nyquist_film::{Film, FilmConfig, FilmSample, FilmStats, Image, PixelExtras, render_tiles};
use std::path::{Path, PathBuf};

/// No file system in the browser (`wasm32-unknown-unknown`): there the references are not
/// cached on disk (the explorer keeps them in memory).
const NO_FILE_SYSTEM: bool = cfg!(all(target_arch = "wasm32", target_os = "unknown"));

/// Tile side of the film: small enough to balance two threads on a 64 × 64 image.
pub const TILE: u32 = 16;
/// The largest image side `--size` accepts.
pub const MAX_SIDE: u32 = 16384;
/// The most pixels `--size` accepts (the film keeps 32 bytes per pixel: 2 GiB).
pub const MAX_PIXELS: u64 = 1 << 26;
/// The cached reference of scenes without a closed form: stratified, this many strata per axis.
const REFERENCE_STRATA: u32 = 32;
/// Seed of the cached reference renders.
const REFERENCE_SEED: u64 = 0x5eed_4ef0;

/// Pixel samplers by name: the names of [`nyquist::sampler::NAMES`], each with its one-line
/// description (the command line's `--sampler` of `render` and `compare`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum SamplerName {
    /// One sample at the centre of each of √spp × √spp strata: the aliasing baseline.
    Uniform,
    /// Independent uniform random samples (PCG32).
    Random,
    /// Jittered strata, √spp × √spp per pixel.
    Stratified,
    /// One Halton sequence over the whole image, digit-permuted by --seed (--scramble none:
    /// unscrambled).
    Halton,
    /// Hammersley points per pixel block, digit-permuted by --seed (--scramble none:
    /// unscrambled).
    Hammersley,
    /// Scrambled (0,2)-sequence per pixel (spp rounded up to a power of two).
    ZeroTwo,
    /// One Sobol sequence over the whole image, digit-permuted by --seed (--scramble none:
    /// unscrambled; spp rounded up to a power of two).
    Sobol,
    /// Mitchell's best-candidate blue noise.
    BestCandidate,
    /// Adaptive: zero-two, spp/4 samples, all spp where the first ones disagree.
    Adaptive,
    /// Owen-scrambled Sobol per pixel, hashed by pixel, frame and seed.
    #[cfg_attr(feature = "clap", value(alias = "sobol-owen"))]
    OwenSobol,
    /// Owen-scrambled Sobol per pixel with blue-noise error across pixels: the scrambles come
    /// from an optimised 128 × 128 tile (docs/blue-noise.md).
    #[cfg_attr(feature = "clap", value(name = "owen-sobol-bn"))]
    OwenSobolBn,
    /// Sobol along a hash-permuted Morton curve: blue-noise error across pixels (spp rounded
    /// up to a power of two).
    #[cfg_attr(feature = "clap", value(name = "zsobol"))]
    ZSobol,
    /// Progressive multi-jittered (0,2) points, shuffled and Owen-scrambled per pixel.
    Pmj02,
    /// PMJ(0,2) per pixel with blue-noise error across pixels, from an optimised 128 × 128
    /// tile (docs/blue-noise.md).
    #[cfg_attr(feature = "clap", value(name = "pmj02-bn"))]
    Pmj02Bn,
    /// Blue-noise dithered: one zero-two set for every pixel, toroidally shifted by a 64 × 64
    /// blue-noise mask, so the error is blue noise (spp rounded up to a power of two).
    #[cfg_attr(feature = "clap", value(name = "bluenoise-dithered"))]
    BluenoiseDithered,
    /// The Fibonacci lattice per dimension pair, Cranley–Patterson rotated per pixel and pair
    /// (spp rounded up to a Fibonacci number).
    Fibonacci,
    /// Roberts' R2 per dimension pair, rotated per pixel and pair.
    #[cfg_attr(feature = "clap", value(name = "r2"))]
    R2,
    /// The Korobov lattice of exactly spp points per dimension pair (multiplier minimising
    /// P2), Cranley–Patterson rotated per pixel and pair.
    Korobov,
    /// An extensible rank-1 lattice per pixel with blue-noise error across pixels, from an
    /// optimised 128 × 128 tile (docs/blue-noise.md).
    #[cfg_attr(feature = "clap", value(name = "lattice-bn"))]
    LatticeBn,
}

impl SamplerName {
    /// Whether the sampler continues past the spp it was made for
    /// ([`nyquist::sampler::continues`]): the ones `render --spp-hint` takes.
    ///
    /// ```
    /// use nyquist_lab::render::SamplerName;
    /// assert!(SamplerName::ZSobol.continues() && !SamplerName::ZeroTwo.continues());
    /// ```
    pub fn continues(self) -> bool {
        nyquist::sampler::continues(self.name())
    }

    /// The name, as [`NamedSampler::new`] takes it.
    ///
    /// ```
    /// use nyquist_lab::render::SamplerName;
    /// assert_eq!(SamplerName::ZSobol.name(), "zsobol");
    /// assert_eq!(SamplerName::BluenoiseDithered.name(), "bluenoise-dithered");
    /// ```
    pub fn name(self) -> &'static str {
        use SamplerName as S;
        match self {
            S::Uniform => "uniform",
            S::Random => "random",
            S::Stratified => "stratified",
            S::Halton => "halton",
            S::Hammersley => "hammersley",
            S::ZeroTwo => "zero-two",
            S::Sobol => "sobol",
            S::BestCandidate => "best-candidate",
            S::Adaptive => "adaptive",
            S::OwenSobol => "owen-sobol",
            S::OwenSobolBn => "owen-sobol-bn",
            S::ZSobol => "zsobol",
            S::Pmj02 => "pmj02",
            S::Pmj02Bn => "pmj02-bn",
            S::BluenoiseDithered => "bluenoise-dithered",
            S::Fibonacci => "fibonacci",
            S::R2 => "r2",
            S::Korobov => "korobov",
            S::LatticeBn => "lattice-bn",
        }
    }
}

/// The scrambles of `--scramble`: core's [`Scramble`], under the same names
/// ([`Scramble::name`]; a test holds them equal), and `permute` for `permute-digits`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum ScrambleName {
    /// The plain sequence.
    None,
    /// A random permutation of the digits per digit position (and dimension).
    #[cfg_attr(feature = "clap", value(alias = "permute"))]
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
    if spp > crate::study::MAX_SPP {
        bail!(
            "--spp {spp}: at most {} samples per pixel",
            crate::study::MAX_SPP
        );
    }
    check_spp_limit("--sampler", n, spp)?;
    let built = match scramble {
        Some(sc) => NamedSampler::with_scramble(n, size, spp, seed, sc.scramble()),
        None => NamedSampler::new(n, size, spp, seed),
    };
    built.map_err(|e| match e {
        NamedSamplerError::NoScramble => anyhow!("--scramble: --sampler {n}: {e}"),
        e => anyhow!("--sampler {n} --spp {spp}: {e}"),
    })
}

/// Parses `WxH` (e.g. `256x256`) into an image size, each side 1 to [`MAX_SIDE`].
pub fn parse_size(s: &str) -> Result<[u32; 2], String> {
    let bad = || format!("not WxH with sides 1 to {MAX_SIDE} (e.g. 256x256)");
    let (a, b) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let side = |t: &str| match t.trim().parse::<u32>() {
        Ok(v) if (1..=MAX_SIDE).contains(&v) => Ok(v),
        _ => Err(bad()),
    };
    let size = [side(a)?, side(b)?];
    if u64::from(size[0]) * u64::from(size[1]) > MAX_PIXELS {
        return Err(format!("more than {MAX_PIXELS} pixels"));
    }
    Ok(size)
}

/// Parses a filter spec, the error listing the filters and keys.
pub fn parse_filter(s: &str) -> Result<FilterKind, String> {
    FilterKind::parse(s).map_err(|e| match e {
        // That message lists the names already.
        nyquist::filter::SpecError::UnknownFilter { .. } => e.to_string(),
        _ => {
            let mut names = String::new();
            for n in nyquist::filter::FILTER_NAMES {
                if !names.is_empty() {
                    names.push_str(", ");
                }
                names.push_str(n);
            }
            format!("{e} (filters: {names}; e.g. mitchell:b=0.5,c=0.25)")
        }
    })
}

/// Pixel updates above which `render` and `compare` warn before they start (several seconds or
/// more of one core's work).
pub const LARGE_WORK: f64 = 2e9;

/// Pixels one sample of a `size` image adds to through `filter`: its footprint, `2r + 1`
/// pixels per axis, clipped to the image.
pub fn footprint_pixels(size: [u32; 2], filter: &FilterKind) -> f64 {
    let [rx, ry] = nyquist::filter::Filter::radius(filter);
    let side = |r: f32, n: u32| (2.0 * f64::from(r)).ceil().clamp(0.0, f64::from(n) - 1.0) + 1.0;
    side(rx, size[0]) * side(ry, size[1])
}

/// Prints one warning line when `work` pixel updates exceed [`LARGE_WORK`] and returns whether
/// it did (the caller then shows its progress bar at once).
pub fn warn_if_large(work: f64, what: &str) -> bool {
    if work <= LARGE_WORK {
        return false;
    }
    eprintln!(
        "nyquist: warning: {what}: about {work:.1e} pixel updates; this may take a while; a \
         smaller --size, fewer --spp or a narrower --filter make it shorter"
    );
    true
}

/// A finished render.
#[derive(Debug)]
pub struct Rendered {
    /// The resolved image.
    pub image: Image,
    /// Samples added and rejected.
    pub stats: FilmStats,
    /// Wall-clock seconds of sampling and reconstruction (not the reference, not the file).
    pub seconds: f64,
    /// The layers kept beside the image ([`Layers`]); all `None` when none were asked for.
    pub extras: ExtraImages,
    /// What adaptive sampling did, when it drove the render ([`render_layers`]).
    pub adaptive: Option<AdaptiveReport>,
}

/// The samplers whose pixels take any number of samples, each a prefix of one sequence (so
/// adaptive sampling can add samples to a pixel): the others lay out a fixed set for their
/// spp.
pub const PROGRESSIVE_SAMPLERS: [SamplerName; 11] = [
    SamplerName::Random,
    SamplerName::Halton,
    SamplerName::Sobol,
    SamplerName::ZeroTwo,
    SamplerName::OwenSobol,
    SamplerName::OwenSobolBn,
    SamplerName::ZSobol,
    SamplerName::Pmj02,
    SamplerName::Pmj02Bn,
    SamplerName::R2,
    SamplerName::LatticeBn,
];

/// An extra channel group a render can keep per pixel, from the scene's
/// [`Surface`](crate::scene::Surface).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Aov {
    /// The surface's reflectance, as `albedo.R`, `albedo.G`, `albedo.B`.
    Albedo,
    /// The camera-space normal, as `normal.X`, `normal.Y`, `normal.Z`.
    Normal,
    /// The distance along the view axis, as `depth.Z`.
    Depth,
}

impl Aov {
    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            Aov::Albedo => "albedo",
            Aov::Normal => "normal",
            Aov::Depth => "depth",
        }
    }

    /// The planes' names (OpenEXR's `layer.channel`).
    pub fn channels(self) -> &'static [&'static str] {
        match self {
            Aov::Albedo => &["albedo.R", "albedo.G", "albedo.B"],
            Aov::Normal => &["normal.X", "normal.Y", "normal.Z"],
            Aov::Depth => &["depth.Z"],
        }
    }

    /// Appends this group's values for `surface` to `out`.
    fn values(self, surface: &crate::scene::Surface, out: &mut Vec<f32>) {
        match self {
            Aov::Albedo => out.extend([surface.albedo as f32; 3]),
            Aov::Normal => out.extend(surface.normal.map(|v| v as f32)),
            Aov::Depth => out.push(surface.depth as f32),
        }
    }
}

/// What a render keeps per pixel beside its image: the variance, the A/B halves, channel
/// groups ([`Aov`]); and whether adaptive sampling drives it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Layers {
    /// The variance of each pixel's value.
    pub variance: bool,
    /// The means of the two sample classes A and B.
    pub halves: bool,
    /// Channel groups, in order, each at most once.
    pub aovs: Vec<Aov>,
    /// Render by [`render_adaptive`] with these settings (the film then also keeps the estimate
    /// it steers by; not a layer of the output).
    pub adaptive: Option<AdaptiveConfig>,
    /// Samples per pixel to draw when they differ from the sampler's own (a progressive
    /// sampler made for fewer, its spp a hint: `render --spp-hint`); not with `adaptive`.
    pub spp: Option<u32>,
}

impl Layers {
    /// Whether anything beyond the image is kept for the output.
    pub fn any(&self) -> bool {
        self.variance || self.halves || !self.aovs.is_empty()
    }

    /// The film's extras for these layers, and the estimate adaptive sampling steers by.
    ///
    /// ```
    /// use nyquist_film::adaptive::{AdaptiveConfig, ErrorEstimate};
    /// use nyquist_lab::render::Layers;
    /// let mut layers = Layers { variance: true, ..Layers::default() };
    /// assert!(layers.extras().variance && !layers.extras().halves);
    /// layers.adaptive = Some(AdaptiveConfig::new(64, 0.02)); // steers by the halves
    /// assert!(layers.extras().variance && layers.extras().halves);
    /// let by_variance = AdaptiveConfig { estimate: ErrorEstimate::Variance, ..AdaptiveConfig::new(64, 0.02) };
    /// let layers = Layers { adaptive: Some(by_variance), ..Layers::default() };
    /// assert!(layers.extras().variance && !layers.extras().halves);
    /// assert!(!layers.any()); // none of them is an output layer
    /// ```
    pub fn extras(&self) -> PixelExtras {
        let steers_by = self.adaptive.map(|a| a.estimate);
        PixelExtras {
            variance: self.variance || steers_by == Some(ErrorEstimate::Variance),
            halves: self.halves || steers_by == Some(ErrorEstimate::Halves),
            channels: self.channel_names().len() as u16,
        }
    }

    /// The names of the channel planes, in order.
    pub fn channel_names(&self) -> Vec<&'static str> {
        self.aovs
            .iter()
            .flat_map(|a| a.channels().iter().copied())
            .collect()
    }
}

/// Renders `scene` at `size` through `sampler` and `filter` on `threads` threads; `tick` is
/// called once per finished tile (on the calling thread).
pub fn render(
    scene: Scene,
    size: [u32; 2],
    sampler: &NamedSampler,
    filter: &FilterKind,
    threads: usize,
    tick: &mut dyn FnMut(),
) -> Result<Rendered> {
    // Its own path, not `render_layers`: a program that only renders (the explorer) carries
    // none of the layers' or adaptive sampling's code.
    let mut film = new_film(FilmConfig::new(size[0], size[1]), size, filter)?;
    let start = Stopwatch::start();
    render_with::<_, false>(
        &mut film,
        sampler,
        scene,
        size,
        threads,
        &Layers::default(),
        tick,
    )
    .map_err(|e| anyhow!("render: {e}"))?;
    let (image, _) = film.try_image().map_err(|e| anyhow!("render: {e}"))?;
    Ok(Rendered {
        image,
        stats: film.stats(),
        seconds: start.seconds(),
        extras: ExtraImages::default(),
        adaptive: None,
    })
}

/// A film for `config`, its errors worded for the command line's flags.
fn new_film(config: FilmConfig, size: [u32; 2], filter: &FilterKind) -> Result<Film> {
    Film::new(config, filter.as_dyn()).map_err(|e| match e {
        nyquist_film::Error::OutOfMemory { .. } => {
            anyhow!("--size {}x{}: {e} (try a smaller --size)", size[0], size[1])
        }
        e => anyhow!("--filter {}: {e}", filter.name()),
    })
}

/// [`render`], keeping `layers` beside the image ([`Rendered::extras`]), and with
/// `layers.adaptive` rendered by [`render_adaptive`] (passes that double the samples of the
/// pixels whose relative error is above the threshold; the film then also keeps the halves or
/// the variance the estimate needs). `sampler` must then be progressive
/// ([`PROGRESSIVE_SAMPLERS`]) and made for its `max_spp` samples per pixel. `tick(n)` reports
/// progress: `n = 1` per finished tile, or when adaptive the samples each pass took.
///
/// ```
/// use nyquist::{filter::FilterKind, sampler::NamedSampler};
/// use nyquist_lab::{render::{self, Aov, Layers}, scene::Scene};
/// let sampler = NamedSampler::new("sobol", [8, 8], 16, 1).unwrap();
/// let filter = FilterKind::parse("box").unwrap();
/// let layers = Layers { variance: true, halves: true, aovs: vec![Aov::Depth], ..Layers::default() };
/// let r = render::render_layers(Scene::Disk, [8, 8], &sampler, &filter, 1, &layers, &mut |_| {})
///     .unwrap();
/// assert_eq!(r.extras.channels.unwrap().pixel(4, 4), [1.0]); // the disk's plane, z = 1
/// assert!(r.extras.variance.is_some() && r.extras.halves.is_some());
/// ```
pub fn render_layers(
    scene: Scene,
    size: [u32; 2],
    sampler: &NamedSampler,
    filter: &FilterKind,
    threads: usize,
    layers: &Layers,
    tick: &mut dyn FnMut(u64),
) -> Result<Rendered> {
    let extras = layers.extras();
    let adaptive = layers.adaptive.as_ref();
    let config = FilmConfig {
        extras,
        ..FilmConfig::new(size[0], size[1])
    };
    let mut film = new_film(config, size, filter)?;
    let start = Stopwatch::start();
    let report = match adaptive {
        Some(a) => Some(
            render_adaptive_with(&mut film, sampler, scene, size, threads, layers, a, tick)
                .map_err(|e| anyhow!("render: {e}"))?,
        ),
        None => {
            render_with::<_, true>(
                &mut film,
                sampler,
                scene,
                size,
                threads,
                layers,
                &mut || tick(1),
            )
            .map_err(|e| anyhow!("render: {e}"))?;
            None
        }
    };
    let (image, _) = film.try_image().map_err(|e| anyhow!("render: {e}"))?;
    let extras = film.extra_images().map_err(|e| anyhow!("render: {e}"))?;
    Ok(Rendered {
        image,
        stats: film.stats(),
        seconds: start.seconds(),
        extras,
        adaptive: report,
    })
}

/// How many tiles a `size` film splits into (the progress bar's units).
pub fn tile_count(size: [u32; 2]) -> u64 {
    u64::from(size[0].div_ceil(TILE)) * u64::from(size[1].div_ceil(TILE))
}

/// The sample loop. Each sample is the sampler's camera sample: the image sample (dimensions
/// 0 and 1) and, for scenes that move, the time (dimension 2), exactly as
/// [`nyquist::sampler::camera_sample`] reads them; the lens dimensions are not drawn because no
/// scene has a lens. Every value depends only on (pixel, sample, dimension, seed), and the film
/// merges tiles in order, so the image is the same for every thread count.
fn render_with<S: Sampler + Clone + Sync, const EXTRAS: bool>(
    film: &mut Film,
    sampler: &S,
    scene: Scene,
    size: [u32; 2],
    threads: usize,
    layers: &Layers,
    tick: &mut dyn FnMut(),
) -> Result<(), nyquist_film::Error> {
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    render_tiles(
        film,
        TILE,
        threads,
        |tile, ctx| {
            let mut s = sampler.clone();
            let mut channels = Vec::new();
            let b = ctx.bounds;
            for py in b.y0..b.y1 {
                for px in b.x0..b.x1 {
                    let pixel = [px as u32, py as u32];
                    let mut i = 0;
                    while i < layers.spp.unwrap_or_else(|| s.pixel_samples(pixel)) {
                        let l = add_camera_sample::<_, EXTRAS>(
                            tile,
                            &mut s,
                            scene,
                            [w, h],
                            pixel,
                            i,
                            &layers.aovs,
                            &mut channels,
                        );
                        s.report(pixel, i, &[l]);
                        i += 1;
                    }
                }
            }
        },
        |_, _| tick(),
    )
}

/// Draws sample `i` of `pixel` from `s` as the sampler's camera sample (the image sample and,
/// for scenes that move, the time, as [`nyquist::sampler::camera_sample`] reads them), adds
/// the scene's radiance there to `tile` and returns it. With `EXTRAS` it goes in through
/// [`FilmTile::add`](nyquist_film::FilmTile::add) with its index and the values of `aovs`
/// (`channels` is scratch), the radiance being the surface's albedo, which is what
/// [`Scene::eval`] returns (evaluated once); without, through `add_sample`.
#[allow(clippy::too_many_arguments)]
#[inline]
fn add_camera_sample<S: Sampler, const EXTRAS: bool>(
    tile: &mut nyquist_film::FilmTile,
    s: &mut S,
    scene: Scene,
    [w, h]: [f64; 2],
    pixel: [u32; 2],
    i: u32,
    aovs: &[Aov],
    channels: &mut Vec<f32>,
) -> f32 {
    s.start_pixel_sample(pixel, i, 0);
    let [ox, oy] = s.get_pixel_2d();
    let t = if scene.uses_time() { s.get_1d() } else { 0.5 };
    let p = [film_coordinate(pixel[0], ox), film_coordinate(pixel[1], oy)];
    let (x, y, t) = (f64::from(p[0]), f64::from(p[1]), f64::from(t));
    if !EXTRAS {
        let l = scene.eval(x, y, t, w, h) as f32;
        tile.add_sample(p, [l; 3], 1.0);
        return l;
    }
    let surface = scene.surface(x, y, t, w, h);
    let l = surface.albedo as f32;
    channels.clear();
    for a in aovs {
        a.values(&surface, channels);
    }
    tile.add(&FilmSample {
        index: u64::from(i),
        channels,
        ..FilmSample::new(p, [l; 3], 1.0)
    });
    l
}

/// [`render_with`] driven by [`render_adaptive`]: each pass adds samples `indices` of the
/// pixels it chose, as the sample loop adds them.
#[allow(clippy::too_many_arguments)]
fn render_adaptive_with<S: Sampler + Clone + Sync>(
    film: &mut Film,
    sampler: &S,
    scene: Scene,
    size: [u32; 2],
    threads: usize,
    layers: &Layers,
    config: &AdaptiveConfig,
    tick: &mut dyn FnMut(u64),
) -> Result<AdaptiveReport, nyquist_film::Error> {
    let mut done = 0;
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    render_adaptive(
        film,
        config,
        TILE,
        threads,
        |tile, pixel, indices| {
            let mut s = sampler.clone();
            let mut channels = Vec::new();
            for i in indices {
                // Below max_spp, which the caller made the sampler for (u32).
                let i = i as u32;
                add_camera_sample::<_, true>(
                    tile,
                    &mut s,
                    scene,
                    [w, h],
                    pixel,
                    i,
                    &layers.aovs,
                    &mut channels,
                );
            }
        },
        |_, samples| {
            tick(samples - done);
            done = samples;
        },
    )
}

/// Bytes a film pixel takes (weighted RGB and weight sums in `f64`).
pub const FILM_PIXEL_BYTES: u64 = 32;
/// Bytes an image pixel takes (RGB in `f32`).
pub const IMAGE_PIXEL_BYTES: u64 = 12;

/// The memory a render of `scene` at `size` takes: the film, the resolved image and its encoded
/// rows, and with `metrics` the two references (and, for scenes without a closed form, the
/// reference render's own film and image).
pub fn render_bytes(scene: Scene, size: [u32; 2], metrics: bool) -> u64 {
    let pixels = u64::from(size[0]) * u64::from(size[1]);
    let mut per_pixel = FILM_PIXEL_BYTES + IMAGE_PIXEL_BYTES + 4;
    if metrics {
        per_pixel += 2 * 8;
        if scene != Scene::Zoneplate {
            per_pixel += FILM_PIXEL_BYTES + IMAGE_PIXEL_BYTES;
        }
    }
    crate::memory::bytes(pixels, per_pixel)
}

/// What the reference of a scene is, in words (for tables and JSON); [`describe_reference`]
/// adds where a rendered one came from.
pub fn reference_kind(scene: Scene) -> String {
    match scene {
        Scene::Zoneplate => "exact pixel means (box filter, Fresnel integrals)".into(),
        Scene::Dots => format!(
            "exact pixel means ½ (box filter; other filters a {REFERENCE_STRATA}x{REFERENCE_STRATA} spp stratified render)"
        ),
        _ => format!(
            "pixel means from a {REFERENCE_STRATA}x{REFERENCE_STRATA} spp stratified box render"
        ),
    }
}

/// Whether `scene`'s reference through `filter` is a closed form, which renders nothing: the
/// zone plate's (any filter; `None` from [`reference_with_progress`] for a non-separable one)
/// and, through the box filter, the dots' (½ in every pixel).
///
/// ```
/// use nyquist::filter::FilterKind;
/// use nyquist_lab::{render::exact_reference, scene::Scene};
/// let boxed = FilterKind::parse("box").unwrap();
/// let tent = FilterKind::parse("triangle").unwrap();
/// assert!(exact_reference(Scene::Dots, &boxed) && !exact_reference(Scene::Dots, &tent));
/// assert!(exact_reference(Scene::Zoneplate, &tent) && !exact_reference(Scene::Disk, &boxed));
/// ```
pub fn exact_reference(scene: Scene, filter: &FilterKind) -> bool {
    let is_box = FilterKind::parse("box").is_ok_and(|b| b.to_string() == filter.to_string());
    scene == Scene::Zoneplate || (scene == Scene::Dots && is_box)
}

/// Where a reference came from ([`reference_with_source`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ReferenceSource {
    /// A closed form: nothing rendered, nothing cached.
    Exact,
    /// Read from the cache folder.
    Cached,
    /// Rendered by this run; `kept`: written to the cache folder for the next runs.
    Rendered {
        /// Whether the render was written to the cache.
        kept: bool,
    },
}

/// [`reference_kind`] with where the reference came from, e.g. `pixel means from a 32x32 spp
/// stratified box render, read from the cache`.
///
/// ```
/// use nyquist_lab::render::{ReferenceSource, describe_reference};
/// use nyquist_lab::scene::Scene;
/// let d = describe_reference(Scene::Disk, ReferenceSource::Rendered { kept: false });
/// assert!(d.ends_with("render, rendered now (not cached)"), "{d}");
/// ```
pub fn describe_reference(scene: Scene, source: ReferenceSource) -> String {
    let kind = reference_kind(scene);
    match source {
        ReferenceSource::Exact => kind,
        ReferenceSource::Cached => format!("{kind}, read from the cache"),
        ReferenceSource::Rendered { kept: true } => format!("{kind}, rendered now and cached"),
        ReferenceSource::Rendered { kept: false } => {
            format!("{kind}, rendered now (not cached)")
        }
    }
}

/// The reference image of `scene` seen through `filter` (`None`: the pixel means, i.e. the box),
/// calling `tick` once per finished tile when the reference is rendered (a scene without a
/// closed form and no cached copy); a closed form or a cache hit ticks nothing.
///
/// The zone plate's references are exact: the Fresnel pixel means, or the filtered zone plate by
/// 1D quadrature ([`crate::scene::zoneplate_filtered_reference`]; `None` for a non-separable
/// filter). For the other scenes it is a stratified `32 × 32` spp render through the filter,
/// cached under the user's cache folder (`$XDG_CACHE_HOME/nyquist`, else `~/.cache/nyquist`)
/// keyed by scene, size and filter spec.
///
/// ```
/// use nyquist_lab::{render::reference_with_progress, scene::Scene};
/// let mut ticks = 0;
/// let means = reference_with_progress(Scene::Zoneplate, [8, 4], None, 1, &mut || ticks += 1)
///     .unwrap()
///     .unwrap();
/// assert_eq!((means.len(), ticks), (32, 0)); // the zone plate's means are exact: no render
/// ```
///
/// # Errors
/// A render error (the film could not be allocated).
pub fn reference_with_progress(
    scene: Scene,
    size: [u32; 2],
    filter: Option<&FilterKind>,
    threads: usize,
    tick: &mut dyn FnMut(),
) -> Result<Option<Vec<f64>>> {
    Ok(reference_with_source(scene, size, filter, threads, tick)?.map(|(r, _)| r))
}

/// [`reference_with_progress`], with where the reference came from. The cache's troubles are
/// notes on stderr, each printed once a run: a cache folder that cannot be created or
/// written, a home folder that does not exist (no cache then), a cached file that cannot be
/// used (then rendered again and rewritten).
///
/// # Errors
/// A render error (the film could not be allocated).
pub fn reference_with_source(
    scene: Scene,
    size: [u32; 2],
    filter: Option<&FilterKind>,
    threads: usize,
    tick: &mut dyn FnMut(),
) -> Result<Option<(Vec<f64>, ReferenceSource)>> {
    let boxed = FilterKind::parse("box").map_err(|e| anyhow!("{e}"))?;
    let filter = filter.unwrap_or(&boxed);
    if scene == Scene::Zoneplate {
        let exact = if filter.to_string() == boxed.to_string() {
            Some(crate::scene::zoneplate_reference(size[0], size[1]))
        } else {
            crate::scene::zoneplate_filtered_reference(size[0], size[1], filter.as_dyn())
        };
        return Ok(exact.map(|r| (r, ReferenceSource::Exact)));
    }
    if scene == Scene::Dots && exact_reference(scene, filter) {
        let n = size[0] as usize * size[1] as usize;
        return Ok(Some((vec![0.5; n], ReferenceSource::Exact)));
    }
    let spec = filter.to_string();
    let key: String = spec
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '.' {
                c
            } else {
                '_'
            }
        })
        .collect();
    // No cache without a file system (the explorer keeps references in memory instead). The
    // cache's uses test `NO_FILE_SYSTEM` again: only then does the compiler drop their code.
    let dir = if NO_FILE_SYSTEM {
        None
    } else {
        usable_cache_dir()
    };
    let path = dir.map(|d| {
        d.join(format!(
            "reference-v2-{}-{}x{}-stratified{REFERENCE_STRATA}-{key}.pfm",
            scene.name(),
            size[0],
            size[1]
        ))
    });
    let header = reference_header(scene, size, &spec);
    if !NO_FILE_SYSTEM && let Some(p) = &path {
        match read_cached_reference(p, &header, size) {
            Ok(Some(img)) => return Ok(Some((channel0(&img), ReferenceSource::Cached))),
            Ok(None) => {}
            Err(why) => note_once(&format!(
                "the cached reference {} {why}; rendering it again",
                p.display()
            )),
        }
    }
    let sampler = NamedSampler::new(
        "stratified",
        size,
        REFERENCE_STRATA * REFERENCE_STRATA,
        REFERENCE_SEED,
    )
    .map_err(|e| anyhow!("the reference's sampler: {e}"))?;
    let r = render(scene, size, &sampler, filter, threads, tick)?;
    let mut kept = false;
    if !NO_FILE_SYSTEM && let Some(p) = &path {
        // A cache that cannot be written only costs time next run.
        match write_cache_file(p, &header, &r.image) {
            Ok(()) => kept = true,
            Err(e) => note_once(&format!(
                "the reference cannot be cached in {} ({e:#}); it is rendered on every run",
                p.parent().unwrap_or(Path::new(".")).display()
            )),
        }
    }
    Ok(Some((
        channel0(&r.image),
        ReferenceSource::Rendered { kept },
    )))
}

/// Prints `nyquist: note: <text>` on stderr unless this run printed that text already.
fn note_once(text: &str) {
    static PRINTED: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let mut printed = PRINTED
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if !printed.iter().any(|t| t == text) {
        eprintln!("nyquist: note: {text}");
        printed.push(text.to_owned());
    }
}

/// The cache folder ([`cache_dir`]), created if missing; `None`, with one note, when there is
/// none or it cannot be used.
fn usable_cache_dir() -> Option<PathBuf> {
    let dir = match cache_dir() {
        Ok(d) => d,
        Err(why) => {
            note_once(&format!(
                "no reference cache: {why}; references are rendered every run"
            ));
            return None;
        }
    };
    match std::fs::create_dir_all(&dir) {
        Ok(()) => Some(dir),
        Err(e) => {
            note_once(&format!(
                "the reference cache {} cannot be used ({e}); references are rendered every run",
                dir.display()
            ));
            None
        }
    }
}

/// The first lines of a cached reference: what it was made from. A cache file whose header
/// differs was made from other parameters (or by another version of the format).
fn reference_header(scene: Scene, size: [u32; 2], filter: &str) -> String {
    format!(
        "nyquist reference image\nscene {}\nsize {}x{}\nsampler stratified {REFERENCE_STRATA}x{REFERENCE_STRATA} spp, seed {REFERENCE_SEED}\nfilter {filter}\n",
        scene.name(),
        size[0],
        size[1]
    )
}

/// FNV-1a, 64 bits: the checksum of a cached reference's image bytes.
fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Writes a cached reference: `header`, a line with the checksum and length of the image bytes,
/// then the image as PFM.
fn write_cached_reference(w: &mut dyn std::io::Write, header: &str, image: &Image) -> Result<()> {
    let mut pfm = Vec::new();
    nyquist_film::output::pfm::write_pfm(&mut pfm, image)?;
    writeln!(
        w,
        "{header}fnv1a64 {:016x} bytes {}",
        fnv1a64(&pfm),
        pfm.len()
    )?;
    w.write_all(&pfm)?;
    Ok(())
}

/// Writes a cached reference to `path` through a temporary file in the same folder, renamed into
/// place, so a reader never sees half a file.
fn write_cache_file(path: &Path, header: &str, image: &Image) -> Result<()> {
    let tmp = path.with_extension(format!("pfm.tmp-{}", std::process::id()));
    let written = std::fs::File::create(&tmp)
        .map_err(anyhow::Error::from)
        .and_then(|f| {
            let mut w = std::io::BufWriter::new(f);
            write_cached_reference(&mut w, header, image)?;
            std::io::Write::flush(&mut w)?;
            Ok(())
        })
        .and_then(|()| Ok(std::fs::rename(&tmp, path)?));
    if written.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    written
}

/// Reads the cached reference at `path`: `Ok(None)` when there is none, `Err(why)` when the file
/// is there but unusable — made from other parameters, truncated, its checksum wrong, not an
/// image of `size`, or holding a non-finite pixel — and the image otherwise.
fn read_cached_reference(
    path: &Path,
    header: &str,
    size: [u32; 2],
) -> std::result::Result<Option<Image>, String> {
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(format!("cannot be read ({e})")),
    };
    let rest = match bytes.strip_prefix(header.as_bytes()) {
        Some(rest) => rest,
        None => return Err(header_mismatch(&bytes, header).into()),
    };
    let line_end = rest
        .iter()
        .position(|&b| b == b'\n')
        .ok_or("is truncated (in its checksum line)")?;
    let line = std::str::from_utf8(&rest[..line_end]).map_err(|_| "has a malformed checksum")?;
    let payload = &rest[line_end + 1..];
    let (sum, len) = line
        .strip_prefix("fnv1a64 ")
        .and_then(|l| l.split_once(" bytes "))
        .and_then(|(h, n)| Some((u64::from_str_radix(h, 16).ok()?, n.parse::<usize>().ok()?)))
        .ok_or("has a malformed checksum line")?;
    if payload.len() < len {
        return Err(format!(
            "is truncated ({} image bytes, {len} expected)",
            payload.len()
        ));
    }
    if payload.len() > len {
        return Err(format!(
            "is corrupt ({} image bytes, {len} expected)",
            payload.len()
        ));
    }
    if fnv1a64(payload) != sum {
        return Err("does not match its checksum".into());
    }
    let img = nyquist_film::output::pfm::read_pfm(&mut &payload[..])
        .map_err(|e| format!("is not a PFM image ({e})"))?;
    if [img.width(), img.height()] != size {
        return Err(format!(
            "is {}x{}, not {}x{}",
            img.width(),
            img.height(),
            size[0],
            size[1]
        ));
    }
    if img.data().iter().any(|v| !v.is_finite()) {
        return Err("has a non-finite pixel".into());
    }
    Ok(Some(img))
}

/// Why a cache file's first lines are not `header`: it ends inside them ("is truncated"), a
/// line is not the header line it should be ("is corrupt"), or a line names another value of
/// the same parameter ("was made from other parameters").
fn header_mismatch(bytes: &[u8], header: &str) -> &'static str {
    let mut rest = bytes;
    for want in header.lines() {
        let Some(end) = rest.iter().position(|&b| b == b'\n') else {
            // The file ends in this line: truncated if what is there begins it.
            return if want.as_bytes().starts_with(rest) {
                "is truncated (in its header)"
            } else {
                "is corrupt (not a nyquist reference header)"
            };
        };
        let got = &rest[..end];
        if got != want.as_bytes() {
            // The parameter's name: the first line's whole text, else its first word.
            let key = if want.starts_with("nyquist ") {
                want
            } else {
                want.split(' ').next().unwrap_or(want)
            };
            let same_key = got
                .strip_prefix(key.as_bytes())
                .is_some_and(|r| r.first() == Some(&b' ') && std::str::from_utf8(r).is_ok());
            return if same_key && key != want {
                "was made from other parameters"
            } else {
                "is corrupt (not a nyquist reference header)"
            };
        }
        rest = &rest[end + 1..];
    }
    "is corrupt (not a nyquist reference header)"
}

/// The folder of cached references: `$XDG_CACHE_HOME/nyquist` when that variable is an
/// absolute path, else `$HOME/.cache/nyquist` when the home folder exists (a cache is never
/// made under a home that is missing, as `/nonexistent` for system users); `Err(why)` when
/// there is neither.
fn cache_dir() -> std::result::Result<PathBuf, String> {
    if let Some(d) = std::env::var_os("XDG_CACHE_HOME")
        && !d.is_empty()
        && Path::new(&d).is_absolute()
    {
        return Ok(PathBuf::from(d).join("nyquist"));
    }
    let home = std::env::var_os("HOME")
        .filter(|h| !h.is_empty())
        .ok_or("neither XDG_CACHE_HOME (absolute) nor HOME is set")?;
    let home = PathBuf::from(home);
    if !home.is_dir() {
        return Err(format!("the home folder {} does not exist", home.display()));
    }
    Ok(home.join(".cache").join("nyquist"))
}

/// The first channel of every pixel (the scenes are grey).
pub fn channel0(img: &Image) -> Vec<f64> {
    img.data()
        .chunks_exact(3)
        .map(|p| f64::from(p[0]))
        .collect()
}

/// Root-mean-square difference between `img`'s first channel and `reference`.
pub fn rmse(img: &Image, reference: &[f64]) -> f64 {
    let n = reference.len().max(1) as f64;
    let sum: f64 = img
        .data()
        .chunks_exact(3)
        .zip(reference)
        .map(|(p, r)| (f64::from(p[0]) - r).powi(2))
        .sum();
    (sum / n).sqrt()
}

/// Peak signal-to-noise ratio in dB for a peak of 1 (infinite for a perfect match).
pub fn psnr(rmse: f64) -> f64 {
    -20.0 * libm::log10(rmse)
}

/// The default thread count: the machine's parallelism.
pub fn default_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn damaged_cache_headers_are_told_apart() {
        let header = reference_header(Scene::Disk, [16, 8], "box:rx=0.5,ry=0.5");
        let h = header.as_bytes();
        assert_eq!(
            header_mismatch(b"", &header),
            "is truncated (in its header)"
        );
        for cut in [1, 10, 24, 30, h.len() - 1] {
            assert_eq!(
                header_mismatch(&h[..cut], &header),
                "is truncated (in its header)",
                "{cut}"
            );
        }
        let other = header.replacen("size 16x8", "size 8x16", 1);
        assert_eq!(
            header_mismatch(other.as_bytes(), &header),
            "was made from other parameters"
        );
        let other = header.replacen("filter box", "filter gaussian", 1);
        assert_eq!(
            header_mismatch(other.as_bytes(), &header),
            "was made from other parameters"
        );
        for bad in [
            header.replacen("nyquist reference image", "nyquist reference imagf", 1),
            header.replacen("scene disk", "scenery disk", 1),
            "P6\n16 8\n255\n".to_owned(),
        ] {
            assert_eq!(
                header_mismatch(bad.as_bytes(), &header),
                "is corrupt (not a nyquist reference header)",
                "{bad:?}"
            );
        }
    }
}
