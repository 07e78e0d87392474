//! Progressive multi-jittered (0,2) samples per pixel, from the baked pmj02 table.

use super::{CameraSample, Sampler, film_coordinate, pixel_hash};
use crate::Error;
use crate::hash::mix64;
use crate::scramble::{
    lk_hash_by, lk_hash_premixed_by, lk_multiplier, reverse16, reversed_to_f32,
    scramble_premixed_rev_f32x4,
};
use crate::sequence::PMJ02_MAX_POINTS;
use crate::sequence::pmj02::PMJ02_PREMIXED;

/// Odd constant separating requests in the per-request hash.
const REQUEST_STEP: u64 = 0x9e37_79b9_7f4a_7c15;

/// The three keys of one request (a 2D pair or a 1D value at one dimension of one pixel): the
/// index shuffle and the Owen scrambles of x and y, each a well-mixed 32-bit hash.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Keys {
    shuffle: Key,
    pub(crate) x: Key,
    pub(crate) y: Key,
}

/// One [`lk_hash`](crate::scramble::lk_hash) seed with its multiplier, derived once per key
/// rather than per hash.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Key {
    seed: u32,
    multiplier: u32,
}

impl Key {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn new(seed: u32) -> Key {
        Key {
            seed,
            multiplier: lk_multiplier(seed),
        }
    }

    /// `lk_hash(x_rev, seed)`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn hash(self, x_rev: u32) -> u32 {
        lk_hash_by(x_rev, self.seed, self.multiplier)
    }

    /// `lk_hash` of a word stored premixed ([`lk_premix`](crate::scramble::lk_premix)).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn hash_premixed(self, premixed: u32) -> u32 {
        lk_hash_premixed_by(premixed, self.seed, self.multiplier)
    }
}

impl Keys {
    /// Keys of request `request` (`2d` for the pair at dimension `d`, `2d + 1` for the 1D value
    /// there: the two kinds never share keys) of the pixel whose key is `pixel_key`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn new(pixel_key: u64, request: u64) -> Keys {
        let h = mix64(pixel_key ^ request.wrapping_mul(REQUEST_STEP));
        let g = mix64(h ^ 0x706d_6a30_3279);
        Keys {
            shuffle: Key::new(h as u32),
            x: Key::new((h >> 32) as u32),
            y: Key::new(g as u32),
        }
    }

    /// The [`PMJ02_PREMIXED`] row of the sample whose 16-bit index reversed into a 32-bit word
    /// is `index_rev`: Burley's nested uniform shuffle of the index (a fast Owen scramble of the
    /// index read as a fraction), which sends the indices `0..2^k` onto one aligned block of
    /// `2^k` table points for every `k ≤ 16`. The scramble's output is bit-reversed; its top 16
    /// bits are the reversed point index, which is that point's row in the reversed table.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn row(&self, index_rev: u32) -> usize {
        (self.shuffle.hash(index_rev) >> 16) as usize
    }

    /// The point in [`PMJ02_PREMIXED`] row `row`, each coordinate fast-Owen-scrambled (on the
    /// reversed words the table holds).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn point(&self, row: usize) -> [f32; 2] {
        let [x, y] = PMJ02_PREMIXED[row];
        [
            reversed_to_f32(self.x.hash_premixed(x)),
            reversed_to_f32(self.y.hash_premixed(y)),
        ]
    }

    /// The 1D value of the sample whose 16-bit index reversed into a 32-bit word is
    /// `index_rev`: the van der Corput point of the shuffled index `j` ([`row`](Self::row) is
    /// `j` reversed, so `j` is the bit-reversed word of that point), fast-Owen-scrambled. The
    /// shuffle sends the first `2^m` samples to `2^m` indices with distinct low `m` bits, so
    /// their values fall one into each stratum of width `2^−m`, as a shuffled table
    /// coordinate's would; two byte-table reads take the place of a read of the 512 KiB table.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value(&self, index_rev: u32) -> f32 {
        reversed_to_f32(self.x.hash(reverse16(self.row(index_rev) as u32)))
    }
}

/// The request numbers of the camera's values: image pair (dimension 0), time (1D at
/// dimension 2), lens pair (dimension 3).
const CAMERA: [u64; 3] = [0, 2 * 2 + 1, 2 * 3];

fn camera_keys(pixel_key: u64) -> [Keys; 3] {
    CAMERA.map(|r| Keys::new(pixel_key, r))
}

