//! Samplers: the values a renderer needs for each pixel sample.
//!
//! Two layers over the same generators:
//!
//! 1. **Stateless, random access** (pbrt-v4's `StartPixelSample` / `Get1D` / `Get2D`): the
//!    [`Sampler`] trait. A sampler is a small `Clone` cursor; after
//!    [`Sampler::start_pixel_sample`] its values depend only on (pixel, sample index, dimension,
//!    seed, construction parameters), so every thread clones its own and replays bit-identical
//!    values in any order. Per-pixel permutations and scrambles come from [`crate::hash`]: no
//!    tables, no shared state.
//! 2. **Request and fill** (pbrt-v2's `Sample`, `Add1D`/`Add2D`, `RoundSize`, `GetNextSample`):
//!    [`SampleLayout`], [`Sample`] and [`PixelRangeSampler`] in [`layout`].
//!
//! ## Dimensions
//!
//! Dimensions 0 and 1 are the image sample, returned by [`Sampler::get_pixel_2d`] whatever the
//! cursor. [`camera_sample`] starts at dimension 0 and takes the image sample (dimensions 0, 1),
//! then time ([`Sampler::get_1d`], dimension 2), then the lens ([`Sampler::get_2d`], dimensions
//! 3, 4); an integrator's own values follow from dimension 5.
//!
//! | sampler | values |
//! |---|---|
//! | [`RandomSampler`] | independent PCG32 values |
//! | [`AdaptiveSampler`] | wraps another: minimum spp, maximum where the first samples disagree |
//! | [`BestCandidateSampler`] | a baked blue-noise (Mitchell best-candidate) table |
//! | [`LatticeSampler`] | the Fibonacci lattice, a Korobov lattice or R2 per dimension pair, rotated per pixel and pair |
//! | [`DitheredSampler`] | one point set in every pixel, toroidally shifted by a blue-noise mask |
//! | [`OwenSobolSampler`] | Owen-scrambled Sobol per pixel, hashed by pixel, frame and seed |
//! | [`ZSobolSampler`] | Sobol along a hash-permuted Morton curve: blue-noise error across pixels |
//! | [`Pmj02Sampler`] | baked progressive multi-jittered (0,2) points, index-shuffled and Owen-scrambled per pixel and dimension |
//! | [`StratifiedSampler`] | jittered (or centred: [`StratifiedSampler::uniform`]) strata, hash-permuted per dimension |

/// `get_1d`, `get_2d` and `get_pixel_2d` for samplers that read dimension `d` of one point
/// through `self.sample(d)` and keep their next dimension in `self.dim` (the global Halton,
/// Hammersley and Sobol samplers, and best-candidate's table rows): dimensions are consumed in
/// order, and the pixel sample is always dimensions 0 and 1.
macro_rules! global_point_dimensions {
    () => {
        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn get_1d(&mut self) -> f32 {
            let d = self.dim;
            self.dim = self.dim.wrapping_add(1);
            self.sample(d)
        }

        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn get_2d(&mut self) -> [f32; 2] {
            let d = self.dim;
            self.dim = self.dim.wrapping_add(2);
            [self.sample(d), self.sample(d.wrapping_add(1))]
        }

        #[cfg_attr(not(feature = "small-code"), inline(always))]
        fn get_pixel_2d(&mut self) -> [f32; 2] {
            self.dim = self.dim.max(2);
            [self.sample(0), self.sample(1)]
        }
    };
}
pub(crate) use global_point_dimensions;

