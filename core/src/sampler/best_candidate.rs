//! Mitchell's best-candidate sampling from a baked, tileable blue-noise table.
//!
//! The table (`best_candidate/table.rs`, 4096 rows of image x, y, time, lens u, v) is made by
//! `scripts/gen_best_candidate.py` (with the `lazy-tables` feature, `best_candidate/generate.rs`
//! runs the same algorithm at first use instead): Mitchell's best-candidate algorithm
//! (Mitchell 1991, "Spectrally optimal sampling for distribution ray tracing") with toroidal
//! distance, so the pattern tiles; each row's time and lens are the best of 32 candidates
//! against the times and lens positions of its 8 nearest earlier image neighbours (pbrt-v2's
//! redistribution). Because the candidate count depends only on the row, every prefix is itself
//! blue noise: relative radius ρ ≥ 0.65 for the first 256 rows and ≥ 0.70 for all 4096 (tested).

use super::{Sampler, pixel_hash};
use crate::Error;
use crate::hash::{hash2, mix64, unit_f32};
use crate::math::clamp_unit;

// The table: stored (written by the script), or with `lazy-tables` generated at first use by
// the same algorithm (the tests compile both and compare them).
#[cfg(any(feature = "lazy-tables", test))]
mod generate;
#[cfg(any(not(feature = "lazy-tables"), test))]
mod table;
#[cfg(feature = "lazy-tables")]
use generate::TABLE;
#[cfg(not(feature = "lazy-tables"))]
use table::TABLE;

/// Rows in the baked table.
///
/// ```
/// use nyquist::sampler::{best_candidate::TABLE_SIZE, BestCandidateSampler};
/// assert!(BestCandidateSampler::new(TABLE_SIZE, 0).is_ok());
/// ```
pub const TABLE_SIZE: u32 = 4096;

/// Row `k` of the baked table as `[x, y, time, u, v]` in `[0, 1)`: stored value `q` reads as
/// `(q + ½) / 65536`. Total: `k` wraps modulo [`TABLE_SIZE`].
///
/// ```
/// use nyquist::sampler::best_candidate::table_row;
/// let r = table_row(0);
/// assert!(r.iter().all(|v| (0.0..1.0).contains(v)));
/// assert_eq!(table_row(4096), r);
/// ```
pub fn table_row(k: u32) -> [f32; 5] {
    let q = TABLE[(k % TABLE_SIZE) as usize];
    q.map(|v| (f32::from(v) + 0.5) * (1.0 / 65536.0))
}

/// Best-candidate sampler: sample `i` of every pixel takes row `i` of the blue-noise table.
///
/// - Image sample (dimensions 0, 1): the table's first `spp` image positions, with a per-pixel
///   toroidal Cranley–Patterson shift from `hash(pixel, seed)`. Every prefix of the table is
///   blue noise on the torus, and a toroidal shift keeps every distance, so each pixel's `spp`
///   samples are blue noise; the shift differs from pixel to pixel, so the image is not one
///   pattern repeated with a period of one pixel (which aliases like a uniform grid at low
///   `spp`, where nonuniform samples are meant to turn aliasing into noise: Cook 1986, Dippé
///   and Wold 1985). Deviation from pbrt-v2, whose table spans a tile of `√(4096/spp)` pixels:
///   there a pixel gets a varying number of samples, which the random-access interface cannot
///   express; here every pixel gets exactly `spp`.
/// - Time (dimension 2) and lens (dimensions 3, 4): the same row's values with their own
///   per-pixel shifts (toroidal, so the redistribution against image neighbours is kept inside
///   the pixel), so neighbouring pixels do not repeat them.
/// - Dimensions ≥ 5: independent hashed values of (pixel, index, dimension, seed).
///
/// `sample_index >= spp` wraps modulo `spp`.
///
/// ```
/// use nyquist::sampler::{BestCandidateSampler, Sampler};
/// let mut s = BestCandidateSampler::new(16, 0).unwrap();
/// s.start_pixel_sample([4, 4], 3, 0);
/// let [x, y] = s.get_pixel_2d();
/// assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
/// ```
#[derive(Clone, Debug)]
pub struct BestCandidateSampler {
    spp: u32,
    seed: u64,
    pixel: [u32; 2],
    /// Image, time and lens Cranley–Patterson shifts of the current pixel.
    shifts: [f32; 5],
    /// `hash(pixel, seed)` of the current pixel, for the dimensions past the table.
    pixel_key: u64,
    index: u32,
    dim: u32,
}

