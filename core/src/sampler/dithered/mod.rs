//! Blue-noise dithered sampling (Georgiev & Fajardo 2016): every pixel uses the same point set,
//! toroidally shifted by the value of a blue-noise mask at that pixel, so the per-pixel errors
//! are negatively correlated between neighbours and the error image is blue noise.

use super::{CameraSample, Sampler};
use crate::Error;
use crate::bluenoise::rank_to_value;
use crate::math::ONE_MINUS_EPSILON;

/// A borrowed threshold mask: `channels` planes of `width × height` ranks, channel-major, each
/// a permutation of `0 … width·height − 1` (as [`VoidAndCluster::generate_channels`] writes
/// them).
///
/// [`VoidAndCluster::generate_channels`]: crate::bluenoise::VoidAndCluster::generate_channels
///
/// ```
/// use nyquist::sampler::MaskView;
/// let ranks = [0u32, 3, 1, 2];
/// let m = MaskView::new(&ranks, 2, 2, 1).unwrap();
/// assert_eq!(m.value(1, 0, 0), 0.875); // rank 3 of 4: (3 + ½)/4
/// assert_eq!(m.value(3, 2, 0), 0.875); // the mask tiles
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaskView<'a> {
    ranks: Ranks<'a>,
    width: u32,
    height: u32,
    channels: u32,
}

/// A mask's ranks as the caller stores them: 16 bits suffice up to 65,536 pixels, as for the
/// built-in mask, and halve its size. Equal when the values are, however stored.
#[derive(Clone, Copy, Debug)]
enum Ranks<'a> {
    Wide(&'a [u32]),
    Narrow(&'a [u16]),
}

impl PartialEq for Ranks<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.len() == other.len() && (0..self.len()).all(|i| self.get(i) == other.get(i))
    }
}

impl Eq for Ranks<'_> {}

impl Ranks<'_> {
    fn len(self) -> usize {
        match self {
            Ranks::Wide(r) => r.len(),
            Ranks::Narrow(r) => r.len(),
        }
    }

    fn get(self, i: usize) -> u32 {
        match self {
            Ranks::Wide(r) => r[i],
            Ranks::Narrow(r) => u32::from(r[i]),
        }
    }

    fn max(self) -> Option<u32> {
        match self {
            Ranks::Wide(r) => r.iter().copied().max(),
            Ranks::Narrow(r) => r.iter().copied().max().map(u32::from),
        }
    }
}

