// Canvas helpers: crisp canvases at any devicePixelRatio, axes with ticks and labels, colour
// maps and bars, legends, and images built from arrays of numbers.

export const FONT = '12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const INK = '#222';
export const GRID = '#e6e6e6';

/** Series colours (distinguishable on white, in order of use). */
export const PALETTE = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf',
  '#8c564b', '#e377c2', '#7f7f7f', '#bcbd22', '#393b79', '#ad494a', '#637939', '#843c39',
  '#7b4173', '#3182bd'];

/** Sizes `canvas` to `width` × `height` CSS pixels with a backing store of that times the
 *  device pixel ratio; returns a context that draws in CSS pixels, cleared to white. */
export function prepare(canvas, width, height) {
  const dpr = window.devicePixelRatio || 1;
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  canvas.width = Math.round(width * dpr);
  canvas.height = Math.round(height * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, width, height);
  ctx.font = FONT;
  ctx.lineJoin = 'round';
  return ctx;
}

/** About `count` round tick values covering [lo, hi]. */
export function niceTicks(lo, hi, count = 5) {
  if (!(hi > lo)) return [lo];
  const raw = (hi - lo) / count;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) ?? raw;
  const ticks = [];
  for (let t = Math.ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) {
    ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
  }
  return ticks;
}

/** Powers of `base` within [lo, hi] (lo, hi > 0). */
export function logTicks(lo, hi, base = 10) {
  const ticks = [];
  const k0 = Math.floor(Math.log(lo) / Math.log(base) + 1e-9);
  const k1 = Math.ceil(Math.log(hi) / Math.log(base) - 1e-9);
  for (let k = k0; k <= k1; k++) {
    const t = base ** k;
    if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push(t);
  }
  return ticks;
}

/** A short label for a tick value. */
export function tickText(v) {
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) {
    const k = Math.round(Math.log10(a));
    if (Math.abs(a - 10 ** k) < 1e-9 * a) return `${v < 0 ? '−' : ''}10${superscript(k)}`;
    return v.toExponential(1).replace('-', '−');
  }
  return String(Number(v.toPrecision(6))).replace('-', '−');
}

function superscript(k) {
  const digits = '⁰¹²³⁴⁵⁶⁷⁸⁹';
  return String(k).split('').map((c) => (c === '-' ? '⁻' : digits[+c])).join('');
}

/**
 * Draws a plot frame in the box {x, y, w, h} (CSS pixels): grid, ticks, tick labels, axis
 * labels and a title. Options: xmin, xmax, ymin, ymax, xlog, ylog (bases, e.g. 2 or 10),
 * xticks, yticks (values), xlabel, ylabel, title, grid (default true).
 * Returns {x(v), y(v)} mapping data to CSS pixels, and the box.
 */
