// Convergence read-out: samples per second, samples per pixel, time since the last reset, the
// server's estimated relative RMS error, and a log-log plot of error against time. Monte Carlo
// error falls as 1/sqrt(samples), so on log-log axes a healthy render is a line of slope -1/2;
// the plot draws that slope as a faint guide through the first point to make stalls visible.

const MAX_POINTS = 2000; // a long still render sends many frames; keep the plot cheap

function formatRate(perSecond) {
  if (!Number.isFinite(perSecond)) return '–';
  if (perSecond >= 1e9) return `${(perSecond / 1e9).toFixed(2)} G`;
  if (perSecond >= 1e6) return `${(perSecond / 1e6).toFixed(2)} M`;
  if (perSecond >= 1e3) return `${(perSecond / 1e3).toFixed(1)} k`;
  return perSecond.toFixed(0);
}

function formatSeconds(s) {
  if (!Number.isFinite(s)) return '–';
  if (s < 60) return `${s.toFixed(1)} s`;
  const m = Math.floor(s / 60);
  return `${m} min ${Math.round(s - 60 * m)} s`;
}

export class Stats {
  // fields: { rate, spp, elapsed, error, nonFinite, truncated, mode } elements to fill; plot: a
  // canvas.
  constructor(fields, plot) {
    this.fields = fields;
    this.plot = plot;
    this.points = []; // [elapsed, error] since the last reset
    this.last = null; // the previous frame message
    this.reset();
  }

  // A new scene or a move: the server restarted accumulation, and the old curve means nothing.
  reset() {
    this.points = [];
    this.last = null;
    this.fields.rate.textContent = '–';
    this.fields.spp.textContent = '0';
    this.fields.elapsed.textContent = '–';
    this.fields.error.textContent = '–';
    this.fields.mode.textContent = '';
    this.draw();
  }

  update(frame) {
    // The server resets accumulation on every move, setting and scene; seeing time or samples
    // go backwards is how we notice, whoever caused it.
    if (this.last && (frame.elapsed < this.last.elapsed || frame.spp < this.last.spp)) this.reset();
    this.last = frame;

    // Pixel samples per second since the reset (frames may be reduced-resolution while moving).
    const rate = frame.elapsed > 0 ? (frame.spp * frame.width * frame.height) / frame.elapsed : NaN;
    this.fields.rate.textContent = `${formatRate(rate)}samples/s`;
    this.fields.spp.textContent = String(frame.spp);
    this.fields.elapsed.textContent = formatSeconds(frame.elapsed);
    const hasError = typeof frame.error === 'number' && Number.isFinite(frame.error);
    this.fields.error.textContent = hasError ? `${(100 * frame.error).toPrecision(3)} %` : '–';
    this.fields.mode.textContent = frame.moving ? 'moving: preview resolution' : '';
    // Counted since the scene was loaded: moves do not reset them.
    this.fields.nonFinite.textContent = String(frame.non_finite_samples ?? 0);
    this.fields.truncated.textContent = String(frame.truncated_geodesics ?? 0);

    if (hasError && frame.error > 0 && frame.elapsed > 0) {
      this.points.push([frame.elapsed, frame.error]);
      // Thin out evenly rather than drop the start: the early points set the slope.
      if (this.points.length > MAX_POINTS) this.points = this.points.filter((_, i) => i % 2 === 0);
      this.draw();
    }
  }

  draw() {
    const canvas = this.plot;
    const ctx = canvas.getContext('2d');
    const w = canvas.width;
    const h = canvas.height;
    const pad = { left: 34, right: 14, top: 6, bottom: 18 }; // right: room for the last time label
    const style = getComputedStyle(canvas);
    const ink = style.getPropertyValue('--plot-ink').trim() || '#ccc';
    const line = style.getPropertyValue('--plot-line').trim() || '#6cf';
    const grid = style.getPropertyValue('--plot-grid').trim() || '#444';
    ctx.clearRect(0, 0, w, h);
    ctx.font = '10px system-ui, sans-serif';
    ctx.fillStyle = ink;

    if (this.points.length < 2) {
      ctx.textAlign = 'center';
      ctx.fillText('error vs time (log-log)', w / 2, h / 2);
      return;
    }

    // Axes span whole decades, so the grid lines fall on 10^k and the slope reads true.
    const lx = this.points.map(([t]) => Math.log10(t));
    const ly = this.points.map(([, e]) => Math.log10(e));
    const x0 = Math.floor(Math.min(...lx));
    const x1 = Math.max(Math.ceil(Math.max(...lx)), x0 + 1);
    const y0 = Math.floor(Math.min(...ly));
    const y1 = Math.max(Math.ceil(Math.max(...ly)), y0 + 1);
    const px = (v) => pad.left + ((v - x0) / (x1 - x0)) * (w - pad.left - pad.right);
    const py = (v) => h - pad.bottom - ((v - y0) / (y1 - y0)) * (h - pad.top - pad.bottom);

    ctx.strokeStyle = grid;
    ctx.lineWidth = 1;
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (let k = y0; k <= y1; k++) {
      ctx.beginPath();
      ctx.moveTo(pad.left, py(k));
      ctx.lineTo(w - pad.right, py(k));
      ctx.stroke();
      ctx.fillText(`${+(100 * 10 ** k).toPrecision(1)}%`, pad.left - 3, py(k));
    }
    ctx.textAlign = 'center';
    ctx.textBaseline = 'alphabetic';
    for (let k = x0; k <= x1; k++) {
      ctx.beginPath();
      ctx.moveTo(px(k), pad.top);
      ctx.lineTo(px(k), h - pad.bottom);
      ctx.stroke();
      ctx.fillText(`${+(10 ** k).toPrecision(1)}s`, px(k), h - 5);
    }

    // The -1/2 guide through the first point.
    ctx.save();
    ctx.beginPath();
    ctx.rect(pad.left, pad.top, w - pad.left - pad.right, h - pad.top - pad.bottom);
    ctx.clip();
    ctx.setLineDash([3, 3]);
    ctx.strokeStyle = ink;
    ctx.globalAlpha = 0.5;
    ctx.beginPath();
    ctx.moveTo(px(lx[0]), py(ly[0]));
    ctx.lineTo(px(x1), py(ly[0] - 0.5 * (x1 - lx[0])));
    ctx.stroke();
    ctx.restore();

    ctx.strokeStyle = line;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    lx.forEach((x, i) => (i === 0 ? ctx.moveTo(px(x), py(ly[i])) : ctx.lineTo(px(x), py(ly[i]))));
    ctx.stroke();
  }
}
