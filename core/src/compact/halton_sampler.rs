//! [`HaltonSampler<N>`]: pbrt's Halton sampler over the whole image, every scramble, with the
//! first `N` bases' constants computed at compile time instead of the radical-inverse tables.

use super::{Halton, round_bits, scale};
use crate::Error;
use crate::hash::{self, Permutation, mix64, packed_entry, packed_table};
use crate::math::{ONE_MINUS_EPSILON, fraction_to_f32};
#[cfg(doc)]
use crate::sampler;
use crate::sampler::Sampler;
use crate::scramble::Scramble;
use crate::sequence::Sequence;

/// `N` is in `3 ..= 1024`, or the type does not compile.
const fn check_sampler_dims<const N: usize>() {
    assert!(
        N >= 3 && N <= 1024,
        "the sampler's dimension count must be in 3..=1024"
    );
}

/// `⌊num · 2^57 / den⌋`'s bits after aligning `num`'s top bit with `den`'s (57 or 58
/// significant bits), its exponent and whether a remainder is left: `num / den` to more bits
/// than an `f64` rounding needs, with a sticky bit. `0 < num < den < 2¹²⁷`.
fn quotient(num: u128, den: u128) -> (u128, i32, bool) {
    let s = num.leading_zeros() - den.leading_zeros();
    let mut r = num << s;
    let mut q = 0u128;
    for _ in 0..58 {
        q <<= 1;
        if r >= den {
            r -= den;
            q |= 1;
        }
        r <<= 1;
    }
    (q, -(s as i32) - 57, r != 0)
}

/// `(num as f64 / den as f64) as f32` for `num < den < 2⁵³` (both exact in `f64`: one rounding
/// to `f64`, one to `f32`; the result can be 1), with integer and `f32` operations only.
#[cfg_attr(
    any(
        target_arch = "x86_64",
        target_arch = "aarch64",
        target_arch = "wasm32"
    ),
    allow(dead_code)
)]
fn ratio_through_f64_int(num: u64, den: u64) -> f32 {
    if num == 0 {
        return 0.0;
    }
    let (q, e, sticky) = quotient(u128::from(num), u128::from(den));
    let (m53, e53) = round_bits(q, e, sticky, 53);
    let (m24, e24) = round_bits(m53, e53, false, 24);
    scale(m24 as u32, e24)
}

/// `(num as f64 / den as f64) as f32` (`num < den < 2⁵³`; the result can be 1): the expression
/// the desktop paths use, on targets whose FPU does `f64`.
#[cfg(any(
    target_arch = "x86_64",
    target_arch = "aarch64",
    target_arch = "wasm32"
))]
#[inline]
fn ratio_through_f64(num: u64, den: u64) -> f32 {
    (num as f64 / den as f64) as f32
}

/// As the `f64` form, by [`ratio_through_f64_int`].
#[cfg(not(any(
    target_arch = "x86_64",
    target_arch = "aarch64",
    target_arch = "wasm32"
)))]
#[inline]
fn ratio_through_f64(num: u64, den: u64) -> f32 {
    ratio_through_f64_int(num, den)
}

/// `num / den` correctly rounded to `f32`, clamped below 1 (`num < den < 2¹²⁷`), with integer
/// and `f32` operations only: what `radical::ratio_f32` returns.
fn ratio_f32_int(num: u128, den: u128) -> f32 {
    if num == 0 {
        return 0.0;
    }
    let (q, e, sticky) = quotient(num, den);
    let (m, e) = round_bits(q, e, sticky, 24);
    scale(m as u32, e).min(ONE_MINUS_EPSILON)
}

/// The largest float below the positive finite `x`.
fn below(x: f32) -> f32 {
    f32::from_bits(x.to_bits() - 1)
}