export function frame(ctx, box, o) {
  const tx = o.xlog ? (v) => Math.log(v) : (v) => v;
  const ty = o.ylog ? (v) => Math.log(v) : (v) => v;
  const [x0, x1, y0, y1] = [tx(o.xmin), tx(o.xmax), ty(o.ymin), ty(o.ymax)];
  const x = (v) => box.x + ((tx(v) - x0) / (x1 - x0)) * box.w;
  const y = (v) => box.y + box.h - ((ty(v) - y0) / (y1 - y0)) * box.h;
  const xticks = o.xticks ?? (o.xlog ? logTicks(o.xmin, o.xmax, o.xlog) : niceTicks(o.xmin, o.xmax));
  const yticks = o.yticks ?? (o.ylog ? logTicks(o.ymin, o.ymax, o.ylog) : niceTicks(o.ymin, o.ymax));
  ctx.save();
  ctx.font = FONT;
  ctx.lineWidth = 1;
  if (o.grid !== false) {
    ctx.strokeStyle = GRID;
    ctx.beginPath();
    for (const t of xticks) { const px = snap(x(t)); ctx.moveTo(px, box.y); ctx.lineTo(px, box.y + box.h); }
    for (const t of yticks) { const py = snap(y(t)); ctx.moveTo(box.x, py); ctx.lineTo(box.x + box.w, py); }
    ctx.stroke();
  }
  ctx.strokeStyle = '#888';
  ctx.strokeRect(snap(box.x), snap(box.y), Math.round(box.w), Math.round(box.h));
  ctx.fillStyle = INK;
  ctx.strokeStyle = INK;
  ctx.beginPath();
  for (const t of xticks) { const px = snap(x(t)); ctx.moveTo(px, box.y + box.h); ctx.lineTo(px, box.y + box.h + 4); }
  for (const t of yticks) { const py = snap(y(t)); ctx.moveTo(box.x - 4, py); ctx.lineTo(box.x, py); }
  ctx.stroke();
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  for (const t of xticks) ctx.fillText((o.xfmt ?? tickText)(t), x(t), box.y + box.h + 6);
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const t of yticks) ctx.fillText((o.yfmt ?? tickText)(t), box.x - 6, y(t));
  if (o.xlabel) {
    ctx.textAlign = 'center';
    ctx.textBaseline = 'top';
    ctx.fillText(o.xlabel, box.x + box.w / 2, box.y + box.h + 22);
  }
  if (o.ylabel) {
    ctx.save();
    ctx.translate(box.x - (o.ylabelGap ?? 44), box.y + box.h / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.textAlign = 'center';
    ctx.textBaseline = 'bottom';
    ctx.fillText(o.ylabel, 0, 0);
    ctx.restore();
  }
  if (o.title) {
    ctx.font = `600 ${FONT}`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'bottom';
    ctx.fillText(o.title, box.x + box.w / 2, box.y - 6);
  }
  ctx.restore();
  return { x, y, box };
}

/** Half-pixel alignment for 1-px lines. */
function snap(v) {
  return Math.round(v) + 0.5;
}

/** Runs `draw(ctx)` clipped to the box. */
export function clipped(ctx, box, draw) {
  ctx.save();
  ctx.beginPath();
  ctx.rect(box.x, box.y, box.w, box.h);
  ctx.clip();
  draw(ctx);
  ctx.restore();
}

/** A polyline through the points [[x, y], …] (pixels); `dash` an array or null. */
export function line(ctx, pts, colour, width = 1.5, dash = null) {
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.setLineDash(dash ?? []);
  ctx.beginPath();
  let pen = false;
  for (const [px, py] of pts) {
    if (!Number.isFinite(px) || !Number.isFinite(py)) { pen = false; continue; }
    if (pen) ctx.lineTo(px, py); else ctx.moveTo(px, py);
    pen = true;
  }
  ctx.stroke();
  ctx.restore();
}

/** Legend rows {label, colour, dash, marker} in a white box whose top-left is (x, y);
 *  `anchor` 'right' puts its top-right there. */
export function legend(ctx, x, y, items, anchor = 'left') {
  ctx.save();
  ctx.font = FONT;
  const rowH = 17;
  const w = 34 + Math.max(...items.map((it) => ctx.measureText(it.label).width));
  const h = items.length * rowH + 6;
  const left = anchor === 'right' ? x - w : x;
  ctx.fillStyle = 'rgba(255,255,255,0.9)';
  ctx.strokeStyle = '#ccc';
  ctx.fillRect(left, y, w, h);
  ctx.strokeRect(left + 0.5, y + 0.5, w - 1, h - 1);
  items.forEach((it, i) => {
    const cy = y + 3 + rowH * i + rowH / 2;
    line(ctx, [[left + 6, cy], [left + 26, cy]], it.colour, it.width ?? 2, it.dash);
    if (it.marker) dot(ctx, left + 16, cy, 3, it.colour);
    ctx.fillStyle = INK;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    ctx.fillText(it.label, left + 30, cy);
  });
  ctx.restore();
}

/** Legend rows without a box, in `cols` columns across the box {x, y, w}. */
export function legendGrid(ctx, box, items, cols) {
  ctx.save();
  ctx.font = FONT;
  const rows = Math.ceil(items.length / cols);
  const colW = box.w / cols;
  items.forEach((it, k) => {
    const left = box.x + Math.floor(k / rows) * colW;
    const cy = box.y + (k % rows) * 17 + 8;
    line(ctx, [[left, cy], [left + 20, cy]], it.colour, it.width ?? 2, it.dash);
    if (it.marker) dot(ctx, left + 10, cy, 2.6, it.colour);
    ctx.fillStyle = INK;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    ctx.fillText(it.label, left + 26, cy);
  });
  ctx.restore();
}

