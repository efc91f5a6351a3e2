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
  /** URL of its .obj model (JSON triangles, MeshMessage), drawn instead of the box; absent without one */
  mesh?: string;
}

export type ObjectShape = "box" | "sphere" | "cylinder" | "capsule";

export interface ObjectInfo {
  id: number;
  type: string;
  shape: ObjectShape;
  /** [sx, sy, sz] for a box, [r] for a sphere, [r, h] for a cylinder or capsule (h with the caps) */
  size: number[];
  color: Rgb;
  /** the shapes it is drawn from, in its own frame; empty: just `shape` at its pose */
  parts: Part[];
  /** URL of its .obj model (JSON triangles, MeshMessage), drawn instead of `parts`; absent without one */
  mesh?: string;
}

/** What a `mesh` URL returns: triangles in the robot's or object's own frame (m), one part per colour. */
export interface MeshMessage {
  parts: { color: Rgb; vertices: number[]; triangles: number[] }[];
}

/** One shape of an object or robot body, placed in that thing's frame; cylinders and capsules stand along z. */
export interface Part {
  shape: ObjectShape;
  size: number[];
  pos: Vec3;
  quat: Quat;
  color?: Rgb;
}

/** A moving part of a robot (an arm link, a finger, a steered wheel), posed by its own snapshots. */
export interface RobotBody {
  id: number;
  robot: number;
  parts: Part[];
}

/** The water a submarine scene is filled with, from the floor up to `surface` (m). */
export interface Water {
  surface: number;
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
  settings: SceneSettings;
  bodies: RobotBody[];
  water: Water | null;
  /** what the scene loader found wrong (the scene still loaded) */
  warnings: SceneWarning[];
}

/** A scene loader warning: where (line and column 0 when unknown), what kind (`code`) and what. */
export interface SceneWarning {
  file: string;
  line: number;
  column: number;
  code: string;
  message: string;
}

/** The scene's `settings`: draw sensor rays (VIS), draw robot paths (TRACE). */
export interface SceneSettings {
  vis: boolean;
  trace: boolean;
}

export interface BodyPose {
  id: number;
  pos: Vec3;
  quat: Quat;
  /** a robot's battery voltage (V), when it has a battery */
  battery?: number;
}

export interface SnapshotMessage {
  type: "snapshot";
  time: number;
  robots: BodyPose[];
  objects: BodyPose[];
  bodies: BodyPose[];
  /** with settings VIS: the robots' sensor beams */
  rays?: SensorRays[];
}

/** Beams of one robot's sensor(s) from a common origin: flat [x, y, z, x, y, z, ...] end points. */
export interface SensorRays {
  robot: number;
  kind: "psd" | "lidar";
  /** a PSD beam's sensor id (as PSDGet takes it); absent for lidar and in older recordings */
  psd?: number;
  origin: Vec3;
  ends: number[];
}

/** The last image a robot's program took with CAMGet (JPEG, base64); width x height as taken. */
export interface CameraMessage {
  type: "camera";
  robot: number;
  width: number;
  height: number;
  jpeg: string;
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
  /** whether the menu bar shows at the LCD's bottom (LCD_HIDEMENU hides it) */
  visible: boolean;
  /** LCD_FB_ROTATE: the LCD image is shown turned by 180 degrees */
  rotated: boolean;
}

/** A beep, or a WAV/MP3 file (base64 `data`) the robot plays. */
export interface AudioMessage {
  type: "audio";
  robot: number;
  sound: "beep" | "file";
  duration: number;
  frequency?: number;
  name?: string;
  format?: "wav" | "mp3";
  data?: string;
}

/** Bytes a robot sent on a serial interface, one character per byte (U+0000..U+00FF). */
export interface SerialMessage {
  type: "serial";
  robot: number;
  interface: number;
  text: string;
}

export interface DigitalLine {
  /** "i" input, "o" output, "I" input with pull-up, "J" input with pull-down */
  direction: string;
  level: number;
  /** the level the viewer or a script drives an input to, or null */
  driven: number | null;
}

/** A robot's 16 digital lines and 8 analog channels (0..1023). */
export interface IoMessage {
  type: "io";
  robot: number;
  digital: DigitalLine[];
  analog: number[];
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
  /** the oldest time of the live run's history the viewer can scrub back to */
  history_start?: number;
}