/// Φ_b(a) with every digit passed through the permutation of `(seed, b)`: bit for bit
/// [`scrambled_radical_inverse`](crate::radical::scrambled_radical_inverse) of base `b`,
/// leading zeros' closed-form tail and stratum-edge rule included.
fn permuted(b: u64, a: u64, seed: u64) -> f32 {
    let key = hash::hash2(seed, b);
    let pi = Permutation::new(b as u32, (key ^ (key >> 32)) as u32);
    let (mut num, mut den, mut a) = (0u128, 1u128, a);
    while a > 0 {
        let (q, digit) = super::div_small(a, b as u32);
        a = q;
        num = num * u128::from(b) + u128::from(pi.apply(digit));
        den *= u128::from(b);
    }
    let tail = u64::from(pi.apply(0));
    let (num, den) = (
        num * u128::from(b - 1) + u128::from(tail),
        den * u128::from(b - 1),
    );
    let x = if den < 1 << 53 {
        ratio_through_f64(num as u64, den as u64)
    } else {
        ratio_f32_int(num, den)
    };
    let x = if tail == b - 1 { below(x) } else { x };
    x.min(ONE_MINUS_EPSILON)
}

/// The nested scrambles' domain tags and hash constants (those of `radical::owen`).
const TAG_UNIFORM: u64 = 0x4f57_454e_5f55_4e49;
const TAG_AFFINE: u64 = 0x4f57_454e_5f41_4646;
const LEVEL_STEP: u64 = 0x9e37_79b9_7f4a_7c15;
const PREFIX_MUL: u64 = 0x517c_c1b7_2722_0a95;

/// Φ_b(a) under the nested scramble of `(seed, key_dim)`, uniform node permutations
/// (`AFFINE == false`) or affine ones: bit for bit
/// [`owen_scrambled_radical_inverse`](crate::radical::owen_scrambled_radical_inverse) and
/// [`fast_owen_scrambled_radical_inverse`](crate::radical::fast_owen_scrambled_radical_inverse)
/// of base `b` at dimension `key_dim`. The digits run on until `b^K ≥ 2³²`.
fn nested<const AFFINE: bool>(b: u64, key_dim: u32, a: u64, seed: u64) -> f32 {
    let tag = if AFFINE { TAG_AFFINE } else { TAG_UNIFORM };
    let key = hash::hash3(seed, u64::from(key_dim), tag);
    let split = (1u64 << 40).div_ceil(b);
    let (mut rest, mut pow, mut level) = (a, 1u64, 0u64);
    let (mut num, mut den) = (0u64, 1u64);
    while den >> 32 == 0 {
        let (next, digit) = if rest == 0 {
            (0, 0)
        } else {
            let (q, r) = super::div_small(rest, b as u32);
            (q, u64::from(r))
        };
        // a mod b^level: the digits already read.
        let prefix = a.wrapping_sub(rest.wrapping_mul(pow));
        let h = mix64(
            (key ^ prefix.wrapping_mul(PREFIX_MUL)).wrapping_add(level.wrapping_mul(LEVEL_STEP)),
        );
        rest = next;
        pow = pow.wrapping_mul(b);
        level += 1;
        let out = if AFFINE {
            let t = u128::from(h) * u128::from(b);
            let g = (t >> 64) as u64;
            let m = 1 + ((u128::from(t as u64) * u128::from(b - 1)) >> 64) as u64;
            let x = m * digit + g;
            x - b * ((x * split) >> 40)
        } else if b <= 16 {
            u64::from(packed_entry(packed_table(b as u32, h), digit as u32))
        } else {
            u64::from(Permutation::new(b as u32, (h ^ (h >> 32)) as u32).apply(digit as u32))
        };
        num = num * b + out;
        den *= b;
    }
    ratio_through_f64(num, den).min(ONE_MINUS_EPSILON)
}

/// The largest scale per axis, as in the desktop sampler (and pbrt): pixels repeat their
/// pattern every 128 (x) and 243 (y) pixels.
const MAX_RESOLUTION: u32 = 128;

/// The inverse of `a` modulo `n` (`a`, `n` coprime, `1 <= n <= 243`), by extended Euclid.
fn mod_inverse(a: u32, n: u32) -> u32 {
    let (mut r0, mut r1) = (n as i32, (a % n) as i32);
    let (mut t0, mut t1) = (0i32, 1i32);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    t0.rem_euclid(n as i32) as u32
}