impl<'a> MaskView<'a> {
    /// Views `ranks` as a `width × height` mask of `channels` channels.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for a zero width, height or channel count;
    /// [`Error::BufferLength`] unless `ranks.len() == width · height · channels`;
    /// [`Error::NotInRange`] (`what: "rank"`, the largest rank given) for a rank
    /// `≥ width · height`.
    ///
    /// ```
    /// use nyquist::{sampler::MaskView, Error};
    /// assert_eq!(
    ///     MaskView::new(&[0, 1, 2], 2, 2, 1).unwrap_err(),
    ///     Error::BufferLength { multiple_of: 4, actual: 3 }
    /// );
    /// assert_eq!(
    ///     MaskView::new(&[0, 9], 2, 1, 1).unwrap_err(),
    ///     Error::NotInRange { what: "rank", value: 9, min: 0, max: 1 }
    /// );
    /// ```
    pub fn new(
        ranks: &'a [u32],
        width: u32,
        height: u32,
        channels: u32,
    ) -> Result<MaskView<'a>, Error> {
        MaskView::checked(Ranks::Wide(ranks), width, height, channels)
    }

    /// [`MaskView::new`] over ranks stored in 16 bits (masks of at most 65,536 pixels).
    ///
    /// # Errors
    /// As [`MaskView::new`].
    ///
    /// ```
    /// use nyquist::sampler::MaskView;
    /// let m = MaskView::new_u16(&[0, 3, 1, 2], 2, 2, 1).unwrap();
    /// assert_eq!(m, MaskView::new(&[0, 3, 1, 2], 2, 2, 1).unwrap());
    /// assert_eq!(m.value(1, 0, 0), 0.875);
    /// ```
    pub fn new_u16(
        ranks: &'a [u16],
        width: u32,
        height: u32,
        channels: u32,
    ) -> Result<MaskView<'a>, Error> {
        MaskView::checked(Ranks::Narrow(ranks), width, height, channels)
    }

    fn checked(
        ranks: Ranks<'a>,
        width: u32,
        height: u32,
        channels: u32,
    ) -> Result<MaskView<'a>, Error> {
        for (v, what) in [(width, "width"), (height, "height"), (channels, "channels")] {
            if v == 0 {
                return Err(Error::ZeroSize { what });
            }
        }
        let n = u64::from(width) * u64::from(height);
        if u64::try_from(ranks.len()).ok() != Some(n * u64::from(channels)) {
            return Err(Error::BufferLength {
                multiple_of: n as usize,
                actual: ranks.len(),
            });
        }
        if let Some(r) = ranks.max().filter(|&r| u64::from(r) >= n) {
            return Err(Error::NotInRange {
                what: "rank",
                value: u64::from(r),
                min: 0,
                max: n - 1,
            });
        }
        Ok(MaskView {
            ranks,
            width,
            height,
            channels,
        })
    }

    /// The built-in mask: 64 × 64 pixels, 2 channels, void-and-cluster with seed 0
    /// ([`DITHER_MASK_RANKS`]).
    ///
    /// ```
    /// use nyquist::sampler::MaskView;
    /// let m = MaskView::builtin();
    /// assert_eq!((m.width(), m.height(), m.channels()), (64, 64, 2));
    /// ```
    pub fn builtin() -> MaskView<'static> {
        MaskView {
            ranks: Ranks::Narrow(builtin_ranks()),
            width: 64,
            height: 64,
            channels: 2,
        }
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Number of channels.
    pub fn channels(&self) -> u32 {
        self.channels
    }

    /// The value `(rank + ½)/N` of channel `channel % channels` at pixel
    /// `(x mod width, y mod height)`, in `(0, 1)`. Total.
    #[inline]
    pub fn value(&self, x: u32, y: u32, channel: u32) -> f32 {
        let n = self.width * self.height;
        let (x, y, c) = (x % self.width, y % self.height, channel % self.channels);
        let i = c as usize * n as usize + (y * self.width + x) as usize;
        rank_to_value(self.ranks.get(i), n)
    }
}

/// The ranks of the built-in dither mask, channel-major (2 × 64 × 64), each below 4096 and so
/// stored in 16 bits (16 KiB); regenerated and checked by the test `builtin_mask_is_current`.
pub static DITHER_MASK_RANKS: [u16; 2 * 64 * 64] = include!("dither_mask.in");

/// The built-in mask as [`MaskView::builtin`] reads it: [`DITHER_MASK_RANKS`], or with the
/// `lazy-tables` feature the same ranks generated at first use (16 KiB less in the binary; once,
/// with 100 KiB of stack; its cost: `docs/performance.md`), so a program that does not name the
/// static does not carry it.
#[cfg(not(feature = "lazy-tables"))]
fn builtin_ranks() -> &'static [u16; 2 * 64 * 64] {
    &DITHER_MASK_RANKS
}

#[cfg(feature = "lazy-tables")]
fn builtin_ranks() -> &'static [u16; 2 * 64 * 64] {
    &GENERATED_MASK
}

/// The fill of [`GENERATED_MASK`]: the generator and parameters that made the stored mask.
#[cfg(any(feature = "lazy-tables", test))]
struct BuiltinMask;

#[cfg(any(feature = "lazy-tables", test))]
impl crate::lazy_table::Fill for BuiltinMask {
    type Table = [u16; 2 * 64 * 64];

    fn fill(t: &mut [u16; 2 * 64 * 64]) {
        let mut ranks = [0u32; 2 * 64 * 64];
        let mut energy = [0.0f32; 64 * 64];
        let mut scratch = [0u32; 3 * 64 * 64];
        // Neither call can fail with these sizes; the test below compares every rank.
        if let Ok(vc) = crate::bluenoise::VoidAndCluster::new(64, 64, 0)
            && vc
                .generate_channels(&mut ranks, &mut energy, &mut scratch)
                .is_ok()
        {
            for (t, r) in t.iter_mut().zip(ranks) {
                *t = r as u16;
            }
        }
    }
}

