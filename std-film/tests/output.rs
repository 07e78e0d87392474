//! Image writers: round trips, exact sRGB bytes, determinism and no half-written files.

#[path = "support/temp_dir.rs"]
mod temp_dir;

use nyquist_film::output::exr::{ExrPrecision, read_exr, write_exr};
use nyquist_film::output::pfm::{read_pfm, write_pfm};
use nyquist_film::output::png::{PngOptions, write_png};
use nyquist_film::{Image, write_image_file};
use proptest::prelude::*;
use temp_dir::TempDir;

fn decode_png(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!(info.color_type, png::ColorType::Rgb);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    buf.truncate(info.buffer_size());
    (info.width, info.height, buf)
}

fn test_image() -> Image {
    Image::from_fn(5, 3, |x, y| {
        [x as f32 * 0.3 - 0.2, y as f32 * 1e-3, 1e30 * (x + y) as f32]
    })
}

#[test]
fn png_bytes_are_the_srgb_codes_of_known_linear_values() {
    let img = Image::from_rgb(
        2,
        2,
        vec![
            0.0,
            1.0,
            0.5,
            2.0,
            -1.0,
            f32::NAN,
            0.0031308,
            0.2140,
            1e-9,
            f32::INFINITY,
            0.25,
            0.75,
        ],
    )
    .unwrap();
    let mut bytes = Vec::new();
    write_png(&mut bytes, &img, &PngOptions::default()).unwrap();
    let (w, h, px) = decode_png(&bytes);
    assert_eq!((w, h), (2, 2));
    // 0.0031308 → 12.92·x = 0.04045 → 10.31 → 10; 0.2140 → 127.49 → 127;
    // 0.25 → 0.5371 → 137; 0.75 → 0.8808 → 225.
    assert_eq!(px, [0, 255, 188, 255, 0, 0, 10, 127, 0, 255, 137, 225]);
}

#[test]
fn a_png_above_the_fast_deflate_limit_decodes_to_the_srgb_codes_of_every_pixel() {
    use nyquist_film::output::png::{FAST_DEFLATE_ABOVE, linear_to_srgb};
    // 1184² RGB bytes are just above the 4 MiB limit: deflated at level 1.
    let side = 1184u32;
    assert!(3 * (side as usize).pow(2) > FAST_DEFLATE_ABOVE);
    // Every pixel its own value: a ramp over [-0.1, 1.1] with hashed jitter, and NaN and
    // infinities on one column.
    let img = Image::from_fn(side, side, |x, y| {
        let k = u64::from(y * side + x);
        let jitter = nyquist::hash::unit_f32(nyquist::hash::hash2(9, k) as u32);
        let v = -0.1 + 1.2 * (k as f32 + jitter) / (side * side) as f32;
        match x {
            0 => [f32::NAN, f32::INFINITY, f32::NEG_INFINITY],
            _ => [v, v * v, 1.0 - v],
        }
    });
    let mut bytes = Vec::new();
    write_png(&mut bytes, &img, &PngOptions::default()).unwrap();
    let (w, h, px) = decode_png(&bytes);
    assert_eq!((w, h), (side, side));
    let expected: Vec<u8> = img
        .data()
        .iter()
        .map(|&v| (255.0 * linear_to_srgb(v)).round() as u8)
        .collect();
    assert!(
        px == expected,
        "decoded codes differ from round(255 · srgb(v))"
    );
    assert!(expected.contains(&0) && expected.contains(&255));
}

#[test]
fn dithered_png_stays_within_one_code_and_averages_to_the_value() {
    let img = Image::from_fn(64, 64, |_, _| [0.2, 0.2, 0.2]);
    let mut bytes = Vec::new();
    write_png(&mut bytes, &img, &PngOptions { dither: Some(3) }).unwrap();
    let (_, _, px) = decode_png(&bytes);
    let exact = 255.0 * nyquist_film::output::png::linear_to_srgb(0.2) as f64;
    assert!(px.iter().all(|&b| (f64::from(b) - exact).abs() < 1.0));
    let mean = px.iter().map(|&b| f64::from(b)).sum::<f64>() / px.len() as f64;
    assert!((mean - exact).abs() < 0.05, "mean {mean} vs {exact}");
}

