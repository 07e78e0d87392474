//! Camera samples against light samples: for the area-light scene, `1 × 16`, `16 × 1` and
//! `4 × 4` (camera samples per pixel × light samples per camera sample at the first vertex,
//! 16 light samples per pixel each), for each sampler, against a converged reference.
//!
//! Every configuration is rendered `runs` times with different seeds; the error is
//! `√(mean over runs of RMSE²)` against the reference, the time the least wall-clock time of
//! the tile rendering over the runs (the least is the most robust on a shared machine). Equal sample count is the raw error; equal time is the error scaled to the
//! time of `16 × 1` by the Monte Carlo rule `error ∝ time^(−1/2)`: `RMSE · √(t / t₁₆ₓ₁)`.
//!
//! The reference is the mean of `reference_spp` camera samples × 4 light samples of the
//! `owen-sobol` sampler (seed 0x5eed), rendered once and cached as PFM under
//! `$XDG_CACHE_HOME/nyquist` (else `~/.cache/nyquist`), its name carrying every parameter it
//! depends on.

use std::path::PathBuf;

use anyhow::{Context, Result};
use nyquist_film::{Image, output::pfm::read_pfm, write_image_file};

use crate::{RenderConfig, render};

/// The three splits of 16 light samples per pixel: (camera samples, light samples each).
pub const SPLITS: [(u32, u32); 3] = [(1, 16), (16, 1), (4, 4)];

/// Version of the scene and estimator in cached reference names: bump it when either changes.
const REFERENCE_VERSION: u32 = 1;

/// The experiment's settings.
#[derive(Clone, Debug)]
pub struct Experiment {
    /// Scene name.
    pub scene: String,
    /// Image size.
    pub size: [u32; 2],
    /// Samplers, by [`crate::build_sampler`] name.
    pub samplers: Vec<String>,
    /// Renders (seeds) per configuration.
    pub runs: u32,
    /// Base seed.
    pub seed: u64,
    /// Worker threads.
    pub threads: usize,
    /// Camera samples per pixel of the reference.
    pub reference_spp: u32,
}

/// One sampler and split.
#[derive(Clone, Debug)]
pub struct Cell {
    /// Sampler name.
    pub sampler: String,
    /// Camera samples per pixel.
    pub camera: u32,
    /// Light samples per camera sample.
    pub light: u32,
    /// `√(mean RMSE²)` over the runs.
    pub rmse: f64,
    /// Least seconds per render over the runs.
    pub seconds: f64,
    /// The first run's image.
    pub image: Image,
    /// At (about) the time of `16 × 1`: camera samples, RMSE, least seconds.
    pub equal_time: Option<(u32, f64, f64)>,
}

impl Experiment {
    /// The reference image: from the cache when present and readable, else rendered and cached.
    ///
    /// # Errors
    /// If rendering fails (a cache that cannot be written is only a note on stderr).
    pub fn reference(&self, progress: impl FnMut(usize, usize)) -> Result<Image> {
        let name = format!(
            "pathtracer-v{REFERENCE_VERSION}-{}-{}x{}-owen-sobol-{}x4.pfm",
            self.scene, self.size[0], self.size[1], self.reference_spp
        );
        let path = cache_dir().map(|d| d.join(name));
        if let Some(p) = &path
            && let Ok(mut f) = std::fs::File::open(p)
            && let Ok(img) = read_pfm(&mut f)
            && (img.width(), img.height()) == (self.size[0], self.size[1])
            && img.data().iter().all(|v| v.is_finite())
        {
            return Ok(img);
        }
        let mut config = RenderConfig::new(&self.scene);
        config.size = self.size;
        config.spp = self.reference_spp;
        config.light_samples = crate::trace::LightSamples::first(4);
        config.sampler = "owen-sobol".into();
        config.seed = 0x5eed;
        config.threads = self.threads;
        let img = render(&config, progress)?.image;
        if let Some(p) = &path {
            let written = std::fs::create_dir_all(p.parent().unwrap_or(p))
                .map_err(anyhow::Error::from)
                .and_then(|()| write_image_file(p, &img).map_err(anyhow::Error::from));
            if let Err(e) = written {
                eprintln!(
                    "pathtracer: note: could not cache the reference at {}: {e}",
                    p.display()
                );
            }
        }
        Ok(img)
    }

