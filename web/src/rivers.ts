// The river layer: for each held tile at a LOD the server carves rivers at, river lines are
// fetched (paced, by URL) and drawn as ribbons under the tile's mesh, and the water sheet's
// river squares they replace are left out. A tile replaced by a fresh frame gets its ribbons
// again from the new heights (and new lines when its URL changed, as after an edit); the lines
// of a URL go once no held tile uses them.
//
// The lines of a tile finer than SOURCE_LOD come from the tile of SOURCE_LOD that holds it (the
// lines do not depend on the LOD, only on the square asked for) and are cut to the fine tile's
// square. One request then serves a whole patch of fine tiles, and it works around the server's
// choice of lines: it keeps a river edge when one of its points (five or nine an edge) lies near
// the tile, so a tile smaller than an edge's pieces (about 250 or 125 m) that a piece crosses
// without a point inside gets no line for it, which left gaps in the ribbons on LOD 0–2 tiles.
import * as THREE from "three";
import type { Tile } from "./frame";
import { setWater, waterMaterial } from "./water";
import { buildRibbons } from "./ribbon";
import { RiverLoader, type RiverLine } from "./riverLines";
import { riverVertices } from "./riverMask";

/**
 * Requests for river lines open at once: the rest wait, so a slow client is not flooded. Six, as
 * browsers open at most six HTTP/1.1 connections to a host: on a client whose frames take seconds
 * (software WebGL) each response waits for a gap between frames, and two slots took 150 s to load
 * the 38 source tiles of a 1,500 m view that six load in 40 s (the server spent 4 s of CPU on all).
 */
const SLOTS = 6;
/** The finest LOD whose river lines are fetched: 4096 m squares at 1 m cells. */
const SOURCE_LOD = 6;

/** The water's colour and translucency, drawn over the ground and the sheet without z-fighting. */
const ribbonMaterial = waterMaterial.clone();
ribbonMaterial.depthWrite = true; // a band overlapping itself at a bend is not darkened twice
ribbonMaterial.polygonOffset = true;
ribbonMaterial.polygonOffsetFactor = -2;
ribbonMaterial.polygonOffsetUnits = -4;

interface Entry {
  url: string; // "" until the layer is enabled
  mesh: THREE.Mesh;
  tile: Tile;
  version: number;
  count: number;
  length: number;
  aboveGround: number;
}

/** What the layer draws, for the HUD and the tests. */
export interface RiverStats {
  ribbons: number; // river lines drawn, counted once per tile they cross
  length: number; // their centre lines' total length inside the tiles, metres
  pending: number; // river-line requests queued or open
  tiles: number; // tiles whose lines have arrived
  aboveGround: number; // highest a ribbon lies above its tile's ground away from lakes and the sea, metres
}

export class RiverLayer {
  private readonly entries = new Map<string, Entry>();
  private readonly byUrl = new Map<string, Set<string>>(); // the held tiles each URL's lines serve
  private readonly loader: RiverLoader;
  private maxLod = -1;

  /**
   * `url(lod, x, z, version)` names the river lines of a tile at a world version; `headers` go with
   * each request (a world's token).
   */
  constructor(
    private readonly url: (lod: number, x: number, z: number, version: number) => string,
    headers: Record<string, string>,
    onError: (message: string) => void,
  ) {
    this.loader = new RiverLoader(SLOTS, headers, (u) => this.byUrl.has(u), (u, lines) => this.drawAll(u, lines), onError);
  }

  /** Starts drawing at LODs `0..=maxLod` (`/v1/info`'s `limits.max_river_lod`). */
  enable(maxLod: number): void {
    this.maxLod = maxLod;
    for (const [key, e] of this.entries) {
      this.release(key, e.url);
      e.url = this.sourceUrl(e.tile, e.version);
      this.request(key, e);
    }
  }

  /** The tile `key` now has `mesh` (a new frame of it at `version`). */
  put(key: string, mesh: THREE.Mesh, tile: Tile, version: number): void {
    const old = this.entries.get(key);
    const e: Entry = { url: this.sourceUrl(tile, version), mesh, tile, version, count: 0, length: 0, aboveGround: 0 };
    this.entries.set(key, e);
    if (old) this.release(key, old.url);
    this.request(key, e);
  }

  /** The tile `key` was freed: its lines go unless another tile uses them (its mesh, ribbons included, is disposed by the caller). */
  drop(key: string): void {
    const e = this.entries.get(key);
    if (!e) return;
    this.entries.delete(key);
    this.release(key, e.url);
  }

  stats(): RiverStats {
    let ribbons = 0;
    let length = 0;
    let tiles = 0;
    let aboveGround = 0;
    for (const e of this.entries.values()) {
      ribbons += e.count;
      length += e.length;
      aboveGround = Math.max(aboveGround, e.aboveGround);
      if (this.loader.get(e.url)) tiles++;
    }
    return { ribbons, length, pending: this.loader.pending, tiles, aboveGround };
  }

  /** The URL of the lines for `tile`: its own, or those of the SOURCE_LOD tile that holds it; "" above the carving LODs. */
  private sourceUrl(tile: Tile, version: number): string {
    if (tile.lod > this.maxLod) return "";
    const lod = Math.max(tile.lod, Math.min(SOURCE_LOD, this.maxLod));
    const f = 2 ** (lod - tile.lod);
    return this.url(lod, Math.floor(tile.x / f), Math.floor(tile.z / f), version);
  }

  private request(key: string, e: Entry): void {
    if (!e.url) return;
    let users = this.byUrl.get(e.url);
    if (!users) this.byUrl.set(e.url, (users = new Set()));
    users.add(key);
    // The finest tiles (nearest the camera) first.
    const lines = this.loader.request(e.url, e.tile.lod);
    if (lines) this.draw(e, lines);
  }

  /** Tile `key` no longer uses `url`; its lines are forgotten once no tile does. */
  private release(key: string, url: string): void {
    const users = this.byUrl.get(url);
    if (!users) return;
    if (this.entries.get(key)?.url !== url) users.delete(key);
    if (users.size > 0) return;
    this.byUrl.delete(url);
    this.loader.forget(url);
  }

  /** Draws the lines that arrived for `url` on every held tile that uses them. */
  private drawAll(url: string, lines: RiverLine[]): void {
    for (const key of this.byUrl.get(url) ?? []) {
      const e = this.entries.get(key);
      if (e && e.url === url) this.draw(e, lines);
    }
  }

  /** Draws `lines`, cut to the tile's square, as the ribbons of tile `e`. */
  private draw(e: Entry, lines: RiverLine[]): void {
    for (const child of [...e.mesh.children]) {
      if (child instanceof THREE.Mesh && child.name === "rivers") {
        e.mesh.remove(child);
        child.geometry.dispose();
      }
    }
    const r = buildRibbons(e.tile, lines);
    e.count = r.count;
    e.length = r.length;
    e.aboveGround = r.aboveGround;
    if (!r.geometry) return;
    setWater(e.mesh, e.tile, riverVertices(e.tile, lines));
    const ribbons = new THREE.Mesh(r.geometry, ribbonMaterial);
    ribbons.name = "rivers";
    ribbons.renderOrder = 2;
    ribbons.matrixAutoUpdate = false;
    ribbons.updateMatrix();
    e.mesh.add(ribbons);
  }
}
