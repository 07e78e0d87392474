//! Point sets whose dimension count is a type parameter, for programs that count their bytes:
//! [`Halton<N>`], [`Sobol<N>`] and [`OwenSobol<N>`] return, bit for bit, what
//! [`sequence::Halton`], [`sequence::Sobol`] and [`sequence::OwenSobol`] return for the same
//! index, dimension and seed, without their speed tables.
//!
//! The constants a type needs — the first `N` primes and their digit-count and reciprocal
//! constants, or the first `N` dimensions' Sobol direction numbers — are `const` items evaluated
//! at compile time for that `N`. A `const` is emitted only where a program uses it, and only its
//! `N` rows; the desktop types read `static` tables that a program links whole (the 1024-base
//! radical-inverse tables are about 500 KB, Owen-Sobol's byte tables close to 1 MB). On a target
//! whose FPU is single precision (Cortex-M4F) values come from integer and `f32` operations only,
//! so nothing here calls a software `f64` routine; where the FPU does `f64` in hardware (x86-64,
//! AArch64, WASM), Halton's fast path rounds with the table path's own `f64` expression instead,
//! which is faster there and, by construction, the same bits.
//!
//! | type | code and constants on Cortex-M4F (`opt-level = "s"`, LTO) | per value |
//! |---|---|---|
//! | [`Halton<N>`] | about 2.7 KB + 100 bytes per dimension | one division per digit |
//! | [`Sobol<N>`] | about 200 bytes + 128 bytes per dimension | 32 masked XORs |
//! | [`OwenSobol<N>`] | about 650 bytes + 128 bytes per dimension | 32 masked XORs, two hashes |
//!
//! [`RuntimeHalton`] is Halton's twin for a dimension count chosen at run time: it stores no
//! per-base constants and computes the one a value needs from its base.
//!
//! The pixel samplers that read those tables have compact twins here too, each returning the
//! desktop sampler's bits through the same [`Sampler`](crate::sampler::Sampler) trait and
//! constructors: [`OwenSobolSampler<N>`], [`ZSobolSampler`], [`SobolSampler<N>`],
//! [`HaltonSampler<N>`] (every scramble) and [`Pmj02Sampler`] (its table points rebuilt one at a
//! time by running their construction backwards). The per-pixel hashing and index maps are the
//! desktop samplers' own code; only the values change source. `N` is the number of dimensions
//! whose constants a sampler carries (a camera sample and an integrator's first values: `N =
//! 8`); what a sampler does past `N` is in its docs. The lattice, stratified and random samplers
//! link no large table and need no twin.
//!
//! The desktop types stay the fast choice where memory is plentiful; `docs/embedded.md` in the
//! repository has the measured sizes and speeds.
//!
//! [`sequence::Halton`]: crate::sequence::Halton
//! [`sequence::Sobol`]: crate::sequence::Sobol
//! [`sequence::OwenSobol`]: crate::sequence::OwenSobol

use crate::Error;
use crate::hash::{hash2, mix32};
use crate::math::TWO_POW_MINUS_32;
use crate::math::{ONE_MINUS_EPSILON, fraction_to_f32};
use crate::radical::{PRIMES, fast_class, fast_limit, phi2, radical_inverse_f64};
use crate::scramble::lk_hash;
use crate::sequence::{IndexShuffle, Sequence, dim_seed, padded_u32_by, sobol_product};

/// `N` is in `1 ..= 1024`, or the type does not compile.
const fn check_dims<const N: usize>() {
    assert!(
        N >= 1 && N <= 1024,
        "the dimension count must be in 1..=1024"
    );
}

/// `dim % N` without a division when `dim < N` (the usual case).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn wrap<const N: usize>(dim: u32) -> usize {
    let d = dim as usize;
    if d < N { d } else { d % N }
}

// ---------------------------------------------------------------------------------------------
// Halton.

