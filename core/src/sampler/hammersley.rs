//! One Hammersley set over the whole image.

use super::Sampler;
use crate::Error;
use crate::math::clamp_unit;
use crate::radical::{
    fast_owen_scrambled_radical_inverse, owen_scrambled_radical_inverse, radical_inverse,
    scrambled_radical_inverse,
};
use crate::scramble::Scramble;

/// Hammersley sampling over the whole image: the `N = width · H · spp` points of one Hammersley
/// set `((k + ½)/N, Φ₂(k), Φ₃(k), Φ₅(k), …)`, scaled to `width × H` pixels, where
/// `H = 2^j ≥ height` pads the height to a power of two.
///
/// Sample `s` of pixel `(px, py)` is point `k = px · H · spp + rev_j(py) + s · 2^j`
/// (`rev_j` reverses `j` bits). Because `Φ₂(k) · 2^j = rev_j(k mod 2^j) + Φ₂(k >> j)` and
/// `k mod 2^j = rev_j(py)`, its film position
/// `(px + (rev_j(py) + s·2^j + ½) / (H·spp), py + Φ₂(k >> j))` lies in the pixel, and
/// `(px, py, s) ↦ k` is a bijection onto `0..N`: the pixels' samples together are exactly the
/// Hammersley set (the rows `py ≥ height` of the padding are never asked for).
///
/// Dimension `2 ≤ d < 1024` is `Φ_{prime(d − 1)}(k)` (base 3, 5, …), scrambled under `seed` by
/// the [`Scramble`] chosen (as the Halton sampler's dimensions are;
/// dimensions 0 and 1 are never scrambled: they place the sample in its pixel). Dimensions from
/// 1024 on are padding (Burley 2020, §6): independently seeded Owen-scrambled 4-D blocks of the
/// sample's number in its pixel, keyed by the pixel and the seed. `sample_index >= spp` wraps
/// modulo `spp`,
/// `px >= width` modulo `width` and `py` modulo `H`, so every pixel argument addresses a point of
/// the set. Index arithmetic is `u64` (`N` reaches 2⁴⁴ at 16384² pixels × 65536 spp);
/// [`HammersleySampler::new`] refuses sizes whose `N` would not fit.
///
/// ```
/// use nyquist::{sampler::{HammersleySampler, Sampler}, scramble::Scramble};
/// let mut s = HammersleySampler::new([4, 4], 2, Scramble::Owen, 9).unwrap();
/// s.start_pixel_sample([2, 3], 1, 0);
/// let [x, y] = s.get_pixel_2d();
/// assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
/// ```
#[derive(Clone, Debug)]
pub struct HammersleySampler {
    spp: u32,
    scramble: Scramble,
    seed: u64,
    j: u32,
    /// Image width in pixels (`px` wraps modulo it).
    width: u32,
    /// `H · spp`: points per pixel column.
    column: u64,
    k: u64,
    film_x: f32,
    dim: u32,
}

