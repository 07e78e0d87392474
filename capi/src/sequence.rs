//! Sequences by index: van der Corput, Halton (plain, Zaremba, scrambled), Hammersley (plain,
//! Zaremba), Sobol (plain, digitally shifted), the (0,2)-sequence, the Fibonacci and Korobov
//! lattices and Roberts' R_d.
//!
//! A sequence is described by a plain [`NyqSequence`] value (no allocation, no handle); each
//! call validates it and builds the core's sequence, which costs a few integer operations.

use nyquist::sequence::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, ScrambledHalton, Sequence, Sobol,
    VanDerCorput, ZeroTwo,
};

use nyquist::lattice::{FibonacciLattice, Korobov, Kronecker};

use crate::NyqStatus;
use crate::ffi::{get, need, put, run, slice_mut};

/// The sequence families, the values of [`NyqSequence::kind`].
///
/// ```
/// use nyquist_capi::NyqSequenceKind;
/// assert_eq!(NyqSequenceKind::NYQ_SEQ_SOBOL as u32, 5);
/// ```
#[repr(u32)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NyqSequenceKind {
    /// Van der Corput, Φ₂(i): one dimension.
    NYQ_SEQ_VAN_DER_CORPUT = 0,
    /// Halton, (Φ₂(i), Φ₃(i), Φ₅(i), …): up to 1024 dimensions.
    NYQ_SEQ_HALTON = 1,
    /// Halton–Zaremba: Halton with the folded radical inverse Ψ: up to 1024 dimensions.
    NYQ_SEQ_HALTON_ZAREMBA = 2,
    /// Halton with seeded digit permutations (`seed`): up to 1024 dimensions.
    NYQ_SEQ_HALTON_SCRAMBLED = 3,
    /// Hammersley, ((i + ½)/N, Φ₂(i), Φ₃(i), …) with `N = points`: up to 1025 dimensions.
    NYQ_SEQ_HAMMERSLEY = 4,
    /// Sobol (Joe–Kuo direction numbers), natural order, 2³² points: up to 1024 dimensions.
    NYQ_SEQ_SOBOL = 5,
    /// Sobol with a digital shift keyed by `seed`.
    NYQ_SEQ_SOBOL_SCRAMBLED = 6,
    /// The (0,2)-sequence (Sobol's first two dimensions), 2 dimensions, 2³² points.
    NYQ_SEQ_ZERO_TWO = 7,
    /// The (0,2)-sequence XOR-scrambled by a hash of `seed`.
    NYQ_SEQ_ZERO_TWO_SCRAMBLED = 8,
    /// Hammersley–Zaremba: Hammersley with Ψ in place of Φ, `N = points`.
    NYQ_SEQ_HAMMERSLEY_ZAREMBA = 9,
    /// The Fibonacci lattice of `N = points` points (a Fibonacci number, 2 … F₉₃), 2
    /// dimensions; `seed != 0` picks a Cranley–Patterson rotation.
    NYQ_SEQ_FIBONACCI = 10,
    /// Roberts' R_d Kronecker sequence in `dims` dimensions (up to 1024; R2 for 2);
    /// `seed != 0` picks a Cranley–Patterson rotation in place of the start ½.
    NYQ_SEQ_RD = 11,
    /// The Korobov rank-1 lattice of `N = points` points with multiplier `a = seed` (coprime to
    /// `N`, `1 ≤ a < N`), generator `(1, a, a², …)`, up to 1024 dimensions, unrotated.
    NYQ_SEQ_KOROBOV = 12,
}

/// A point set, by value: which family and its parameters.
///
/// ```
/// use nyquist_capi::{NyqSequence, NyqSequenceKind};
/// let s = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32, dims: 3, points: 0, seed: 0 };
/// assert_eq!(s.dims, 3);
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NyqSequence {
    /// One of [`NyqSequenceKind`], as an integer (other values give `NYQ_ERR_OUT_OF_RANGE`).
    pub kind: u32,
    /// Number of dimensions, at least 1 (van der Corput: 1; (0,2): 1 or 2).
    pub dims: u32,
    /// The point count `N` of Hammersley (at least 1), of the Fibonacci lattice (a Fibonacci
    /// number) and of the Korobov lattice; ignored by the other families.
    pub points: u64,
    /// Scramble seed of the `*_SCRAMBLED` kinds, rotation seed of the Fibonacci lattice and
    /// R_d (0: none) (every value is valid), the multiplier of the Korobov lattice; ignored
    /// otherwise.
    pub seed: u64,
}

