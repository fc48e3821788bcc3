// Ptex pages of stream protocol v2 (frame kind 3, api/stream_protocol_v2.md "Ptex pages"; the
// planes of api/ptex_pages_v1.md), decoded without three.js so the decoding worker
// (./decode.worker.ts) can use it. Only the albedo plane is kept: the viewer lights the pages with
// the tiles' normals.

/** The pages of one kind-3 frame: one detail level, `count` pages of `res`² interior texels, all
 * of height-tile faces or all of volume-chunk faces. */
export interface PtexPages {
  /** Detail level: 0 vista (8²), 1…5 (16² … 256²). */
  level: number;
  /** Interior texels per side; a page is `S = res + 2` texels a side with its one-texel border. */
  res: number;
  count: number;
  /** Whether the faces are volume chunks' quads (else height tiles' faces). */
  chunk: boolean;
  /** Per page: the face's LOD (a chunk face: its chunk's), its slot in the level's texture array,
   * its face column and row (a chunk face: its chunk's x and z). */
  lod: Uint32Array;
  slot: Uint32Array;
  fx: Float64Array;
  fz: Float64Array;
  /** Per page of a chunk face: its chunk's y and its quad's index (zeros for tile faces). */
  y: Int32Array;
  quad: Uint32Array;
  /** Per page in record order, `S²` texels of sRGB R, G, B and linear roughness (4 bytes each). */
  albedo: Uint8Array;
}

const RECORD_BYTES = 48;

/** The payload of a kind-3 frame whose header gave `level`, `res`, `count` and the kind of its
 * faces, `faces` (0 tiles', 1 chunks'). */
export function decodePtex(p: DataView, level: number, res: number, count: number, faces: number): PtexPages {
  if (faces !== 0 && faces !== 1) throw new Error(`Ptex frame of unknown faces ${faces}`);
  if (level > 5 || res !== 8 << level) throw new Error(`Ptex frame of level ${level} with pages of ${res}²`);
  const s = res + 2;
  const page = 12 * s * s;
  if (count < 0 || p.byteLength !== count * (RECORD_BYTES + page)) throw new Error("Ptex frame of the wrong length");
  const out: PtexPages = {
    level,
    res,
    count,
    chunk: faces === 1,
    lod: new Uint32Array(count),
    slot: new Uint32Array(count),
    fx: new Float64Array(count),
    fz: new Float64Array(count),
    y: new Int32Array(count),
    quad: new Uint32Array(count),
    albedo: new Uint8Array(count * s * s * 4),
  };
  for (let k = 0; k < count; k++) {
    const at = k * RECORD_BYTES;
    out.lod[k] = p.getUint32(at, true);
    out.slot[k] = p.getUint32(at + 4, true);
    out.fx[k] = Number(p.getBigInt64(at + 8, true));
    out.fz[k] = Number(p.getBigInt64(at + 16, true));
    if (out.chunk) {
      out.y[k] = p.getInt32(at + 24, true);
      out.quad[k] = p.getUint32(at + 44, true);
    }
    const plane = p.byteOffset + count * RECORD_BYTES + k * page;
    out.albedo.set(new Uint8Array(p.buffer, plane, s * s * 4), k * s * s * 4);
  }
  return out;
}