impl HammersleySampler {
    /// A Hammersley sampler for an image of `resolution` pixels, its dimensions ≥ 2 scrambled
    /// by `scramble` under `seed` ([`Scramble::None`]: the plain set; the seed is then
    /// ignored).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0; [`Error::TooMany`] if the
    /// point count `N = width · H · spp` does not fit a `u64` (`max` is the largest width that
    /// fits with this `H · spp`).
    ///
    /// ```
    /// use nyquist::{sampler::HammersleySampler, scramble::Scramble, Error};
    /// assert!(HammersleySampler::new([4, 0], 1, Scramble::None, 0).is_err());
    /// assert_eq!(
    ///     HammersleySampler::new([u32::MAX, u32::MAX], u32::MAX, Scramble::None, 0).err(),
    ///     Some(Error::TooMany {
    ///         what: "width (at this height and spp)",
    ///         value: u32::MAX.into(),
    ///         max: 1
    ///     })
    /// );
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
        super::check_image(resolution, spp)?;
        let j = 32 - (resolution[1] - 1).leading_zeros();
        let column = (1u64 << j) * u64::from(spp);
        column
            .checked_mul(u64::from(resolution[0]))
            .ok_or(Error::TooMany {
                what: "width (at this height and spp)",
                value: u64::from(resolution[0]),
                max: u64::MAX / column,
            })?;
        Ok(Self {
            spp,
            scramble,
            seed,
            j,
            width: resolution[0],
            column,
            k: 0,
            film_x: 0.0,
            dim: 0,
        })
    }

    /// The Hammersley index `k` of sample `sample_index` (modulo spp) of `pixel`; `pixel[1]`
    /// wraps modulo `2^j`.
    ///
    /// ```
    /// use nyquist::{sampler::HammersleySampler, scramble::Scramble};
    /// let s = HammersleySampler::new([2, 2], 1, Scramble::None, 0).unwrap();
    /// // H = 2: pixel (0, 1) takes k = rev₁(1) = 1; pixel (1, 0) takes k = 2.
    /// assert_eq!(s.point_index([0, 1], 0), 1);
    /// assert_eq!(s.point_index([1, 0], 0), 2);
    /// ```
    pub fn point_index(&self, pixel: [u32; 2], sample_index: u32) -> u64 {
        u64::from(pixel[0] % self.width) * self.column + self.row_offset(pixel[1], sample_index)
    }

    fn row_offset(&self, py: u32, sample_index: u32) -> u64 {
        let rev = if self.j == 0 {
            0
        } else {
            u64::from(py.reverse_bits() >> (32 - self.j))
        };
        rev + (u64::from(sample_index % self.spp) << self.j)
    }

    #[inline]
    fn sample(&self, dim: u32) -> f32 {
        match dim {
            0 => self.film_x,
            1 => radical_inverse(0, self.k >> self.j),
            1024.. => self.padded(dim),
            _ => {
                let d = dim - 1;
                match self.scramble {
                    Scramble::None => radical_inverse(d, self.k),
                    Scramble::PermuteDigits => scrambled_radical_inverse(d, self.k, self.seed),
                    Scramble::FastOwen => fast_owen_scrambled_radical_inverse(d, self.k, self.seed),
                    Scramble::Owen => owen_scrambled_radical_inverse(d, self.k, self.seed),
                }
            }
        }
    }
}

impl HammersleySampler {
    /// A padding dimension (`dim >= 1024`) of the current sample: the pixel is the point's
    /// index without its sample bits, the sample its number in the pixel.
    #[inline(never)]
    fn padded(&self, dim: u32) -> f32 {
        // k = px·column + rev_j(py) + s·2^j with rev_j(py) < 2^j and s·2^j < column.
        let s = (self.k % self.column) >> self.j;
        let key = super::padding_key(self.k - (s << self.j), self.seed);
        crate::math::fraction_to_f32(crate::sequence::padded_u32(key, s, dim))
    }
}

