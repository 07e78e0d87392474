//! The request-and-fill layer (pbrt-v2's `Sample`, `Add1D`/`Add2D`, `RoundSize`,
//! `GetNextSample`, `TotalSamples`, `GetSubSampler`), without a heap.
//!
//! An integrator adds its array requests to a fixed-capacity [`SampleLayout`]; a [`Sample`] is a
//! view over a caller buffer of [`SampleLayout::len`] floats; a [`PixelRangeSampler`] walks a
//! pixel range and fills one `Sample` per call of [`PixelRangeSampler::next_sample`].
//!
//! Buffer layout of a `Sample` (one documented layout, as png does):
//! `[film x, film y, lens u, lens v, time, array 0…, array 1…, …]` where a 1D array of `n`
//! values takes `n` floats and a 2D array of `n` points takes `2n` floats (`[u0, v0, u1, …]`),
//! in the order the requests were added.
//!
//! No sampler here needs per-pixel scratch memory: stratified and Latin-hypercube arrays and the
//! per-pixel permutations are hash-derived and computed in place in the `Sample` buffer.

use super::{Sampler, camera_sample};
use crate::Error;

/// Floats of a [`Sample`] before the arrays: film x, y, lens u, v, time.
///
/// ```
/// assert_eq!(nyquist::sampler::SampleLayout::<0>::new().len(), nyquist::sampler::layout::CAMERA_LEN);
/// ```
pub const CAMERA_LEN: usize = 5;

/// One array request in a [`SampleLayout`].
///
/// ```
/// use nyquist::sampler::{layout::ArrayRequest, RandomSampler, SampleLayout};
/// let mut l = SampleLayout::<2>::new();
/// l.add_2d(&RandomSampler::new(1, 0).unwrap(), 3).unwrap();
/// assert_eq!(l.requests()[0], ArrayRequest { dims: 2, count: 3, offset: 5 });
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ArrayRequest {
    /// 1 or 2.
    pub dims: u32,
    /// Values (1D) or points (2D), after the sampler's rounding.
    pub count: u32,
    /// Index of the array's first float in the `Sample` buffer.
    pub offset: usize,
}

impl ArrayRequest {
    /// Floats the array takes: `count × dims`.
    ///
    /// ```
    /// use nyquist::sampler::layout::ArrayRequest;
    /// assert_eq!(ArrayRequest { dims: 2, count: 3, offset: 5 }.len(), 6);
    /// ```
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.count as usize * self.dims as usize
    }
}

/// The arrays an integrator requests per sample, at most `N` of them (heapless).
///
/// ```
/// use nyquist::sampler::{RandomSampler, SampleLayout};
/// let s = RandomSampler::new(4, 0).unwrap();
/// let mut layout = SampleLayout::<4>::new();
/// let light = layout.add_2d(&s, 4).unwrap();
/// let bsdf = layout.add_1d(&s, 3).unwrap();
/// assert_eq!((light, bsdf), (0, 1));
/// assert_eq!(layout.len(), 5 + 8 + 3);
/// ```
#[derive(Clone, Debug, Default)]
pub struct SampleLayout<const N: usize> {
    requests: heapless::Vec<ArrayRequest, N>,
    len: usize,
}

impl<const N: usize> SampleLayout<N> {
    /// An empty layout: only the camera sample.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::SampleLayout::<0>::new().len(), 5);
    /// ```
    pub const fn new() -> Self {
        Self {
            requests: heapless::Vec::new(),
            len: CAMERA_LEN,
        }
    }

