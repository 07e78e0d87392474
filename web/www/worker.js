// The explorer's compute thread: loads nyquist_web.wasm and answers requests from the page.
// In:  {id, query}                    (query: the URL query text the Rust side parses)
// Out: {id, progress: [done, total]}  while the request runs
//      {id, ok, json, data, ms}       when it ends (json: the reply text, or the error line;
//                                      data: a Float32Array whose buffer is transferred)

const WASM_URL = new URL('nyquist_web.wasm', import.meta.url);

let current = 0;
let lastProgress = 0;

function progress(done, total) {
  // Throttled: the page redraws its bar at most every 40 ms, plus the final tick.
  const now = performance.now();
  if (done < total && now - lastProgress < 40) return;
  lastProgress = now;
  postMessage({ id: current, progress: [done, total] });
}

async function load() {
  const imports = { env: { nq_progress: progress } };
  try {
    const { instance } = await WebAssembly.instantiateStreaming(fetch(WASM_URL), imports);
    return instance.exports;
  } catch (streamingError) {
    // Served without the application/wasm type, or no streaming support: compile from bytes.
    const response = await fetch(WASM_URL);
    if (!response.ok) throw new Error(`${WASM_URL.pathname}: HTTP ${response.status}`);
    const { instance } = await WebAssembly.instantiate(await response.arrayBuffer(), imports);
    return instance.exports;
  }
}

let exportsPromise = load();
exportsPromise.catch(() => {}); // reported with the first request

function run(wasm, query) {
  const bytes = new TextEncoder().encode(query);
  const ptr = wasm.nq_input(bytes.length);
  new Uint8Array(wasm.memory.buffer, ptr, bytes.length).set(bytes);
  const status = wasm.nq_run();
  const text = new TextDecoder().decode(
    new Uint8Array(wasm.memory.buffer, wasm.nq_text_ptr(), wasm.nq_text_len()));
  const data = new Float32Array(wasm.memory.buffer, wasm.nq_data_ptr(), wasm.nq_data_len()).slice();
  return { ok: status === 0, text, data };
}

// Requests run one after another in arrival order.
let queue = Promise.resolve();

self.onmessage = (event) => {
  const { id, query } = event.data;
  queue = queue.then(async () => {
    let wasm;
    try {
      wasm = await exportsPromise;
    } catch (e) {
      postMessage({ id, ok: false, json: `cannot load the module: ${e.message}`, data: null, ms: 0 });
      return;
    }
    current = id;
    lastProgress = 0;
    const t0 = performance.now();
    try {
      const r = run(wasm, query);
      const ms = performance.now() - t0;
      postMessage({ id, ok: r.ok, json: r.text, data: r.data, ms }, [r.data.buffer]);
    } catch (e) {
      // A trap leaves the module's state unknown: start from a fresh instance next time.
      exportsPromise = load();
      exportsPromise.catch(() => {});
      postMessage({ id, ok: false, json: `the module failed: ${e.message}`, data: null,
        ms: performance.now() - t0 });
    }
  });
};
