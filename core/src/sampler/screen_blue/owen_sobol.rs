//! The Owen-scrambled Sobol family of the blue-noise samplers.

use super::{BlueFamily, TileBytes, read};
use crate::hash::mix32;
use crate::lazy_table::{baked_table, const_unless_lazy};
use crate::scramble::{lk_hash, rev_to_f32};
use crate::sequence::{DimSeeds, IndexShuffle, SOBOL_MATRICES};

/// The optimised tile of [`OwenSobolBlue`].
static TILE: TileBytes = include!("owen_sobol_tile.in");

/// Owen-scrambled Sobol in 4-D blocks: a block is Sobol dimensions 0 … 3, each Owen-scrambled
/// by its own seed and the index shuffled by a nested uniform shuffle, all hashed from the
/// entry's key. So each pair and each block is a (0, k, 2)-net, (t, k, 4)-net, at every
/// `2^k` (the [`OwenSobolSampler`](crate::sampler::OwenSobolSampler)'s construction).
///
/// ```
/// use nyquist::sampler::screen_blue::{BlueFamily, OwenSobolBlue};
/// let e = OwenSobolBlue::entry(0, 0);
/// assert_eq!(e, OwenSobolBlue::entry(128, 256));
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct OwenSobolBlue;

/// One 4-D block's scramble: the rank, index shuffle and four dimensions' seeds of an entry.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OwenSobolBlock {
    rank: u32,
    shuffle: IndexShuffle,
    seeds: [u32; 4],
}

impl BlueFamily for OwenSobolBlue {
    type Block = OwenSobolBlock;
    /// The reversed shuffled index.
    type Index = u32;
    const NAME: &'static str = "owen-sobol-bn";

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn entry(x: u32, y: u32) -> u32 {
        read(&TILE, x, y)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn block(entry: u32) -> OwenSobolBlock {
        let key = mix32((entry >> 8) ^ 0x424c_4b00); // "BLK"
        OwenSobolBlock {
            rank: entry & 0xff,
            shuffle: IndexShuffle::new(mix32(key ^ 0x5348_5546)), // "SHUF"
            seeds: *DimSeeds::<4>::new(key).kept(),
        }
    }

    /// The reversed shuffled index, the rank XOR-ed in first.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn index(b: &OwenSobolBlock, index: u32) -> u32 {
        b.shuffle.rev(index ^ b.rank)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value(b: &OwenSobolBlock, rev: &u32, c: u32) -> f32 {
        let c = c as usize;
        rev_to_f32(lk_hash(block_product_rev(*rev, c), b.seeds[c]))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::screen_blue::{TILE_SIZE, initial_entry};
    use std::vec::Vec;

    /// The shipped tile, pinned at three pixels, read as a torus; its keys are a permutation
    /// of the optimiser's starting keys, and some ranks are not 0.
    #[test]
    fn the_tile_is_pinned_wraps_and_permutes_the_initial_keys() {
        let entry = OwenSobolBlue::entry;
        assert_eq!(entry(0, 0), 0x3d_81ca);
        assert_eq!(entry(127, 0), 0x0c_1057);
        assert_eq!(entry(5, 77), 0x21_89b0);
        assert_eq!(entry(5 + 128, 77 + 256), entry(5, 77));
        assert_eq!(entry(128, 0), entry(0, 0));
        assert_eq!(entry(0, 128 * 7), entry(0, 0));
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

    /// The block's nibble table gives the Owen-Sobol sequence's values (its 1024-dimension
    /// tables) for the four dimensions, at indices over all 32 bits.
    #[test]
    fn block_values_are_owen_sobols() {
        let mut x = 0x1234_5678u32;
        for _ in 0..4096 {
            x = mix32(x.wrapping_add(0x9e37_79b9));
            for d in 0..4u32 {
                let seed = mix32(x ^ d);
                let b = OwenSobolBlock {
                    rank: 0,
                    shuffle: IndexShuffle::new(1),
                    seeds: [seed; 4],
                };
                assert_eq!(
                    OwenSobolBlue::value(&b, &x, d),
                    crate::sequence::owen_sobol_rev_f32(x, d, seed),
                    "{x:#x} {d}"
                );
            }
        }
    }

    /// The optimiser's values of one entry, pinned.
    #[test]
    fn values_are_pinned() {
        assert_eq!(
            OwenSobolBlue::values(OwenSobolBlue::entry(3, 4), 5).map(f32::to_bits),
            [1_064_477_725, 1_056_348_880, 1_058_578_648, 1_040_250_296]
        );
    }
}
