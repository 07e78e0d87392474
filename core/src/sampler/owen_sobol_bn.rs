//! Owen-scrambled Sobol per pixel with blue-noise error across pixels: the pixels' scrambles
//! come from the optimised tile of [`super::screen_blue`].

use super::Sampler;
use super::screen_blue::{entry, offset};
use crate::Error;
use crate::hash::mix32;
use crate::lazy_table::{baked_table, const_unless_lazy};
use crate::scramble::{lk_hash, rev_to_f32};
use crate::sequence::{DimSeeds, IndexShuffle, SOBOL_MATRICES};

/// One 4-D block's scramble: the rank, index shuffle and four dimensions' seeds of a tile
/// entry.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Block {
    rank: u32,
    shuffle: IndexShuffle,
    seeds: [u32; 4],
}

impl Block {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn new(entry: u32) -> Block {
        let key = mix32((entry >> 8) ^ 0x424c_4b00); // "BLK"
        Block {
            rank: entry & 0xff,
            shuffle: IndexShuffle::new(mix32(key ^ 0x5348_5546)), // "SHUF"
            seeds: *DimSeeds::<4>::new(key).kept(),
        }
    }

    /// The reversed shuffled index of sample `index`: the rank XOR-ed in first.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn rev(&self, index: u32) -> u32 {
        self.shuffle.rev(index ^ self.rank)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value(&self, rev: u32, component: u32) -> f32 {
        let c = component as usize;
        rev_to_f32(lk_hash(block_product_rev(rev, c), self.seeds[c]))
    }
}

baked_table! {
    /// `BLOCK_REVERSED[n][v][d]`: the bit-reversed XOR of Sobol dimension `d`'s columns
    /// `31 − 4n − m` over the set bits `m` of `v`, so that a block's value at a reversed index
    /// is eight reads (2 KiB: the sampler carries four dimensions' columns, not the 1024 of
    /// the Owen-Sobol tables).
    static BLOCK_REVERSED: [[[u32; 4]; 16]; 8] = [[[0; 4]; 16]; 8], block_reversed,
        block_reversed_at_first_use_equals_the_baked_table;
}

const_unless_lazy! {
    fn block_reversed(t: &mut [[[u32; 4]; 16]; 8]) {
        let mut n = 0;
        while n < 8 {
            let mut v = 1;
            while v < 16 {
                let m = (v as u32).trailing_zeros() as usize;
                let mut d = 0;
                while d < 4 {
                    t[n][v][d] =
                        t[n][v & (v - 1)][d] ^ SOBOL_MATRICES[d][31 - 4 * n - m].reverse_bits();
                    d += 1;
                }
                v += 1;
            }
            n += 1;
        }
    }
}

/// Sobol dimension `d < 4`, bit-reversed, at the index whose reversal is `rev`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn block_product_rev(rev: u32, d: usize) -> u32 {
    let t = &BLOCK_REVERSED;
    let mut out = 0;
    let mut n = 0;
    while n < 8 {
        out ^= t[n][((rev >> (4 * n)) & 15) as usize][d];
        n += 1;
    }
    out
}

/// Owen-scrambled Sobol samples whose error is blue noise across the screen (Heitz et al.
/// 2019; Belcour and Heitz 2021): each pixel's samples are an Owen-scrambled Sobol net, as
/// [`OwenSobolSampler`](super::OwenSobolSampler)'s are, and the scrambles are laid out so that
/// neighbouring pixels' errors differ.
///
/// Dimensions go in 4-D blocks: dimension `d` is Sobol dimension `d mod 4` of block `d / 4`,
/// scrambled and index-shuffled by the [tile](super::screen_blue) key at the pixel plus the
/// block's offset. So the camera's image sample (0, 1), time and lens (2 … 4), and every later
/// pair and 4-D block, are each a (0, k, 2)-net in every pixel for every `k`, and blue across
/// pixels at 1 to 256 spp. Every sample index is a new sample, so the sampler continues past
/// its `spp`.
///
/// `with_frame` moves every block's offset by the frame's point of Roberts' R2 sequence: each
/// frame is blue, and consecutive frames read unrelated keys.
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
pub struct OwenSobolBlueSampler {
    spp: u32,
    seed: u64,
    frame: u32,
    /// The offsets of blocks 0 and 1 (the camera's five dimensions).
    offsets: [[u32; 2]; 2],
    /// The pixel whose blocks are cached (`None` before the first), and those blocks.
    pixel: Option<[u32; 2]>,
    blocks: [Block; 2],
    /// The sample index and its reversed shuffled index in blocks 0 and 1.
    index: u32,
    rev: [u32; 2],
    dim: u32,
}

