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

/** The luminance (Rec. 709 weights, 0…255) of each pixel of a decoded PNG. */
export function luminance(img) {
  const { width: w, height: h, data } = img;
  const lum = new Float32Array(w * h);
  for (let p = 0; p < w * h; p++) lum[p] = 0.2126 * data[4 * p] + 0.7152 * data[4 * p + 1] + 0.0722 * data[4 * p + 2];
  return lum;
}

/** Texture detail of a decoded PNG: the mean |Laplacian| of its luminance (the 4-neighbour
 * kernel `4c − n − s − e − w`) over the pixels from row `top` down (below the horizon), the
 * image's border excluded, and, given a `mask` (one byte a pixel), over the pixels whose four
 * neighbours and themselves are all in it (no edge of the masked area counts); 0 when no pixel
 * is left. Smooth shading (vertex colours, lighting by interpolated normals) has little of it;
 * an albedo that varies from texel to texel has much. */
export function meanAbsLaplacian(img, top, mask) {
  const { width: w, height: h } = img;
  const lum = luminance(img);
  const inside = (p) => !mask || (mask[p] && mask[p - 1] && mask[p + 1] && mask[p - w] && mask[p + w]);
  let sum = 0;
  let n = 0;
  for (let y = Math.max(1, top); y < h - 1; y++) {
    for (let x = 1; x < w - 1; x++) {
      const p = y * w + x;
      if (!inside(p)) continue;
      sum += Math.abs(4 * lum[p] - lum[p - 1] - lum[p + 1] - lum[p - w] - lum[p + w]);
      n++;
    }
  }
  return n ? sum / n : 0;
}

/** Mean |Δ| per RGB channel of two decoded PNGs of the same size over the pixels of `mask` (one
 * byte a pixel); 0 when the mask is empty. */
export function meanRgbDiffIn(a, b, mask) {
  let sum = 0;
  let n = 0;
  for (let p = 0; p < mask.length; p++) {
    if (!mask[p]) continue;
    for (let c = 0; c < 3; c++) sum += Math.abs(a.data[4 * p + c] - b.data[4 * p + c]);
    n += 3;
  }
  return n ? sum / n : 0;
}

/** The pixels where two decoded PNGs of the same size differ in luminance by more than `min`
 * (one byte a pixel, 1 where they do): with a picture and the same picture without some
 * objects, the objects' pixels. */
export function differingPixels(a, b, min) {
  const la = luminance(a);
  const lb = luminance(b);
  const mask = new Uint8Array(la.length);
  for (let p = 0; p < la.length; p++) mask[p] = Math.abs(la[p] - lb[p]) > min ? 1 : 0;
  return mask;
}
