//! The closed set of built-in filters, for configuration and command-line specs.

use super::{Axis, BlackmanHarris, Boxcar, Filter, Gaussian, Lanczos, Mitchell, Triangle};
use crate::Error;
use core::fmt;

/// One of the built-in filters, chosen at run time (configuration, command line). It is a
/// [`Filter`] itself, dispatching by `match`.
///
/// Spec syntax ([`FilterKind::parse`]): `name[:key=value,…]` with names `box` (or `boxcar`),
/// `triangle` (or `tent`), `gaussian`, `mitchell`, `catmull-rom` (the Mitchell–Netravali cubic
/// at `B = 0`, `C = ½`: a [`Mitchell`] filter, so it takes only the radius keys),
/// `blackman-harris`, `lanczos`, and keys
///
/// - `radius` (both axes), `rx`, `ry`: all filters; `radius` with `rx` or `ry` is a conflict;
/// - `alpha` or `sigma` (`α = 1/(2σ²)`): gaussian;
/// - `b`, `c`: mitchell;
/// - `tau`: lanczos.
///
/// No key may be given twice. Unset keys keep the filter's defaults. [`Display`](fmt::Display) writes a spec that parses
/// back to the same filter.
///
/// ```
/// use nyquist::filter::{FilterKind, Mitchell};
/// let f = FilterKind::parse("mitchell:b=0.5,c=0.25").unwrap();
/// assert_eq!(f, FilterKind::Mitchell(Mitchell::new([2.0, 2.0], 0.5, 0.25).unwrap()));
/// assert_eq!(FilterKind::parse(&f.to_string()).unwrap(), f);
/// assert_eq!(f.name(), "mitchell");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum FilterKind {
    /// [`Boxcar`].
    Boxcar(Boxcar),
    /// [`Triangle`].
    Triangle(Triangle),
    /// [`Gaussian`].
    Gaussian(Gaussian),
    /// [`Mitchell`].
    Mitchell(Mitchell),
    /// [`Lanczos`].
    Lanczos(Lanczos),
    /// [`BlackmanHarris`].
    BlackmanHarris(BlackmanHarris),
}

/// The filter names [`FilterKind::parse`] takes (each alias aside): the list front ends offer.
///
/// ```
/// use nyquist::filter::{FilterKind, FILTER_NAMES};
/// for name in FILTER_NAMES {
///     assert!(FilterKind::parse(name).is_ok(), "{name}");
/// }
/// ```
pub const FILTER_NAMES: [&str; 7] = [
    "box",
    "triangle",
    "gaussian",
    "mitchell",
    "catmull-rom",
    "blackman-harris",
    "lanczos",
];

/// Why [`FilterKind::parse`] rejected a spec; borrows the offending text.
///
/// ```
/// use nyquist::filter::{FilterKind, SpecError};
/// let e = FilterKind::parse("mitchell:b=x").unwrap_err();
/// assert_eq!(e, SpecError::BadNumber { key: "b", value: "x" });
/// assert_eq!(e.to_string(), "filter spec: value `x` of key `b` is not a number");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum SpecError<'a> {
    /// The spec, or its name, is empty.
    Empty,
    /// The name is not a built-in filter.
    UnknownFilter {
        /// The name given.
        name: &'a str,
    },
    /// The key is not one this filter takes.
    UnknownKey {
        /// The filter's name.
        filter: &'static str,
        /// The key given.
        key: &'a str,
    },
    /// An item has no `=value`, or an empty key or value.
    MissingValue {
        /// The item as written.
        item: &'a str,
    },
    /// A value does not parse as a number.
    BadNumber {
        /// The key.
        key: &'a str,
        /// The value given.
        value: &'a str,
    },
    /// A key was given twice.
    Duplicate {
        /// The key.
        key: &'a str,
    },
    /// Two keys that set the same parameter were given: `alpha` and `sigma`, or `radius` and
    /// `rx` or `ry` (either order would decide otherwise).
    Conflict {
        /// The first key.
        first: &'a str,
        /// The second key.
        second: &'a str,
    },
    /// The filter's constructor rejected a value.
    Invalid {
        /// The key that set the value (or the parameter, if a default was rejected).
        key: &'a str,
        /// The value as written (empty for a default).
        value: &'a str,
        /// The constructor's error.
        error: Error,
    },
}

