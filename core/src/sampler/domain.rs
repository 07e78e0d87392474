//! Domains: independent, still stratified sub-streams of a pixel sample, derived from a key.
//!
//! A [`Domain`] is one Owen-scrambled Sobol sequence (the construction of
//! [`OwenSobol`](crate::sequence::OwenSobol), keyed by a 64-bit word) and an index into it. A
//! pixel sample of [`OwenSobolSampler`](super::OwenSobolSampler) *is* a domain
//! ([`OwenSobolSampler::pixel_domain`](super::OwenSobolSampler::pixel_domain),
//! [`Sampler::domain`](super::Sampler::domain)): its dimension `d` is the
//! sampler's dimension `d`. From a domain an integrator derives others:
//!
//! | derivation | key | index | the points of `K` sub-samples over `N` parent samples |
//! |---|---|---|---|
//! | [`Domain::branch`]`(key)` | new | the parent's | one per parent sample: `N` points of a new sequence, a net at every power of two |
//! | [`Domain::split`]`(key, K, k)` | new | `K·i + k` | the first `N·K` points of one new sequence: a net at every power of two of `N·K`, and each parent sample's `K` an aligned block of it |
//! | [`Domain::distribute`]`(key, k)` | new per parent sample | `k` | per parent sample, the first `K` points of its own sequence (stratified within the sample, independent across samples) |
//! | [`Domain::chain`]`(key, k)` | new per `k` | the parent's | per `k`, `N` points of its own sequence (stratified across samples, independent within one) |
//!
//! OpenQMC's `newDomain`, `newDomainSplit`, `newDomainDistrib` and `newDomainChain` have the
//! same four shapes (its README compares their RMSE); here the index is 64-bit, so `N·K` may
//! pass 2³², and every derivation is a pure function of the parent, the key and `k`. `split`
//! needs the same `K` for every parent sample of that key (it is the index's stride); a `K`
//! that varies per sample (adaptive light sampling) takes `distribute` when `K` is large next to
//! `N`, `chain` when it is small. `K` may vary per vertex: each vertex takes its own key.
//!
//! Allocates: no. A domain is two words; derivations and values are a few hashes.

use crate::Error;
use crate::hash::{hash2, hash3, mix32};
use crate::math::fraction_to_f32;
use crate::sequence::{IndexShuffle, SOBOL_DIMS, dim_seed, owen_sobol_u64, padded_u32};

/// Tags that keep the four derivations' keys apart.
const SPLIT: u64 = 0x0053_504c_4954; // "SPLIT"
const DISTRIBUTE: u64 = 0x0044_4953_5452; // "DISTR"
const CHAIN: u64 = 0x0043_4841_494e; // "CHAIN"

/// A sub-stream of samples: an Owen-scrambled Sobol sequence chosen by `key`, at point `index`
/// (module docs).
///
/// ```
/// use nyquist::sampler::{Domain, OwenSobolSampler, Sampler};
/// let mut s = OwenSobolSampler::new(16, 7).unwrap();
/// s.start_pixel_sample([3, 5], 2, 0);
/// let pixel: Domain = s.pixel_domain();
/// assert_eq!(pixel.get_2d(0), s.get_pixel_2d()); // the sample itself
/// // Four light samples per camera sample, still one stratified stream per pixel.
/// let lights: Vec<[f32; 2]> = (0..4).map(|k| pixel.split(1, 4, k).unwrap().get_2d(0)).collect();
/// assert_eq!(lights.len(), 4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Domain {
    key: u64,
    index: u64,
}

impl Domain {
    /// Point `index` of the sequence keyed `key`.
    ///
    /// ```
    /// use nyquist::sampler::Domain;
    /// let d = Domain::new(9, 4);
    /// assert_eq!((d.key(), d.index()), (9, 4));
    /// ```
    pub const fn new(key: u64, index: u64) -> Domain {
        Domain { key, index }
    }

    /// The key of the domain's sequence.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::Domain::new(3, 1).key(), 3);
    /// ```
    pub const fn key(&self) -> u64 {
        self.key
    }

    /// The domain's point in its sequence.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::Domain::new(3, 1).index(), 1);
    /// ```
    pub const fn index(&self) -> u64 {
        self.index
    }

