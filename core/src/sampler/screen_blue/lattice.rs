//! The rank-1 lattice family of the blue-noise samplers.

use super::{BlueFamily, TileBytes, read, shift};
use crate::hash::mix32;
use crate::math::fraction_to_f32;
use crate::sequence::IndexShuffle;

/// The optimised tile of [`LatticeBlue`].
static TILE: TileBytes = include!("lattice_tile.in");

/// The generating vector of the 4-D rank-1 lattice: Hickernell, Kritzer, Kuo and Nuyens
/// (2011), "Weighted compound integration rules with higher order convergence for all N", as
/// OpenQMC's `rank1.h` uses it. All four are odd, so each coordinate of the first `2^k`
/// points is one point per interval of width `2^−k`.
pub const LATTICE_GENERATOR: [u32; 4] = [1, 364_981, 245_389, 97_823];

/// An extensible rank-1 lattice in 4-D blocks: sample `i` of a block is
/// `frac(φ₂(s(i)) · g + Δ)`, with `g` the [`LATTICE_GENERATOR`], `φ₂` the base-2 radical
/// inverse, `s` a nested uniform shuffle of the index and `Δ` a Cranley–Patterson shift, both
/// hashed from the entry's key. The first `2^k` samples are a shifted rank-1 lattice of `2^k`
/// points for every `k` (the shuffle maps them onto an aligned block of `2^k` indices, whose
/// radical inverses are the multiples of `2^−k` plus one offset), computed in 32-bit fixed
/// point: a multiply and an add per value.
///
/// ```
/// use nyquist::sampler::screen_blue::{BlueFamily, LatticeBlue};
/// let v = LatticeBlue::values(LatticeBlue::entry(1, 2), 7);
/// assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct LatticeBlue;

/// One 4-D block's randomisation: the rank, the index shuffle and the shift.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LatticeBlock {
    rank: u32,
    shuffle: IndexShuffle,
    shift: [u32; 4],
}

impl LatticeBlue {
    /// Component `c` of the sample whose reversed shuffled index is `rev`, as a 32-bit
    /// fraction.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn fixed(b: &LatticeBlock, rev: u32, c: u32) -> u32 {
        let c = c as usize;
        rev.wrapping_mul(LATTICE_GENERATOR[c])
            .wrapping_add(b.shift[c])
    }
}

impl BlueFamily for LatticeBlue {
    type Block = LatticeBlock;
    /// The reversed shuffled index: `φ₂(s(i))` as a 32-bit fraction.
    type Index = u32;
    const NAME: &'static str = "lattice-bn";

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn entry(x: u32, y: u32) -> u32 {
        read(&TILE, x, y)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn block(entry: u32) -> LatticeBlock {
        let key = mix32((entry >> 8) ^ 0x4c41_5400); // "LAT"
        LatticeBlock {
            rank: entry & 0xff,
            shuffle: IndexShuffle::new(mix32(key ^ 0x5348_5546)), // "SHUF"
            shift: [0, 1, 2, 3].map(|c| shift(key, c)),
        }
    }

    /// The reversed shuffled index, the rank XOR-ed in first.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn index(b: &LatticeBlock, index: u32) -> u32 {
        b.shuffle.rev(index ^ b.rank)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value(b: &LatticeBlock, rev: &u32, c: u32) -> f32 {
        fraction_to_f32(Self::fixed(b, *rev, c))
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
        let entry = LatticeBlue::entry;
        assert_eq!(
            [entry(0, 0), entry(127, 0), entry(5, 77)],
            [0x34_d644, 0x16_5d63, 0x27_042c]
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

    /// For every entry tried and every `k ≤ 12`, the first `2^k` samples are the rank-1
    /// lattice `{ j · 2^−k · g }` shifted by one vector: their radical inverses are the `2^k`
    /// multiples of `2^(32−k)` plus one common offset, so `x_c − g_c · x_0` is the same for
    /// every sample, and each coordinate has one point per interval of width `2^−k`.
    #[test]
    fn every_power_of_two_prefix_is_a_shifted_lattice() {
        for entry in [0u32, 0x12_3456, initial_entry(16383) | 0xff, 0x3f_00a5] {
            let b = LatticeBlue::block(entry);
            for k in 0..=12u32 {
                let n = 1u32 << k;
                let revs: Vec<u32> = (0..n).map(|i| LatticeBlue::index(&b, i)).collect();
                let low = if k == 0 {
                    u32::MAX
                } else {
                    (1u32 << (32 - k)) - 1
                };
                let mut high: Vec<u32> = revs.iter().map(|r| r & !low).collect();
                high.sort_unstable();
                high.dedup();
                assert_eq!(high.len(), n as usize, "{entry:#x} {k}");
                assert!(revs.iter().all(|r| r & low == revs[0] & low));
                for c in 1..4 {
                    let d: Vec<u32> = revs
                        .iter()
                        .map(|&r| {
                            LatticeBlue::fixed(&b, r, c).wrapping_sub(
                                LATTICE_GENERATOR[c as usize]
                                    .wrapping_mul(LatticeBlue::fixed(&b, r, 0)),
                            )
                        })
                        .collect();
                    assert!(d.iter().all(|&v| v == d[0]), "{entry:#x} {k} {c}");
                }
                for c in 0..4 {
                    let mut cells: Vec<u32> = revs
                        .iter()
                        .map(|&r| (LatticeBlue::value(&b, &r, c) * n as f32) as u32)
                        .collect();
                    cells.sort_unstable();
                    cells.dedup();
                    assert_eq!(cells.len(), n as usize, "{entry:#x} {k} {c}");
                }
            }
        }
    }

    /// Pinned values of one entry.
    #[test]
    fn values_are_pinned() {
        let v = LatticeBlue::values(0x12_3456, 5).map(f32::to_bits);
        assert_eq!(
            v,
            [1_057_093_664, 1_020_525_088, 1_042_591_752, 1_059_967_209]
        );
    }
}