impl OwenSobolBlueSampler {
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
        let mut s = OwenSobolBlueSampler {
            spp,
            seed,
            frame: 0,
            offsets: [[0; 2]; 2],
            pixel: None,
            blocks: [Block::default(); 2],
            index: 0,
            rev: [0; 2],
            dim: 0,
        };
        s.offsets = [0, 1].map(|b| offset(seed, 0, b));
        Ok(s)
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
    pub fn frame(&self) -> u32 {
        self.frame
    }

    /// The seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The block of dimensions `4b .. 4b + 4` at `pixel`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn block_at(&self, pixel: [u32; 2], offset: [u32; 2]) -> Block {
        Block::new(entry(
            pixel[0].wrapping_add(offset[0]),
            pixel[1].wrapping_add(offset[1]),
        ))
    }

    /// Dimension `d` of the current sample.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, d: u32) -> f32 {
        let (b, c) = (d / 4, d % 4);
        match b {
            0 | 1 => self.blocks[b as usize].value(self.rev[b as usize], c),
            _ => {
                let pixel = self.pixel.unwrap_or_default();
                let block = self.block_at(pixel, offset(self.seed, self.frame, b));
                block.value(block.rev(self.index), c)
            }
        }
    }

    /// Batched values: none; the arrays take the value-by-value path.
    fn batch(&self, _dim: u32, _out: &mut [f32]) -> bool {
        false
    }
}

impl Sampler for OwenSobolBlueSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if self.pixel != Some(pixel) {
            self.pixel = Some(pixel);
            self.blocks = [0, 1].map(|b| self.block_at(pixel, self.offsets[b]));
        }
        self.rev = [0, 1].map(|b| self.blocks[b].rev(sample_index));
        self.index = sample_index;
        self.dim = dim;
    }

    super::global_point_dimensions!();

    super::global_point_arrays!();
}

