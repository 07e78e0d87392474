//! Domains: keyed sub-streams of a pixel sample (`nyquist::sampler::Domain`), as a plain
//! struct passed by value.
//!
//! [`nyq_sampler_domain`] gives the current sample of an `owen-sobol` handle as a domain; the
//! derivations ([`nyq_domain_branch`], [`nyq_domain_split`], [`nyq_domain_distribute`],
//! [`nyq_domain_chain`]) and values ([`nyq_domain_get_1d`], [`nyq_domain_get_2d`]) are pure
//! functions of their arguments, safe from any thread.

use nyquist::sampler::Domain;

use crate::NyqStatus;
use crate::ffi::{need, put, put_array, query, run};
use crate::sampler::NyqSampler;

/// A domain: the key of its Owen-scrambled Sobol sequence and its point's index (see
/// `nyquist::sampler::Domain`).
///
/// ```
/// let d = nyquist_capi::NyqDomain { key: 3, index: 1 };
/// assert_eq!((d.key, d.index), (3, 1));
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NyqDomain {
    /// The sequence's key.
    pub key: u64,
    /// The point's index in it.
    pub index: u64,
}

impl From<Domain> for NyqDomain {
    fn from(d: Domain) -> NyqDomain {
        NyqDomain {
            key: d.key(),
            index: d.index(),
        }
    }
}

impl From<NyqDomain> for Domain {
    fn from(d: NyqDomain) -> Domain {
        Domain::new(d.key, d.index)
    }
}

/// Writes the current sample of `sampler` as a domain to `*out`: its dimension `d` is the
/// sampler's dimension `d` (after `nyq_sampler_start_pixel_sample`).
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_OUT_OF_RANGE` if the sampler's samples are not
/// domains (every sampler but `owen-sobol`).
///
/// # Safety
/// `sampler` is null or a live handle; `out` is null or valid for writing one [`NyqDomain`].
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let (mut d, mut v, mut w) = (NyqDomain::default(), 0.0f32, 0.0f32);
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"owen-sobol".as_ptr(), 64, 64, 16, 7, &mut s);
///     nyq_sampler_start_pixel_sample(s, 3, 5, 2, 9);
///     assert_eq!(nyq_sampler_domain(s, &mut d), NyqStatus::NYQ_OK);
///     nyq_sampler_get_1d(s, &mut v);
///     nyq_domain_get_1d(d, 9, &mut w);
///     nyq_sampler_destroy(s);
///     nyq_sampler_create(c"random".as_ptr(), 64, 64, 16, 7, &mut s);
///     assert_eq!(nyq_sampler_domain(s, &mut d), NyqStatus::NYQ_ERR_OUT_OF_RANGE);
///     nyq_sampler_destroy(s);
/// }
/// assert_eq!(v, w);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_domain(
    sampler: *const NyqSampler,
    out: *mut NyqDomain,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe {
        query(
            sampler,
            out,
            |s| {
                s.domain()
                    .map(NyqDomain::from)
                    .ok_or(NyqStatus::NYQ_ERR_OUT_OF_RANGE)
            },
            put,
        )
    }
}

/// Writes `domain`'s branch for `key` (a purpose: light, BSDF, roulette) to `*out`: a new
/// sequence at the same index.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null.
///
/// # Safety
/// `out` is null or valid for writing one [`NyqDomain`].
///
/// ```
/// use nyquist_capi::*;
/// let mut b = NyqDomain::default();
/// // SAFETY: a valid pointer.
/// assert_eq!(unsafe { nyq_domain_branch(NyqDomain { key: 1, index: 5 }, 2, &mut b) }, NyqStatus::NYQ_OK);
/// assert_eq!(b.index, 5);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_domain_branch(
    domain: NyqDomain,
    key: u64,
    out: *mut NyqDomain,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let d = Domain::from(domain).branch(key);
        // SAFETY: `out` is writable (caller).
        unsafe { put(out, NyqDomain::from(d)) }
    })
}

