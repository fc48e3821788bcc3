// Biome tints of the vertex colours, by biome name: the tiles' biome weights are in the order of
// the world's biomes, which the v2 stream's `hello` names (`biomes`; the `bin` tile carries only
// their count). The default world's generator, `earth-1`, has six (ice, tundra, taiga, temperate,
// steppe, desert), a `classic` world four (arctic, tundra, grassland, desert); a world's scene
// may name its own, which get the neutral tint.
import * as THREE from "three";

/** sRGB tints of the biome names the server's generators use. */
const BY_NAME: Record<string, [number, number, number]> = {
  ice: [0.88, 0.92, 0.97],
  arctic: [0.88, 0.92, 0.97],
  tundra: [0.52, 0.56, 0.4],
  taiga: [0.26, 0.42, 0.24],
  grassland: [0.3, 0.52, 0.2],
  temperate: [0.32, 0.5, 0.2],
  steppe: [0.64, 0.6, 0.36],
  desert: [0.88, 0.68, 0.4],
};

/** The tint of a biome this table does not know: a mid green-brown, no biome's colour. */
const NEUTRAL: [number, number, number] = [0.5, 0.5, 0.36];

/** The biomes a stream assumes before its `hello` names them: the default world's. */
export const DEFAULT_BIOMES = ["ice", "tundra", "taiga", "temperate", "steppe", "desert"];

const neutral = new THREE.Color().setRGB(NEUTRAL[0], NEUTRAL[1], NEUTRAL[2], THREE.SRGBColorSpace);

/** The tint of weight `b` of `tints`, the neutral one past their end (a tile of more biomes than
 * the stream named). */
export function tintOf(tints: readonly THREE.Color[], b: number): THREE.Color {
  return tints[b] ?? neutral;
}

/** The tints (linear RGB) of `names`, index `b` for the tiles' weight `b`. */
export function biomeTints(names: readonly string[]): THREE.Color[] {
  return names.map((name) => {
    const [r, g, b] = BY_NAME[name] ?? NEUTRAL;
    return new THREE.Color().setRGB(r, g, b, THREE.SRGBColorSpace);
  });
}
