// The stream worker: it holds the WebSocket and decodes what arrives, so neither reading the socket
// nor decoding tiles, chunks and Ptex pages waits on the main thread, which renders (a frame of the
// software renderer of headless Chromium takes most of a second, and a socket the page reads
// between frames takes a 1 MB Ptex frame too slowly for the server's 10 s write limit). A binary
// frame goes to the main thread decoded (its typed arrays transferred, not copied), a text message
// as it came, both in arrival order; so do the socket's opening and closing. The main thread asks
// for a connection and sends its messages (views, credits, edits) through the worker.
import { decodeChunk } from "./chunkFormat";
import { decodeFrame, decodeTile, KIND_CHUNK, KIND_PTEX, KIND_TILE } from "./frame";
import type { Decoded, ToWorker } from "./decoded";
import { decodePtex } from "./ptexFormat";

const post = (m: Decoded, transfer: Transferable[] = []) =>
  (self as unknown as { postMessage: (m: Decoded, t: Transferable[]) => void }).postMessage(m, transfer);

let socket: WebSocket | undefined;

function decode(data: ArrayBuffer): void {
  try {
    const frame = decodeFrame(data);
    const head = { kind: frame.kind, lod: frame.lod, x: frame.x, y: frame.y, z: frame.z, version: frame.version };
    if (frame.format !== 2) throw new Error(`unexpected payload format ${frame.format}`);
    if (frame.kind === KIND_TILE) {
      const tile = decodeTile(frame.payload);
      const arrays = [tile.heights, tile.normals, tile.weights, tile.materials, tile.waterDepth, tile.waterKind, tile.volumeOverride];
      post({ type: "tile", ...head, tile }, arrays.map((a) => a.buffer));
    } else if (frame.kind === KIND_CHUNK) {
      const chunk = decodeChunk(frame.payload);
      const arrays = [chunk.positions, chunk.normals, chunk.materials, chunk.quads, chunk.skirtPositions, chunk.skirtQuads];
      post({ type: "chunk", ...head, chunk }, arrays.map((a) => a.buffer));
    } else if (frame.kind === KIND_PTEX) {
      const pages = decodePtex(frame.payload, frame.lod, frame.x, frame.z, frame.faces);
      const arrays = [pages.lod, pages.slot, pages.fx, pages.fz, pages.y, pages.quad, pages.albedo];
      post({ type: "ptex", ...head, pages }, arrays.map((a) => a.buffer));
    } else {
      post({ type: "other", ...head });
    }
  } catch (e) {
    post({ type: "error", message: (e as Error).message });
  }
}

/** Opens the stream at `url`, dropping the socket before it (whose events are then ignored). */
function connect(url: string): void {
  if (socket) {
    socket.onopen = socket.onmessage = socket.onclose = null;
    socket.close();
  }
  const ws = new WebSocket(url);
  ws.binaryType = "arraybuffer";
  socket = ws;
  ws.onopen = () => post({ type: "open" });
  ws.onmessage = (ev) => {
    if (typeof ev.data === "string") post({ type: "text", text: ev.data });
    else decode(ev.data as ArrayBuffer);
  };
  ws.onclose = (ev) => {
    if (socket !== ws) return;
    socket = undefined;
    post({ type: "closed", code: ev.code, reason: ev.reason });
  };
}

self.onmessage = (ev: MessageEvent<ToWorker>) => {
  const m = ev.data;
  if (m.op === "connect") connect(m.url);
  else if (socket && socket.readyState === WebSocket.OPEN) socket.send(m.text);
};
