//! `nyquist web`: serves the browser explorer (the folder `web/build.sh` assembles: the page and
//! `nyquist_web.wasm`) over HTTP on a loopback address. A small static file server: `GET` and
//! `HEAD` only, files inside the root only, the content types a module page and
//! `WebAssembly.instantiateStreaming` need, one thread per connection, one request each.

use anyhow::{Context, Result, anyhow, bail};
use clap::Args;
pub use nyquist_lab::url::{DecodeError, percent_decode};
use std::io::{BufRead, BufReader, Write};
use std::net::{IpAddr, SocketAddr, TcpListener, TcpStream};
use std::path::{Component, Path, PathBuf};
use std::time::Duration;

/// Arguments of `nyquist web`.
#[derive(Debug, Args)]
#[command(after_help = "Example: nyquist web --root \"$(bash web/build.sh)\" --port 8000")]
pub struct WebArgs {
    /// The folder to serve: the site `bash web/build.sh` assembles (it prints the path); it
    /// must hold index.html and nyquist_web.wasm.
    #[arg(long, value_name = "DIR")]
    pub root: PathBuf,
    /// Address to listen on. Only loopback addresses are accepted: the explorer is a local tool.
    #[arg(long, default_value = "127.0.0.1", value_name = "IP")]
    pub addr: IpAddr,
    /// Port to listen on; 0 picks a free one (the address is printed either way).
    #[arg(long, default_value_t = 8000, value_parser = nyquist_lab::flags::whole(0u16, u16::MAX))]
    pub port: u16,
}

/// The content type of a file, by extension (`application/octet-stream` for others).
///
/// ```
/// use nyquist_cli::web::content_type;
/// assert_eq!(content_type(std::path::Path::new("nyquist_web.wasm")), "application/wasm");
/// assert_eq!(content_type(std::path::Path::new("app.js")), "text/javascript; charset=utf-8");
/// ```
pub fn content_type(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()) {
        Some("html") => "text/html; charset=utf-8",
        Some("js" | "mjs") => "text/javascript; charset=utf-8",
        Some("css") => "text/css; charset=utf-8",
        Some("wasm") => "application/wasm",
        Some("json") => "application/json",
        Some("png") => "image/png",
        Some("svg") => "image/svg+xml",
        Some("ico") => "image/x-icon",
        Some("txt" | "md") => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

/// The file under `root` a request target names, or `None` when it would leave the root
/// (`..`, an absolute path, a drive, a NUL) or is not valid percent-encoded UTF-8. The query
/// and fragment are ignored; `/` and folders map to their `index.html`.
///
/// ```
/// use nyquist_cli::web::resolve;
/// use std::path::Path;
/// let root = Path::new("/srv/site");
/// assert_eq!(resolve(root, "/"), Some(root.join("index.html")));
/// assert_eq!(resolve(root, "/app.js?v=1"), Some(root.join("app.js")));
/// assert_eq!(resolve(root, "/a%20b.txt"), Some(root.join("a b.txt")));
/// assert_eq!(resolve(root, "/../etc/passwd"), None);
/// assert_eq!(resolve(root, "/%2e%2e/etc/passwd"), None);
/// ```
pub fn resolve(root: &Path, target: &str) -> Option<PathBuf> {
    let path = target.split(['?', '#']).next()?;
    let path = path.strip_prefix('/')?;
    let decoded = percent_decode(path).ok()?;
    let mut out = root.to_path_buf();
    for part in decoded.split('/') {
        if part.is_empty() {
            continue;
        }
        if part.contains('\0') || part.contains('\\') {
            return None;
        }
        match Path::new(part).components().next() {
            Some(Component::Normal(_)) if Path::new(part).components().count() == 1 => {
                out.push(part);
            }
            _ => return None,
        }
    }
    if decoded.is_empty() || decoded.ends_with('/') || out.is_dir() {
        out.push("index.html");
    }
    Some(out)
}

/// Runs `nyquist web`: checks the root, binds, prints the address and serves until stopped.
pub fn run(args: &WebArgs) -> Result<()> {
    if !args.addr.is_loopback() {
        bail!(
            "--addr {}: not a loopback address (use 127.0.0.1 or ::1)",
            args.addr
        );
    }
    for file in ["index.html", "nyquist_web.wasm"] {
        if !args.root.join(file).is_file() {
            bail!(
                "--root {}: no {file} there (build the site with `bash web/build.sh`, which prints its folder)",
                args.root.display()
            );
        }
    }
    let listener = TcpListener::bind(SocketAddr::new(args.addr, args.port))
        .map_err(|e| anyhow!("--port {}: cannot listen on {}: {e}", args.port, args.addr))?;
    let local = listener.local_addr().context("the listening address")?;
    let url = match local {
        SocketAddr::V4(a) => format!("http://{a}/"),
        SocketAddr::V6(a) => format!("http://[{}]:{}/", a.ip(), a.port()),
    };
    println!(
        "nyquist explorer: serving {} on {url} (Ctrl-C stops)",
        args.root.display()
    );
    std::io::stdout().flush().ok();
    let root = std::sync::Arc::new(args.root.clone());
    for stream in listener.incoming() {
        let Ok(stream) = stream else { continue };
        let root = std::sync::Arc::clone(&root);
        // A connection that fails (the client went away) only ends its own thread.
        std::thread::spawn(move || {
            let _ = serve(&root, stream);
        });
    }
    Ok(())
}

/// Answers one request on `stream`.
fn serve(root: &Path, stream: TcpStream) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    let mut reader = BufReader::new(stream.try_clone()?);
    let mut line = String::new();
    reader.read_line(&mut line)?;
    // The headers are read and ignored (nothing here depends on them).
    let mut header = String::new();
    while reader.read_line(&mut header)? > 2 {
        header.clear();
    }
    let mut out = stream;
    let mut parts = line.split_whitespace();
    let (method, target) = match (parts.next(), parts.next(), parts.next()) {
        (Some(m), Some(t), Some(v)) if v.starts_with("HTTP/1.") => (m, t),
        _ => {
            return respond(
                &mut out,
                "400 Bad Request",
                "text/plain",
                b"bad request\n",
                true,
            );
        }
    };
    let head = method == "HEAD";
    if method != "GET" && !head {
        return respond(
            &mut out,
            "405 Method Not Allowed",
            "text/plain",
            b"GET or HEAD only\n",
            true,
        );
    }
    let Some(path) = resolve(root, target) else {
        return respond(
            &mut out,
            "404 Not Found",
            "text/plain",
            b"not found\n",
            !head,
        );
    };
    match std::fs::read(&path) {
        Ok(body) => respond(&mut out, "200 OK", content_type(&path), &body, !head),
        Err(_) => respond(
            &mut out,
            "404 Not Found",
            "text/plain",
            b"not found\n",
            !head,
        ),
    }
}

fn respond(
    out: &mut TcpStream,
    status: &str,
    kind: &str,
    body: &[u8],
    with_body: bool,
) -> std::io::Result<()> {
    write!(
        out,
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nCache-Control: no-cache\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n",
        body.len()
    )?;
    if with_body {
        out.write_all(body)?;
    }
    out.flush()
}