/** What the timeline scrubs: the live run (its recent history) or a recording. */
export interface TimelineMessage {
  type: "timeline";
  mode: "live" | "replay";
  /** the recording's file name (replay) */
  name?: string;
  start?: number;
  end?: number;
}

/** The state at `time`: ordinary messages, after emptying the panels of the robots in `clear`. */
export interface FrameMessage {
  type: "frame";
  time: number;
  start?: number;
  end?: number;
  clear: number[];
  messages: ServerMessage[];
}

export interface SignalInfo {
  id: string;
  robot: number;
  name: string;
  label: string;
  unit: string;
}

export interface SignalsMessage {
  type: "signals";
  signals: SignalInfo[];
}

export interface Series {
  id: string;
  times: number[];
  values: number[];
}

export interface SeriesMessage {
  type: "series";
  series: Series[];
}

/** Each robot's path: flat [x, y, x, y, ...] points with the time each was reached. */
export interface PathsMessage {
  type: "paths";
  robots: { id: number; times: number[]; points: number[] }[];
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
  | ErrorMessage
  | AudioMessage
  | SerialMessage
  | IoMessage
  | CameraMessage
  | TimelineMessage
  | FrameMessage
  | SignalsMessage
  | SeriesMessage
  | PathsMessage;

/** Soft keys KEY1..KEY4 as RoBIOS numbers them. */
export type KeyCode = 1 | 2 | 4 | 8;
export const KEY_CODES: readonly KeyCode[] = [1, 2, 4, 8];

export type BrowserCommand =
  | { type: "key"; robot: number; key: KeyCode }
  | { type: "pause" }
  | { type: "resume" }
  | { type: "speed"; value: number | "max" }
  | { type: "reset" }
  | { type: "touch"; robot: number; x: number; y: number }
  | { type: "irtv"; robot: number; code: string }
  | { type: "serial"; robot: number; interface: number; text: string }
  | { type: "digital"; robot: number; line: number; level: number | null }
  | { type: "analog"; robot: number; channel: number; value: number }
  | { type: "place"; robot: number; x: number; y: number; phi: number }
  | { type: "place"; object: number; x: number; y: number; phi: number }
  | { type: "seek"; time: number }
  | { type: "live" }
  | { type: "signals" }
  | { type: "series"; ids: string[] }
  | { type: "paths" };

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
  const robot: RobotInfo = {
    id: num(r.id, `${what}.id`),
    name: text(r.name, `${what}.name`),
    type: text(r.type, `${what}.type`),
    size: size as Vec3,
    color: channels(r.color, 3, `${what}.color`) as Rgb,
    // 0: the robot has no wheels of this kind (they may come as bodies)
    wheel_diameter: Math.max(0, num(r.wheel_diameter, `${what}.wheel_diameter`)),
    track: Math.max(0, num(r.track, `${what}.track`)),
  };
  if (r.mesh !== undefined) robot.mesh = text(r.mesh, `${what}.mesh`);
  return robot;
}

const SHAPES = ["box", "sphere", "cylinder", "capsule"] as const;
const SIZE_LENGTH: Record<ObjectShape, number> = { box: 3, sphere: 1, cylinder: 2, capsule: 2 };

function parseShapeSize(o: Fields, what: string): { shape: ObjectShape; size: number[] } {
  const shape = oneOf(o.shape, SHAPES, `${what}.shape`);
  const size = numbers(o.size, SIZE_LENGTH[shape], `${what}.size`);
  size.forEach((s, i) => positive(s, `${what}.size[${i}]`));
  return { shape, size };
}

function parsePart(p: Fields, what: string): Part {
  const part: Part = {
    ...parseShapeSize(p, what),
    pos: numbers(p.pos, 3, `${what}.pos`) as Vec3,
    quat: numbers(p.quat, 4, `${what}.quat`) as Quat,
  };
  if (p.color !== undefined) part.color = channels(p.color, 3, `${what}.color`) as Rgb;
  return part;
}

