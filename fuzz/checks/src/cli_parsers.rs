//! `nyquist-cli`'s string parsers: image sizes, grids, pixels, filter specs and spec lists,
//! CSV point sets, the value-enum names (samplers, scenes, measures), and `compare`'s
//! comma-separated lists through clap exactly as the command line parses them.

use clap::{Args, FromArgMatches, ValueEnum};
use nyquist::filter::{Filter, FilterKind, MAX_RADIUS};
use nyquist_cli::render::{MAX_PIXELS, MAX_SIDE, parse_filter, parse_size};
use nyquist_cli::{analyze, compare, points, render};
use nyquist_lab::scene;

use crate::Bytes;

/// CLI parsers: none panics on any string; `Ok` values lie in their documented ranges (sizes
/// 1 to `MAX_SIDE` a side and at most `MAX_PIXELS` pixels, grids positive, filter radii finite
/// in `(0, MAX_RADIUS]`, CSV values finite in `[0, 1)` with a constant column count) and
/// print back to themselves (`WxH`, `NXxNY`, `X,Y`, a filter's `Display`, a value-enum's name);
/// a plain decimal `WxH` is accepted exactly when it is in range; `Err` messages are non-empty
/// and one line whenever the input is.
pub fn cli_parsers(data: &[u8]) {
    let mut b = Bytes::new(data);
    let op = b.u8() % 10;
    let flag = b.u8();
    let text = match b.u8() % 4 {
        // Structured `AxB` with plain decimals, so the range checks are hit exactly.
        0 => {
            let (x, y) = (number(&mut b), number(&mut b));
            let sep = ["x", "X", ",", " x "][b.u8() as usize % 4];
            format!("{x}{sep}{y}")
        }
        _ => String::from_utf8_lossy(b.rest()).into_owned(),
    };
    let s = text.as_str();
    match op {
        0 => match parse_size(s) {
            Ok([w, h]) => {
                assert!(
                    (1..=MAX_SIDE).contains(&w) && (1..=MAX_SIDE).contains(&h),
                    "{s:?}"
                );
                assert!(u64::from(w) * u64::from(h) <= MAX_PIXELS, "{s:?}");
                assert_eq!(parse_size(&format!("{w}x{h}")), Ok([w, h]));
                if let Some((a, c)) = plain_pair(s, &['x', 'X']) {
                    assert_eq!((u64::from(w), u64::from(h)), (a, c), "{s:?}");
                }
            }
            Err(e) => {
                one_line(s, &e);
                if let Some((a, c)) = plain_pair(s, &['x', 'X']) {
                    let side = |v: u64| (1..=u64::from(MAX_SIDE)).contains(&v);
                    assert!(
                        !(side(a) && side(c) && a * c <= MAX_PIXELS),
                        "{s:?} refused: {e}"
                    );
                }
            }
        },
        1 => match points::parse_grid(s) {
            Ok((x, y)) => {
                assert!(x > 0 && y > 0, "{s:?}");
                assert_eq!(points::parse_grid(&format!("{x}x{y}")), Ok((x, y)));
            }
            Err(e) => {
                one_line(s, &e);
                if let Some((a, c)) = plain_pair(s, &['x', 'X']) {
                    let ok = |v: u64| (1..=u64::from(u32::MAX)).contains(&v);
                    assert!(!(ok(a) && ok(c)), "{s:?} refused: {e}");
                }
            }
        },
        2 => match points::parse_pixel(s) {
            Ok((x, y)) => assert_eq!(points::parse_pixel(&format!("{x},{y}")), Ok((x, y))),
            Err(e) => {
                one_line(s, &e);
                if let Some((a, c)) = plain_pair(s, &[',']) {
                    let ok = |v: u64| v <= u64::from(u32::MAX);
                    assert!(!(ok(a) && ok(c)), "{s:?} refused: {e}");
                }
            }
        },
        3 => match parse_filter(s) {
            Ok(kind) => check_kind(s, &kind),
            Err(e) => one_line(s, &e),
        },
        4 => match compare::parse_filters(s) {
            Ok(list) => {
                assert!(!list.0.is_empty(), "{s:?}: empty list accepted");
                for (spec, kind) in &list.0 {
                    assert_eq!(
                        parse_filter(spec).as_ref(),
                        Ok(kind),
                        "{s:?}: piece {spec:?}"
                    );
                    check_kind(spec, kind);
                }
                // Each filter's Display, joined by commas, is a list that parses back.
                let printed: Vec<String> = list.0.iter().map(|(_, k)| k.to_string()).collect();
                let joined = printed.join(",");
                let back = compare::parse_filters(&joined)
                    .unwrap_or_else(|e| panic!("{s:?} printed as {joined:?}: {e}"));
                let kinds: Vec<&FilterKind> = back.0.iter().map(|(_, k)| k).collect();
                let want: Vec<&FilterKind> = list.0.iter().map(|(_, k)| k).collect();
                assert_eq!(kinds, want, "{s:?} printed as {joined:?}");
            }
            Err(e) => one_line(s, &e),
        },
        5 => match analyze::parse_csv(s, "input") {
            Ok((coords, dims)) => {
                assert!(dims > 0 && !coords.is_empty(), "{s:?}");
                assert_eq!(coords.len() % dims, 0, "{s:?}");
                assert!(coords.iter().all(|v| (0.0..1.0).contains(v)), "{s:?}");
                // Printed back with Rust's shortest round-trip form, the set reads the same.
                let csv: String = coords
                    .chunks(dims)
                    .map(|p| p.iter().map(f64::to_string).collect::<Vec<_>>().join(",") + "\n")
                    .collect();
                let back = analyze::parse_csv(&csv, "input").expect("printed points parse");
                assert_eq!(back, (coords, dims));
            }
            Err(e) => one_line(s, &format!("{e:#}")),
        },
        6 => value_enum::<nyquist_lab::points::PointSetName>(s),
        7 => value_enum::<render::SamplerName>(s),
        8 => {
            value_enum::<scene::Scene>(s);
            value_enum::<analyze::Measure>(s);
            value_enum::<analyze::StarMethod>(s);
            value_enum::<points::Format>(s);
        }
        _ => compare_lists(flag, s),
    }
}