/// Progressive multi-jittered (0,2) sampling (Christensen, Kensler & Kilpatrick 2018) from the
/// baked table [`PMJ02_TABLE`](crate::sequence::PMJ02_TABLE), decorrelated per pixel and
/// dimension by hashing.
///
/// Every request — the image sample ([`Sampler::get_pixel_2d`], dimensions 0 and 1), a pair
/// ([`Sampler::get_2d`] at dimension `d`) or a 1D value ([`Sampler::get_1d`] at `d`) — has its
/// own keys, a hash of (pixel, seed, `d`, 1D or 2D). For sample `i`, a pair reads table point
/// `shuffle(i)` and Owen-scrambles its coordinates; a 1D value is the van der Corput point of
/// `shuffle(i)`, Owen-scrambled; `shuffle` is Burley's nested uniform shuffle of the 16-bit
/// index. The image pair alone reads point `i` unshuffled.
///
/// Why these randomizations: the Owen scramble maps elementary intervals onto elementary
/// intervals, and the nested shuffle maps the first `2^m` samples onto one aligned block of
/// `2^m` points, which is a (0, m, 2)-net (pmj02 is a (0,2)-sequence; the tests check every
/// block) and whose indices differ in their low `m` bits. So for every pixel and every pair,
/// the first `2^m` samples form a (0, m, 2)-net and every 1D value is stratified into `2^m`
/// strata, at every power of two — the progressive property survives. The shuffles
/// decorrelate the requests: two values that are functions of the same index digits (two pairs
/// reading one point, or two unshuffled progressive values) are strongly correlated whatever
/// their scrambles, and a plain permutation of `0..spp` would decorrelate them but break every
/// prefix but the whole set. One request can go unshuffled, since every other one is shuffled
/// against it: the image pair, whose per-pixel scramble alone makes each pixel's points an
/// independent random net (a hash per camera sample fewer).
///
/// `samples_per_pixel` is any value in `1..=65536` and is not rounded; the net property holds
/// at every power of two below it, and samples past it continue the sequence. Past 65536
/// samples (the table's size: the construction is a stochastic table, which cannot be extended
/// without a larger one) the sampler starts **epochs** of 65536: sample `i` is sample
/// `i mod 65536` under the pixel key hashed with the epoch `⌊i / 65536⌋`, so each epoch is
/// a (0, 16, 2)-net in every pixel and pair, independent of the others, and no sample repeats
/// an earlier one. Arrays are the trait's defaults: one pair or value per dimension, in order.
/// Allocates: no.
///
/// ```
/// use nyquist::sampler::{Pmj02Sampler, Sampler};
/// let mut s = Pmj02Sampler::new(16, 0).unwrap();
/// let mut seen = [[false; 4]; 4];
/// for i in 0..16 {
///     s.start_pixel_sample([3, 1], i, 0);
///     let [x, y] = s.get_pixel_2d();
///     seen[(y * 4.0) as usize][(x * 4.0) as usize] = true;
/// }
/// assert!(seen.iter().flatten().all(|&b| b)); // one sample in each 1/4 × 1/4 square
/// ```
#[derive(Clone, Debug)]
pub struct Pmj02Sampler {
    spp: u32,
    seed: u64,
    pixel: [u32; 2],
    /// `hash(pixel, seed)` (hashed with the epoch past the first), cached across the samples of
    /// one pixel and epoch.
    pixel_key: u64,
    /// The epoch of the cached keys: `sample_index >> 16`.
    epoch: u32,
    /// The camera's keys for the current pixel, built once per pixel.
    camera: [Keys; 3],
    /// The sample index modulo 65536, bit-reversed into a 32-bit word (what the shuffles read).
    pub(crate) index_rev: u32,
    dim: u32,
}

/// Tag of the pixel hash.
const PIXEL_TAG: u64 = 0x0070_6d6a_3032; // "pmj02"

