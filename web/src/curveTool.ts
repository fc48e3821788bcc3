// The curve tool: the control points of the world's volume regions' feature curves (Becher et al.
// §3; the `volumes` scene element, api/scene.schema.json) shown as handles, picked and dragged,
// and committed through the scene API: `PUT /v1/worlds/{id}/volumes/{vid}/curves.json` with
// `If-Match` the version the curves were read at (a concurrent edit is 409 and the curves are read
// again). The server re-solves the region and the stream re-sends the chunks the edit touched.
//
// A drag moves the point on the horizontal plane through it (x and z); with Shift held, up and
// down (its height, read on the vertical plane through it that faces the camera). The coordinates
// the drag does not move keep the scene's values exactly. The handles are drawn over everything (a
// control point may lie inside the solid), a constant size on screen, and each curve's control
// polygon as a line.
import * as THREE from "three";

/** One control point's handle: where it is in the scene and whose it is. */
interface Handle {
  mesh: THREE.Mesh;
  volume: string;
  curve: number;
  point: number;
}

/** A volume region's curves as the scene holds them (the JSON of `curves.json`). */
interface Volume {
  id: string;
  curves: { control_points: number[][] }[];
  line: THREE.Group;
}

/** A handle on the screen, for tests: CSS pixels, and the point in metres. */
export interface HandleOnScreen {
  volume: string;
  curve: number;
  point: number;
  x: number;
  y: number;
  position: number[];
}

/** What the tool needs from the page. */
export interface CurveToolHost {
  scene: THREE.Scene;
  camera: THREE.PerspectiveCamera;
  /** The world's API base, e.g. `/v1/worlds/ID`, absolute. */
  worldUrl: string;
  headers: Record<string, string>;
  showError: (text: string) => void;
  setStatus: (text: string) => void;
}

/** A handle's radius on the screen, pixels. */
const HANDLE_PX = 7;
const HANDLE_COLOUR = 0xff8c1a;
const PICKED_COLOUR = 0xfff066;

const round = (v: number) => Math.round(v * 100) / 100;

export class CurveTool {
  private readonly host: CurveToolHost;
  private readonly group = new THREE.Group();
  private readonly geometry = new THREE.SphereGeometry(1, 12, 8);
  private readonly material = new THREE.MeshBasicMaterial({ color: HANDLE_COLOUR, depthTest: false, transparent: true });
  private readonly picked = new THREE.MeshBasicMaterial({ color: PICKED_COLOUR, depthTest: false, transparent: true });
  private readonly lineMaterial = new THREE.LineBasicMaterial({ color: HANDLE_COLOUR, depthTest: false, transparent: true, opacity: 0.7 });
  private readonly raycaster = new THREE.Raycaster();
  private handles: Handle[] = [];
  private volumes = new Map<string, Volume>();
  /** The world version the curves were read at, quoted as `If-Match` takes it. */
  private etag = "";
  private drag:
    | {
        handle: Handle;
        plane: THREE.Plane;
        from: THREE.Vector3;
        offset: THREE.Vector3;
        /** Whether the drag moves the height (Shift) rather than x and z. */
        vertical: boolean;
        /** The control point as the scene holds it before the drag. */
        original: number[];
      }
    | undefined;

  /** Whether a commit is awaiting the server's answer. */
  private busy = false;
  /** Curve edits the server accepted. */
  commits = 0;
  /** Whether a drag is under way (the orbit controls stay still meanwhile). */
  get dragging(): boolean {
    return this.drag !== undefined;
  }

  constructor(host: CurveToolHost) {
    this.host = host;
    this.group.name = "curve-handles";
    this.group.visible = false;
    this.group.renderOrder = 10;
    host.scene.add(this.group);
  }

  /** The handles shown. */
  get count(): number {
    return this.group.visible ? this.handles.length : 0;
  }

  /** Shows the handles (reading the curves afresh) or hides them. */
  async show(on: boolean): Promise<void> {
    this.group.visible = on;
    this.drag = undefined;
    if (on) await this.load();
  }