/// A number for structured `AxB` input: small, near the limits, or any `u64`.
fn number(b: &mut Bytes) -> u64 {
    match b.u8() % 6 {
        0 => u64::from(b.u8()),
        1 => u64::from(MAX_SIDE) - 2 + u64::from(b.u8() % 4),
        2 => u64::from(u32::MAX) - 1 + u64::from(b.u8() % 3),
        3 => u64::from(b.u16()),
        4 => 8192 - 4 + u64::from(b.u8() % 8),
        _ => b.u64(),
    }
}

/// `s` as `A<sep>B` with A and B plain decimals (digits only, at most 19, surrounding spaces
/// allowed), as `u64`.
fn plain_pair(s: &str, seps: &[char]) -> Option<(u64, u64)> {
    let (a, c) = s.split_once(seps)?;
    let plain = |t: &str| {
        let t = t.trim();
        (!t.is_empty() && t.len() <= 19 && t.bytes().all(|c| c.is_ascii_digit()))
            .then(|| t.parse::<u64>().ok())
            .flatten()
    };
    Some((plain(a)?, plain(c)?))
}

/// An error message is non-empty, and one line when the input is.
fn one_line(input: &str, message: &str) {
    assert!(!message.trim().is_empty(), "{input:?}: empty error message");
    if !input.contains(['\n', '\r']) {
        assert!(
            !message.contains(['\n', '\r']),
            "{input:?}: error message is not one line: {message:?}"
        );
    }
}

/// A parsed filter: radius finite in `(0, MAX_RADIUS]`, eval finite, and its `Display` parses
/// back to the same filter.
fn check_kind(s: &str, kind: &FilterKind) {
    let [rx, ry] = kind.radius();
    for r in [rx, ry] {
        assert!(
            r.is_finite() && r > 0.0 && r <= MAX_RADIUS,
            "{s:?}: radius {r}"
        );
    }
    assert!(kind.eval(0.0, 0.0).is_finite() && kind.eval(rx * 0.5, -ry * 0.5).is_finite());
    let printed = kind.to_string();
    assert_eq!(
        parse_filter(&printed).as_ref(),
        Ok(kind),
        "{s:?} parsed to {kind:?}, printed as {printed:?}"
    );
}

/// A value-enum name: accepted exactly when it is one of the listed names or aliases (clap's
/// `from_str`), and the accepted value's name parses back to it.
fn value_enum<T: ValueEnum + PartialEq + std::fmt::Debug>(s: &str) {
    match T::from_str(s, false) {
        Ok(v) => {
            let pv = v.to_possible_value().expect("a listed value");
            assert!(
                pv.matches(s, false),
                "{s:?} parsed to {v:?}, not one of its names"
            );
            assert_eq!(T::from_str(pv.get_name(), false).as_ref(), Ok(&v));
        }
        Err(e) => {
            one_line(s, &e);
            let listed = T::value_variants()
                .iter()
                .filter_map(|v| v.to_possible_value())
                .any(|pv| pv.matches(s, false));
            assert!(!listed, "{s:?} is a listed name but was refused");
        }
    }
}

/// `compare`'s list and size options through clap, as `nyquist compare` parses them: `--spp`
/// values in `1..=65536`, `--size` in range, every `--filters` piece a valid spec.
fn compare_lists(flag: u8, s: &str) {
    let flag = ["--spp", "--samplers", "--filters", "--size", "--threads"][flag as usize % 5];
    let cmd = compare::CompareArgs::augment_args(clap::Command::new("compare"));
    let matches = cmd.try_get_matches_from(["compare", flag, s]);
    let matches = match matches {
        Ok(m) => m,
        Err(e) => {
            assert!(!e.render().to_string().trim().is_empty(), "{flag} {s:?}");
            return;
        }
    };
    let args = compare::CompareArgs::from_arg_matches(&matches).expect("matches convert");
    assert!(
        args.spp.iter().all(|n| (1..=65536).contains(n)),
        "{flag} {s:?}: {:?}",
        args.spp
    );
    let [w, h] = args.size;
    assert!((1..=MAX_SIDE).contains(&w) && (1..=MAX_SIDE).contains(&h));
    assert!(args.threads.is_none_or(|t| (1..=1024).contains(&t)));
    for (spec, kind) in &args.filters.0 {
        check_kind(spec, kind);
    }
}
