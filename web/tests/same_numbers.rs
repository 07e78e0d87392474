//! The explorer's replies against the command line they name: each reply's `"cli"` is parsed
//! with the command's own argument types and run through the same library entry points the
//! `nyquist` binary calls, and the numbers must be equal. (web/tests/browser.mjs checks the
//! page against the binary itself, in Chromium.)

use clap::Parser;

use nyquist_cli::{
    analyze::AnalyzeArgs, compare::CompareArgs, converge::ConvergeArgs, filter::FilterArgs,
};
use nyquist_web::handle;

#[derive(Parser)]
enum Cli {
    Analyze(AnalyzeArgs),
    Converge(ConvergeArgs),
    Filter(FilterArgs),
    Compare(CompareArgs),
}

/// The reply's JSON and its `"cli"` parsed (the leading `nyquist` dropped).
fn reply(query: &str) -> (String, Vec<f32>, Cli) {
    let r = handle(query, &|_, _| {}).unwrap_or_else(|e| panic!("{query}: {e:#}"));
    let cli = field(&r.json, "cli");
    let cli = cli.trim_matches('"').to_owned();
    let mut words: Vec<String> = cli.split(' ').map(str::to_owned).collect();
    assert_eq!(words[0], "nyquist", "{cli}");
    words[0] = "x".to_owned();
    let parsed = Cli::try_parse_from(&words).unwrap_or_else(|e| panic!("{cli}: {e}"));
    (r.json, r.data, parsed)
}

/// The raw JSON text of `"key":` at its first occurrence (a number, string, array or object).
fn field(json: &str, key: &str) -> String {
    let start = json
        .find(&format!("\"{key}\":"))
        .unwrap_or_else(|| panic!("no {key} in {json}"))
        + key.len()
        + 3;
    let rest = &json[start..];
    let (mut depth, mut in_str) = (0i32, false);
    for (i, c) in rest.char_indices() {
        match c {
            '"' if !rest[..i].ends_with('\\') => in_str = !in_str,
            '[' | '{' if !in_str => depth += 1,
            ']' | '}' if !in_str => {
                if depth == 0 {
                    return rest[..i].to_owned();
                }
                depth -= 1;
            }
            ',' if !in_str && depth == 0 => return rest[..i].to_owned(),
            _ => {}
        }
    }
    rest.to_owned()
}

#[test]
fn points_equal_analyze_json_for_the_same_flags() {
    for q in [
        "view=points",
        "view=points&sampler=halton&count=500&x=3&y=7",
        "view=points&sampler=sobol&count=1024&seed=5&x=0&y=9",
        "view=points&sampler=stratified&count=24&grid=6x4",
        "view=points&sampler=pmj02&spp=64",
    ] {
        let (json, data, cli) = reply(q);
        let Cli::Analyze(args) = cli else {
            panic!("{q}: not analyze")
        };
        let printed = nyquist_cli::analyze::report(&args).unwrap();
        let analysis = field(&json, "analysis");
        for key in [
            "star",
            "l2-star",
            "centered-l2",
            "wraparound-l2",
            "min-distance",
            "rho",
        ] {
            assert_eq!(field(&analysis, key), field(&printed, key), "{q}: {key}");
        }
        let n: usize = field(&json, "count").parse().unwrap();
        assert_eq!(data.len(), 2 * n, "{q}");
    }
}

