//! Every point set of the crate by name, with one meaning per name: what the CLI's
//! `points --sampler NAME`, the explorer and the C API's `NyqSequence` build.
//!
//! A name is a family; [`SequenceSpec::seed`] says whether it is randomized. `None` gives the
//! published deterministic set; `Some(seed)` gives the family's one randomization under that
//! seed (every seed, 0 included, randomizes): a digit permutation for Halton, a digital shift
//! for Sobol and the (0,2)-sequence, an Owen scramble for PMJ(0,2), a Cranley–Patterson rotation
//! for the lattices and R_d. Owen-scrambled Sobol is randomized by definition (no seed: seed 0).

use core::fmt;

use super::{
    Halton, HaltonZaremba, Hammersley, HammersleyZaremba, OwenSobol, Pmj02, ScrambledHalton,
    Sequence, Sobol, VanDerCorput, ZeroTwo,
};
use crate::Error;
use crate::lattice::{FibonacciLattice, Korobov, Kronecker};

/// The names [`NamedSequence::new`] accepts, as the CLI lists them.
///
/// ```
/// use nyquist::sequence::{NamedSequence, SequenceSpec, SEQUENCE_NAMES};
/// for name in SEQUENCE_NAMES {
///     let sized = ["hammersley", "hammersley-zaremba", "fibonacci", "korobov"].contains(&name);
///     let spec = SequenceSpec {
///         dims: if name == "vdc" { 1 } else { 2 },
///         points: sized.then_some(21),
///         ..SequenceSpec::default()
///     };
///     assert_eq!(NamedSequence::new(name, spec).unwrap().name(), name);
/// }
/// ```
pub const SEQUENCE_NAMES: [&str; 12] = [
    "vdc",
    "halton",
    "halton-zaremba",
    "hammersley",
    "hammersley-zaremba",
    "sobol",
    "owen-sobol",
    "zero-two",
    "pmj02",
    "fibonacci",
    "korobov",
    "rd",
];

/// The canonical name of `name` for [`NamedSequence::new`]: one of [`SEQUENCE_NAMES`] in any
/// ASCII case, or an alias (`sobol-owen` for `owen-sobol`, `r2` for `rd`); `None` otherwise.
///
/// ```
/// use nyquist::sequence::canonical_sequence_name;
/// assert_eq!(canonical_sequence_name("Halton"), Some("halton"));
/// assert_eq!(canonical_sequence_name("R2"), Some("rd"));
/// assert_eq!(canonical_sequence_name("sobol-owen"), Some("owen-sobol"));
/// assert_eq!(canonical_sequence_name("halton "), None);
/// ```
pub fn canonical_sequence_name(name: &str) -> Option<&'static str> {
    let alias = [("sobol-owen", "owen-sobol"), ("r2", "rd")]
        .into_iter()
        .find(|(a, _)| a.eq_ignore_ascii_case(name))
        .map(|(_, n)| n);
    alias.or_else(|| {
        SEQUENCE_NAMES
            .into_iter()
            .find(|n| n.eq_ignore_ascii_case(name))
    })
}

/// The randomization `Some(seed)` gives sequence `name` (as [`canonical_sequence_name`] takes
/// it), `None` for the deterministic-only families and unknown names.
///
/// ```
/// use nyquist::sequence::randomization;
/// assert_eq!(randomization("halton"), Some("digit permutation"));
/// assert_eq!(randomization("korobov"), Some("Cranley–Patterson rotation"));
/// assert_eq!(randomization("hammersley"), None);
/// ```
pub fn randomization(name: &str) -> Option<&'static str> {
    match canonical_sequence_name(name)? {
        "halton" => Some("digit permutation"),
        "sobol" | "zero-two" => Some("digital shift"),
        "owen-sobol" | "pmj02" => Some("Owen scramble"),
        "fibonacci" | "korobov" | "rd" => Some("Cranley–Patterson rotation"),
        _ => None,
    }
}

/// Whether sequence `name` (as [`canonical_sequence_name`] takes it) is a set of `N` points
/// whose size is part of its definition, so that [`SequenceSpec::points`] is required:
/// `hammersley`, `hammersley-zaremba`, `fibonacci` and `korobov`.
///
/// ```
/// use nyquist::sequence::takes_points;
/// assert!(takes_points("Korobov"));
/// assert!(!takes_points("halton"));
/// assert!(!takes_points("nope"));
/// ```
pub fn takes_points(name: &str) -> bool {
    matches!(
        canonical_sequence_name(name),
        Some("hammersley" | "hammersley-zaremba" | "fibonacci" | "korobov")
    )
}