/// [`DITHER_MASK_RANKS`] generated at first use.
#[cfg(any(feature = "lazy-tables", test))]
#[cfg_attr(all(test, not(feature = "lazy-tables")), allow(dead_code))]
static GENERATED_MASK: crate::lazy_table::LazyTable<BuiltinMask> =
    crate::lazy_table::LazyTable::new([0; 2 * 64 * 64]);

/// A pixel sampler that gives every pixel the same point set, the one `inner` gives pixel
/// (0, 0), toroidally shifted by the mask: dimension `d` of pixel `p` is
/// `frac(x_d + mask(p, d mod channels))`, so a two-channel mask gives each dimension pair its own
/// 2-D shift (Georgiev & Fajardo, "Blue-noise dithered sampling", SIGGRAPH 2016 Talks). Each
/// pixel's estimate has the error of the shared set, and the shifts make neighbouring pixels'
/// errors differ as the mask's values do: the error image is blue noise rather than a smooth
/// (correlated) or white one.
///
/// [`Sampler::report`] and [`Sampler::pixel_samples`] go to `inner` with the real pixel.
///
/// ```
/// use nyquist::sampler::{DitheredSampler, MaskView, Sampler, ZeroTwoSampler};
/// let mut s = DitheredSampler::new(ZeroTwoSampler::new(16, 0).unwrap(), MaskView::builtin());
/// let mut inner = ZeroTwoSampler::new(16, 0).unwrap();
/// s.start_pixel_sample([5, 9], 3, 0);
/// inner.start_pixel_sample([0, 0], 3, 0);
/// let (a, b) = (s.get_1d(), inner.get_1d());
/// let shift = MaskView::builtin().value(5, 9, 0);
/// assert!(((a - b - shift).rem_euclid(1.0)).min(1.0 - (a - b - shift).rem_euclid(1.0)) < 1e-6);
/// ```
#[derive(Clone, Debug)]
pub struct DitheredSampler<'m, S> {
    inner: S,
    mask: MaskView<'m>,
    pixel: [u32; 2],
    dim: u32,
}

impl<'m, S: Sampler> DitheredSampler<'m, S> {
    /// Dithers `inner` by `mask`.
    pub fn new(inner: S, mask: MaskView<'m>) -> DitheredSampler<'m, S> {
        DitheredSampler {
            inner,
            mask,
            pixel: [0; 2],
            dim: 0,
        }
    }

    /// The wrapped sampler.
    pub fn inner(&self) -> &S {
        &self.inner
    }

    /// The mask.
    pub fn mask(&self) -> MaskView<'m> {
        self.mask
    }

    /// `frac(x + shift of dimension d at the current pixel)`.
    #[inline]
    fn shift(&self, x: f32, d: u32) -> f32 {
        let s = x + self.mask.value(self.pixel[0], self.pixel[1], d);
        let s = if s >= 1.0 { s - 1.0 } else { s };
        s.clamp(0.0, ONE_MINUS_EPSILON)
    }
}

impl<S: Sampler> Sampler for DitheredSampler<'_, S> {
    fn samples_per_pixel(&self) -> u32 {
        self.inner.samples_per_pixel()
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        self.pixel = pixel;
        self.dim = dim;
        self.inner.start_pixel_sample([0, 0], sample_index, dim);
    }

    fn get_1d(&mut self) -> f32 {
        let d = self.dim;
        self.dim = d.wrapping_add(1);
        let x = self.inner.get_1d();
        self.shift(x, d)
    }

    fn get_2d(&mut self) -> [f32; 2] {
        let d = self.dim;
        self.dim = d.wrapping_add(2);
        let [u, v] = self.inner.get_2d();
        [self.shift(u, d), self.shift(v, d.wrapping_add(1))]
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        let [u, v] = self.inner.get_pixel_2d();
        [self.shift(u, 0), self.shift(v, 1)]
    }

    fn round_size(&self, n: u32) -> u32 {
        self.inner.round_size(n)
    }

    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        super::camera_sample_by_parts(self, pixel, sample_index)
    }

    fn pixel_samples(&self, pixel: [u32; 2]) -> u32 {
        self.inner.pixel_samples(pixel)
    }

    fn report(&mut self, pixel: [u32; 2], sample_index: u32, radiance: &[f32]) {
        self.inner.report(pixel, sample_index, radiance);
    }
}

#[cfg(test)]
mod tests;