    /// Renders every sampler × split × run; `progress(done, total)` after each render.
    ///
    /// # Errors
    /// An unknown sampler, or one that rejects a split's sample count.
    pub fn run(
        &self,
        reference: &Image,
        mut progress: impl FnMut(usize, usize),
    ) -> Result<Vec<Cell>> {
        let total = self.samplers.len() * (2 * SPLITS.len() - 1) * self.runs as usize;
        let mut done = 0;
        let mut cells = Vec::new();
        for name in &self.samplers {
            let mut row = Vec::new();
            for (camera, light) in SPLITS {
                let (rmse, seconds, image) = self.measure(
                    name,
                    camera,
                    light,
                    reference,
                    &mut done,
                    total,
                    &mut progress,
                )?;
                row.push(Cell {
                    sampler: name.clone(),
                    camera,
                    light,
                    rmse,
                    seconds,
                    image,
                    equal_time: None,
                });
            }
            // Equal time, measured: each split's camera samples scaled by the power of two
            // (of four for the square-only samplers) nearest to t(16 × 1) / t(split).
            let t_ref = row
                .iter()
                .find(|c| (c.camera, c.light) == (16, 1))
                .map_or(0.0, |c| c.seconds);
            for c in &mut row {
                let ratio = (t_ref / c.seconds).max(1.0);
                let step: f64 = if matches!(name.as_str(), "stratified" | "uniform") {
                    4.0
                } else {
                    2.0
                };
                let k = step.powf((ratio.ln() / step.ln()).round()) as u32;
                let camera = c.camera * k.max(1);
                let (rmse, seconds) = if (c.camera, c.light) == (16, 1) {
                    done += self.runs as usize;
                    progress(done, total);
                    (c.rmse, c.seconds)
                } else {
                    let m = &mut progress;
                    let (r, t, _) =
                        self.measure(name, camera, c.light, reference, &mut done, total, m)?;
                    (r, t)
                };
                c.equal_time = Some((camera, rmse, seconds));
            }
            cells.extend(row);
        }
        Ok(cells)
    }
}

impl Experiment {
    /// `runs` renders of `camera × light` with `name`: `√(mean RMSE²)`, least seconds, first
    /// image.
    #[allow(clippy::too_many_arguments)]
    fn measure(
        &self,
        name: &str,
        camera: u32,
        light: u32,
        reference: &Image,
        done: &mut usize,
        total: usize,
        progress: &mut impl FnMut(usize, usize),
    ) -> Result<(f64, f64, Image)> {
        let mut sum_sq = 0.0;
        let mut seconds = f64::INFINITY;
        let mut first = None;
        for r in 0..self.runs {
            let mut config = RenderConfig::new(&self.scene);
            config.size = self.size;
            config.spp = camera;
            config.light_samples = crate::trace::LightSamples::first(light);
            config.sampler = name.to_owned();
            config.seed = run_seed(self.seed, r);
            config.threads = self.threads;
            let out =
                render(&config, |_, _| {}).with_context(|| format!("{name} {camera}x{light}"))?;
            let rmse = out
                .image
                .rmse(reference)
                .context("RMSE against the reference")?;
            sum_sq += rmse.powi(2);
            seconds = seconds.min(out.seconds);
            first.get_or_insert(out.image);
            *done += 1;
            progress(*done, total);
        }
        let runs = f64::from(self.runs.max(1));
        Ok((
            (sum_sq / runs).sqrt(),
            seconds,
            first.expect("at least one run"),
        ))
    }
}

