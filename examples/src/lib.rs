//! # nyquist-examples
//!
//! A client of `nyquist` and `nyquist-film` that uses them as a renderer does: an analytic path
//! tracer ([`scene`], [`trace`]) whose every random decision comes from a named sampler through
//! the request-and-fill layer (`SampleLayout`, `PixelRangeSampler`, `get_array_2d` for the light
//! samples), films and filters from `nyquist-film`, tiles through `render_tiles`; and the
//! experiment of [`experiment`]: N camera samples × M light samples at equal sample count.
//!
//! The binary is `pathtracer`; see `docs/path-tracer.md`.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod adaptive_study;
pub mod experiment;
pub mod geometry;
pub mod scene;
pub mod trace;

use std::time::Instant;

use anyhow::{Context, Result, anyhow, bail};
use nyquist::filter::FilterKind;
use nyquist::sampler::{CameraSample, NamedSampler, OwenSobolSampler, Sampler};
use nyquist_film::adaptive::{AdaptiveConfig, AdaptiveReport, render_adaptive};
use nyquist_film::{Film, FilmConfig, FilmSample, Image, PixelExtras, render_tiles};

use crate::scene::Scene;
use crate::trace::{
    Derivation, LightSamples, PathLayout, for_each_sample, for_each_sample_counter,
    for_each_sample_domains, for_each_sample_stateless, for_pixel_samples,
};

/// Builds the sampler called `name` ([`NamedSampler::new`]: any of
/// [`nyquist::sampler::NAMES`] or [`nyquist::sampler::OTHER_NAMES`], such as `halton-plain` and
/// `sobol-plain` for the unscrambled Halton and Sobol samplers), with the error naming it.
///
/// # Errors
/// An unknown name, or sizes the sampler rejects (e.g. `pmj02` above 65536 spp).
pub fn build_sampler(name: &str, size: [u32; 2], spp: u32, seed: u64) -> Result<NamedSampler> {
    NamedSampler::new(name, size, spp, seed)
        .map_err(|e| anyhow!("sampler {name:?} with {spp} spp: {e}"))
}

/// What to render.
#[derive(Clone, Debug)]
pub struct RenderConfig {
    /// Scene name (see [`scene::SCENE_NAMES`]).
    pub scene: String,
    /// Image size in pixels.
    pub size: [u32; 2],
    /// Camera samples per pixel.
    pub spp: u32,
    /// Light samples per camera sample at each vertex.
    pub light_samples: LightSamples,
    /// Sampler name (see [`build_sampler`]).
    pub sampler: String,
    /// Sampler seed.
    pub seed: u64,
    /// Worker threads.
    pub threads: usize,
    /// Tile side in pixels.
    pub tile_size: u32,
    /// Reconstruction filter.
    pub filter: FilterKind,
    /// Draw the values through the stateless layer (`camera_sample`, `get_array_2d`,
    /// `get_2d`, `get_1d`) instead of `SampleLayout` and `PixelRangeSampler`.
    pub stateless: bool,
    /// With `stateless`, draw the light points one `get_2d` each (pbrt-v4's counter) instead of
    /// one `get_array_2d` per vertex.
    pub counter: bool,
    /// Make the sampler for this many samples per pixel and draw `spp` of them through the
    /// stateless layer, past it where `spp` is larger (samplers whose every sample index is a
    /// new sample: random, halton, sobol, owen-sobol, owen-sobol-bn, zsobol, pmj02, pmj02-bn, lattice-bn).
    pub spp_hint: Option<u32>,
    /// Draw the values past the camera sample from the camera sample's [`Domain`]s, the light
    /// samples by this derivation ([`trace::DomainSource`]; the `owen-sobol` sampler only).
    ///
    /// [`Domain`]: nyquist::sampler::Domain
    pub domains: Option<Derivation>,
    /// Render adaptively ([`render_adaptive`]; `spp` is then its budget and the sampler is
    /// made for its `max_spp`); the stateless layer draws the values.
    pub adaptive: Option<AdaptiveConfig>,
}

