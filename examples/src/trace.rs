//! The path tracer: next-event estimation on the square light, cosine-weighted diffuse bounces,
//! Russian roulette from the third vertex, every value drawn from the sampler through a
//! [`SampleLayout`].
//!
//! ## Dimension layout
//!
//! One camera sample is a [`Sample`] filled by a [`PixelRangeSampler`] (the request-and-fill
//! layer), or the same values drawn through the stateless layer ([`Stateless`],
//! [`for_each_sample_stateless`]). Its values, in the order the sampler draws them:
//!
//! | values | what | request |
//! |---|---|---|
//! | 2 (dims 0–1) | image sample: film position inside the pixel | camera sample |
//! | 1 (dim 2) | shutter time `[0, 1)` | camera sample |
//! | 2 (dims 3–4) | lens position (concentric disk) | camera sample |
//! | 2N | vertex 1: N light samples (points on the light) | `add_2d(N)` |
//! | 2 | vertex 1: cosine-weighted bounce direction | `add_2d(1)` |
//! | 1 | vertex 1: Russian roulette (unused before vertex 3) | `add_1d(1)` |
//! | 2 + 2 + 1 | vertex k = 2 … 8: one light sample, direction, roulette | `add_2d(1)`, `add_2d(1)`, `add_1d(1)` |
//!
//! Vertex 1 is the first surface the camera ray hits. For samplers whose arrays are runs of
//! dimensions ([`Sampler::arrays_are_dimension_runs`]: all but the stratified and padded ones),
//! the values above are dimensions 0, 1, 2, … in order: with N light samples, vertex 1's light
//! samples are dimensions 5 … 4 + 2N and vertex k ≥ 2 starts at dimension 8 + 2N + 5(k − 2).
//! Samplers that stratify their arrays spend one array dimension (1D) or pair (2D) per request.
//! Every value is requested whether the path uses it or not, so the layout is fixed: a path
//! has at most [`MAX_VERTICES`] vertices (the last one's direction and roulette go unused),
//! `5 + 2N + 5·8 − 2` values per camera sample.
//!
//! ## Estimator
//!
//! Next-event estimation without multiple importance sampling: at each vertex the light is
//! sampled uniformly by area (the mean over the vertex's light samples), and the light's own
//! emission counts only when the camera ray sees it directly. After a bounce, a ray that hits
//! the light ends the path (its contribution was the light sample's). Every surface is
//! Lambertian, so this is unbiased for the scene truncated at [`MAX_VERTICES`] vertices.
//! Russian roulette at vertex k ≥ 3 continues with probability `min(1, max(0.05, max β))`, β
//! the path throughput, and divides β by it.

use nyquist::sampler::{
    CameraSample, Domain, OwenSobolSampler, PixelRangeSampler, Sample, SampleLayout, Sampler,
};

use crate::geometry::{Ray, V3, cosine_hemisphere};
use crate::scene::{EPSILON, Scene};

/// The most surface vertices a path visits.
pub const MAX_VERTICES: usize = 8;

/// Arrays per camera sample: light samples, direction and roulette for each vertex.
pub const ARRAYS: usize = 3 * MAX_VERTICES;

/// Russian roulette applies from this vertex on (1-based).
pub const ROULETTE_FROM: usize = 3;

/// Light samples per vertex: `counts[k]` points on the light at vertex `k + 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightSamples {
    counts: [u32; MAX_VERTICES],
}

impl LightSamples {
    /// `n` light samples at the first vertex and one at every later vertex.
    pub fn first(n: u32) -> LightSamples {
        let mut counts = [1; MAX_VERTICES];
        counts[0] = n;
        LightSamples { counts }
    }

