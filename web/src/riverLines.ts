// River centre lines of a tile (`api/rivers_v1.md`): the JSON's types, a reader that checks it,
// and a paced loader that fetches one tile's lines at a time per slot and keeps them by URL.

/** One river line: centre-line points from upstream to downstream and the width at each point. */
export interface RiverLine {
  /** World `[x, z, water level]` in metres, upstream first. */
  points: [number, number, number][];
  /** Channel width at each point, metres (as many as `points`). */
  widths: number[];
  /** How the line ends: `sea`, `lake`, `river` or `continues`. */
  ends: string;
}

/** Reads a `strata.rivers.v1` body; throws on a body that is not one. */
export function parseRiverLines(doc: unknown): RiverLine[] {
  const d = doc as { format?: unknown; lines?: unknown };
  if (d?.format !== "strata.rivers.v1" || !Array.isArray(d.lines)) throw new Error("not a strata.rivers.v1 body");
  const out: RiverLine[] = [];
  for (const raw of d.lines as { points?: unknown; width_m?: unknown; ends?: unknown }[]) {
    if (!Array.isArray(raw?.points)) continue;
    const points = (raw.points as unknown[]).filter(
      (p): p is [number, number, number] =>
        Array.isArray(p) && p.length >= 3 && p.every((c) => typeof c === "number" && Number.isFinite(c)),
    );
    if (points.length < 2) continue;
    // One width per point; a missing or short list repeats its last width (or 1 m).
    const given = Array.isArray(raw.width_m) ? (raw.width_m as unknown[]) : [];
    const widths: number[] = [];
    let last = 1;
    for (let k = 0; k < points.length; k++) {
      const w = given[k];
      if (typeof w === "number" && Number.isFinite(w) && w > 0) last = w;
      widths.push(last);
    }
    out.push({ points, widths, ends: typeof raw.ends === "string" ? raw.ends : "continues" });
  }
  return out;
}

interface Job {
  url: string;
  priority: number;
}

/**
 * Fetches river-line bodies with at most `slots` requests open at once, so a slow connection
 * slows the loading down instead of queueing hundreds of requests in the browser. Bodies are kept
 * by URL until `forget(url)`; a URL asked for again while it is queued or in flight is not fetched
 * twice. `wanted(url)` is asked before each request starts, so URLs nobody needs any more are
 * skipped rather than fetched.
 */
export class RiverLoader {
  private readonly cache = new Map<string, RiverLine[]>();
  private readonly queue: Job[] = [];
  private readonly queued = new Set<string>();
  private readonly inFlight = new Set<string>();

  constructor(
    private readonly slots: number,
    private readonly headers: Record<string, string>,
    private readonly wanted: (url: string) => boolean,
    private readonly onLoad: (url: string, lines: RiverLine[]) => void,
    private readonly onError: (message: string) => void,
  ) {}

  /** Requests left: queued or in flight. */
  get pending(): number {
    return this.queue.length + this.inFlight.size;
  }

  /** The lines of `url` when they have arrived. */
  get(url: string): RiverLine[] | undefined {
    return this.cache.get(url);
  }

  /**
   * Asks for `url`: its lines when they are here already, else `undefined` and `onLoad` is called
   * once they arrive. Lower `priority` values are fetched first.
   */
  request(url: string, priority: number): RiverLine[] | undefined {
    const cached = this.cache.get(url);
    if (cached) return cached;
    if (this.inFlight.has(url)) return undefined;
    if (this.queued.has(url)) {
      for (const job of this.queue) if (job.url === url) job.priority = Math.min(job.priority, priority);
      return undefined;
    }
    this.queued.add(url);
    this.queue.push({ url, priority });
    this.pump();
    return undefined;
  }

  /** Drops the lines of `url` (its tile was freed); a queued request for it is skipped. */
  forget(url: string): void {
    this.cache.delete(url);
  }

  private pump(): void {
    while (this.inFlight.size < this.slots && this.queue.length > 0) {
      // The most urgent job first (the finest tiles, nearest the camera); ties keep their order.
      let best = 0;
      for (let i = 1; i < this.queue.length; i++) if (this.queue[i].priority < this.queue[best].priority) best = i;
      const [job] = this.queue.splice(best, 1);
      this.queued.delete(job.url);
      if (!this.wanted(job.url)) continue;
      this.inFlight.add(job.url);
      void this.load(job.url);
    }
  }

  private async load(url: string): Promise<void> {
    try {
      const r = await fetch(url, { headers: this.headers });
      if (!r.ok) throw new Error(`HTTP ${r.status}`);
      const lines = parseRiverLines(await r.json());
      // A tile freed while its request was open does not keep its lines.
      if (this.wanted(url)) {
        this.cache.set(url, lines);
        this.onLoad(url, lines);
      }
    } catch (e) {
      this.onError(`river lines ${new URL(url).pathname}: ${(e as Error).message}`);
    } finally {
      this.inFlight.delete(url);
      this.pump();
    }
  }
}
