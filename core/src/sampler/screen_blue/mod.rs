//! Screen-space blue-noise samplers: per-pixel scrambled nets whose errors are blue noise
//! across the screen (Heitz, Belcour, Ostromoukhov, Coeurjolly and Iehl 2019; Belcour and
//! Heitz 2021).
//!
//! Each pixel's samples are a randomised net of one *family* ([`BlueFamily`]): Owen-scrambled
//! Sobol ([`OwenSobolBlue`]), PMJ(0,2) ([`Pmj02Blue`]) or a rank-1 lattice ([`LatticeBlue`]).
//! Which randomisation a pixel gets comes from its family's *tile*: one entry per pixel of a
//! 128 × 128 torus, optimised so that the pixels' errors on test integrands are blue.
//!
//! An entry is a 24-bit *key* and an 8-bit *rank*, `key << 8 | rank`. The key seeds the
//! pixel's scramble and index shuffle; the rank is XOR-ed into the sample index, which picks
//! the aligned block of `n` points the pixel's first `n` samples are (for `n ≤ 128`), so every
//! prefix of a power of two is still a net.
//!
//! The optimiser (`cargo run --release -p nyquist-lab --bin blue-tile`, `docs/blue-noise.md`)
//! starts from the keys `0 … 128² − 1` in slot order, rank 0 ([`initial_entry`]), and lowers
//! the Gaussian-weighted correlation of neighbouring pixels' errors over test integrands,
//! which is the error image's power at low frequencies: first by permuting the keys (for
//! every power-of-two spp from 1 to 256 at once), then by choosing each pixel's rank bits from
//! the top, one spp at a time. The tiles (`*_tile.in`, 48 KiB each, carried only by a program
//! that builds that family's sampler) are its output; [`BlueFamily::entry`] reads them.
//!
//! A pixel reads the tile at its coordinates plus an offset (toroidally): one per 4-D block of
//! dimensions, hashed from the seed and the block, and one per frame from Roberts' R2
//! sequence ([`offset`]). A shift of the torus keeps the error blue, so every block and frame
//! is blue, and the offsets decorrelate blocks and frames from each other.

mod lattice;
mod owen_sobol;
mod pmj02;
mod sampler;

pub use lattice::{LATTICE_GENERATOR, LatticeBlue};
pub use owen_sobol::OwenSobolBlue;
pub use pmj02::Pmj02Blue;
pub use sampler::{BlueNoiseSampler, LatticeBlueSampler, OwenSobolBlueSampler, Pmj02BlueSampler};

use super::values_one_at_a_time;
use crate::hash::hash2;

/// Side of the tiles, in pixels.
pub const TILE_SIZE: u32 = 128;

/// A tile's bytes, row-major: `[y · 128 + x]` is pixel `(x, y)`'s entry as three bytes, the
/// key's low and high byte and the rank (48 KiB).
type TileBytes = [[u8; 3]; (TILE_SIZE * TILE_SIZE) as usize];

/// Entry `(x, y)` of `tile`, modulo the tile's side (a torus).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn read(tile: &TileBytes, x: u32, y: u32) -> u32 {
    let m = TILE_SIZE - 1;
    let [lo, hi, rank] = tile[((y & m) * TILE_SIZE + (x & m)) as usize];
    (u32::from(u16::from_le_bytes([lo, hi])) << 8) | u32::from(rank)
}

/// A family of per-pixel nets with its optimised tile: how a tile entry randomises a pixel's
/// 4-D block of dimensions, and how sample `index` of that block is computed. Implemented by
/// [`OwenSobolBlue`], [`Pmj02Blue`] and [`LatticeBlue`] (sealed).
///
/// ```
/// use nyquist::sampler::screen_blue::{BlueFamily, LatticeBlue};
/// let e = LatticeBlue::entry(3, 4);
/// let v = LatticeBlue::values(e, 0);
/// assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
/// ```
pub trait BlueFamily:
    sealed::Sealed + Copy + core::fmt::Debug + Default + Send + Sync + 'static
{
    /// A 4-D block's randomisation, built once per pixel and block from an entry.
    type Block: Copy + core::fmt::Debug + Default + Send + Sync;
    /// What a sample index becomes in a block before its four values are read (the shuffled
    /// index, say), computed once per sample and block.
    type Index: Copy + core::fmt::Debug + Default + Send + Sync;
    /// The sampler name ([`NamedSampler`](crate::sampler::NamedSampler) takes it).
    const NAME: &'static str;

    /// The family's tile entry at `(x, y)`, modulo the tile's side (a torus).
    fn entry(x: u32, y: u32) -> u32;

    /// The block an entry makes.
    fn block(entry: u32) -> Self::Block;

    /// Sample `index` of `block`, ready for [`value`](Self::value).
    fn index(block: &Self::Block, index: u32) -> Self::Index;

    /// Component `c < 4` of the sample.
    fn value(block: &Self::Block, index: &Self::Index, c: u32) -> f32;

    /// The four values of sample `index` of a pixel whose entry is `entry`: what the
    /// optimiser integrates (the sampler's first block at that pixel).
    fn values(entry: u32, index: u32) -> [f32; 4] {
        let b = Self::block(entry);
        let i = Self::index(&b, index);
        core::array::from_fn(|c| Self::value(&b, &i, c as u32))
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::OwenSobolBlue {}
    impl Sealed for super::Pmj02Blue {}
    impl Sealed for super::LatticeBlue {}
}

/// Shift `c` (0 … 3) of a block whose hashed key is `key`: `mix32(key ⊕ (c + 1)·0x9e3779b9)`,
/// the Cranley–Patterson shift of `lattice-bn` and the digital shift of `pmj02-bn`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn shift(key: u32, c: u32) -> u32 {
    crate::hash::mix32(key ^ (c + 1).wrapping_mul(0x9e37_79b9))
}