    /// Counts per vertex from a list (`4,2,1`: four at the first vertex, two at the second,
    /// one at each vertex past the list).
    ///
    /// # Errors
    /// An empty list, a count that is not a positive integer, or more counts than vertices.
    pub fn parse(text: &str) -> Result<LightSamples, String> {
        let mut counts = [1; MAX_VERTICES];
        let fields: Vec<&str> = text.split(',').map(str::trim).collect();
        if fields.len() > MAX_VERTICES {
            return Err(format!(
                "{text:?}: {} counts, at most {MAX_VERTICES} (one per vertex)",
                fields.len()
            ));
        }
        for (c, f) in counts.iter_mut().zip(&fields) {
            *c = f
                .parse::<u32>()
                .ok()
                .filter(|&n| (1..=1 << 16).contains(&n))
                .ok_or_else(|| format!("{text:?}: {f:?} is not a count in 1..=65536"))?;
        }
        Ok(LightSamples { counts })
    }

    /// Light samples at vertex `k + 1`.
    pub fn at(&self, k: usize) -> u32 {
        self.counts.get(k).copied().unwrap_or(1)
    }

    /// The list, without the trailing ones past the first vertex (`4,2`, or `3`).
    pub fn label(&self) -> String {
        let last = self.counts.iter().rposition(|&c| c != 1).unwrap_or(0);
        let shown: Vec<String> = self.counts[..=last].iter().map(u32::to_string).collect();
        shown.join(",")
    }
}

/// The sample layout of a path: the handles of each vertex's arrays.
#[derive(Clone, Debug)]
pub struct PathLayout {
    /// The layout the sampler fills.
    pub layout: SampleLayout<ARRAYS>,
    light: [usize; MAX_VERTICES],
    direction: [usize; MAX_VERTICES],
    roulette: [usize; MAX_VERTICES],
}

impl PathLayout {
    /// The layout for `light_samples` light samples per vertex (each rounded by the sampler's
    /// `round_size`): pbrt-v2's arrays, one per vertex, sized up front.
    ///
    /// # Errors
    /// If the sampler rejects the sizes.
    pub fn new<S: Sampler + ?Sized>(
        sampler: &S,
        light_samples: &LightSamples,
    ) -> Result<PathLayout, nyquist::Error> {
        let mut layout = SampleLayout::new();
        let mut light = [0; MAX_VERTICES];
        let mut direction = [0; MAX_VERTICES];
        let mut roulette = [0; MAX_VERTICES];
        for k in 0..MAX_VERTICES {
            light[k] = layout.add_2d(sampler, light_samples.at(k))?;
            direction[k] = layout.add_2d(sampler, 1)?;
            roulette[k] = layout.add_1d(sampler, 1)?;
        }
        Ok(PathLayout {
            layout,
            light,
            direction,
            roulette,
        })
    }

    /// Floats per camera sample.
    pub fn len(&self) -> usize {
        self.layout.len()
    }

    /// Never empty (the camera sample alone takes 5 floats).
    pub fn is_empty(&self) -> bool {
        false
    }
}

/// Where a path's values come from, vertex by vertex (vertex `k = 0` is the first hit): the
/// vertex's light points (pairs), its bounce direction sample and its roulette value, drawn in
/// that order.
pub trait PathSource {
    /// The values of vertex `k`.
    fn vertex(&mut self, k: usize) -> (&[f32], [f32; 2], f32);
}

/// A [`Sample`] filled through a [`PathLayout`] (the request-and-fill layer).
#[derive(Debug)]
pub struct FilledSample<'a, 'b> {
    /// The filled sample.
    pub sample: &'a Sample<'b>,
    /// Its layout.
    pub layout: &'a PathLayout,
}

impl PathSource for FilledSample<'_, '_> {
    fn vertex(&mut self, k: usize) -> (&[f32], [f32; 2], f32) {
        let d = self.sample.array_2d(self.layout.direction[k]);
        let u = [
            d.first().copied().unwrap_or(0.5),
            d.get(1).copied().unwrap_or(0.5),
        ];
        let rr = self.sample.array_1d(self.layout.roulette[k]);
        let rr = rr.first().copied().unwrap_or(0.0);
        (self.sample.array_2d(self.layout.light[k]), u, rr)
    }
}