    /// Requests an array of `n` 1D values per sample, rounded by `sampler`'s
    /// [`Sampler::round_size`]. Returns the array's handle for [`Sample::array_1d`].
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `n == 0`; [`Error::TooMany`] if the layout already holds `N`
    /// arrays (`what: "array requests"`, `max: N`) or its length would overflow `usize`
    /// (`what: "array length"`, the room left as `max`).
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, SampleLayout};
    /// let mut l = SampleLayout::<1>::new();
    /// let s = RandomSampler::new(1, 0).unwrap();
    /// assert_eq!(l.add_1d(&s, 2), Ok(0));
    /// assert!(l.add_1d(&s, 2).is_err()); // full
    /// ```
    pub fn add_1d<S: Sampler + ?Sized>(&mut self, sampler: &S, n: u32) -> Result<usize, Error> {
        self.add(1, sampler, n)
    }

    /// Requests an array of `n` 2D points per sample, rounded by `sampler`'s
    /// [`Sampler::round_size`]. Returns the array's handle for [`Sample::array_2d`].
    ///
    /// # Errors
    /// As [`SampleLayout::add_1d`].
    ///
    /// ```
    /// use nyquist::sampler::{RandomSampler, SampleLayout};
    /// let mut l = SampleLayout::<1>::new();
    /// l.add_2d(&RandomSampler::new(1, 0).unwrap(), 7).unwrap();
    /// assert_eq!(l.len(), 5 + 14);
    /// ```
    pub fn add_2d<S: Sampler + ?Sized>(&mut self, sampler: &S, n: u32) -> Result<usize, Error> {
        self.add(2, sampler, n)
    }

    fn add<S: Sampler + ?Sized>(&mut self, dims: u32, sampler: &S, n: u32) -> Result<usize, Error> {
        if n == 0 {
            return Err(Error::ZeroSize { what: "array size" });
        }
        let count = sampler.round_size(n).max(1);
        let request = ArrayRequest {
            dims,
            count,
            offset: self.len,
        };
        let len = self.len.checked_add(request.len()).ok_or(Error::TooMany {
            what: "array length",
            value: request.len() as u64,
            max: (usize::MAX - self.len) as u64,
        })?;
        let handle = self.requests.len();
        self.requests.push(request).map_err(|_| Error::TooMany {
            what: "array requests",
            value: N as u64 + 1,
            max: N as u64,
        })?;
        self.len = len;
        Ok(handle)
    }

    /// Floats one [`Sample`] needs: 5 + Σ 1D counts + 2 × Σ 2D counts.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::SampleLayout::<3>::new().len(), 5);
    /// ```
    #[allow(clippy::len_without_is_empty)]
    pub fn len(&self) -> usize {
        self.len
    }

    /// The requests, in the order they were added.
    ///
    /// ```
    /// assert!(nyquist::sampler::SampleLayout::<3>::new().requests().is_empty());
    /// ```
    pub fn requests(&self) -> &[ArrayRequest] {
        &self.requests
    }
}

/// One pixel sample's values: a view over a caller buffer laid out by a [`SampleLayout`].
///
/// ```
/// use nyquist::sampler::{Sample, SampleLayout};
/// let layout = SampleLayout::<0>::new();
/// let mut buf = [0.0f32; 5];
/// let s = Sample::new(&layout, &mut buf).unwrap();
/// assert_eq!(s.time(), 0.0);
/// let mut short = [0.0f32; 4];
/// assert!(Sample::new(&layout, &mut short).is_err());
/// ```
#[derive(Debug)]
pub struct Sample<'a> {
    requests: &'a [ArrayRequest],
    buf: &'a mut [f32],
    pixel: [u32; 2],
    index: u32,
}

impl<'a> Sample<'a> {
    /// A view over `buf` laid out by `layout`; only the first `layout.len()` floats are used.
    ///
    /// # Errors
    /// [`Error::BufferTooShort`] if `buf.len() < layout.len()`.
    ///
    /// ```
    /// use nyquist::{sampler::{Sample, SampleLayout}, Error};
    /// let layout = SampleLayout::<0>::new();
    /// assert_eq!(
    ///     Sample::new(&layout, &mut [0.0; 2]).unwrap_err(),
    ///     Error::BufferTooShort { needed: 5, actual: 2 }
    /// );
    /// ```
    pub fn new<const N: usize>(
        layout: &'a SampleLayout<N>,
        buf: &'a mut [f32],
    ) -> Result<Self, Error> {
        if buf.len() < layout.len() {
            return Err(Error::BufferTooShort {
                needed: layout.len(),
                actual: buf.len(),
            });
        }
        Ok(Self {
            requests: layout.requests(),
            buf: &mut buf[..layout.len()],
            pixel: [0; 2],
            index: 0,
        })
    }