/// How a path's values past the camera sample are drawn, for light samples that vary per
/// vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightLayout {
    /// pbrt-v2: one array per vertex, sized up front (`SampleLayout::add_2d(N_k)`), filled by
    /// `PixelRangeSampler`; samplers that stratify arrays stratify each.
    Arrays,
    /// pbrt-v4: the next dimensions in order (`get_array_2d`, `get_2d`, `get_1d`), as far as
    /// the path goes.
    Counter,
    /// The camera sample's domains: light sample `j` of vertex `k` derives from the vertex's key
    /// by split, distribute or chain (owen-sobol).
    Domains(crate::trace::Derivation),
}

impl LightLayout {
    /// The row label.
    pub fn label(self) -> &'static str {
        match self {
            LightLayout::Arrays => "pbrt-v2 arrays",
            LightLayout::Counter => "pbrt-v4 counter",
            LightLayout::Domains(d) => match d {
                crate::trace::Derivation::Split => "domains: split",
                crate::trace::Derivation::Distribute => "domains: distribute",
                crate::trace::Derivation::Chain => "domains: chain",
            },
        }
    }
}

/// One row of [`Experiment::light_layouts`].
#[derive(Clone, Debug)]
pub struct LayoutRow {
    /// How the values were drawn.
    pub layout: LightLayout,
    /// Sampler name.
    pub sampler: String,
    /// Camera samples per pixel and light samples per vertex.
    pub spp: u32,
    /// The light samples, as given (`4,2,1`).
    pub light: String,
    /// `√(mean RMSE²)` over the runs.
    pub rmse: f64,
    /// Least seconds per render over the runs.
    pub seconds: f64,
}

impl Experiment {
    /// Light samples `light` per vertex at `spp` camera samples, drawn each [`LightLayout`]
    /// way: the arrays and the counter with every sampler of the experiment, the domains with
    /// `owen-sobol` (whose samples are domains). `progress(done, total)` after each render.
    ///
    /// # Errors
    /// An unknown sampler, or one that rejects the sizes.
    pub fn light_layouts(
        &self,
        spp: u32,
        light: &crate::trace::LightSamples,
        reference: &Image,
        mut progress: impl FnMut(usize, usize),
    ) -> Result<Vec<LayoutRow>> {
        let mut plan = Vec::new();
        for layout in [LightLayout::Arrays, LightLayout::Counter] {
            for name in &self.samplers {
                plan.push((layout, name.clone()));
            }
        }
        for how in [
            crate::trace::Derivation::Split,
            crate::trace::Derivation::Distribute,
            crate::trace::Derivation::Chain,
        ] {
            plan.push((LightLayout::Domains(how), "owen-sobol".to_owned()));
        }
        let total = plan.len() * self.runs as usize;
        let mut done = 0;
        let mut rows = Vec::new();
        for (layout, name) in plan {
            let (mut sum_sq, mut seconds) = (0.0, f64::INFINITY);
            for r in 0..self.runs {
                let mut config = RenderConfig::new(&self.scene);
                config.size = self.size;
                config.spp = spp;
                config.light_samples = *light;
                config.sampler = name.clone();
                config.seed = run_seed(self.seed, r);
                config.threads = self.threads;
                config.stateless = layout == LightLayout::Counter;
                config.counter = layout == LightLayout::Counter;
                config.domains = match layout {
                    LightLayout::Domains(how) => Some(how),
                    _ => None,
                };
                let out = render(&config, |_, _| {})
                    .with_context(|| format!("{} {name}", layout.label()))?;
                sum_sq += out.image.rmse(reference).context("RMSE")?.powi(2);
                seconds = seconds.min(out.seconds);
                done += 1;
                progress(done, total);
            }
            rows.push(LayoutRow {
                layout,
                sampler: name,
                spp,
                light: light.label(),
                rmse: (sum_sq / f64::from(self.runs.max(1))).sqrt(),
                seconds,
            });
        }
        Ok(rows)
    }
}

