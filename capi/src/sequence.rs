//! Sequences by index: van der Corput, Halton (plain, Zaremba, digit-permuted), Hammersley
//! (plain, Zaremba), Sobol (plain, digitally shifted), Owen-scrambled Sobol, the
//! (0,2)-sequence, PMJ(0,2), the Fibonacci and Korobov lattices and Roberts' R_d, plain or
//! rotated: the core's [`NamedSequence`], one kind per family and randomization.
//!
//! A sequence is described by a plain [`NyqSequence`] value (no allocation, no handle); each
//! call validates it and builds the core's sequence, which costs a few integer operations (a
//! Korobov lattice whose multiplier is left to nyquist also searches it, about linear in `N`).

use nyquist::compact::RuntimeHalton;
use nyquist::sequence::{NamedSequence, NamedSequenceError, Sequence, SequenceSpec, takes_points};

use crate::NyqStatus;
use crate::ffi::{get, need, put, run, slice_mut};

/// The sequence families and their randomizations, the values of [`NyqSequence::kind`]. The
/// randomized kinds (`*_SCRAMBLED`, `*_ROTATED`, `NYQ_SEQ_OWEN_SOBOL`) take `seed`, and every
/// seed, 0 included, randomizes; the other kinds ignore it.
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
    /// Halton with seeded digit permutations: up to 1024 dimensions.
    NYQ_SEQ_HALTON_SCRAMBLED = 3,
    /// Hammersley, ((i + ½)/N, Φ₂(i), Φ₃(i), …) with `N = points`: up to 1025 dimensions.
    NYQ_SEQ_HAMMERSLEY = 4,
    /// Sobol (Joe–Kuo direction numbers), natural order, every `u64` index a point: any number
    /// of dimensions (from 1024 on, seeded Owen-scrambled 4-D blocks).
    NYQ_SEQ_SOBOL = 5,
    /// Sobol with a digital shift keyed by `seed`.
    NYQ_SEQ_SOBOL_SCRAMBLED = 6,
    /// The (0,2)-sequence (Sobol's first two dimensions), 2 dimensions, 2³² points.
    NYQ_SEQ_ZERO_TWO = 7,
    /// The (0,2)-sequence with a digital shift keyed by `seed`.
    NYQ_SEQ_ZERO_TWO_SCRAMBLED = 8,
    /// Hammersley–Zaremba: Hammersley with Ψ in place of Φ, `N = points`.
    NYQ_SEQ_HAMMERSLEY_ZAREMBA = 9,
    /// The Fibonacci lattice of `N = points` points (a Fibonacci number, 2 … F₉₃), 2
    /// dimensions, unrotated.
    NYQ_SEQ_FIBONACCI = 10,
    /// Roberts' R_d Kronecker sequence in `dims` dimensions (up to 1024; R2 for 2), starting
    /// at ½.
    NYQ_SEQ_RD = 11,
    /// The Korobov rank-1 lattice of `N = points` points, generator `(1, a, a², …)` with `a =
    /// multiplier` (coprime to `N`, `1 ≤ a < N`; 0: nyquist picks it, from Stroud's 1971 tables
    /// or by minimising P2), up to 1024 dimensions, unrotated.
    NYQ_SEQ_KOROBOV = 12,
    /// [`NyqSequenceKind::NYQ_SEQ_FIBONACCI`] with a Cranley–Patterson rotation keyed by `seed`.
    NYQ_SEQ_FIBONACCI_ROTATED = 13,
    /// [`NyqSequenceKind::NYQ_SEQ_RD`] with a Cranley–Patterson rotation keyed by `seed` in
    /// place of the start ½.
    NYQ_SEQ_RD_ROTATED = 14,
    /// [`NyqSequenceKind::NYQ_SEQ_KOROBOV`] with a Cranley–Patterson rotation keyed by `seed`.
    NYQ_SEQ_KOROBOV_ROTATED = 15,
    /// Owen-scrambled Sobol (Burley 2020: nested uniform shuffle and scramble) keyed by `seed`,
    /// every `u64` index a point, any number of dimensions (padded from 1024 on).
    NYQ_SEQ_OWEN_SOBOL = 16,
    /// PMJ(0,2), 2 dimensions, 65536 points: the baked table.
    NYQ_SEQ_PMJ02 = 17,
    /// PMJ(0,2) Owen-scrambled by `seed`.
    NYQ_SEQ_PMJ02_SCRAMBLED = 18,
}