    /// Film position in pixels (pixel corner + image sample).
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// let mut buf = [1.5, 2.5, 0.0, 0.0, 0.0];
    /// assert_eq!(Sample::new(&layout, &mut buf).unwrap().image(), [1.5, 2.5]);
    /// ```
    pub fn image(&self) -> [f32; 2] {
        [self.buf[0], self.buf[1]]
    }

    /// Lens position in `[0, 1)²`.
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// let mut buf = [0.0, 0.0, 0.25, 0.5, 0.0];
    /// assert_eq!(Sample::new(&layout, &mut buf).unwrap().lens(), [0.25, 0.5]);
    /// ```
    pub fn lens(&self) -> [f32; 2] {
        [self.buf[2], self.buf[3]]
    }

    /// Time in `[0, 1)`.
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// let mut buf = [0.0, 0.0, 0.0, 0.0, 0.75];
    /// assert_eq!(Sample::new(&layout, &mut buf).unwrap().time(), 0.75);
    /// ```
    pub fn time(&self) -> f32 {
        self.buf[4]
    }

    /// The pixel this sample belongs to (set by [`PixelRangeSampler::next_sample`]).
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// assert_eq!(Sample::new(&layout, &mut [0.0; 5]).unwrap().pixel(), [0, 0]);
    /// ```
    pub fn pixel(&self) -> [u32; 2] {
        self.pixel
    }

    /// The sample's index inside its pixel.
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// assert_eq!(Sample::new(&layout, &mut [0.0; 5]).unwrap().sample_index(), 0);
    /// ```
    pub fn sample_index(&self) -> u32 {
        self.index
    }

    /// 1D array `handle` (from [`SampleLayout::add_1d`]). Total: an unknown handle, or a 2D
    /// array's, gives the empty slice.
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// assert!(Sample::new(&layout, &mut [0.0; 5]).unwrap().array_1d(0).is_empty());
    /// ```
    pub fn array_1d(&self, handle: usize) -> &[f32] {
        self.array(handle, 1)
    }

    /// 2D array `handle` as pairs `[u0, v0, u1, v1, …]` (from [`SampleLayout::add_2d`]).
    /// Total: an unknown handle, or a 1D array's, gives the empty slice.
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler, Sample, SampleLayout};
    /// let s = RandomSampler::new(1, 0).unwrap();
    /// let mut layout = SampleLayout::<1>::new();
    /// let h = layout.add_2d(&s, 3).unwrap();
    /// let mut buf = vec![0.0; layout.len()];
    /// let mut sample = Sample::new(&layout, &mut buf).unwrap();
    /// let mut range = PixelRangeSampler::new(s, [0, 0], [1, 1]).unwrap();
    /// assert!(range.next_sample(&mut sample));
    /// assert_eq!(sample.array_2d(h).len(), 6);
    /// ```
    pub fn array_2d(&self, handle: usize) -> &[f32] {
        self.array(handle, 2)
    }

    fn array(&self, handle: usize, dims: u32) -> &[f32] {
        match self.requests.get(handle) {
            Some(r) if r.dims == dims => &self.buf[r.offset..r.offset + r.len()],
            _ => &[],
        }
    }

    /// The whole buffer in the documented layout.
    ///
    /// ```
    /// # use nyquist::sampler::{Sample, SampleLayout};
    /// # let layout = SampleLayout::<0>::new();
    /// assert_eq!(Sample::new(&layout, &mut [0.0; 9]).unwrap().as_slice().len(), 5);
    /// ```
    pub fn as_slice(&self) -> &[f32] {
        self.buf
    }
}