impl fmt::Display for SpecError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("filter spec: ")?;
        match *self {
            SpecError::Empty => f.write_str("empty (expected e.g. `mitchell:b=0.5,c=0.25`)"),
            SpecError::UnknownFilter { name } => {
                write!(f, "unknown filter `{name}` (expected ")?;
                for (i, n) in FILTER_NAMES.iter().enumerate() {
                    let sep = match i {
                        0 => "",
                        _ if i + 1 == FILTER_NAMES.len() => " or ",
                        _ => ", ",
                    };
                    write!(f, "{sep}{n}")?;
                }
                f.write_str(")")
            }
            SpecError::UnknownKey { filter, key } => {
                write!(f, "filter `{filter}` has no key `{key}`")
            }
            SpecError::MissingValue { item } => {
                write!(f, "`{item}` is not of the form key=value")
            }
            SpecError::BadNumber { key, value } => {
                write!(f, "value `{value}` of key `{key}` is not a number")
            }
            SpecError::Duplicate { key } => write!(f, "key `{key}` is given twice"),
            SpecError::Conflict { first, second } => {
                write!(f, "keys `{first}` and `{second}` cannot both be given")
            }
            SpecError::Invalid {
                key,
                value,
                error:
                    Error::OutOfRange {
                        what: "filter integral",
                        value: value_f,
                        range,
                    },
            } => write!(
                f,
                "invalid value `{value}` for key `{key}`: the filter's integral {:e} is below \
                 {:e}, so every sample would weigh almost nothing",
                value_f as f32, range.min as f32
            ),
            SpecError::Invalid {
                key,
                value,
                error: Error::OutOfRange { what, range, .. },
            } => {
                // The value as typed is already named (an `f32` may have rounded it).
                write!(
                    f,
                    "invalid value `{value}` for key `{key}`: {what} must be in {range}"
                )?;
                if matches!(what, "rx" | "ry") {
                    f.write_str(" (2^-16 to 1024 pixels)")?;
                }
                Ok(())
            }
            SpecError::Invalid { key, value, error } => {
                write!(f, "invalid value `{value}` for key `{key}`: {error}")
            }
        }
    }
}

impl core::error::Error for SpecError<'_> {}

/// Every key a spec may hold (each at most once).
const KEYS: [&str; 8] = ["radius", "rx", "ry", "alpha", "sigma", "b", "c", "tau"];

/// A parsed parameter and the `key=value` text that set it.
#[derive(Clone, Copy)]
struct Param<'a> {
    value: f32,
    source: Option<(&'a str, &'a str)>,
}

impl<'a> Param<'a> {
    fn new(value: f32) -> Param<'a> {
        Param {
            value,
            source: None,
        }
    }
    fn set(&mut self, value: f32, key: &'a str, text: &'a str) {
        *self = Param {
            value,
            source: Some((key, text)),
        };
    }
}