/// What the radical inverse of one base needs: the base, the fast path's limit and, per index
/// class (its length in nibbles, 1 ..= 8), the digits the reversal spans and the reciprocal's
/// `f64` bits (see [`phi_short`]).
#[derive(Clone, Copy, Debug)]
struct Base {
    b: u32,
    limit: u64,
    inv: [u64; 8],
    digits: [u8; 8],
}

const fn halton_bases<const N: usize>() -> [Base; N] {
    check_dims::<N>();
    let mut out = [Base {
        b: 2,
        limit: 0,
        inv: [0; 8],
        digits: [0; 8],
    }; N];
    let mut d = 1;
    while d < N {
        let mut base = Base {
            b: crate::radical::PRIMES[d],
            limit: fast_limit(d),
            inv: [0; 8],
            digits: [0; 8],
        };
        let mut c = 1;
        while c <= 8 {
            let (digits, inv) = fast_class(d, c);
            base.digits[c - 1] = digits as u8;
            base.inv[c - 1] = inv;
            c += 1;
        }
        out[d] = base;
        d += 1;
    }
    out
}

/// `x / b` and `x % b` for `b < 2¹⁶`, by 32-bit divisions only (no 64-bit division routine on
/// a 32-bit core): the high word, then two 16-bit limbs with the remainder carried in.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn div_small(x: u64, b: u32) -> (u64, u32) {
    let (hi, lo) = ((x >> 32) as u32, x as u32);
    let (q2, r) = (hi / b, hi % b);
    let t = (r << 16) | (lo >> 16);
    let (q1, r) = (t / b, t % b);
    let t = (r << 16) | (lo & 0xffff);
    let (q0, r) = (t / b, t % b);
    ((u64::from(q2) << 32) | u64::from((q1 << 16) | q0), r)
}

/// `q · 2^e` for `q < 2²⁵` and `-126 <= e <= 127`, in `f32` arithmetic: exact when `q` fits
/// 24 bits, as it does after [`round_bits`].
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn scale(q: u32, e: i32) -> f32 {
    q as f32 * f32::from_bits(((e + 127) as u32) << 23)
}

/// `(q + f) · 2^e` (`0 <= f < 1`, `sticky` true iff `f > 0`) rounded to `bits` significant bits,
/// to nearest, ties to even: the rounded mantissa and its exponent.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn round_bits(q: u128, e: i32, sticky: bool, bits: u32) -> (u128, i32) {
    let len = 128 - q.leading_zeros();
    if len <= bits {
        // Exact already; `sticky` cannot be set here for the callers (they keep enough bits).
        return (q, e);
    }
    let sh = len - bits;
    let rest = q & ((1u128 << sh) - 1);
    let half = 1u128 << (sh - 1);
    let mut m = q >> sh;
    if rest > half || (rest == half && (sticky || m & 1 == 1)) {
        m += 1;
    }
    (m, e + sh as i32)
}

/// The fast path's value for `a < b^k` (see `radical::fast_class`): the index's digits reversed
/// over `digits` places, `R'`, times the `f64` reciprocal `inv`, rounded to `f64` and then to
/// `f32` — the two roundings done on integers, so the result is the table path's to the bit.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phi_short(b: u32, digits: u32, inv: u64, a: u32) -> f32 {
    let mut x = a;
    let mut rev = 0u64;
    for _ in 0..digits {
        rev = rev * u64::from(b) + u64::from(x % b);
        x /= b;
    }
    narrow(rev, inv)
}

/// `R'·inv` rounded to `f64`, then to `f32`, clamped below 1 (`R' < 2⁴⁵`, exact in `f64`): the
/// table path's own expression, on targets whose FPU does `f64` in hardware.
#[cfg(any(
    target_arch = "x86_64",
    target_arch = "aarch64",
    target_arch = "wasm32"
))]
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn narrow(rev: u64, inv: u64) -> f32 {
    ((rev as f64 * f64::from_bits(inv)) as f32).min(ONE_MINUS_EPSILON)
}

/// As the `f64` form, by [`narrow_int`]: integer and `f32` operations only, for targets whose
/// FPU is single precision or absent.
#[cfg(not(any(
    target_arch = "x86_64",
    target_arch = "aarch64",
    target_arch = "wasm32"
)))]
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn narrow(rev: u64, inv: u64) -> f32 {
    narrow_int(rev, inv)
}