/// Every kind with the core name it builds and whether it is randomized.
const KINDS: [(NyqSequenceKind, &str, bool); 19] = {
    use NyqSequenceKind as K;
    [
        (K::NYQ_SEQ_VAN_DER_CORPUT, "vdc", false),
        (K::NYQ_SEQ_HALTON, "halton", false),
        (K::NYQ_SEQ_HALTON_ZAREMBA, "halton-zaremba", false),
        (K::NYQ_SEQ_HALTON_SCRAMBLED, "halton", true),
        (K::NYQ_SEQ_HAMMERSLEY, "hammersley", false),
        (K::NYQ_SEQ_SOBOL, "sobol", false),
        (K::NYQ_SEQ_SOBOL_SCRAMBLED, "sobol", true),
        (K::NYQ_SEQ_ZERO_TWO, "zero-two", false),
        (K::NYQ_SEQ_ZERO_TWO_SCRAMBLED, "zero-two", true),
        (K::NYQ_SEQ_HAMMERSLEY_ZAREMBA, "hammersley-zaremba", false),
        (K::NYQ_SEQ_FIBONACCI, "fibonacci", false),
        (K::NYQ_SEQ_RD, "rd", false),
        (K::NYQ_SEQ_KOROBOV, "korobov", false),
        (K::NYQ_SEQ_FIBONACCI_ROTATED, "fibonacci", true),
        (K::NYQ_SEQ_RD_ROTATED, "rd", true),
        (K::NYQ_SEQ_KOROBOV_ROTATED, "korobov", true),
        (K::NYQ_SEQ_OWEN_SOBOL, "owen-sobol", true),
        (K::NYQ_SEQ_PMJ02, "pmj02", false),
        (K::NYQ_SEQ_PMJ02_SCRAMBLED, "pmj02", true),
    ]
};

/// A point set, by value: which family and its parameters.
///
/// ```
/// use nyquist_capi::{NyqSequence, NyqSequenceKind};
/// let s = NyqSequence {
///     kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32,
///     dims: 3,
///     points: 0,
///     seed: 0,
///     multiplier: 0,
/// };
/// assert_eq!(s.dims, 3);
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NyqSequence {
    /// One of [`NyqSequenceKind`], as an integer (other values give `NYQ_ERR_OUT_OF_RANGE`).
    pub kind: u32,
    /// Number of dimensions, at least 1 (van der Corput: 1; (0,2), PMJ(0,2), Fibonacci: 1 or 2).
    pub dims: u32,
    /// The point count `N` of Hammersley (at least 1), of the Fibonacci lattice (a Fibonacci
    /// number) and of the Korobov lattice; ignored by the other families.
    pub points: u64,
    /// The seed of the randomized kinds (every value is valid and randomizes); ignored by the
    /// others.
    pub seed: u64,
    /// The Korobov multiplier `a` (0: nyquist picks it); ignored by the other families. Last,
    /// so that a C initializer of the first four fields leaves it 0.
    pub multiplier: u64,
}

/// The core sequence `*s` describes.
fn build(s: &NyqSequence) -> Result<NamedSequence, NyqStatus> {
    let &(_, name, randomized) = KINDS
        .iter()
        .find(|(k, ..)| *k as u32 == s.kind)
        .ok_or(NyqStatus::NYQ_ERR_OUT_OF_RANGE)?;
    let spec = SequenceSpec {
        dims: s.dims,
        points: takes_points(name).then_some(s.points),
        seed: randomized.then_some(s.seed),
        multiplier: (name == "korobov" && s.multiplier != 0).then_some(s.multiplier),
    };
    NamedSequence::new(name, spec).map_err(|e| match e {
        NamedSequenceError::Sequence(e) => e.into(),
        _ => NyqStatus::NYQ_ERR_OUT_OF_RANGE,
    })
}

