//! The path tracer end to end: the binary renders small images in every format, renders do not
//! depend on the thread count, and every randomised sampler's estimate is unbiased.

use std::path::PathBuf;
use std::process::Command;

use nyquist::sampler::NAMES;
use nyquist::sampler::OwenSobolSampler;
use nyquist_examples::scene::Scene;
use nyquist_examples::trace::{
    Derivation, LightSamples, PathLayout, for_each_sample, for_each_sample_domains,
    for_each_sample_stateless,
};
use nyquist_examples::{RenderConfig, build_sampler, render};
use nyquist_film::output::{exr::read_exr, pfm::read_pfm};

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("nyquist-pathtracer-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn the_binary_renders_small_images_in_every_format() {
    let dir = temp_dir("formats");
    for (scene, file) in [("cornell", "c.pfm"), ("dof", "d.exr"), ("cornell", "c.png")] {
        let out = dir.join(file);
        let status = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
            .args(["render", "--scene", scene, "--size", "24x16", "--spp", "4"])
            .args([
                "--light-samples",
                "2",
                "--sampler",
                "pmj02",
                "--threads",
                "2",
                "-o",
            ])
            .arg(&out)
            .output()
            .unwrap();
        assert!(
            status.status.success(),
            "{}",
            String::from_utf8_lossy(&status.stderr)
        );
        let bytes = std::fs::read(&out).unwrap();
        let img = match file.rsplit('.').next() {
            Some("pfm") => read_pfm(&mut bytes.as_slice()).unwrap(),
            Some("exr") => read_exr(&mut bytes.as_slice()).unwrap(),
            _ => {
                assert_eq!(&bytes[1..4], b"PNG");
                continue;
            }
        };
        assert_eq!((img.width(), img.height()), (24, 16));
        assert!(img.data().iter().all(|v| v.is_finite() && *v >= 0.0));
        let mean = img.data().iter().map(|v| f64::from(*v)).sum::<f64>() / img.data().len() as f64;
        assert!(mean > 0.05 && mean < 5.0, "{scene}: mean {mean}");
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn the_binary_rejects_unknown_samplers_and_scenes() {
    for args in [["--sampler", "nope"], ["--scene", "nope"]] {
        let out = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
            .args(["render", "--size", "4x4", "-o", "/nonexistent/x.png"])
            .args(args)
            .output()
            .unwrap();
        assert!(!out.status.success());
        assert!(String::from_utf8_lossy(&out.stderr).contains("nope"));
    }
}

#[test]
fn renders_do_not_depend_on_the_thread_count() {
    let mut c = RenderConfig::new("dof");
    c.size = [20, 12];
    c.spp = 4;
    c.light_samples = LightSamples::first(3);
    c.tile_size = 8;
    c.sampler = "zsobol".into();
    let one = render(&c, |_, _| {}).unwrap();
    c.threads = 2;
    let two = render(&c, |_, _| {}).unwrap();
    assert_eq!(one.image.data(), two.image.data());
    assert_eq!(one.samples, 20 * 12 * 4);
}

/// Mean and standard error of `xs`.
fn mean_se(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let m = xs.iter().sum::<f64>() / n;
    let var = xs.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0);
    (m, (var / n).sqrt())
}

/// The mean radiance (channel average) over the pixels `A … B` of a 32 × 32 `cornell` film with
/// `spp` camera samples × `light` light samples from `sampler` at `seed`, through the
/// request-and-fill layer or the stateless one.
fn block_mean(sampler: &str, spp: u32, light: u32, seed: u64, stateless: bool) -> f64 {
    block_mean_per_vertex(sampler, spp, &LightSamples::first(light), seed, stateless)
}

/// [`block_mean`] with light samples per vertex.
fn block_mean_per_vertex(
    sampler: &str,
    spp: u32,
    light: &LightSamples,
    seed: u64,
    stateless: bool,
) -> f64 {
    const SIZE: [u32; 2] = [32, 32];
    let scene = Scene::cornell();
    let s = build_sampler(sampler, SIZE, spp, seed).unwrap();
    let layout = PathLayout::new(&s, light).unwrap();
    let (mut sum, mut n) = (0.0f64, 0u32);
    if stateless {
        for_each_sample_stateless(&scene, s, light, SIZE, [6, 10], [22, 26], |_, l| {
            sum += f64::from(l.0.iter().sum::<f32>()) / 3.0;
            n += 1;
        });
    } else {
        for_each_sample(&scene, &layout, s, SIZE, [6, 10], [22, 26], |_, l| {
            sum += f64::from(l.0.iter().sum::<f32>()) / 3.0;
            n += 1;
        })
        .unwrap();
    }
    sum / f64::from(n)
}

/// Unbiasedness. For each randomised sampler, the mean over 32 seeds of a 16 × 16-pixel block's
/// estimate (4 camera samples × 2 light samples) must match a reference: the mean over 256 seeds
/// of the independent `random` sampler at 16 spp. The test fails when
/// `|mean − reference| > 4 √(se² + se_ref²)`; with means of 32 and 256 independent renders
/// (close to normal), each comparison raises a false alarm with probability about 6·10⁻⁵,
/// about 1.4·10⁻³ over the 11 samplers × 2 layers (request-and-fill and stateless). The seeds are fixed, so the outcome is too.
///
/// `uniform` (centred strata: the same image positions for every seed) is not a randomised
/// estimator and is left out, as are `halton-plain` and `sobol-plain`.
#[test]
fn every_randomised_sampler_is_unbiased() {
    let reference: Vec<f64> = (0..256)
        .map(|r| block_mean("random", 16, 1, 1_000_003 + r, false))
        .collect();
    let (m_ref, se_ref) = mean_se(&reference);
    let mut failures = Vec::new();
    for name in NAMES.iter().filter(|n| **n != "uniform") {
        for stateless in [false, true] {
            let xs: Vec<f64> = (0..32)
                .map(|r| block_mean(name, 4, 2, 1 + 7919 * r, stateless))
                .collect();
            let (m, se) = mean_se(&xs);
            let z = (m - m_ref) / (se * se + se_ref * se_ref).sqrt();
            if z.abs() > 4.0 {
                failures.push(format!(
                    "{name} (stateless: {stateless}): {m:.5} ± {se:.5} vs {m_ref:.5} ± {se_ref:.5}, z = {z:.2}"
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// Light samples varying per vertex (4, 2, 1), drawn from the camera sample's domains and
/// through the arrays and the counter: each unbiased against the same reference as
/// [`every_randomised_sampler_is_unbiased`] (the same 4σ rule: about 6·10⁻⁵ per comparison,
/// five comparisons; fixed seeds).
#[test]
fn light_samples_per_vertex_are_unbiased_in_every_layout() {
    const SIZE: [u32; 2] = [32, 32];
    let reference: Vec<f64> = (0..256)
        .map(|r| block_mean("random", 16, 1, 3_000_017 + r, false))
        .collect();
    let (m_ref, se_ref) = mean_se(&reference);
    let light = LightSamples::parse("4,2,1").unwrap();
    let scene = Scene::cornell();
    let domains = |seed: u64, how: Derivation| {
        let s = OwenSobolSampler::new(4, seed).unwrap();
        let (mut sum, mut n) = (0.0f64, 0u32);
        for_each_sample_domains(&scene, s, &light, how, SIZE, [6, 10], [22, 26], |_, l| {
            sum += f64::from(l.0.iter().sum::<f32>()) / 3.0;
            n += 1;
        });
        sum / f64::from(n)
    };
    type Mean<'a> = Box<dyn Fn(u64) -> f64 + 'a>;
    let layouts: [(&str, Mean); 5] = [
        ("split", Box::new(|s| domains(s, Derivation::Split))),
        (
            "distribute",
            Box::new(|s| domains(s, Derivation::Distribute)),
        ),
        ("chain", Box::new(|s| domains(s, Derivation::Chain))),
        (
            "arrays",
            Box::new(|seed| block_mean_per_vertex("owen-sobol", 4, &light, seed, false)),
        ),
        (
            "counter",
            Box::new(|seed| block_mean_per_vertex("owen-sobol", 4, &light, seed, true)),
        ),
    ];
    for (name, mean) in layouts {
        let xs: Vec<f64> = (0..32).map(|r| mean(1 + 7919 * r)).collect();
        let (m, se) = mean_se(&xs);
        let z = (m - m_ref) / (se * se + se_ref * se_ref).sqrt();
        assert!(
            z.abs() <= 4.0,
            "{name}: {m:.5} ± {se:.5} vs {m_ref:.5} ± {se_ref:.5}"
        );
    }
    assert_eq!(light.label(), "4,2");
    assert_eq!(
        LightSamples::parse("4,0").unwrap_err(),
        "\"4,0\": \"0\" is not a count in 1..=65536"
    );
}

/// The estimator is consistent too: the unscrambled Halton sampler (deterministic) converges
/// to the reference as spp grows (error at 256 spp well under that at 4 spp).
#[test]
fn unscrambled_halton_converges_to_the_reference() {
    let reference: Vec<f64> = (0..256)
        .map(|r| block_mean("random", 16, 1, 2_000_003 + r, false))
        .collect();
    let (m_ref, se_ref) = mean_se(&reference);
    let e4 = (block_mean("halton-plain", 4, 1, 0, false) - m_ref).abs();
    let e256 = (block_mean("halton-plain", 256, 1, 0, false) - m_ref).abs();
    assert!(
        e256 < 4.0 * se_ref + 0.5 * e4,
        "{e4} {e256} (se_ref {se_ref})"
    );
}

/// The two layers agree: for samplers whose arrays are runs of dimensions, the stateless
/// layer's values (drawn only as far as each path goes) equal the layout's, so the images are
/// bit-identical; for the others both are valid estimates of the same image.
#[test]
fn the_stateless_layer_renders_what_the_layout_renders() {
    let mut c = RenderConfig::new("dof");
    c.size = [16, 12];
    c.spp = 4;
    c.light_samples = LightSamples::first(3);
    for name in [
        "random",
        "halton",
        "sobol",
        "owen-sobol",
        "hammersley",
        "best-candidate",
    ] {
        c.sampler = name.into();
        c.stateless = false;
        let layout = render(&c, |_, _| {}).unwrap();
        c.stateless = true;
        let stateless = render(&c, |_, _| {}).unwrap();
        assert_eq!(layout.image.data(), stateless.image.data(), "{name}");
    }
    for name in ["stratified", "pmj02", "zsobol", "zero-two"] {
        c.sampler = name.into();
        let img = render(&c, |_, _| {}).unwrap().image;
        assert!(
            img.data().iter().all(|v| v.is_finite() && *v >= 0.0),
            "{name}"
        );
    }
}

/// The experiment prints both tables, writes the contact sheet, caches its reference under
/// `$XDG_CACHE_HOME/nyquist` and, run again, reads it back (same numbers).
#[test]
fn the_experiment_prints_its_tables_and_caches_the_reference() {
    let dir = temp_dir("experiment");
    let run = || {
        let out = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
            .args([
                "experiment",
                "--size",
                "12x8",
                "--runs",
                "2",
                "--reference-spp",
                "16",
            ])
            .args(["--samplers", "random,sobol", "--threads", "2", "--sheet"])
            .arg(dir.join("sheet.png"))
            .env("XDG_CACHE_HOME", &dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let first = run();
    for row in ["| random |", "| sobol |", "16×1: "] {
        assert!(first.contains(row), "{first}");
    }
    let cached: Vec<_> = std::fs::read_dir(dir.join("nyquist")).unwrap().collect();
    assert_eq!(cached.len(), 1);
    let sheet = std::fs::read(dir.join("sheet.png")).unwrap();
    assert_eq!(&sheet[1..4], b"PNG");
    // The RMSE columns (not the times) are the same when the reference comes from the cache.
    let rmse = |s: &str| -> Vec<String> {
        s.lines()
            .filter(|l| l.starts_with("| random") || l.starts_with("| sobol"))
            .take(2)
            .map(|l| l.split('|').take(5).collect::<Vec<_>>().join("|"))
            .collect()
    };
    assert_eq!(rmse(&first), rmse(&run()));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn adaptive_renders_keep_their_budget_and_do_not_depend_on_the_thread_count() {
    let mut c = RenderConfig::new("dof");
    c.size = [20, 12];
    c.tile_size = 8;
    c.adaptive = Some(nyquist_film::adaptive::AdaptiveConfig::new(32, 0.02));
    let one = render(&c, |_, _| {}).unwrap();
    c.threads = 3;
    let three = render(&c, |_, _| {}).unwrap();
    assert_eq!(one.image.data(), three.image.data());
    let (a, b) = (one.adaptive.unwrap(), three.adaptive.unwrap());
    assert_eq!(a, b);
    assert!(a.samples <= 20 * 12 * 32 && a.passes > 1, "{a:?}");
    assert_eq!(one.samples, a.samples);
    // The samples went unevenly: some pixels stopped at the first pass's 16, others took more.
    assert_eq!(a.spp.iter().min(), Some(&16));
    assert!(a.spp.iter().max().unwrap() > &32);
}

#[test]
fn the_adaptive_study_pools_its_seeds_and_measures_every_method() {
    use nyquist_examples::adaptive_study::{StudyConfig, UNIFORM_SPP, run};
    let mut base = RenderConfig::new("cornell");
    base.size = [8, 8];
    let mut r = base.clone();
    r.spp = 64;
    r.stateless = true;
    let reference = render(&r, |_, _| {}).unwrap().image;
    let study = StudyConfig {
        sampler: "owen-sobol".into(),
        budgets: vec![16, 32],
        thresholds: vec![0.05, 0.0],
        floor: 1.0,
        seeds: vec![3, 5],
    };
    let rows = run(&base, &study, &reference, |_, _| {}).unwrap();
    let methods: Vec<(&str, u32)> = rows.iter().map(|m| (m.method.as_str(), m.spp)).collect();
    let mut want: Vec<(&str, u32)> = UNIFORM_SPP.iter().map(|&s| ("uniform", s)).collect();
    for b in [16, 32] {
        want.extend([("adaptive 0.05", b), ("adaptive 0", b), ("contrast", b)]);
    }
    assert_eq!(methods, want);
    // The uniform 16-spp row: the root of the mean of the two seeds' squared RMSE.
    let mut c = base.clone();
    c.spp = 16;
    c.stateless = true;
    let squares: Vec<f64> = [3, 5]
        .map(|seed| {
            c.seed = seed;
            render(&c, |_, _| {})
                .unwrap()
                .image
                .rmse(&reference)
                .unwrap()
                .powi(2)
        })
        .to_vec();
    assert_ne!(squares[0], squares[1]);
    let pooled = ((squares[0] + squares[1]) / 2.0).sqrt();
    assert!(
        (rows[0].rmse - pooled).abs() <= 1e-15 * pooled,
        "{} {pooled}",
        rows[0].rmse
    );
    // Threshold 0 never stops a pixel: the whole budget is spent; the contrast test takes a
    // quarter of it; every non-uniform row has its uniform equivalent.
    for m in &rows[UNIFORM_SPP.len()..] {
        match m.method.as_str() {
            "adaptive 0" => assert_eq!(m.mean_spp, f64::from(m.spp)),
            "contrast" => assert_eq!(m.mean_spp, f64::from(m.spp) / 4.0),
            _ => assert!(m.mean_spp <= f64::from(m.spp)),
        }
        assert!(m.uniform_equivalent.unwrap() > 0.0, "{}", m.method);
    }
}

#[test]
fn the_adaptive_study_rejects_bad_settings() {
    for (flag, value, says) in [
        ("--seeds", "0", "--seeds 0: at least 1"),
        ("--thresholds", "0.1,-1", "--thresholds -1: not a threshold"),
        ("--floor", "NaN", "--floor NaN: must be finite and ≥ 0"),
        (
            "--budgets",
            "8",
            "--budgets: at least one, each at least 16",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
            .args(["adaptive", "--size", "4x4", flag, value])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success() && err.contains(says),
            "{flag} {value}: {err}"
        );
    }
}

/// `--spp-hint`: the sampler made for fewer samples draws `spp` of them. Owen-Sobol's samples
/// do not depend on its spp, so the image equals the one made for `spp`; a sampler that wraps
/// at its spp, or the layout (which fills the sampler's own spp), is refused.
#[test]
fn spp_hint_draws_past_the_samplers_spp() {
    let mut c = RenderConfig::new("cornell");
    c.size = [12, 8];
    c.spp = 16;
    c.stateless = true;
    let plain = render(&c, |_, _| {}).unwrap();
    c.spp_hint = Some(4);
    let hinted = render(&c, |_, _| {}).unwrap();
    assert_eq!(plain.image.data(), hinted.image.data());
    assert_eq!(hinted.samples, 12 * 8 * 16);
    c.sampler = "zsobol".into();
    assert_eq!(render(&c, |_, _| {}).unwrap().samples, 12 * 8 * 16);
    c.sampler = "stratified".into();
    assert!(render(&c, |_, _| {}).is_err());
    c.sampler = "owen-sobol".into();
    c.stateless = false;
    assert!(render(&c, |_, _| {}).is_err());
}