/// `R'·inv` (`R' < 2⁴⁵`, `inv` the bits of a positive normal `f64`) rounded to `f64` and then to
/// `f32`, clamped below 1, with integer and `f32` operations only: the same bits as
/// `((R' as f64) * inv) as f32` (a test compares the two on the host).
#[cfg_attr(
    any(
        target_arch = "x86_64",
        target_arch = "aarch64",
        target_arch = "wasm32"
    ),
    allow(dead_code)
)]
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn narrow_int(rev: u64, inv: u64) -> f32 {
    if rev == 0 {
        return 0.0;
    }
    // inv = m · 2^e exactly (a normal f64).
    let m = (inv & ((1 << 52) - 1)) | (1 << 52);
    let e = (inv >> 52) as i32 - 1075;
    // R' < 2⁴⁵ and m < 2⁵³: the product is exact in 128 bits.
    let (m53, e53) = round_bits(u128::from(rev) * u128::from(m), e, false, 53);
    let (m24, e24) = round_bits(m53, e53, false, 24);
    scale(m24 as u32, e24).min(ONE_MINUS_EPSILON)
}

/// Φ_b(a) for any `a`, correctly rounded to `f32` (what the table path returns for an index at
/// or past `b^k`): the exact fraction `num / b^m` of the reversed digits, divided bit by bit.
#[inline(never)]
fn phi_long(b: u32, a: u64) -> f32 {
    let (mut num, mut den) = (0u128, 1u128);
    let mut x = a;
    while x > 0 {
        let (q, r) = div_small(x, b);
        num = num * u128::from(b) + u128::from(r);
        den *= u128::from(b);
        x = q;
    }
    if num == 0 {
        return 0.0;
    }
    // Align num's top bit with den's: num / den = r / den · 2^-s with r / den in (½, 2).
    let s = num.leading_zeros() - den.leading_zeros();
    let mut r = num << s;
    // 26 quotient bits: floor(r / den · 2²⁵), with 25 or 26 significant bits.
    let mut q = 0u128;
    for _ in 0..26 {
        q <<= 1;
        if r >= den {
            r -= den;
            q |= 1;
        }
        r <<= 1;
    }
    let (m, e) = round_bits(q, -(s as i32) - 25, r != 0, 24);
    scale(m as u32, e).min(ONE_MINUS_EPSILON)
}

/// The Halton sequence over its first `N` dimensions (`1 <= N <= 1024`, checked at compile
/// time): dimension `d` of point `i` is Φ_{p_d}(i), bit for bit what
/// [`sequence::Halton`](crate::sequence::Halton)`::new(N)` returns, for every `u64` index.
///
/// Carries about 100 bytes of constants per dimension, computed at compile time, and none of
/// the radical-inverse tables; without a double-precision FPU, `f32` values use integer and
/// `f32` arithmetic only. Slower than the table path: one 32-bit division per digit, and a
/// bit-by-bit division for indices at or past the base's largest power below 2³². `dim >= N`
/// wraps modulo `N`. Allocates: no.
///
/// ```
/// use nyquist::compact::Halton;
/// use nyquist::sequence::{self, Sequence};
/// let h = Halton::<2>::new();
/// assert_eq!(h.sample(1, 1), 1.0 / 3.0);
/// let table = sequence::Halton::new(2).unwrap();
/// for i in [0, 5, 123_456_789, u64::MAX] {
///     assert_eq!(h.sample(i, 1).to_bits(), table.sample(i, 1).to_bits());
/// }
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Halton<const N: usize>;

impl<const N: usize> Halton<N> {
    const BASES: [Base; N] = halton_bases::<N>();

    /// The sequence. (A unit struct: `Halton::<N>` is a value too.) `N` outside `1..=1024`
    /// does not compile.
    ///
    /// ```
    /// use nyquist::{compact::Halton, sequence::Sequence};
    /// const H: Halton<3> = Halton::new();
    /// assert_eq!((H.dims(), H.sample(1, 2)), (3, 0.2));
    /// ```
    pub const fn new() -> Self {
        const { check_dims::<N>() };
        Halton
    }
}