impl Pmj02Sampler {
    /// A pmj02 sampler with `spp` samples per pixel (not rounded).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`; [`Error::TooMany`] if `spp > 65536` (the table).
    ///
    /// ```
    /// use nyquist::sampler::{Pmj02Sampler, Sampler};
    /// assert_eq!(Pmj02Sampler::new(100, 1).unwrap().samples_per_pixel(), 100);
    /// assert!(Pmj02Sampler::new(0, 1).is_err());
    /// assert!(Pmj02Sampler::new(65_537, 1).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        if spp as usize > PMJ02_MAX_POINTS {
            return Err(Error::TooMany {
                what: "spp",
                value: u64::from(spp),
                max: PMJ02_MAX_POINTS as u64,
            });
        }
        let pixel_key = pixel_hash([0; 2], seed, PIXEL_TAG);
        Ok(Self {
            spp,
            seed,
            pixel: [0; 2],
            pixel_key,
            epoch: 0,
            camera: camera_keys(pixel_key),
            index_rev: 0,
            dim: 0,
        })
    }

    /// The seed.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::Pmj02Sampler::new(4, 9).unwrap().seed(), 9);
    /// ```
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The image pair (the pair at dimension 0): table point `index` itself, unshuffled (its
    /// row is `index` reversed), Owen-scrambled by the pixel's keys (see the type's docs).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn image_point(&self) -> [f32; 2] {
        self.camera[0].point((self.index_rev >> 16) as usize)
    }

    /// The keys of request `request` (`2d` for the pair at dimension `d`, `2d + 1` for the 1D
    /// value there) of the current pixel.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn keys(&self, request: u64) -> Keys {
        match request {
            0 => self.camera[0],
            r if r == CAMERA[1] => self.camera[1],
            r if r == CAMERA[2] => self.camera[2],
            r => Keys::new(self.pixel_key, r),
        }
    }
}