/// What [`NamedSequence::new`] builds besides the name.
///
/// ```
/// use nyquist::sequence::SequenceSpec;
/// let s = SequenceSpec::default();
/// assert_eq!((s.dims, s.points, s.seed, s.multiplier), (2, None, None, None));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SequenceSpec {
    /// Dimensions, at least 1 (`vdc`: 1; `zero-two`, `pmj02`, `fibonacci`: at most 2).
    pub dims: u32,
    /// The set's size `N`: required by `hammersley`, `hammersley-zaremba`, `fibonacci` (a
    /// Fibonacci number) and `korobov`; rejected by the others, whose points are addressed by
    /// index alone.
    pub points: Option<u64>,
    /// `None`: the deterministic set; `Some(seed)`: the family's randomization under `seed`
    /// ([`randomization`]). Rejected by the families without one.
    pub seed: Option<u64>,
    /// `korobov`'s multiplier `a` (coprime to `N`, `1 ≤ a < N`); `None` picks one: Stroud's
    /// (1971) tabled multiplier where the table has (`N`, `dims`), else the minimiser of the P2
    /// criterion ([`Korobov::searched`]; in two dimensions [`Korobov::searched_2d`], the same
    /// minimiser in linear time, up to 2²⁴ points). Rejected by the other families.
    pub multiplier: Option<u64>,
}

impl Default for SequenceSpec {
    /// Two dimensions, no size, deterministic, no multiplier.
    fn default() -> SequenceSpec {
        SequenceSpec {
            dims: 2,
            points: None,
            seed: None,
            multiplier: None,
        }
    }
}

/// Why [`NamedSequence::new`] rejected its input.
///
/// ```
/// use nyquist::sequence::{NamedSequence, NamedSequenceError, SequenceSpec};
/// let spec = SequenceSpec { seed: Some(3), ..SequenceSpec::default() };
/// let e = NamedSequence::new("halton-zaremba", spec).unwrap_err();
/// assert_eq!(e, NamedSequenceError::NotRandomized { name: "halton-zaremba" });
/// assert_eq!(e.to_string(), "halton-zaremba has no randomization: give no seed");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum NamedSequenceError {
    /// The name is not one of [`SEQUENCE_NAMES`] or an alias.
    UnknownName,
    /// A seed for a family without a randomization.
    NotRandomized {
        /// The family.
        name: &'static str,
    },
    /// No [`SequenceSpec::points`] for a family whose size is part of its definition.
    PointsRequired {
        /// The family.
        name: &'static str,
    },
    /// [`SequenceSpec::points`] for a family addressed by index alone.
    PointsNotTaken {
        /// The family.
        name: &'static str,
    },
    /// [`SequenceSpec::multiplier`] for a family other than `korobov`.
    MultiplierNotTaken {
        /// The family.
        name: &'static str,
    },
    /// The family's constructor rejected the parameters.
    Sequence(Error),
}

impl fmt::Display for NamedSequenceError {
    /// Lowercase, names the fault.
    ///
    /// ```
    /// use nyquist::sequence::NamedSequenceError;
    /// let e = NamedSequenceError::PointsRequired { name: "hammersley" };
    /// assert_eq!(e.to_string(), "hammersley needs its point count N");
    /// ```
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            NamedSequenceError::UnknownName => {
                f.write_str("unknown sequence name (known: ")?;
                for (i, n) in SEQUENCE_NAMES.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    f.write_str(n)?;
                }
                f.write_str(")")
            }
            NamedSequenceError::NotRandomized { name } => {
                write!(f, "{name} has no randomization: give no seed")
            }
            NamedSequenceError::PointsRequired { name } => {
                write!(f, "{name} needs its point count N")
            }
            NamedSequenceError::PointsNotTaken { name } => {
                write!(f, "{name} takes no point count: its points go by index")
            }
            NamedSequenceError::MultiplierNotTaken { name } => {
                write!(f, "{name} takes no multiplier (korobov does)")
            }
            NamedSequenceError::Sequence(e) => e.fmt(f),
        }
    }
}