/// The Markdown table of [`Experiment::light_layouts`]: RMSE, its ratio to the domains' row,
/// and milliseconds per render.
pub fn light_layouts_markdown(rows: &[LayoutRow]) -> String {
    let base = rows
        .iter()
        .find(|r| r.layout == LightLayout::Domains(crate::trace::Derivation::Split))
        .map_or(f64::NAN, |r| r.rmse);
    let mut s = String::from(
        "| light samples drawn by | sampler | spp | light samples | RMSE | ÷ split | ms |\n|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {} | {} | {} | {:.5} | {:.2} | {:.0} |\n",
            r.layout.label(),
            r.sampler,
            r.spp,
            r.light,
            r.rmse,
            r.rmse / base,
            r.seconds * 1e3
        ));
    }
    s
}

/// The seed of run `r`: hashed from the base seed, never 0 (0 turns scrambling off).
pub fn run_seed(seed: u64, r: u32) -> u64 {
    nyquist::hash::hash2(seed, u64::from(r)) | 1
}

/// The Markdown table: per sampler, RMSE at equal sample count and at equal time (scaled to the
/// time of `16 × 1`), and milliseconds per render, for each split.
pub fn markdown(cells: &[Cell]) -> String {
    let mut s = String::from(
        "| sampler | RMSE 1×16 | RMSE 16×1 | RMSE 4×4 | eq. time 1×16 | eq. time 16×1 | eq. time 4×4 | ms 1×16 | ms 16×1 | ms 4×4 |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for row in cells.chunks(SPLITS.len()) {
        let t_ref = row
            .iter()
            .find(|c| (c.camera, c.light) == (16, 1))
            .map_or(1.0, |c| c.seconds);
        let mut line = format!("| {} |", row[0].sampler);
        for c in row {
            line += &format!(" {:.4} |", c.rmse);
        }
        for c in row {
            line += &format!(" {:.4} |", c.rmse * (c.seconds / t_ref).sqrt());
        }
        for c in row {
            line += &format!(" {:.1} |", c.seconds * 1e3);
        }
        s += &line;
        s.push('\n');
    }
    s
}

/// The measured equal-time table: per sampler and split, the camera samples that take about
/// the time of `16 × 1`, their RMSE and milliseconds.
pub fn markdown_equal_time(cells: &[Cell]) -> String {
    let mut s = String::from("| sampler | 1×16 scaled | 16×1 | 4×4 scaled |\n|---|---|---|---|\n");
    for row in cells.chunks(SPLITS.len()) {
        let mut line = format!("| {} |", row[0].sampler);
        for c in row {
            if let Some((camera, rmse, t)) = c.equal_time {
                line += &format!(" {camera}×{}: {rmse:.4} ({:.0} ms) |", c.light, t * 1e3);
            } else {
                line += " - |";
            }
        }
        s += &line;
        s.push('\n');
    }
    s
}

/// The contact sheet: one row per sampler, columns `1 × 16`, `16 × 1`, `4 × 4`, reference
/// (each the first run's image), separated by 2-pixel black lines.
pub fn contact_sheet(cells: &[Cell], reference: &Image) -> Image {
    let (w, h) = (reference.width(), reference.height());
    let cols = SPLITS.len() as u32 + 1;
    let rows = cells.len().div_ceil(SPLITS.len()) as u32;
    let gap = 2;
    let mut sheet = Image::from_fn(cols * (w + gap) - gap, rows * (h + gap) - gap, |_, _| {
        [0.0; 3]
    });
    for (r, row) in cells.chunks(SPLITS.len()).enumerate() {
        let images = row.iter().map(|c| &c.image).chain([reference]);
        for (c, img) in images.enumerate() {
            let (x0, y0) = (c as u32 * (w + gap), r as u32 * (h + gap));
            for y in 0..h {
                for x in 0..w {
                    sheet.set(x0 + x, y0 + y, img.get(x, y));
                }
            }
        }
    }
    sheet
}