impl Sampler for HammersleySampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        let r = self.row_offset(pixel[1], sample_index);
        self.k = u64::from(pixel[0] % self.width) * self.column + r;
        self.film_x = clamp_unit(((r as f64 + 0.5) / self.column as f64) as f32);
        self.dim = dim;
    }

    super::global_point_dimensions!();

    /// The default arrays: one dimension per value.
    fn arrays_are_dimension_runs(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dimensions past 1024: padding, per pixel (repeated where the pixels repeat).
    #[test]
    fn dimensions_past_1024_are_padded_per_pixel() {
        for scramble in Scramble::ALL {
            let mut s = HammersleySampler::new([20, 10], 64, scramble, 7).unwrap();
            crate::sampler::tests::padding_holds(&mut s, [5, 6], [6, 6], [25, 6], 64);
        }
    }

    /// Found by the fuzzer: pixels past the width overflowed the index; they wrap now.
    #[test]
    fn pixels_past_the_width_wrap_instead_of_overflowing() {
        let mut s = HammersleySampler::new([17, 421_068_800], 47, Scramble::None, 0).unwrap();
        s.start_pixel_sample([1_465_358_105, 0], 3, 0);
        let a = s.get_pixel_2d();
        s.start_pixel_sample([1_465_358_105 % 17, 0], 3, 0);
        assert_eq!(s.get_pixel_2d(), a);
        assert_eq!(s.point_index([17 + 2, 5], 1), s.point_index([2, 5], 1));
    }
    use crate::sampler::tests::{consistent_values, threads_agree};

    /// Each scramble reaches dimensions ≥ 2 only, through the radical inverse of that
    /// scramble (base 3 for dimension 2); dimensions 0 and 1 keep the sample in its pixel.
    #[test]
    fn scrambles_reach_the_dimensions_above_the_pixel_only() {
        let (pixel, i, seed) = ([3, 5], 2, 11);
        let mut plain = HammersleySampler::new([8, 8], 4, Scramble::None, seed).unwrap();
        plain.start_pixel_sample(pixel, i, 0);
        let offset = plain.get_pixel_2d();
        let k = plain.point_index(pixel, i);
        let mut dim2 = std::vec::Vec::new();
        for scramble in Scramble::ALL {
            let mut s = HammersleySampler::new([8, 8], 4, scramble, seed).unwrap();
            s.start_pixel_sample(pixel, i, 0);
            assert_eq!(s.get_pixel_2d(), offset, "{scramble:?}");
            let v = s.get_1d();
            let want = match scramble {
                Scramble::None => radical_inverse(1, k),
                Scramble::PermuteDigits => scrambled_radical_inverse(1, k, seed),
                Scramble::FastOwen => fast_owen_scrambled_radical_inverse(1, k, seed),
                Scramble::Owen => owen_scrambled_radical_inverse(1, k, seed),
            };
            assert_eq!(v, want, "{scramble:?}");
            dim2.push(v.to_bits());
        }
        dim2.sort_unstable();
        dim2.dedup();
        assert_eq!(dim2.len(), 4, "four scrambles, four values");
    }

    #[test]
    fn hammersley_is_consistent_and_thread_independent() {
        for scramble in Scramble::ALL {
            let s = HammersleySampler::new([20, 30], 8, scramble, 3).unwrap();
            consistent_values(&s);
            threads_agree(&s);
        }
    }

    #[test]
    fn hammersley_samples_land_in_their_pixel_and_form_the_whole_set() {
        let (w, h, spp) = (5u32, 8u32, 4u32);
        let n = u64::from(w * h * spp);
        let mut s = HammersleySampler::new([w, h], spp, Scramble::None, 0).unwrap();
        let mut hit = std::vec![false; n as usize];
        for py in 0..h {
            for px in 0..w {
                for i in 0..spp {
                    let k = s.point_index([px, py], i);
                    assert!(!core::mem::replace(&mut hit[k as usize], true));
                    let c = crate::sampler::camera_sample(&mut s, [px, py], i);
                    // The Hammersley point k of N, scaled to the image.
                    let gx = (k as f64 + 0.5) / n as f64 * f64::from(w);
                    let gy = f64::from(radical_inverse(0, k)) * f64::from(h);
                    assert!((f64::from(c.p_film[0]) - gx).abs() < 1e-5, "{px} {py} {i}");
                    assert!((f64::from(c.p_film[1]) - gy).abs() < 1e-5, "{px} {py} {i}");
                    assert!(c.p_film[0] >= px as f32 && c.p_film[0] < (px + 1) as f32);
                    assert!(c.p_film[1] >= py as f32 && c.p_film[1] < (py + 1) as f32);
                    assert_eq!(c.time, radical_inverse(1, k));
                }
            }
        }
        assert!(hit.iter().all(|&b| b));
    }

    #[test]
    fn hammersley_huge_image_corner() {
        let mut s =
            HammersleySampler::new([16384, 16384], 65536, Scramble::PermuteDigits, 1).unwrap();
        let r = crate::sampler::tests::record(&mut s, [16383, 16383], 65535);
        assert!(r.iter().all(|x| (0.0..1.0).contains(x)));
        assert_eq!(s.point_index([16383, 16383], 65535), (1u64 << 44) - 1);
    }
}
