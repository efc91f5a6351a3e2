// Viewer channel messages (docs/viewer-channel.md): their types and a parser that checks them.

export type Vec3 = [number, number, number];
/** A rotation as on the wire: [w, x, y, z]. */
export type Quat = [number, number, number, number];
/** Colour channels 0..255; markers add alpha (also 0..255). */
export type Rgb = [number, number, number];
export type Rgba = [number, number, number, number];

export interface Floor {
  width: number;
  height: number;
  texture: string | null;
}

export interface Wall {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
  thickness: number;
  height: number;
  color: Rgb;
}

export interface RobotInfo {
  id: number;
  name: string;
  type: string;
  /** [length, width, height] */
  size: Vec3;
  color: Rgb;
  wheel_diameter: number;
  track: number;
}

export type ObjectShape = "box" | "sphere" | "cylinder";

export interface ObjectInfo {
  id: number;
  type: string;
  shape: ObjectShape;
  /** [sx, sy, sz] for a box, [r] for a sphere, [r, h] for a cylinder */
  size: number[];
  color: Rgb;
}

export interface Marker {
  x: number;
  y: number;
  color: Rgba;
}

export interface SceneMessage {
  type: "scene";
  floor: Floor;
  walls: Wall[];
  robots: RobotInfo[];
  objects: ObjectInfo[];
  markers: Marker[];
}

export interface BodyPose {
  id: number;
  pos: Vec3;
  quat: Quat;
}

export interface SnapshotMessage {
  type: "snapshot";
  time: number;
  robots: BodyPose[];
  objects: BodyPose[];
}

export interface LcdMessage {
  type: "lcd";
  robot: number;
  png: string;
}

export type MenuLabels = [string, string, string, string];

export interface MenuMessage {
  type: "menu";
  robot: number;
  labels: MenuLabels;
}

export interface ConsoleMessage {
  type: "console";
  robot: number;
  stream: "stdout" | "stderr";
  text: string;
}

export interface ProgramMessage {
  type: "program";
  robot: number;
  event: "started" | "exited";
  name: string;
  exit_code: number | null;
}

export interface StatusMessage {
  type: "status";
  time: number;
  paused: boolean;
  speed: number | "max";
  clock: string;
  real_time_factor: number;
}

/** The server's answer to a malformed or unknown command from the browser. */
export interface ErrorMessage {
  type: "error";
  message: string;
}

export type ServerMessage =
  | SceneMessage
  | SnapshotMessage
  | LcdMessage
  | MenuMessage
  | ConsoleMessage
  | ProgramMessage
  | StatusMessage
  | ErrorMessage;

/** Soft keys KEY1..KEY4 as RoBIOS numbers them. */
export type KeyCode = 1 | 2 | 4 | 8;
export const KEY_CODES: readonly KeyCode[] = [1, 2, 4, 8];

export type BrowserCommand =
  | { type: "key"; robot: number; key: KeyCode }
  | { type: "pause" }
  | { type: "resume" }
  | { type: "speed"; value: number }
  | { type: "reset" };

class MalformedMessage extends Error {}

type Fields = Record<string, unknown>;

function record(value: unknown, what: string): Fields {
  if (typeof value !== "object" || value === null || Array.isArray(value)) {
    throw new MalformedMessage(`${what} must be an object`);
  }
  return value as Fields;
}

function num(value: unknown, what: string): number {
  if (typeof value !== "number" || !Number.isFinite(value)) {
    throw new MalformedMessage(`${what} must be a finite number`);
  }
  return value;
}

function positive(value: unknown, what: string): number {
  const n = num(value, what);
  if (n <= 0) throw new MalformedMessage(`${what} must be > 0`);
  return n;
}

function text(value: unknown, what: string): string {
  if (typeof value !== "string") throw new MalformedMessage(`${what} must be a string`);
  return value;
}

function flag(value: unknown, what: string): boolean {
  if (typeof value !== "boolean") throw new MalformedMessage(`${what} must be true or false`);
  return value;
}

function oneOf<T extends string>(value: unknown, choices: readonly T[], what: string): T {
  if (!choices.includes(value as T)) {
    throw new MalformedMessage(`${what} must be one of ${choices.join(", ")}`);
  }
  return value as T;
}

function numbers(value: unknown, length: number, what: string): number[] {
  if (!Array.isArray(value) || value.length !== length) {
    throw new MalformedMessage(`${what} must be a list of ${length} numbers`);
  }
  return value.map((v, i) => num(v, `${what}[${i}]`));
}

function channels(value: unknown, length: number, what: string): number[] {
  return numbers(value, length, what).map((c) => Math.min(255, Math.max(0, c)));
}

/** Parses each item of a list; a bad item is logged and skipped so one typo hides one thing. */
function items<T>(value: unknown, what: string, parse: (item: Fields, what: string) => T): T[] {
  if (!Array.isArray(value)) throw new MalformedMessage(`${what} must be a list`);
  const parsed: T[] = [];
  value.forEach((item, i) => {
    try {
      parsed.push(parse(record(item, `${what}[${i}]`), `${what}[${i}]`));
    } catch (error) {
      if (!(error instanceof MalformedMessage)) throw error;
      console.warn(`EyeSim viewer: skipped ${what}[${i}]: ${error.message}`, item);
    }
  });
  return parsed;
}

function parseFloor(f: Fields): Floor {
  const texture = f.texture ?? null;
  return {
    width: positive(f.width, "floor.width"),
    height: positive(f.height, "floor.height"),
    texture: texture === null ? null : text(texture, "floor.texture"),
  };
}