/// Reads and validates `*seq`, and checks `(index, dim)` addresses a point of it.
///
/// # Safety
/// `seq` is null or points to a readable `NyqSequence`.
unsafe fn checked(
    seq: *const NyqSequence,
    index: u64,
    dim: u32,
) -> Result<NamedSequence, NyqStatus> {
    // SAFETY: forwarded caller contract.
    let spec = unsafe { get(seq)? };
    let s = build(spec)?;
    if dim >= spec.dims || s.point_count().is_some_and(|n| index >= n) {
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
/// let halton = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HALTON as u32, dims: 2, points: 0, seed: 0, multiplier: 0 };
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
        unsafe { put(out, s.sample(index, dim)) }
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
/// let vdc = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_VAN_DER_CORPUT as u32, dims: 1, points: 0, seed: 0, multiplier: 0 };
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
        unsafe { put(out, s.sample_f64(index, dim)) }
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
/// let sobol = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_SOBOL as u32, dims: 2, points: 0, seed: 0, multiplier: 0 };
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
        let s = build(spec)?;
        if dims == 0 {
            return Err(NyqStatus::NYQ_ERR_ZERO_SIZE);
        }
        if dims > spec.dims {
            return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
        }
        let n = s.fill(first, dims, out)?;
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
/// let h = NyqSequence { kind: NyqSequenceKind::NYQ_SEQ_HAMMERSLEY as u32, dims: 2, points: 16, seed: 0, multiplier: 0 };
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
        let n = build(spec)?.point_count().unwrap_or(0);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, n) }
    })
}

/// The Halton sequence in `dims` dimensions, checked: `NYQ_ERR_ZERO_SIZE` for 0,
/// `NYQ_ERR_OUT_OF_RANGE` above 1024.
fn halton(dims: u32) -> Result<RuntimeHalton, NyqStatus> {
    Ok(RuntimeHalton::new(dims)?)
}

/// [`nyq_sequence_sample`] of the Halton sequence in `dims` dimensions (kind
/// `NYQ_SEQ_HALTON`): the same value and errors. A program that calls the Halton functions and
/// not [`nyq_sequence_sample`] links no radical-inverse table: the value comes from the core's
/// [`RuntimeHalton`], which computes its base's constants per call (bit for bit the tables'
/// value, somewhat slower).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `dims == 0`;
/// `NYQ_ERR_OUT_OF_RANGE` if `dims > 1024` or `dim >= dims`.
///
/// # Safety
/// `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_halton_sample};
/// let mut x = 0.0f32;
/// // SAFETY: valid pointer.
/// assert_eq!(unsafe { nyq_halton_sample(2, 3, 1, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, 1.0 / 9.0);
/// assert_eq!(unsafe { nyq_halton_sample(2, 3, 2, &mut x) }, NyqStatus::NYQ_ERR_OUT_OF_RANGE);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_halton_sample(
    dims: u32,
    index: u64,
    dim: u32,
    out: *mut f32,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let h = halton(dims)?;
        if dim >= dims {
            return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
        }
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, h.sample(index, dim)) }
    })
}

/// [`nyq_sequence_fill`] of the Halton sequence in `dims` dimensions (kind `NYQ_SEQ_HALTON`,
/// all `dims` of them written): points `first, first + 1, …` into `out[0..len]`, point-major,
/// and their number to `*written`; the same values and errors, linking no radical-inverse
/// table (as [`nyq_halton_sample`]).
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_ZERO_SIZE` if `len == 0` or `dims == 0`;
/// `NYQ_ERR_OUT_OF_RANGE` if `dims > 1024`; `NYQ_ERR_BUFFER` if `len` is not a multiple of
/// `dims` or `out` is misaligned; `NYQ_ERR_TOO_MANY` if the points run past `u64::MAX`. On
/// error `out` is unspecified.
///
/// # Safety
/// `out` is null or valid for writing `len` floats; `written` is null or valid for writing one
/// `uint64_t`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_halton_fill};
/// let (mut pts, mut n) = ([0.0f32; 6], 0u64);
/// // SAFETY: valid pointers, `pts` holds 6 floats.
/// assert_eq!(unsafe { nyq_halton_fill(1, 2, pts.as_mut_ptr(), 6, &mut n) }, NyqStatus::NYQ_OK);
/// assert_eq!((n, pts), (3, [0.5, 1.0 / 3.0, 0.25, 2.0 / 3.0, 0.75, 1.0 / 9.0]));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_halton_fill(
    first: u64,
    dims: u32,
    out: *mut f32,
    len: usize,
    written: *mut u64,
) -> NyqStatus {
    run(|| {
        need(written)?;
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        let n = halton(dims)?.fill(first, dims, out)?;
        // SAFETY: `written` is writable (caller; null checked above).
        unsafe { put(written, n) }
    })
}