impl core::error::Error for NamedSequenceError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            NamedSequenceError::Sequence(e) => Some(e),
            _ => None,
        }
    }
}

impl From<Error> for NamedSequenceError {
    /// Wraps a core error as [`NamedSequenceError::Sequence`].
    fn from(e: Error) -> Self {
        NamedSequenceError::Sequence(e)
    }
}

/// A point set chosen by name ([`NamedSequence::new`]); it is a [`Sequence`] and gives the
/// values of the set it names, bit for bit.
///
/// ```
/// use nyquist::sequence::{NamedSequence, Sequence, SequenceSpec, Sobol};
/// let s = NamedSequence::new("sobol", SequenceSpec::default()).unwrap();
/// assert_eq!(s.sample(3, 1), Sobol::new(2).unwrap().sample(3, 1));
/// ```
#[derive(Clone, Debug)]
#[non_exhaustive]
// Without `alloc` nothing can be boxed: the enum is as large as its largest set (about 1 KiB,
// the per-dimension seeds of Owen-scrambled Sobol); it is built once and read by reference.
#[allow(clippy::large_enum_variant)]
pub enum NamedSequence {
    /// `vdc`.
    VanDerCorput(VanDerCorput),
    /// `halton`, deterministic.
    Halton(Halton),
    /// `halton` with a seed.
    ScrambledHalton(ScrambledHalton),
    /// `halton-zaremba`.
    HaltonZaremba(HaltonZaremba),
    /// `hammersley`.
    Hammersley(Hammersley),
    /// `hammersley-zaremba`.
    HammersleyZaremba(HammersleyZaremba),
    /// `sobol`, plain or digitally shifted.
    Sobol(Sobol),
    /// `owen-sobol`.
    OwenSobol(OwenSobol),
    /// `zero-two`, plain or digitally shifted.
    ZeroTwo(ZeroTwo),
    /// `pmj02`: the baked table, or Owen-scrambled.
    Pmj02(Pmj02),
    /// `fibonacci`, plain or rotated.
    Fibonacci(FibonacciLattice),
    /// `korobov`, plain or rotated.
    Korobov(Korobov),
    /// `rd`, plain or rotated.
    Rd(Kronecker),
}

