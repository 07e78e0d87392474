//! The PMJ(0,2) family of the blue-noise samplers.

use super::{BlueFamily, TileBytes, read, shift};
use crate::hash::mix32;
use crate::math::fraction_to_f32;
use crate::sequence::IndexShuffle;

/// Coordinate `dim` of the pmj02 table's point `index` ([`PMJ02_TABLE`](crate::sequence::PMJ02_TABLE)):
/// a read of the 512 KiB table, or, where the build keeps tables and code small (`lazy-tables`,
/// `small-code`: the explorer, firmware), the point rebuilt from its construction
/// ([`compact::Pmj02Sampler`](crate::compact::Pmj02Sampler)'s, at most 17 generator draws), the
/// same bits. The branch is a constant, so an optimised build links one of the two.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn table_point(index: u16, dim: usize) -> u32 {
    if cfg!(any(feature = "lazy-tables", feature = "small-code")) {
        crate::compact::pmj02_point(crate::sequence::PMJ02_TABLE_SEED, u32::from(index), dim)
    } else {
        crate::sequence::PMJ02_TABLE[usize::from(index)][dim]
    }
}

/// The optimised tile of [`Pmj02Blue`].
static TILE: TileBytes = include!("pmj02_tile.in");

/// Progressive multi-jittered (0,2) points in 4-D blocks: a block is two pairs, each a point
/// of the baked pmj02 table ([`PMJ02_TABLE`](crate::sequence::PMJ02_TABLE)) at a nested uniform shuffle of the index, its
/// coordinates XOR-ed with a random digital shift, with shuffles and shifts hashed from the
/// entry's key and the pair. So each pair is a (0, k, 2)-net at every `2^k` (the shuffle maps
/// the first `2^k` samples onto an aligned block of the table, which is a net, and a digital
/// shift keeps a net a net), and the two pairs are shuffled independently.
///
/// A digital shift, not an Owen scramble (which [`Pmj02Sampler`](crate::sampler::Pmj02Sampler)
/// applies): it keeps the table's jitter below the net's strata, which is what makes a pmj02
/// set's error lower than an Owen-scrambled Sobol net's (docs/blue-noise.md measures it). Past
/// 65536 samples (the table) each epoch of 65536 is hashed anew.
///
/// ```
/// use nyquist::sampler::screen_blue::{BlueFamily, Pmj02Blue};
/// let v = Pmj02Blue::values(Pmj02Blue::entry(1, 2), 7);
/// assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Pmj02Blue;

/// One 4-D block's randomisation in one epoch of 65536 samples: the rank, the two pairs'
/// index shuffles and the four coordinates' digital shifts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pmj02Block {
    rank: u32,
    key: u32,
    shuffles: [IndexShuffle; 2],
    shifts: [u32; 4],
}

impl Pmj02Block {
    /// The block of hashed key `key` in `epoch`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn new(rank: u32, key: u32, epoch: u32) -> Pmj02Block {
        let k = if epoch == 0 {
            key
        } else {
            mix32(key ^ mix32(epoch))
        };
        Pmj02Block {
            rank,
            key,
            shuffles: [0x5348_5546u32, 0x5348_5547].map(|t| IndexShuffle::new(mix32(k ^ t))), // "SHUF"
            shifts: [0, 1, 2, 3].map(|c| shift(k, c)),
        }
    }
}

/// A sample of a block: each pair's table index, and the epoch (`index >> 16`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pmj02Index {
    points: [u16; 2],
    epoch: u32,
}

impl BlueFamily for Pmj02Blue {
    type Block = Pmj02Block;
    type Index = Pmj02Index;
    const NAME: &'static str = "pmj02-bn";

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn entry(x: u32, y: u32) -> u32 {
        read(&TILE, x, y)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn block(entry: u32) -> Pmj02Block {
        Pmj02Block::new(entry & 0xff, mix32((entry >> 8) ^ 0x504d_4a00), 0) // "PMJ"
    }

    /// The rank XOR-ed into the index, then each pair's shuffled table index: the shuffle of
    /// the index's low 16 bits within `0 .. 2^16`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn index(b: &Pmj02Block, index: u32) -> Pmj02Index {
        let index = index ^ b.rank;
        let epoch = index >> 16;
        let point =
            |b: &Pmj02Block, p: usize| (b.shuffles[p].rev(index & 0xffff).reverse_bits()) as u16;
        let points = if epoch == 0 {
            [point(b, 0), point(b, 1)]
        } else {
            let e = Pmj02Block::new(b.rank, b.key, epoch);
            [point(&e, 0), point(&e, 1)]
        };
        Pmj02Index { points, epoch }
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value(b: &Pmj02Block, i: &Pmj02Index, c: u32) -> f32 {
        let shift = if i.epoch == 0 {
            b.shifts[c as usize]
        } else {
            Pmj02Block::new(b.rank, b.key, i.epoch).shifts[c as usize]
        };
        let point = table_point(i.points[(c / 2) as usize], (c % 2) as usize);
        fraction_to_f32(point ^ shift)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::screen_blue::{TILE_SIZE, initial_entry};
    use std::vec::Vec;

    /// The shipped tile is pinned, wraps, and permutes the optimiser's starting keys.
    #[test]
    fn the_tile_is_pinned_wraps_and_permutes_the_initial_keys() {
        let entry = Pmj02Blue::entry;
        assert_eq!(
            [entry(0, 0), entry(127, 0), entry(5, 77)],
            [0x29_8c48, 0x3f_81ac, 0x33_f477]
        );
        assert_eq!(entry(5 + 128, 77 + 256), entry(5, 77));
        let mut got: Vec<u32> = (0..TILE_SIZE * TILE_SIZE)
            .map(|i| entry(i % TILE_SIZE, i / TILE_SIZE) & !0xff)
            .collect();
        let mut want: Vec<u32> = (0..TILE_SIZE * TILE_SIZE).map(initial_entry).collect();
        assert_ne!(got, want, "optimised, not in slot order");
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want);
    }

    /// Values past the first epoch differ from the first epoch's at the same index modulo
    /// 65536, and stay in `[0, 1)`; one is pinned, and the table point it reads is the
    /// construction's.
    #[test]
    fn epochs_are_hashed_anew() {
        assert_eq!(
            Pmj02Blue::values(initial_entry(9) | 3, (1 << 16) + 5).map(f32::to_bits),
            [1_064_906_222, 1_062_764_139, 1_061_935_310, 1_058_609_525]
        );
        for (i, d) in [(0u16, 0usize), (1, 1), (777, 0), (65535, 1)] {
            assert_eq!(
                table_point(i, d),
                crate::sequence::PMJ02_TABLE[usize::from(i)][d]
            );
        }
        let e = initial_entry(9) | 3;
        for i in [0u32, 1, 77] {
            let a = Pmj02Blue::values(e, i);
            let b = Pmj02Blue::values(e, i + (1 << 16));
            assert_ne!(a, b);
            assert!(b.iter().all(|v| (0.0..1.0).contains(v)));
        }
    }
}