/// The core sequence a [`NyqSequence`] describes.
enum AnySequence {
    VanDerCorput(VanDerCorput),
    Halton(Halton),
    HaltonZaremba(HaltonZaremba),
    ScrambledHalton(ScrambledHalton),
    Hammersley(Hammersley),
    HammersleyZaremba(HammersleyZaremba),
    Sobol(Sobol),
    ZeroTwo(ZeroTwo),
    Fibonacci(FibonacciLattice),
    Rd(Kronecker),
    Korobov(Korobov),
}

/// `dims` for the fixed-size families: 1 ≤ dims ≤ max.
fn small_dims(dims: u32, max: u32) -> Result<(), NyqStatus> {
    match dims {
        0 => Err(NyqStatus::NYQ_ERR_ZERO_SIZE),
        d if d > max => Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE),
        _ => Ok(()),
    }
}

impl AnySequence {
    fn new(s: &NyqSequence) -> Result<AnySequence, NyqStatus> {
        use NyqSequenceKind as K;
        let kinds = [
            K::NYQ_SEQ_VAN_DER_CORPUT,
            K::NYQ_SEQ_HALTON,
            K::NYQ_SEQ_HALTON_ZAREMBA,
            K::NYQ_SEQ_HALTON_SCRAMBLED,
            K::NYQ_SEQ_HAMMERSLEY,
            K::NYQ_SEQ_SOBOL,
            K::NYQ_SEQ_SOBOL_SCRAMBLED,
            K::NYQ_SEQ_ZERO_TWO,
            K::NYQ_SEQ_ZERO_TWO_SCRAMBLED,
            K::NYQ_SEQ_HAMMERSLEY_ZAREMBA,
            K::NYQ_SEQ_FIBONACCI,
            K::NYQ_SEQ_RD,
            K::NYQ_SEQ_KOROBOV,
        ];
        let kind = kinds
            .into_iter()
            .find(|&k| k as u32 == s.kind)
            .ok_or(NyqStatus::NYQ_ERR_OUT_OF_RANGE)?;
        Ok(match kind {
            K::NYQ_SEQ_VAN_DER_CORPUT => {
                small_dims(s.dims, 1)?;
                AnySequence::VanDerCorput(VanDerCorput)
            }
            K::NYQ_SEQ_HALTON => AnySequence::Halton(Halton::new(s.dims)?),
            K::NYQ_SEQ_HALTON_ZAREMBA => AnySequence::HaltonZaremba(HaltonZaremba::new(s.dims)?),
            K::NYQ_SEQ_HALTON_SCRAMBLED => {
                AnySequence::ScrambledHalton(ScrambledHalton::new(s.dims, s.seed)?)
            }
            K::NYQ_SEQ_HAMMERSLEY => AnySequence::Hammersley(Hammersley::new(s.points, s.dims)?),
            K::NYQ_SEQ_HAMMERSLEY_ZAREMBA => {
                AnySequence::HammersleyZaremba(HammersleyZaremba::new(s.points, s.dims)?)
            }
            K::NYQ_SEQ_SOBOL => AnySequence::Sobol(Sobol::new(s.dims)?),
            K::NYQ_SEQ_SOBOL_SCRAMBLED => {
                AnySequence::Sobol(Sobol::with_digital_shift(s.dims, s.seed)?)
            }
            K::NYQ_SEQ_ZERO_TWO => {
                small_dims(s.dims, 2)?;
                AnySequence::ZeroTwo(ZeroTwo::new([0, 0]))
            }
            K::NYQ_SEQ_ZERO_TWO_SCRAMBLED => {
                small_dims(s.dims, 2)?;
                AnySequence::ZeroTwo(ZeroTwo::from_seed(s.seed))
            }
            K::NYQ_SEQ_FIBONACCI => {
                small_dims(s.dims, 2)?;
                let f = FibonacciLattice::at_least(s.points)?;
                if f.point_count() != Some(s.points) {
                    return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
                }
                AnySequence::Fibonacci(if s.seed == 0 { f } else { f.rotated(s.seed) })
            }
            K::NYQ_SEQ_RD => {
                let r = Kronecker::new(s.dims)?;
                AnySequence::Rd(if s.seed == 0 { r } else { r.rotated(s.seed) })
            }
            K::NYQ_SEQ_KOROBOV => AnySequence::Korobov(Korobov::new(s.points, s.seed, s.dims)?),
        })
    }