/// The entry the optimiser starts slot `slot` with (key `slot`, rank 0): a tile's keys are a
/// permutation of these.
///
/// ```
/// use nyquist::sampler::screen_blue::initial_entry;
/// assert_eq!(initial_entry(3), 3 << 8);
/// ```
pub const fn initial_entry(slot: u32) -> u32 {
    slot << 8
}

/// Roberts' R2 sequence in 32-bit fixed point: `round(2³² / φ₂)` and `round(2³² / φ₂²)`, with
/// φ₂ = 1.324717957 the plastic number (the real root of `x³ = x + 1`).
const R2: [u32; 2] = [0xc13f_a9a9, 0x91e1_0da6];

/// The toroidal offset of `block` (4-D block of dimensions) in `frame` under `seed`: a hash of
/// the seed and block, plus the frame's R2 point, which puts consecutive frames far apart.
///
/// ```
/// use nyquist::sampler::screen_blue::offset;
/// assert_ne!(offset(0, 0, 0), offset(0, 1, 0));
/// assert_ne!(offset(0, 0, 0), offset(0, 0, 1));
/// assert!(offset(9, 3, 2).iter().all(|&o| o < 128));
/// ```
pub fn offset(seed: u64, frame: u32, block: u32) -> [u32; 2] {
    let h = hash2(seed, u64::from(block) ^ 0x424c_5545); // "BLUE"
    let shift = 32 - TILE_SIZE.trailing_zeros();
    [0, 1].map(|k| {
        let r = frame.wrapping_mul(R2[k]) >> shift;
        ((h >> (32 * k)) as u32).wrapping_add(r) & (TILE_SIZE - 1)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn initial_entries_are_slots_with_rank_zero() {
        assert_eq!(initial_entry(0), 0);
        assert_eq!(initial_entry(3), 0x300);
        assert_eq!(initial_entry(TILE_SIZE * TILE_SIZE - 1), 16383 << 8);
    }

    /// Offsets: pinned; inside the tile; the frame's part is R2's point `frac(f·α)` in
    /// 1/128 steps, computed here in f64 from α = 1/φ₂, 1/φ₂².
    #[test]
    fn offsets_are_pinned_and_frames_follow_r2() {
        assert_eq!(offset(0, 0, 0), [102, 28]);
        assert_eq!(offset(0, 1, 0), [70, 100]);
        assert_eq!(offset(0, 2, 1), [69, 110]);
        assert_eq!(offset(7, 5, 3), [76, 5]);
        let plastic = 1.324_717_957_244_746_f64;
        let alpha = [1.0 / plastic, 1.0 / (plastic * plastic)];
        for seed in [0u64, 9] {
            for block in [0u32, 1, 40] {
                let o0 = offset(seed, 0, block);
                for f in 0..2000u32 {
                    let o = offset(seed, f, block);
                    for k in 0..2 {
                        assert!(o[k] < TILE_SIZE);
                        let want = ((f64::from(f) * alpha[k]).fract() * 128.0) as u32;
                        let got = (o[k] + TILE_SIZE - o0[k]) % TILE_SIZE;
                        // The fixed-point product may round across a 1/128 step.
                        assert!(
                            got == want || got == (want + 1) % 128 || (got + 1) % 128 == want,
                            "{f} {k}"
                        );
                    }
                }
            }
        }
        assert_ne!(offset(0, 0, 0), offset(1, 0, 0));
        assert_ne!(offset(0, 0, 0), offset(0, 0, 1));
    }
}