/// The domain split of the Points view: after the parents' pairs, each parent's `split`
/// sub-samples, the core's `Domain::split` of the Owen-Sobol sampler's sample, and all
/// `spp·split` of them a (0, m, 2)-net in dimensions 0 and 1.
#[test]
fn the_domain_split_gives_each_samples_sub_samples() {
    use nyquist::sampler::{OwenSobolSampler, Sampler};
    let (json, data, _) = reply("view=points&sampler=owen-sobol&spp=16&split=4&seed=2");
    assert_eq!(field(&json, "split"), "{\"k\":4}");
    assert_eq!(data.len(), 2 * 16 + 2 * 16 * 4);
    let sub: Vec<[f32; 2]> = data[32..].chunks_exact(2).map(|p| [p[0], p[1]]).collect();
    // Every 2^a × 2^b box with a + b = 6 holds one of the 64.
    for (a, b) in [(0u32, 6u32), (3, 3), (6, 0), (2, 4)] {
        let mut seen = [false; 64];
        for p in &sub {
            let cell = ((p[1] * (1 << b) as f32) as usize) << a | (p[0] * (1 << a) as f32) as usize;
            assert!(!std::mem::replace(&mut seen[cell], true), "{a} {b}");
        }
    }
    let mut s = OwenSobolSampler::new(16, 2).unwrap();
    s.start_pixel_sample([0, 0], 5, 0);
    assert_eq!(&data[10..12], &s.get_pixel_2d());
    let d = s.pixel_domain().split(1, 4, 3).unwrap();
    assert_eq!(&data[32 + 2 * (5 * 4 + 3)..][..2], &d.get_2d(0));
    let err = |q: &str| format!("{:#}", handle(q, &|_, _| {}).unwrap_err());
    assert!(err("view=points&sampler=halton&spp=16&split=4").starts_with("split=4: "));
    assert_eq!(
        err("view=points&sampler=owen-sobol&spp=16&split=65"),
        "split=65: need an integer in 1 ..= 64"
    );
}

#[test]
fn the_closest_pair_is_at_the_minimum_distance() {
    let (json, data, _) = reply("view=points&sampler=random&count=700&seed=3");
    let pair = field(&json, "closest_pair");
    let ij: Vec<usize> = pair
        .trim_matches(['[', ']'])
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let p = |k: usize| [f64::from(data[2 * k]), f64::from(data[2 * k + 1])];
    let (a, b) = (p(ij[0]), p(ij[1]));
    let d = (a[0] - b[0]).hypot(a[1] - b[1]);
    let min: f64 = field(&field(&json, "analysis"), "min-distance")
        .parse()
        .unwrap();
    // The page's coordinates are f32, the analysis works in the f64 of those same values.
    assert!(
        (d - min).abs() <= 1e-12 * min.max(1e-300) + 1e-15,
        "{d} vs {min}"
    );
}

#[test]
fn spectrum_equals_analyze_spectrum_json() {
    let q = "view=spectrum&sampler=stratified&count=64&freq=8&realisations=4&seed=2";
    let (json, data, cli) = reply(q);
    let Cli::Analyze(mut args) = cli else {
        panic!("not analyze")
    };
    let png = std::env::temp_dir().join(format!("nyquist-web-spectrum-{}.png", std::process::id()));
    args.spectrum = Some(png.clone());
    let printed = nyquist_cli::analyze::report(&args).unwrap();
    let _ = std::fs::remove_file(png);
    assert_eq!(
        field(&json, "radial_mean"),
        field(&printed, "spectrum_radial_mean")
    );
    assert_eq!(data.len(), 17 * 17);
    // DC, at the centre of the grid, is N.
    assert_eq!(data[8 * 17 + 8], 64.0);
}