impl RenderConfig {
    /// The defaults: `cornell`, 256 × 256, 16 spp, 1 light sample, `owen-sobol`, seed 1, one
    /// thread, 16-pixel tiles, the box filter (each pixel the mean of its own samples).
    pub fn new(scene: &str) -> RenderConfig {
        RenderConfig {
            scene: scene.into(),
            size: [256, 256],
            spp: 16,
            light_samples: LightSamples::first(1),
            sampler: "owen-sobol".into(),
            seed: 1,
            threads: 1,
            tile_size: 16,
            filter: FilterKind::parse("box").expect("the box filter parses"),
            stateless: false,
            counter: false,
            spp_hint: None,
            domains: None,
            adaptive: None,
        }
    }
}

/// A sampler drawn for `spp` samples per pixel whatever it was made for: past its spp for the
/// samplers whose every sample index is new (`RenderConfig::spp_hint`). With `spp` `None`, the
/// sampler itself.
#[derive(Clone, Debug)]
pub struct PastHint<S> {
    /// The sampler.
    pub inner: S,
    /// Samples per pixel to draw, if not the sampler's own.
    pub spp: Option<u32>,
}

impl<S: Sampler> Sampler for PastHint<S> {
    fn samples_per_pixel(&self) -> u32 {
        self.spp.unwrap_or_else(|| self.inner.samples_per_pixel())
    }
    fn pixel_samples(&self, pixel: [u32; 2]) -> u32 {
        self.spp.unwrap_or_else(|| self.inner.pixel_samples(pixel))
    }
    fn report(&mut self, pixel: [u32; 2], sample_index: u32, radiance: &[f32]) {
        self.inner.report(pixel, sample_index, radiance);
    }
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        self.inner.start_pixel_sample(pixel, sample_index, dim);
    }
    fn get_1d(&mut self) -> f32 {
        self.inner.get_1d()
    }
    fn get_2d(&mut self) -> [f32; 2] {
        self.inner.get_2d()
    }
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.inner.get_pixel_2d()
    }
    fn round_size(&self, n: u32) -> u32 {
        self.inner.round_size(n)
    }
    fn get_array_1d(&mut self, out: &mut [f32]) {
        self.inner.get_array_1d(out);
    }
    fn get_array_2d(&mut self, out: &mut [f32]) {
        self.inner.get_array_2d(out);
    }
    fn arrays_are_dimension_runs(&self) -> bool {
        self.inner.arrays_are_dimension_runs()
    }
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        self.inner.camera_sample(pixel, sample_index)
    }
    fn domain(&self) -> Option<nyquist::sampler::Domain> {
        self.inner.domain()
    }
}

/// A finished render.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The resolved image (linear RGB).
    pub image: Image,
    /// Camera samples traced.
    pub samples: u64,
    /// Wall-clock seconds of the tile rendering (not the film's resolve).
    pub seconds: f64,
    /// What adaptive sampling did, when it drove the render.
    pub adaptive: Option<AdaptiveReport>,
}

