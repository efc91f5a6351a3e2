// Draws a robot's or object's .obj model (fetched from its `mesh` URL) in place of its stand-in shapes.

import {
  Box3,
  BufferGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  Matrix4,
  Mesh,
  MeshStandardMaterial,
  Object3D,
  Vector3,
} from "three";
import { parseMeshBody, type MeshMessage } from "./protocol";
import { colorOf } from "./robot_model";

/** The models drawn in the current world, by the name of what they belong to ("robot 1", "object 2"). */
const drawn = new Map<string, Group>();
/** Bumped for every new world, so a model that arrives for an old one is dropped. */
let generation = 0;

export function forgetMeshes(): void {
  drawn.clear();
  generation += 1;
}

function partGeometry(part: MeshMessage["parts"][number]): BufferGeometry | null {
  const { vertices, triangles } = part;
  const count = vertices.length / 3;
  const valid =
    Array.isArray(vertices) &&
    Array.isArray(triangles) &&
    vertices.length % 3 === 0 &&
    triangles.length % 3 === 0 &&
    vertices.every(Number.isFinite) &&
    triangles.every((i) => Number.isInteger(i) && i >= 0 && i < count);
  if (!valid) return null;
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new Float32BufferAttribute(vertices, 3));
  geometry.setIndex(triangles);
  geometry.computeVertexNormals();
  return geometry;
}

function createMesh(message: MeshMessage): Group | null {
  if (!Array.isArray(message?.parts)) return null;
  const group = new Group();
  group.name = "model";
  for (const part of message.parts) {
    const geometry = partGeometry(part);
    if (!geometry) return null;
    // .obj files often mix the winding of their faces: draw both sides
    const material = new MeshStandardMaterial({ color: colorOf(part.color), roughness: 0.6, side: DoubleSide });
    group.add(new Mesh(geometry, material));
  }
  return group;
}

/** Fetches the model and, once it is there, hides `thing`'s stand-in shapes (its label stays) and
 * adds the model in `thing`'s own frame. A model that cannot be loaded leaves the stand-in. */
export function drawMesh(thing: Object3D, url: string, onLoaded: () => void): void {
  const mine = generation;
  fetch(url)
    .then((response) => {
      if (!response.ok) throw new Error(`HTTP ${response.status}`);
      return response.json();
    })
    .then((body) => {
      const message = parseMeshBody(body, "model");
      if (mine !== generation) return;
      const model = createMesh(message);
      if (!model) throw new Error("malformed model");
      for (const child of thing.children) if (child instanceof Mesh || child instanceof Group) child.visible = false;
      if (thing instanceof Mesh) (thing.material as MeshStandardMaterial).visible = false;
      thing.add(model);
      drawn.set(thing.name, model);
      onLoaded();
    })
    .catch((error) => console.warn(`EyeSim viewer: could not load the model ${url}: ${error}`));
}

/** How many models are drawn now. */
export function meshCount(): number {
  return drawn.size;
}

/** The drawn model's bounding box in world coordinates (z up, m), null when none is drawn. */
export function meshBox(name: string): { min: number[]; max: number[] } | null {
  const model = drawn.get(name);
  const world = model?.parent?.parent; // the world's group: its frame is the world frame
  if (!model || !world) return null;
  world.updateWorldMatrix(true, true);
  const toWorld = new Matrix4().copy(world.matrixWorld).invert();
  const box = new Box3();
  const point = new Vector3();
  for (const mesh of model.children) {
    if (!(mesh instanceof Mesh)) continue;
    const matrix = new Matrix4().multiplyMatrices(toWorld, mesh.matrixWorld);
    const positions = mesh.geometry.getAttribute("position");
    for (let i = 0; i < positions.count; i++) {
      box.expandByPoint(point.fromBufferAttribute(positions, i).applyMatrix4(matrix));
    }
  }
  return { min: box.min.toArray(), max: box.max.toArray() };
}