    fn as_dyn(&self) -> &dyn Sequence {
        match self {
            AnySequence::VanDerCorput(s) => s,
            AnySequence::Halton(s) => s,
            AnySequence::HaltonZaremba(s) => s,
            AnySequence::ScrambledHalton(s) => s,
            AnySequence::Hammersley(s) => s,
            AnySequence::HammersleyZaremba(s) => s,
            AnySequence::Sobol(s) => s,
            AnySequence::ZeroTwo(s) => s,
            AnySequence::Fibonacci(s) => s,
            AnySequence::Rd(s) => s,
            AnySequence::Korobov(s) => s,
        }
    }
}

/// Reads and validates `*seq`, and checks `(index, dim)` addresses a point of it.
///
/// # Safety
/// `seq` is null or points to a readable `NyqSequence`.
unsafe fn checked(seq: *const NyqSequence, index: u64, dim: u32) -> Result<AnySequence, NyqStatus> {
    // SAFETY: forwarded caller contract.
    let spec = unsafe { get(seq)? };
    let s = AnySequence::new(spec)?;
    if dim >= spec.dims || s.as_dyn().point_count().is_some_and(|n| index >= n) {
        return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
    }
    Ok(s)
}

/// Writes coordinate `dim` of point `index` of `*seq`, a `float` in `[0, 1)`, to `*out`: the
/// core's [`Sequence::sample`].
///
/// # Errors
/// `NYQ_ERR_NULL` if `seq` or `out` is null; `NYQ_ERR_ZERO_SIZE` if `seq->dims == 0` (or
/// Hammersley's `points == 0`); `NYQ_ERR_OUT_OF_RANGE` for an unknown kind, too many
/// dimensions, `dim >= seq->dims`, or `index` at or past the set's point count (Hammersley's
/// `points`, 2³² for Sobol and (0,2)). Unlike the core, nothing wraps.
///
/// # Safety
/// `seq` is null or points to a readable `NyqSequence`; `out` is null or valid for writing one
/// `float`.
///
/// ```
/// use nyquist_capi::{NyqSequence, NyqSequenceKind, NyqStatus, nyq_sequence_sample};
/// let halton = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32, dims: 2, points: 0, seed: 0 };
/// let mut x = 0.0f32;
/// // SAFETY: valid pointers.
/// assert_eq!(unsafe { nyq_sequence_sample(&halton, 3, 0, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, 0.75);
/// assert_eq!(unsafe { nyq_sequence_sample(&halton, 3, 2, &mut x) }, NyqStatus::NYQ_ERR_OUT_OF_RANGE);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sequence_sample(
    seq: *const NyqSequence,
    index: u64,
    dim: u32,
    out: *mut f32,
) -> NyqStatus {
    run(|| {
        need(out)?;
        // SAFETY: `seq` is null or readable (caller).
        let s = unsafe { checked(seq, index, dim)? };
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, s.as_dyn().sample(index, dim)) }
    })
}