impl FilterKind {
    /// Parses a spec `name[:key=value,…]` (see the [type docs](FilterKind)). Names are
    /// case-insensitive; spaces around names, keys and values are ignored. Allocates: no.
    ///
    /// # Errors
    /// A [`SpecError`] naming the offending name, key or value.
    ///
    /// ```
    /// use nyquist::filter::{Filter, FilterKind, SpecError};
    /// let g = FilterKind::parse("gaussian:radius=1.5,sigma=0.5").unwrap();
    /// assert_eq!(g.radius(), [1.5, 1.5]);
    /// let b = FilterKind::parse("box:rx=1,ry=0.5").unwrap();
    /// assert_eq!(b.radius(), [1.0, 0.5]);
    /// assert_eq!(
    ///     FilterKind::parse("lanczos:b=1"),
    ///     Err(SpecError::UnknownKey { filter: "lanczos", key: "b" })
    /// );
    /// assert!(matches!(
    ///     FilterKind::parse("triangle:radius=-1"),
    ///     Err(SpecError::Invalid { key: "radius", value: "-1", .. })
    /// ));
    /// ```
    pub fn parse(spec: &str) -> Result<FilterKind, SpecError<'_>> {
        let (name, params) = match spec.split_once(':') {
            Some((n, p)) => (n.trim(), Some(p)),
            None => (spec.trim(), None),
        };
        if name.is_empty() {
            return Err(SpecError::Empty);
        }
        let lower = |s: &str, t: &str| s.eq_ignore_ascii_case(t);
        let (canonical, defaults): (&'static str, FilterKind) =
            if lower(name, "box") || lower(name, "boxcar") {
                ("box", FilterKind::Boxcar(Boxcar::default()))
            } else if lower(name, "triangle") || lower(name, "tent") {
                ("triangle", FilterKind::Triangle(Triangle::default()))
            } else if lower(name, "gaussian") {
                ("gaussian", FilterKind::Gaussian(Gaussian::default()))
            } else if lower(name, "mitchell") {
                ("mitchell", FilterKind::Mitchell(Mitchell::default()))
            } else if lower(name, "catmull-rom") || lower(name, "catmullrom") {
                ("catmull-rom", FilterKind::Mitchell(Mitchell::catmull_rom()))
            } else if lower(name, "blackman-harris") || lower(name, "blackmanharris") {
                (
                    "blackman-harris",
                    FilterKind::BlackmanHarris(BlackmanHarris::default()),
                )
            } else if lower(name, "lanczos") {
                ("lanczos", FilterKind::Lanczos(Lanczos::default()))
            } else {
                return Err(SpecError::UnknownFilter { name });
            };
        let r = defaults.radius();
        let (mut rx, mut ry) = (Param::new(r[0]), Param::new(r[1]));
        let mut alpha = Param::new(2.0);
        let mut sigma: Option<Param<'_>> = None;
        let (mut b, mut c) = match defaults {
            FilterKind::Mitchell(m) => (Param::new(m.bc()[0]), Param::new(m.bc()[1])),
            _ => (Param::new(1.0 / 3.0), Param::new(1.0 / 3.0)),
        };
        let mut tau = Param::new(3.0);
        let mut alpha_key: Option<&str> = None;
        let mut seen = 0u16;
        for item in params.into_iter().flat_map(|p| p.split(',')) {
            let item = item.trim();
            if item.is_empty() && params.is_some_and(|p| p.trim().is_empty()) {
                continue; // "name:" with nothing after it
            }
            let Some((key, text)) = item.split_once('=') else {
                return Err(SpecError::MissingValue { item });
            };
            let (key, text) = (key.trim(), text.trim());
            if key.is_empty() || text.is_empty() {
                return Err(SpecError::MissingValue { item });
            }
            let value: f32 = text
                .parse()
                .map_err(|_| SpecError::BadNumber { key, value: text })?;
            // A finite number beyond f32 (`1e308`) is out of range, not "infinite": only a
            // spelled-out `inf`/`infinity` (which has an `i`) is.
            let value = if value.is_infinite() && !text.bytes().any(|b| b == b'i' || b == b'I') {
                f32::MAX.copysign(value)
            } else {
                value
            };
            let unknown = SpecError::UnknownKey {
                filter: canonical,
                key,
            };
            let bit = KEYS.iter().position(|&k| k == key).map_or(0, |i| 1u16 << i);
            if seen & bit != 0 {
                return Err(SpecError::Duplicate { key });
            }
            // `radius` sets both half-widths: with `rx` or `ry` the order would decide.
            let earlier = |k: &str| {
                KEYS.iter()
                    .position(|&x| x == k)
                    .is_some_and(|i| seen & (1 << i) != 0)
            };
            let clash = match key {
                "radius" => ["rx", "ry"].into_iter().find(|k| earlier(k)),
                "rx" | "ry" => Some("radius").filter(|k| earlier(k)),
                _ => None,
            };
            if let Some(first) = clash {
                return Err(SpecError::Conflict { first, second: key });
            }
            seen |= bit;
            match key {
                "radius" => {
                    rx.set(value, key, text);
                    ry.set(value, key, text);
                }
                "rx" => rx.set(value, key, text),
                "ry" => ry.set(value, key, text),
                "alpha" | "sigma" if canonical == "gaussian" => {
                    if let Some(first) = alpha_key.filter(|&k| k != key) {
                        return Err(SpecError::Conflict { first, second: key });
                    }
                    alpha_key = Some(key);
                    if key == "alpha" {
                        alpha.set(value, key, text);
                    } else {
                        let mut s = Param::new(value);
                        s.set(value, key, text);
                        sigma = Some(s);
                    }
                }
                "b" if canonical == "mitchell" => b.set(value, key, text),
                "c" if canonical == "mitchell" => c.set(value, key, text),
                "tau" if canonical == "lanczos" => tau.set(value, key, text),
                _ => return Err(unknown),
            }
        }
        let radius = [rx.value, ry.value];
        let built = match defaults {
            FilterKind::Boxcar(_) => Boxcar::new(radius).map(FilterKind::Boxcar),
            FilterKind::Triangle(_) => Triangle::new(radius).map(FilterKind::Triangle),
            FilterKind::Gaussian(_) => match sigma {
                Some(s) => Gaussian::with_sigma(radius, s.value),
                None => Gaussian::new(radius, alpha.value),
            }
            .map(FilterKind::Gaussian),
            FilterKind::Mitchell(_) => {
                Mitchell::new(radius, b.value, c.value).map(FilterKind::Mitchell)
            }
            FilterKind::Lanczos(_) => Lanczos::new(radius, tau.value).map(FilterKind::Lanczos),
            FilterKind::BlackmanHarris(_) => {
                BlackmanHarris::new(radius).map(FilterKind::BlackmanHarris)
            }
        };
        built.map_err(|error| {
            let what = match error {
                Error::NonFinite { what } | Error::OutOfRange { what, .. } => what,
                _ => "",
            };
            let param = match what {
                "rx" => Some(rx),
                "ry" => Some(ry),
                "alpha" => Some(alpha),
                "sigma" => sigma,
                "b" => Some(b),
                "c" => Some(c),
                "tau" => Some(tau),
                // Only a Gaussian's falloff can make its integral negligible.
                "filter integral" => sigma.or(Some(alpha)),
                _ => None,
            };
            let (key, value) = param.and_then(|p| p.source).unwrap_or((what, ""));
            SpecError::Invalid { key, value, error }
        })
    }