function parseWall(w: Fields, what: string): Wall {
  return {
    x1: num(w.x1, `${what}.x1`),
    y1: num(w.y1, `${what}.y1`),
    x2: num(w.x2, `${what}.x2`),
    y2: num(w.y2, `${what}.y2`),
    thickness: positive(w.thickness, `${what}.thickness`),
    height: positive(w.height, `${what}.height`),
    color: channels(w.color, 3, `${what}.color`) as Rgb,
  };
}

function parseRobot(r: Fields, what: string): RobotInfo {
  const size = numbers(r.size, 3, `${what}.size`);
  size.forEach((s, i) => positive(s, `${what}.size[${i}]`));
  return {
    id: num(r.id, `${what}.id`),
    name: text(r.name, `${what}.name`),
    type: text(r.type, `${what}.type`),
    size: size as Vec3,
    color: channels(r.color, 3, `${what}.color`) as Rgb,
    wheel_diameter: positive(r.wheel_diameter, `${what}.wheel_diameter`),
    track: positive(r.track, `${what}.track`),
  };
}

const SIZE_LENGTH: Record<ObjectShape, number> = { box: 3, sphere: 1, cylinder: 2 };

function parseObject(o: Fields, what: string): ObjectInfo {
  const shape = oneOf(o.shape, ["box", "sphere", "cylinder"] as const, `${what}.shape`);
  const size = numbers(o.size, SIZE_LENGTH[shape], `${what}.size`);
  size.forEach((s, i) => positive(s, `${what}.size[${i}]`));
  return {
    id: num(o.id, `${what}.id`),
    type: text(o.type, `${what}.type`),
    shape,
    size,
    color: channels(o.color, 3, `${what}.color`) as Rgb,
  };
}

function parseMarker(m: Fields, what: string): Marker {
  return {
    x: num(m.x, `${what}.x`),
    y: num(m.y, `${what}.y`),
    color: channels(m.color, 4, `${what}.color`) as Rgba,
  };
}

function parseBodyPose(b: Fields, what: string): BodyPose {
  return {
    id: num(b.id, `${what}.id`),
    pos: numbers(b.pos, 3, `${what}.pos`) as Vec3,
    quat: numbers(b.quat, 4, `${what}.quat`) as Quat,
  };
}

const BASE64 = /^[A-Za-z0-9+/]*={0,2}$/;

function parseFields(m: Fields): ServerMessage | null {
  switch (m.type) {
    case "scene":
      return {
        type: "scene",
        floor: parseFloor(record(m.floor, "floor")),
        walls: items(m.walls, "walls", parseWall),
        robots: items(m.robots, "robots", parseRobot),
        objects: items(m.objects ?? [], "objects", parseObject),
        markers: items(m.markers ?? [], "markers", parseMarker),
      };
    case "snapshot":
      return {
        type: "snapshot",
        time: num(m.time, "time"),
        robots: items(m.robots, "robots", parseBodyPose),
        objects: items(m.objects ?? [], "objects", parseBodyPose),
      };
    case "lcd": {
      const png = text(m.png, "png");
      if (!BASE64.test(png)) throw new MalformedMessage("png must be base64");
      return { type: "lcd", robot: num(m.robot, "robot"), png };
    }
    case "menu": {
      const labels = m.labels;
      if (!Array.isArray(labels) || labels.length !== 4) {
        throw new MalformedMessage("labels must be a list of four strings");
      }
      return {
        type: "menu",
        robot: num(m.robot, "robot"),
        labels: labels.map((l, i) => text(l, `labels[${i}]`)) as MenuLabels,
      };
    }
    case "console":
      return {
        type: "console",
        robot: num(m.robot, "robot"),
        stream: oneOf(m.stream, ["stdout", "stderr"] as const, "stream"),
        text: text(m.text, "text"),
      };
    case "program": {
      const exitCode = m.exit_code ?? null;
      return {
        type: "program",
        robot: num(m.robot, "robot"),
        event: oneOf(m.event, ["started", "exited"] as const, "event"),
        name: text(m.name, "name"),
        exit_code: exitCode === null ? null : num(exitCode, "exit_code"),
      };
    }
    case "status":
      return {
        type: "status",
        time: num(m.time, "time"),
        paused: flag(m.paused, "paused"),
        speed: m.speed === "max" ? "max" : positive(m.speed, "speed"),
        clock: text(m.clock, "clock"),
        real_time_factor: num(m.real_time_factor, "real_time_factor"),
      };
    case "error":
      return { type: "error", message: text(m.message, "message") };
    default:
      return null;
  }
}

/**
 * Parses one WebSocket text frame. Returns null for unknown message types (ignored by
 * contract) and for malformed data (logged to the console, never thrown).
 */
export function parseServerMessage(frame: unknown): ServerMessage | null {
  if (typeof frame !== "string") {
    console.warn("EyeSim viewer: ignored a non-text WebSocket frame");
    return null;
  }
  let data: unknown;
  try {
    data = JSON.parse(frame);
  } catch {
    console.warn("EyeSim viewer: ignored a frame that is not JSON:", frame.slice(0, 200));
    return null;
  }
  try {
    return parseFields(record(data, "message"));
  } catch (error) {
    if (!(error instanceof MalformedMessage)) throw error;
    console.warn(`EyeSim viewer: ignored a malformed message: ${error.message}`, data);
    return null;
  }
}
