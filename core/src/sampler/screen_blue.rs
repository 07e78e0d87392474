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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn initial_entries_are_slots_with_rank_zero() {
        assert_eq!(initial_entry(0), 0);
        assert_eq!(initial_entry(3), 0x300);
        assert_eq!(initial_entry(TILE_SIZE * TILE_SIZE - 1), 16383 << 8);
    }

    /// The shipped tile, pinned at three pixels, read as a torus.
    #[test]
    fn entries_are_pinned_and_wrap() {
        assert_eq!(entry(0, 0), 0x24_5681);
        assert_eq!(entry(127, 0), 0x3e_d832);
        assert_eq!(entry(5, 77), 0x34_6fd1);
        assert_eq!(entry(5 + 128, 77 + 256), entry(5, 77));
        assert_eq!(entry(128, 0), entry(0, 0));
        assert_eq!(entry(0, 128 * 7), entry(0, 0));
        assert_ne!(entry(1, 0), entry(0, 0));
        assert_ne!(entry(0, 1), entry(0, 0));
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
