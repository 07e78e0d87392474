//! Every sampler of the crate by name: what the CLI's `--sampler NAME --spp SPP --size WxH
//! --seed SEED` and the C API's `nyq_sampler_create` build.

use core::fmt;

use super::{
    AdaptiveSampler, BestCandidateSampler, DitheredSampler, HaltonSampler, HammersleySampler,
    Jitter, LatticeBlueSampler, LatticeSampler, MaskView, OwenSobolBlueSampler, OwenSobolSampler,
    Pmj02BlueSampler, Pmj02Sampler, RandomSampler, Sampler, SobolSampler, StratifiedSampler,
    ZSobolSampler, ZeroTwoSampler,
};
use crate::scramble::Scramble;

/// The names [`NamedSampler::new`] accepts, in the order the CLI lists them.
///
/// ```
/// use nyquist::sampler::{NamedSampler, NAMES};
/// assert_eq!(NAMES.len(), 19);
/// for name in NAMES {
///     let s = NamedSampler::new(name, [8, 8], 16, 1).unwrap();
///     assert_eq!(s.name(), name);
/// }
/// ```
pub const NAMES: [&str; 19] = [
    "random",
    "uniform",
    "stratified",
    "halton",
    "hammersley",
    "zero-two",
    "sobol",
    "best-candidate",
    "adaptive",
    "owen-sobol",
    "owen-sobol-bn",
    "zsobol",
    "pmj02",
    "pmj02-bn",
    "bluenoise-dithered",
    "fibonacci",
    "r2",
    "korobov",
    "lattice-bn",
];

/// The names of [`NAMES`] that take a scramble through [`NamedSampler::with_scramble`].
///
/// ```
/// use nyquist::sampler::{NAMES, SCRAMBLE_NAMES};
/// assert!(SCRAMBLE_NAMES.iter().all(|n| NAMES.contains(n)));
/// ```
pub const SCRAMBLE_NAMES: [&str; 4] = ["halton", "hammersley", "sobol", "zsobol"];

/// Names [`NamedSampler::new`] also accepts: `halton-plain`, `hammersley-plain` and
/// `sobol-plain` are `halton`, `hammersley` and `sobol` without their digit permutation (the
/// unscrambled sequences, one deterministic set whatever the seed; their [`NamedSampler::name`]
/// is `halton`, `hammersley` and `sobol`), and `sobol-owen` is `owen-sobol`.
///
/// ```
/// use nyquist::sampler::{NamedSampler, Sampler, OTHER_NAMES};
/// use nyquist::{sampler::SobolSampler, scramble::Scramble};
/// assert_eq!(OTHER_NAMES, ["halton-plain", "hammersley-plain", "sobol-plain", "sobol-owen"]);
/// let mut plain = NamedSampler::new("sobol-plain", [4, 4], 4, 99).unwrap();
/// let mut direct = SobolSampler::new([4, 4], 4, Scramble::None, 0).unwrap();
/// plain.start_pixel_sample([1, 2], 3, 0);
/// direct.start_pixel_sample([1, 2], 3, 0);
/// assert_eq!(plain.get_2d(), direct.get_2d());
/// ```
pub const OTHER_NAMES: [&str; 4] = [
    "halton-plain",
    "hammersley-plain",
    "sobol-plain",
    "sobol-owen",
];

/// The name [`NamedSampler::new`] builds for `name`: one of [`NAMES`] or [`OTHER_NAMES`],
/// compared ignoring ASCII case, as its canonical spelling (`None` for an unknown name).
///
/// ```
/// use nyquist::sampler::canonical_name;
/// assert_eq!(canonical_name("ZSobol"), Some("zsobol"));
/// assert_eq!(canonical_name("Sobol-Owen"), Some("sobol-owen"));
/// assert_eq!(canonical_name("sobol "), None);
/// ```
pub fn canonical_name(name: &str) -> Option<&'static str> {
    NAMES
        .iter()
        .chain(&OTHER_NAMES)
        .find(|n| n.eq_ignore_ascii_case(name))
        .copied()
}

/// The names of [`NAMES`] whose every sample index is a new sample, past the spp they were
/// made for: drawing `spp · k` samples from one made for `spp` continues the set instead of
/// repeating it (the spp given is a hint). The others lay out a fixed set for their spp and
/// wrap past it (zero-two and r2 are progressive up to their spp).
///
/// ```
/// use nyquist::sampler::{NAMES, CONTINUING_NAMES, continues};
/// assert!(CONTINUING_NAMES.iter().all(|n| NAMES.contains(n)));
/// assert!(continues("ZSobol") && continues("sobol-plain") && !continues("zero-two"));
/// ```
pub const CONTINUING_NAMES: [&str; 9] = [
    "random",
    "halton",
    "sobol",
    "owen-sobol",
    "owen-sobol-bn",
    "zsobol",
    "pmj02",
    "pmj02-bn",
    "lattice-bn",
];

/// Whether sampler `name` (as [`canonical_name`] takes it) is one of [`CONTINUING_NAMES`],
/// or an [`OTHER_NAMES`] spelling of one (`halton-plain`, `sobol-plain`, `sobol-owen`).
pub fn continues(name: &str) -> bool {
    let name = match canonical_name(name) {
        Some("halton-plain") => "halton",
        Some("sobol-plain") => "sobol",
        Some("sobol-owen") => "owen-sobol",
        Some(n) => n,
        None => return false,
    };
    CONTINUING_NAMES.contains(&name)
}

