//! The blue-noise sampler over any [`BlueFamily`].

use super::{BlueFamily, LatticeBlue, OwenSobolBlue, Pmj02Blue, offset};
use crate::Error;
use crate::sampler::Sampler;

/// Samples whose error is blue noise across the screen (Heitz et al. 2019; Belcour and Heitz
/// 2021): each pixel's samples are one of family `F`'s randomised nets, and the
/// randomisations are laid out by `F`'s optimised tile so that neighbouring pixels' errors
/// differ. Use it through [`OwenSobolBlueSampler`], [`Pmj02BlueSampler`] or
/// [`LatticeBlueSampler`].
///
/// Dimensions go in 4-D blocks: dimension `d` is component `d mod 4` of block `d / 4`, whose
/// randomisation is the [tile](super) entry at the pixel plus the block's offset. So the
/// camera's image sample (0, 1), time and lens (2 … 4), and every later pair and 4-D block,
/// are each the family's net in every pixel at every power of two, and blue across pixels at
/// 1 to 256 spp. Every sample index is a new sample, so the sampler continues past its `spp`.
///
/// `with_frame` moves every block's offset by the frame's point of Roberts' R2 sequence: each
/// frame is blue, and consecutive frames read unrelated entries.
///
/// ```
/// use nyquist::sampler::{OwenSobolBlueSampler, Sampler};
/// let mut s = OwenSobolBlueSampler::new(16, 7).unwrap();
/// s.start_pixel_sample([3, 5], 0, 0);
/// let a = s.get_pixel_2d();
/// s.start_pixel_sample([4, 5], 0, 0);
/// assert_ne!(s.get_pixel_2d(), a);
/// ```
#[derive(Clone, Debug)]
pub struct BlueNoiseSampler<F: BlueFamily> {
    spp: u32,
    seed: u64,
    frame: u32,
    /// The offsets of blocks 0 and 1 (the camera's five dimensions).
    offsets: [[u32; 2]; 2],
    /// The pixel whose blocks are cached (`None` before the first), and those blocks.
    pixel: Option<[u32; 2]>,
    blocks: [F::Block; 2],
    /// The sample index and what it becomes in blocks 0 and 1.
    index: u32,
    prepared: [F::Index; 2],
    dim: u32,
}

/// Owen-scrambled Sobol per pixel with blue-noise error across pixels ([`OwenSobolBlue`]):
/// `owen-sobol-bn`.
///
/// ```
/// use nyquist::sampler::{OwenSobolBlueSampler, Sampler};
/// let mut s = OwenSobolBlueSampler::new(4, 1).unwrap();
/// s.start_pixel_sample([0, 0], 3, 0);
/// assert!(s.get_2d().iter().all(|v| (0.0..1.0).contains(v)));
/// ```
pub type OwenSobolBlueSampler = BlueNoiseSampler<OwenSobolBlue>;

/// PMJ(0,2) per pixel with blue-noise error across pixels ([`Pmj02Blue`]): `pmj02-bn`.
///
/// ```
/// use nyquist::sampler::{Pmj02BlueSampler, Sampler};
/// let mut s = Pmj02BlueSampler::new(4, 1).unwrap();
/// s.start_pixel_sample([0, 0], 3, 0);
/// assert!(s.get_2d().iter().all(|v| (0.0..1.0).contains(v)));
/// ```
pub type Pmj02BlueSampler = BlueNoiseSampler<Pmj02Blue>;

/// A rank-1 lattice per pixel with blue-noise error across pixels ([`LatticeBlue`]):
/// `lattice-bn`.
///
/// ```
/// use nyquist::sampler::{LatticeBlueSampler, Sampler};
/// let mut s = LatticeBlueSampler::new(4, 1).unwrap();
/// s.start_pixel_sample([0, 0], 3, 0);
/// assert!(s.get_2d().iter().all(|v| (0.0..1.0).contains(v)));
/// ```
pub type LatticeBlueSampler = BlueNoiseSampler<LatticeBlue>;

