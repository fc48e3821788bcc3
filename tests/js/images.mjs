// Picture comparisons shared by the viewer scripts.

/** Mean |Δ| per RGB channel of two decoded PNGs of the same size, over the rows from `top` down
 * (below the horizon); 0 when no row is left. */
export function meanRgbDiff(a, b, top) {
  let sum = 0;
  let n = 0;
  for (let y = top; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      const p = 4 * (y * a.width + x);
      for (let c = 0; c < 3; c++) sum += Math.abs(a.data[p + c] - b.data[p + c]);
      n += 3;
    }
  }
  return n ? sum / n : 0;
}