/// The most samples per pixel sampler `name` takes (`None`: no limit of its own below
/// `u32::MAX`; the image-wide samplers `sobol` and `zsobol` also bound spp × pixels, which
/// depends on the size): `best-candidate`'s baked table has 4096 rows, `pmj02`'s
/// construction 65536 points. Names as [`canonical_name`] takes them.
///
/// ```
/// use nyquist::sampler::spp_limit;
/// assert_eq!(spp_limit("best-candidate"), Some(4096));
/// assert_eq!(spp_limit("PMJ02"), Some(65536));
/// assert_eq!(spp_limit("random"), None);
/// ```
pub fn spp_limit(name: &str) -> Option<u32> {
    match canonical_name(name)? {
        "best-candidate" => Some(super::best_candidate::TABLE_SIZE),
        "pmj02" => u32::try_from(crate::sequence::PMJ02_MAX_POINTS).ok(),
        _ => None,
    }
}

/// The strata grid `[nx, ny]` of `uniform` and `stratified` for `spp` samples: `ny` the largest
/// divisor of `spp` with `ny² ≤ spp`, `nx = spp / ny` (√spp × √spp for a square; for
/// `spp = 2^m`, `2^⌈m/2⌉ × 2^⌊m/2⌋`), so that every spp has a grid.
///
/// ```
/// use nyquist::sampler::strata;
/// assert_eq!(strata(16), [4, 4]);
/// assert_eq!(strata(32), [8, 4]);
/// assert_eq!(strata(7), [7, 1]);
/// ```
pub fn strata(spp: u32) -> [u32; 2] {
    let ny = (1..=spp.max(1).isqrt())
        .rev()
        .find(|&d| spp.is_multiple_of(d))
        .unwrap_or(1);
    [spp.max(1) / ny, ny]
}

/// Threshold of the `adaptive` sampler (see [`AdaptiveSampler::new`]).
const ADAPTIVE_THRESHOLD: f32 = 0.1;

/// Why [`NamedSampler::new`] rejected its input.
///
/// ```
/// use nyquist::sampler::{NamedSampler, NamedSamplerError};
/// assert_eq!(NamedSampler::new("nope", [1, 1], 4, 0).unwrap_err(), NamedSamplerError::UnknownName);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum NamedSamplerError {
    /// The name is not one of [`NAMES`].
    UnknownName,
    /// `spp` is above the sampler's own limit ([`spp_limit`]).
    SppAboveLimit {
        /// The samples per pixel asked for.
        spp: u32,
        /// The most the sampler takes.
        max: u32,
    },
    /// Width, height or spp was zero ([`crate::Error::ZeroSize`]), or the sampler rejected
    /// the parameters.
    Sampler(crate::Error),
    /// [`NamedSampler::with_scramble`] for a sampler without a scramble choice (only those of
    /// [`SCRAMBLE_NAMES`] have one).
    NoScramble,
}

impl fmt::Display for NamedSamplerError {
    /// Lowercase, names the fault.
    ///
    /// ```
    /// use nyquist::sampler::NamedSamplerError;
    /// let e = NamedSamplerError::SppAboveLimit { spp: 5000, max: 4096 };
    /// assert_eq!(e.to_string(), "spp 5000 is above this sampler's limit of 4096");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            NamedSamplerError::UnknownName => {
                f.write_str("unknown sampler name (known: ")?;
                for (i, n) in NAMES.iter().chain(&OTHER_NAMES).enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    f.write_str(n)?;
                }
                f.write_str(")")
            }
            NamedSamplerError::SppAboveLimit { spp, max } => {
                write!(f, "spp {spp} is above this sampler's limit of {max}")
            }
            NamedSamplerError::Sampler(e) => e.fmt(f),
            NamedSamplerError::NoScramble => {
                f.write_str("no scramble choice (halton, hammersley, sobol and zsobol have one)")
            }
        }
    }
}

impl core::error::Error for NamedSamplerError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            NamedSamplerError::Sampler(e) => Some(e),
            _ => None,
        }
    }
}

impl From<crate::Error> for NamedSamplerError {
    /// Wraps a core error as [`NamedSamplerError::Sampler`].
    ///
    /// ```
    /// use nyquist::{Error, sampler::NamedSamplerError};
    /// let e = NamedSamplerError::from(Error::TooMany { what: "spp", value: 5000, max: 4096 });
    /// assert_eq!(
    ///     e,
    ///     NamedSamplerError::Sampler(Error::TooMany { what: "spp", value: 5000, max: 4096 })
    /// );
    /// ```
    fn from(e: crate::Error) -> Self {
        NamedSamplerError::Sampler(e)
    }
}