/// `get_array_1d` and `get_array_2d` for the global samplers, whose arrays take one dimension
/// per value as the defaults do (pairs for 2D; an odd last value is left untouched): a run of
/// dimensions goes to the sampler's `self.batch(first_dim, out)`, and where that declines
/// (returns `false`) to `self.sample(d)` one value at a time.
macro_rules! global_point_arrays {
    () => {
        fn arrays_are_dimension_runs(&self) -> bool {
            true
        }

        fn get_array_1d(&mut self, out: &mut [f32]) {
            let dim = self.dim;
            self.dim = dim.wrapping_add(out.len() as u32);
            if !self.batch(dim, out) {
                super::values_one_at_a_time(dim, out, |d| self.sample(d));
            }
        }

        fn get_array_2d(&mut self, out: &mut [f32]) {
            let n = out.len() & !1;
            let dim = self.dim;
            self.dim = dim.wrapping_add(n as u32);
            let out = &mut out[..n];
            if !self.batch(dim, out) {
                super::values_one_at_a_time(dim, out, |d| self.sample(d));
            }
        }
    };
}
pub(crate) use global_point_arrays;

/// `out[i] = sample(dim + i)`, the dimension wrapping at `u32::MAX` as the cursor does.
#[inline]
fn values_one_at_a_time(dim: u32, out: &mut [f32], sample: impl Fn(u32) -> f32) {
    let mut d = dim;
    for x in out {
        *x = sample(d);
        d = d.wrapping_add(1);
    }
}

mod adaptive;
pub mod best_candidate;
mod dithered;
pub mod domain;
mod halton;
mod hammersley;
mod lattice;
mod named;
mod owen_sobol;
mod pmj02;
mod random;
pub mod screen_blue;
mod sobol;
mod stratified;
mod zero_two;
mod zsobol;

pub mod layout;

pub use adaptive::{ADAPTIVE_CHANNELS, AdaptiveSampler};
pub use best_candidate::BestCandidateSampler;
pub use dithered::{DITHER_MASK_RANKS, DitheredSampler, MaskView};
pub use domain::Domain;
pub use halton::HaltonSampler;
pub use hammersley::HammersleySampler;
pub use lattice::LatticeSampler;
pub use layout::{PixelRangeSampler, Sample, SampleLayout};
pub use named::{
    CONTINUING_NAMES, NAMES, NamedSampler, NamedSamplerError, OTHER_NAMES, SCRAMBLE_NAMES,
    canonical_name, continues, spp_limit, strata,
};
pub use owen_sobol::OwenSobolSampler;
pub(crate) use pmj02::Keys as Pmj02Keys;
pub use pmj02::Pmj02Sampler;
pub use random::RandomSampler;
pub use screen_blue::{
    BlueNoiseSampler, LatticeBlueSampler, OwenSobolBlueSampler, Pmj02BlueSampler,
};
pub use sobol::SobolSampler;
pub use stratified::{Jitter, StratifiedSampler};
pub use zero_two::ZeroTwoSampler;
pub use zsobol::ZSobolSampler;
pub(crate) use zsobol::{key_seed as zsobol_key_seed, scramble_dim0 as zsobol_scramble_dim0};

/// A source of sample values addressed by (pixel, sample index, dimension).
///
/// Contract for every implementation:
/// - every value is in `[0, 1)` and never NaN;
/// - after `start_pixel_sample(pixel, index, dim)` the values returned depend only on those
///   arguments, the calls made since, and the construction parameters (seed, sizes);
/// - `sample_index >= samples_per_pixel()` is allowed: samplers with a fixed per-pixel pattern
///   wrap it modulo `samples_per_pixel()` (each documents what it does);
/// - the trait is object safe: a renderer may hold a `&mut dyn Sampler`.
///
/// ```
/// use nyquist::sampler::{RandomSampler, Sampler};
/// let mut s = RandomSampler::new(4, 7).unwrap();
/// s.start_pixel_sample([3, 5], 2, 0);
/// let a = s.get_2d();
/// s.start_pixel_sample([3, 5], 2, 0);
/// assert_eq!(s.get_2d(), a);
/// ```
pub trait Sampler {
    /// Samples per pixel.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let s = RandomSampler::new(4, 7).unwrap();
    /// assert_eq!(s.samples_per_pixel(), 4);
    /// ```
    fn samples_per_pixel(&self) -> u32;