impl<F: BlueFamily> BlueNoiseSampler<F> {
    /// A sampler made for `spp` samples per pixel (it continues past them), frame 0.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`.
    ///
    /// ```
    /// assert!(nyquist::sampler::OwenSobolBlueSampler::new(0, 1).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        Ok(BlueNoiseSampler {
            spp,
            seed,
            frame: 0,
            offsets: [0, 1].map(|b| offset(seed, 0, b)),
            pixel: None,
            blocks: [F::Block::default(); 2],
            index: 0,
            prepared: [F::Index::default(); 2],
            dim: 0,
        })
    }

    /// The same sampler in frame `frame`: every block reads the tile at the frame's offset.
    ///
    /// ```
    /// use nyquist::sampler::{OwenSobolBlueSampler, Sampler};
    /// let mut a = OwenSobolBlueSampler::new(4, 1).unwrap();
    /// let mut b = a.clone().with_frame(1);
    /// a.start_pixel_sample([0, 0], 0, 0);
    /// b.start_pixel_sample([0, 0], 0, 0);
    /// assert_ne!(a.get_2d(), b.get_2d());
    /// ```
    pub fn with_frame(mut self, frame: u32) -> Self {
        self.frame = frame;
        self.offsets = [0, 1].map(|b| offset(self.seed, frame, b));
        self.pixel = None;
        self
    }

    /// The frame.
    ///
    /// ```
    /// let s = nyquist::sampler::LatticeBlueSampler::new(4, 1).unwrap().with_frame(3);
    /// assert_eq!(s.frame(), 3);
    /// ```
    pub fn frame(&self) -> u32 {
        self.frame
    }

    /// The seed.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::Pmj02BlueSampler::new(4, 9).unwrap().seed(), 9);
    /// ```
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The block of dimensions `4b .. 4b + 4` at `pixel`, whose offset is `offset`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn block_at(pixel: [u32; 2], offset: [u32; 2]) -> F::Block {
        F::block(F::entry(
            pixel[0].wrapping_add(offset[0]),
            pixel[1].wrapping_add(offset[1]),
        ))
    }

    /// Dimension `d` of the current sample.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, d: u32) -> f32 {
        let (b, c) = (d / 4, d % 4);
        match b {
            0 | 1 => F::value(&self.blocks[b as usize], &self.prepared[b as usize], c),
            _ => {
                let pixel = self.pixel.unwrap_or_default();
                let block = Self::block_at(pixel, offset(self.seed, self.frame, b));
                F::value(&block, &F::index(&block, self.index), c)
            }
        }
    }

    /// Batched values: none; the arrays take the value-by-value path.
    fn batch(&self, _dim: u32, _out: &mut [f32]) -> bool {
        false
    }
}