function parseObject(o: Fields, what: string): ObjectInfo {
  const object: ObjectInfo = {
    id: num(o.id, `${what}.id`),
    type: text(o.type, `${what}.type`),
    ...parseShapeSize(o, what),
    color: channels(o.color, 3, `${what}.color`) as Rgb,
    parts: items(o.parts ?? [], `${what}.parts`, parsePart),
  };
  if (o.mesh !== undefined) object.mesh = text(o.mesh, `${what}.mesh`);
  return object;
}

function parseRobotBody(b: Fields, what: string): RobotBody {
  return {
    id: num(b.id, `${what}.id`),
    robot: num(b.robot, `${what}.robot`),
    parts: items(b.parts, `${what}.parts`, parsePart),
  };
}

function parseWater(value: unknown): Water | null {
  if (value === null || value === undefined) return null;
  return { surface: positive(record(value, "water").surface, "water.surface") };
}

function parseMarker(m: Fields, what: string): Marker {
  return {
    x: num(m.x, `${what}.x`),
    y: num(m.y, `${what}.y`),
    color: channels(m.color, 4, `${what}.color`) as Rgba,
  };
}

function parseSceneWarning(w: Fields, what: string): SceneWarning {
  return {
    file: text(w.file, `${what}.file`),
    line: w.line === undefined ? 0 : num(w.line, `${what}.line`),
    column: w.column === undefined ? 0 : num(w.column, `${what}.column`),
    code: w.code === undefined ? "" : text(w.code, `${what}.code`),
    message: text(w.message, `${what}.message`),
  };
}

function parseSettings(value: unknown): SceneSettings {
  const s = record(value, "settings");
  return {
    vis: s.vis === undefined ? false : flag(s.vis, "settings.vis"),
    trace: s.trace === undefined ? false : flag(s.trace, "settings.trace"),
  };
}

function parseSensorRays(r: Fields, what: string): SensorRays {
  const ends = r.ends;
  if (!Array.isArray(ends) || ends.length % 3 !== 0) {
    throw new MalformedMessage(`${what}.ends must be a list of x, y, z triples`);
  }
  const rays: SensorRays = {
    robot: num(r.robot, `${what}.robot`),
    kind: oneOf(r.kind, ["psd", "lidar"] as const, `${what}.kind`),
    origin: numbers(r.origin, 3, `${what}.origin`) as Vec3,
    ends: numbers(ends, ends.length, `${what}.ends`),
  };
  if (r.psd !== undefined) rays.psd = num(r.psd, `${what}.psd`);
  return rays;
}

function parseBodyPose(b: Fields, what: string): BodyPose {
  const pose: BodyPose = {
    id: num(b.id, `${what}.id`),
    pos: numbers(b.pos, 3, `${what}.pos`) as Vec3,
    quat: numbers(b.quat, 4, `${what}.quat`) as Quat,
  };
  if (b.battery !== undefined) pose.battery = num(b.battery, `${what}.battery`);
  return pose;
}

