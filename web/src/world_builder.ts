// Turns a `scene` message into three.js objects in world coordinates (z up, metres).

import {
  BoxGeometry,
  BufferGeometry,
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
import type { Floor, Marker, ObjectInfo, SceneMessage, Wall } from "./protocol";
import { colorOf, createRobotModel } from "./robot_model";

export interface BuiltWorld {
  /** Everything in the scene, to be added under the world root. */
  group: Group;
  robots: Map<number, Object3D>;
  objects: Map<number, Object3D>;
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

function objectGeometry(object: ObjectInfo): BufferGeometry {
  switch (object.shape) {
    case "box":
      return new BoxGeometry(object.size[0], object.size[1], object.size[2]);
    case "sphere":
      return new SphereGeometry(object.size[0], 24, 16);
    case "cylinder":
      // CylinderGeometry stands along y; the world's cylinders stand along z.
      return new CylinderGeometry(object.size[0], object.size[0], object.size[1], 24).rotateX(
        Math.PI / 2,
      );
  }
}

function createObject(object: ObjectInfo): Mesh {
  const mesh = new Mesh(
    objectGeometry(object),
    new MeshStandardMaterial({ color: colorOf(object.color), roughness: 0.6 }),
  );
  mesh.name = `object ${object.id}`;
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

export function buildWorld(scene: SceneMessage, onTextureLoaded: () => void): BuiltWorld {
  const group = new Group();
  group.add(createFloor(scene.floor, onTextureLoaded));
  for (const wall of scene.walls) group.add(createWall(wall));
  for (const marker of scene.markers) group.add(createMarker(marker));
  const robots = new Map<number, Object3D>();
  for (const robot of scene.robots) {
    const model = hiddenUntilPlaced(createRobotModel(robot));
    robots.set(robot.id, model);
    group.add(model);
  }
  const objects = new Map<number, Object3D>();
  for (const object of scene.objects) {
    const mesh = hiddenUntilPlaced(createObject(object));
    objects.set(object.id, mesh);
    group.add(mesh);
  }
  return {
    group,
    robots,
    objects,
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