    /// Moves the cursor to sample `sample_index` of `pixel`, at dimension `dim`.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([1, 2], 0, 3);
    /// let a = s.get_1d();
    /// s.start_pixel_sample([1, 2], 0, 2);
    /// s.get_1d();
    /// assert_eq!(s.get_1d(), a); // dimension 3 either way
    /// ```
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32);

    /// The value of the current dimension, in `[0, 1)`; advances the cursor by one.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([0, 0], 0, 9);
    /// assert!((0.0..1.0).contains(&s.get_1d()));
    /// ```
    fn get_1d(&mut self) -> f32;

    /// The values of the current and the next dimension, in `[0, 1)²`; advances by two.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([0, 0], 0, 5);
    /// let [u, v] = s.get_2d();
    /// s.start_pixel_sample([0, 0], 0, 5);
    /// assert_eq!([s.get_1d(), s.get_1d()], [u, v]);
    /// ```
    fn get_2d(&mut self) -> [f32; 2];

    /// The image sample: the offset inside the pixel, in `[0, 1)²` (dimensions 0 and 1 whatever
    /// the cursor). Moves the cursor to `max(cursor, 2)`.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([0, 0], 1, 7);
    /// let a = s.get_pixel_2d();
    /// s.start_pixel_sample([0, 0], 1, 0);
    /// assert_eq!(s.get_pixel_2d(), a);
    /// ```
    fn get_pixel_2d(&mut self) -> [f32; 2];

    /// The array size this sampler prefers for a request of `n` values (pbrt-v2's `RoundSize`):
    /// `n` itself unless the sampler's arrays need, e.g., a power of two. Total: never returns 0
    /// for `n > 0`; saturates at the largest size the sampler supports.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let s = RandomSampler::new(4, 7).unwrap();
    /// assert_eq!(s.round_size(7), 7);
    /// ```
    fn round_size(&self, n: u32) -> u32 {
        n
    }

    /// Fills `out` with an array of `out.len()` values for the current sample, at the current
    /// dimension. The default takes one dimension per value; stratified samplers override it to
    /// stratify the array (taking one dimension in all). Allocates: no.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([0, 0], 0, 5);
    /// let mut a = [2.0f32; 3];
    /// s.get_array_1d(&mut a);
    /// assert!(a.iter().all(|x| (0.0..1.0).contains(x)));
    /// ```
    fn get_array_1d(&mut self, out: &mut [f32]) {
        for x in out {
            *x = self.get_1d();
        }
    }

    /// Fills `out` (pairs `[u0, v0, u1, v1, …]`, `out.len() / 2` points; an odd last value is
    /// left untouched) with an array of 2D values for the current sample. The default takes two
    /// dimensions per point; stratified samplers override it (taking two dimensions in all).
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([0, 0], 0, 5);
    /// let mut a = [2.0f32; 5];
    /// s.get_array_2d(&mut a);
    /// assert!(a[..4].iter().all(|x| (0.0..1.0).contains(x)) && a[4] == 2.0);
    /// ```
    fn get_array_2d(&mut self, out: &mut [f32]) {
        for p in out.chunks_exact_mut(2) {
            let [u, v] = self.get_2d();
            p[0] = u;
            p[1] = v;
        }
    }

    /// Whether this sampler's arrays are plain runs of dimensions: [`Sampler::get_array_1d`]
    /// takes one dimension per value and [`Sampler::get_array_2d`] two per point, as the
    /// defaults do. Arrays requested back to back then equal one `get_array_1d` over all of
    /// them, and [`PixelRangeSampler`] fills a sample's arrays in one call. The default, `false`,
    /// is always safe; a sampler that stratifies its arrays must answer `false`.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// assert!(s.arrays_are_dimension_runs());
    /// let (mut two, mut one) = ([0.0f32; 6], [0.0f32; 6]);
    /// s.start_pixel_sample([1, 2], 3, 5);
    /// s.get_array_2d(&mut two[..4]);
    /// s.get_array_1d(&mut two[4..]);
    /// s.start_pixel_sample([1, 2], 3, 5);
    /// s.get_array_1d(&mut one);
    /// assert_eq!(one, two);
    /// ```
    fn arrays_are_dimension_runs(&self) -> bool {
        false
    }

    /// The camera sample of `pixel`, sample `sample_index`: image sample (dimensions 0, 1),
    /// time (2), lens (3, 4); leaves the cursor at dimension 5. [`camera_sample`] calls it.
    ///
    /// The default is `start_pixel_sample(pixel, sample_index, 0)`, `get_pixel_2d`, `get_1d`,
    /// `get_2d`. A sampler may override it to share work between the five values (one hash for
    /// time and lens, say); an override returns exactly the default's values, bit for bit.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// let c = s.camera_sample([3, 5], 2);
    /// s.start_pixel_sample([3, 5], 2, 0);
    /// let p = s.get_pixel_2d();
    /// assert_eq!((c.p_film, c.time), ([3.0 + p[0], 5.0 + p[1]], s.get_1d()));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        camera_sample_by_parts(self, pixel, sample_index)
    }

    /// How many samples `pixel` takes, given what was [reported](Sampler::report) for it so far.
    /// The default is [`Sampler::samples_per_pixel`]; adaptive samplers answer between their
    /// minimum and maximum.
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let s = RandomSampler::new(4, 7).unwrap();
    /// assert_eq!(s.pixel_samples([5, 5]), 4);
    /// ```
    fn pixel_samples(&self, pixel: [u32; 2]) -> u32 {
        let _ = pixel;
        self.samples_per_pixel()
    }

    /// Reports the radiance (any number of channels) that sample `sample_index` of `pixel`
    /// produced. The default ignores it; adaptive samplers use it to decide
    /// [`Sampler::pixel_samples`].
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, Sampler};
    /// let mut s = RandomSampler::new(4, 7).unwrap();
    /// s.report([0, 0], 0, &[1.0, 0.0, 0.0]); // ignored
    /// assert_eq!(s.pixel_samples([0, 0]), 4);
    /// ```
    fn report(&mut self, pixel: [u32; 2], sample_index: u32, radiance: &[f32]) {
        let _ = (pixel, sample_index, radiance);
    }

    /// The current pixel sample as a [`Domain`], for samplers whose samples are domains
    /// ([`OwenSobolSampler`]: its dimension `d` is the domain's dimension `d`), from which
    /// [`Domain::split`] and the others derive sub-streams. `None` (the default) for the others.
    ///
    /// ```
    /// use nyquist::sampler::{OwenSobolSampler, RandomSampler, Sampler};
    /// let mut s = OwenSobolSampler::new(4, 7).unwrap();
    /// s.start_pixel_sample([1, 2], 3, 0);
    /// assert_eq!(s.domain().map(|d| d.index()), Some(3));
    /// assert_eq!(RandomSampler::new(4, 7).unwrap().domain(), None);
    /// ```
    fn domain(&self) -> Option<Domain> {
        None
    }
}

