// The 3D model of a robot: body box, two wheels, a heading arrow and a floating name label.

import {
  BoxGeometry,
  Color,
  ConeGeometry,
  CylinderGeometry,
  Group,
  Mesh,
  MeshStandardMaterial,
} from "three";
import { CSS2DObject } from "three/addons/renderers/CSS2DRenderer.js";
import type { RobotInfo, Rgb } from "./protocol";

export function colorOf([r, g, b]: Rgb): Color {
  return new Color().setRGB(r / 255, g / 255, b / 255, "srgb");
}

/** Dark arrow on a light body, white arrow on a dark one, so the heading always stands out. */
function arrowColor([r, g, b]: Rgb): Color {
  const luminance = (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255;
  return new Color(luminance > 0.6 ? 0x1b1f24 : 0xffffff);
}

function nameLabel(name: string, height: number): CSS2DObject {
  const element = document.createElement("div");
  element.className = "robot-label";
  element.textContent = name;
  const label = new CSS2DObject(element);
  label.center.set(0.5, 1);
  label.position.set(0, 0, height * 1.2 + 0.03);
  return label;
}

/**
 * Built in the robot's own frame: x forward, y left, z up, origin at the body centre on the floor
 * (where `pos` in a snapshot puts it).
 */
export function createRobotModel(robot: RobotInfo): Group {
  const [length, width, height] = robot.size;
  const model = new Group();
  model.name = `robot ${robot.id}`;

  const body = new Mesh(
    new BoxGeometry(length, width, height),
    new MeshStandardMaterial({ color: colorOf(robot.color), roughness: 0.7 }),
  );
  body.position.z = height / 2;
  model.add(body);

  const radius = robot.wheel_diameter / 2;
  const wheelWidth = Math.max(0.006, robot.wheel_diameter * 0.25);
  // Wheels inside the body's footprint would be hidden, so they sit at least flush with its sides.
  const wheelY = Math.max(robot.track / 2, width / 2 + wheelWidth / 2);
  const wheelMaterial = new MeshStandardMaterial({ color: 0x202326, roughness: 0.9 });
  // Without a wheel diameter the robot has no two drive wheels to draw (its wheels, if any, are bodies).
  for (const side of radius > 0 ? [1, -1] : []) {
    // CylinderGeometry's axis is y: the axle direction.
    const wheel = new Mesh(new CylinderGeometry(radius, radius, wheelWidth, 24), wheelMaterial);
    wheel.position.set(0, side * wheelY, radius);
    model.add(wheel);
  }

  const arrowLength = length * 0.55;
  const arrowRadius = Math.min(width, length) * 0.3;
  // The cone points along its y axis: turn it to point forward (+x), then flatten it into an
  // arrowhead lying on the body's top.
  const arrow = new Mesh(
    new ConeGeometry(arrowRadius, arrowLength, 3).rotateZ(-Math.PI / 2),
    new MeshStandardMaterial({ color: arrowColor(robot.color), roughness: 0.5 }),
  );
  const flatten = 0.35;
  arrow.scale.z = flatten;
  arrow.position.set(length * 0.1, 0, height + 0.5 * arrowRadius * flatten);
  model.add(arrow);

  model.add(nameLabel(robot.name, height));
  return model;
}
