//! pbrt-v3/v4's Halton sampler: one Halton sequence over the whole image.

use super::{CameraSample, Sampler, film_coordinate};
use crate::Error;
use crate::radical::{
    PermutedDigitGroups, fast_owen_scrambled_radical_inverse, inverse_radical_inverse,
    owen_scrambled_radical_inverse, radical_inverse_dims, radical_inverse_inlined,
    scrambled_radical_inverse,
};
use crate::scramble::Scramble;

/// The largest scale per axis: pixels repeat their sample pattern every 128 (x) and 243 (y)
/// pixels, as in pbrt.
const MAX_RESOLUTION: u32 = 128;

/// Extended Euclid: the inverse of `a` modulo `n` (`a`, `n` coprime, `n ≥ 1`).
fn mod_inverse(a: u64, n: u64) -> u64 {
    let (mut r0, mut r1) = (i128::from(n), i128::from(a % n));
    let (mut t0, mut t1) = (0i128, 1i128);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    t0.rem_euclid(i128::from(n)) as u64
}

/// Halton sampling over the whole image (pbrt-v3's `HaltonSampler`).
///
/// Dimension 0 and 1 of the Halton sequence are scaled by `2^j ≥ min(width, 128)` and
/// `3^k ≥ min(height, 128)`, so each pixel of a `2^j × 3^k` block owns every `(2^j·3^k)`-th
/// point. Sample `s` of pixel `p` is sequence index `idx = h(p) + s·2^j·3^k`, where `h(p)` is the
/// unique value modulo `2^j·3^k` whose last `j` base-2 digits reversed are `p.x mod 2^j` and last
/// `k` base-3 digits reversed are `p.y mod 3^k` (Chinese remainder theorem with inverses computed
/// at construction). The image sample is `(Φ₂(idx >> j), Φ₃(idx / 3^k))` — the exact fractional
/// part of the scaled radical inverses; dimension `2 ≤ d < 1024` is `Φ_{prime(d)}(idx)`.
/// Dimensions from 1024 on are padding (Burley 2020, §6): independently seeded Owen-scrambled
/// 4-D blocks of the pixel's sample index `s`, keyed by `h(p)` and the seed, so they are nets
/// inside each pixel and no dimension repeats a lower one.
///
/// Scrambling ([`Scramble`]) applies to every dimension. In dimensions 0 and 1 it
/// scrambles the in-pixel values `Φ₂(idx >> j)` and `Φ₃(idx / 3^k)`, the same way for every
/// pixel, so each pixel keeps its own samples (the pixel's digits are never touched) and the
/// samples of a pixel keep their strata: `Owen` and `FastOwen` are nested scrambles, which map
/// each interval `[c/bᵐ, (c + 1)/bᵐ)` onto one of the same size. A pixel's consecutive samples
/// step the in-pixel indices by `3^k` and `2^j`, so any `2ᵐ` (`3ᵐ`) consecutive samples of a
/// pixel fall one per `1/2ᵐ` (`1/3ᵐ`) column (row) of the pixel, scrambled or not.
///
/// All index arithmetic is `u64`: no overflow for any `u32` pixel and sample index. Every sample
/// index gives a new point (no wrap at `samples_per_pixel`).
///
/// **Pixels outside the image** are not an error: the samples depend on `p.x mod 2^j` and
/// `p.y mod 3^k` only ([`HaltonSampler::scales`]), so pixel `(x + 2^j, y)` repeats pixel
/// `(x, y)`'s samples, inside the image (when it is wider than `2^j`, past 128 pixels) and
/// outside it alike.
///
/// ```
/// use nyquist::scramble::Scramble;
/// use nyquist::sampler::{HaltonSampler, Sampler};
/// let mut s = HaltonSampler::new([64, 64], 16, Scramble::None, 0).unwrap();
/// // Pixel (0, 0), sample 0 is index 0: the origin.
/// s.start_pixel_sample([0, 0], 0, 0);
/// assert_eq!(s.get_pixel_2d(), [0.0, 0.0]);
/// ```
#[derive(Clone, Debug)]
pub struct HaltonSampler {
    spp: u32,
    scramble: Scramble,
    seed: u64,
    exponents: [u32; 2],
    scales: [u64; 2],
    stride: u64,
    /// `3^k · (3^k)⁻¹ mod 2^j` and `2^j · (2^j)⁻¹ mod 3^k`: the CRT basis.
    basis: [u64; 2],
    /// The last pixel started and its offset `h(p)`, cached across its samples.
    pixel: [u32; 2],
    offset: u64,
    index: u64,
    /// The indices dimensions 0 and 1 read, `index >> exponent₀` and `index / 3^exponent₁`:
    /// because the stride is a multiple of both scales they are `offset`'s plus the sample
    /// index times `steps`, so no division runs per sample.
    axis_index: [u64; 2],
    axis_base: [u64; 2],
    steps: [u64; 2],
    dim: u32,
    /// `PermuteDigits`' tables for dimensions 0..5 (bases 2 … 11), built once in `new`: those
    /// five values then take a few table reads each instead of a permutation per value.
    permuted: Option<PermutedDigitGroups>,
}