/// One of the crate's samplers, chosen by name at run time; implements [`Sampler`] by
/// delegating to the sampler it holds (one `match` per call, no allocation).
///
/// A caller that wants a monomorphized sample loop can `match` on the variants itself.
///
/// ```
/// use nyquist::sampler::{NamedSampler, Sampler, ZeroTwoSampler};
/// let mut a = NamedSampler::new("zero-two", [8, 8], 3, 5).unwrap();
/// let mut b = ZeroTwoSampler::new(3, 5).unwrap();
/// assert_eq!(a.samples_per_pixel(), 4); // rounded up to a power of two
/// a.start_pixel_sample([1, 2], 3, 0);
/// b.start_pixel_sample([1, 2], 3, 0);
/// assert_eq!(a.get_2d(), b.get_2d());
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum NamedSampler {
    /// `random`.
    Random(RandomSampler),
    /// `uniform` (centred strata) and `stratified` (jittered strata).
    Stratified(StratifiedSampler),
    /// `halton`.
    Halton(HaltonSampler),
    /// `hammersley`.
    Hammersley(HammersleySampler),
    /// `zero-two`.
    ZeroTwo(ZeroTwoSampler),
    /// `sobol`.
    Sobol(SobolSampler),
    /// `best-candidate`.
    BestCandidate(BestCandidateSampler),
    /// `adaptive`.
    Adaptive(AdaptiveSampler<ZeroTwoSampler>),
    /// `owen-sobol`.
    OwenSobol(OwenSobolSampler),
    /// `owen-sobol-bn`.
    OwenSobolBlue(OwenSobolBlueSampler),
    /// `pmj02-bn`.
    Pmj02Blue(Pmj02BlueSampler),
    /// `lattice-bn`.
    LatticeBlue(LatticeBlueSampler),
    /// `zsobol`.
    ZSobol(ZSobolSampler),
    /// `pmj02`.
    Pmj02(Pmj02Sampler),
    /// `bluenoise-dithered`.
    Dithered(DitheredSampler<'static, ZeroTwoSampler>),
    /// `fibonacci`, `r2` and `korobov`.
    Lattice(LatticeSampler),
}

/// Evaluates `$body` with `$s` bound to the sampler inside `$self`.
macro_rules! delegate {
    ($self:expr, $s:ident => $body:expr) => {
        match $self {
            NamedSampler::Random($s) => $body,
            NamedSampler::Stratified($s) => $body,
            NamedSampler::Halton($s) => $body,
            NamedSampler::Hammersley($s) => $body,
            NamedSampler::ZeroTwo($s) => $body,
            NamedSampler::Sobol($s) => $body,
            NamedSampler::BestCandidate($s) => $body,
            NamedSampler::Adaptive($s) => $body,
            NamedSampler::OwenSobol($s) => $body,
            NamedSampler::OwenSobolBlue($s) => $body,
            NamedSampler::Pmj02Blue($s) => $body,
            NamedSampler::LatticeBlue($s) => $body,
            NamedSampler::ZSobol($s) => $body,
            NamedSampler::Pmj02($s) => $body,
            NamedSampler::Dithered($s) => $body,
            NamedSampler::Lattice($s) => $body,
        }
    };
}

impl NamedSampler {
    /// Sampler `name` (one of [`NAMES`]) for `spp` samples per pixel of a `size` image
    /// (`[width, height]` in pixels) with `seed`:
    ///
    /// - `random`: [`RandomSampler`];
    /// - `uniform`, `stratified`: a [`StratifiedSampler`] on the [`strata`] grid (√spp × √spp
    ///   for a square spp), cell centres ([`Jitter::Centered`]) or jittered;
    /// - `halton`: [`HaltonSampler`] over the image, digit-permuted by `seed`
    ///   ([`Scramble::PermuteDigits`]; every seed, 0 included, permutes);
    /// - `hammersley`: [`HammersleySampler`], digit-permuted by `seed`;
    /// - `zero-two`: [`ZeroTwoSampler`] (spp rounded up to a power of two);
    /// - `sobol`: [`SobolSampler`] over the image, digit-permuted by `seed` (spp rounded up to
    ///   a power of two);
    /// - `best-candidate`: [`BestCandidateSampler`];
    /// - `adaptive`: an [`AdaptiveSampler`] over a `zero-two` sampler, between a quarter of its
    ///   spp (at least 1) and all of it, threshold 0.1;
    /// - `owen-sobol`: [`OwenSobolSampler`] (frame 0);
    /// - `owen-sobol-bn`: [`OwenSobolBlueSampler`] (frame 0): Owen-Sobol with blue-noise error
    ///   across pixels;
    /// - `zsobol`: [`ZSobolSampler`] over the image, fast-Owen scrambled (spp rounded up to a
    ///   power of two);
    /// - `pmj02`: [`Pmj02Sampler`] (spp up to 65536);
    /// - `pmj02-bn`, `lattice-bn`: [`Pmj02BlueSampler`] and [`LatticeBlueSampler`] (frame 0):
    ///   PMJ(0,2) and an extensible rank-1 lattice per pixel, with blue-noise error across
    ///   pixels;
    /// - `bluenoise-dithered`: a [`DitheredSampler`] over the `zero-two` set of pixel (0, 0),
    ///   shifted per pixel by the built-in 64 × 64 two-channel mask ([`MaskView::builtin`]);
    /// - `fibonacci`, `r2`, `korobov`: [`LatticeSampler::fibonacci`] (spp rounded up to a
    ///   Fibonacci number), [`LatticeSampler::r2`] and [`LatticeSampler::korobov`] (exactly spp
    ///   points, its multiplier searched here, in time about linear in spp: `docs/performance.md`).
    ///
    /// Names are compared ignoring ASCII case, and [`OTHER_NAMES`] are accepted too
    /// ([`canonical_name`]). The size matters to `halton`, `hammersley`, `sobol` and `zsobol`
    /// only, but must be non-zero for all. Allocates: no.
    ///
    /// # Errors
    /// Checked in this order: [`NamedSamplerError::Sampler`]`(`[`ZeroSize`](crate::Error::ZeroSize)`)`
    /// if the width, height or `spp` is 0; [`NamedSamplerError::UnknownName`];
    /// [`NamedSamplerError::SppAboveLimit`] above [`spp_limit`]; then whatever the sampler's
    /// constructor rejects, as [`NamedSamplerError::Sampler`].
    ///
    /// ```
    /// use nyquist::{Error, sampler::{NamedSampler, NamedSamplerError, Sampler}};
    /// assert_eq!(NamedSampler::new("stratified", [4, 4], 9, 0).unwrap().samples_per_pixel(), 9);
    /// assert_eq!(NamedSampler::new("Uniform", [4, 4], 8, 0).unwrap().samples_per_pixel(), 8);
    /// assert_eq!(
    ///     NamedSampler::new("pmj02", [4, 4], 1 << 17, 0).unwrap_err(),
    ///     NamedSamplerError::SppAboveLimit { spp: 1 << 17, max: 1 << 16 }
    /// );
    /// assert_eq!(
    ///     NamedSampler::new("nope", [0, 4], 8, 0).unwrap_err(),
    ///     NamedSamplerError::Sampler(Error::ZeroSize { what: "width" })
    /// );
    /// ```
    pub fn new(
        name: &str,
        size: [u32; 2],
        spp: u32,
        seed: u64,
    ) -> Result<NamedSampler, NamedSamplerError> {
        for (v, what) in [(size[0], "width"), (size[1], "height"), (spp, "spp")] {
            if v == 0 {
                return Err(crate::Error::ZeroSize { what }.into());
            }
        }
        let name = canonical_name(name).ok_or(NamedSamplerError::UnknownName)?;
        if let Some(max) = spp_limit(name)
            && spp > max
        {
            return Err(NamedSamplerError::SppAboveLimit { spp, max });
        }
        let [nx, ny] = strata(spp);
        let scramble = Scramble::PermuteDigits;
        Ok(match name {
            "random" => NamedSampler::Random(RandomSampler::new(spp, seed)?),
            "uniform" => NamedSampler::Stratified(StratifiedSampler::uniform(nx, ny, seed)?),
            "stratified" => {
                NamedSampler::Stratified(StratifiedSampler::new(nx, ny, Jitter::Jittered, seed)?)
            }
            "halton" => NamedSampler::Halton(HaltonSampler::new(size, spp, scramble, seed)?),
            "hammersley" => {
                NamedSampler::Hammersley(HammersleySampler::new(size, spp, scramble, seed)?)
            }
            "zero-two" => NamedSampler::ZeroTwo(ZeroTwoSampler::new(spp, seed)?),
            "sobol" => NamedSampler::Sobol(SobolSampler::new(size, spp, scramble, seed)?),
            "best-candidate" => NamedSampler::BestCandidate(BestCandidateSampler::new(spp, seed)?),
            "adaptive" => {
                let inner = ZeroTwoSampler::new(spp, seed)?;
                let min = (inner.samples_per_pixel() / 4).max(1);
                NamedSampler::Adaptive(AdaptiveSampler::new(inner, min, ADAPTIVE_THRESHOLD)?)
            }
            "halton-plain" => {
                NamedSampler::Halton(HaltonSampler::new(size, spp, Scramble::None, 0)?)
            }
            "hammersley-plain" => {
                NamedSampler::Hammersley(HammersleySampler::new(size, spp, Scramble::None, 0)?)
            }
            "sobol-plain" => NamedSampler::Sobol(SobolSampler::new(size, spp, Scramble::None, 0)?),
            "owen-sobol" | "sobol-owen" => {
                NamedSampler::OwenSobol(OwenSobolSampler::new(spp, seed)?)
            }
            "owen-sobol-bn" => NamedSampler::OwenSobolBlue(OwenSobolBlueSampler::new(spp, seed)?),
            "zsobol" => {
                NamedSampler::ZSobol(ZSobolSampler::new(size, spp, Scramble::FastOwen, seed)?)
            }
            "pmj02" => NamedSampler::Pmj02(Pmj02Sampler::new(spp, seed)?),
            "pmj02-bn" => NamedSampler::Pmj02Blue(Pmj02BlueSampler::new(spp, seed)?),
            "lattice-bn" => NamedSampler::LatticeBlue(LatticeBlueSampler::new(spp, seed)?),
            "bluenoise-dithered" => NamedSampler::Dithered(DitheredSampler::new(
                ZeroTwoSampler::new(spp, seed)?,
                MaskView::builtin(),
            )),
            "fibonacci" => NamedSampler::Lattice(LatticeSampler::fibonacci(spp, seed)?),
            "r2" => NamedSampler::Lattice(LatticeSampler::r2(spp, seed)?),
            "korobov" => NamedSampler::Lattice(LatticeSampler::korobov(spp, seed)?),
            _ => return Err(NamedSamplerError::UnknownName),
        })
    }

    /// [`NamedSampler::new`] with the scramble chosen instead of defaulted, for the samplers
    /// that offer the four of [`Scramble`] (pbrt-v4's names): `halton`
    /// ([`HaltonSampler::new`]), `hammersley` ([`HammersleySampler::new`]), `sobol`
    /// ([`SobolSampler::new`]) and `zsobol` ([`ZSobolSampler::new`]). `new` picks digit
    /// permutation for halton, hammersley and sobol and fast Owen for zsobol;
    /// [`Scramble::None`] gives the unscrambled sets (as the `-plain` names do).
    ///
    /// # Errors
    /// As [`NamedSampler::new`]; [`NamedSamplerError::NoScramble`] for the other names in
    /// [`NAMES`].
    ///
    /// ```
    /// use nyquist::sampler::{NamedSampler, NamedSamplerError, Sampler};
    /// use nyquist::scramble::Scramble;
    /// let mut s = NamedSampler::with_scramble("sobol", [8, 8], 16, 3, Scramble::Owen).unwrap();
    /// s.start_pixel_sample([1, 2], 5, 0);
    /// assert!(s.get_1d() < 1.0);
    /// assert_eq!(
    ///     NamedSampler::with_scramble("random", [8, 8], 16, 3, Scramble::Owen).unwrap_err(),
    ///     NamedSamplerError::NoScramble
    /// );
    /// ```
    pub fn with_scramble(
        name: &str,
        size: [u32; 2],
        spp: u32,
        seed: u64,
        scramble: Scramble,
    ) -> Result<NamedSampler, NamedSamplerError> {
        let name = canonical_name(name).ok_or(NamedSamplerError::UnknownName)?;
        if !SCRAMBLE_NAMES.contains(&name) {
            return Err(if NAMES.contains(&name) || OTHER_NAMES.contains(&name) {
                NamedSamplerError::NoScramble
            } else {
                NamedSamplerError::UnknownName
            });
        }
        // `new` checks the sizes (zero width, height or spp) first, as here.
        NamedSampler::new(name, size, spp, seed)?;
        Ok(match name {
            "halton" => NamedSampler::Halton(HaltonSampler::new(size, spp, scramble, seed)?),
            "hammersley" => {
                NamedSampler::Hammersley(HammersleySampler::new(size, spp, scramble, seed)?)
            }
            "sobol" => NamedSampler::Sobol(SobolSampler::new(size, spp, scramble, seed)?),
            _ => NamedSampler::ZSobol(ZSobolSampler::new(size, spp, scramble, seed)?),
        })
    }

    /// The name this sampler is built from (one of [`NAMES`]).
    ///
    /// ```
    /// use nyquist::sampler::NamedSampler;
    /// assert_eq!(NamedSampler::new("uniform", [1, 1], 4, 0).unwrap().name(), "uniform");
    /// assert_eq!(NamedSampler::new("stratified", [1, 1], 4, 0).unwrap().name(), "stratified");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            NamedSampler::Random(_) => "random",
            NamedSampler::Stratified(s) => match s.jitter() {
                Jitter::Centered => "uniform",
                _ => "stratified",
            },
            NamedSampler::Halton(_) => "halton",
            NamedSampler::Hammersley(_) => "hammersley",
            NamedSampler::ZeroTwo(_) => "zero-two",
            NamedSampler::Sobol(_) => "sobol",
            NamedSampler::BestCandidate(_) => "best-candidate",
            NamedSampler::Adaptive(_) => "adaptive",
            NamedSampler::OwenSobol(_) => "owen-sobol",
            NamedSampler::OwenSobolBlue(_) => "owen-sobol-bn",
            NamedSampler::Pmj02Blue(_) => "pmj02-bn",
            NamedSampler::LatticeBlue(_) => "lattice-bn",
            NamedSampler::ZSobol(_) => "zsobol",
            NamedSampler::Pmj02(_) => "pmj02",
            NamedSampler::Dithered(_) => "bluenoise-dithered",
            NamedSampler::Lattice(s) => s.name(),
        }
    }
}

