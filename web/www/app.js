// The explorer's main thread: URL state, controls, the worker that runs the wasm, and drawing.
import * as P from './plot.js';

const VIEWS = ['points', 'spectrum', 'aliasing', 'filters', 'convergence'];
/** Keys that only the page reads; the request to the worker leaves them out. */
const PAGE_KEYS = new Set(['overlay', 'shape', 'crop']);
const DEFAULTS = {
  points: { sampler: 'halton', count: '256', spp: '', grid: '', seed: '', x: '0', y: '1',
    overlay: 'strata', shape: '', split: '' },
  spectrum: { sampler: 'stratified', count: '256', spp: '', grid: '', seed: '', x: '0', y: '1',
    freq: '32', realisations: '16' },
  aliasing: { scene: 'zoneplate', size: '256x256', sampler: 'stratified', filter: 'box',
    spp: '16', seed: '0', crop: '' },
  filters: { filter: 'mitchell', grid: '65', samples: '4096', seed: '0' },
  convergence: { samplers: 'random,stratified,halton,sobol,pmj02',
    integrands: 'disk,triangle,step,gaussian,bilinear', min: '16', max: '1024', runs: '16',
    seed: '0', hint: '' },
};
const CROP = 32;

const $ = (sel, root = document) => root.querySelector(sel);
const $$ = (sel, root = document) => [...root.querySelectorAll(sel)];

/** A JSON number as Rust's `{}` prints an f64: shortest round trip, never an exponent. */
function numText(v) {
  if (v === null || v === undefined) return '—';
  if (typeof v !== 'number') return String(v);
  if (Object.is(v, -0)) return '-0';
  let s = String(v);
  if (!s.includes('e')) return s;
  const neg = s.startsWith('-');
  if (neg) s = s.slice(1);
  const [mant, e] = s.split('e');
  const [int, frac = ''] = mant.split('.');
  const digits = int + frac;
  const point = int.length + Number(e);
  if (point <= 0) s = `0.${'0'.repeat(-point)}${digits}`;
  else if (point >= digits.length) s = digits + '0'.repeat(point - digits.length);
  else s = `${digits.slice(0, point)}.${digits.slice(point)}`;
  return (neg ? '-' : '') + s;
}

// ---------------------------------------------------------------------------------------------
// The worker: one request at a time; a new view request supersedes a running one by restarting
// the worker (the wasm cannot be interrupted).

class Engine {
  constructor() {
    this.nextId = 1;
    this.jobs = new Map();
    this.spawn();
  }

