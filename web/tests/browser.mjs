// Browser test of the nyquist explorer: loads each view in headless Chromium, takes a screenshot,
// runs the command line the page shows and compares its numbers with the page's, then measures
// two budgets (the default view's time to ready and a zone-plate render in the worker).
//
// Environment: BASE_URL (the served site, e.g. http://127.0.0.1:8123/), NYQUIST (the native
// `nyquist` binary), SHOTS (folder for screenshots), CHROMIUM (default /usr/bin/chromium),
// PLAYWRIGHT_CORE (path or specifier of playwright-core, default 'playwright-core').
// Prints one line per check, `FIRST_USE best_candidate_points_ms=… dithered_points_ms=…` (first
// uses that generate the best-candidate table and the dither mask) and
// `BUDGETS points_ready_ms=… zoneplate_ms=…`; exits 1 on failure.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const env = process.env;
const BASE_URL = env.BASE_URL ?? 'http://127.0.0.1:8123/';
const NYQUIST = env.NYQUIST ?? 'nyquist';
const SHOTS = env.SHOTS ?? path.join(os.tmpdir(), 'nyquist-shots');
const CHROMIUM = env.CHROMIUM ?? '/usr/bin/chromium';
const POINTS_BUDGET_MS = 1000;
const ZONEPLATE_BUDGET_MS = 500;

async function loadPlaywright() {
  let spec = env.PLAYWRIGHT_CORE || 'playwright-core';
  if (spec.includes('/') && fs.existsSync(spec)) {
    if (fs.statSync(spec).isDirectory()) spec = path.join(spec, 'index.mjs');
    spec = pathToFileURL(path.resolve(spec)).href;
  }
  const mod = await import(spec);
  return mod.chromium ?? mod.default.chromium;
}

let failures = 0;
function check(name, ok, detail = '') {
  if (!ok) failures++;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}${detail ? `: ${detail}` : ''}`);
  return ok;
}

/** JSON.parse keeping every number as its source text (a string starting with '#'). */
function rawParse(text) {
  let out = '';
  let i = 0;
  while (i < text.length) {
    const c = text[i];
    if (c === '"') {
      let j = i + 1;
      while (text[j] !== '"') j += text[j] === '\\' ? 2 : 1;
      out += text.slice(i, j + 1);
      i = j + 1;
    } else if (c === '-' || (c >= '0' && c <= '9')) {
      let j = i;
      while (j < text.length && /[-+0-9.eE]/.test(text[j])) j++;
      out += JSON.stringify(`#${text.slice(i, j)}`);
      i = j;
    } else {
      out += c;
      i++;
    }
  }
  return JSON.parse(out);
}
const raw = (v) => (typeof v === 'string' && v.startsWith('#') ? v.slice(1) : String(v));