impl<const N: usize> Sequence for Halton<N> {
    fn dims(&self) -> u32 {
        N as u32
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        let d = wrap::<N>(dim);
        if d == 0 {
            return phi2(index);
        }
        let base = &Self::BASES[d];
        if index < base.limit {
            // Below 2³²: the class is the index's length in nibbles, 1 ..= 8 (0 is index 0).
            let class = (64 - index.leading_zeros()).div_ceil(4) as usize;
            let Some(c) = class.checked_sub(1) else {
                return 0.0;
            };
            return phi_short(base.b, u32::from(base.digits[c]), base.inv[c], index as u32);
        }
        phi_long(base.b, index)
    }

    /// As [`sequence::Halton`](crate::sequence::Halton)'s (the table path, in `f64`).
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        radical_inverse_f64(wrap::<N>(dim) as u32, index)
    }
}

/// The Halton sequence in `dims` dimensions chosen at run time (1 ..= 1024) with no per-base
/// constants stored: bit for bit what [`sequence::Halton`](crate::sequence::Halton)`::new(dims)`
/// returns in `f32`, for every `u64` index and dimension (`dim >= dims` wraps modulo `dims`).
///
/// Where [`Halton<N>`] stores each base's constants (about 100 bytes per dimension), this type
/// computes the one it needs for each value from the base (a few dozen integer operations and
/// one `f64` division more per value), so a program carries the 4 KB prime table and the code
/// only, whatever `dims` is. For programs that pick the dimension count at run time and count
/// their bytes (the C library's `nyq_halton_sample`). Allocates: no.
///
/// ```
/// use nyquist::compact::RuntimeHalton;
/// use nyquist::sequence::{self, Sequence};
/// let h = RuntimeHalton::new(300).unwrap();
/// let table = sequence::Halton::new(300).unwrap();
/// for i in [0, 5, 123_456_789, u64::MAX] {
///     assert_eq!(h.sample(i, 299).to_bits(), table.sample(i, 299).to_bits());
/// }
/// assert!(RuntimeHalton::new(1025).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RuntimeHalton {
    dims: u32,
}

impl RuntimeHalton {
    /// The sequence in `dims` dimensions.
    ///
    /// # Errors
    /// As [`sequence::Halton::new`](crate::sequence::Halton::new): [`Error::ZeroSize`] for 0,
    /// [`Error::NotInRange`] above 1024.
    ///
    /// ```
    /// use nyquist::{compact::RuntimeHalton, sequence::Sequence};
    /// assert_eq!(RuntimeHalton::new(3).unwrap().sample(1, 2), 0.2);
    /// assert!(RuntimeHalton::new(0).is_err());
    /// ```
    pub fn new(dims: u32) -> Result<Self, Error> {
        Ok(RuntimeHalton {
            dims: crate::sequence::Halton::new(dims)?.dims(),
        })
    }
}

impl Sequence for RuntimeHalton {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        let d = (dim % self.dims) as usize;
        if d == 0 {
            return phi2(index);
        }
        let b = PRIMES[d];
        if index < fast_limit(d) {
            // As `Halton<N>`, with the class's constants computed here.
            let class = (64 - index.leading_zeros()).div_ceil(4) as usize;
            if class == 0 {
                return 0.0;
            }
            let (digits, inv) = fast_class(d, class);
            return phi_short(b, digits, inv, index as u32);
        }
        phi_long(b, index)
    }

    /// As [`sequence::Halton`](crate::sequence::Halton)'s (the table path, in `f64`, which
    /// links the exact path's tables).
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        radical_inverse_f64(dim % self.dims, index)
    }
}

// ---------------------------------------------------------------------------------------------
// Sobol.