impl HaltonSampler {
    /// A Halton sampler for an image of `resolution` pixels.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0.
    ///
    /// ```
    /// use nyquist::scramble::Scramble;
    /// use nyquist::sampler::{HaltonSampler};
    /// assert!(HaltonSampler::new([0, 4], 1, Scramble::None, 0).is_err());
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
        super::check_image(resolution, spp)?;
        let mut exponents = [0u32; 2];
        let mut scales = [1u64; 2];
        for (axis, base) in [(0usize, 2u64), (1, 3)] {
            let target = u64::from(resolution[axis].min(MAX_RESOLUTION));
            while scales[axis] < target {
                scales[axis] *= base;
                exponents[axis] += 1;
            }
        }
        let stride = scales[0] * scales[1];
        let basis = [
            scales[1] * mod_inverse(scales[1], scales[0]),
            scales[0] * mod_inverse(scales[0], scales[1]),
        ];
        Ok(Self {
            spp,
            scramble,
            seed,
            exponents,
            scales,
            stride,
            basis,
            pixel: [0; 2],
            offset: 0,
            index: 0,
            axis_index: [0; 2],
            axis_base: [0; 2],
            steps: [stride >> exponents[0], stride / scales[1]],
            dim: 0,
            permuted: (scramble == Scramble::PermuteDigits).then(|| PermutedDigitGroups::new(seed)),
        })
    }

    /// The scales `[2^j, 3^k]`: the pattern repeats every `2^j` pixels in x and `3^k` in y.
    ///
    /// ```
    /// use nyquist::scramble::Scramble;
    /// use nyquist::sampler::{HaltonSampler};
    /// let s = HaltonSampler::new([100, 30], 1, Scramble::None, 0).unwrap();
    /// assert_eq!(s.scales(), [128, 81]);
    /// ```
    pub fn scales(&self) -> [u64; 2] {
        self.scales
    }

    /// The global Halton index of sample `sample_index` of `pixel`.
    ///
    /// ```
    /// use nyquist::scramble::Scramble;
    /// use nyquist::sampler::{HaltonSampler};
    /// let s = HaltonSampler::new([2, 3], 1, Scramble::None, 0).unwrap();
    /// // 2 × 3 pixels, stride 6: pixel (1, 0) owns the indices whose base-2 last digit is 1
    /// // and whose base-3 last digit is 0 — 3, 9, 15, …
    /// assert_eq!(s.sequence_index([1, 0], 0), 3);
    /// assert_eq!(s.sequence_index([1, 0], 2), 15);
    /// ```
    pub fn sequence_index(&self, pixel: [u32; 2], sample_index: u32) -> u64 {
        self.pixel_offset(pixel) + u64::from(sample_index) * self.stride
    }

    /// `h(p)`: the index of the pixel's first sample.
    fn pixel_offset(&self, pixel: [u32; 2]) -> u64 {
        let mut offset = 0u64;
        for (axis, p) in (0u32..).zip(pixel) {
            let a = axis as usize;
            let pm = u64::from(p) % self.scales[a];
            let digits = inverse_radical_inverse(axis, pm, self.exponents[a]);
            // `digits < scale ≤ 243` and `basis < stride ≤ 31104`: no overflow.
            offset = (offset + digits * self.basis[a]) % self.stride;
        }
        offset
    }

    #[inline]
    fn value(&self, dim: u32, a: u64) -> f32 {
        match self.scramble {
            Scramble::None => radical_inverse_inlined(dim, a),
            Scramble::PermuteDigits => match self.permuted.as_ref().and_then(|t| t.value(dim, a)) {
                Some(x) => x,
                None => scrambled_radical_inverse(dim, a, self.seed),
            },
            how => self.owen_value(dim, a, how),
        }
    }

    /// The Owen-scrambled values, out of line: inlined, their digit loops slowed the camera
    /// sample of the other scrambles by about 5 %.
    #[inline(never)]
    fn owen_value(&self, dim: u32, a: u64, how: Scramble) -> f32 {
        if how == Scramble::FastOwen {
            fast_owen_scrambled_radical_inverse(dim, a, self.seed)
        } else {
            owen_scrambled_radical_inverse(dim, a, self.seed)
        }
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, dim: u32) -> f32 {
        match dim {
            0 => self.value(0, self.axis_index[0]),
            1 => self.value(1, self.axis_index[1]),
            // The camera's time and lens dimensions with the base a constant, so the per-base
            // table reads fold away.
            2 if self.scramble == Scramble::None => radical_inverse_inlined(2, self.index),
            3 if self.scramble == Scramble::None => radical_inverse_inlined(3, self.index),
            4 if self.scramble == Scramble::None => radical_inverse_inlined(4, self.index),
            1024.. => self.padded(dim),
            _ => self.value(dim, self.index),
        }
    }

    /// A padding dimension (`dim >= 1024`) of the current sample.
    #[inline(never)]
    fn padded(&self, dim: u32) -> f32 {
        let key = super::padding_key(self.offset, self.seed);
        let s = (self.index - self.offset) / self.stride;
        crate::math::fraction_to_f32(crate::sequence::padded_u32(key, s, dim))
    }

    /// Dimensions `dim, dim + 1, …` into `out` as `sample` gives them, when they are a run of
    /// plain radical inverses of `index` (no scrambling, clear of dimensions 0 and 1, which read
    /// the axis indices, also after wrapping): one batch that finds the index's class once.
    /// `false`, with nothing written, otherwise.
    #[inline]
    fn batch(&self, dim: u32, out: &mut [f32]) -> bool {
        let d = dim;
        let fits = self.scramble == Scramble::None
            && d >= 2
            && (d as usize).saturating_add(out.len()) <= 1024;
        if fits {
            radical_inverse_dims(d, self.index, out);
        }
        fits
    }
}