/// Walks the pixels `[x0, x1) × [y0, y1)` row by row and fills one [`Sample`] per call with
/// [`Sampler::pixel_samples`] samples per pixel (pbrt-v2's `GetNextSample`).
///
/// The values come from the stateless [`Sampler`] layer, so a range split into sub-samplers
/// ([`PixelRangeSampler::sub_sampler`]) and run on any number of threads produces the very same
/// values as the whole range. Arrays are filled in request order from dimension 5 on: a 1D
/// array by [`Sampler::get_array_1d`], a 2D array by [`Sampler::get_array_2d`].
///
/// ```
/// use nyquist::sampler::{Jitter, PixelRangeSampler, Sample, SampleLayout, StratifiedSampler};
/// let s = StratifiedSampler::new(2, 2, Jitter::Jittered, 1).unwrap();
/// let layout = SampleLayout::<0>::new();
/// let mut buf = [0.0f32; 5];
/// let mut sample = Sample::new(&layout, &mut buf).unwrap();
/// let mut range = PixelRangeSampler::new(s, [0, 0], [3, 2]).unwrap();
/// assert_eq!(range.total_samples(), 24);
/// let mut n = 0;
/// while range.next_sample(&mut sample) {
///     n += 1;
/// }
/// assert_eq!(n, 24);
/// ```
#[derive(Clone, Debug)]
pub struct PixelRangeSampler<S> {
    sampler: S,
    start: [u32; 2],
    end: [u32; 2],
    pixel: [u32; 2],
    index: u32,
    done: bool,
}

