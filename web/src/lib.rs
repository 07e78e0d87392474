//! The nyquist explorer's engine: one function, [`handle`], that answers a request from the
//! page (its URL query, e.g. `view=points&sampler=halton&count=256&x=3&y=7`) with a JSON text
//! and an array of `f32` (points, images, spectra). It calls the same library functions as the
//! `nyquist` command (`nyquist_lab`), so the numbers the page shows are the numbers the command
//! prints, and each reply carries that command line (`"cli"`).
//!
//! Compiled to `wasm32-unknown-unknown`, [`abi`] exports [`handle`] to the page's worker
//! (`web/www/worker.js`); natively the same function is what the tests call.
//!
//! ```
//! let r = nyquist_web::handle("view=filters&filter=box&samples=16", &|_, _| {}).unwrap();
//! assert!(r.json.contains("\"integral\":1,"), "{}", r.json);
//! assert_eq!(r.data.len(), 65 * 65 + 3 * 16); // the footprint, then offsets and weights
//! assert!(nyquist_web::handle("view=nope", &|_, _| {}).is_err());
//! ```
#![deny(unsafe_code)]

pub mod abi;
pub mod query;
mod views;

use anyhow::{Result, bail};
use query::Query;

/// A reply: a JSON object (one line) and bulk numbers whose layout the view documents.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Reply {
    /// The JSON object.
    pub json: String,
    /// Points, images or spectra, as the view's documentation lays them out.
    pub data: Vec<f32>,
}

/// Answers one request; `progress(done, total)` is called as long work advances.
///
/// Views (`view=`): `names`, `points`, `spectrum`, `aliasing`, `filters`, `convergence`; each
/// is documented in `docs/web.md` with its parameters and reply.
///
/// # Errors
/// One line naming the parameter at fault (`count=0: need an integer in 1 ..= 65536`), or the
/// command-line error of the computation it runs (which names the flag).
pub fn handle(request: &str, progress: &(dyn Fn(u32, u32) + Sync)) -> Result<Reply> {
    let q = Query::parse(request)?;
    let view = q.text("view", "points");
    let reply = match view.as_str() {
        "names" => views::names(),
        "points" => views::points(&q)?,
        "spectrum" => views::spectrum(&q, progress)?,
        "aliasing" => views::aliasing(&q, progress)?,
        "filters" => views::filters(&q)?,
        "convergence" => views::convergence(&q, progress)?,
        v => bail!("view={v}: not one of names, points, spectrum, aliasing, filters, convergence"),
    };
    q.finish()?;
    Ok(reply)
}

/// A JSON string literal.
fn js(s: &str) -> String {
    nyquist_lab::json::json_string(s)
}

/// A JSON number (`null` where not finite).
fn jn(x: f64) -> String {
    nyquist_lab::json::json_number(x)
}

/// A JSON array of numbers.
fn jlist(v: impl IntoIterator<Item = f64>) -> String {
    let items: Vec<String> = v.into_iter().map(jn).collect();
    format!("[{}]", items.join(","))
}