  spawn() {
    this.worker = new Worker(new URL('worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = (e) => this.receive(e.data);
    this.worker.onerror = (e) => {
      e.preventDefault();
      for (const job of this.jobs.values()) {
        job.resolve({ ok: false, json: `the worker failed: ${e.message || 'cannot start'}`, ms: 0 });
      }
      this.jobs.clear();
    };
  }

  receive(m) {
    const job = this.jobs.get(m.id);
    if (!job) return;
    if (m.progress) {
      job.onProgress?.(m.progress[0], m.progress[1]);
      return;
    }
    this.jobs.delete(m.id);
    job.resolve(m);
  }

  /** Runs `query`; resolves {ok, json, data, ms}, or {superseded: true} when replaced. */
  run(query, { onProgress = null, supersedes = true } = {}) {
    if (supersedes && [...this.jobs.values()].some((j) => j.supersedes)) this.restart();
    return new Promise((resolve) => {
      const id = this.nextId++;
      this.jobs.set(id, { query, onProgress, supersedes, resolve });
      this.worker.postMessage({ id, query });
    });
  }

  restart() {
    this.worker.terminate();
    const kept = [];
    for (const [id, job] of this.jobs) {
      if (job.supersedes) job.resolve({ superseded: true });
      else kept.push([id, job]);
    }
    this.jobs = new Map(kept);
    this.spawn();
    for (const [id, job] of kept) this.worker.postMessage({ id, query: job.query });
  }
}

// ---------------------------------------------------------------------------------------------
// State: the current view and every view's parameters (strings, as in the URL).

const state = { view: 'points', params: {} };
const cache = {};
let inflight = null;
let names = null;
let firstDone = false;
let resolveReady;

window.nyquist = {
  last: null,
  ready: new Promise((r) => { resolveReady = r; }),
  timing: { navigationToReadyMs: null },
};

function readURL() {
  const q = new URLSearchParams(location.search);
  const view = q.get('view');
  state.view = VIEWS.includes(view) ? view : 'points';
  for (const v of VIEWS) state.params[v] = { ...DEFAULTS[v] };
  for (const [k, val] of q) if (k !== 'view') state.params[state.view][k] = val;
}

function enc(s) {
  return encodeURIComponent(s).replace(/%2C/gi, ',').replace(/%3A/gi, ':').replace(/%3D/gi, '=');
}

/** The key=value pairs of a view; `page` includes the page-only keys. */
function pairs(view, page) {
  const p = state.params[view];
  const out = [`view=${view}`];
  for (const [k, v] of Object.entries(p)) {
    if (v === '' || (!page && PAGE_KEYS.has(k))) continue;
    if (k === 'count' && p.spp) continue;
    out.push(`${enc(k)}=${enc(v)}`);
  }
  return out.join('&');
}
const requestOf = (view) => pairs(view, false);

function writeURL() {
  const url = `${location.pathname}?${pairs(state.view, true)}`;
  if (url !== location.pathname + location.search) history.replaceState(null, '', url);
}

// ---------------------------------------------------------------------------------------------
// Controls.

function fillMenus() {
  for (const sel of $$('select[data-menu]')) {
    const menu = sel.dataset.menu;
    const items = menu === 'powers'
      ? Array.from({ length: 17 }, (_, k) => ({ name: String(2 ** k), help: '' }))
      : names[menu];
    sel.replaceChildren(...items.map((it) => {
      const o = new Option(it.name, it.name);
      if (it.help) o.title = it.help;
      return o;
    }));
  }
  for (const box of $$('fieldset[data-menu]')) {
    const items = names[box.dataset.menu].map((it) => (typeof it === 'string' ? { name: it } : it));
    const legend = $('legend', box);
    box.replaceChildren(legend, ...items.map((it) => {
      const label = document.createElement('label');
      const input = document.createElement('input');
      input.type = 'checkbox';
      input.value = it.name;
      label.append(input, ` ${it.name}`);
      if (it.help) label.title = it.help;
      return label;
    }));
    box.classList.toggle('columns', items.length > 6);
  }
  $('#filter-buttons').replaceChildren(...names.filters.map((name) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = name;
    b.title = `filter=${name} (its default parameters)`;
    b.addEventListener('click', () => {
      $('#filters-filter').value = name;
      commit();
    });
    return b;
  }));
  for (const sel of $$('select[data-key="sampler"]')) sel.addEventListener('change', () => {
    sel.title = sel.selectedOptions[0]?.title ?? '';
  });
}

/** Shows the view's parameters in its controls. */
function writeForm(view) {
  const p = state.params[view];
  const box = $(`#controls fieldset[data-view="${view}"]`);
  for (const el of $$('[data-key]', box)) {
    const v = p[el.dataset.key] ?? '';
    if (el.hasAttribute('data-list')) {
      const on = new Set(v.split(',').filter(Boolean));
      for (const c of $$('input[type="checkbox"]', el)) c.checked = on.has(c.value);
    } else if (el.tagName === 'SELECT') {
      if (el.dataset.key === 'shape') continue;
      if (v && ![...el.options].some((o) => o.value === v)) el.add(new Option(v, v));
      el.value = v;
      el.title = el.selectedOptions[0]?.title ?? '';
    } else {
      el.value = v;
    }
  }
  const count = $('[data-key="count"]', box);
  if (count) count.disabled = Boolean(p.spp);
}

/** Reads the view's controls back into its parameters (dropping keys no control has). */
function readForm(view) {
  const box = $(`#controls fieldset[data-view="${view}"]`);
  const p = { ...DEFAULTS[view] };
  for (const el of $$('[data-key]', box)) {
    if (el.hasAttribute('data-list')) {
      p[el.dataset.key] = $$('input:checked', el).map((c) => c.value).join(',');
    } else {
      p[el.dataset.key] = el.value.trim();
    }
  }
  if (view === 'aliasing') p.crop = state.params.aliasing.crop;
  if (view === 'points' && !p.overlay) p.overlay = 'none';
  state.params[view] = p;
  const count = $('[data-key="count"]', box);
  if (count) count.disabled = Boolean(p.spp);
}

let debounce = 0;
function commit() {
  clearTimeout(debounce);
  readForm(state.view);
  update();
}

function wireControls() {
  const form = $('#controls');
  form.addEventListener('submit', (e) => e.preventDefault());
  form.addEventListener('input', (e) => {
    if (e.target.matches('input[type="number"], input[type="text"]')) {
      clearTimeout(debounce);
      debounce = setTimeout(commit, 350);
    }
  });
  form.addEventListener('change', commit);
  form.addEventListener('keydown', (e) => {
    if (e.key === 'Enter' && e.target.matches('input')) {
      e.preventDefault();
      commit();
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Tabs.

function selectView(view, focus = false) {
  state.view = view;
  for (const b of $$('#tabs [role="tab"]')) {
    const on = b.dataset.view === view;
    b.setAttribute('aria-selected', String(on));
    b.tabIndex = on ? 0 : -1;
    if (on && focus) b.focus();
  }
  $('#panel').setAttribute('aria-labelledby', `tab-${view}`);
  for (const el of $$('[data-view]:is(fieldset, article)')) el.hidden = el.dataset.view !== view;
  writeForm(view);
  update();
}

function wireTabs() {
  const tabs = $$('#tabs [role="tab"]');
  for (const b of tabs) b.addEventListener('click', () => selectView(b.dataset.view));
  $('#tabs').addEventListener('keydown', (e) => {
    const k = tabs.findIndex((b) => b.dataset.view === state.view);
    const to = { ArrowRight: k + 1, ArrowLeft: k - 1, Home: 0, End: tabs.length - 1 }[e.key];
    if (to === undefined) return;
    e.preventDefault();
    selectView(tabs[(to + tabs.length) % tabs.length].dataset.view, true);
  });
}

// ---------------------------------------------------------------------------------------------
// Computing and showing.

const engine = new Engine();

function setState(s) {
  document.body.dataset.state = s;
}

function showError(message) {
  const el = $('#error');
  el.hidden = !message;
  el.textContent = message ? message.split('\n')[0] : '';
}

/** Stops the running request, if any. */
function cancel() {
  if (!inflight) return;
  engine.restart();
  inflight = null;
}

function update() {
  writeURL();
  const view = state.view;
  const query = requestOf(view);
  if (cache[view]?.query === query) {
    cancel();
    show(view, cache[view]);
    return;
  }
  if (inflight?.query === query) return;
  const p = state.params[view];
  if (view === 'convergence' && !(p.samplers && p.integrands)) {
    cancel();
    fail('Pick at least one sampler and one integrand.');
    return;
  }
  compute(view, query);
}

async function compute(view, query) {
  const token = { view, query };
  inflight = token;
  setState('busy');
  const bar = $('#progress');
  bar.removeAttribute('value');
  const t0 = performance.now();
  let count = '';
  const tell = () => {
    const s = (performance.now() - t0) / 1000;
    $('#status').textContent = `Computing ${view}…${count}${s >= 1 ? ` ${s.toFixed(0)} s` : ''}`;
  };
  tell();
  const clock = setInterval(() => (inflight === token ? tell() : clearInterval(clock)), 500);
  const m = await engine.run(query, {
    onProgress: (done, total) => {
      if (inflight !== token) return;
      count = ` ${done} / ${total}`;
      if (done > 0) {
        bar.max = Math.max(total, 1);
        bar.value = done;
      }
      tell();
    },
  });
  clearInterval(clock);
  if (m.superseded || inflight !== token) return;
  inflight = null;
  bar.max = 1;
  bar.value = 1;
  if (!m.ok) {
    delete cache[view];
    $('#status').textContent = `${view}: failed after ${m.ms.toFixed(0)} ms`;
    fail(m.json);
    return;
  }
  const result = { query, text: m.json, json: JSON.parse(m.json), data: m.data, ms: m.ms };
  cache[view] = result;
  if (state.view === view) show(view, result);
}

function show(view, result) {
  try {
    DRAW[view](result, state.params[view]);
  } catch (e) {
    fail(`drawing ${view} failed: ${e.message}`);
    return;
  }
  showError('');
  const metrics = result.metrics ?? result.json;
  for (const el of $$(`article[data-view="${view}"] [data-metric]`)) {
    const v = metrics[el.dataset.metric];
    if (typeof v === 'number' || v === null) el.textContent = numText(v);
  }
  $('#cli').textContent = result.json.cli;
  $('#status').textContent = `${view}: computed in ${result.ms.toFixed(0)} ms in the worker`;
  window.nyquist.last = { view, query: result.query, json: result.json, text: result.text,
    ms: result.ms };
  $('#progress').value = 1;
  setState('ready');
  finishFirst();
}

/** Shows a one-line error near the controls. */
function fail(message) {
  showError(message);
  setState('error');
  finishFirst();
}

function finishFirst() {
  if (firstDone) return;
  firstDone = true;
  window.nyquist.timing.navigationToReadyMs = performance.now();
  resolveReady(window.nyquist.last);
}

/** Width available to the view's figures, in CSS pixels. */
function panelWidth() {
  const panel = $('#panel');
  const cs = getComputedStyle(panel);
  return panel.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
}

// ---------------------------------------------------------------------------------------------
// Points.

function drawPoints(r, p) {
  const { json, data } = r;
  r.metrics = { ...json.analysis, count: json.count };
  const n = json.count;
  const side = Math.min(540, Math.max(320, panelWidth() - 320));
  const ctx = P.prepare($('#points-plot'), side, side - 8);
  const box = { x: 56, y: 14, w: side - 70, h: side - 70 };
  const quarter = [0, 0.25, 0.5, 0.75, 1];
  const f = P.frame(ctx, box, { xmin: 0, xmax: 1, ymin: 0, ymax: 1, xticks: quarter,
    yticks: quarter, grid: false, xlabel: `dimension ${json.x}`, ylabel: `dimension ${json.y}`,
    ylabelGap: 40 });
  const overlays = new Set((p.overlay ?? '').split(',').filter(Boolean));

  // Elementary intervals 2^a × 2^b with a + b = log2 N.
  const m = Number.isInteger(Math.log2(n)) ? Math.log2(n) : -1;
  const shapeSel = $('#points-shape');
  const shapes = m < 0 ? [] : Array.from({ length: m + 1 }, (_, a) => `${2 ** a}x${2 ** (m - a)}`);
  shapeSel.replaceChildren(...(shapes.length
    ? shapes.map((s) => new Option(s.replace('x', ' × ') + ' cells', s))
    : [new Option(`N = ${n} is not a power of two`, '')]));
  if (p.shape && !shapes.includes(p.shape)) {
    p.shape = '';
    writeURL();
  }
  const shape = p.shape || (shapes[Math.ceil(m / 2)] ?? '');
  shapeSel.value = shape;
  shapeSel.disabled = !shapes.length || !overlays.has('intervals');
  const verdict = $('#points-verdict');
  verdict.textContent = '';
  verdict.className = 'verdict';

  P.clipped(ctx, box, () => {
    if (overlays.has('strata') && json.strata) {
      const [sx, sy] = json.strata;
      gridLines(ctx, f, sx, sy, 'rgba(230,140,20,0.75)', 1);
    }
    if (overlays.has('intervals') && shape) {
      const [cx, cy] = shape.split('x').map(Number);
      const counts = new Uint32Array(cx * cy);
      for (let k = 0; k < n; k++) {
        const i = Math.min(cx - 1, Math.floor(data[2 * k] * cx));
        const j = Math.min(cy - 1, Math.floor(data[2 * k + 1] * cy));
        counts[j * cx + i]++;
      }
      let empty = 0;
      let over = 0;
      counts.forEach((c, k) => {
        if (c === 1) return;
        if (c === 0) empty++; else over++;
        const i = k % cx;
        const j = (k - i) / cx;
        ctx.fillStyle = c === 0 ? 'rgba(214,39,40,0.16)' : 'rgba(255,140,0,0.35)';
        ctx.fillRect(f.x(i / cx), f.y((j + 1) / cy), box.w / cx, box.h / cy);
      });
      if (cx <= 256 && cy <= 256) gridLines(ctx, f, cx, cy, 'rgba(40,120,60,0.55)', 1);
      const cell = `1/${cx} × 1/${cy}`;
      if (empty === 0 && over === 0) {
        verdict.textContent = `Every one of the ${n} elementary intervals of ${cell} holds exactly one point.`;
        verdict.classList.add('good');
      } else {
        verdict.textContent = `Not every elementary interval of ${cell} holds exactly one point: `
          + `${n - empty - over} of ${n} do, ${empty} are empty (red), ${over} hold more (orange).`;
        verdict.classList.add('bad');
      }
    }
  });
  const rad = Math.max(1.1, Math.min(3.2, 3.2 * Math.sqrt(256 / n)));
  if (json.split) {
    // The sub-samples (orange) under their parents: spp·K points of one Owen-scrambled Sobol
    // sequence, K per parent sample.
    const k = json.split.k;
    const m2 = n * k;
    const small = Math.max(1, Math.min(2.4, 2.4 * Math.sqrt(256 / m2)));
    ctx.fillStyle = '#e8891a';
    for (let q = 0; q < m2; q++) {
      ctx.beginPath();
      ctx.arc(f.x(data[2 * n + 2 * q]), f.y(data[2 * n + 2 * q + 1]), small, 0, 2 * Math.PI);
      ctx.fill();
    }
    const text = `${m2} sub-samples (orange): the ${k} of Domain::split(1, ${k}, k) under each of the ${n} samples (blue), together the first ${m2} points of one Owen-scrambled Sobol sequence.`;
    verdict.textContent = verdict.textContent ? `${verdict.textContent} ${text}` : text;
  }
  ctx.fillStyle = '#17406d';
  for (let k = 0; k < n; k++) {
    ctx.beginPath();
    ctx.arc(f.x(data[2 * k]), f.y(data[2 * k + 1]), rad, 0, 2 * Math.PI);
    ctx.fill();
  }
  if (overlays.has('pairs') && json.closest_pair) {
    const [a, b] = json.closest_pair;
    const pa = [f.x(data[2 * a]), f.y(data[2 * a + 1])];
    const pb = [f.x(data[2 * b]), f.y(data[2 * b + 1])];
    P.line(ctx, [pa, pb], '#d62728', 2);
    for (const [px, py] of [pa, pb]) {
      ctx.strokeStyle = '#d62728';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(px, py, rad + 4, 0, 2 * Math.PI);
      ctx.stroke();
    }
    const extra = `Closest pair: points ${a} and ${b} (red), ${numText(json.analysis['min-distance'])} apart.`;
    verdict.textContent = verdict.textContent ? `${verdict.textContent} ${extra}` : extra;
  }
  const method = json.analysis['star-method'];
  $('#points-star-method').textContent = method ? `Star discrepancy method: ${method}.` : '';
}

function gridLines(ctx, f, nx, ny, colour, width) {
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.beginPath();
  for (let i = 1; i < nx; i++) { const px = f.x(i / nx); ctx.moveTo(px, f.y(0)); ctx.lineTo(px, f.y(1)); }
  for (let j = 1; j < ny; j++) { const py = f.y(j / ny); ctx.moveTo(f.x(0), py); ctx.lineTo(f.x(1), py); }
  ctx.stroke();
  ctx.restore();
}

// ---------------------------------------------------------------------------------------------
// Spectrum.

const DB_LO = -30;
const DB_HI = 10;

function drawSpectrum(r) {
  const { json, data } = r;
  const F = json.max_freq;
  const side = 2 * F + 1;
  const wide = panelWidth();
  const imgW = Math.min(520, Math.max(340, Math.floor(wide * 0.5)));
  const ctx = P.prepare($('#spectrum-image'), imgW, imgW - 50);
  const box = { x: 50, y: 24, w: imgW - 140, h: imgW - 140 };
  const dbGrey = (db) => P.grey((db - DB_LO) / (DB_HI - DB_LO));
  const img = P.imageCanvas(data, side, side, (pw) => dbGrey(10 * Math.log10(Math.max(pw, 1e-30))),
    { flipY: true });
  P.frame(ctx, box, { xmin: -F - 0.5, xmax: F + 0.5, ymin: -F - 0.5, ymax: F + 0.5,
    xticks: P.niceTicks(-F, F, 4), yticks: P.niceTicks(-F, F, 4), grid: false,
    xlabel: 'frequency fx', ylabel: 'frequency fy', ylabelGap: 36,
    title: `periodogram, ${json.realisations} realisation${json.realisations > 1 ? 's' : ''}` });
  P.blit(ctx, img, box);
  ctx.strokeStyle = '#888';
  ctx.strokeRect(Math.round(box.x) + 0.5, Math.round(box.y) + 0.5, box.w, box.h);
  P.colourBar(ctx, { x: box.x + box.w + 18, y: box.y, w: 14, h: box.h }, dbGrey, DB_LO, DB_HI,
    [-30, -20, -10, 0, 10], 'dB', (t) => (t > 0 ? `+${t}` : P.tickText(t)));

  const radial = json.radial_mean.slice(1);
  const jit = json.jittered_radial_mean ? json.jittered_radial_mean.slice(1) : null;
  const rw = Math.max(360, Math.min(560, wide - imgW - 24));
  const rctx = P.prepare($('#spectrum-radial'), rw, imgW - 50);
  const rbox = { x: 58, y: 24, w: rw - 76, h: imgW - 140 };
  const top = Math.max(1.25, ...radial.filter(Number.isFinite), ...(jit ?? []).filter(Number.isFinite)) * 1.05;
  const g = P.frame(rctx, rbox, { xmin: 0, xmax: F, ymin: 0, ymax: top, xlabel: 'radial frequency |f|',
    ylabel: 'mean power (1 = white noise)', title: 'radial mean' });
  P.line(rctx, [[g.x(0), g.y(1)], [g.x(F), g.y(1)]], '#777', 1.2, [6, 4]);
  const pts = radial.map((v, k) => [g.x(k + 1), g.y(v)]);
  P.clipped(rctx, rbox, () => {
    P.line(rctx, pts, P.PALETTE[0], 1.8);
    if (F <= 40) for (const [px, py] of pts) P.dot(rctx, px, py, 2.5, P.PALETTE[0]);
    if (jit) P.line(rctx, jit.map((v, k) => [g.x(k + 1), g.y(v)]), P.PALETTE[1], 2, [5, 3]);
  });
  const items = [
    { label: `measured (${json.count} points)`, colour: P.PALETTE[0], marker: F <= 40 },
    { label: 'white noise', colour: '#777', dash: [6, 4], width: 1.2 },
  ];
  if (jit) items.push({ label: 'jittered, closed form 1 − sinc²·sinc²', colour: P.PALETTE[1], dash: [5, 3] });
  P.legend(rctx, rbox.x + rbox.w - 8, rbox.y + rbox.h - 8 - items.length * 17 - 6, items, 'right');

  const notes = [`DC (f = 0) holds N = ${numText(json.radial_mean[0])}; the image clamps it to white.`];
  if (json.identical) notes.push('Every realisation is the same set (it ignores the seed), so averaging does not smooth the periodogram.');
  $('#spectrum-note').textContent = notes.join(' ');
}

// ---------------------------------------------------------------------------------------------
// Aliasing.

function aliasingImages(r) {
  if (r.images) return r.images;
  const { width: w, height: h } = r.json;
  const n = w * h;
  const err = new Float32Array(n);
  let scale = 0;
  for (let k = 0; k < n; k++) {
    err[k] = r.data[k] - r.data[n + k];
    scale = Math.max(scale, Math.abs(err[k]));
  }
  scale = scale || 1;
  r.images = {
    w, h, scale,
    render: P.imageCanvas(r.data, w, h, P.grey),
    reference: P.imageCanvas(r.data, w, h, P.grey, { offset: n }),
    error: P.imageCanvas(err, w, h, (e) => P.diverging(e / scale)),
  };
  return r.images;
}

function cropOf(w, h) {
  const cw = Math.min(CROP, w);
  const ch = Math.min(CROP, h);
  let [x, y] = (state.params.aliasing.crop || '').split(',').map(Number);
  if (!Number.isFinite(x) || !Number.isFinite(y)) [x, y] = [w - cw - Math.floor(w / 16), h - ch - Math.floor(h / 16)];
  x = Math.max(0, Math.min(w - cw, Math.round(x)));
  y = Math.max(0, Math.min(h - ch, Math.round(y)));
  return { x, y, w: cw, h: ch };
}

let aliasLayout = null;

function drawAliasing(r) {
  const im = aliasingImages(r);
  const { w, h } = im;
  const avail = Math.floor((panelWidth() - 2 * 20 - 76) / 3);
  let scale = Math.min(8, avail / w, 400 / h);
  if (scale >= 1) scale = Math.floor(scale);
  const dw = Math.round(w * scale);
  const dh = Math.round(h * scale);
  const crop = cropOf(w, h);
  aliasLayout = { w, h, scale };
  const mark = (ctx) => {
    ctx.strokeStyle = '#ffbf00';
    ctx.lineWidth = 2;
    ctx.strokeRect(crop.x * scale + 1, crop.y * scale + 1, crop.w * scale - 2, crop.h * scale - 2);
  };
  for (const [id, src] of [['render', im.render], ['reference', im.reference]]) {
    const ctx = P.prepare($(`#alias-${id}`), dw, dh);
    P.blit(ctx, src, { x: 0, y: 0, w: dw, h: dh });
    mark(ctx);
  }
  const ectx = P.prepare($('#alias-error'), dw + 76, Math.max(dh, 160));
  P.blit(ectx, im.error, { x: 0, y: 0, w: dw, h: dh });
  mark(ectx);
  const s = im.scale;
  P.colourBar(ectx, { x: dw + 12, y: 18, w: 12, h: Math.max(dh, 160) - 30 }, (v) => P.diverging(v / s), -s, s,
    [-s, 0, s], 'error', (t) => (t === 0 ? '0' : (t > 0 ? '+' : '−') + Number(Math.abs(t).toPrecision(2))));

  const zoom = Math.max(1, Math.floor(Math.min(256, avail) / crop.w));
  const sub = [crop.x, crop.y, crop.w, crop.h];
  for (const [id, src] of [['render', im.render], ['reference', im.reference], ['error', im.error]]) {
    const ctx = P.prepare($(`#alias-crop-${id}`), crop.w * zoom, crop.h * zoom);
    ctx.imageSmoothingEnabled = false;
    P.blit(ctx, src, { x: 0, y: 0, w: crop.w * zoom, h: crop.h * zoom }, sub);
  }
  $('#alias-crop-caption').textContent = `render, pixels ${crop.x}…${crop.x + crop.w - 1} × ${crop.y}…${crop.y + crop.h - 1} (${zoom}×)`;
  $('#alias-reference-caption').textContent = `reference: ${r.json.reference}`;
  $('#alias-filter').textContent = r.json.filter;
}

function wireCrop() {
  const ids = ['#alias-render', '#alias-reference', '#alias-error'];
  const moveTo = (e) => {
    if (!aliasLayout) return;
    const rect = e.currentTarget.getBoundingClientRect();
    const { w, h, scale } = aliasLayout;
    const px = (e.clientX - rect.left) / scale;
    const py = (e.clientY - rect.top) / scale;
    if (px > w + 2) return;
    setCrop(px - CROP / 2, py - CROP / 2);
  };
  for (const id of ids) {
    const c = $(id);
    c.addEventListener('pointerdown', (e) => {
      c.setPointerCapture(e.pointerId);
      moveTo(e);
    });
    c.addEventListener('pointermove', (e) => { if (e.buttons & 1) moveTo(e); });
    c.addEventListener('keydown', (e) => {
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] }[e.key];
      if (!d || !aliasLayout) return;
      e.preventDefault();
      const step = e.shiftKey ? 8 : 1;
      const cur = cropOf(aliasLayout.w, aliasLayout.h);
      setCrop(cur.x + d[0] * step, cur.y + d[1] * step);
    });
  }
}

function setCrop(x, y) {
  const { w, h } = aliasLayout;
  const cw = Math.min(CROP, w);
  const ch = Math.min(CROP, h);
  const cx = Math.max(0, Math.min(w - cw, Math.round(x)));
  const cy = Math.max(0, Math.min(h - ch, Math.round(y)));
  const text = `${cx},${cy}`;
  if (text === state.params.aliasing.crop) return;
  state.params.aliasing.crop = text;
  writeURL();
  if (cache.aliasing && state.view === 'aliasing') drawAliasing(cache.aliasing);
}

// ---------------------------------------------------------------------------------------------
// Filters.

function drawFilters(r) {
  const { json, data } = r;
  $('#filters-name').textContent = json.filter;
  const [rx, ry] = json.radius;
  const wide = panelWidth();
  const pw = Math.max(340, Math.min(520, Math.floor((wide - 24) / 2)));

  const prof = json.profile;
  const vmin = Math.min(0, ...prof.map((q) => q[1]));
  const vmax = Math.max(...prof.map((q) => q[1]));
  const pctx = P.prepare($('#filters-profile'), pw, 280);
  const pbox = { x: 58, y: 24, w: pw - 76, h: 200 };
  const pad = (vmax - vmin) * 0.06 || 0.1;
  const f = P.frame(pctx, pbox, { xmin: -rx, xmax: rx, ymin: vmin - pad, ymax: vmax + pad,
    xlabel: 'offset x (pixels)', ylabel: 'f(x, 0)', title: 'profile' });
  P.line(pctx, [[f.x(-rx), f.y(0)], [f.x(rx), f.y(0)]], '#999', 1);
  P.line(pctx, prof.map(([x, v]) => [f.x(x), f.y(v)]), P.PALETTE[0], 2);

  const resp = json.response;
  const numax = resp[resp.length - 1][0];
  const rmin = Math.min(0, ...resp.map((q) => q[1]));
  const rmax = Math.max(1, ...resp.map((q) => q[1]));
  const rctx = P.prepare($('#filters-response'), pw, 280);
  const rbox = { x: 58, y: 24, w: pw - 76, h: 200 };
  const g = P.frame(rctx, rbox, { xmin: 0, xmax: numax, ymin: rmin, ymax: rmax * 1.05,
    xlabel: 'frequency ν (cycles per pixel)', ylabel: '|F(ν)| / |F(0)|', title: 'frequency response' });
  P.line(rctx, [[g.x(0.5), rbox.y], [g.x(0.5), rbox.y + rbox.h]], '#d62728', 1.2, [6, 4]);
  rctx.fillStyle = '#d62728';
  rctx.textAlign = 'left';
  rctx.textBaseline = 'top';
  rctx.fillText('Nyquist ν = ½', g.x(0.5) + 5, rbox.y + 5);
  P.line(rctx, resp.map(([nu, v]) => [g.x(nu), g.y(v)]), P.PALETTE[0], 2);

  // Footprint, one cell per grid point, and the importance samples on top.
  const G = json.grid;
  const n = json.samples;
  const peak = json.peak || 1;
  const hx = (2 * rx) / (G - 1);
  const hy = (2 * ry) / (G - 1);
  const side = Math.max(320, Math.min(480, wide - 520));
  const aspect = (ry + hy / 2) / (rx + hx / 2);
  const bw = side - 130;
  const bh = Math.round(bw * aspect);
  const fctx = P.prepare($('#filters-footprint'), side, bh + 70);
  const fbox = { x: 50, y: 24, w: bw, h: bh };
  const map = (v) => P.diverging(v / peak);
  const img = P.imageCanvas(data, G, G, map, { flipY: true });
  const h = P.frame(fctx, fbox, { xmin: -rx - hx / 2, xmax: rx + hx / 2, ymin: -ry - hy / 2,
    ymax: ry + hy / 2, xticks: P.niceTicks(-rx, rx, 4), yticks: P.niceTicks(-ry, ry, 4),
    grid: false, xlabel: 'x', ylabel: 'y', ylabelGap: 34,
    title: `footprint (${G} × ${G}) and ${n} samples` });
  P.blit(fctx, img, fbox);
  const base = G * G;
  const dotSize = n > 8192 ? 1 : n > 1024 ? 1.6 : 2.4;
  P.clipped(fctx, fbox, () => {
    for (let k = 0; k < n; k++) {
      const wgt = data[base + 2 * n + k];
      fctx.fillStyle = wgt < 0 ? 'rgba(230,120,0,0.9)' : 'rgba(20,25,35,0.6)';
      fctx.fillRect(h.x(data[base + 2 * k]) - dotSize / 2, h.y(data[base + 2 * k + 1]) - dotSize / 2,
        dotSize, dotSize);
    }
  });
  fctx.strokeStyle = '#888';
  fctx.strokeRect(Math.round(fbox.x) + 0.5, Math.round(fbox.y) + 0.5, fbox.w, fbox.h);
  P.colourBar(fctx, { x: fbox.x + fbox.w + 16, y: fbox.y, w: 12, h: fbox.h }, map, -peak, peak,
    [-peak, 0, peak], 'f', (t) => (t === 0 ? '0' : numText(Number(t.toPrecision(3)))));
  $('[data-metric="radius"]').textContent = `${numText(rx)} × ${numText(ry)}`;
}

// ---------------------------------------------------------------------------------------------
// Convergence.

function drawConvergence(r) {
  const study = r.json.study;
  const integrands = study.integrands.map((it) => it.name);
  const samplers = [...new Set(study.curves.map((c) => c.sampler))];
  const colour = (s) => P.PALETTE[samplers.indexOf(s) % P.PALETTE.length];
  const wide = panelWidth();
  const perRow = Math.max(1, Math.min(integrands.length, Math.floor((wide + 14) / 340)));
  const pw = Math.floor((wide - 14 * (perRow - 1)) / perRow);
  const holder = $('#convergence-panels');
  while (holder.children.length < integrands.length) {
    const c = document.createElement('canvas');
    holder.append(c);
  }
  while (holder.children.length > integrands.length) holder.lastChild.remove();

  integrands.forEach((name, idx) => {
    const curves = study.curves.filter((c) => c.integrand === name);
    const all = curves.flatMap((c) => c.rmse).filter((v) => v > 0 && Number.isFinite(v));
    const canvas = holder.children[idx];
    canvas.setAttribute('aria-label', `RMSE against N for ${name}`);
    const items = curves.map((c) => ({
      label: `${c.sampler} ${c.slope === null ? '—' : c.slope.toFixed(2).replace('-', '−')}`,
      colour: colour(c.sampler), marker: true }));
    items.push({ label: 'slope −½', colour: '#9a9a9a', dash: [8, 4], width: 1.2 });
    items.push({ label: 'slope −1', colour: '#9a9a9a', dash: [2, 3], width: 1.2 });
    const legendRows = Math.ceil(items.length / 2);
    const ph = 300 + legendRows * 17;
    const ctx = P.prepare(canvas, pw, ph);
    const box = { x: 62, y: 24, w: pw - 76, h: 226 };
    const lo = all.length ? Math.min(...all) : 1e-3;
    const hi = all.length ? Math.max(...all) : 1;
    const ymin = 10 ** Math.floor(Math.log10(lo) - 0.05);
    const ymax = 10 ** Math.ceil(Math.log10(hi) + 0.05);
    const f = P.frame(ctx, box, { xmin: study.min_spp, xmax: study.max_spp, xlog: 2, ymin, ymax,
      ylog: 10, xlabel: 'samples N', ylabel: 'RMSE', title: name,
      xticks: study.counts.length > 9 ? study.counts.filter((_, k) => k % 2 === 0) : study.counts });
    P.clipped(ctx, box, () => {
      const n0 = study.min_spp;
      const n1 = study.max_spp;
      for (const [slope, dash] of [[-0.5, [8, 4]], [-1, [2, 3]]]) {
        const y0 = hi;
        P.line(ctx, [[f.x(n0), f.y(y0)], [f.x(n1), f.y(y0 * (n1 / n0) ** slope)]], '#9a9a9a', 1.2, dash);
      }
      for (const c of curves) {
        const pts = c.spp.map((s, k) => [f.x(s), c.rmse[k] > 0 ? f.y(c.rmse[k]) : NaN]);
        P.line(ctx, pts, colour(c.sampler), 1.8);
        for (const [px, py] of pts) if (Number.isFinite(py)) P.dot(ctx, px, py, 2.4, colour(c.sampler));
      }
    });
    P.legendGrid(ctx, { x: 20, y: box.y + box.h + 44, w: pw - 30 }, items, 2);
  });

  const table = $('#convergence-slopes');
  const head = document.createElement('tr');
  head.append(th('sampler', 'col'), ...study.integrands.map((it) => {
    const h = th(it.name, 'col');
    h.title = `exact integral ${numText(it.reference)}`;
    return h;
  }));
  const rows = samplers.map((s) => {
    const tr = document.createElement('tr');
    const name = th(s, 'row');
    name.style.color = colour(s);
    tr.append(name, ...integrands.map((i) => {
      const td = document.createElement('td');
      const c = study.curves.find((q) => q.sampler === s && q.integrand === i);
      td.dataset.metric = `slope:${s}:${i}`;
      td.textContent = c ? numText(c.slope) : '';
      return td;
    }));
    return tr;
  });
  const cap = document.createElement('caption');
  cap.textContent = `Least-squares slopes of log RMSE on log N (${study.runs} runs, N = ${study.min_spp} … ${study.max_spp})`;
  table.replaceChildren(cap, head, ...rows);
}

function th(text, scope) {
  const h = document.createElement('th');
  h.scope = scope;
  h.textContent = text;
  return h;
}

const DRAW = {
  points: drawPoints,
  spectrum: drawSpectrum,
  aliasing: drawAliasing,
  filters: drawFilters,
  convergence: drawConvergence,
};

// ---------------------------------------------------------------------------------------------
// Start: the view in the URL is requested at once, next to the menus.

async function start() {
  readURL();
  wireTabs();
  wireControls();
  wireCrop();
  const namesReply = engine.run('view=names', { supersedes: false });
  selectView(state.view);
  const m = await namesReply;
  if (!m.ok) {
    fail(m.json);
    return;
  }
  names = JSON.parse(m.json);
  fillMenus();
  writeForm(state.view);
  // Figures are sized from the panel's width: redraw when it changes.
  let resizing = 0;
  let width = panelWidth();
  new ResizeObserver(() => {
    if (panelWidth() === width) return;
    width = panelWidth();
    clearTimeout(resizing);
    resizing = setTimeout(() => {
      if (cache[state.view] && !inflight) DRAW[state.view](cache[state.view], state.params[state.view]);
    }, 100);
  }).observe($('#panel'));
}

start();