#[test]
fn jittered_closed_form_matches_the_measured_spectrum() {
    // 16 × 16 jittered strata averaged over 256 realisations: each annulus' measured mean power
    // is within 0.1 of the closed form 1 − sinc²(π fx/16)·sinc²(π fy/16). Per frequency the
    // power of one realisation has standard deviation ≲ 1, so an annulus mean over ≥ 8
    // frequencies and 256 realisations has σ ≲ 0.022: 0.1 is more than 4σ.
    let q = "view=spectrum&sampler=stratified&count=256&freq=24&realisations=256&seed=11";
    let (json, _, _) = reply(q);
    let list = |key: &str| -> Vec<f64> {
        field(&json, key)
            .trim_matches(['[', ']'])
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let (measured, closed) = (list("radial_mean"), list("jittered_radial_mean"));
    assert_eq!(measured.len(), 25);
    assert_eq!((measured[0], closed[0]), (256.0, 256.0));
    for r in 1..25 {
        assert!(
            (measured[r] - closed[r]).abs() < 0.1,
            "r = {r}: {} vs {}",
            measured[r],
            closed[r]
        );
    }
    // Low frequencies are suppressed (blue): well below white noise's 1 near DC.
    assert!(
        closed[1] < 0.05 && measured[1] < 0.1,
        "{} {}",
        closed[1],
        measured[1]
    );
    // Other sets have no closed form here.
    let (json, _, _) = reply("view=spectrum&sampler=random&count=256&freq=4&realisations=2");
    assert_eq!(field(&json, "jittered_radial_mean"), "null");
}

#[test]
fn convergence_equals_converge_json() {
    let q = "view=convergence&samplers=random,stratified,sobol&integrands=disk,gaussian&min=16&max=256&runs=8&seed=4";
    let (json, _, cli) = reply(q);
    let Cli::Converge(args) = cli else {
        panic!("not converge")
    };
    let printed = nyquist_cli::converge::json_report(&args, 2, &|_, _| {}).unwrap();
    assert_eq!(field(&json, "curves"), field(&printed, "curves"));
    assert!(field(&json, "curves").matches("\"slope\":").count() == 6);
    // `hint` is `--spp-hint`, and the page's error for a sampler that wraps is the command's.
    let q = "view=convergence&samplers=zsobol&integrands=gaussian&min=16&max=256&runs=8&hint=16";
    let (json, _, cli) = reply(q);
    let Cli::Converge(args) = cli else {
        panic!("not converge")
    };
    assert_eq!(args.spp_hint, Some(16));
    let printed = nyquist_cli::converge::json_report(&args, 2, &|_, _| {}).unwrap();
    assert_eq!(field(&json, "curves"), field(&printed, "curves"));
    let plain = reply(&q.replace("&hint=16", "")).0;
    assert_ne!(field(&json, "curves"), field(&plain, "curves"));
    let e = format!(
        "{:#}",
        handle("view=convergence&samplers=zero-two&hint=16", &|_, _| {}).unwrap_err()
    );
    assert!(e.contains("wraps past its spp"), "{e}");
}

#[test]
fn filters_equal_the_filter_command() {
    let (json, data, cli) = reply("view=filters&filter=mitchell:b=0.25,c=0.375&grid=9&samples=100");
    let Cli::Filter(args) = cli else {
        panic!("not filter")
    };
    use nyquist::filter::Filter;
    // `nyquist filter` prints `integral {}` of the same filter.
    assert_eq!(
        field(&json, "integral"),
        format!("{}", args.filter.integral())
    );
    assert_eq!(args.grid, 9);
    assert_eq!(data.len(), 81 + 3 * 100);
    // The footprint is the grid the command prints: f at (−2 + k/2, −2 + j/2).
    for j in 0..9 {
        for i in 0..9 {
            let (x, y) = (-2.0 + 0.5 * i as f32, -2.0 + 0.5 * j as f32);
            assert_eq!(data[j * 9 + i], args.filter.eval(x, y) + 0.0);
        }
    }
    // Importance sampling is unbiased: the mean weight f/pdf estimates the integral (1 for a
    // Mitchell filter); 65536 samples put it within 1 %.
    let (json, _, _) = reply("view=filters&filter=mitchell&samples=65536&seed=9");
    let mean: f64 = field(&json, "mean_weight").parse().unwrap();
    assert!((mean - 1.0).abs() < 0.01, "{mean}");
}

#[test]
fn aliasing_reply_holds_the_render_and_the_exact_means() {
    let (json, data, _) = reply("view=aliasing&size=64x32&spp=4&sampler=sobol&filter=box");
    assert_eq!(data.len(), 2 * 64 * 32);
    let (img, means) = data.split_at(64 * 32);
    let rmse = (img
        .iter()
        .zip(means)
        .map(|(a, b)| (f64::from(*a) - f64::from(*b)).powi(2))
        .sum::<f64>()
        / (64.0 * 32.0))
        .sqrt();
    let reported: f64 = field(&json, "rmse").parse().unwrap();
    // The reply's arrays are f32 copies of the f64 images the RMSE was computed from.
    assert!((rmse - reported).abs() < 1e-6, "{rmse} vs {reported}");
    let (_, _, cli) =
        reply("view=aliasing&size=64x32&spp=4&sampler=sobol&filter=mitchell:b=0.5,c=0.25");
    let Cli::Compare(args) = cli else {
        panic!("not compare")
    };
    assert_eq!(args.filters.0[0].0, "mitchell:b=0.5,c=0.25");
    assert_eq!((args.size, args.spp.as_slice()), ([64, 32], &[4][..]));
}

#[test]
fn bad_requests_name_the_parameter_and_the_limit() {
    let err = |q: &str| format!("{:#}", handle(q, &|_, _| {}).unwrap_err());
    assert_eq!(
        err("view=points&count=0"),
        "count=0: need an integer in 1 ..= 16384"
    );
    assert_eq!(
        err("view=points&x=2&y=2"),
        "x=2, y=2: pick two different dimensions"
    );
    assert_eq!(err("view=points&x=32"), "x=32: need an integer in 0 ..= 31");
    assert_eq!(err("view=points&colour=red"), "colour: unknown parameter");
    assert!(
        err("view=points&sampler=nope").starts_with("sampler=nope: not one of random, uniform,")
    );
    assert!(err("view=aliasing&size=2000x2000").contains("at most 1048576"));
    assert!(err("view=filters&filter=mitchell:q=1").starts_with("filter=mitchell:q=1: "));
    assert!(err("view=convergence&min=3").starts_with("--min-spp 3: not a power of two"));
    assert_eq!(err("a=%zz"), "query: bad escape in \"%zz\"");
    assert!(err("view=spectrum&count=4096&freq=64&realisations=1024").contains("terms"));
}

#[test]
fn names_list_every_menu() {
    let r = handle("view=names", &|_, _| {}).unwrap();
    for key in [
        "point_sets",
        "samplers",
        "scenes",
        "integrands",
        "converge_samplers",
        "filters",
    ] {
        assert!(r.json.contains(&format!("\"{key}\":[")), "{key}");
    }
    assert!(r.json.contains("{\"name\":\"zoneplate\",\"help\":"));
}

#[test]
fn references_are_rendered_once_and_progress_reaches_its_total() {
    use std::sync::Mutex;
    let calls = Mutex::new(Vec::new());
    let run = |q: &str| {
        calls.lock().unwrap().clear();
        handle(q, &|d, t| calls.lock().unwrap().push((d, t))).unwrap();
        calls.lock().unwrap().clone()
    };
    // 32 × 16 pixels is 2 × 1 tiles; the disk has no closed form, so its box reference and its
    // Mitchell reference are rendered (2 + 2 tiles) before the image (2 tiles). (Natively a
    // reference may come from the command line's cache folder instead, and tick nothing.)
    let q = "view=aliasing&scene=disk&size=32x16&spp=4&filter=mitchell";
    let first = run(q);
    assert_eq!(first.first(), Some(&(0, 6)));
    assert_eq!(first.last(), Some(&(6, 6)));
    assert!(first.windows(2).all(|w| w[1].0 >= w[0].0), "{first:?}");
    assert!(first.len() >= 4, "{first:?}"); // at least the image's two tiles between the ends
    // The same scene and size again: both references are kept, only the image is rendered.
    let again = run("view=aliasing&scene=disk&size=32x16&spp=16&filter=mitchell&sampler=sobol");
    assert_eq!(
        (again.first(), again.last()),
        (Some(&(0, 2)), Some(&(2, 2)))
    );
}

#[test]
fn whole_image_samplers_take_a_resolution_in_pixel_mode() {
    for sampler in ["halton", "hammersley", "sobol", "zsobol"] {
        let q = format!("view=points&sampler={sampler}&spp=16");
        let (json, data, cli) = reply(&q);
        let Cli::Analyze(args) = cli else {
            panic!("not analyze")
        };
        assert_eq!(args.resolution, Some((64, 64)), "{q}");
        assert_eq!(data.len(), 32, "{q}: {json}");
    }
    let (_, _, cli) = reply("view=points&sampler=sobol&spp=4&resolution=8x4");
    let Cli::Analyze(args) = cli else {
        panic!("not analyze")
    };
    assert_eq!(args.resolution, Some((8, 4)));
}