impl<S: Sampler> PixelRangeSampler<S> {
    /// A sampler over the pixels `[start[0], end[0]) × [start[1], end[1])`.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if the range is empty.
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler};
    /// let s = RandomSampler::new(1, 0).unwrap();
    /// assert!(PixelRangeSampler::new(s, [4, 0], [4, 9]).is_err());
    /// ```
    pub fn new(sampler: S, start: [u32; 2], end: [u32; 2]) -> Result<Self, Error> {
        if start[0] >= end[0] || start[1] >= end[1] {
            return Err(Error::ZeroSize {
                what: "pixel range",
            });
        }
        Ok(Self {
            sampler,
            start,
            end,
            pixel: start,
            index: 0,
            done: false,
        })
    }

    /// Pixels × samples per pixel (for adaptive samplers, the most it can take).
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler};
    /// let r = PixelRangeSampler::new(RandomSampler::new(3, 0).unwrap(), [0, 0], [2, 2]).unwrap();
    /// assert_eq!(r.total_samples(), 12);
    /// ```
    pub fn total_samples(&self) -> u64 {
        u64::from(self.end[0] - self.start[0])
            * u64::from(self.end[1] - self.start[1])
            * u64::from(self.sampler.samples_per_pixel())
    }

    /// The pixel range `(start, end)`.
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler};
    /// let r = PixelRangeSampler::new(RandomSampler::new(3, 0).unwrap(), [1, 2], [3, 4]).unwrap();
    /// assert_eq!(r.range(), ([1, 2], [3, 4]));
    /// ```
    pub fn range(&self) -> ([u32; 2], [u32; 2]) {
        (self.start, self.end)
    }

    /// The wrapped sampler.
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler, Sampler};
    /// let r = PixelRangeSampler::new(RandomSampler::new(3, 0).unwrap(), [0, 0], [1, 1]).unwrap();
    /// assert_eq!(r.sampler().samples_per_pixel(), 3);
    /// ```
    pub fn sampler(&self) -> &S {
        &self.sampler
    }

    /// Fills `sample` with the next pixel sample; `false` (and `sample` untouched) once the
    /// range is exhausted.
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler, Sample, SampleLayout};
    /// let layout = SampleLayout::<0>::new();
    /// let mut buf = [0.0f32; 5];
    /// let mut sample = Sample::new(&layout, &mut buf).unwrap();
    /// let mut r = PixelRangeSampler::new(RandomSampler::new(1, 0).unwrap(), [7, 8], [8, 9]).unwrap();
    /// assert!(r.next_sample(&mut sample));
    /// assert_eq!(sample.pixel(), [7, 8]);
    /// assert!(sample.image()[0] >= 7.0 && sample.image()[0] < 8.0);
    /// assert!(!r.next_sample(&mut sample));
    /// ```
    pub fn next_sample(&mut self, sample: &mut Sample<'_>) -> bool {
        if self.done {
            return false;
        }
        // A pixel may take no samples at all (a sampler's `pixel_samples` can return 0).
        while self.index >= self.sampler.pixel_samples(self.pixel) {
            self.index = 0;
            self.pixel[0] += 1;
            if self.pixel[0] >= self.end[0] {
                self.pixel[0] = self.start[0];
                self.pixel[1] += 1;
                if self.pixel[1] >= self.end[1] {
                    self.done = true;
                    return false;
                }
            }
        }
        let c = camera_sample(&mut self.sampler, self.pixel, self.index);
        sample.buf[..CAMERA_LEN].copy_from_slice(&[
            c.p_film[0],
            c.p_film[1],
            c.lens[0],
            c.lens[1],
            c.time,
        ]);
        match sample.requests.last() {
            // The layout's arrays follow the camera sample back to back, each 2D one of even
            // length: for such a sampler one run of dimensions fills them all.
            Some(last) if self.sampler.arrays_are_dimension_runs() => {
                let end = last.offset + last.len();
                self.sampler.get_array_1d(&mut sample.buf[CAMERA_LEN..end]);
            }
            _ => {
                for r in sample.requests {
                    let out = &mut sample.buf[r.offset..r.offset + r.len()];
                    if r.dims == 1 {
                        self.sampler.get_array_1d(out);
                    } else {
                        self.sampler.get_array_2d(out);
                    }
                }
            }
        }
        sample.pixel = self.pixel;
        sample.index = self.index;
        self.index += 1;
        true
    }

    /// Reports the radiance of the sample last filled (adaptive samplers use it to decide how
    /// many samples the pixel takes; others ignore it).
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler, Sample, SampleLayout};
    /// let layout = SampleLayout::<0>::new();
    /// let mut buf = [0.0f32; 5];
    /// let mut sample = Sample::new(&layout, &mut buf).unwrap();
    /// let mut r = PixelRangeSampler::new(RandomSampler::new(1, 0).unwrap(), [0, 0], [1, 1]).unwrap();
    /// r.next_sample(&mut sample);
    /// r.report(&[0.5, 0.5, 0.5]);
    /// assert!(!r.next_sample(&mut sample));
    /// ```
    pub fn report(&mut self, radiance: &[f32]) {
        if let Some(last) = self.index.checked_sub(1) {
            self.sampler.report(self.pixel, last, radiance);
        }
    }
}