/// The values of dimensions `0..4` at sample `index` of a pixel whose tile entry is `entry`:
/// what the blue-noise optimiser integrates (the sampler's block 0 at that pixel).
///
/// ```
/// use nyquist::sampler::{OwenSobolBlueSampler, Sampler, screen_blue};
/// let mut s = OwenSobolBlueSampler::new(4, 0).unwrap();
/// s.start_pixel_sample([5, 9], 3, 0);
/// let [x, y] = s.get_2d();
/// let o = screen_blue::offset(0, 0, 0);
/// let e = screen_blue::entry(5 + o[0], 9 + o[1]);
/// let v = nyquist::sampler::owen_sobol_blue_values(e, 3);
/// assert_eq!([v[0], v[1]], [x, y]);
/// ```
pub fn owen_sobol_blue_values(entry: u32, index: u32) -> [f32; 4] {
    let b = Block::new(entry);
    let rev = b.rev(index);
    core::array::from_fn(|c| b.value(rev, c as u32))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::screen_blue::{TILE_SIZE, initial_entry};
    use crate::sampler::tests::{
        arrays_are_values_in_order, consistent_values, is_zero_two_net, progressive_nets,
        threads_agree,
    };
    use std::vec::Vec;

    /// The shipped tile's keys are a permutation of the optimiser's starting keys, and some
    /// ranks are not 0.
    #[test]
    fn the_tile_permutes_the_initial_keys() {
        let entries: Vec<u32> = (0..TILE_SIZE * TILE_SIZE)
            .map(|i| entry(i % TILE_SIZE, i / TILE_SIZE))
            .collect();
        assert!(entries.iter().any(|e| e & 0xff != 0));
        let mut got: Vec<u32> = entries.iter().map(|e| e & !0xff).collect();
        let mut want: Vec<u32> = (0..TILE_SIZE * TILE_SIZE).map(initial_entry).collect();
        assert_ne!(got, want, "optimised, not in slot order");
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want);
    }

    /// In every pixel, each 4-D block's first pair is a (0, k, 2)-net over the first `2^k`
    /// samples for every `k ≤ 10`, and its other two dimensions are stratified in `2^k`
    /// intervals: the nets of Owen-scrambled Sobol, in the camera's dimensions and far past
    /// them.
    #[test]
    fn every_block_is_a_net_in_every_pixel() {
        let mut s = OwenSobolBlueSampler::new(16, 3).unwrap();
        for pixel in [[0, 0], [5, 77], [300, 9]] {
            progressive_nets(&mut s, pixel, Some(4), 10);
            for block in [0u32, 1, 7, 1000] {
                let mut pair = Vec::new();
                let mut third = Vec::new();
                for i in 0..1024u32 {
                    s.start_pixel_sample(pixel, i, 4 * block);
                    pair.push(s.get_2d());
                    third.push(s.get_2d());
                    let n = i + 1;
                    if n.is_power_of_two() {
                        assert!(is_zero_two_net(&pair), "{pixel:?} block {block} {n}");
                        for c in 0..2 {
                            let mut cells: Vec<u32> =
                                third.iter().map(|v| (v[c] * n as f32) as u32).collect();
                            cells.sort_unstable();
                            cells.dedup();
                            assert_eq!(cells.len(), n as usize, "{pixel:?} block {block}");
                        }
                    }
                }
            }
        }
    }

    /// Neighbouring pixels and blocks read different keys; frames move every block; the camera
    /// sample is the values in order; every sample index is new.
    #[test]
    fn pixels_blocks_and_frames_differ() {
        let s = OwenSobolBlueSampler::new(4, 9).unwrap();
        let first = |s: &OwenSobolBlueSampler, pixel: [u32; 2], dim: u32| {
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
        let mut seen: Vec<[u32; 2]> = (0..1 << 16)
            .map(|i| {
                c.start_pixel_sample([2, 2], i, 0);
                c.get_pixel_2d().map(f32::to_bits)
            })
            .collect();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), 1 << 16);
        assert_eq!(
            OwenSobolBlueSampler::new(0, 1).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
        assert_eq!(s.samples_per_pixel(), 4);
    }

    /// The block's nibble table gives the Owen-Sobol sequence's values (its 1024-dimension
    /// tables) for the four dimensions, at indices over all 32 bits.
    #[test]
    fn block_values_are_owen_sobols() {
        let mut x = 0x1234_5678u32;
        for _ in 0..4096 {
            x = crate::hash::mix32(x.wrapping_add(0x9e37_79b9));
            for d in 0..4u32 {
                let seed = crate::hash::mix32(x ^ d);
                let b = Block {
                    rank: 0,
                    shuffle: IndexShuffle::new(1),
                    seeds: [seed; 4],
                };
                assert_eq!(
                    b.value(x, d),
                    crate::sequence::owen_sobol_rev_f32(x, d, seed),
                    "{x:#x} {d}"
                );
            }
        }
    }

    /// The sampler's values, pinned: ten dimensions of one sample (blocks 0, 1 and 2), and the
    /// optimiser's values of one entry.
    #[test]
    fn values_are_pinned() {
        let mut s = OwenSobolBlueSampler::new(4, 9).unwrap();
        s.start_pixel_sample([3, 4], 5, 0);
        let v: Vec<u32> = (0..10).map(|_| s.get_1d().to_bits()).collect();
        assert_eq!(
            v,
            [
                0x3e5a_e6b4,
                0x3f15_21e8,
                0x3e03_05a0,
                0x3f13_f8bb,
                0x3eb3_a0a6,
                0x3f6c_1d19,
                0x3e9a_b0ac,
                0x3f6c_2a72,
                0x3d32_b310,
                0x3f27_ee70
            ]
        );
        assert_eq!(
            owen_sobol_blue_values(entry(3, 4), 5).map(f32::to_bits),
            [1_043_493_632, 1_062_860_919, 1_033_604_872, 1_061_669_637]
        );
    }

    /// The values the optimiser integrates are block 0's at the pixel's key.
    #[test]
    fn optimiser_values_are_block_zero() {
        let mut s = OwenSobolBlueSampler::new(8, 21).unwrap();
        let o = offset(21, 0, 0);
        for (pixel, i) in [([0u32, 0u32], 0u32), ([17, 99], 5), ([127, 127], 200)] {
            s.start_pixel_sample(pixel, i, 0);
            let v = [s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()];
            let e = entry(pixel[0] + o[0], pixel[1] + o[1]);
            assert_eq!(owen_sobol_blue_values(e, i), v);
        }
    }
}