/// The stateless layer: after [`Sampler::camera_sample`], each vertex takes its light points
/// with one [`Sampler::get_array_2d`] (`round_size(N)` points for the vertex's `N`), then
/// [`Sampler::get_2d`] for the direction and [`Sampler::get_1d`] for the roulette, only as far
/// as the path goes: pbrt-v4's dimension counter. For samplers whose arrays are dimension runs
/// the values equal the layout's bit for bit.
#[derive(Debug)]
pub struct Stateless<'a, S: ?Sized> {
    /// The sampler, positioned after the camera sample.
    pub sampler: &'a mut S,
    /// Light points per vertex.
    pub light: LightSamples,
    /// Scratch for the light points.
    pub buf: Vec<f32>,
    /// Draw the light points one `get_2d` each (pbrt-v4's counter) instead of one
    /// `get_array_2d` per vertex (equal for samplers whose arrays are dimension runs).
    pub counter: bool,
}

impl<S: Sampler + ?Sized> PathSource for Stateless<'_, S> {
    fn vertex(&mut self, k: usize) -> (&[f32], [f32; 2], f32) {
        let n = self.sampler.round_size(self.light.at(k)).max(1);
        self.buf.resize(2 * n as usize, 0.0);
        if self.counter {
            for p in self.buf.chunks_exact_mut(2) {
                p.copy_from_slice(&self.sampler.get_2d());
            }
        } else {
            self.sampler.get_array_2d(&mut self.buf);
        }
        let u = self.sampler.get_2d();
        let rr = self.sampler.get_1d();
        (&self.buf, u, rr)
    }
}

/// The radiance (RGB) one camera sample carries, for a film of `resolution` pixels, with the
/// camera values `p_film`, `lens`, `time` and the rest from `src`.
pub fn radiance(
    scene: &Scene,
    camera: &CameraSample,
    src: &mut impl PathSource,
    resolution: [u32; 2],
) -> V3 {
    let time = camera.time;
    let mut ray = scene.camera.ray(camera.p_film, camera.lens, resolution);
    let mut beta = V3::new(1.0, 1.0, 1.0);
    let mut l = V3::default();
    let light = &scene.light;
    let (light_n, light_area) = (light.normal(), light.area());
    for k in 0..MAX_VERTICES {
        let Some((i, t, n)) = scene.intersect(&ray, time, f32::INFINITY) else {
            break;
        };
        let obj = &scene.objects[i];
        if obj.emitter {
            if k == 0 && ray.dir.dot(light_n) < 0.0 {
                l = l + beta.hadamard(light.radiance);
            }
            break;
        }
        let p = ray.origin + ray.dir * t;
        let n = if n.dot(ray.dir) < 0.0 { n } else { -n };
        let origin = p + n * EPSILON;
        let (points, u_dir, u_rr) = src.vertex(k);
        // Next-event estimation: the mean over this vertex's light samples.
        let count = points.len() / 2;
        let mut direct = 0.0f32;
        for uv in points.chunks_exact(2) {
            let q = light.point([uv[0], uv[1]]);
            let d = q - p;
            let d2 = d.dot(d);
            let wi = d * (1.0 / d2.sqrt());
            let cos_s = n.dot(wi);
            let cos_l = -light_n.dot(wi);
            if cos_s > 0.0 && cos_l > 0.0 && !scene.occluded(origin, q, time) {
                direct += cos_s * cos_l / d2;
            }
        }
        if count > 0 {
            let g = direct * light_area / count as f32 * core::f32::consts::FRAC_1_PI;
            l = l + beta.hadamard(obj.albedo).hadamard(light.radiance) * g;
        }
        if k + 1 == MAX_VERTICES {
            break;
        }
        if k + 1 >= ROULETTE_FROM {
            let q = beta.max_component().clamp(0.05, 1.0);
            if u_rr >= q {
                break;
            }
            beta = beta * (1.0 / q);
        }
        ray = Ray {
            origin,
            dir: cosine_hemisphere(n, u_dir),
        };
        beta = beta.hadamard(obj.albedo);
    }
    l
}

/// Calls `f(p_film, radiance)` for every camera sample of the pixels `start .. end` through the
/// stateless layer ([`Stateless`]), pixel by pixel in row order, `pixel_samples` each.
pub fn for_each_sample_stateless<S: Sampler>(
    scene: &Scene,
    sampler: S,
    light: &LightSamples,
    resolution: [u32; 2],
    start: [u32; 2],
    end: [u32; 2],
    f: impl FnMut([f32; 2], V3),
) {
    let light = Lights {
        counts: *light,
        counter: false,
    };
    stateless_pixels(scene, sampler, &light, resolution, start, end, f);
}