/// The direction numbers of dimensions `0..N`, copied at compile time from the full table.
const fn sobol_directions<const N: usize>() -> [[u32; 32]; N] {
    check_dims::<N>();
    let mut out = [[0u32; 32]; N];
    // With `lazy-tables` the full table is built at run time; these rows come from the same
    // packed direction numbers, at compile time.
    #[cfg(all(feature = "lazy-tables", not(test)))]
    crate::sequence::sobol_matrix_rows(&mut out);
    #[cfg(any(not(feature = "lazy-tables"), test))]
    {
        let mut d = 0;
        while d < N {
            out[d] = crate::sequence::SOBOL_MATRICES[d];
            d += 1;
        }
    }
    out
}

/// The columns past 32 of dimensions `0..N` ([`sobol_u64`](crate::sequence::sobol_u64)), copied
/// or built at compile time as [`sobol_directions`] is.
const fn sobol_directions_hi<const N: usize>() -> [[u32; 32]; N] {
    check_dims::<N>();
    let mut out = [[0u32; 32]; N];
    #[cfg(all(feature = "lazy-tables", not(test)))]
    crate::sequence::sobol_matrix_rows_hi(&mut out);
    #[cfg(any(not(feature = "lazy-tables"), test))]
    {
        let mut d = 0;
        while d < N {
            out[d] = crate::sequence::SOBOL_MATRICES_HI[d];
            d += 1;
        }
    }
    out
}

/// The Sobol sequence over its first `N` dimensions (`1 <= N <= 1024`, checked at compile
/// time), optionally digitally shifted: bit for bit what
/// [`sequence::Sobol`](crate::sequence::Sobol)`::new(N)` (or `with_digital_shift(N, seed)`) returns.
///
/// Carries the `N` dimensions' direction numbers (128 bytes each, computed at compile time),
/// their columns past 32 (128 bytes more, linked only where an index past 2³² can reach
/// them) and none of the byte tables; each value is a 32-column masked XOR, two past 2³².
/// Indices are 64-bit; `dim >= N` wraps modulo `N`. Allocates: no.
///
/// ```
/// use nyquist::compact::Sobol;
/// use nyquist::sequence::{self, Sequence};
/// let s = Sobol::<4>::new();
/// assert_eq!([0, 1, 2, 3].map(|i| s.sample(i, 1)), [0.0, 0.5, 0.75, 0.25]);
/// let table = sequence::Sobol::with_digital_shift(4, 9).unwrap();
/// assert_eq!(Sobol::<4>::with_digital_shift(9).sample_u32(77, 3), table.sample_u32(77, 3));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sobol<const N: usize> {
    seed: u64,
    scrambled: bool,
}

impl<const N: usize> Sobol<N> {
    const DIRECTIONS: [[u32; 32]; N] = sobol_directions::<N>();
    const DIRECTIONS_HI: [[u32; 32]; N] = sobol_directions_hi::<N>();

    /// The unscrambled sequence. `N` outside `1..=1024` does not compile.
    ///
    /// ```
    /// use nyquist::{compact::Sobol, sequence::Sequence};
    /// let s = Sobol::<2>::new();
    /// assert_eq!([s.sample(3, 0), s.sample(3, 1)], [0.75, 0.25]);
    /// ```
    pub const fn new() -> Self {
        const { check_dims::<N>() };
        Sobol {
            seed: 0,
            scrambled: false,
        }
    }

    /// The sequence with the digital shift of
    /// [`sequence::Sobol::with_digital_shift`](crate::sequence::Sobol::with_digital_shift).
    ///
    /// ```
    /// use nyquist::compact::Sobol;
    /// let (plain, shifted) = (Sobol::<2>::new(), Sobol::<2>::with_digital_shift(7));
    /// // A digital shift XORs each dimension with one constant.
    /// let x = plain.sample_u32(0, 1) ^ shifted.sample_u32(0, 1);
    /// assert_eq!(plain.sample_u32(9, 1) ^ shifted.sample_u32(9, 1), x);
    /// ```
    pub const fn with_digital_shift(seed: u64) -> Self {
        const { check_dims::<N>() };
        Sobol {
            seed,
            scrambled: true,
        }
    }