#[test]
fn pfm_and_exr_f32_round_trip_exactly() {
    let img = test_image();
    let mut pfm = Vec::new();
    write_pfm(&mut pfm, &img).unwrap();
    assert_eq!(read_pfm(&mut pfm.as_slice()).unwrap(), img);
    let mut exr = Vec::new();
    write_exr(&mut exr, &img, ExrPrecision::F32).unwrap();
    let back = read_exr(&mut exr.as_slice()).unwrap();
    assert_eq!(
        back.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        img.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>()
    );
}

#[test]
fn exr_f16_round_trips_half_representable_values() {
    let img = Image::from_fn(4, 4, |x, y| [x as f32 * 0.5, y as f32 * 0.25, 1024.0]);
    let mut exr = Vec::new();
    write_exr(&mut exr, &img, ExrPrecision::F16).unwrap();
    assert_eq!(read_exr(&mut exr.as_slice()).unwrap(), img);
    let mut exr32 = Vec::new();
    write_exr(&mut exr32, &img, ExrPrecision::F32).unwrap();
    assert_ne!(exr, exr32);
}

#[test]
fn encoders_are_byte_deterministic() {
    let img = test_image();
    let enc = |f: &dyn Fn(&mut Vec<u8>)| {
        let mut v = Vec::new();
        f(&mut v);
        v
    };
    // A determinism check only: two encodings of one image in one process must be the same
    // bytes (the EXR encoder runs without threads, the dither is seeded). The bytes' content is
    // checked by the round-trip and exact-byte tests above.
    for _ in 0..3 {
        assert_eq!(
            enc(&|v| write_exr(v, &img, ExrPrecision::F32).unwrap()),
            enc(&|v| write_exr(v, &img, ExrPrecision::F32).unwrap()),
            "EXR encodings of one image differ: the encoder is not deterministic"
        );
        assert_eq!(
            enc(&|v| write_png(v, &img, &PngOptions { dither: Some(1) }).unwrap()),
            enc(&|v| write_png(v, &img, &PngOptions { dither: Some(1) }).unwrap()),
            "PNG encodings of one image differ: the dither is not deterministic"
        );
    }
}

#[test]
fn writing_into_a_missing_or_read_only_folder_fails_and_leaves_nothing() {
    let img = test_image();
    let dir = TempDir::new("nyquist-film-out");
    for ext in ["png", "exr", "pfm"] {
        let missing = dir.join("missing").join(format!("x.{ext}"));
        assert!(write_image_file(&missing, &img).is_err());
        assert!(!missing.exists());
        // /proc is read-only even for root.
        let read_only = std::path::Path::new("/proc").join(format!("nyquist-{ext}.{ext}"));
        if std::path::Path::new("/proc/self").exists() {
            assert!(write_image_file(&read_only, &img).is_err());
            assert!(!read_only.exists());
        }
        let ok = dir.join(format!("x.{ext}"));
        write_image_file(&ok, &img).unwrap();
        assert!(ok.exists());
    }
    assert!(write_image_file(&dir.join("x.tiff"), &img).is_err());
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        3,
        "stray temporary files"
    );
}