impl NamedSequence {
    /// The set `name` (one of [`SEQUENCE_NAMES`], any ASCII case, or an alias) with `spec`:
    ///
    /// - `vdc`: [`VanDerCorput`] (one dimension);
    /// - `halton`: [`Halton`], or with a seed [`ScrambledHalton`] (digit permutation);
    /// - `halton-zaremba`: [`HaltonZaremba`];
    /// - `hammersley`, `hammersley-zaremba`: [`Hammersley`], [`HammersleyZaremba`] of `N`
    ///   points;
    /// - `sobol`: [`Sobol`], or with a seed [`Sobol::with_digital_shift`];
    /// - `owen-sobol`: [`OwenSobol`] (seed 0 when none is given);
    /// - `zero-two`: [`ZeroTwo`], or with a seed [`ZeroTwo::from_seed`] (a digital shift);
    /// - `pmj02`: [`Pmj02::new`] (the baked table), or with a seed [`Pmj02::scrambled`];
    /// - `fibonacci`: [`FibonacciLattice`] of `N` points (a Fibonacci number);
    /// - `korobov`: [`Korobov`] of `N` points with [`SequenceSpec::multiplier`] or one picked;
    /// - `rd`: [`Kronecker`] (Roberts' R_d);
    ///
    /// the last three rotated ([`Korobov::rotated`] and the like) with a seed. Allocates: no.
    /// Picking a Korobov multiplier by search takes time about linear in `N` (see
    /// [`Korobov::searched`]).
    ///
    /// # Errors
    /// In this order: [`NamedSequenceError::UnknownName`]; `NotRandomized`, `PointsRequired`,
    /// `PointsNotTaken`, `MultiplierNotTaken` as [`SequenceSpec`] describes; then the family's
    /// own rejection (zero or too many dimensions, `N` not a Fibonacci number, a multiplier not
    /// coprime to `N`, …) as [`NamedSequenceError::Sequence`].
    ///
    /// ```
    /// use nyquist::sequence::{NamedSequence, NamedSequenceError, Sequence, SequenceSpec};
    /// let fib = SequenceSpec { points: Some(21), seed: Some(0), ..SequenceSpec::default() };
    /// let rotated = NamedSequence::new("fibonacci", fib).unwrap();
    /// let plain = NamedSequence::new("fibonacci", SequenceSpec { seed: None, ..fib }).unwrap();
    /// assert_eq!(plain.sample(0, 0), 0.0);
    /// assert_ne!(rotated.sample(0, 0), 0.0); // seed 0 rotates like any other seed
    /// assert_eq!(
    ///     NamedSequence::new("hammersley", SequenceSpec::default()).unwrap_err(),
    ///     NamedSequenceError::PointsRequired { name: "hammersley" }
    /// );
    /// ```
    pub fn new(name: &str, spec: SequenceSpec) -> Result<NamedSequence, NamedSequenceError> {
        let name = canonical_sequence_name(name).ok_or(NamedSequenceError::UnknownName)?;
        if spec.seed.is_some() && randomization(name).is_none() {
            return Err(NamedSequenceError::NotRandomized { name });
        }
        let n = match (spec.points, takes_points(name)) {
            (Some(n), true) => n,
            (None, true) => return Err(NamedSequenceError::PointsRequired { name }),
            (Some(_), false) => return Err(NamedSequenceError::PointsNotTaken { name }),
            (None, false) => 0,
        };
        if spec.multiplier.is_some() && name != "korobov" {
            return Err(NamedSequenceError::MultiplierNotTaken { name });
        }
        let dims = spec.dims;
        let at_most = |max: u32| super::dims_within(dims, max);
        Ok(match name {
            "vdc" => {
                at_most(1)?;
                NamedSequence::VanDerCorput(VanDerCorput)
            }
            "halton" => match spec.seed {
                None => NamedSequence::Halton(Halton::new(dims)?),
                Some(seed) => NamedSequence::ScrambledHalton(ScrambledHalton::new(dims, seed)?),
            },
            "halton-zaremba" => NamedSequence::HaltonZaremba(HaltonZaremba::new(dims)?),
            "hammersley" => NamedSequence::Hammersley(Hammersley::new(n, dims)?),
            "hammersley-zaremba" => {
                NamedSequence::HammersleyZaremba(HammersleyZaremba::new(n, dims)?)
            }
            "sobol" => NamedSequence::Sobol(match spec.seed {
                None => Sobol::new(dims)?,
                Some(seed) => Sobol::with_digital_shift(dims, seed)?,
            }),
            "owen-sobol" => NamedSequence::OwenSobol(OwenSobol::new(dims, spec.seed.unwrap_or(0))?),
            "zero-two" => {
                at_most(2)?;
                NamedSequence::ZeroTwo(spec.seed.map_or(ZeroTwo::new([0, 0]), ZeroTwo::from_seed))
            }
            "pmj02" => {
                at_most(2)?;
                NamedSequence::Pmj02(spec.seed.map_or_else(Pmj02::new, Pmj02::scrambled))
            }
            "fibonacci" => {
                at_most(2)?;
                let f = FibonacciLattice::at_least(n)?;
                if let Some(next) = f.point_count().filter(|&next| next != n) {
                    return Err(Error::Invalid {
                        what: "points",
                        value: n,
                        rule: "is not a Fibonacci number; the next is",
                        other: next,
                    }
                    .into());
                }
                NamedSequence::Fibonacci(spec.seed.map_or(f, |s| f.rotated(s)))
            }
            "korobov" => {
                let k = match spec.multiplier {
                    Some(a) => Korobov::new(n, a, dims)?,
                    None => match Korobov::tabled(n, dims) {
                        Ok(k) => k,
                        // The same minimiser as `searched(n, 2)`, in linear time.
                        Err(_) if dims == 2 => Korobov::searched_2d(n)?,
                        Err(_) => Korobov::searched(n, dims)?,
                    },
                };
                NamedSequence::Korobov(spec.seed.map_or(k, |s| k.rotated(s)))
            }
            _ => {
                let r = Kronecker::new(dims)?;
                NamedSequence::Rd(spec.seed.map_or(r, |s| r.rotated(s)))
            }
        })
    }