/// [`for_each_sample_stateless`] with the light points one `get_2d` each: pbrt-v4's dimension
/// counter, which a sampler that stratifies its arrays (pmj02, zsobol) does not stratify.
pub fn for_each_sample_counter<S: Sampler>(
    scene: &Scene,
    sampler: S,
    light: &LightSamples,
    resolution: [u32; 2],
    start: [u32; 2],
    end: [u32; 2],
    f: impl FnMut([f32; 2], V3),
) {
    let light = Lights {
        counts: *light,
        counter: true,
    };
    stateless_pixels(scene, sampler, &light, resolution, start, end, f);
}

/// Light samples per vertex and how the stateless layer draws them.
#[derive(Clone, Copy, Debug)]
struct Lights {
    counts: LightSamples,
    counter: bool,
}

/// The pixels `start .. end` in row order through the stateless layer.
fn stateless_pixels<S: Sampler>(
    scene: &Scene,
    mut sampler: S,
    light: &Lights,
    resolution: [u32; 2],
    start: [u32; 2],
    end: [u32; 2],
    mut f: impl FnMut([f32; 2], V3),
) {
    let mut buf = Vec::new();
    for y in start[1]..end[1] {
        for x in start[0]..end[0] {
            for i in 0..sampler.pixel_samples([x, y]) {
                let (p, l) =
                    trace_stateless(scene, &mut sampler, light, &mut buf, resolution, [x, y], i);
                f(p, l);
            }
        }
    }
}

/// Camera sample `i` of `pixel` traced through the stateless layer: its film position and
/// radiance. `buf` is the light points' scratch, kept between calls.
fn trace_stateless<S: Sampler>(
    scene: &Scene,
    sampler: &mut S,
    light: &Lights,
    buf: &mut Vec<f32>,
    resolution: [u32; 2],
    pixel: [u32; 2],
    i: u32,
) -> ([f32; 2], V3) {
    let camera = sampler.camera_sample(pixel, i);
    let mut src = Stateless {
        sampler,
        light: light.counts,
        buf: core::mem::take(buf),
        counter: light.counter,
    };
    let l = radiance(scene, &camera, &mut src, resolution);
    *buf = src.buf;
    (camera.p_film, l)
}

/// Calls `f(sample, radiance)` for every camera sample of the pixels `start .. end` (exclusive),
/// in the sampler's order.
///
/// # Errors
/// An empty pixel range.
pub fn for_each_sample<S: Sampler>(
    scene: &Scene,
    layout: &PathLayout,
    sampler: S,
    resolution: [u32; 2],
    start: [u32; 2],
    end: [u32; 2],
    mut f: impl FnMut(&Sample<'_>, V3),
) -> Result<(), nyquist::Error> {
    let mut pixels = PixelRangeSampler::new(sampler, start, end)?;
    let mut buf = vec![0.0f32; layout.len()];
    let mut sample = Sample::new(&layout.layout, &mut buf)?;
    while pixels.next_sample(&mut sample) {
        let camera = CameraSample {
            p_film: sample.image(),
            lens: sample.lens(),
            time: sample.time(),
        };
        let mut src = FilledSample {
            sample: &sample,
            layout,
        };
        let l = radiance(scene, &camera, &mut src, resolution);
        f(&sample, l);
    }
    Ok(())
}

/// The camera samples `indices` of `pixel`, traced through the stateless layer as
/// [`for_each_sample_stateless`] traces them: `f(p_film, index, radiance)` for each. For
/// adaptive rendering, which adds samples to a pixel pass by pass.
pub fn for_pixel_samples<S: Sampler>(
    scene: &Scene,
    mut sampler: S,
    light: &LightSamples,
    resolution: [u32; 2],
    pixel: [u32; 2],
    indices: core::ops::Range<u64>,
    mut f: impl FnMut([f32; 2], u64, V3),
) {
    let mut buf = Vec::new();
    let light = Lights {
        counts: *light,
        counter: false,
    };
    for i in indices {
        // Below the sampler's spp, which the caller made it for (u32).
        let (p, l) = trace_stateless(
            scene,
            &mut sampler,
            &light,
            &mut buf,
            resolution,
            pixel,
            i as u32,
        );
        f(p, i, l);
    }
}

/// Domain keys of a path's values at vertex `k`: its light samples, its direction and its
/// roulette, each vertex its own (so each vertex's count may differ).
const LIGHT_KEY: u64 = 0x100;
const DIRECTION_KEY: u64 = 0x200;
const ROULETTE_KEY: u64 = 0x300;

/// How a vertex's light samples derive from the camera sample's domain (OpenQMC's three).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Derivation {
    /// [`Domain::split`]: over the pixel's camera samples, a vertex's light samples are one
    /// stratified sequence of `spp · N_k` points.
    Split,
    /// [`Domain::distribute`]: each camera sample's `N_k` light samples are a net of their own.
    Distribute,
    /// [`Domain::chain`]: light sample `j` of every camera sample is one net over the pixel.
    Chain,
}

