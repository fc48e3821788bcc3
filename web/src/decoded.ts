// What the decoding worker (./decode.worker.ts) sends back for each stream message.
import type { Chunk } from "./chunkFormat";
import type { Tile } from "./frame";

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
  | { type: "text"; text: string }
  | ({ type: "tile"; tile: Tile } & FrameHead)
  | ({ type: "chunk"; chunk: Chunk } & FrameHead)
  | ({ type: "other" } & FrameHead)
  | { type: "error"; message: string };