    /// The family's canonical name (one of [`SEQUENCE_NAMES`]).
    ///
    /// ```
    /// use nyquist::sequence::{NamedSequence, SequenceSpec};
    /// let s = NamedSequence::new("R2", SequenceSpec::default()).unwrap();
    /// assert_eq!(s.name(), "rd");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            NamedSequence::VanDerCorput(_) => "vdc",
            NamedSequence::Halton(_) | NamedSequence::ScrambledHalton(_) => "halton",
            NamedSequence::HaltonZaremba(_) => "halton-zaremba",
            NamedSequence::Hammersley(_) => "hammersley",
            NamedSequence::HammersleyZaremba(_) => "hammersley-zaremba",
            NamedSequence::Sobol(_) => "sobol",
            NamedSequence::OwenSobol(_) => "owen-sobol",
            NamedSequence::ZeroTwo(_) => "zero-two",
            NamedSequence::Pmj02(_) => "pmj02",
            NamedSequence::Fibonacci(_) => "fibonacci",
            NamedSequence::Korobov(_) => "korobov",
            NamedSequence::Rd(_) => "rd",
        }
    }

    fn as_dyn(&self) -> &dyn Sequence {
        match self {
            NamedSequence::VanDerCorput(s) => s,
            NamedSequence::Halton(s) => s,
            NamedSequence::ScrambledHalton(s) => s,
            NamedSequence::HaltonZaremba(s) => s,
            NamedSequence::Hammersley(s) => s,
            NamedSequence::HammersleyZaremba(s) => s,
            NamedSequence::Sobol(s) => s,
            NamedSequence::OwenSobol(s) => s,
            NamedSequence::ZeroTwo(s) => s,
            NamedSequence::Pmj02(s) => s,
            NamedSequence::Fibonacci(s) => s,
            NamedSequence::Korobov(s) => s,
            NamedSequence::Rd(s) => s,
        }
    }
}

impl Sequence for NamedSequence {
    fn dims(&self) -> u32 {
        self.as_dyn().dims()
    }

    fn point_count(&self) -> Option<u64> {
        self.as_dyn().point_count()
    }