impl Sampler for Pmj02Sampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        let epoch = sample_index >> 16;
        if pixel != self.pixel || epoch != self.epoch {
            self.pixel = pixel;
            self.epoch = epoch;
            self.pixel_key = pixel_hash(pixel, self.seed, PIXEL_TAG);
            if epoch != 0 {
                self.pixel_key = crate::hash::hash2(self.pixel_key, u64::from(epoch));
            }
            self.camera = camera_keys(self.pixel_key);
        }
        self.index_rev = reverse16(sample_index) << 16;
        self.dim = dim;
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_1d(&mut self) -> f32 {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(1);
        self.keys(2 * u64::from(d) + 1).value(self.index_rev)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_2d(&mut self) -> [f32; 2] {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(2);
        if d == 0 {
            return self.image_point();
        }
        let keys = self.keys(2 * u64::from(d));
        keys.point(keys.row(self.index_rev))
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        self.image_point()
    }

    /// The default's values. The four table coordinates (image pair, lens pair) hash together
    /// on four vector lanes.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        self.start_pixel_sample(pixel, sample_index, 0);
        let [image, time, lens] = &self.camera;
        let [ix, iy] = PMJ02_PREMIXED[(self.index_rev >> 16) as usize];
        let [lx, ly] = PMJ02_PREMIXED[lens.row(self.index_rev)];
        let seeds = [image.x.seed, image.y.seed, lens.x.seed, lens.y.seed];
        let [px, py, u, v] = scramble_premixed_rev_f32x4([ix, iy, lx, ly], seeds);
        let time = time.value(self.index_rev);
        self.dim = 5;
        CameraSample {
            p_film: [film_coordinate(pixel[0], px), film_coordinate(pixel[1], py)],
            lens: [u, v],
            time,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{
        arrays_are_values_in_order, consistent_values, is_latin, is_zero_two_net, threads_agree,
    };
    use std::vec::Vec;

    const SEEDS: [u64; 6] = [0, 1, 5, 6, 10, 15];

    /// The first `n` samples of `pixel`: what `get` returns after `start_pixel_sample(.., dim)`.
    fn run<T>(
        s: &mut Pmj02Sampler,
        pixel: [u32; 2],
        dim: u32,
        n: u32,
        get: impl Fn(&mut Pmj02Sampler) -> T,
    ) -> Vec<T> {
        (0..n)
            .map(|i| {
                s.start_pixel_sample(pixel, i, dim);
                get(s)
            })
            .collect()
    }

    /// Every request has its own keys: the 1D values and 2D pairs at dimensions 0..12 never
    /// agree at every sample of a pixel, as two requests that shared their keys would (the same
    /// shuffled row and scramble give the same value). The camera's values are three of these
    /// requests (the pair at 0, the value at 2, the pair at 3).
    #[test]
    fn pmj02_requests_never_share_keys() {
        let mut s = Pmj02Sampler::new(16, 3).unwrap();
        for pixel in [[0, 0], [5, 9]] {
            // One column per request: (what, values over the pixel's 16 samples).
            let mut columns: Vec<(std::string::String, Vec<f32>)> = Vec::new();
            let mut push = |what: std::string::String, i: u32, v: f32| match columns
                .iter_mut()
                .find(|(w, _)| *w == what)
            {
                Some((_, c)) => c.push(v),
                None if i == 0 => columns.push((what, std::vec![v])),
                None => unreachable!(),
            };
            for i in 0..16 {
                for d in 0..12 {
                    s.start_pixel_sample(pixel, i, d);
                    push(std::format!("1d {d}"), i, s.get_1d());
                    s.start_pixel_sample(pixel, i, d);
                    let [x, y] = s.get_2d();
                    push(std::format!("2d {d} x"), i, x);
                    push(std::format!("2d {d} y"), i, y);
                }
            }
            for (a, (wa, va)) in columns.iter().enumerate() {
                for (wb, vb) in &columns[a + 1..] {
                    assert_ne!(va, vb, "{wa} and {wb} share their keys at pixel {pixel:?}");
                }
            }
        }
    }

    #[test]
    fn pmj02_sampler_is_consistent_and_thread_independent() {
        for spp in [1, 16, 100] {
            let s = Pmj02Sampler::new(spp, 3).unwrap();
            consistent_values(&s);
            threads_agree(&s);
            arrays_are_values_in_order(&s);
        }
    }

    #[test]
    fn pmj02_sampler_pixel_and_pair_samples_are_nets_at_every_power_of_two_up_to_1024() {
        // Every pixel of a 10 × 10 image, six seeds; the image pair, the lens pair (dimension
        // 3, cached keys) and a pair at dimension 12; and the 1D values of time (dimension 2)
        // and of dimension 9, each stratified into 2^m strata at every 2^m.
        for seed in SEEDS {
            let mut s = Pmj02Sampler::new(1024, seed).unwrap();
            for py in 0..10 {
                for px in 0..10 {
                    let p = [px, py];
                    let image = run(&mut s, p, 0, 1024, |s| s.get_pixel_2d());
                    let lens = run(&mut s, p, 3, 1024, |s| s.get_2d());
                    let later = run(&mut s, p, 12, 1024, |s| s.get_2d());
                    let time = run(&mut s, p, 2, 1024, |s| s.get_1d());
                    let d9 = run(&mut s, p, 9, 1024, |s| s.get_1d());
                    for m in 0..=10 {
                        let n = 1 << m;
                        for (what, pts) in [("image", &image), ("lens", &lens), ("12", &later)] {
                            let pts = &pts[..n];
                            assert!(is_zero_two_net(pts), "seed {seed} {p:?} {what} 2^{m}");
                            assert!(pts.iter().flatten().all(|v| (0.0..1.0).contains(v)));
                        }
                        for (what, xs) in [("time", &time), ("dim 9", &d9)] {
                            assert!(is_latin(&xs[..n], 1), "seed {seed} {p:?} {what} 2^{m}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn pmj02_sampler_non_power_of_two_spp_keeps_the_nets_below_it() {
        let mut s = Pmj02Sampler::new(100, 2).unwrap();
        assert_eq!(s.samples_per_pixel(), 100);
        let pts = run(&mut s, [4, 4], 0, 100, |s| s.get_pixel_2d());
        for m in 0..=6 {
            assert!(is_zero_two_net(&pts[..1 << m]), "2^{m}");
        }
        // Between powers of two no column of width 1/128 holds two of the 100 samples.
        let xs: Vec<f32> = pts.iter().map(|p| p[0]).collect();
        let mut seen = [false; 128];
        for x in xs {
            assert!(!core::mem::replace(&mut seen[(x * 128.0) as usize], true));
        }
    }

    #[test]
    fn pmj02_sampler_pixels_dimensions_and_seeds_differ() {
        let first = |seed: u64, pixel: [u32; 2], dim: u32| {
            let mut s = Pmj02Sampler::new(16, seed).unwrap();
            run(&mut s, pixel, dim, 16, |s| s.get_2d())
        };
        let base = first(1, [2, 3], 5);
        assert_ne!(base, first(2, [2, 3], 5), "seed");
        assert_ne!(base, first(1, [3, 2], 5), "pixel");
        assert_ne!(base, first(1, [2, 3], 7), "dimension");
        // A 1D value at d is not the first coordinate of the pair at d.
        let mut s = Pmj02Sampler::new(16, 1).unwrap();
        let ones = run(&mut s, [2, 3], 5, 16, |s| s.get_1d());
        assert!(ones.iter().zip(&base).all(|(a, b)| *a != b[0]));
    }

    #[test]
    fn pmj02_sampler_dimensions_are_decorrelated() {
        // The camera's values against each other over 1024 samples, in a 32 × 32 grid: were
        // two of them functions of the same index digits (two pairs reading one table row, or
        // an unshuffled 1D value beside the unshuffled image pair), only 32 to 256 cells would
        // be hit. Independent uniform pairs hit 1024·(1 − e⁻¹) ≈ 647 on average, with a
        // standard deviation near 10: below 550 is a false alarm with probability under 10⁻¹⁵.
        for seed in SEEDS {
            let mut s = Pmj02Sampler::new(1024, seed).unwrap();
            let image = run(&mut s, [5, 5], 0, 1024, |s| s.get_pixel_2d());
            let time = run(&mut s, [5, 5], 2, 1024, |s| s.get_1d());
            let lens = run(&mut s, [5, 5], 3, 1024, |s| s.get_2d());
            let d9 = run(&mut s, [5, 5], 9, 1024, |s| s.get_1d());
            let columns: [(&str, Vec<f32>); 6] = [
                ("image x", image.iter().map(|p| p[0]).collect()),
                ("image y", image.iter().map(|p| p[1]).collect()),
                ("time", time),
                ("lens u", lens.iter().map(|p| p[0]).collect()),
                ("lens v", lens.iter().map(|p| p[1]).collect()),
                ("1D at 9", d9),
            ];
            for (i, (a, u)) in columns.iter().enumerate() {
                // A pair's own two coordinates are one net: skip them.
                for (b, v) in columns.iter().skip(i + 1).filter(|(b, _)| a[..4] != b[..4]) {
                    let mut cells = [false; 1024];
                    for (x, y) in u.iter().zip(v) {
                        cells[(x * 32.0) as usize * 32 + (y * 32.0) as usize] = true;
                    }
                    let hit = cells.iter().filter(|&&c| c).count();
                    assert!(hit > 550, "seed {seed}, {a} against {b}: {hit} cells");
                }
            }
        }
    }

    #[test]
    fn pmj02_sampler_epochs_past_the_table_size() {
        let mut s = Pmj02Sampler::new(4, 8).unwrap();
        let mut get = |i: u32| {
            s.start_pixel_sample([1, 1], i, 0);
            (s.get_pixel_2d(), s.get_1d(), s.get_2d())
        };
        // Epoch e is the first epoch's pattern under the pixel key hashed with e.
        for i in [0u32, 5, 65535] {
            assert_ne!(get(i), get(i + 65536), "index {i}");
            assert_ne!(get(i + 65536), get(i + 7 * 65536), "index {i}");
        }
        let key = pixel_hash([1, 1], 8, PIXEL_TAG);
        let keys = camera_keys(crate::hash::hash2(key, 3));
        s.start_pixel_sample([1, 1], 3 * 65536 + 9, 0);
        assert_eq!(s.get_pixel_2d(), keys[0].point(reverse16(9) as usize));
        // Each epoch is a net: an epoch's first 1024 samples.
        let pts: Vec<[f32; 2]> = (0..1024)
            .map(|i| {
                s.start_pixel_sample([1, 1], 2 * 65536 + i, 0);
                s.get_pixel_2d()
            })
            .collect();
        assert!(is_zero_two_net(&pts));
        assert_eq!(
            crate::sampler::tests::progressive_samples_are_distinct(&mut s, [2, 3]),
            1 << 20
        );
        // Past spp the sequence goes on: samples 4..8 complete the net of 8.
        let pts = run(&mut s, [1, 1], 0, 8, |s| s.get_pixel_2d());
        assert!(is_zero_two_net(&pts));
    }

    #[test]
    fn pmj02_sampler_rejects_bad_spp() {
        assert_eq!(
            Pmj02Sampler::new(0, 0).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
        assert_eq!(
            Pmj02Sampler::new(65_537, 0).unwrap_err(),
            Error::TooMany {
                what: "spp",
                value: 65_537,
                max: 65_536
            }
        );
        assert!(Pmj02Sampler::new(65_536, 0).is_ok());
    }

    proptest::proptest! {
        #[test]
        fn pmj02_sampler_never_panics_and_stays_in_unit_interval(
            px: u32, py: u32, index: u32, dim: u32, seed: u64, spp in 1u32..=65_536,
        ) {
            let mut s = Pmj02Sampler::new(spp, seed).unwrap();
            let c = crate::sampler::camera_sample(&mut s, [px, py], index);
            proptest::prop_assert!((0.0..1.0).contains(&c.time));
            proptest::prop_assert!(c.lens.iter().all(|v| (0.0..1.0).contains(v)));
            s.start_pixel_sample([px, py], index, dim);
            let mut v = std::vec![s.get_1d()];
            v.extend_from_slice(&s.get_2d());
            v.extend_from_slice(&s.get_pixel_2d());
            let mut a = [0.0f32; 7];
            s.get_array_2d(&mut a);
            v.extend_from_slice(&a[..6]);
            s.get_array_1d(&mut a);
            v.extend_from_slice(&a);
            proptest::prop_assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
        }
    }
}