/// Renders `config`; `progress(done, total)` after each tile.
///
/// # Errors
/// Unknown scene or sampler, sizes the sampler or the film rejects.
pub fn render(config: &RenderConfig, progress: impl FnMut(usize, usize)) -> Result<Rendered> {
    let scene = Scene::by_name(&config.scene).ok_or_else(|| {
        anyhow!(
            "unknown scene {:?} (one of {:?})",
            config.scene,
            scene::SCENE_NAMES
        )
    })?;
    if let Some(a) = &config.adaptive {
        return render_adaptively(config, a, scene);
    }
    if let Some(hint) = config.spp_hint {
        if !nyquist::sampler::continues(&config.sampler) {
            bail!(
                "--spp-hint {hint}: {:?} wraps at its spp; one of {:?} draws past it",
                config.sampler,
                nyquist::sampler::CONTINUING_NAMES
            );
        }
        if !config.stateless {
            bail!("--spp-hint {hint}: with --stateless (the layout fills the sampler's own spp)");
        }
    }
    let made_for = config.spp_hint.unwrap_or(config.spp);
    let sampler = PastHint {
        inner: build_sampler(&config.sampler, config.size, made_for, config.seed)?,
        spp: config.spp_hint.map(|_| config.spp),
    };
    if config.domains.is_some() && config.sampler != "owen-sobol" {
        bail!(
            "domains: the sampler is {:?}; only owen-sobol's samples are domains",
            config.sampler
        );
    }
    let domain_sampler = OwenSobolSampler::new(config.spp, config.seed)?;
    let layout = PathLayout::new(&sampler, &config.light_samples)
        .map_err(|e| anyhow!("light samples: {e}"))?;
    let mut film = Film::new(
        FilmConfig::new(config.size[0], config.size[1]),
        config.filter.as_dyn(),
    )
    .context("film")?;
    let start = Instant::now();
    render_tiles(
        &mut film,
        config.tile_size,
        config.threads,
        |tile, ctx| {
            let Some((a, b)) = ctx.pixel_range() else {
                return;
            };
            let n = &config.light_samples;
            if let Some(how) = config.domains {
                let s = domain_sampler.clone();
                for_each_sample_domains(&scene, s, n, how, config.size, a, b, |p, l| {
                    tile.add_sample(p, l.0, 1.0)
                });
            } else if config.stateless && config.counter {
                let s = sampler.clone();
                for_each_sample_counter(&scene, s, n, config.size, a, b, |p, l| {
                    tile.add_sample(p, l.0, 1.0)
                });
            } else if config.stateless {
                let s = sampler.clone();
                for_each_sample_stateless(&scene, s, n, config.size, a, b, |p, l| {
                    tile.add_sample(p, l.0, 1.0)
                });
            } else {
                for_each_sample(
                    &scene,
                    &layout,
                    sampler.clone(),
                    config.size,
                    a,
                    b,
                    |s, l| tile.add_sample(s.image(), l.0, 1.0),
                )
                .expect("tiles are never empty");
            }
        },
        progress,
    )
    .context("render")?;
    let seconds = start.elapsed().as_secs_f64();
    let samples = film.stats().samples + film.stats().rejected;
    Ok(Rendered {
        image: film.try_image().context("render")?.0,
        samples,
        seconds,
        adaptive: None,
    })
}

/// [`render`] driven by [`render_adaptive`] with the halves' estimate.
fn render_adaptively(config: &RenderConfig, a: &AdaptiveConfig, scene: Scene) -> Result<Rendered> {
    let sampler = build_sampler(&config.sampler, config.size, a.max_spp, config.seed)?;
    let film_config = FilmConfig {
        extras: PixelExtras {
            halves: true,
            ..PixelExtras::default()
        },
        ..FilmConfig::new(config.size[0], config.size[1])
    };
    let mut film = Film::new(film_config, config.filter.as_dyn()).context("film")?;
    let start = Instant::now();
    let report = render_adaptive(
        &mut film,
        a,
        config.tile_size,
        config.threads,
        |tile, pixel, indices| {
            let n = &config.light_samples;
            for_pixel_samples(
                &scene,
                sampler.clone(),
                n,
                config.size,
                pixel,
                indices,
                |p, i, l| {
                    tile.add(&FilmSample {
                        index: i,
                        ..FilmSample::new(p, l.0, 1.0)
                    })
                },
            );
        },
        |_, _| {},
    )
    .context("render")?;
    let seconds = start.elapsed().as_secs_f64();
    Ok(Rendered {
        image: film.try_image().context("render")?.0,
        samples: report.samples,
        seconds,
        adaptive: Some(report),
    })
}