    /// Point `index`, dimension `dim` as a 32-bit fraction (`value / 2³²`), scramble applied.
    ///
    /// ```
    /// use nyquist::{compact::Sobol, sequence::sobol_u32};
    /// assert_eq!(Sobol::<8>::new().sample_u32(77, 5), sobol_u32(77, 5));
    /// ```
    #[inline]
    pub fn sample_u32(&self, index: u64, dim: u32) -> u32 {
        let d = wrap::<N>(dim);
        let shift = if self.scrambled {
            (hash2(self.seed, d as u64) >> 32) as u32
        } else {
            0
        };
        let hi = (index >> 32) as u32;
        let upper = if hi == 0 {
            0
        } else {
            sobol_product(&Self::DIRECTIONS_HI[d], hi)
        };
        sobol_product(&Self::DIRECTIONS[d], index as u32) ^ upper ^ shift
    }
}

impl<const N: usize> Sequence for Sobol<N> {
    fn dims(&self) -> u32 {
        N as u32
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        fraction_to_f32(self.sample_u32(index, dim))
    }

    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        f64::from(self.sample_u32(index, dim)) * TWO_POW_MINUS_32
    }
}

// ---------------------------------------------------------------------------------------------
// Owen-scrambled Sobol.

/// The Owen-scrambled Sobol sequence over its first `N` dimensions (`1 <= N <= 1024`, checked
/// at compile time): bit for bit what [`sequence::OwenSobol`](crate::sequence::OwenSobol)`::new(N,
/// seed)` returns, through `sample`, [`OwenSobol::sample_u32`] and [`OwenSobol::sample_4d`].
///
/// Carries the `N` dimensions' direction numbers (computed at compile time) and their `N`
/// scramble seeds, and none of the byte tables; each value is a 32-column masked XOR and two
/// hashes (past 2³², the columns past 32 and the upper half's shuffle too). Indices are
/// 64-bit; `dim >= N` wraps modulo `N`. Allocates: no.
///
/// ```
/// use nyquist::compact::OwenSobol;
/// use nyquist::sequence::{self, Sequence};
/// let s = OwenSobol::<4>::new(7);
/// let table = sequence::OwenSobol::new(4, 7).unwrap();
/// assert_eq!(s.sample_4d(1000, 0), table.sample_4d(1000, 0));
/// assert_eq!(s.sample(3, 2), table.sample(3, 2));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OwenSobol<const N: usize> {
    seed: u64,
    shuffle: IndexShuffle,
    seeds: [u32; N],
}

/// The direction numbers of dimensions `0..N` for bit-reversed words: `out[d][j]` is column
/// `31 − j` reversed, so that the product over the bits of a reversed index `r` is
/// `reverse(sobol(reverse(r), d))` with no reversal at run time.
const fn reversed_directions<const N: usize>() -> [[u32; 32]; N] {
    let m = sobol_directions::<N>();
    let mut out = [[0u32; 32]; N];
    let mut d = 0;
    while d < N {
        let mut j = 0;
        while j < 32 {
            out[d][j] = m[d][31 - j].reverse_bits();
            j += 1;
        }
        d += 1;
    }
    out
}

/// A padding dimension as [`padded_u32`](crate::sequence::padded_u32) gives it (`dim >= 1024`
/// of the stream `key`), from Sobol dimensions 0..3 as compile-time constants (1 KiB, linked
/// only where a padding dimension can be asked for) instead of the desktop byte tables.
pub(crate) fn padded_u32(key: u32, index: u64, dim: u32) -> u32 {
    const REVERSED: [[u32; 32]; 4] = reversed_directions::<4>();
    const HI: [[u32; 32]; 4] = sobol_directions_hi::<4>();
    padded_u32_by(key, index, dim, |d, (r, hi)| {
        let p = sobol_product(&REVERSED[d], r);
        if hi == 0 {
            p
        } else {
            p ^ sobol_product(&HI[d], hi).reverse_bits()
        }
    })
}

