// The web walkthrough's view of the canvas (walkthrough.test.mjs): its pixels reduced to a grid
// of block-mean luminances, the mean difference of two such grids, and its raw sRGB codes.

import assert from 'node:assert/strict';

// The canvas's pixels reduced to a grid of block-mean luminances: blocks average away most of
// the Monte Carlo noise, so comparing two grids tells a changed view from a refined one.
export async function canvasBlocks(p, cols = 16, rows = 12) {
  return p.evaluate(
    ([cols, rows]) => {
      const c = document.getElementById('view');
      const { data, width, height } = c.getContext('2d').getImageData(0, 0, c.width, c.height);
      const sums = new Float64Array(cols * rows);
      const counts = new Float64Array(cols * rows);
      let max = 0;
      for (let y = 0; y < height; y++) {
        for (let x = 0; x < width; x++) {
          const i = 4 * (y * width + x);
          const lum = 0.2126 * data[i] + 0.7152 * data[i + 1] + 0.0722 * data[i + 2];
          const b = Math.floor((y * rows) / height) * cols + Math.floor((x * cols) / width);
          sums[b] += lum;
          counts[b] += 1;
          max = Math.max(max, lum);
        }
      }
      return { blocks: Array.from(sums, (s, b) => s / counts[b]), max, width, height };
    },
    [cols, rows],
  );
}

export function meanAbsDiff(a, b) {
  assert.equal(a.blocks.length, b.blocks.length);
  return a.blocks.reduce((s, v, i) => s + Math.abs(v - b.blocks[i]), 0) / a.blocks.length;
}

// The canvas's RGB codes, and sRGB codes to linear values and back.
export const canvasCodes = (p) =>
  p.evaluate(() => {
    const c = document.getElementById('view');
    const { data } = c.getContext('2d').getImageData(0, 0, c.width, c.height);
    return Array.from(data).filter((_, i) => i % 4 !== 3);
  });
export const toLinear = (code) => {
  const s = code / 255;
  return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
};
export const toCode = (v) => {
  const c = Math.min(1, Math.max(0, v));
  return 255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055);
};