  /** Reads the world's volume regions and their curves at the head version. */
  async load(): Promise<void> {
    const { worldUrl, headers } = this.host;
    try {
      const r = await fetch(worldUrl, { headers });
      if (!r.ok) throw new Error(`GET world: HTTP ${r.status}`);
      const doc = await r.json();
      const ids: string[] = (doc?.scene?.volumes ?? []).map((v: { id: string }) => v.id);
      const read = await Promise.all(
        ids.map(async (id) => {
          const c = await fetch(`${worldUrl}/volumes/${encodeURIComponent(id)}/curves.json`, { headers });
          if (!c.ok) throw new Error(`GET curves of ${id}: HTTP ${c.status}`);
          // The version header, not the ETag: a gzip-compressed answer's ETag is `"N-gzip"`,
          // which If-Match does not take.
          return { id, etag: `"${c.headers.get("x-strata-version") ?? ""}"`, curves: (await c.json()).curves ?? [] };
        }),
      );
      // Every read is of the head; keep the oldest version, so a commit never skips an edit.
      const etags = read.map((v) => v.etag).sort((a, b) => Number(a.replace(/"/g, "")) - Number(b.replace(/"/g, "")));
      this.etag = etags[0] && etags[0] !== '""' ? etags[0] : "";
      this.rebuild(read);
      this.host.setStatus(
        ids.length ? `curve: ${this.handles.length} control points · drag one (Shift: up/down)` : "curve: this world has no volume regions",
      );
    } catch (e) {
      this.host.showError(`curve tool: ${(e as Error).message}`);
    }
  }

  private rebuild(read: { id: string; curves: { control_points: number[][] }[] }[]): void {
    for (const h of this.handles) this.group.remove(h.mesh);
    for (const v of this.volumes.values()) {
      this.group.remove(v.line);
      for (const l of v.line.children) (l as THREE.Line).geometry.dispose();
    }
    this.handles = [];
    this.volumes.clear();
    for (const { id, curves } of read) {
      const line = new THREE.Group();
      const volume: Volume = { id, curves, line };
      curves.forEach((c, ci) => {
        const geo = new THREE.BufferGeometry().setFromPoints(c.control_points.map((p) => new THREE.Vector3(p[0], p[1], p[2])));
        const l = new THREE.Line(geo, this.lineMaterial);
        l.renderOrder = 10;
        line.add(l);
        c.control_points.forEach((p, pi) => {
          const mesh = new THREE.Mesh(this.geometry, this.material);
          mesh.position.set(p[0], p[1], p[2]);
          mesh.renderOrder = 11;
          this.group.add(mesh);
          this.handles.push({ mesh, volume: id, curve: ci, point: pi });
        });
      });
      this.group.add(line);
      this.volumes.set(id, volume);
    }
  }

  /** Keeps the handles `HANDLE_PX` pixels in radius on a `height`-pixel picture (call each frame). */
  update(height: number): void {
    if (!this.group.visible) return;
    const cam = this.host.camera;
    const perPixel = (2 * Math.tan(THREE.MathUtils.degToRad(cam.fov / 2))) / height;
    for (const h of this.handles) {
      h.mesh.scale.setScalar(HANDLE_PX * perPixel * cam.position.distanceTo(h.mesh.position));
    }
  }

  /** The handles on the screen of a `width` × `height` picture (tests aim the mouse with it). */
  onScreen(width: number, height: number): HandleOnScreen[] {
    return this.handles.map((h) => {
      const p = h.mesh.position.clone().project(this.host.camera);
      return {
        volume: h.volume,
        curve: h.curve,
        point: h.point,
        x: ((p.x + 1) / 2) * width,
        y: ((1 - p.y) / 2) * height,
        position: h.mesh.position.toArray(),
      };
    });
  }

