//! [`FilmSample`]: one sample with everything a film can take from it.

/// One sample for [`FilmTile::add`](crate::FilmTile::add) and [`Film::add`](crate::Film::add):
/// what [`FilmTile::add_sample`](crate::FilmTile::add_sample) takes, and what a film that keeps
/// [`PixelExtras`](crate::PixelExtras) needs beside it.
///
/// ```
/// use nyquist_film::FilmSample;
/// let albedo = [0.8, 0.7, 0.6];
/// let s = FilmSample { index: 5, channels: &albedo, ..FilmSample::new([1.5, 2.5], [1.0; 3], 1.0) };
/// assert_eq!((s.index, s.channels.len()), (5, 3));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmSample<'a> {
    /// Film position in pixels.
    pub p_film: [f32; 2],
    /// Radiance.
    pub rgb: [f32; 3],
    /// Sample weight (multiplies `rgb`, as in [`FilmTile::add_sample`](crate::FilmTile::add_sample)).
    pub weight: f32,
    /// The sample's index within its pixel: its half ([`sample_half`](crate::extras::sample_half))
    /// when the film keeps [`PixelExtras::halves`](crate::PixelExtras::halves).
    pub index: u64,
    /// The extra channels' values, exactly [`PixelExtras::channels`](crate::PixelExtras::channels)
    /// of them (a sample with another count, or a non-finite value, is rejected and counted).
    pub channels: &'a [f32],
}

impl FilmSample<'static> {
    /// A sample at `p_film` with radiance `rgb` and weight `weight`, index 0, no channels.
    ///
    /// ```
    /// let s = nyquist_film::FilmSample::new([0.5, 0.5], [1.0; 3], 2.0);
    /// assert_eq!((s.weight, s.index), (2.0, 0));
    /// ```
    pub fn new(p_film: [f32; 2], rgb: [f32; 3], weight: f32) -> FilmSample<'static> {
        FilmSample {
            p_film,
            rgb,
            weight,
            index: 0,
            channels: &[],
        }
    }
}