/// The index whose last `n` base-`b` digits, reversed, are those of `x` (`x < bⁿ ≤ 243`): the
/// pixel's share of its sample indices along one axis.
fn reversed_digits(b: u32, mut x: u32, n: u32) -> u32 {
    let mut index = 0;
    for _ in 0..n {
        index = index * b + x % b;
        x /= b;
    }
    index
}

/// Halton sampling over the whole image (pbrt-v3/v4's `HaltonSampler`) without the desktop
/// tables: bit for bit what [`sampler::HaltonSampler`] returns for every resolution, spp,
/// scramble, seed, pixel and sample index, in dimensions `0..N` (`3 <= N <= 1024`, checked at
/// compile time).
///
/// The radical inverses come from the first `N` primes' constants, computed at compile time
/// (about 100 bytes per base), where the desktop sampler reads 500 KB of per-base tables:
/// plain ([`Halton<N>`]'s path), with digits permuted, or nested-scrambled (uniform or affine
/// node permutations), each as the corresponding [`radical`](crate::radical) function computes
/// it. Without a double-precision FPU every value comes from integer and `f32` operations only,
/// the `f64` roundings of the desktop paths done on integers. The pixel-to-index map is the
/// desktop sampler's (pixel `p`'s samples are the indices `h(p) + s·2^j·3^k`), computed in
/// 32-bit arithmetic.
///
/// Dimensions from 1024 on are the desktop sampler's padding (from four dimensions' Sobol
/// constants, 1 KiB). A dimension `N ≤ d < 1024` takes the base of dimension `2 + (d − 2) mod (N − 2)` (never bases 2 and 3 of the pixel) and
/// its own scramble: the nested scrambles key on `d`, digit permutations on a seed hashed
/// from `(seed, d)`; unscrambled, such a dimension repeats the values of the one whose base
/// it takes. With `N = 1024` every dimension is the desktop sampler's. A camera sample and an
/// integrator's first few values need `N = 8`. Allocates: no.
///
/// ```
/// use nyquist::{compact, sampler::{self, Sampler}, scramble::Scramble};
/// let mut small = compact::HaltonSampler::<8>::new([64, 64], 16, Scramble::Owen, 3).unwrap();
/// let mut desk = sampler::HaltonSampler::new([64, 64], 16, Scramble::Owen, 3).unwrap();
/// assert_eq!(small.camera_sample([10, 20], 5), desk.camera_sample([10, 20], 5));
/// assert_eq!(small.get_2d(), desk.get_2d());
/// ```
#[derive(Clone, Debug)]
pub struct HaltonSampler<const N: usize> {
    spp: u32,
    scramble: Scramble,
    seed: u64,
    exponents: [u32; 2],
    scales: [u32; 2],
    stride: u32,
    /// The CRT basis: `3^k · (3^k)⁻¹ mod 2^j` and `2^j · (2^j)⁻¹ mod 3^k`.
    basis: [u32; 2],
    /// The last pixel started, and the index of its first sample.
    pixel: [u32; 2],
    offset: u32,
    /// The current sample's index, and the indices dimensions 0 and 1 read (`index >> j` and
    /// `index / 3^k`), each its pixel's plus the sample index times a step.
    index: u64,
    axis_index: [u64; 2],
    axis_base: [u64; 2],
    steps: [u64; 2],
    dim: u32,
}

impl<const N: usize> HaltonSampler<N> {
    const BASES: [super::Base; N] = super::halton_bases::<N>();