#[test]
fn a_device_target_is_written_in_place_not_replaced() {
    let img = test_image();
    let dir = TempDir::new("nyquist-film-device");
    // A link named like an image, to /dev/null: written through, the link and device kept.
    let link = dir.join("x.pfm");
    std::os::unix::fs::symlink("/dev/null", &link).unwrap();
    write_image_file(&link, &img).unwrap();
    assert!(
        std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(
        std::fs::read_link(&link).unwrap(),
        std::path::Path::new("/dev/null")
    );
    // /dev/full fails with the disk-full error and stays a device.
    let full = dir.join("full.pfm");
    std::os::unix::fs::symlink("/dev/full", &full).unwrap();
    let e = write_image_file(&full, &img).unwrap_err();
    assert!(e.to_string().contains("No space left"), "{e}");
    assert!(
        std::fs::symlink_metadata(&full)
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 2, "stray files");
}

#[test]
fn writing_into_a_folder_without_write_permission_fails_and_leaves_nothing() {
    use std::os::unix::fs::PermissionsExt;
    let img = test_image();
    let dir = TempDir::new("nyquist-film-ro");
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o555)).unwrap();
    // Root ignores directory permissions: then there is nothing to test here (the /proc case
    // above still covers a read-only folder).
    let probe = dir.join("probe");
    let enforced = std::fs::write(&probe, b"x").is_err();
    let _ = std::fs::remove_file(&probe);
    if enforced {
        for ext in ["png", "exr", "pfm"] {
            let target = dir.join(format!("x.{ext}"));
            assert!(write_image_file(&target, &img).is_err(), "{ext}");
        }
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    }
    std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o755)).unwrap();
}

#[test]
fn malformed_inputs_are_errors() {
    assert!(read_pfm(&mut b"PF\n2 2\n-1.0\n\0\0".as_slice()).is_err());
    assert!(read_pfm(&mut b"PF\nx 2\n-1.0\n".as_slice()).is_err());
    assert!(read_pfm(&mut b"".as_slice()).is_err());
    assert!(read_exr(&mut b"\x76\x2f\x31\x01garbage".as_slice()).is_err());
    assert!(Image::new(0, 5).is_err());
}

proptest! {
    #[test]
    fn pfm_round_trips_any_floats(w in 1u32..6, h in 1u32..6, seed: u64) {
        let mut rng = nyquist::rng::default_rng(seed);
        let data: Vec<f32> = (0..w * h * 3).map(|_| f32::from_bits(rand_bits(&mut rng))).collect();
        let img = Image::from_rgb(w, h, data).unwrap();
        let mut bytes = Vec::new();
        write_pfm(&mut bytes, &img).unwrap();
        let back = read_pfm(&mut bytes.as_slice()).unwrap();
        prop_assert_eq!(back.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                        img.data().iter().map(|v| v.to_bits()).collect::<Vec<_>>());
    }
}

fn rand_bits(rng: &mut nyquist::rng::DefaultRng) -> u32 {
    (nyquist::rng::uniform_f64(rng) * 4_294_967_296.0) as u32
}

/// Every I/O failure of `write_image_file` names the file: a missing folder (the temporary
/// file cannot be created) and a full device (the encoder's own writes fail, for PNG inside
/// the encoder), for each format.
#[test]
fn io_errors_name_the_file_they_are_about() {
    use nyquist_film::Error;
    let img = test_image();
    let dir = TempDir::new("nyquist-film-io-errors");
    for ext in ["png", "exr", "pfm"] {
        let missing = dir.join("missing").join(format!("x.{ext}"));
        match write_image_file(&missing, &img) {
            Err(e @ Error::File { .. }) => {
                let Error::File { path, source } = &e else {
                    unreachable!()
                };
                assert_eq!(path, &missing);
                assert_eq!(source.kind(), std::io::ErrorKind::NotFound);
                let text = e.to_string();
                assert!(
                    text.starts_with(&format!("{}: ", missing.display())),
                    "{text}"
                );
            }
            other => panic!("{ext}: {other:?}"),
        }
        let full = dir.join(format!("full.{ext}"));
        std::os::unix::fs::symlink("/dev/full", &full).unwrap();
        match write_image_file(&full, &img) {
            Err(Error::File { path, source }) => {
                assert_eq!(path, full, "{ext}");
                assert!(
                    source.to_string().contains("No space left"),
                    "{ext}: {source}"
                );
            }
            other => panic!("{ext}: {other:?}"),
        }
    }
}