    /// A new sequence for `key` (a purpose: light, BSDF, roulette…) at the same index:
    /// OpenQMC's `newDomain`. Across the parent's samples its points are as well distributed
    /// as the parent's, and independent of them.
    ///
    /// ```
    /// use nyquist::sampler::Domain;
    /// let d = Domain::new(1, 5);
    /// assert_eq!(d.branch(2).index(), 5);
    /// assert_ne!(d.branch(2).key(), d.branch(3).key());
    /// ```
    pub fn branch(&self, key: u64) -> Domain {
        Domain {
            key: hash2(self.key, key),
            index: self.index,
        }
    }

    /// Sub-sample `k` of `count` of this sample, for `key`: point `count·index + k` of a new
    /// sequence. Over `N` parent samples `0..N` the `N·count` sub-samples are that sequence's
    /// first `N·count` points, so they are as well distributed as `N·count` samples of the
    /// parent (nets at every power of two), and each sample's `count` are an aligned block
    /// (OpenQMC's `newDomainSplit`). `count` must be the same for every parent sample of `key`.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `count == 0`; [`Error::NotInRange`] if `k >= count`;
    /// [`Error::TooMany`] if `count·index + k` passes `u64::MAX`.
    ///
    /// ```
    /// use nyquist::{sampler::Domain, Error};
    /// let d = Domain::new(1, 5);
    /// assert_eq!(d.split(7, 4, 3).unwrap().index(), 23);
    /// assert_eq!(d.split(7, 4, 4), Err(Error::NotInRange { what: "k", value: 4, min: 0, max: 3 }));
    /// ```
    pub fn split(&self, key: u64, count: u32, k: u32) -> Result<Domain, Error> {
        if count == 0 {
            return Err(Error::ZeroSize { what: "count" });
        }
        if k >= count {
            return Err(Error::NotInRange {
                what: "k",
                value: u64::from(k),
                min: 0,
                max: u64::from(count - 1),
            });
        }
        let index = self
            .index
            .checked_mul(u64::from(count))
            .and_then(|i| i.checked_add(u64::from(k)))
            .ok_or(Error::TooMany {
                what: "count × index",
                value: self.index,
                max: u64::MAX / u64::from(count),
            })?;
        Ok(Domain {
            key: hash3(self.key, key, SPLIT),
            index,
        })
    }

    /// Sub-sample `k` of this sample, for `key`, when the number of sub-samples varies: point
    /// `k` of a sequence of this sample's own. A sample's first `2^m` sub-samples are a net;
    /// different parent samples' sub-samples are independent (OpenQMC's `newDomainDistrib`).
    ///
    /// ```
    /// use nyquist::sampler::Domain;
    /// let (a, b) = (Domain::new(1, 5), Domain::new(1, 6));
    /// assert_eq!(a.distribute(2, 3).index(), 3);
    /// assert_ne!(a.distribute(2, 3).key(), b.distribute(2, 3).key());
    /// assert_eq!(a.distribute(2, 0).key(), a.distribute(2, 3).key());
    /// ```
    pub fn distribute(&self, key: u64, k: u32) -> Domain {
        Domain {
            key: hash3(self.key, key ^ DISTRIBUTE, self.index),
            index: u64::from(k),
        }
    }

    /// Sub-sample `k` of this sample, for `key`, when the number of sub-samples varies: the
    /// sample's own index in a sequence of sub-sample `k`'s own. Over the parent's samples each
    /// `k` is as well distributed as the parent; the `k`s of one sample are independent
    /// (OpenQMC's `newDomainChain`).
    ///
    /// ```
    /// use nyquist::sampler::Domain;
    /// let d = Domain::new(1, 5);
    /// assert_eq!(d.chain(2, 3).index(), 5);
    /// assert_ne!(d.chain(2, 3).key(), d.chain(2, 4).key());
    /// ```
    pub fn chain(&self, key: u64, k: u32) -> Domain {
        Domain {
            key: hash3(self.key, key ^ CHAIN, u64::from(k)),
            index: self.index,
        }
    }

