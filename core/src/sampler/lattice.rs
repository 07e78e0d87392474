//! Lattice pixel samplers: the Fibonacci lattice or Roberts' R2 in every dimension pair,
//! Cranley–Patterson rotated per pixel and pair.

use super::{Sampler, pixel_hash};
use crate::Error;
use crate::lattice::{FibonacciLattice, Kronecker, fixed_to_f32};

/// Which two-dimensional set a [`LatticeSampler`] replays.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Set {
    Fibonacci(FibonacciLattice),
    R2(Kronecker),
}

/// A pixel sampler built on a two-dimensional lattice or Kronecker set: sample `k` of a pixel,
/// dimensions `2j` and `2j + 1`, is point `k` of the set shifted modulo 1 by a Cranley–Patterson
/// rotation hashed from (pixel, `j`, seed), so every pixel and dimension pair gets an
/// independent randomisation of the same well-spaced set.
///
/// - [`LatticeSampler::fibonacci`]: the Fibonacci lattice, spp rounded up to a Fibonacci
///   number (at least 2);
/// - [`LatticeSampler::r2`]: the first spp points of Roberts' R2.
///
/// ```
/// use nyquist::sampler::{LatticeSampler, Sampler};
/// let mut s = LatticeSampler::fibonacci(20, 1).unwrap();
/// assert_eq!(s.samples_per_pixel(), 21);
/// s.start_pixel_sample([3, 4], 5, 0);
/// let [u, v] = s.get_2d();
/// assert!((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v));
/// ```
#[derive(Clone, Debug)]
pub struct LatticeSampler {
    set: Set,
    spp: u32,
    seed: u64,
    pixel: [u32; 2],
    index: u32,
    dim: u32,
}

impl LatticeSampler {
    /// The Fibonacci lattice of the smallest Fibonacci number `≥ max(spp, 2)` of points.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `spp == 0`; [`Error::TooMany`] when the rounded count passes
    /// `u32::MAX`.
    pub fn fibonacci(spp: u32, seed: u64) -> Result<LatticeSampler, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        let set = FibonacciLattice::at_least(u64::from(spp.max(2)))?;
        let n = set
            .point_count_u64()
            .try_into()
            .map_err(|_| Error::TooMany { what: "spp" })?;
        Ok(LatticeSampler::with(Set::Fibonacci(set), n, seed))
    }

    /// The first `spp` points of R2.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `spp == 0`.
    pub fn r2(spp: u32, seed: u64) -> Result<LatticeSampler, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        Ok(LatticeSampler::with(Set::R2(Kronecker::new(2)?), spp, seed))
    }

    fn with(set: Set, spp: u32, seed: u64) -> LatticeSampler {
        LatticeSampler {
            set,
            spp,
            seed,
            pixel: [0; 2],
            index: 0,
            dim: 0,
        }
    }

    /// Whether this is the Fibonacci form (else R2).
    pub fn is_fibonacci(&self) -> bool {
        matches!(self.set, Set::Fibonacci(_))
    }

    #[inline]
    fn value(&self, dim: u32) -> f32 {
        let k = u64::from(self.index % self.spp);
        let component = dim % 2;
        let base = match &self.set {
            Set::Fibonacci(f) => f.fixed(k, component),
            Set::R2(r) => r.fixed(k, component),
        };
        let shift = pixel_hash(self.pixel, u64::from(dim / 2), self.seed);
        let shift = crate::hash::hash2(shift, u64::from(component));
        fixed_to_f32(base.wrapping_add(shift))
    }
}

impl Sampler for LatticeSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        self.pixel = pixel;
        self.index = sample_index;
        self.dim = dim;
    }

    fn get_1d(&mut self) -> f32 {
        let d = self.dim;
        self.dim = d.wrapping_add(1);
        self.value(d)
    }

    fn get_2d(&mut self) -> [f32; 2] {
        let d = self.dim;
        self.dim = d.wrapping_add(2);
        [self.value(d), self.value(d.wrapping_add(1))]
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        [self.value(0), self.value(1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// In every pixel and dimension pair the spp samples are the lattice (or R2) shifted
    /// modulo 1: differences to sample 0 agree with the unshifted set's, to f32 rounding; pixels
    /// and pairs get different shifts.
    #[test]
    fn pixels_replay_the_set_rotated() {
        for mut s in [
            LatticeSampler::fibonacci(55, 3).unwrap(),
            LatticeSampler::r2(40, 3).unwrap(),
        ] {
            let spp = s.samples_per_pixel();
            let base: Vec<[f64; 2]> = (0..u64::from(spp))
                .map(|k| match &s.set {
                    Set::Fibonacci(f) => {
                        [0, 1].map(|d| crate::lattice::fixed_to_f64(f.fixed(k, d)))
                    }
                    Set::R2(r) => [0, 1].map(|d| crate::lattice::fixed_to_f64(r.fixed(k, d))),
                })
                .collect();
            let mut firsts = Vec::new();
            for pixel in [[0u32, 0], [7, 3]] {
                for pair in 0..3u32 {
                    let mut pts = Vec::new();
                    for k in 0..spp {
                        s.start_pixel_sample(pixel, k, 2 * pair);
                        pts.push(s.get_2d());
                    }
                    firsts.push(pts[0]);
                    for k in 0..spp as usize {
                        for d in 0..2 {
                            let got = (f64::from(pts[k][d]) - f64::from(pts[0][d])).rem_euclid(1.0);
                            let want = (base[k][d] - base[0][d]).rem_euclid(1.0);
                            let err = (got - want).abs();
                            assert!(err.min(1.0 - err) < 1e-6, "{pixel:?} pair {pair} k {k}");
                            assert!((0.0..1.0).contains(&pts[k][d]));
                        }
                    }
                }
            }
            firsts.sort_by(|a, b| a[0].total_cmp(&b[0]));
            firsts.dedup();
            assert_eq!(firsts.len(), 6);
        }
        assert_eq!(
            LatticeSampler::fibonacci(1, 0).unwrap().samples_per_pixel(),
            2
        );
        assert_eq!(
            LatticeSampler::fibonacci(0, 0).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
        assert_eq!(
            LatticeSampler::r2(0, 0).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
    }
}
