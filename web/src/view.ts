// Which tiles a view holds: a port of `src/stream/view.rs` (`select`), so the client knows which
// meshes to free when the server accepts a new view (its reply only gives counts).

export interface ViewTile {
  lod: number;
  x: number;
  z: number;
}

export const tileKey = (lod: number, x: number, z: number): string => `${lod}/${x}/${z}`;

const MAX_LEVELS = 13;
const MAX_RINGS_PER_LEVEL = 16;

export interface Square {
  x0: number;
  z0: number;
  x1: number;
  z1: number;
}

const divEuclid2 = (v: number): number => Math.floor(v / 2);
const remEuclid2 = (v: number): number => v - 2 * Math.floor(v / 2);

/** The squares of tile indices a view holds at each LOD, finest first, as the server selects them. */
function viewSquares(xM: number, zM: number, rings: number[], cellM: number): Square[] {
  const levels = Math.min(rings.length, MAX_LEVELS);
  const squares: Square[] = [];
  for (let l = 0; l < levels; l++) {
    const size = 64 * cellM * 2 ** l;
    const r = Math.min(rings[l], MAX_RINGS_PER_LEVEL);
    const inner = squares[squares.length - 1];
    const sq: Square = inner
      ? {
          x0: divEuclid2(inner.x0) - r,
          z0: divEuclid2(inner.z0) - r,
          x1: divEuclid2(inner.x1) + r,
          z1: divEuclid2(inner.z1) + r,
        }
      : (() => {
          const cx = Math.floor(xM / size);
          const cz = Math.floor(zM / size);
          return { x0: cx - r, z0: cz - r, x1: cx + r, z1: cz + r };
        })();
    const aligned: Square = {
      x0: sq.x0 - remEuclid2(sq.x0),
      z0: sq.z0 - remEuclid2(sq.z0),
      x1: sq.x1 + 1 - remEuclid2(sq.x1),
      z1: sq.z1 + 1 - remEuclid2(sq.z1),
    };
    squares.push(l + 1 < levels ? aligned : sq);
  }
  return squares;
}

/**
 * The ground a view at `(x, z)` metres with `rings` covers: its coarsest square, in metres
 * (`x1`, `z1` exclusive). Beyond it nothing is drawn, so the fog must be complete at its edge.
 */
export function viewExtentM(xM: number, zM: number, rings: number[], cellM: number): Square {
  const squares = viewSquares(xM, zM, rings, cellM);
  const l = squares.length - 1;
  if (l < 0) return { x0: xM, z0: zM, x1: xM, z1: zM };
  const size = 64 * cellM * 2 ** l;
  const sq = squares[l];
  return { x0: sq.x0 * size, z0: sq.z0 * size, x1: (sq.x1 + 1) * size, z1: (sq.z1 + 1) * size };
}

/** The keys of the tiles of a view at `(x, z)` metres with `rings`, as the server selects them. */
export function selectView(xM: number, zM: number, rings: number[], cellM: number): Set<string> {
  const squares = viewSquares(xM, zM, rings, cellM);
  const out = new Set<string>();
  squares.forEach((sq, l) => {
    for (let z = sq.z0; z <= sq.z1; z++) {
      for (let x = sq.x0; x <= sq.x1; x++) {
        if (l > 0) {
          const inner = squares[l - 1];
          const cx = 2 * x;
          const cz = 2 * z;
          if (cx >= inner.x0 && cx <= inner.x1 && cz >= inner.z0 && cz <= inner.z1) continue;
        }
        out.add(tileKey(l, x, z));
      }
    }
  });
  return out;
}