/// Writes sub-sample `k` of `count` of `domain`'s sample, for `key`, to `*out`: point
/// `count·index + k` of a new sequence (over N parent samples, the first N·count points).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `count` is 0;
/// `NYQ_ERR_OUT_OF_RANGE` if `k >= count`; `NYQ_ERR_TOO_MANY` if the index passes 2⁶⁴ − 1.
///
/// # Safety
/// `out` is null or valid for writing one [`NyqDomain`].
///
/// ```
/// use nyquist_capi::*;
/// let mut s = NyqDomain::default();
/// // SAFETY: a valid pointer.
/// unsafe {
///     assert_eq!(nyq_domain_split(NyqDomain { key: 1, index: 5 }, 7, 4, 3, &mut s), NyqStatus::NYQ_OK);
///     assert_eq!(nyq_domain_split(NyqDomain { key: 1, index: 5 }, 7, 4, 4, &mut s), NyqStatus::NYQ_ERR_OUT_OF_RANGE);
/// }
/// assert_eq!(s.index, 23);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_domain_split(
    domain: NyqDomain,
    key: u64,
    count: u32,
    k: u32,
    out: *mut NyqDomain,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let d = Domain::from(domain).split(key, count, k)?;
        // SAFETY: `out` is writable (caller).
        unsafe { put(out, NyqDomain::from(d)) }
    })
}

/// Writes sub-sample `k` of `domain`'s sample, for `key`, to `*out`, for a count that varies
/// per sample: point `k` of a sequence of the sample's own.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null.
///
/// # Safety
/// `out` is null or valid for writing one [`NyqDomain`].
///
/// ```
/// use nyquist_capi::*;
/// let mut d = NyqDomain::default();
/// // SAFETY: a valid pointer.
/// assert_eq!(unsafe { nyq_domain_distribute(NyqDomain { key: 1, index: 5 }, 2, 3, &mut d) }, NyqStatus::NYQ_OK);
/// assert_eq!(d.index, 3);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_domain_distribute(
    domain: NyqDomain,
    key: u64,
    k: u32,
    out: *mut NyqDomain,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let d = Domain::from(domain).distribute(key, k);
        // SAFETY: `out` is writable (caller).
        unsafe { put(out, NyqDomain::from(d)) }
    })
}

/// Writes sub-sample `k` of `domain`'s sample, for `key`, to `*out`, for a count that varies
/// per sample: the sample's index in a sequence of sub-sample `k`'s own.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null.
///
/// # Safety
/// `out` is null or valid for writing one [`NyqDomain`].
///
/// ```
/// use nyquist_capi::*;
/// let mut d = NyqDomain::default();
/// // SAFETY: a valid pointer.
/// assert_eq!(unsafe { nyq_domain_chain(NyqDomain { key: 1, index: 5 }, 2, 3, &mut d) }, NyqStatus::NYQ_OK);
/// assert_eq!(d.index, 5);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_domain_chain(
    domain: NyqDomain,
    key: u64,
    k: u32,
    out: *mut NyqDomain,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let d = Domain::from(domain).chain(key, k);
        // SAFETY: `out` is writable (caller).
        unsafe { put(out, NyqDomain::from(d)) }
    })
}

/// Writes dimension `dim` of `domain`'s point, in `[0, 1)`, to `*out`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null.
///
/// # Safety
/// `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::*;
/// let mut x = 2.0f32;
/// // SAFETY: a valid pointer.
/// assert_eq!(unsafe { nyq_domain_get_1d(NyqDomain { key: 8, index: 3 }, 4, &mut x) }, NyqStatus::NYQ_OK);
/// assert!((0.0..1.0).contains(&x));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_domain_get_1d(
    domain: NyqDomain,
    dim: u32,
    out: *mut f32,
) -> NyqStatus {
    run(|| {
        need(out)?;
        // SAFETY: `out` is writable (caller).
        unsafe { put(out, Domain::from(domain).get_1d(dim)) }
    })
}

/// Writes dimensions `dim` and `dim + 1` of `domain`'s point, in `[0, 1)²`, to `out[0]` and
/// `out[1]`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null.
///
/// # Safety
/// `out` is null or valid for writing two `float`s.
///
/// ```
/// use nyquist_capi::*;
/// let mut uv = [2.0f32; 2];
/// // SAFETY: a valid pointer.
/// assert_eq!(unsafe { nyq_domain_get_2d(NyqDomain { key: 8, index: 3 }, 4, uv.as_mut_ptr()) }, NyqStatus::NYQ_OK);
/// assert!(uv.iter().all(|v| (0.0..1.0).contains(v)));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_domain_get_2d(
    domain: NyqDomain,
    dim: u32,
    out: *mut f32,
) -> NyqStatus {
    run(|| {
        need(out)?;
        // SAFETY: `out` is valid for two floats (caller).
        unsafe { put_array(out, Domain::from(domain).get_2d(dim)) }
    })
}
