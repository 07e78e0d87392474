//! The path tracer: next-event estimation on the square light, cosine-weighted diffuse bounces,
//! Russian roulette from the third vertex, every value drawn from the sampler through a
//! [`SampleLayout`].
//!
//! ## Dimension layout
//!
//! One camera sample is a [`Sample`] filled by a [`PixelRangeSampler`] (the request-and-fill
//! layer). Its values, in the order the sampler draws them:
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

use nyquist::sampler::{PixelRangeSampler, Sample, SampleLayout, Sampler};

use crate::geometry::{Ray, V3, cosine_hemisphere};
use crate::scene::{EPSILON, Scene};

/// The most surface vertices a path visits.
pub const MAX_VERTICES: usize = 8;

/// Arrays per camera sample: light samples, direction and roulette for each vertex.
pub const ARRAYS: usize = 3 * MAX_VERTICES;

/// Russian roulette applies from this vertex on (1-based).
pub const ROULETTE_FROM: usize = 3;

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
    /// The layout for `light_samples` light samples at the first vertex (rounded by the
    /// sampler's `round_size`; one at every other vertex).
    ///
    /// # Errors
    /// If the sampler rejects the sizes (`light_samples == 0`).
    pub fn new<S: Sampler + ?Sized>(
        sampler: &S,
        light_samples: u32,
    ) -> Result<PathLayout, nyquist::Error> {
        let mut layout = SampleLayout::new();
        let mut light = [0; MAX_VERTICES];
        let mut direction = [0; MAX_VERTICES];
        let mut roulette = [0; MAX_VERTICES];
        for k in 0..MAX_VERTICES {
            light[k] = layout.add_2d(sampler, if k == 0 { light_samples } else { 1 })?;
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

/// The radiance (RGB) one camera sample carries, for a film of `resolution` pixels.
pub fn radiance(scene: &Scene, layout: &PathLayout, s: &Sample<'_>, resolution: [u32; 2]) -> V3 {
    let time = s.time();
    let mut ray = scene.camera.ray(s.image(), s.lens(), resolution);
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
        // Next-event estimation: the mean over this vertex's light samples.
        let points = s.array_2d(layout.light[k]);
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
            let u = s
                .array_1d(layout.roulette[k])
                .first()
                .copied()
                .unwrap_or(0.0);
            if u >= q {
                break;
            }
            beta = beta * (1.0 / q);
        }
        let d = s.array_2d(layout.direction[k]);
        let u = [
            d.first().copied().unwrap_or(0.5),
            d.get(1).copied().unwrap_or(0.5),
        ];
        ray = Ray {
            origin,
            dir: cosine_hemisphere(n, u),
        };
        beta = beta.hadamard(obj.albedo);
    }
    l
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
        let l = radiance(scene, layout, &sample, resolution);
        f(&sample, l);
    }
    Ok(())
}