    /// A Halton sampler for an image of `resolution` pixels, as
    /// [`sampler::HaltonSampler::new`]. `N` outside `3..=1024` does not compile.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0.
    ///
    /// ```
    /// use nyquist::{compact::HaltonSampler, scramble::Scramble};
    /// assert!(HaltonSampler::<8>::new([0, 4], 1, Scramble::None, 0).is_err());
    /// ```
    ///
    /// Dimensions 0 and 1 carry the pixel, so fewer than three do not compile:
    ///
    /// ```compile_fail
    /// use nyquist::{compact::HaltonSampler, scramble::Scramble};
    /// let _ = HaltonSampler::<2>::new([4, 4], 1, Scramble::None, 0);
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
        const { check_sampler_dims::<N>() };
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        if resolution[0] == 0 || resolution[1] == 0 {
            return Err(Error::ZeroSize { what: "resolution" });
        }
        let (mut exponents, mut scales) = ([0u32; 2], [1u32; 2]);
        for (axis, base) in [(0usize, 2u32), (1, 3)] {
            let target = resolution[axis].min(MAX_RESOLUTION);
            while scales[axis] < target {
                scales[axis] *= base;
                exponents[axis] += 1;
            }
        }
        let stride = scales[0] * scales[1];
        Ok(Self {
            spp,
            scramble,
            seed,
            exponents,
            scales,
            stride,
            basis: [
                scales[1] * mod_inverse(scales[1], scales[0]),
                scales[0] * mod_inverse(scales[0], scales[1]),
            ],
            pixel: [0; 2],
            offset: 0,
            index: 0,
            axis_index: [0; 2],
            axis_base: [0; 2],
            steps: [
                u64::from(stride >> exponents[0]),
                u64::from(stride / scales[1]),
            ],
            dim: 0,
        })
    }

    /// The scales `[2^j, 3^k]`: the pattern repeats every `2^j` pixels in x and `3^k` in y.
    ///
    /// ```
    /// use nyquist::{compact::HaltonSampler, scramble::Scramble};
    /// let s = HaltonSampler::<8>::new([100, 30], 1, Scramble::None, 0).unwrap();
    /// assert_eq!(s.scales(), [128, 81]);
    /// ```
    pub fn scales(&self) -> [u64; 2] {
        self.scales.map(u64::from)
    }

    /// The global Halton index of sample `sample_index` of `pixel`, as
    /// [`sampler::HaltonSampler::sequence_index`].
    ///
    /// ```
    /// use nyquist::{compact::HaltonSampler, scramble::Scramble};
    /// let s = HaltonSampler::<8>::new([2, 3], 1, Scramble::None, 0).unwrap();
    /// assert_eq!(s.sequence_index([1, 0], 2), 15);
    /// ```
    pub fn sequence_index(&self, pixel: [u32; 2], sample_index: u32) -> u64 {
        u64::from(self.pixel_offset(pixel)) + u64::from(sample_index) * u64::from(self.stride)
    }

    /// `h(p)`: the index of the pixel's first sample (below the stride, at most 31 104).
    fn pixel_offset(&self, pixel: [u32; 2]) -> u32 {
        let digits =
            |a: usize, b: u32| reversed_digits(b, pixel[a] % self.scales[a], self.exponents[a]);
        // `digits < scale ≤ 243` and `basis < stride ≤ 31 104`: no overflow.
        let offset = digits(0, 2) * self.basis[0] % self.stride;
        (offset + digits(1, 3) * self.basis[1]) % self.stride
    }

    /// Dimension `dim` of the current sample.
    #[inline(never)]
    fn sample(&self, dim: u32) -> f32 {
        if dim >= 1024 {
            // The desktop sampler's padding, from four dimensions' constants.
            let key = crate::sampler::padding_key(u64::from(self.offset), self.seed);
            let s = (self.index - u64::from(self.offset)) / u64::from(self.stride);
            return fraction_to_f32(super::padded_u32(key, s, dim));
        }
        let d = dim;
        let a = match d {
            0 => self.axis_index[0],
            1 => self.axis_index[1],
            _ => self.index,
        };
        let k = d as usize;
        let k = if k < N { k } else { 2 + (k - 2) % (N - 2) };
        let b = u64::from(Self::BASES[k].b);
        match self.scramble {
            Scramble::None => Halton::<N>::new().sample(a, k as u32),
            Scramble::PermuteDigits if k == d as usize => permuted(b, a, self.seed),
            Scramble::PermuteDigits => permuted(b, a, hash::hash2(self.seed, u64::from(d))),
            Scramble::FastOwen => nested::<true>(b, d, a, self.seed),
            Scramble::Owen => nested::<false>(b, d, a, self.seed),
        }
    }
}

