//! The WebAssembly interface the page's worker calls (`web/www/worker.js`), without
//! wasm-bindgen: a request goes in as UTF-8 text, the reply comes out as a JSON text and an
//! `f32` array, both read by the worker from the module's memory.
//!
//! 1. `nq_input(len) -> ptr`: a buffer of `len` bytes for the request; the worker writes it.
//! 2. `nq_run() -> status`: answers it ([`crate::handle`]); 0 for a reply, 1 for an error
//!    (the text is then the one-line message). During the work the module calls the import
//!    `env.nq_progress(done, total)`.
//! 3. `nq_text_ptr()`, `nq_text_len()`: the JSON (or the error); `nq_data_ptr()`,
//!    `nq_data_len()`: the `f32` array (length in values). Valid until the next `nq_input`.
//!
//! There is no `unsafe` block here: the exports hand out addresses of buffers this module owns,
//! and the worker writes and reads them through its own view of memory between calls.
//! The only unsafe-marked items are the `no_mangle` export names and the import block, which is
//! why this module alone allows `unsafe_code`.
#![allow(unsafe_code)]

#[cfg(target_family = "wasm")]
mod exports {
    use std::cell::RefCell;

    thread_local! {
        static INPUT: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
        static TEXT: RefCell<String> = const { RefCell::new(String::new()) };
        static DATA: RefCell<Vec<f32>> = const { RefCell::new(Vec::new()) };
    }

    #[link(wasm_import_module = "env")]
    unsafe extern "C" {
        /// Progress of the current request, posted by the worker to the page.
        safe fn nq_progress(done: u32, total: u32);
    }

    /// A buffer of `len` bytes for the request.
    #[unsafe(no_mangle)]
    pub extern "C" fn nq_input(len: usize) -> *mut u8 {
        TEXT.with_borrow_mut(String::clear);
        DATA.with_borrow_mut(Vec::clear);
        INPUT.with_borrow_mut(|b| {
            b.clear();
            b.resize(len, 0);
            b.as_mut_ptr()
        })
    }

    /// Answers the request in the input buffer: 0 with a reply, 1 with an error message.
    #[unsafe(no_mangle)]
    pub extern "C" fn nq_run() -> u32 {
        let request = INPUT.with_borrow(|b| String::from_utf8_lossy(b).into_owned());
        let (status, text, data) = match crate::handle(&request, &|d, t| nq_progress(d, t)) {
            Ok(r) => (0, r.json, r.data),
            Err(e) => (1, format!("{e:#}"), Vec::new()),
        };
        TEXT.set(text);
        DATA.set(data);
        status
    }

    /// Address of the reply's text.
    #[unsafe(no_mangle)]
    pub extern "C" fn nq_text_ptr() -> *const u8 {
        TEXT.with_borrow(|t| t.as_ptr())
    }

    /// Length of the reply's text in bytes.
    #[unsafe(no_mangle)]
    pub extern "C" fn nq_text_len() -> usize {
        TEXT.with_borrow(String::len)
    }

    /// Address of the reply's numbers.
    #[unsafe(no_mangle)]
    pub extern "C" fn nq_data_ptr() -> *const f32 {
        DATA.with_borrow(|d| d.as_ptr())
    }

    /// Count of the reply's numbers.
    #[unsafe(no_mangle)]
    pub extern "C" fn nq_data_len() -> usize {
        DATA.with_borrow(Vec::len)
    }
}