function parseDigitalLine(d: Fields, what: string): DigitalLine {
  const driven = d.driven ?? null;
  return {
    direction: oneOf(d.direction, ["i", "o", "I", "J"] as const, `${what}.direction`),
    level: num(d.level, `${what}.level`),
    driven: driven === null ? null : num(driven, `${what}.driven`),
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
        settings: parseSettings(m.settings ?? {}),
        bodies: items(m.bodies ?? [], "bodies", parseRobotBody),
        water: parseWater(m.water),
        warnings: items(m.warnings ?? [], "warnings", parseSceneWarning),
      };
    case "snapshot": {
      const snapshot: SnapshotMessage = {
        type: "snapshot",
        time: num(m.time, "time"),
        robots: items(m.robots, "robots", parseBodyPose),
        objects: items(m.objects ?? [], "objects", parseBodyPose),
        bodies: items(m.bodies ?? [], "bodies", parseBodyPose),
      };
      if (m.rays !== undefined) snapshot.rays = items(m.rays, "rays", parseSensorRays);
      return snapshot;
    }
    case "camera": {
      const jpeg = text(m.jpeg, "jpeg");
      if (!BASE64.test(jpeg)) throw new MalformedMessage("jpeg must be base64");
      return {
        type: "camera",
        robot: num(m.robot, "robot"),
        width: positive(m.width, "width"),
        height: positive(m.height, "height"),
        jpeg,
      };
    }
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
        visible: m.visible === undefined ? true : flag(m.visible, "visible"),
        rotated: m.rotated === undefined ? false : flag(m.rotated, "rotated"),
      };
    }
    case "audio": {
      const sound = oneOf(m.sound, ["beep", "file"] as const, "sound");
      const message: AudioMessage = { type: "audio", robot: num(m.robot, "robot"), sound, duration: num(m.duration, "duration") };
      if (m.frequency !== undefined) message.frequency = positive(m.frequency, "frequency");
      if (m.name !== undefined) message.name = text(m.name, "name");
      if (m.format !== undefined) message.format = oneOf(m.format, ["wav", "mp3"] as const, "format");
      if (m.data !== undefined) {
        const data = text(m.data, "data");
        if (!BASE64.test(data)) throw new MalformedMessage("data must be base64");
        message.data = data;
      }
      return message;
    }
    case "serial":
      return {
        type: "serial",
        robot: num(m.robot, "robot"),
        interface: num(m.interface, "interface"),
        text: text(m.text, "text"),
      };
    case "io": {
      const analog = m.analog;
      if (!Array.isArray(analog)) throw new MalformedMessage("analog must be a list of numbers");
      return {
        type: "io",
        robot: num(m.robot, "robot"),
        digital: items(m.digital, "digital", parseDigitalLine),
        analog: numbers(analog, analog.length, "analog"),
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
    case "status": {
      const status: StatusMessage = {
        type: "status",
        time: num(m.time, "time"),
        paused: flag(m.paused, "paused"),
        speed: m.speed === "max" ? "max" : positive(m.speed, "speed"),
        clock: text(m.clock, "clock"),
        real_time_factor: num(m.real_time_factor, "real_time_factor"),
      };
      if (m.history_start !== undefined) status.history_start = num(m.history_start, "history_start");
      return status;
    }
    case "timeline": {
      const message: TimelineMessage = { type: "timeline", mode: oneOf(m.mode, ["live", "replay"] as const, "mode") };
      if (m.name !== undefined) message.name = text(m.name, "name");
      if (m.start !== undefined) message.start = num(m.start, "start");
      if (m.end !== undefined) message.end = num(m.end, "end");
      return message;
    }
    case "frame": {
      if (!Array.isArray(m.messages)) throw new MalformedMessage("messages must be a list");
      const inner: ServerMessage[] = [];
      for (const item of m.messages) {
        const parsed = parseFields(record(item, "messages[]"));
        if (parsed && parsed.type !== "frame") inner.push(parsed);
      }
      const clear = m.clear ?? [];
      if (!Array.isArray(clear)) throw new MalformedMessage("clear must be a list of robot ids");
      const frame: FrameMessage = {
        type: "frame",
        time: num(m.time, "time"),
        clear: clear.map((id, i) => num(id, `clear[${i}]`)),
        messages: inner,
      };
      if (m.start !== undefined) frame.start = num(m.start, "start");
      if (m.end !== undefined) frame.end = num(m.end, "end");
      return frame;
    }
    case "signals":
      return {
        type: "signals",
        signals: items(m.signals, "signals", (s, what) => ({
          id: text(s.id, `${what}.id`),
          robot: num(s.robot, `${what}.robot`),
          name: text(s.name, `${what}.name`),
          label: text(s.label, `${what}.label`),
          unit: text(s.unit, `${what}.unit`),
        })),
      };
    case "series":
      return {
        type: "series",
        series: items(m.series, "series", (s, what) => {
          const times = s.times as unknown[];
          if (!Array.isArray(times)) throw new MalformedMessage(`${what}.times must be a list`);
          return {
            id: text(s.id, `${what}.id`),
            times: numbers(times, times.length, `${what}.times`),
            values: numbers(s.values, times.length, `${what}.values`),
          };
        }),
      };
    case "paths":
      return {
        type: "paths",
        robots: items(m.robots, "robots", (r, what) => {
          const times = r.times as unknown[];
          if (!Array.isArray(times)) throw new MalformedMessage(`${what}.times must be a list`);
          return {
            id: num(r.id, `${what}.id`),
            times: numbers(times, times.length, `${what}.times`),
            points: numbers(r.points, times.length * 2, `${what}.points`),
          };
        }),
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