impl<const N: usize> Sampler for HaltonSampler<N> {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if pixel != self.pixel {
            self.pixel = pixel;
            self.offset = self.pixel_offset(pixel);
            self.axis_base = [
                u64::from(self.offset >> self.exponents[0]),
                u64::from(self.offset / self.scales[1]),
            ];
        }
        let i = u64::from(sample_index);
        self.index = u64::from(self.offset) + i * u64::from(self.stride);
        self.axis_index = [
            self.axis_base[0] + i * self.steps[0],
            self.axis_base[1] + i * self.steps[1],
        ];
        self.dim = dim;
    }

    crate::sampler::global_point_dimensions!();

    fn arrays_are_dimension_runs(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::radical::ratio_f32;
    use proptest::prelude::*;

    /// The quotient aligns the numerator's top bit with the denominator's whatever their gap:
    /// 58 significant bits and the exponent of `num / den`, also when `num` is 2⁻¹⁰⁰ of `den`
    /// (a shift by the difference of the leading zeros, not any other function of them).
    #[test]
    fn quotients_keep_their_bits_across_any_gap() {
        assert_eq!(quotient(1, 1 << 100), (1 << 57, -157, false));
        assert_eq!(quotient(3, 1 << 126), (3 << 56, -182, false));
        assert_eq!(ratio_f32_int(1, 1 << 100), 2f32.powi(-100));
        assert_eq!(
            ratio_f32_int(5, 3 << 90),
            (5.0f64 / 3.0 * 2f64.powi(-90)) as f32
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        /// The integer double rounding is the `f64` expression's, for fractions of every size.
        #[test]
        fn integer_ratio_through_f64_is_the_f64_expression(den in 2u64..1 << 53, x: u64, shift in 0u32..53) {
            let den = (den >> shift).max(2);
            let num = x % den;
            prop_assert_eq!(
                ratio_through_f64_int(num, den).to_bits(),
                ((num as f64 / den as f64) as f32).to_bits()
            );
        }

        /// The integer correct rounding is `radical::ratio_f32`'s.
        #[test]
        fn integer_ratio_is_the_correctly_rounded_one(den in 2u128..1 << 96, x: u128, shift in 0u32..96) {
            let den = (den >> shift).max(2);
            let num = x % den;
            prop_assert_eq!(ratio_f32_int(num, den).to_bits(), ratio_f32(num, den).to_bits());
        }
    }

    /// Fractions `1/(den·2²⁵)` above a multiple of `2⁻²⁵`: in `[½, 1)` an odd multiple is an
    /// `f32` midpoint, the `f64` rounding lands on it and ties to even, so the two roundings
    /// differ from the correct one in about a quarter of these. The integer form must round
    /// twice as the `f64` expression does.
    #[test]
    fn integer_ratio_through_f64_rounds_twice_just_above_midpoints() {
        let mut differ = 0;
        for t in 0..400u64 {
            let den = (1u64 << 52) + 1 + 2 * t;
            // num = 2⁻²⁵ mod den, by extended Euclid: num · 2²⁵ ≡ 1 (mod den).
            let (mut r0, mut r1) = (i128::from(den), 1i128 << 25);
            let (mut t0, mut t1) = (0i128, 1i128);
            while r1 != 0 {
                let q = r0 / r1;
                (r0, r1) = (r1, r0 - q * r1);
                (t0, t1) = (t1, t0 - q * t1);
            }
            let num = t0.rem_euclid(i128::from(den)) as u64;
            let want = (num as f64 / den as f64) as f32;
            assert_eq!(
                ratio_through_f64_int(num, den).to_bits(),
                want.to_bits(),
                "{num}/{den}"
            );
            differ += usize::from(ratio_f32_int(u128::from(num), u128::from(den)) != want);
        }
        assert!(
            differ > 40,
            "{differ} double roundings differ from the correct one"
        );
    }
}