    /// The canonical spec name: `box`, `triangle`, `gaussian`, `mitchell`, `lanczos` or
    /// `blackman-harris` (a `catmull-rom` spec is a `mitchell` filter).
    ///
    /// ```
    /// use nyquist::filter::{Boxcar, FilterKind};
    /// assert_eq!(FilterKind::Boxcar(Boxcar::default()).name(), "box");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            FilterKind::Boxcar(_) => "box",
            FilterKind::Triangle(_) => "triangle",
            FilterKind::Gaussian(_) => "gaussian",
            FilterKind::Mitchell(_) => "mitchell",
            FilterKind::Lanczos(_) => "lanczos",
            FilterKind::BlackmanHarris(_) => "blackman-harris",
        }
    }

    /// The filter as a trait object.
    ///
    /// ```
    /// use nyquist::filter::FilterKind;
    /// let f = FilterKind::parse("lanczos").unwrap();
    /// assert_eq!(f.as_dyn().eval(0.0, 0.0), 1.0);
    /// ```
    pub fn as_dyn(&self) -> &dyn Filter {
        match self {
            FilterKind::Boxcar(f) => f,
            FilterKind::Triangle(f) => f,
            FilterKind::Gaussian(f) => f,
            FilterKind::Mitchell(f) => f,
            FilterKind::Lanczos(f) => f,
            FilterKind::BlackmanHarris(f) => f,
        }
    }
}

impl fmt::Display for FilterKind {
    /// The spec that parses back to this filter, every parameter written out (shortest
    /// round-tripping decimals).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [rx, ry] = self.radius();
        write!(f, "{}:rx={rx},ry={ry}", self.name())?;
        match self {
            FilterKind::Gaussian(g) => write!(f, ",alpha={}", g.alpha()),
            FilterKind::Mitchell(m) => {
                let [b, c] = m.bc();
                write!(f, ",b={b},c={c}")
            }
            FilterKind::Lanczos(l) => write!(f, ",tau={}", l.tau()),
            _ => Ok(()),
        }
    }
}

macro_rules! dispatch {
    ($self:ident, $f:ident => $e:expr) => {
        match $self {
            FilterKind::Boxcar($f) => $e,
            FilterKind::Triangle($f) => $e,
            FilterKind::Gaussian($f) => $e,
            FilterKind::Mitchell($f) => $e,
            FilterKind::Lanczos($f) => $e,
            FilterKind::BlackmanHarris($f) => $e,
        }
    };
}

impl Filter for FilterKind {
    #[inline]
    fn radius(&self) -> [f32; 2] {
        dispatch!(self, f => f.radius())
    }
    #[inline]
    fn eval(&self, x: f32, y: f32) -> f32 {
        dispatch!(self, f => f.eval(x, y))
    }
    fn integral(&self) -> f32 {
        dispatch!(self, f => f.integral())
    }
    #[inline]
    fn eval_1d(&self, axis: Axis, x: f32) -> Option<f32> {
        dispatch!(self, f => f.eval_1d(axis, x))
    }
    fn is_separable(&self) -> bool {
        true
    }
}