/// The per-pixel image, time and lens shifts (dimensions 0 ..= 4).
fn shifts(pixel: [u32; 2], seed: u64) -> [f32; 5] {
    let h = pixel_hash(pixel, seed, 0x6370);
    let g = hash2(h, 1);
    let k = hash2(h, 2);
    [
        unit_f32((k >> 32) as u32),
        unit_f32(k as u32),
        unit_f32((h >> 32) as u32),
        unit_f32(h as u32),
        unit_f32((g >> 32) as u32),
    ]
}

impl BestCandidateSampler {
    /// A best-candidate sampler with `spp` samples per pixel.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`; [`Error::TooMany`] if `spp` exceeds [`TABLE_SIZE`].
    ///
    /// ```
    /// use nyquist::sampler::BestCandidateSampler;
    /// assert!(BestCandidateSampler::new(4097, 0).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        if spp > TABLE_SIZE {
            return Err(Error::TooMany {
                what: "spp",
                value: u64::from(spp),
                max: u64::from(TABLE_SIZE),
            });
        }
        Ok(Self {
            spp,
            seed,
            pixel: [0; 2],
            shifts: shifts([0; 2], seed),
            pixel_key: pixel_hash([0; 2], seed, 0x6263),
            index: 0,
            dim: 0,
        })
    }

    #[inline]
    fn sample(&self, dim: u32) -> f32 {
        let row = self.index % self.spp;
        if dim >= 5 {
            // Independent values: one hash of (pixel, seed) ⊕ index ⊕ dimension.
            let h = mix64(
                self.pixel_key
                    ^ u64::from(self.index).wrapping_mul(0x9e37_79b9_7f4a_7c15)
                    ^ u64::from(dim).wrapping_mul(0xc2b2_ae3d_27d4_eb4f),
            );
            return unit_f32((h >> 32) as u32);
        }
        let v = (f32::from(TABLE[row as usize][dim as usize]) + 0.5) * (1.0 / 65536.0);
        let s = v + self.shifts[dim as usize];
        clamp_unit(if s >= 1.0 { s - 1.0 } else { s })
    }
}

