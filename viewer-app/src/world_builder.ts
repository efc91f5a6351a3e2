// Turns a `scene` message into three.js objects in world coordinates (z up, metres).

import {
  BoxGeometry,
  BufferGeometry,
  CapsuleGeometry,
  CircleGeometry,
  CylinderGeometry,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  Material,
  Mesh,
  MeshStandardMaterial,
  Object3D,
  PlaneGeometry,
  SphereGeometry,
  SRGBColorSpace,
  TextureLoader,
} from "three";
import { CSS2DObject } from "three/addons/renderers/CSS2DRenderer.js";
import type {
  Floor,
  Marker,
  ObjectInfo,
  ObjectShape,
  Part,
  RobotBody,
  SceneMessage,
  Wall,
  Water,
} from "./protocol";
import { drawMesh, forgetMeshes } from "./mesh_loader";
import { colorOf, createRobotModel } from "./robot_model";

export interface BuiltWorld {
  /** Everything in the scene, to be added under the world root. */
  group: Group;
  robots: Map<number, Object3D>;
  objects: Map<number, Object3D>;
  /** robots' moving parts, by body id */
  bodies: Map<number, Object3D>;
  /** height of the water's surface, null without water */
  waterSurface: number | null;
  wallCount: number;
  markerCount: number;
}

const GRID_STEP = 0.5;
const MARKER_RADIUS = 0.025;
/** Lifts flat things just above the floor so they do not flicker against it. */
const FLOOR_GAP = 0.001;