    /// Dimension `dim` of the domain's point, as a 32-bit binary fraction: Owen-scrambled Sobol
    /// (index shuffle from the key's upper half, scramble seeds from its lower half), padded
    /// from dimension 1024 on.
    ///
    /// ```
    /// use nyquist::sampler::Domain;
    /// // Two points of one sequence share no first digit in dimension 0 when they are 0 and 1.
    /// let (a, b) = (Domain::new(8, 0), Domain::new(8, 1));
    /// assert_ne!(a.sample_u32(0) >> 31, b.sample_u32(0) >> 31);
    /// ```
    pub fn sample_u32(&self, dim: u32) -> u32 {
        let seeds = self.key as u32;
        if dim >= SOBOL_DIMS {
            return padded_u32(seeds, self.index, dim);
        }
        let shuffle = IndexShuffle::new(mix32((self.key >> 32) as u32));
        owen_sobol_u64(shuffle.rev64(self.index), dim, dim_seed(seeds, dim))
    }

    /// Dimension `dim` of the domain's point, in `[0, 1)`.
    ///
    /// ```
    /// let x = nyquist::sampler::Domain::new(8, 3).get_1d(4);
    /// assert!((0.0..1.0).contains(&x));
    /// ```
    pub fn get_1d(&self, dim: u32) -> f32 {
        fraction_to_f32(self.sample_u32(dim))
    }