/// What a camera needs for one pixel sample.
///
/// ```
/// use nyquist::sampler::{camera_sample, RandomSampler};
/// let c = camera_sample(&mut RandomSampler::new(1, 0).unwrap(), [10, 20], 0);
/// assert!(c.p_film[0] >= 10.0 && c.p_film[0] < 11.0);
/// assert!((0.0..1.0).contains(&c.time));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    /// Film position in pixels: the pixel's corner plus the image sample.
    pub p_film: [f32; 2],
    /// Lens position, in `[0, 1)²`.
    pub lens: [f32; 2],
    /// Time, in `[0, 1)`.
    pub time: f32,
}

/// The camera sample of `pixel`, sample `sample_index`: image sample (dimensions 0, 1), then
/// time (dimension 2), then lens (dimensions 3, 4). Leaves the cursor at dimension 5.
///
/// `p_film` is `pixel + image sample` in `f32`, kept inside the pixel (rounding can never carry
/// it to the next pixel's corner).
///
/// ```
/// use nyquist::sampler::{camera_sample, StratifiedSampler, Sampler, Jitter};
/// let mut s = StratifiedSampler::new(2, 2, Jitter::Jittered, 1).unwrap();
/// let c = camera_sample(&mut s, [0, 0], 3);
/// assert!(c.p_film[0] < 1.0 && c.p_film[1] < 1.0);
/// assert!((0.0..1.0).contains(&s.get_1d())); // dimension 5
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub fn camera_sample<S: Sampler + ?Sized>(
    s: &mut S,
    pixel: [u32; 2],
    sample_index: u32,
) -> CameraSample {
    s.camera_sample(pixel, sample_index)
}