impl Derivation {
    /// `split`, `distribute` or `chain`.
    ///
    /// # Errors
    /// Any other name.
    pub fn parse(name: &str) -> Result<Derivation, String> {
        match name {
            "split" => Ok(Derivation::Split),
            "distribute" => Ok(Derivation::Distribute),
            "chain" => Ok(Derivation::Chain),
            other => Err(format!("{other:?}: one of split, distribute, chain")),
        }
    }
}

/// A path's values from the camera sample's [`Domain`]: at vertex `k`, light sample `j` of
/// `N_k` derives from the vertex's light key by [`Derivation`]; the direction and the roulette
/// are [`Domain::branch`]es.
#[derive(Debug)]
pub struct DomainSource {
    /// The camera sample's domain.
    pub root: Domain,
    /// Light points per vertex.
    pub light: LightSamples,
    /// How light samples derive from the root.
    pub derivation: Derivation,
    /// Scratch for the light points.
    pub buf: Vec<f32>,
}

impl PathSource for DomainSource {
    fn vertex(&mut self, k: usize) -> (&[f32], [f32; 2], f32) {
        let n = self.light.at(k);
        let key = LIGHT_KEY + k as u64;
        self.buf.clear();
        for j in 0..n {
            let d = match self.derivation {
                // `n ≤ 65536` and a camera index below 2³²: the split's index fits.
                Derivation::Split => self.root.split(key, n, j).unwrap_or(self.root),
                Derivation::Distribute => self.root.distribute(key, j),
                Derivation::Chain => self.root.chain(key, j),
            };
            self.buf.extend(d.get_2d(0));
        }
        let u = self.root.branch(DIRECTION_KEY + k as u64).get_2d(0);
        let rr = self.root.branch(ROULETTE_KEY + k as u64).get_1d(0);
        (&self.buf, u, rr)
    }
}

/// Calls `f(p_film, radiance)` for every camera sample of the pixels `start .. end`, the camera
/// values from `sampler` and the rest from its samples' domains ([`DomainSource`]).
#[allow(clippy::too_many_arguments)]
pub fn for_each_sample_domains(
    scene: &Scene,
    mut sampler: OwenSobolSampler,
    light: &LightSamples,
    derivation: Derivation,
    resolution: [u32; 2],
    start: [u32; 2],
    end: [u32; 2],
    mut f: impl FnMut([f32; 2], V3),
) {
    let mut buf = Vec::new();
    for y in start[1]..end[1] {
        for x in start[0]..end[0] {
            for i in 0..sampler.pixel_samples([x, y]) {
                let camera = sampler.camera_sample([x, y], i);
                let mut src = DomainSource {
                    root: sampler.pixel_domain(),
                    light: *light,
                    derivation,
                    buf: core::mem::take(&mut buf),
                };
                let l = radiance(scene, &camera, &mut src, resolution);
                buf = src.buf;
                f(camera.p_film, l);
            }
        }
    }
}