impl<const N: usize> OwenSobol<N> {
    const REVERSED: [[u32; 32]; N] = reversed_directions::<N>();
    const DIRECTIONS_HI: [[u32; 32]; N] = sobol_directions_hi::<N>();

    /// The sequence scrambled by `seed` (every seed, 0 included, is a scramble). `N` outside
    /// `1..=1024` does not compile.
    ///
    /// ```
    /// use nyquist::{compact::OwenSobol, sequence::Sequence};
    /// let s = OwenSobol::<2>::new(0);
    /// // Any seed: the first 2 points put one value in each half of every dimension.
    /// assert_ne!(s.sample(0, 1) < 0.5, s.sample(1, 1) < 0.5);
    /// ```
    pub fn new(seed: u64) -> Self {
        const { check_dims::<N>() };
        let h = hash2(seed, 0x4f57_454e); // "OWEN", as the table path.
        OwenSobol {
            seed,
            shuffle: IndexShuffle::new(mix32((h >> 32) as u32)),
            seeds: core::array::from_fn(|d| dim_seed(h as u32, d as u32)),
        }
    }

    /// The seed this sequence was built with.
    ///
    /// ```
    /// assert_eq!(nyquist::compact::OwenSobol::<2>::new(9).seed(), 9);
    /// ```
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The scrambled value, bit-reversed, of dimension `d < N` at the shuffled index
    /// `(r, hi)` ([`IndexShuffle::rev64`]'s split: the reversed low half, the upper half).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value_rev(&self, (r, hi): (u32, u32), d: usize) -> u32 {
        let mut p = sobol_product(&Self::REVERSED[d], r);
        if hi != 0 {
            p ^= sobol_product(&Self::DIRECTIONS_HI[d], hi).reverse_bits();
        }
        lk_hash(p, self.seeds[d])
    }

    /// Point `index`, dimension `dim` as a 32-bit binary fraction.
    ///
    /// ```
    /// use nyquist::{compact::OwenSobol, sequence};
    /// let table = sequence::OwenSobol::new(3, 1).unwrap();
    /// assert_eq!(OwenSobol::<3>::new(1).sample_u32(5, 4), table.sample_u32(5, 4));
    /// ```
    #[inline]
    pub fn sample_u32(&self, index: u64, dim: u32) -> u32 {
        self.value_rev(self.shuffle.rev64(index), wrap::<N>(dim))
            .reverse_bits()
    }

    /// Four consecutive dimensions `first_dim .. first_dim + 4` (each wrapping) of point
    /// `index`, sharing the index shuffle; equal to four calls of `sample`.
    ///
    /// ```
    /// use nyquist::{compact::OwenSobol, sequence::Sequence};
    /// let s = OwenSobol::<8>::new(3);
    /// assert_eq!(s.sample_4d(77, 6), [6, 7, 0, 1].map(|d| s.sample(77, d)));
    /// ```
    #[inline]
    pub fn sample_4d(&self, index: u64, first_dim: u32) -> [f32; 4] {
        let r = self.shuffle.rev64(index);
        core::array::from_fn(|k| {
            let d = wrap::<N>(first_dim.wrapping_add(k as u32));
            fraction_to_f32(self.value_rev(r, d).reverse_bits())
        })
    }
}

impl<const N: usize> Sequence for OwenSobol<N> {
    fn dims(&self) -> u32 {
        N as u32
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        fraction_to_f32(self.sample_u32(index, dim))
    }

    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        f64::from(self.sample_u32(index, dim)) * TWO_POW_MINUS_32
    }
}

mod halton_sampler;
mod owen_sobol_sampler;
mod pmj02_sampler;
pub(crate) use pmj02_sampler::pmj02_point;
mod sobol_sampler;
mod zsobol_sampler;

pub use halton_sampler::HaltonSampler;
pub use owen_sobol_sampler::OwenSobolSampler;
pub use pmj02_sampler::Pmj02Sampler;
pub use sobol_sampler::SobolSampler;
pub use zsobol_sampler::ZSobolSampler;

#[cfg(test)]
mod sampler_tests;
#[cfg(test)]
mod tests;