    /// Dimensions `dim` and `dim + 1` of the domain's point, in `[0, 1)²`.
    ///
    /// ```
    /// use nyquist::sampler::Domain;
    /// let d = Domain::new(8, 3);
    /// assert_eq!(d.get_2d(2), [d.get_1d(2), d.get_1d(3)]);
    /// ```
    pub fn get_2d(&self, dim: u32) -> [f32; 2] {
        [self.get_1d(dim), self.get_1d(dim.wrapping_add(1))]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::is_zero_two_net;
    use crate::sampler::{OwenSobolSampler, Sampler};
    use crate::sequence::{OwenSobol, Sequence};

    use std::vec::Vec;

    /// A sampler's pixel sample is its domain, in every dimension, padding included.
    #[test]
    fn the_owen_sobol_samplers_sample_is_its_domain() {
        let mut s = OwenSobolSampler::new(16, 7).unwrap().with_frame(2);
        for (pixel, i) in [([0u32, 0u32], 0u32), ([3, 5], 9), ([1000, 7], 1 << 20)] {
            for d in [0u32, 1, 2, 5, 6, 100, 1023, 1024, 5000] {
                s.start_pixel_sample(pixel, i, d);
                let want = s.get_1d();
                s.start_pixel_sample(pixel, i, d);
                assert_eq!(s.pixel_domain().get_1d(d), want, "{pixel:?} {i} {d}");
                assert_eq!(s.domain(), Some(s.pixel_domain()));
                assert_eq!(s.pixel_domain().index(), u64::from(i));
            }
        }
    }

    /// A domain's values are the Owen-Sobol sequence's of the same construction: the first
    /// 2^m points of dimensions 0 and 1 are nets.
    #[test]
    fn a_domains_points_are_nets_at_every_power_of_two() {
        for key in [0u64, 5, u64::MAX] {
            let pts: Vec<[f32; 2]> = (0..1024).map(|i| Domain::new(key, i).get_2d(0)).collect();
            for m in 0..=10 {
                assert!(is_zero_two_net(&pts[..1 << m]), "key {key} m {m}");
            }
        }
        // The key's halves are the sequence's shuffle and scramble, as `OwenSobol` derives
        // them from its hashed seed: the same values, 64-bit indices and padding included.
        let s = OwenSobol::new(3000, 3).unwrap();
        let h = hash2(3, 0x4f57_454e); // "OWEN"
        for i in [0u64, 9, 1 << 40] {
            for d in [0u32, 7, 1023, 2999] {
                assert_eq!(
                    Domain::new(h, i).sample_u32(d),
                    s.sample_u32(i, d),
                    "{i} {d}"
                );
                assert_eq!(Domain::new(h, i).get_1d(d), s.sample(i, d));
            }
        }
    }

    /// Splitting: over N parent samples, the N·K sub-samples are the first N·K points of one
    /// sequence (nets at every power of two), whatever K, and each parent's K are one aligned
    /// block; K may differ between keys (vertices).
    #[test]
    fn split_sub_samples_of_all_parent_samples_are_one_net() {
        for (n, k) in [(16u32, 4u32), (64, 2), (8, 32), (256, 1)] {
            for key in [1u64, 2] {
                let parent = |i: u32| Domain::new(0xfeed, u64::from(i));
                let mut pts = Vec::new();
                for i in 0..n {
                    for j in 0..k {
                        let d = parent(i).split(key, k, j).unwrap();
                        assert_eq!(d.index(), u64::from(i * k + j));
                        pts.push((d.index(), d.get_2d(0)));
                    }
                }
                pts.sort_by_key(|p| p.0);
                let pts: Vec<[f32; 2]> = pts.into_iter().map(|p| p.1).collect();
                for m in 0..=(n * k).trailing_zeros() {
                    assert!(is_zero_two_net(&pts[..1 << m]), "n {n} k {k} m {m}");
                }
                // Each parent's K sub-samples: an aligned block, so a net of K.
                assert!(is_zero_two_net(&pts[..k as usize]));
            }
        }
    }

    /// Distribute: per parent sample a sequence of its own (nets over its sub-samples); chain:
    /// per k a sequence over the parent samples (nets over them).
    #[test]
    fn distribute_and_chain_stratify_along_their_axis() {
        for i in [0u64, 7, 1 << 40] {
            let parent = Domain::new(3, i);
            let within: Vec<[f32; 2]> =
                (0..64).map(|k| parent.distribute(9, k).get_2d(0)).collect();
            assert!(is_zero_two_net(&within));
        }
        for k in [0u32, 3] {
            let across: Vec<[f32; 2]> = (0..64)
                .map(|i| Domain::new(3, i).chain(9, k).get_2d(0))
                .collect();
            assert!(is_zero_two_net(&across));
        }
        let d = Domain::new(3, 5);
        assert_ne!(d.chain(9, 0).get_2d(0), d.chain(9, 1).get_2d(0));
        assert_ne!(
            d.distribute(9, 0).key(),
            Domain::new(3, 6).distribute(9, 0).key()
        );
    }

    /// Independence: a branch's values are uncorrelated with the parent's (|r| < 4/√N over
    /// N = 4096 samples: a false alarm about once in 16 000 for independent values; fixed keys).
    #[test]
    fn branches_are_uncorrelated_with_their_parent() {
        let n = 4096u64;
        for key in [1u64, 2, 3] {
            let (mut sx, mut sy, mut sxy) = (0.0f64, 0.0f64, 0.0f64);
            for i in 0..n {
                let parent = Domain::new(77, i);
                let x = f64::from(parent.get_1d(0)) - 0.5;
                let y = f64::from(parent.branch(key).get_1d(0)) - 0.5;
                (sx, sy, sxy) = (sx + x * x, sy + y * y, sxy + x * y);
            }
            let r = sxy / (sx * sy).sqrt();
            assert!(r.abs() < 4.0 / 64.0, "key {key}: r = {r}");
        }
    }

    /// The derivations' keys, pinned: they are part of every image a renderer makes with them.
    #[test]
    fn derived_keys_are_pinned() {
        let d = Domain::new(1, 5);
        let keys = [
            d.branch(2).key(),
            d.split(2, 4, 1).unwrap().key(),
            d.distribute(2, 3).key(),
            d.chain(2, 3).key(),
        ];
        assert_eq!(keys, PINNED_KEYS);
    }

    const PINNED_KEYS: [u64; 4] = [
        0xbf7f_6a7a_7887_b1ee,
        0x6d3e_6c72_864a_50d3,
        0x69e1_7e9f_e79f_354c,
        0x2736_8d61_8c7a_4fd0,
    ];

    #[test]
    fn split_checks_its_arguments() {
        let d = Domain::new(1, u64::MAX / 2);
        assert_eq!(d.split(1, 0, 0), Err(Error::ZeroSize { what: "count" }));
        assert_eq!(
            d.split(1, 3, 0),
            Err(Error::TooMany {
                what: "count × index",
                value: u64::MAX / 2,
                max: u64::MAX / 3
            })
        );
        assert_eq!(
            d.split(7, 4, 4),
            Err(Error::NotInRange {
                what: "k",
                value: 4,
                min: 0,
                max: 3
            })
        );
        assert!(d.split(1, 2, 1).is_ok());
        assert_eq!(d.split(1, 2, 1).unwrap().index(), u64::MAX);
    }
}
