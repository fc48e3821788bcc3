// What the stream worker (./decode.worker.ts) sends back for each stream message and socket event,
// and what the main thread asks of it.
import type { Chunk } from "./chunkFormat";
import type { Tile } from "./frame";
import type { PtexPages } from "./ptexFormat";

/** A frame's address and version. */
export interface FrameHead {
  kind: number;
  lod: number;
  x: number;
  y: number;
  z: number;
  version: number;
}

export type Decoded =
  | { type: "open" }
  | { type: "closed"; code: number; reason: string }
  | { type: "text"; text: string }
  | ({ type: "tile"; tile: Tile } & FrameHead)
  | ({ type: "chunk"; chunk: Chunk } & FrameHead)
  | ({ type: "ptex"; pages: PtexPages } & FrameHead)
  | ({ type: "other" } & FrameHead)
  | { type: "error"; message: string };

/** Open the stream at `url` (dropping the socket before), or send `text` on the open socket. */
export type ToWorker = { op: "connect"; url: string } | { op: "send"; text: string };