impl Sampler for BestCandidateSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if pixel != self.pixel {
            self.pixel = pixel;
            self.shifts = shifts(pixel, self.seed);
            self.pixel_key = pixel_hash(pixel, self.seed, 0x6263);
        }
        self.index = sample_index;
        self.dim = dim;
    }

    super::global_point_dimensions!();

    /// The default arrays: one dimension per value.
    fn arrays_are_dimension_runs(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{consistent_values, threads_agree};
    use std::vec::Vec;

    // The script's random numbers and toroidal distance, as the generator implements them.
    use super::generate::{SEED, SplitMix64, wrap};

    fn d2(p: &[f64; 5], x: f64, y: f64) -> f64 {
        let (a, b) = (wrap(x - p[0]), wrap(y - p[1]));
        a * a + b * b
    }

    /// The script's algorithm, brute force, written from its description (the script and
    /// `generate.rs` switch to grid searches from 64 points on, which make the same choices;
    /// `generate.rs`'s test compares all 4096 rows).
    fn regenerate(n: usize) -> Vec<[u16; 5]> {
        let mut rng = SplitMix64(SEED);
        let mut pts: Vec<[f64; 5]> = Vec::new();
        for i in 0..n {
            let mut best = (0.0, 0.0);
            let mut best_d2 = -1.0;
            for _ in 0..(1 + 4 * i).min(4096) {
                let x = rng.unit();
                let y = rng.unit();
                let d = pts.iter().map(|p| d2(p, x, y)).fold(8.0, f64::min);
                if d > best_d2 {
                    best_d2 = d;
                    best = (x, y);
                }
            }
            let (x, y) = best;
            let mut nbs: Vec<usize> = (0..pts.len()).collect();
            nbs.sort_by(|&a, &b| {
                d2(&pts[a], x, y)
                    .total_cmp(&d2(&pts[b], x, y))
                    .then(a.cmp(&b))
            });
            nbs.truncate(8);
            let (mut bt, mut bd) = (0.0, -1.0);
            for _ in 0..32 {
                let t = rng.unit();
                let d = nbs.iter().map(|&j| wrap(t - pts[j][2])).fold(2.0, f64::min);
                if d > bd {
                    (bd, bt) = (d, t);
                }
            }
            let (mut bu, mut bv, mut bd) = (0.0, 0.0, -1.0);
            for _ in 0..32 {
                let u = rng.unit();
                let v = rng.unit();
                let d = nbs
                    .iter()
                    .map(|&j| {
                        let (a, b) = (wrap(u - pts[j][3]), wrap(v - pts[j][4]));
                        a * a + b * b
                    })
                    .fold(8.0, f64::min);
                if d > bd {
                    (bd, bu, bv) = (d, u, v);
                }
            }
            pts.push([x, y, bt, bu, bv]);
        }
        pts.iter()
            .map(|p| p.map(|v| ((v * 65536.0) as u32).min(65535) as u16))
            .collect()
    }

    #[test]
    fn table_prefix_matches_the_algorithm() {
        assert_eq!(regenerate(64), table::TABLE[..64]);
    }

    /// Toroidal minimum distance of the first `n` image positions, brute force.
    fn toroidal_min_distance(n: usize) -> f64 {
        let p: Vec<[f64; 2]> = (0..n as u32)
            .map(|k| {
                let r = table_row(k);
                [f64::from(r[0]), f64::from(r[1])]
            })
            .collect();
        let mut best = f64::INFINITY;
        for i in 0..n {
            for j in 0..i {
                let (a, b) = (wrap(p[i][0] - p[j][0]), wrap(p[i][1] - p[j][1]));
                best = best.min(a * a + b * b);
            }
        }
        best.sqrt()
    }

    fn rho(n: usize) -> f64 {
        toroidal_min_distance(n) / (2.0 / (3f64.sqrt() * n as f64)).sqrt()
    }

    #[test]
    fn table_is_blue_noise_in_full_and_in_prefixes() {
        assert!(rho(4096) >= 0.70, "full table rho {}", rho(4096));
        assert!(rho(256) >= 0.65, "first 256 rho {}", rho(256));
        for n in [16, 64, 1024] {
            assert!(rho(n) >= 0.6, "first {n} rho {}", rho(n));
        }
    }

    #[test]
    fn tile_wraps_across_its_edge() {
        // Lay out 2×2 copies of the tile (plain Euclidean distance, no wrap): points near the
        // seams of neighbouring copies must honour the same ρ as the torus.
        let n = 4096usize;
        let p: Vec<[f64; 2]> = (0..n as u32)
            .map(|k| {
                let r = table_row(k);
                [f64::from(r[0]), f64::from(r[1])]
            })
            .collect();
        let near = |v: f64| !(0.05..0.95).contains(&v);
        let mut tiled = Vec::new();
        for (ox, oy) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
            for q in p.iter().filter(|q| near(q[0]) || near(q[1])) {
                tiled.push([q[0] + ox, q[1] + oy]);
            }
        }
        let mut best = f64::INFINITY;
        for i in 0..tiled.len() {
            for j in 0..i {
                let (a, b) = (tiled[i][0] - tiled[j][0], tiled[i][1] - tiled[j][1]);
                best = best.min(a * a + b * b);
            }
        }
        let rho_seam = best.sqrt() / (2.0 / (3f64.sqrt() * n as f64)).sqrt();
        assert!(rho_seam >= 0.70, "rho across the seams {rho_seam}");
    }

    #[test]
    fn time_and_lens_are_spread_against_image_neighbours() {
        // Each of the first 256 rows' time differs from its nearest image neighbour's time by
        // more than random values would: the mean toroidal |Δt| clearly beats the 1/4 of
        // independent uniform values (standard error ≈ 0.009 over 256 rows).
        let rows: Vec<[f32; 5]> = (0..256).map(table_row).collect();
        let mut sum = 0.0;
        for (i, r) in rows.iter().enumerate() {
            let j = (0..rows.len())
                .filter(|&j| j != i)
                .min_by(|&a, &b| {
                    let da = d2(&rows[a].map(f64::from), f64::from(r[0]), f64::from(r[1]));
                    let db = d2(&rows[b].map(f64::from), f64::from(r[0]), f64::from(r[1]));
                    da.total_cmp(&db)
                })
                .unwrap();
            sum += wrap(f64::from(r[2] - rows[j][2]));
        }
        assert!(sum / 256.0 > 0.27, "mean time gap {}", sum / 256.0);
    }

    /// At 1 spp the image offsets vary from pixel to pixel (no one-pixel period, which would
    /// alias like a uniform grid), and at 16 spp each pixel's pattern keeps the table prefix's
    /// toroidal minimum distance (a toroidal shift moves no distance).
    #[test]
    fn image_patterns_are_shifted_per_pixel_and_stay_blue_noise() {
        let mut s = BestCandidateSampler::new(1, 3).unwrap();
        let mut offsets = std::vec::Vec::new();
        for y in 0..8 {
            for x in 0..8 {
                s.start_pixel_sample([x, y], 0, 0);
                offsets.push(s.get_pixel_2d());
            }
        }
        offsets.sort_by(|a, b| a.partial_cmp(b).unwrap());
        offsets.dedup();
        assert_eq!(offsets.len(), 64, "identical offsets across pixels");

        let torus = |a: [f32; 2], b: [f32; 2]| {
            let d = |u: f32, v: f32| {
                let t = (u - v).abs();
                t.min(1.0 - t)
            };
            (d(a[0], b[0]).powi(2) + d(a[1], b[1]).powi(2)).sqrt()
        };
        let min_dist = |pts: &[[f32; 2]]| {
            let mut m = f32::MAX;
            for i in 0..pts.len() {
                for j in 0..i {
                    m = m.min(torus(pts[i], pts[j]));
                }
            }
            m
        };
        let prefix: std::vec::Vec<[f32; 2]> = (0..16)
            .map(|r| {
                let row = table::TABLE[r];
                [
                    (f32::from(row[0]) + 0.5) / 65536.0,
                    (f32::from(row[1]) + 0.5) / 65536.0,
                ]
            })
            .collect();
        let want = min_dist(&prefix);
        let mut s = BestCandidateSampler::new(16, 3).unwrap();
        for pixel in [[0u32, 0u32], [5, 9], [1000, 3]] {
            let pts: std::vec::Vec<[f32; 2]> = (0..16)
                .map(|i| {
                    s.start_pixel_sample(pixel, i, 0);
                    s.get_pixel_2d()
                })
                .collect();
            assert!((min_dist(&pts) - want).abs() < 1e-5, "{pixel:?}");
        }
    }

    #[test]
    fn best_candidate_is_consistent_and_thread_independent() {
        let s = BestCandidateSampler::new(16, 4).unwrap();
        consistent_values(&s);
        threads_agree(&s);
    }
}