/// [`nyq_sequence_sample`] in double precision: the core's [`Sequence::sample_f64`].
///
/// # Errors
/// As [`nyq_sequence_sample`].
///
/// # Safety
/// As [`nyq_sequence_sample`], with `out` valid for writing one `double`.
///
/// ```
/// use nyquist_capi::{NyqSequence, NyqSequenceKind, NyqStatus, nyq_sequence_sample_f64};
/// let vdc = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_VAN_DER_CORPUT as u32, dims: 1, points: 0, seed: 0 };
/// let mut x = 0.0f64;
/// // SAFETY: valid pointers.
/// assert_eq!(unsafe { nyq_sequence_sample_f64(&vdc, 5, 0, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, 0.625);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sequence_sample_f64(
    seq: *const NyqSequence,
    index: u64,
    dim: u32,
    out: *mut f64,
) -> NyqStatus {
    run(|| {
        need(out)?;
        // SAFETY: `seq` is null or readable (caller).
        let s = unsafe { checked(seq, index, dim)? };
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, s.as_dyn().sample_f64(index, dim)) }
    })
}

/// Writes points `first, first + 1, …` of `*seq` into `out[0..len]`, point-major (`[x0, y0,
/// x1, y1, …]` for `dims == 2`), the first `dims` coordinates of `len / dims` points, and their
/// number to `*written`: the core's [`Sequence::fill`].
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_ZERO_SIZE` if `len == 0` or `dims == 0`;
/// `NYQ_ERR_OUT_OF_RANGE` for a bad `*seq` or `dims > seq->dims`; `NYQ_ERR_BUFFER` if `len` is
/// not a multiple of `dims` or `out` is misaligned; `NYQ_ERR_TOO_MANY` if the points run past
/// the set's point count or `u64::MAX`. On error `out` is unspecified.
///
/// # Safety
/// `seq` is null or readable; `out` is null or valid for writing `len` floats; `written` is null
/// or valid for writing one `uint64_t`.
///
/// ```
/// use nyquist_capi::{NyqSequence, NyqSequenceKind, NyqStatus, nyq_sequence_fill};
/// let sobol = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_SOBOL as u32, dims: 2, points: 0, seed: 0 };
/// let (mut pts, mut n) = ([0.0f32; 8], 0u64);
/// // SAFETY: valid pointers, `pts` holds 8 floats.
/// assert_eq!(unsafe { nyq_sequence_fill(&sobol, 0, 2, pts.as_mut_ptr(), 8, &mut n) }, NyqStatus::NYQ_OK);
/// assert_eq!((n, pts), (4, [0.0, 0.0, 0.5, 0.5, 0.25, 0.75, 0.75, 0.25]));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sequence_fill(
    seq: *const NyqSequence,
    first: u64,
    dims: u32,
    out: *mut f32,
    len: usize,
    written: *mut u64,
) -> NyqStatus {
    run(|| {
        // SAFETY: `seq` is null or readable (caller).
        let spec = unsafe { get(seq)? };
        need(written)?;
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        let s = AnySequence::new(spec)?;
        if dims == 0 {
            return Err(NyqStatus::NYQ_ERR_ZERO_SIZE);
        }
        if dims > spec.dims {
            return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
        }
        let n = s.as_dyn().fill(first, dims, out)?;
        // SAFETY: `written` is writable (caller; null checked above).
        unsafe { put(written, n) }
    })
}

/// Writes the number of distinct points of `*seq` to `*out`: Hammersley's `points`, 2³² for
/// Sobol and (0,2), and 0 for the unbounded families (van der Corput, Halton).
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; otherwise as [`nyq_sequence_sample`] for a bad `*seq`.
///
/// # Safety
/// `seq` is null or readable; `out` is null or valid for writing one `uint64_t`.
///
/// ```
/// use nyquist_capi::{NyqSequence, NyqSequenceKind, NyqStatus, nyq_sequence_point_count};
/// let h = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HAMMERSLEY as u32, dims: 2, points: 16, seed: 0 };
/// let mut n = 0u64;
/// // SAFETY: valid pointers.
/// assert_eq!(unsafe { nyq_sequence_point_count(&h, &mut n) }, NyqStatus::NYQ_OK);
/// assert_eq!(n, 16);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sequence_point_count(
    seq: *const NyqSequence,
    out: *mut u64,
) -> NyqStatus {
    run(|| {
        // SAFETY: `seq` is null or readable (caller).
        let spec = unsafe { get(seq)? };
        need(out)?;
        let n = AnySequence::new(spec)?.as_dyn().point_count().unwrap_or(0);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, n) }
    })
}