function floorGrid(floor: Floor): LineSegments {
  const points: number[] = [];
  for (let x = GRID_STEP; x < floor.width - 1e-9; x += GRID_STEP) {
    points.push(x, 0, FLOOR_GAP, x, floor.height, FLOOR_GAP);
  }
  for (let y = GRID_STEP; y < floor.height - 1e-9; y += GRID_STEP) {
    points.push(0, y, FLOOR_GAP, floor.width, y, FLOOR_GAP);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute("position", new Float32BufferAttribute(points, 3));
  return new LineSegments(geometry, new LineBasicMaterial({ color: 0xc9c4b8 }));
}

function createFloor(floor: Floor, onTextureLoaded: () => void): Object3D {
  const group = new Group();
  const material = new MeshStandardMaterial({ color: 0xeeebe3, roughness: 0.95 });
  const plane = new Mesh(new PlaneGeometry(floor.width, floor.height), material);
  // The floor's origin is its lower-left corner.
  plane.position.set(floor.width / 2, floor.height / 2, 0);
  group.add(plane);
  if (floor.texture) {
    new TextureLoader().load(
      floor.texture,
      (texture) => {
        texture.colorSpace = SRGBColorSpace;
        material.map = texture;
        material.color.set(0xffffff);
        material.needsUpdate = true;
        onTextureLoaded();
      },
      undefined,
      () => console.warn(`EyeSim viewer: could not load the floor texture ${floor.texture}`),
    );
  } else {
    group.add(floorGrid(floor));
  }
  return group;
}

function createWall(wall: Wall): Mesh {
  const dx = wall.x2 - wall.x1;
  const dy = wall.y2 - wall.y1;
  // Extending each end by half the thickness closes the corners where walls meet.
  const length = Math.hypot(dx, dy) + wall.thickness;
  const mesh = new Mesh(
    new BoxGeometry(length, wall.thickness, wall.height),
    new MeshStandardMaterial({ color: colorOf(wall.color), roughness: 0.8 }),
  );
  mesh.position.set((wall.x1 + wall.x2) / 2, (wall.y1 + wall.y2) / 2, wall.height / 2);
  mesh.rotation.z = Math.atan2(dy, dx);
  return mesh;
}

function shapeGeometry(shape: ObjectShape, size: number[]): BufferGeometry {
  switch (shape) {
    case "box":
      return new BoxGeometry(size[0], size[1], size[2]);
    case "sphere":
      return new SphereGeometry(size[0], 24, 16);
    // CylinderGeometry and CapsuleGeometry stand along y; the world's stand along z.
    case "cylinder":
      return new CylinderGeometry(size[0], size[0], size[1], 24).rotateX(Math.PI / 2);
    case "capsule":
      return new CapsuleGeometry(size[0], Math.max(size[1] - 2 * size[0], 0), 8, 16).rotateX(
        Math.PI / 2,
      );
  }
}

/** The parts of an object or robot body in its own frame, each in its own colour or `color`. */
function createParts(parts: Part[], color: Part["color"]): Group {
  const group = new Group();
  for (const part of parts) {
    const mesh = new Mesh(
      shapeGeometry(part.shape, part.size),
      new MeshStandardMaterial({ color: colorOf(part.color ?? color ?? [180, 180, 180]), roughness: 0.6 }),
    );
    const [w, x, y, z] = part.quat;
    mesh.position.set(...part.pos);
    mesh.quaternion.set(x, y, z, w);
    group.add(mesh);
  }
  return group;
}

function createObject(object: ObjectInfo): Object3D {
  const thing: Object3D =
    object.parts.length > 0
      ? createParts(object.parts, object.color)
      : new Mesh(
          shapeGeometry(object.shape, object.size),
          new MeshStandardMaterial({ color: colorOf(object.color), roughness: 0.6 }),
        );
  thing.name = `object ${object.id}`;
  return thing;
}

function createBody(body: RobotBody): Object3D {
  const group = createParts(body.parts, undefined);
  group.name = `robot ${body.robot} body ${body.id}`;
  return group;
}

/** Translucent water from the floor up to its surface, over the whole floor. */
function createWater(water: Water, floor: Floor): Mesh {
  const mesh = new Mesh(
    new BoxGeometry(floor.width, floor.height, water.surface),
    new MeshStandardMaterial({ color: 0x2a7fc9, transparent: true, opacity: 0.25, depthWrite: false }),
  );
  mesh.position.set(floor.width / 2, floor.height / 2, water.surface / 2);
  mesh.name = "water";
  return mesh;
}

function createMarker(marker: Marker): Mesh {
  const [r, g, b, a] = marker.color;
  const mesh = new Mesh(
    new CircleGeometry(MARKER_RADIUS, 24),
    new MeshStandardMaterial({
      color: colorOf([r, g, b]),
      transparent: a < 255,
      opacity: a / 255,
    }),
  );
  mesh.position.set(marker.x, marker.y, 2 * FLOOR_GAP);
  return mesh;
}

/** Robots and objects stay hidden until the first snapshot says where they are. */
function hiddenUntilPlaced<T extends Object3D>(thing: T): T {
  thing.visible = false;
  return thing;
}

export function buildWorld(scene: SceneMessage, onTextureLoaded: () => void, onFloorLoaded: () => void = () => {}): BuiltWorld {
  forgetMeshes();
  const group = new Group();
  group.add(createFloor(scene.floor, () => {
    onFloorLoaded();
    onTextureLoaded();
  }));
  for (const wall of scene.walls) group.add(createWall(wall));
  for (const marker of scene.markers) group.add(createMarker(marker));
  const robots = new Map<number, Object3D>();
  for (const robot of scene.robots) {
    const model = hiddenUntilPlaced(createRobotModel(robot));
    if (robot.mesh) drawMesh(model, robot.mesh, onTextureLoaded);
    robots.set(robot.id, model);
    group.add(model);
  }
  const objects = new Map<number, Object3D>();
  for (const object of scene.objects) {
    const mesh = hiddenUntilPlaced(createObject(object));
    if (object.mesh) drawMesh(mesh, object.mesh, onTextureLoaded);
    objects.set(object.id, mesh);
    group.add(mesh);
  }
  const bodies = new Map<number, Object3D>();
  for (const body of scene.bodies) {
    const model = hiddenUntilPlaced(createBody(body));
    bodies.set(body.id, model);
    group.add(model);
  }
  if (scene.water) group.add(createWater(scene.water, scene.floor));
  return {
    group,
    robots,
    objects,
    bodies,
    waterSurface: scene.water?.surface ?? null,
    wallCount: scene.walls.length,
    markerCount: scene.markers.length,
  };
}

/** Frees GPU resources and removes label elements (three.js does neither on its own). */
export function disposeWorld(world: BuiltWorld): void {
  world.group.removeFromParent();
  world.group.traverse((thing) => {
    if (thing instanceof Mesh || thing instanceof LineSegments) {
      thing.geometry.dispose();
      const materials: Material[] = Array.isArray(thing.material) ? thing.material : [thing.material];
      for (const material of materials) {
        if (material instanceof MeshStandardMaterial) material.map?.dispose();
        material.dispose();
      }
    } else if (thing instanceof CSS2DObject) {
      thing.element.remove();
    }
  });
}