    fn sample(&self, index: u64, dim: u32) -> f32 {
        self.as_dyn().sample(index, dim)
    }

    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        self.as_dyn().sample_f64(index, dim)
    }

    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        self.as_dyn().fill(first, dims, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::ToString;
    use std::vec::Vec;

    fn values(s: &dyn Sequence, dims: u32) -> Vec<u32> {
        let mut out = std::vec![0.0f32; 16 * dims as usize];
        s.fill(0, dims, &mut out).unwrap();
        out.iter().map(|x| x.to_bits()).collect()
    }

    fn spec(dims: u32, points: Option<u64>, seed: Option<u64>) -> SequenceSpec {
        SequenceSpec {
            dims,
            points,
            seed,
            multiplier: None,
        }
    }

    /// A name, its dimensions and size, the set built directly, and its randomized form.
    type Case<'a> = (
        &'static str,
        u32,
        Option<u64>,
        &'a dyn Sequence,
        Option<&'a dyn Sequence>,
    );

    /// Every name gives the values of the set it names, built directly, plain and seeded; and
    /// a seed, 0 included, changes them.
    #[test]
    fn names_build_the_sets_they_name() {
        let k = Korobov::tabled(101, 3).unwrap();
        let cases: [Case; 12] = [
            ("vdc", 1, None, &VanDerCorput, None),
            (
                "halton",
                3,
                None,
                &Halton::new(3).unwrap(),
                Some(&ScrambledHalton::new(3, 0).unwrap()),
            ),
            (
                "halton-zaremba",
                3,
                None,
                &HaltonZaremba::new(3).unwrap(),
                None,
            ),
            (
                "hammersley",
                3,
                Some(16),
                &Hammersley::new(16, 3).unwrap(),
                None,
            ),
            (
                "hammersley-zaremba",
                3,
                Some(16),
                &HammersleyZaremba::new(16, 3).unwrap(),
                None,
            ),
            (
                "sobol",
                3,
                None,
                &Sobol::new(3).unwrap(),
                Some(&Sobol::with_digital_shift(3, 0).unwrap()),
            ),
            (
                "owen-sobol",
                3,
                None,
                &OwenSobol::new(3, 0).unwrap(),
                Some(&OwenSobol::new(3, 0).unwrap()),
            ),
            (
                "zero-two",
                2,
                None,
                &ZeroTwo::new([0, 0]),
                Some(&ZeroTwo::from_seed(0)),
            ),
            ("pmj02", 2, None, &Pmj02::new(), Some(&Pmj02::scrambled(0))),
            (
                "fibonacci",
                2,
                Some(21),
                &FibonacciLattice::at_least(21).unwrap(),
                Some(&FibonacciLattice::at_least(21).unwrap().rotated(0)),
            ),
            ("korobov", 3, Some(101), &k, Some(&k.rotated(0))),
            (
                "rd",
                3,
                None,
                &Kronecker::new(3).unwrap(),
                Some(&Kronecker::new(3).unwrap().rotated(0)),
            ),
        ];
        for (i, (name, dims, points, plain, seeded)) in cases.into_iter().enumerate() {
            assert_eq!(SEQUENCE_NAMES[i], name);
            let s = NamedSequence::new(name, spec(dims, points, None)).unwrap();
            assert_eq!(s.name(), name);
            assert_eq!(s.dims(), plain.dims(), "{name}");
            assert_eq!(s.point_count(), plain.point_count(), "{name}");
            assert_eq!(values(&s, dims), values(plain, dims), "{name}");
            assert_eq!(s.sample_f64(5, dims - 1), plain.sample_f64(5, dims - 1));
            assert_eq!(
                s.sample(5, dims - 1).to_bits(),
                plain.sample(5, dims - 1).to_bits()
            );
            match seeded {
                Some(want) => {
                    let r = NamedSequence::new(name, spec(dims, points, Some(0))).unwrap();
                    assert_eq!(values(&r, dims), values(want, dims), "{name} seeded");
                    if name != "owen-sobol" {
                        assert_ne!(values(&r, dims), values(plain, dims), "{name} seed 0");
                    }
                }
                None => assert_eq!(
                    NamedSequence::new(name, spec(dims, points, Some(0))).unwrap_err(),
                    NamedSequenceError::NotRandomized { name }
                ),
            }
        }
    }

    #[test]
    fn sizes_multipliers_and_dimension_limits() {
        let korobov = |points, multiplier, dims| {
            NamedSequence::new(
                "korobov",
                SequenceSpec {
                    dims,
                    points,
                    seed: None,
                    multiplier,
                },
            )
        };
        // Stroud's table has (101, 3); a given multiplier is used as given.
        let NamedSequence::Korobov(k) = korobov(Some(101), None, 3).unwrap() else {
            panic!("not korobov")
        };
        assert_eq!(
            k.multiplier(),
            Korobov::tabled(101, 3).unwrap().multiplier()
        );
        let NamedSequence::Korobov(k) = korobov(Some(101), Some(12), 3).unwrap() else {
            panic!("not korobov")
        };
        assert_eq!(k.multiplier(), 12);
        // Not tabled: searched (in two dimensions by the linear-time 2-D search, which finds the
        // same multiplier).
        let NamedSequence::Korobov(k) = korobov(Some(64), None, 2).unwrap() else {
            panic!("not korobov")
        };
        assert_eq!(
            k.multiplier(),
            Korobov::searched(64, 2).unwrap().multiplier()
        );
        let NamedSequence::Korobov(k) = korobov(Some(5000), None, 2).unwrap() else {
            panic!("not korobov")
        };
        assert_eq!(
            k.multiplier(),
            Korobov::searched_2d(5000).unwrap().multiplier()
        );
        assert!(matches!(
            korobov(Some(64), Some(4), 2),
            Err(NamedSequenceError::Sequence(_))
        ));
        assert_eq!(
            korobov(None, None, 2).unwrap_err(),
            NamedSequenceError::PointsRequired { name: "korobov" }
        );
        let with = |name: &str, s: SequenceSpec| NamedSequence::new(name, s).unwrap_err();
        assert_eq!(
            with("sobol", spec(2, Some(8), None)),
            NamedSequenceError::PointsNotTaken { name: "sobol" }
        );
        assert_eq!(
            with(
                "halton",
                SequenceSpec {
                    multiplier: Some(3),
                    ..SequenceSpec::default()
                }
            ),
            NamedSequenceError::MultiplierNotTaken { name: "halton" }
        );
        assert_eq!(
            with("fibonacci", spec(2, Some(20), None)).to_string(),
            "points 20 is not a Fibonacci number; the next is 21"
        );
        assert_eq!(
            with("fibonacci", spec(2, Some(20), None)),
            NamedSequenceError::Sequence(Error::Invalid {
                what: "points",
                value: 20,
                rule: "is not a Fibonacci number; the next is",
                other: 21
            })
        );
        for (name, max) in [
            ("vdc", 1u32),
            ("zero-two", 2),
            ("pmj02", 2),
            ("fibonacci", 2),
        ] {
            let points = (name == "fibonacci").then_some(21);
            assert_eq!(
                with(name, spec(max + 1, points, None)),
                NamedSequenceError::Sequence(Error::NotInRange {
                    what: "dims",
                    value: u64::from(max) + 1,
                    min: 1,
                    max: u64::from(max)
                }),
                "{name}"
            );
            assert_eq!(
                with(name, spec(0, points, None)),
                NamedSequenceError::Sequence(Error::ZeroSize { what: "dims" })
            );
        }
        assert_eq!(
            with("halton", spec(1025, None, None)),
            NamedSequenceError::Sequence(Error::NotInRange {
                what: "dims",
                value: 1025,
                min: 1,
                max: 1024
            })
        );
        assert_eq!(
            with("nope", SequenceSpec::default()),
            NamedSequenceError::UnknownName
        );
    }

    /// Every error prints one line naming the fault; a wrapped core error prints as itself and
    /// is the source.
    #[test]
    fn errors_print_their_fault() {
        use core::error::Error as _;
        let known = SEQUENCE_NAMES.join(", ");
        assert_eq!(
            NamedSequenceError::UnknownName.to_string(),
            std::format!("unknown sequence name (known: {known})")
        );
        let name = "vdc";
        for (e, want) in [
            (
                NamedSequenceError::NotRandomized { name },
                "vdc has no randomization: give no seed",
            ),
            (
                NamedSequenceError::PointsRequired { name },
                "vdc needs its point count N",
            ),
            (
                NamedSequenceError::PointsNotTaken { name },
                "vdc takes no point count: its points go by index",
            ),
            (
                NamedSequenceError::MultiplierNotTaken { name },
                "vdc takes no multiplier (korobov does)",
            ),
        ] {
            assert_eq!(e.to_string(), want);
            assert!(e.source().is_none());
        }
        let core = Error::ZeroSize { what: "dims" };
        let e = NamedSequenceError::from(core);
        assert_eq!(e, NamedSequenceError::Sequence(core));
        assert_eq!(e.to_string(), core.to_string());
        assert_eq!(e.source().map(|s| s.to_string()), Some(core.to_string()));
    }

    /// Names in any ASCII case and the aliases build the canonical set.
    #[test]
    fn case_and_aliases() {
        for (alias, name) in [
            ("R2", "rd"),
            ("Sobol-Owen", "owen-sobol"),
            ("HALTON", "halton"),
        ] {
            assert_eq!(canonical_sequence_name(alias), Some(name));
            let s = NamedSequence::new(alias, SequenceSpec::default()).unwrap();
            assert_eq!(s.name(), name);
        }
        let sized: Vec<&str> = SEQUENCE_NAMES
            .into_iter()
            .filter(|n| takes_points(n))
            .collect();
        assert_eq!(
            sized,
            ["hammersley", "hammersley-zaremba", "fibonacci", "korobov"]
        );
        assert!(takes_points("Hammersley-Zaremba") && !takes_points("nope"));
        assert_eq!(canonical_sequence_name("rd2"), None);
        assert_eq!(randomization("nope"), None);
        assert_eq!(randomization("PMJ02"), Some("Owen scramble"));
        assert_eq!(randomization("zero-two"), Some("digital shift"));
    }

    proptest::proptest! {
        /// Any name and spec builds a set whose values lie in [0, 1), or gives an error; never
        /// a panic.
        #[test]
        fn any_spec_builds_or_errors(
            which in 0usize..=SEQUENCE_NAMES.len(),
            dims in 0u32..8,
            points in proptest::option::of(0u64..200),
            seed: Option<u64>,
            multiplier in proptest::option::of(0u64..200),
            index in 0u64..1000,
        ) {
            let name = SEQUENCE_NAMES.get(which).copied().unwrap_or("bogus");
            let spec = SequenceSpec { dims, points, seed, multiplier };
            if let Ok(s) = NamedSequence::new(name, spec) {
                let index = s.point_count().map_or(index, |n| index % n);
                for d in 0..s.dims() {
                    let v = s.sample(index, d);
                    proptest::prop_assert!((0.0..1.0).contains(&v), "{name} {d}: {v}");
                }
            }
        }
    }
}