/** A filled circle. */
export function dot(ctx, x, y, r, colour) {
  ctx.fillStyle = colour;
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.fill();
}

/** Grey level for t in [0, 1] (clamped), as [r, g, b]. */
export function grey(t) {
  const v = Math.round(255 * Math.min(1, Math.max(0, t)));
  return [v, v, v];
}

/** Diverging map for t in [−1, 1] (clamped): blue below 0, white at 0, red above. */
export function diverging(t) {
  const s = Math.min(1, Math.max(-1, t));
  const a = Math.abs(s);
  const end = s < 0 ? [33, 102, 172] : [178, 24, 43];
  const mid = s < 0 ? [146, 197, 222] : [244, 165, 130];
  if (a < 0.5) {
    const u = a / 0.5;
    return [0, 1, 2].map((k) => Math.round(255 + (mid[k] - 255) * u));
  }
  const u = (a - 0.5) / 0.5;
  return [0, 1, 2].map((k) => Math.round(mid[k] + (end[k] - mid[k]) * u));
}

/**
 * An offscreen canvas of w × h pixels whose pixel (i, j) has colour map(values[offset + j·w + i]);
 * `flipY` puts row 0 of the values at the bottom.
 */
export function imageCanvas(values, w, h, map, { offset = 0, flipY = false } = {}) {
  const c = document.createElement('canvas');
  c.width = w;
  c.height = h;
  const ctx = c.getContext('2d');
  const img = ctx.createImageData(w, h);
  for (let j = 0; j < h; j++) {
    const row = flipY ? h - 1 - j : j;
    for (let i = 0; i < w; i++) {
      const [r, g, b] = map(values[offset + j * w + i]);
      const p = 4 * (row * w + i);
      img.data[p] = r;
      img.data[p + 1] = g;
      img.data[p + 2] = b;
      img.data[p + 3] = 255;
    }
  }
  ctx.putImageData(img, 0, 0);
  return c;
}

/** Draws an image canvas into the box; nearest-neighbour when magnified. */
export function blit(ctx, src, box, sub = null) {
  ctx.save();
  const [sx, sy, sw, sh] = sub ?? [0, 0, src.width, src.height];
  ctx.imageSmoothingEnabled = box.w < sw || box.h < sh;
  ctx.drawImage(src, sx, sy, sw, sh, box.x, box.y, box.w, box.h);
  ctx.restore();
}

/** A vertical colour bar in the box for values lo … hi (top = hi), with ticks on the right. */
export function colourBar(ctx, box, map, lo, hi, ticks, label, fmt = tickText) {
  for (let k = 0; k < box.h; k++) {
    const v = hi - ((k + 0.5) / box.h) * (hi - lo);
    const [r, g, b] = map(v);
    ctx.fillStyle = `rgb(${r},${g},${b})`;
    ctx.fillRect(box.x, box.y + k, box.w, 1.5);
  }
  ctx.save();
  ctx.strokeStyle = '#888';
  ctx.strokeRect(box.x + 0.5, box.y + 0.5, box.w - 1, box.h - 1);
  ctx.fillStyle = INK;
  ctx.strokeStyle = INK;
  ctx.font = FONT;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  for (const t of ticks) {
    const py = Math.round(box.y + ((hi - t) / (hi - lo)) * box.h) + 0.5;
    ctx.beginPath();
    ctx.moveTo(box.x + box.w, py);
    ctx.lineTo(box.x + box.w + 4, py);
    ctx.stroke();
    ctx.fillText(fmt(t), box.x + box.w + 6, py);
  }
  if (label) {
    ctx.textAlign = 'center';
    ctx.textBaseline = 'bottom';
    ctx.fillText(label, box.x + box.w / 2, box.y - 6);
  }
  ctx.restore();
}
