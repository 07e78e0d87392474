//! The blue-noise tile of the screen-space samplers: one 32-bit entry per pixel of a 128 × 128
//! torus, chosen so that the errors of the pixels' estimates are blue noise across the screen
//! (Heitz, Belcour, Ostromoukhov, Coeurjolly and Iehl 2019; Belcour and Heitz 2021).
//!
//! An entry is a 24-bit *key* and an 8-bit *rank*, `key << 8 | rank`. The key seeds the
//! pixel's Owen scramble and index shuffle; the rank is XOR-ed into the sample index, which
//! picks the aligned block of `n` points the pixel's first `n` samples are (for `n ≤ 128`), so
//! every prefix of a power of two is still a net.
//!
//! The optimiser (`cargo run --release -p nyquist-lab --bin blue-tile`, `docs/blue-noise.md`)
//! starts from the keys `0 … 128² − 1` in slot order, rank 0 ([`initial_entry`]), and lowers
//! the Gaussian-weighted correlation of neighbouring pixels' errors over test integrands,
//! which is the error image's power at low frequencies: first by permuting the keys (for
//! every power-of-two spp from 1 to 256 at once), then by choosing each pixel's rank bits from
//! the top, one spp at a time. The tile (`screen_blue_tile.in`) is its output; [`entry`] reads it.
//!
//! A pixel reads the tile at its coordinates plus an offset (toroidally): one per 4-D block of
//! dimensions, hashed from the seed and the block, and one per frame from Roberts' R2
//! sequence. A shift of the torus keeps the error blue, so every block and frame is blue, and
//! the offsets decorrelate blocks and frames from each other.

use crate::hash::hash2;

/// Side of the tile, in pixels.
pub const TILE_SIZE: u32 = 128;

/// The optimised tile, row-major: `TILE[y · 128 + x]` is pixel `(x, y)`'s entry as three
/// bytes, the key's low and high byte and the rank (48 KiB, carried only by programs that build
/// a blue-noise sampler).
pub(crate) static TILE: [[u8; 3]; (TILE_SIZE * TILE_SIZE) as usize] =
    include!("screen_blue_tile.in");

/// The entry the optimiser starts slot `slot` with (key `slot`, rank 0): the tile's keys are a
/// permutation of these.
///
/// ```
/// use nyquist::sampler::screen_blue::initial_entry;
/// assert_eq!(initial_entry(3), 3 << 8);
/// ```
pub const fn initial_entry(slot: u32) -> u32 {
    slot << 8
}

/// The tile's entry at `(x, y)`, modulo the tile's side (a torus).
///
/// ```
/// use nyquist::sampler::screen_blue::entry;
/// assert_eq!(entry(3, 5), entry(3 + 128, 5 + 3 * 128));
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub fn entry(x: u32, y: u32) -> u32 {
    let m = TILE_SIZE - 1;
    let [lo, hi, rank] = TILE[((y & m) * TILE_SIZE + (x & m)) as usize];
    (u32::from(u16::from_le_bytes([lo, hi])) << 8) | u32::from(rank)
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