fn cache_dir() -> Option<PathBuf> {
    let base = match std::env::var_os("XDG_CACHE_HOME") {
        Some(d) if !d.is_empty() && std::path::Path::new(&d).is_absolute() => PathBuf::from(d),
        _ => PathBuf::from(std::env::var_os("HOME").filter(|h| !h.is_empty())?).join(".cache"),
    };
    Some(base.join("nyquist"))
}

/// One sampler's row of [`pixel_study`]: name, RMSE at each count, slope.
pub type PixelCurve = (String, Vec<f64>, Option<f64>);

/// The path tracer's pixel estimate as an integrand: for pixel `pixel` of a `size` film of
/// `scene`, the RMSE over `runs` seeds of the mean of `n` camera samples (one light sample
/// each, so `43 + 2 = 45` dimensions for samplers whose arrays are dimension runs), for every
/// `n` in `counts`, against `reference` (see [`pixel_reference`]). Returns, per sampler, the
/// RMSE at each count and the least-squares slope of log RMSE against log n.
///
/// # Errors
/// An unknown sampler or a count it rejects.
pub fn pixel_study(
    scene: &str,
    size: [u32; 2],
    pixel: [u32; 2],
    samplers: &[String],
    counts: &[u32],
    runs: u32,
    reference: f64,
) -> Result<Vec<PixelCurve>> {
    let mut out = Vec::new();
    for name in samplers {
        let mut rmse = Vec::new();
        for &n in counts {
            let mut sq = 0.0;
            for r in 0..runs {
                let e = pixel_mean(scene, size, pixel, name, n, run_seed(0x9e37, r))?;
                sq += (e - reference).powi(2);
            }
            rmse.push((sq / f64::from(runs.max(1))).sqrt());
        }
        let slope = slope(counts, &rmse);
        out.push((name.clone(), rmse, slope));
    }
    Ok(out)
}

/// The mean radiance (channel average) of `spp` camera samples of `pixel` from `sampler`.
///
/// # Errors
/// An unknown scene or sampler, or a count the sampler rejects.
pub fn pixel_mean(
    scene: &str,
    size: [u32; 2],
    pixel: [u32; 2],
    sampler: &str,
    spp: u32,
    seed: u64,
) -> Result<f64> {
    let sc = crate::scene::Scene::by_name(scene)
        .ok_or_else(|| anyhow::anyhow!("unknown scene {scene:?}"))?;
    let s = crate::build_sampler(sampler, size, spp, seed)?;
    let layout = crate::trace::PathLayout::new(&s, &crate::trace::LightSamples::first(1))?;
    let (mut sum, mut n) = (0.0f64, 0u32);
    let end = [pixel[0] + 1, pixel[1] + 1];
    crate::trace::for_each_sample(&sc, &layout, s, size, pixel, end, |_, l| {
        sum += f64::from(l.0.iter().sum::<f32>()) / 3.0;
        n += 1;
    })?;
    Ok(sum / f64::from(n.max(1)))
}

/// The pixel's reference: the mean of 64 `owen-sobol` renders of 16384 samples each (2^20
/// samples), and its standard error.
///
/// # Errors
/// An unknown scene.
pub fn pixel_reference(scene: &str, size: [u32; 2], pixel: [u32; 2]) -> Result<(f64, f64)> {
    let xs = (0..64)
        .map(|r| pixel_mean(scene, size, pixel, "owen-sobol", 16384, run_seed(0xfeed, r)))
        .collect::<Result<Vec<f64>>>()?;
    let m = xs.iter().sum::<f64>() / 64.0;
    let var = xs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / 63.0;
    Ok((m, (var / 64.0).sqrt()))
}

/// Least-squares slope of `ln rmse` against `ln n`.
fn slope(counts: &[u32], rmse: &[f64]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = counts
        .iter()
        .zip(rmse)
        .filter(|(_, e)| **e > 0.0)
        .map(|(n, e)| (f64::from(*n).ln(), e.ln()))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let k = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|p| p.0).sum::<f64>() / k,
        pts.iter().map(|p| p.1).sum::<f64>() / k,
    );
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}