  /** Starts a drag if `ndc` (normalised device coordinates) lies on a handle; whether it did. */
  down(ndc: THREE.Vector2, vertical: boolean): boolean {
    if (!this.group.visible) return false;
    this.raycaster.setFromCamera(ndc, this.host.camera);
    const hit = this.raycaster.intersectObjects(
      this.handles.map((h) => h.mesh),
      false,
    )[0];
    const handle = hit && this.handles.find((h) => h.mesh === hit.object);
    if (!handle) return false;
    const at = handle.mesh.position.clone();
    const normal = vertical
      ? this.host.camera.getWorldDirection(new THREE.Vector3()).setY(0).normalize()
      : new THREE.Vector3(0, 1, 0);
    if (normal.lengthSq() < 0.5) normal.set(0, 0, 1);
    const plane = new THREE.Plane().setFromNormalAndCoplanarPoint(normal, at);
    const start = this.raycaster.ray.intersectPlane(plane, new THREE.Vector3()) ?? at.clone();
    handle.mesh.material = this.picked;
    const original = [...(this.volumes.get(handle.volume)?.curves[handle.curve].control_points[handle.point] ?? at.toArray())];
    this.drag = { handle, plane, from: at, offset: at.clone().sub(start), vertical, original };
    return true;
  }

  /** Moves the dragged point under `ndc` on its plane. */
  move(ndc: THREE.Vector2): void {
    if (!this.drag) return;
    this.raycaster.setFromCamera(ndc, this.host.camera);
    const p = this.raycaster.ray.intersectPlane(this.drag.plane, new THREE.Vector3());
    if (!p) return;
    const { handle, from, vertical } = this.drag;
    p.add(this.drag.offset);
    // Only the coordinates the drag moves change (rounded to centimetres): x and z on the
    // horizontal plane, y on the vertical one.
    const at = vertical ? [from.x, round(p.y), from.z] : [round(p.x), from.y, round(p.z)];
    handle.mesh.position.set(at[0], at[1], at[2]);
    const original = this.drag.original;
    this.setPoint(handle, vertical ? [original[0], at[1], original[2]] : [at[0], original[1], at[2]]);
  }

  /** The stream announced world version `version`: the curves shown are read again if it is newer
   * than theirs (someone else edited) and no drag is under way. */
  onVersion(version: number): void {
    if (!this.group.visible || this.drag || this.busy) return;
    if (version > Number(this.etag.replace(/"/g, ""))) void this.load();
  }

  /** Ends the drag and commits the moved point; resolves when the server has answered. */
  async up(): Promise<void> {
    const drag = this.drag;
    this.drag = undefined;
    if (!drag) return;
    drag.handle.mesh.material = this.material;
    if (drag.handle.mesh.position.distanceTo(drag.from) < 0.01) return;
    await this.commit(drag.handle.volume);
  }

  /** Writes `p` as the handle's control point and redraws its curve's line. */
  private setPoint(h: Handle, p: number[]): void {
    const volume = this.volumes.get(h.volume);
    if (!volume) return;
    volume.curves[h.curve].control_points[h.point] = p;
    const line = volume.line.children[h.curve] as THREE.Line;
    const pos = line.geometry.getAttribute("position") as THREE.BufferAttribute;
    pos.setXYZ(h.point, p[0], p[1], p[2]);
    pos.needsUpdate = true;
  }

  private async commit(id: string): Promise<void> {
    const volume = this.volumes.get(id);
    if (!volume) return;
    this.busy = true;
    const { worldUrl, headers } = this.host;
    this.host.setStatus(`curve: saving ${id}…`);
    try {
      const r = await fetch(`${worldUrl}/volumes/${encodeURIComponent(id)}/curves.json`, {
        method: "PUT",
        headers: { ...headers, "content-type": "application/json", ...(this.etag ? { "if-match": this.etag } : {}) },
        body: JSON.stringify({ curves: volume.curves }),
      });
      const answer = await r.json().catch(() => undefined);
      if (!r.ok) {
        const e = answer?.error;
        throw new Error(e ? `${e.code}: ${e.message}${e.field ? ` (field ${e.field})` : ""}` : `HTTP ${r.status}`);
      }
      this.etag = `"${answer.version}"`;
      this.commits++;
      this.host.setStatus(`curve: ${id} saved as version ${answer.version}`);
    } catch (e) {
      this.host.showError(`curve edit refused: ${(e as Error).message}; the curves are read again`);
      await this.load();
    } finally {
      this.busy = false;
    }
  }
}