/// [`Sampler::camera_sample`]'s default, kept apart so that tests can hold every override to it.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn camera_sample_by_parts<S: Sampler + ?Sized>(
    s: &mut S,
    pixel: [u32; 2],
    sample_index: u32,
) -> CameraSample {
    s.start_pixel_sample(pixel, sample_index, 0);
    let p = s.get_pixel_2d();
    let time = s.get_1d();
    let lens = s.get_2d();
    CameraSample {
        p_film: [
            film_coordinate(pixel[0], p[0]),
            film_coordinate(pixel[1], p[1]),
        ],
        lens,
        time,
    }
}

/// The film coordinate of a sample at `offset ∈ [0, 1)` inside pixel `pixel` along one axis:
/// `pixel + offset` rounded to `f32`, kept inside the pixel, as
/// [`Sampler::camera_sample`] computes `p_film`.
///
/// Above 1 the `f32` spacing is coarser than the offsets, so a sum can round up onto the next
/// pixel's edge `pixel + 1` (at pixel 105, an offset of `1 − 2⁻²⁴` does); the result is then
/// the largest `f32` below that edge, still inside the pixel and at the far end of it, where
/// the offset put the sample. Where `f32` has no value between `pixel` and `pixel + 1` (pixels
/// from 2²⁴ on) it is the pixel's own coordinate. Total (no panic for any input); no allocation.
///
/// ```
/// use nyquist::sampler::film_coordinate;
/// assert_eq!(film_coordinate(3, 0.25), 3.25);
/// let last = 1.0 - f32::EPSILON / 2.0; // the largest offset below 1
/// assert_eq!(film_coordinate(105, last), 106.0f32.next_down()); // not 106, not 105
/// assert_eq!(film_coordinate(1 << 24, 0.75), 16_777_216.0);
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub fn film_coordinate(pixel: u32, offset: f32) -> f32 {
    let base = pixel as f32;
    let x = base + offset;
    let edge = base + 1.0;
    if x < edge {
        x
    } else {
        // The sum rounded up onto the next pixel's edge.
        let below = edge.next_down();
        if below >= base { below } else { base }
    }
}

/// The first checks of the samplers over a whole image (halton, hammersley, sobol, zsobol):
/// [`Error::ZeroSize`] for `spp == 0`, then for a zero side of `resolution`.
pub(crate) fn check_image(resolution: [u32; 2], spp: u32) -> Result<(), crate::Error> {
    if spp == 0 {
        return Err(crate::Error::ZeroSize { what: "spp" });
    }
    if resolution[0] == 0 || resolution[1] == 0 {
        return Err(crate::Error::ZeroSize { what: "resolution" });
    }
    Ok(())
}

/// The key of a pixel's padding dimensions (those from 1024 on, [`crate::sequence::padded_u32`])
/// in the global samplers: a hash of `pixel_id`, a number each sampler gives its pixels after
/// its own wrapping of their coordinates (so pixels it repeats repeat their padding too), and
/// the seed.
#[inline]
pub(crate) fn padding_key(pixel_id: u64, seed: u64) -> u32 {
    (crate::hash::hash3(pixel_id, 0x5041_4444, seed) >> 32) as u32 // "PADD"
}

/// Hash of a pixel's coordinates with two more words (dimension, seed, …).
#[inline]
pub(crate) fn pixel_hash(pixel: [u32; 2], a: u64, b: u64) -> u64 {
    crate::hash::hash3((u64::from(pixel[1]) << 32) | u64::from(pixel[0]), a, b)
}

#[cfg(test)]
pub(crate) mod tests;