impl<S: Sampler + Clone> PixelRangeSampler<S> {
    /// Sub-sampler `i` of `count` for tiles: the range split into `count` bands of whole rows
    /// (the first `rows % count` bands one row taller). `None` if `i >= count` or band `i` is
    /// empty (more bands than rows). The union of all bands' samples is this range's samples,
    /// bit for bit.
    ///
    /// ```
    /// use nyquist::sampler::{PixelRangeSampler, RandomSampler};
    /// let r = PixelRangeSampler::new(RandomSampler::new(1, 0).unwrap(), [0, 0], [4, 5]).unwrap();
    /// let bands: Vec<_> = (0..2).map(|i| r.sub_sampler(i, 2).unwrap().range()).collect();
    /// assert_eq!(bands, [([0, 0], [4, 3]), ([0, 3], [4, 5])]);
    /// assert!(r.sub_sampler(5, 6).is_none());
    /// ```
    pub fn sub_sampler(&self, i: u32, count: u32) -> Option<Self> {
        if i >= count {
            return None;
        }
        let rows = self.end[1] - self.start[1];
        let (base, extra) = (rows / count, rows % count);
        let y0 = self.start[1] + i * base + i.min(extra);
        let y1 = y0 + base + u32::from(i < extra);
        Self::new(self.sampler.clone(), [self.start[0], y0], [self.end[0], y1]).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::{Jitter, RandomSampler, StratifiedSampler};
    use std::vec::Vec;

    /// A sampler that rounds array sizes to a power of two, to check the layout uses rounding.
    #[derive(Clone, Debug)]
    struct Pow2(RandomSampler);
    impl Sampler for Pow2 {
        fn samples_per_pixel(&self) -> u32 {
            self.0.samples_per_pixel()
        }
        fn start_pixel_sample(&mut self, p: [u32; 2], i: u32, d: u32) {
            self.0.start_pixel_sample(p, i, d)
        }
        fn get_1d(&mut self) -> f32 {
            self.0.get_1d()
        }
        fn get_2d(&mut self) -> [f32; 2] {
            self.0.get_2d()
        }
        fn get_pixel_2d(&mut self) -> [f32; 2] {
            self.0.get_pixel_2d()
        }
        fn round_size(&self, n: u32) -> u32 {
            n.checked_next_power_of_two().unwrap_or(1 << 31)
        }
    }

    #[test]
    fn layout_rounds_requests_and_its_length_is_exact() {
        let s = Pow2(RandomSampler::new(4, 0).unwrap());
        let mut l = SampleLayout::<4>::new();
        let a = l.add_2d(&s, 7).unwrap();
        let b = l.add_1d(&s, 3).unwrap();
        let c = l.add_2d(&s, 1).unwrap();
        assert_eq!(l.len(), 5 + 2 * 8 + 4 + 2);
        let mut buf = std::vec![f32::NAN; l.len()];
        let mut sample = Sample::new(&l, &mut buf).unwrap();
        let mut r = PixelRangeSampler::new(s, [0, 0], [1, 1]).unwrap();
        assert!(r.next_sample(&mut sample));
        assert_eq!(sample.array_2d(a).len(), 16);
        assert_eq!(sample.array_1d(b).len(), 4);
        assert_eq!(sample.array_2d(c).len(), 2);
        assert!(sample.array_1d(a).is_empty() && sample.array_2d(9).is_empty());
        // Every float of the exact-length buffer was written, in [0, 1) except the film position.
        assert!(buf[2..].iter().all(|x| (0.0..1.0).contains(x)));
        // One float short is an error, not a panic.
        let mut short = std::vec![0.0; l.len() - 1];
        assert_eq!(
            Sample::new(&l, &mut short).unwrap_err(),
            Error::BufferTooShort {
                needed: l.len(),
                actual: l.len() - 1
            }
        );
    }

    #[test]
    fn layout_rejects_zero_and_overflowing_requests() {
        let s = RandomSampler::new(1, 0).unwrap();
        let mut l = SampleLayout::<2>::new();
        assert!(l.add_1d(&s, 0).is_err());
        l.add_2d(&s, 5).unwrap();
        l.add_2d(&s, 5).unwrap();
        assert_eq!(
            l.add_1d(&s, 1),
            Err(Error::TooMany {
                what: "array requests",
                value: 3,
                max: 2
            })
        );
        assert_eq!(l.len(), 25);
    }

    fn collect<S: Sampler>(mut r: PixelRangeSampler<S>, layout: &SampleLayout<2>) -> Vec<Vec<u32>> {
        let mut buf = std::vec![0.0; layout.len()];
        let mut sample = Sample::new(layout, &mut buf).unwrap();
        let mut out = Vec::new();
        while r.next_sample(&mut sample) {
            let mut v: Vec<u32> = sample.as_slice().iter().map(|x| x.to_bits()).collect();
            v.push(sample.pixel()[0]);
            v.push(sample.pixel()[1]);
            out.push(v);
        }
        out
    }

    #[test]
    fn sub_samplers_cover_the_range_with_identical_values() {
        let s = StratifiedSampler::new(2, 2, Jitter::Jittered, 3).unwrap();
        let mut layout = SampleLayout::<2>::new();
        layout.add_2d(&s, 4).unwrap();
        layout.add_1d(&s, 3).unwrap();
        let whole = PixelRangeSampler::new(s, [2, 1], [7, 8]).unwrap();
        let all = collect(whole.clone(), &layout);
        assert_eq!(all.len() as u64, whole.total_samples());
        for count in [1u32, 2, 3, 7, 9] {
            let mut parts = Vec::new();
            let mut total = 0;
            for i in 0..count {
                if let Some(sub) = whole.sub_sampler(i, count) {
                    total += sub.total_samples();
                    parts.extend(collect(sub, &layout));
                }
            }
            assert_eq!(total, whole.total_samples(), "count {count}");
            assert_eq!(parts, all, "count {count}");
        }
    }

    /// The request-and-fill layer gives, for every sampler, exactly the values of the stateless
    /// layer taken request by request — whether or not it fills the arrays as one run of
    /// dimensions ([`Sampler::arrays_are_dimension_runs`]).
    #[test]
    fn filled_samples_equal_requests_taken_one_by_one() {
        use crate::sampler::{NAMES, NamedSampler};
        let mut runs = 0;
        for name in NAMES {
            let s = NamedSampler::new(name, [40, 30], 16, 3).unwrap();
            runs += usize::from(s.arrays_are_dimension_runs());
            let mut layout = SampleLayout::<4>::new();
            layout.add_1d(&s, 3).unwrap();
            layout.add_2d(&s, 4).unwrap();
            layout.add_2d(&s, 1).unwrap();
            layout.add_1d(&s, 2).unwrap();
            let mut buf = std::vec![0.0f32; layout.len()];
            let mut sample = Sample::new(&layout, &mut buf).unwrap();
            let mut r = PixelRangeSampler::new(s.clone(), [5, 6], [7, 8]).unwrap();
            let mut by_hand = s.clone();
            while r.next_sample(&mut sample) {
                let (p, i) = (sample.pixel(), sample.sample_index());
                let c = camera_sample(&mut by_hand, p, i);
                let mut want = std::vec![c.p_film[0], c.p_film[1], c.lens[0], c.lens[1], c.time];
                for req in layout.requests() {
                    let mut out = std::vec![0.0f32; req.len()];
                    if req.dims == 1 {
                        by_hand.get_array_1d(&mut out);
                    } else {
                        by_hand.get_array_2d(&mut out);
                    }
                    want.extend_from_slice(&out);
                }
                let got: Vec<u32> = sample.as_slice().iter().map(|x| x.to_bits()).collect();
                let want: Vec<u32> = want.iter().map(|x| x.to_bits()).collect();
                assert_eq!(got, want, "{name} pixel {p:?} sample {i}");
            }
        }
        // The global samplers and the random one take the single run.
        assert!(runs >= 5, "{runs}");
    }

    #[test]
    fn film_positions_stay_inside_their_pixel() {
        let s = RandomSampler::new(3, 1).unwrap();
        let layout = SampleLayout::<2>::new();
        for v in collect(PixelRangeSampler::new(s, [0, 0], [4, 4]).unwrap(), &layout) {
            let (x, y) = (f32::from_bits(v[0]), f32::from_bits(v[1]));
            let (px, py) = (v[v.len() - 2] as f32, v[v.len() - 1] as f32);
            assert!(x >= px && x < px + 1.0 && y >= py && y < py + 1.0);
        }
    }
}
