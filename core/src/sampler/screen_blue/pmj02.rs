//! The PMJ(0,2) family of the blue-noise samplers.

use super::{BlueFamily, TileBytes, read};
use crate::hash::{hash2, mix32};
use crate::sampler::Pmj02Keys;
use crate::scramble::reverse16;

/// The optimised tile of [`Pmj02Blue`].
static TILE: TileBytes = include!("pmj02_tile.in");

/// Progressive multi-jittered (0,2) points in 4-D blocks: a block is two pairs, each a point
/// of the baked pmj02 table ([`PMJ02_TABLE`](crate::sequence::PMJ02_TABLE)) at a nested
/// uniform shuffle of the index, its coordinates Owen-scrambled, with keys hashed from the
/// entry's key and the pair (the [`Pmj02Sampler`](crate::sampler::Pmj02Sampler)'s
/// randomisation). So each pair is a (0, k, 2)-net at every `2^k`, and the two pairs are
/// shuffled independently. Past 65536 samples (the table) each epoch of 65536 is hashed anew.
///
/// ```
/// use nyquist::sampler::screen_blue::{BlueFamily, Pmj02Blue};
/// let v = Pmj02Blue::values(Pmj02Blue::entry(1, 2), 7);
/// assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Pmj02Blue;

/// One 4-D block's randomisation: the rank, the entry's hashed key, and the two pairs' keys in
/// the first epoch.
#[derive(Clone, Copy, Debug, Default)]
pub struct Pmj02Block {
    rank: u32,
    key: u64,
    pairs: [Pmj02Keys; 2],
}

/// A sample of a block: each pair's table row, and the epoch (`index >> 16`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Pmj02Index {
    rows: [u16; 2],
    epoch: u32,
}

/// The two pairs' keys of `key` in `epoch`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn pair_keys(key: u64, epoch: u32) -> [Pmj02Keys; 2] {
    let key = if epoch == 0 {
        key
    } else {
        hash2(key, u64::from(epoch))
    };
    [0, 1].map(|p| Pmj02Keys::new(key, p))
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
        let key = u64::from(mix32((entry >> 8) ^ 0x504d_4a00)); // "PMJ"
        Pmj02Block {
            rank: entry & 0xff,
            key,
            pairs: pair_keys(key, 0),
        }
    }

    /// The rank XOR-ed into the index, then each pair's shuffled table row.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn index(b: &Pmj02Block, index: u32) -> Pmj02Index {
        let index = index ^ b.rank;
        let epoch = index >> 16;
        let rev = reverse16(index) << 16;
        let rows = if epoch == 0 {
            b.pairs.map(|k| k.row(rev) as u16)
        } else {
            pair_keys(b.key, epoch).map(|k| k.row(rev) as u16)
        };
        Pmj02Index { rows, epoch }
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value(b: &Pmj02Block, i: &Pmj02Index, c: u32) -> f32 {
        let pair = (c / 2) as usize;
        let row = usize::from(i.rows[pair]);
        if i.epoch == 0 {
            b.pairs[pair].coordinate(row, (c % 2) as usize)
        } else {
            pair_keys(b.key, i.epoch)[pair].coordinate(row, (c % 2) as usize)
        }
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
            [0x06_0344, 0x20_c19d, 0x0c_e40c]
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
    /// 65536, and stay in `[0, 1)`.
    #[test]
    fn epochs_are_hashed_anew() {
        let e = initial_entry(9) | 3;
        for i in [0u32, 1, 77] {
            let a = Pmj02Blue::values(e, i);
            let b = Pmj02Blue::values(e, i + (1 << 16));
            assert_ne!(a, b);
            assert!(b.iter().all(|v| (0.0..1.0).contains(v)));
        }
    }
}
