//! `nyquist web`: the explorer's static server, over real TCP connections to the binary.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

/// A server on a free loopback port over a temporary site; killed on drop.
struct Server {
    child: Child,
    addr: String,
    root: std::path::PathBuf,
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

fn start(name: &str) -> Server {
    let root = std::env::temp_dir().join(format!("nyquist-web-{}-{name}", std::process::id()));
    std::fs::create_dir_all(root.join("sub")).unwrap();
    std::fs::write(root.join("index.html"), "<!doctype html><title>x</title>").unwrap();
    std::fs::write(root.join("nyquist_web.wasm"), b"\0asm\x01\0\0\0").unwrap();
    std::fs::write(root.join("app.js"), "export const x = 1;\n").unwrap();
    std::fs::write(root.join("sub").join("index.html"), "sub").unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_nyquist"))
        .args(["web", "--port", "0", "--root"])
        .arg(&root)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    let addr = line
        .split("http://")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .unwrap_or_else(|| panic!("no address in {line:?}"))
        .to_owned();
    Server { child, addr, root }
}

/// Sends `request` raw and returns (status line, headers, body).
fn raw(addr: &str, request: &str) -> (String, String, Vec<u8>) {
    let mut s = TcpStream::connect(addr).unwrap();
    s.write_all(request.as_bytes()).unwrap();
    let mut all = Vec::new();
    s.read_to_end(&mut all).unwrap();
    let split = all
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .expect("a header block");
    let head = String::from_utf8(all[..split].to_vec()).unwrap();
    let (status, headers) = head.split_once("\r\n").unwrap_or((&head, ""));
    (
        status.to_owned(),
        headers.to_owned(),
        all[split + 4..].to_vec(),
    )
}

fn get(addr: &str, target: &str) -> (String, String, Vec<u8>) {
    raw(addr, &format!("GET {target} HTTP/1.1\r\nHost: x\r\n\r\n"))
}

#[test]
fn serves_the_site_with_the_types_a_module_page_needs() {
    let s = start("types");
    let (status, headers, body) = get(&s.addr, "/");
    assert_eq!(status, "HTTP/1.1 200 OK");
    assert!(
        headers.contains("Content-Type: text/html; charset=utf-8"),
        "{headers}"
    );
    assert_eq!(body, b"<!doctype html><title>x</title>");
    let (status, headers, body) = get(&s.addr, "/nyquist_web.wasm");
    assert_eq!(status, "HTTP/1.1 200 OK");
    assert!(
        headers.contains("Content-Type: application/wasm"),
        "{headers}"
    );
    assert!(headers.contains("Content-Length: 8"), "{headers}");
    assert_eq!(body, b"\0asm\x01\0\0\0");
    let (_, headers, _) = get(&s.addr, "/app.js?view=points&count=16");
    assert!(
        headers.contains("Content-Type: text/javascript"),
        "{headers}"
    );
    assert_eq!(get(&s.addr, "/sub/").2, b"sub");
    assert_eq!(get(&s.addr, "/sub").2, b"sub");
}

#[test]
fn head_has_no_body_and_other_methods_are_refused() {
    let s = start("methods");
    let (status, headers, body) = raw(&s.addr, "HEAD /app.js HTTP/1.1\r\n\r\n");
    assert_eq!(status, "HTTP/1.1 200 OK");
    assert!(headers.contains("Content-Length: 20"), "{headers}");
    assert!(body.is_empty());
    let (status, _, _) = raw(&s.addr, "POST / HTTP/1.1\r\nContent-Length: 0\r\n\r\n");
    assert_eq!(status, "HTTP/1.1 405 Method Not Allowed");
    let (status, _, _) = raw(&s.addr, "nonsense\r\n\r\n");
    assert_eq!(status, "HTTP/1.1 400 Bad Request");
}

#[test]
fn nothing_outside_the_root_is_served() {
    let s = start("escape");
    // A file beside the root, which a path that climbs out would reach.
    let outside = s.root.with_extension("secret");
    std::fs::write(&outside, "secret").unwrap();
    let name = outside.file_name().unwrap().to_string_lossy().into_owned();
    for target in [
        format!("/../{name}"),
        format!("/%2e%2e/{name}"),
        format!("/sub/../../{name}"),
        "/%ff".to_owned(),
        "/missing.js".to_owned(),
    ] {
        let (status, _, body) = get(&s.addr, &target);
        assert_eq!(status, "HTTP/1.1 404 Not Found", "{target}");
        assert_eq!(body, b"not found\n", "{target}");
    }
    std::fs::remove_file(outside).unwrap();
}

#[test]
fn bad_flags_get_one_line_and_status_2() {
    let run = |args: &[&str]| {
        let o = Command::new(env!("CARGO_BIN_EXE_nyquist"))
            .arg("web")
            .args(args)
            .output()
            .unwrap();
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let empty = std::env::temp_dir();
    let (code, err) = run(&["--root", empty.to_str().unwrap(), "--port", "0"]);
    assert_eq!(code, Some(2));
    assert!(
        err.starts_with("nyquist: --root ") && err.contains("no index.html"),
        "{err}"
    );
    let (code, err) = run(&["--root", ".", "--addr", "8.8.8.8"]);
    assert_eq!(
        (code, err.trim()),
        (
            Some(2),
            "nyquist: --addr 8.8.8.8: not a loopback address (use 127.0.0.1 or ::1)"
        )
    );
    let (code, err) = run(&["--root", ".", "--port", "70000"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("--port") && err.contains("70000"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
}