impl Sampler for HaltonSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if pixel != self.pixel {
            self.pixel = pixel;
            self.offset = self.pixel_offset(pixel);
            self.axis_base = [
                self.offset >> self.exponents[0],
                self.offset / self.scales[1],
            ];
        }
        let i = u64::from(sample_index);
        self.index = self.offset + i * self.stride;
        self.axis_index = [
            self.axis_base[0] + i * self.steps[0],
            self.axis_base[1] + i * self.steps[1],
        ];
        self.dim = dim;
    }

    super::global_point_dimensions!();

    /// The default's values.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        self.start_pixel_sample(pixel, sample_index, 0);
        let p = [self.sample(0), self.sample(1)];
        // Each a constant base, so its table reads and step kind fold away.
        let v = [self.sample(2), self.sample(3), self.sample(4)];
        self.dim = 5;
        CameraSample {
            p_film: [
                film_coordinate(pixel[0], p[0]),
                film_coordinate(pixel[1], p[1]),
            ],
            lens: [v[1], v[2]],
            time: v[0],
        }
    }

    super::global_point_arrays!();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::radical::radical_inverse;
    use crate::sampler::tests::{consistent_values, threads_agree};

    /// Dimensions past 1024: padding, per pixel (repeated where the pixels repeat).
    #[test]
    fn dimensions_past_1024_are_padded_per_pixel() {
        for scramble in Scramble::ALL {
            let mut s = HaltonSampler::new([300, 200], 4, scramble, 7).unwrap();
            let [sx, sy] = s.scales().map(|v| v as u32);
            crate::sampler::tests::padding_holds(&mut s, [5, 6], [6, 6], [5 + sx, 6 + sy], 64);
        }
    }

    /// The in-pixel offset (`get_pixel_2d`, exact at any pixel coordinate, where `p_film` would
    /// round) and the next six dimensions of sample `i` of `pixel`.
    fn record(s: &mut impl Sampler, pixel: [u32; 2], i: u32) -> std::vec::Vec<f32> {
        s.start_pixel_sample(pixel, i, 0);
        let mut v = s.get_pixel_2d().to_vec();
        v.extend((0..6).map(|_| s.get_1d()));
        v
    }

    /// As documented: pixel (x + 2^j, y + 3^k) repeats pixel (x, y)'s samples, inside the image
    /// and outside it.
    #[test]
    fn pixels_repeat_every_scale_inside_and_outside_the_image() {
        for scramble in Scramble::ALL {
            let mut s = HaltonSampler::new([300, 200], 4, scramble, 7).unwrap();
            let [sx, sy] = s.scales().map(|v| v as u32);
            assert_eq!([sx, sy], [128, 243]);
            for (pixel, i) in [([3u32, 4u32], 0u32), ([130, 7], 2), ([5, 250], 3)] {
                let base = [pixel[0] % sx, pixel[1] % sy];
                let a = record(&mut s, pixel, i);
                assert_eq!(a, record(&mut s, base, i), "{scramble:?} {pixel:?}");
                let far = [pixel[0] + 7 * sx, pixel[1] + 3 * sy];
                assert_eq!(a, record(&mut s, far, i), "{scramble:?} {far:?}");
            }
            assert_ne!(record(&mut s, [1, 0], 0), record(&mut s, [0, 0], 0));
        }
    }

    #[test]
    fn halton_is_consistent_and_thread_independent() {
        for scramble in Scramble::ALL {
            let s = HaltonSampler::new([64, 48], 16, scramble, 5).unwrap();
            consistent_values(&s);
            threads_agree(&s);
        }
    }

    #[test]
    fn halton_image_sample_is_the_scaled_global_point() {
        // Film position / resolution scale equals (Φ₂(idx), Φ₃(idx)) of the global sequence.
        let s0 = HaltonSampler::new([8, 9], 4, Scramble::None, 0).unwrap();
        let mut s = s0.clone();
        let mut hit = std::vec![false; 8 * 9 * 4];
        for y in 0..9u32 {
            for x in 0..8u32 {
                for i in 0..4 {
                    let idx = s.sequence_index([x, y], i);
                    s.start_pixel_sample([x, y], i, 0);
                    let [u, v] = s.get_pixel_2d();
                    let gx = f64::from(radical_inverse(0, idx)) * 8.0;
                    let gy = f64::from(radical_inverse(1, idx)) * 9.0;
                    assert!(
                        (gx - (f64::from(x) + f64::from(u))).abs() < 1e-4,
                        "x {x} {y} {i}"
                    );
                    assert!(
                        (gy - (f64::from(y) + f64::from(v))).abs() < 1e-4,
                        "y {x} {y} {i}"
                    );
                    hit[idx as usize] = true;
                }
            }
        }
        // The 8 × 9 pixels × 4 samples are exactly the first 288 Halton points.
        assert!(hit.iter().all(|&b| b));
    }

    #[test]
    fn halton_corner_pixel_of_a_huge_image() {
        let mut s = HaltonSampler::new([16384, 16384], 65536, Scramble::None, 0).unwrap();
        let mut seen = std::vec::Vec::new();
        for dim in [0u32, 2] {
            s.start_pixel_sample([16383, 16383], 65535, dim);
            let v = if dim == 0 {
                s.get_pixel_2d()
            } else {
                s.get_2d()
            };
            for x in v {
                assert!(x.is_finite() && (0.0..1.0).contains(&x), "{x}");
                assert!(!seen.contains(&x.to_bits()), "{x} twice");
                seen.push(x.to_bits());
            }
        }
        for scramble in [Scramble::PermuteDigits, Scramble::FastOwen, Scramble::Owen] {
            let mut t = HaltonSampler::new([16384, 16384], 65536, scramble, 3).unwrap();
            let a = super::super::tests::record(&mut t, [16383, 16383], 65535);
            assert!(a.iter().all(|x| (0.0..1.0).contains(x)), "{scramble:?}");
            let b = super::super::tests::record(&mut t, [16383, 16383], 65534);
            assert_ne!(a, b, "{scramble:?}");
        }
        // u64 index math: stride 2⁷·3⁵ = 31104, and the largest sample index passes 2³².
        assert!(s.sequence_index([16383, 16383], 65535) >= 65535 * 31104);
        assert!(s.sequence_index([16383, 16383], u32::MAX) > u64::from(u32::MAX));
    }

    #[test]
    fn halton_arrays_equal_values_taken_one_at_a_time() {
        for scramble in Scramble::ALL {
            let s = HaltonSampler::new([640, 480], 16, scramble, 9).unwrap();
            crate::sampler::tests::arrays_are_values_in_order(&s);
        }
    }

    /// With the nested scrambles the film position is the pixel plus the scrambled in-pixel
    /// value (`Φ₂(idx >> j)`, `Φ₃(idx / 3^k)` through the scramble), every other dimension the
    /// scrambled `Φ(idx)`; the pixels of one pattern block together take each index once.
    #[test]
    fn halton_owen_values_are_the_scrambled_radical_inverses() {
        type Scrambled = fn(u32, u64, u64) -> f32;
        let cases: [(Scramble, Scrambled); 2] = [
            (Scramble::Owen, owen_scrambled_radical_inverse),
            (Scramble::FastOwen, fast_owen_scrambled_radical_inverse),
        ];
        for (scramble, f) in cases {
            let mut s = HaltonSampler::new([8, 9], 4, scramble, 21).unwrap();
            for y in 0..9u32 {
                for x in 0..8u32 {
                    for i in 0..4 {
                        let idx = s.sequence_index([x, y], i);
                        s.start_pixel_sample([x, y], i, 0);
                        let p = s.get_pixel_2d();
                        assert_eq!(p, [f(0, idx >> 3, 21), f(1, idx / 9, 21)], "{scramble:?}");
                        let c = s.camera_sample([x, y], i);
                        assert!(c.p_film[0] >= x as f32 && c.p_film[0] < (x + 1) as f32);
                        assert!(c.p_film[1] >= y as f32 && c.p_film[1] < (y + 1) as f32);
                        assert_eq!(
                            [c.time, c.lens[0], c.lens[1]],
                            [2, 3, 4].map(|d| f(d, idx, 21))
                        );
                        assert_eq!(s.get_1d(), f(5, idx, 21));
                    }
                }
            }
        }
    }

    /// Any `2ᵐ` consecutive samples of a pixel fall one per `1/2ᵐ` column of the pixel and any
    /// `3ᵐ` one per `1/3ᵐ` row, under every scramble (the nested ones map strata to strata).
    #[test]
    fn halton_pixel_samples_keep_their_strata_under_every_scramble() {
        for scramble in Scramble::ALL {
            let mut s = HaltonSampler::new([64, 48], 64, scramble, 8).unwrap();
            for pixel in [[0u32, 0], [5, 7], [63, 47], [1000, 3]] {
                for first in [0u32, 5] {
                    for (axis, n) in [(0usize, 16u32), (1, 27)] {
                        let mut seen = std::vec![false; n as usize];
                        for i in first..first + n {
                            s.start_pixel_sample(pixel, i, 0);
                            let v = f64::from(s.get_pixel_2d()[axis]);
                            // Unscrambled (and some digit-permuted) values sit on a stratum's
                            // lower edge, which f32 can round just below: allow 4e-6 of slack,
                            // above the rounding (27·2⁻²⁴ ≈ 1.6e-6).
                            let cell = (v * f64::from(n) + 4e-6) as usize;
                            assert!(
                                !std::mem::replace(&mut seen[cell], true),
                                "{scramble:?} {pixel:?} axis {axis} first {first}"
                            );
                        }
                    }
                }
            }
        }
    }

    /// The scrambles differ from each other and from the plain values, and depend on the seed.
    #[test]
    fn halton_scrambles_are_distinct_and_seeded() {
        let run = |scramble, seed| {
            let mut s = HaltonSampler::new([32, 32], 16, scramble, seed).unwrap();
            super::super::tests::record(&mut s, [3, 4], 2)
        };
        let all: std::vec::Vec<_> = Scramble::ALL.iter().map(|&sc| run(sc, 5)).collect();
        for i in 0..4 {
            for j in 0..i {
                assert_ne!(
                    all[i],
                    all[j],
                    "{:?} {:?}",
                    Scramble::ALL[i],
                    Scramble::ALL[j]
                );
            }
        }
        for scramble in [Scramble::PermuteDigits, Scramble::FastOwen, Scramble::Owen] {
            assert_ne!(run(scramble, 5), run(scramble, 6), "{scramble:?}");
        }
        assert_eq!(run(Scramble::None, 5), run(Scramble::None, 6));
    }

    proptest::proptest! {
        /// Any pixel, sample, starting dimension and seed, under every scramble: values in
        /// `[0, 1)`, and the camera sample inside its pixel.
        #[test]
        fn halton_values_are_in_unit_interval_for_every_scramble(
            px in 0u32..1 << 20, py in 0u32..1 << 20, index in proptest::prelude::any::<u32>(),
            dim in proptest::prelude::any::<u32>(), seed in proptest::prelude::any::<u64>(),
        ) {
            for scramble in Scramble::ALL {
                let mut s = HaltonSampler::new([1920, 1080], 64, scramble, seed).unwrap();
                let v = super::super::tests::record(&mut s, [px, py], index);
                proptest::prop_assert!(v.iter().all(|x| (0.0..1.0).contains(x)), "{v:?}");
                let c = s.camera_sample([px, py], index);
                proptest::prop_assert!(c.p_film[0] >= px as f32 && c.p_film[0] < (px + 1) as f32);
                proptest::prop_assert!(c.p_film[1] >= py as f32 && c.p_film[1] < (py + 1) as f32);
                s.start_pixel_sample([px, py], index, dim);
                let w = [s.get_1d(), s.get_2d()[0], s.get_2d()[1]];
                proptest::prop_assert!(w.iter().all(|x| (0.0..1.0).contains(x)), "{w:?}");
            }
        }
    }

    #[test]
    fn mod_inverse_is_an_inverse() {
        for (a, n) in [(3u64, 4u64), (243, 128), (128, 243), (9, 2), (2, 9), (1, 1)] {
            assert_eq!((a * mod_inverse(a, n)) % n, 1 % n, "{a} mod {n}");
        }
    }
}
