// The decoding worker: stream messages go through it in order, so decoding tiles and chunks never
// holds the main thread (which renders and reads the socket). A binary frame comes back decoded
// (its typed arrays transferred, not copied), a text message as it came, both in arrival order.
import { decodeChunk } from "./chunkFormat";
import { decodeFrame, decodeTile, KIND_CHUNK, KIND_TILE } from "./frame";
import type { Decoded } from "./decoded";

const post = (m: Decoded, transfer: Transferable[] = []) =>
  (self as unknown as { postMessage: (m: Decoded, t: Transferable[]) => void }).postMessage(m, transfer);

self.onmessage = (ev: MessageEvent<string | ArrayBuffer>) => {
  if (typeof ev.data === "string") {
    post({ type: "text", text: ev.data });
    return;
  }
  try {
    const frame = decodeFrame(ev.data);
    const head = { kind: frame.kind, lod: frame.lod, x: frame.x, y: frame.y, z: frame.z, version: frame.version };
    if (frame.format !== 2) throw new Error(`unexpected payload format ${frame.format}`);
    if (frame.kind === KIND_TILE) {
      const tile = decodeTile(frame.payload);
      const arrays = [tile.heights, tile.normals, tile.weights, tile.materials, tile.waterDepth, tile.volumeOverride];
      post({ type: "tile", ...head, tile }, arrays.map((a) => a.buffer));
    } else if (frame.kind === KIND_CHUNK) {
      const chunk = decodeChunk(frame.payload);
      const arrays = [chunk.positions, chunk.normals, chunk.materials, chunk.quads, chunk.skirtPositions, chunk.skirtQuads];
      post({ type: "chunk", ...head, chunk }, arrays.map((a) => a.buffer));
    } else {
      post({ type: "other", ...head });
    }
  } catch (e) {
    post({ type: "error", message: (e as Error).message });
  }
};