impl Sampler for NamedSampler {
    #[inline]
    fn samples_per_pixel(&self) -> u32 {
        delegate!(self, s => s.samples_per_pixel())
    }

    #[inline]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        delegate!(self, s => s.start_pixel_sample(pixel, sample_index, dim))
    }

    #[inline]
    fn get_1d(&mut self) -> f32 {
        delegate!(self, s => s.get_1d())
    }

    #[inline]
    fn get_2d(&mut self) -> [f32; 2] {
        delegate!(self, s => s.get_2d())
    }

    #[inline]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        delegate!(self, s => s.get_pixel_2d())
    }

    #[inline]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> super::CameraSample {
        delegate!(self, s => s.camera_sample(pixel, sample_index))
    }

    fn domain(&self) -> Option<super::Domain> {
        delegate!(self, s => s.domain())
    }

    #[inline]
    fn round_size(&self, n: u32) -> u32 {
        delegate!(self, s => s.round_size(n))
    }

    #[inline]
    fn get_array_1d(&mut self, out: &mut [f32]) {
        delegate!(self, s => s.get_array_1d(out))
    }

    #[inline]
    fn get_array_2d(&mut self, out: &mut [f32]) {
        delegate!(self, s => s.get_array_2d(out))
    }

    #[inline]
    fn arrays_are_dimension_runs(&self) -> bool {
        delegate!(self, s => s.arrays_are_dimension_runs())
    }

    #[inline]
    fn pixel_samples(&self, pixel: [u32; 2]) -> u32 {
        delegate!(self, s => s.pixel_samples(pixel))
    }

    #[inline]
    fn report(&mut self, pixel: [u32; 2], sample_index: u32, radiance: &[f32]) {
        delegate!(self, s => s.report(pixel, sample_index, radiance))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::record;
    use std::vec::Vec;

    /// The owen-sobol sampler's samples are domains through the enum too; the others have none.
    #[test]
    fn domains_come_through_the_enum() {
        let mut s = NamedSampler::new("owen-sobol", [8, 8], 16, 3).unwrap();
        s.start_pixel_sample([1, 2], 5, 0);
        let mut o = crate::sampler::OwenSobolSampler::new(16, 3).unwrap();
        o.start_pixel_sample([1, 2], 5, 0);
        assert_eq!(s.domain(), Some(o.pixel_domain()));
        let mut r = NamedSampler::new("random", [8, 8], 16, 3).unwrap();
        r.start_pixel_sample([1, 2], 5, 0);
        assert_eq!(r.domain(), None);
    }

    /// Each name gives the same values as its sampler built directly, as the CLI built them.
    #[test]
    fn names_build_the_samplers_they_name() {
        let size = [16, 16];
        for seed in [0u64, 7] {
            let direct: [(&str, std::boxed::Box<dyn Sampler>); 19] = [
                (
                    "random",
                    std::boxed::Box::new(RandomSampler::new(16, seed).unwrap()),
                ),
                (
                    "uniform",
                    std::boxed::Box::new(
                        StratifiedSampler::new(4, 4, Jitter::Centered, seed).unwrap(),
                    ),
                ),
                (
                    "stratified",
                    std::boxed::Box::new(
                        StratifiedSampler::new(4, 4, Jitter::Jittered, seed).unwrap(),
                    ),
                ),
                (
                    "halton",
                    std::boxed::Box::new(
                        HaltonSampler::new(size, 16, Scramble::PermuteDigits, seed).unwrap(),
                    ),
                ),
                (
                    "hammersley",
                    std::boxed::Box::new(
                        HammersleySampler::new(size, 16, Scramble::PermuteDigits, seed).unwrap(),
                    ),
                ),
                (
                    "zero-two",
                    std::boxed::Box::new(ZeroTwoSampler::new(16, seed).unwrap()),
                ),
                (
                    "sobol",
                    std::boxed::Box::new(
                        SobolSampler::new(size, 16, Scramble::PermuteDigits, seed).unwrap(),
                    ),
                ),
                (
                    "best-candidate",
                    std::boxed::Box::new(BestCandidateSampler::new(16, seed).unwrap()),
                ),
                (
                    "adaptive",
                    std::boxed::Box::new(
                        AdaptiveSampler::new(ZeroTwoSampler::new(16, seed).unwrap(), 4, 0.1)
                            .unwrap(),
                    ),
                ),
                (
                    "owen-sobol",
                    std::boxed::Box::new(OwenSobolSampler::new(16, seed).unwrap()),
                ),
                (
                    "owen-sobol-bn",
                    std::boxed::Box::new(OwenSobolBlueSampler::new(16, seed).unwrap()),
                ),
                (
                    "zsobol",
                    std::boxed::Box::new(
                        ZSobolSampler::new(size, 16, Scramble::FastOwen, seed).unwrap(),
                    ),
                ),
                (
                    "pmj02",
                    std::boxed::Box::new(Pmj02Sampler::new(16, seed).unwrap()),
                ),
                (
                    "pmj02-bn",
                    std::boxed::Box::new(Pmj02BlueSampler::new(16, seed).unwrap()),
                ),
                (
                    "bluenoise-dithered",
                    std::boxed::Box::new(DitheredSampler::new(
                        ZeroTwoSampler::new(16, seed).unwrap(),
                        MaskView::builtin(),
                    )),
                ),
                (
                    "fibonacci",
                    std::boxed::Box::new(LatticeSampler::fibonacci(16, seed).unwrap()),
                ),
                (
                    "r2",
                    std::boxed::Box::new(LatticeSampler::r2(16, seed).unwrap()),
                ),
                (
                    "korobov",
                    std::boxed::Box::new(LatticeSampler::korobov(16, seed).unwrap()),
                ),
                (
                    "lattice-bn",
                    std::boxed::Box::new(LatticeBlueSampler::new(16, seed).unwrap()),
                ),
            ];
            for (i, (name, mut d)) in direct.into_iter().enumerate() {
                assert_eq!(NAMES[i], name);
                let mut n = NamedSampler::new(name, size, 16, seed).unwrap();
                assert_eq!(n.name(), name);
                assert_eq!(n.samples_per_pixel(), d.samples_per_pixel(), "{name}");
                assert_eq!(n.round_size(7), d.round_size(7), "{name}");
                for (pixel, index) in [([3, 5], 2), ([9, 2], 11), ([0, 0], 0)] {
                    let a = record(&mut n, pixel, index);
                    let b = record(&mut *d, pixel, index);
                    let bits =
                        |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<std::vec::Vec<_>>();
                    assert_eq!(bits(&a), bits(&b), "{name} {pixel:?} {index}");
                }
                n.report([1, 1], 0, &[1.0, 0.0, 0.0]);
                n.report([1, 1], 1, &[0.0, 1.0, 0.0]);
                d.report([1, 1], 0, &[1.0, 0.0, 0.0]);
                d.report([1, 1], 1, &[0.0, 1.0, 0.0]);
                assert_eq!(n.pixel_samples([1, 1]), d.pixel_samples([1, 1]), "{name}");
            }
        }
    }

    #[test]
    fn errors_come_in_the_documented_order() {
        use crate::Error;
        let new = |name, size, spp| NamedSampler::new(name, size, spp, 0).unwrap_err();
        assert_eq!(
            new("nope", [1, 0], 4),
            Error::ZeroSize { what: "height" }.into()
        );
        assert_eq!(
            new("uniform", [1, 1], 0),
            Error::ZeroSize { what: "spp" }.into()
        );
        assert_eq!(new("", [1, 1], 4), NamedSamplerError::UnknownName);
        assert_eq!(new("random ", [1, 1], 4), NamedSamplerError::UnknownName);
        assert_eq!(
            new("best-candidate", [1, 1], 4097),
            NamedSamplerError::SppAboveLimit {
                spp: 4097,
                max: 4096
            }
        );
        assert!(NamedSampler::new("best-candidate", [1, 1], 4096, 0).is_ok());
        assert_eq!(
            new("PMJ02", [0, 1], 1 << 17),
            Error::ZeroSize { what: "width" }.into()
        );
        assert_eq!(
            new("pmj02", [1, 1], (1 << 16) + 1),
            NamedSamplerError::SppAboveLimit {
                spp: (1 << 16) + 1,
                max: 1 << 16
            }
        );
        assert!(NamedSampler::new("pmj02", [1, 1], 1 << 16, 0).is_ok());
    }

    /// Other spellings build the same sampler: any ASCII case, the `-plain` names (no scramble,
    /// whatever the seed), `sobol-owen`; and `uniform`/`stratified` take any spp on the
    /// [`strata`] grid, every stratum hit once.
    #[test]
    fn other_names_and_grids() {
        let values = |name: &str, seed: u64| {
            let mut s = NamedSampler::new(name, [8, 8], 16, seed).unwrap();
            (0..16u32)
                .flat_map(|i| record(&mut s, [3, 1], i))
                .map(f32::to_bits)
                .collect::<Vec<_>>()
        };
        assert_eq!(values("ZSOBOL", 5), values("zsobol", 5));
        assert_eq!(values("Owen-Sobol", 5), values("owen-sobol", 5));
        assert_eq!(values("sobol-owen", 5), values("owen-sobol", 5));
        let direct = |mut s: std::boxed::Box<dyn Sampler>| {
            (0..16u32)
                .flat_map(|i| record(&mut *s, [3, 1], i))
                .map(f32::to_bits)
                .collect::<Vec<_>>()
        };
        let none = Scramble::None;
        assert_eq!(
            values("halton-plain", 5),
            direct(std::boxed::Box::new(
                HaltonSampler::new([8, 8], 16, none, 0).unwrap()
            ))
        );
        assert_eq!(
            values("hammersley-plain", 5),
            direct(std::boxed::Box::new(
                HammersleySampler::new([8, 8], 16, none, 0).unwrap()
            ))
        );
        assert_eq!(
            values("sobol-plain", 5),
            direct(std::boxed::Box::new(
                SobolSampler::new([8, 8], 16, none, 0).unwrap()
            ))
        );
        for name in ["halton", "hammersley", "sobol"] {
            // Seed 0 is a permutation like any other: not the plain set, not seed 5's.
            let plain = std::format!("{name}-plain");
            assert_ne!(values(name, 0), values(&plain, 0), "{name}");
            assert_ne!(values(name, 5), values(name, 0), "{name}");
        }
        assert_eq!(
            NamedSampler::new("SOBOL-plain", [8, 8], 16, 5)
                .unwrap()
                .name(),
            "sobol"
        );
        assert_eq!(
            NamedSampler::new("sobol-owen", [8, 8], 16, 5)
                .unwrap()
                .name(),
            "owen-sobol"
        );
        for spp in [2u32, 6, 7, 8, 12, 32] {
            let [nx, ny] = strata(spp);
            assert_eq!(nx * ny, spp);
            assert!(ny <= nx && (ny..=nx).filter(|d| spp % d == 0 && *d * *d <= spp).count() <= 1);
            for name in ["uniform", "stratified"] {
                let mut s = NamedSampler::new(name, [1, 1], spp, 3).unwrap();
                assert_eq!(s.samples_per_pixel(), spp);
                let mut hit = std::vec![0u32; spp as usize];
                for i in 0..spp {
                    s.start_pixel_sample([0, 0], i, 0);
                    let [x, y] = s.get_pixel_2d();
                    let cell = (y * ny as f32) as u32 * nx + (x * nx as f32) as u32;
                    hit[cell as usize] += 1;
                }
                assert!(hit.iter().all(|&h| h == 1), "{name} {spp}: {hit:?}");
            }
        }
    }

    proptest::proptest! {
        /// Any name (every one of [`NAMES`], and one that is not), size, spp and seed: a
        /// sampler whose values are in [0, 1), or an error; never a panic.
        #[test]
        fn any_input_builds_or_errors(
            which in 0usize..=NAMES.len(),
            w in 0u32..64,
            h in 0u32..64,
            spp in 0u32..300,
            seed: u64,
            pixel: [u32; 2],
            index: u32,
        ) {
            let name = NAMES.get(which).copied().unwrap_or("bogus");
            match NamedSampler::new(name, [w, h], spp, seed) {
                Ok(mut s) => {
                    proptest::prop_assert_eq!(s.name(), name);
                    for x in record(&mut s, pixel, index) {
                        proptest::prop_assert!((0.0..1.0).contains(&x), "{} {}", name, x);
                    }
                }
                Err(e) => {
                    let expected = if w == 0 || h == 0 || spp == 0 {
                        matches!(e, NamedSamplerError::Sampler(crate::Error::ZeroSize { .. }))
                    } else if which == NAMES.len() {
                        e == NamedSamplerError::UnknownName
                    } else {
                        false
                    };
                    proptest::prop_assert!(expected, "{} {:?}", name, e);
                }
            }
        }
    }

    /// `with_scramble` builds halton, hammersley, sobol and zsobol with the asked scramble: the same values
    /// as the sampler built directly, every scramble a different set (seed ≠ 0), and the other
    /// names refused by kind.
    #[test]
    fn with_scramble_builds_the_four_and_refuses_the_rest() {
        fn values(mut s: impl Sampler) -> Vec<u32> {
            let mut v = Vec::new();
            for i in 0..16 {
                s.start_pixel_sample([3, 2], i, 0);
                for _ in 0..4 {
                    v.push(s.get_1d().to_bits());
                }
            }
            v
        }
        let (size, spp, seed) = ([8, 8], 16, 9);
        for scramble in Scramble::ALL {
            let direct = [
                values(HaltonSampler::new(size, spp, scramble, seed).unwrap()),
                values(HammersleySampler::new(size, spp, scramble, seed).unwrap()),
                values(SobolSampler::new(size, spp, scramble, seed).unwrap()),
                values(ZSobolSampler::new(size, spp, scramble, seed).unwrap()),
            ];
            for (name, want) in SCRAMBLE_NAMES.iter().zip(direct) {
                let s = NamedSampler::with_scramble(name, size, spp, seed, scramble).unwrap();
                assert_eq!(s.name(), *name);
                assert_eq!(values(s), want, "{name} {scramble:?}");
            }
        }
        for name in SCRAMBLE_NAMES {
            let mut sets: Vec<Vec<u32>> = Scramble::ALL
                .iter()
                .map(|&sc| values(NamedSampler::with_scramble(name, size, spp, seed, sc).unwrap()))
                .collect();
            sets.sort();
            sets.dedup();
            assert_eq!(sets.len(), 4, "{name}: the four scrambles give four sets");
            assert_eq!(
                NamedSampler::with_scramble(name, [0, 8], spp, seed, Scramble::Owen).unwrap_err(),
                NamedSamplerError::Sampler(crate::Error::ZeroSize { what: "width" })
            );
        }
        for name in NAMES
            .iter()
            .filter(|n| !matches!(**n, "halton" | "hammersley" | "sobol" | "zsobol"))
        {
            assert_eq!(
                NamedSampler::with_scramble(name, size, spp, seed, Scramble::Owen).unwrap_err(),
                NamedSamplerError::NoScramble,
                "{name}"
            );
        }
        assert_eq!(
            NamedSampler::with_scramble("nope", size, spp, seed, Scramble::Owen).unwrap_err(),
            NamedSamplerError::UnknownName
        );
        assert_eq!(SCRAMBLE_NAMES, ["halton", "hammersley", "sobol", "zsobol"]);
    }

    /// The continuing samplers give 256 distinct image samples from one pixel of a sampler
    /// made for 4. (The others' values may differ too, by a fresh jitter in repeated strata,
    /// so distinctness does not tell them apart.)
    #[test]
    fn continuing_samplers_draw_new_samples_past_their_spp() {
        for name in NAMES.iter().chain(&OTHER_NAMES) {
            if !continues(name) {
                continue;
            }
            let mut s = NamedSampler::new(name, [4, 4], 4, 7).unwrap();
            let mut seen: Vec<[u32; 2]> = (0..256)
                .map(|i| {
                    s.start_pixel_sample([1, 2], i, 0);
                    s.get_pixel_2d().map(f32::to_bits)
                })
                .collect();
            seen.sort_unstable();
            seen.dedup();
            assert_eq!(seen.len(), 256, "{name}");
        }
        assert!(!continues("nope") && !continues("zero-two") && !continues("hammersley-plain"));
        for alias in ["Halton-Plain", "sobol-plain", "sobol-owen", "ZSOBOL"] {
            assert!(continues(alias), "{alias}");
        }
    }
}