/** Runs the page's command line natively; returns {stdout, stderr}. */
function runCli(cli, tmp) {
  const args = cli.split(' ').filter(Boolean);
  if (args[0] !== 'nyquist') throw new Error(`not a nyquist command: ${cli}`);
  const argv = args.slice(1).map((a) => (a === 'spectrum.png' ? path.join(tmp, 'spectrum.png') : a));
  const r = spawnSync(NYQUIST, argv, { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (r.error) throw r.error;
  if (r.status !== 0) throw new Error(`${cli} exited with ${r.status}: ${r.stderr.trim()}`);
  return { stdout: r.stdout, stderr: r.stderr };
}

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

function same(name, page, cli) {
  return check(name, page === cli, page === cli ? page : `page ${page} != cli ${cli}`);
}

const VIEWS = [
  ['points', 'view=points&sampler=halton&count=256&x=3&y=7&overlay=strata,intervals,pairs'],
  ['spectrum', 'view=spectrum&sampler=stratified&count=256&freq=16&realisations=8'],
  ['aliasing', 'view=aliasing&scene=zoneplate&size=256x256&sampler=stratified&filter=box&spp=16'],
  ['filters', 'view=filters&filter=mitchell:b=0.3333,c=0.3333'],
  ['convergence', 'view=convergence&samplers=random,stratified,sobol&integrands=disk,gaussian&min=16&max=256&runs=8'],
];

const COMPARE = {
  points(page, out, metrics) {
    const p = rawParse(page.text).analysis;
    const c = rawParse(out.stdout);
    for (const k of ['star', 'l2-star', 'centered-l2', 'wraparound-l2', 'min-distance', 'rho']) {
      same(`points: ${k} equals the CLI`, raw(p[k]), raw(c[k]));
      same(`points: displayed ${k}`, metrics[k], raw(p[k]));
    }
  },
  spectrum(page, out) {
    const p = rawParse(page.text).radial_mean.map(raw);
    const c = rawParse(out.stdout).spectrum_radial_mean.map(raw);
    const differ = p.map((v, k) => [k, v, c[k]]).filter(([, a, b]) => a !== b);
    let detail = `${p.length} values`;
    if (differ.length || p.length !== c.length) {
      const rel = differ.map(([, a, b]) => Math.abs(a - b) / Math.max(Math.abs(a), Math.abs(b)));
      detail = `${differ.length} of ${p.length} differ (largest relative difference `
        + `${Math.max(0, ...rel).toExponential(2)}); first: bin ${differ[0]?.[0]} page ${differ[0]?.[1]} cli ${differ[0]?.[2]}`;
    }
    check('spectrum: radial_mean equals the CLI spectrum_radial_mean',
      !differ.length && p.length === c.length, detail);
  },
  aliasing(page, out, metrics) {
    const p = rawParse(page.text);
    const cell = rawParse(out.stdout).cells[0];
    same('aliasing: rmse equals the CLI', raw(p.rmse), raw(cell.rmse));
    same('aliasing: psnr equals the CLI', raw(p.psnr), raw(cell.psnr));
    same('aliasing: displayed rmse', metrics.rmse, raw(p.rmse));
    same('aliasing: displayed psnr', metrics.psnr, raw(p.psnr));
  },
  filters(page, out, metrics) {
    const p = rawParse(page.text);
    const line = out.stderr.split('\n').find((l) => l.startsWith('integral '));
    same('filters: integral equals the CLI', raw(p.integral), line ? line.slice(9).trim() : '(no integral line)');
    same('filters: displayed integral', metrics.integral, raw(p.integral));
  },
  convergence(page, out, metrics) {
    const p = rawParse(page.text).study.curves;
    const c = rawParse(out.stdout).curves;
    check('convergence: the same curves as the CLI', p.length === c.length && p.length > 0,
      `${p.length} curves, CLI ${c.length}`);
    for (const curve of p) {
      const other = c.find((q) => q.sampler === curve.sampler && q.integrand === curve.integrand);
      const key = `slope:${curve.sampler}:${curve.integrand}`;
      same(`convergence: ${key} equals the CLI`, raw(curve.slope), other ? raw(other.slope) : '(missing)');
      same(`convergence: displayed ${key}`, metrics[key], raw(curve.slope));
    }
  },
};

async function waitReady(page) {
  return page.evaluate(async () => {
    await window.nyquist.ready;
    const state = () => document.body.dataset.state;
    while (state() === 'busy' || state() === 'loading') await new Promise((r) => setTimeout(r, 20));
    return state();
  });
}

async function main() {
  const chromium = await loadPlaywright();
  fs.mkdirSync(SHOTS, { recursive: true });
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'nyquist-browser-'));
  const profile = path.join(tmp, 'profile');
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: false,
    args: ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    viewport: { width: 1400, height: 1000 },
    deviceScaleFactor: 1,
  });
  const messages = [];
  const watch = (page) => {
    page.on('console', (m) => {
      if (m.type() === 'error' || m.type() === 'warning') messages.push(`console ${m.type()}: ${m.text()}`);
    });
    page.on('pageerror', (e) => messages.push(`page error: ${e.message}`));
  };
  const newPage = async () => {
    const page = await context.newPage();
    watch(page);
    return page;
  };
  for (const p of context.pages()) await p.close();

  try {
    const page = await newPage();
    for (const [view, query] of VIEWS) {
      await page.goto(`${BASE_URL}?${query}`);
      const state = await waitReady(page);
      const why = state === 'ready' ? '' : `state ${state}: ${await page.textContent('#error')}`;
      if (!check(`${view}: state ready`, state === 'ready', why)) continue;
      const info = await page.evaluate(() => ({
        last: window.nyquist.last,
        metrics: Object.fromEntries([...document.querySelectorAll('article:not([hidden]) [data-metric]')]
          .map((el) => [el.dataset.metric, el.textContent])),
        progress: [document.querySelector('#progress').value, document.querySelector('#progress').max],
        cli: document.querySelector('#cli').textContent,
      }));
      check(`${view}: the worker answered this view`, info.last?.view === view, info.last?.query);
      check(`${view}: progress complete`, info.progress[0] === info.progress[1], info.progress.join(' / '));
      check(`${view}: the page shows the command line`, info.cli === info.last.json.cli, info.cli);
      await page.screenshot({ path: path.join(SHOTS, `${view}.png`), fullPage: true });
      try {
        const out = runCli(info.last.json.cli, tmp);
        COMPARE[view](info.last, out, info.metrics);
      } catch (e) {
        check(`${view}: CLI comparison`, false, e.message);
      }
    }
    await page.close();

    // The best-candidate table and the dither mask are generated in the module at their first
    // use (lazy-tables): the numbers must still equal the native command's (which reads the
    // stored tables), and the worker's time for each first view is printed (it includes the
    // generation).
    const firstUse = [];
    for (const [name, query] of [
      ['best_candidate', 'view=points&sampler=best-candidate&spp=1024&seed=3'],
      ['dithered', 'view=points&sampler=bluenoise-dithered&spp=64&seed=3'],
    ]) {
      const p = await newPage();
      await p.goto(`${BASE_URL}?${query}`);
      const state = await waitReady(p);
      const why = state === 'ready' ? '' : `state ${state}: ${await p.textContent('#error')}`;
      if (check(`${name} points (first use): state ready`, state === 'ready', why)) {
        const last = await p.evaluate(() => window.nyquist.last);
        const metrics = await p.evaluate(() => Object.fromEntries(
          [...document.querySelectorAll('article:not([hidden]) [data-metric]')]
            .map((el) => [el.dataset.metric, el.textContent])));
        try {
          COMPARE.points(last, runCli(last.json.cli, tmp), metrics);
        } catch (e) {
          check(`${name} points: CLI comparison`, false, e.message);
        }
        firstUse.push(`${name}_points_ms=${last.ms.toFixed(0)}`);
      }
      await p.close();
    }
    console.log(`FIRST_USE ${firstUse.join(' ')}`);

    const ready = [];
    for (let k = 0; k < 5; k++) {
      const p = await newPage();
      await p.goto(BASE_URL);
      const state = await waitReady(p);
      const t = await p.evaluate(() => window.nyquist.timing.navigationToReadyMs);
      check(`default view load ${k + 1}: ready`, state === 'ready' && typeof t === 'number', `${t?.toFixed(0)} ms`);
      ready.push(t);
      await p.close();
    }
    const zone = [];
    for (let k = 0; k < 5; k++) {
      const p = await newPage();
      await p.goto(`${BASE_URL}?view=aliasing&scene=zoneplate&size=256x256&sampler=stratified&filter=box&spp=16&seed=${k}`);
      const state = await waitReady(p);
      const ms = await p.evaluate(() => window.nyquist.last?.ms);
      check(`zone plate render ${k + 1}: ready`, state === 'ready' && typeof ms === 'number', `${ms?.toFixed(0)} ms`);
      zone.push(ms);
      await p.close();
    }
    check('no console errors or warnings, no page errors', messages.length === 0, messages.join(' | '));
    const pr = median(ready);
    const zp = median(zone);
    check(`points ready median ${pr.toFixed(0)} ms <= ${POINTS_BUDGET_MS}`, pr <= POINTS_BUDGET_MS);
    check(`zone plate median ${zp.toFixed(0)} ms <= ${ZONEPLATE_BUDGET_MS}`, zp <= ZONEPLATE_BUDGET_MS);
    console.log(`BUDGETS points_ready_ms=${pr.toFixed(0)} zoneplate_ms=${zp.toFixed(0)}`);
  } finally {
    await context.close();
    fs.rmSync(tmp, { recursive: true, force: true });
  }
  if (failures) {
    console.log(`${failures} check${failures > 1 ? 's' : ''} failed`);
    process.exit(1);
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