impl<F: BlueFamily> Sampler for BlueNoiseSampler<F> {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if self.pixel != Some(pixel) {
            self.pixel = Some(pixel);
            self.blocks = [0, 1].map(|b| Self::block_at(pixel, self.offsets[b]));
        }
        self.prepared = [0, 1].map(|b| F::index(&self.blocks[b], sample_index));
        self.index = sample_index;
        self.dim = dim;
    }

    super::super::global_point_dimensions!();

    super::super::global_point_arrays!();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{
        arrays_are_values_in_order, consistent_values, is_zero_two_net, threads_agree,
    };
    use std::vec::Vec;

    /// In every pixel and 4-D block, over the first `2^k` samples for every `k ≤ 10`: each
    /// dimension has one value in each interval of width `2^−k`, and the pairs `nets` name
    /// (0 for dimensions 0–1, 1 for 2–3) are (0, k, 2)-nets. The camera's dimensions and far
    /// past them.
    fn every_block_is_the_familys_net<F: BlueFamily>(nets: &[usize]) {
        let mut s = BlueNoiseSampler::<F>::new(16, 3).unwrap();
        for pixel in [[0, 0], [5, 77], [300, 9]] {
            for block in [0u32, 1, 7, 1000] {
                let mut v: Vec<[f32; 4]> = Vec::new();
                for i in 0..1024u32 {
                    s.start_pixel_sample(pixel, i, 4 * block);
                    v.push([s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()]);
                    let n = i + 1;
                    if !n.is_power_of_two() {
                        continue;
                    }
                    for c in 0..4 {
                        let mut cells: Vec<u32> =
                            v.iter().map(|x| (x[c] * n as f32) as u32).collect();
                        cells.sort_unstable();
                        cells.dedup();
                        assert_eq!(cells.len(), n as usize, "{} {pixel:?} {block} {c}", F::NAME);
                    }
                    for &p in nets {
                        let pair: Vec<[f32; 2]> =
                            v.iter().map(|x| [x[2 * p], x[2 * p + 1]]).collect();
                        assert!(
                            is_zero_two_net(&pair),
                            "{} {pixel:?} block {block} {n}",
                            F::NAME
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn every_block_is_a_net_in_every_pixel() {
        every_block_is_the_familys_net::<OwenSobolBlue>(&[0]);
        every_block_is_the_familys_net::<Pmj02Blue>(&[0, 1]);
        every_block_is_the_familys_net::<LatticeBlue>(&[]);
    }

    /// Neighbouring pixels and blocks read different entries; frames move every block; the
    /// values are consistent, thread-safe and in order; every sample index is new.
    fn pixels_blocks_and_frames_differ<F: BlueFamily>() {
        let s = BlueNoiseSampler::<F>::new(4, 9).unwrap();
        let first = |s: &BlueNoiseSampler<F>, pixel: [u32; 2], dim: u32| {
            let mut s = s.clone();
            s.start_pixel_sample(pixel, 0, dim);
            s.get_2d()
        };
        assert_ne!(first(&s, [0, 0], 0), first(&s, [1, 0], 0));
        assert_ne!(first(&s, [0, 0], 0), first(&s, [0, 0], 4));
        let f1 = s.clone().with_frame(1);
        assert_eq!(s.frame(), 0);
        assert_eq!(f1.frame(), 1);
        assert_eq!(f1.seed(), 9);
        assert_ne!(first(&s, [0, 0], 0), first(&f1, [0, 0], 0));
        assert_ne!(first(&s, [0, 0], 8), first(&f1, [0, 0], 8));
        // The tile wraps: pixel (x + 128, y) is pixel (x, y).
        assert_eq!(first(&s, [3, 4], 0), first(&s, [131, 4], 0));
        consistent_values(&s);
        threads_agree(&s);
        arrays_are_values_in_order(&s);
        let mut c = s.clone();
        let mut seen: Vec<[u32; 2]> = (0..1 << 17)
            .map(|i| {
                c.start_pixel_sample([2, 2], i, 0);
                c.get_pixel_2d().map(f32::to_bits)
            })
            .collect();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), 1 << 17, "{}", F::NAME);
        assert_eq!(
            BlueNoiseSampler::<F>::new(0, 1).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
        assert_eq!(s.samples_per_pixel(), 4);
    }

    #[test]
    fn pixels_blocks_and_frames_differ_in_every_family() {
        pixels_blocks_and_frames_differ::<OwenSobolBlue>();
        pixels_blocks_and_frames_differ::<Pmj02Blue>();
        pixels_blocks_and_frames_differ::<LatticeBlue>();
    }

    /// The sampler's values, pinned: ten dimensions of one sample (blocks 0, 1 and 2).
    #[test]
    fn values_are_pinned() {
        fn ten<F: BlueFamily>() -> Vec<u32> {
            let mut s = BlueNoiseSampler::<F>::new(4, 9).unwrap();
            s.start_pixel_sample([3, 4], 5, 0);
            (0..10).map(|_| s.get_1d().to_bits()).collect()
        }
        let got = [
            ten::<OwenSobolBlue>(),
            ten::<Pmj02Blue>(),
            ten::<LatticeBlue>(),
        ];
        assert_eq!(
            got,
            [
                [
                    0x3f78_52d9,
                    0x3f03_0fc3,
                    0x3e77_16e8,
                    0x3f5b_4063,
                    0x3eb1_63cc,
                    0x3f6c_a645,
                    0x3ecc_5536,
                    0x3f1a_3b71,
                    0x3cff_8bc0,
                    0x3f6d_dbd1
                ],
                [
                    0x3ebb_93fe,
                    0x3e3f_62e4,
                    0x3f5b_62e0,
                    0x3f1f_411c,
                    0x3f54_a6b1,
                    0x3f0b_f7bd,
                    0x3e29_6b9c,
                    0x3f71_5fef,
                    0x3f3f_7ec6,
                    0x3e8c_45e0
                ],
                [
                    0x3dd9_5be0,
                    0x3f14_f4fc,
                    0x3f36_add2,
                    0x3f70_dcd8,
                    0x3f58_5806,
                    0x3eee_05b8,
                    0x3f29_dd12,
                    0x3d43_e010,
                    0x3ecc_c812,
                    0x3efb_dcb2
                ]
            ]
        );
    }

    /// The values the optimiser integrates are block 0's at the pixel's entry.
    fn optimiser_values_are_block_zero<F: BlueFamily>() {
        let mut s = BlueNoiseSampler::<F>::new(8, 21).unwrap();
        let o = offset(21, 0, 0);
        for (pixel, i) in [([0u32, 0u32], 0u32), ([17, 99], 5), ([127, 127], 200)] {
            s.start_pixel_sample(pixel, i, 0);
            let v = [s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()];
            let e = F::entry(pixel[0] + o[0], pixel[1] + o[1]);
            assert_eq!(F::values(e, i), v, "{}", F::NAME);
        }
    }

    #[test]
    fn optimiser_values_are_block_zero_in_every_family() {
        optimiser_values_are_block_zero::<OwenSobolBlue>();
        optimiser_values_are_block_zero::<Pmj02Blue>();
        optimiser_values_are_block_zero::<LatticeBlue>();
    }
}
