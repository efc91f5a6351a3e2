// Viewer channel messages (docs/viewer-channel.md). Their types and checking parsers are generated
// from interface/viewer.schema.json into ./generated/viewer_protocol.ts (`make protocol`); this file
// adds the few checks a JSON Schema cannot say (one field's length depending on another's) and
// turns a WebSocket frame into a message or null.

import {
  MalformedMessage,
  parseServerMessage as parseMessage,
  ROBIOS_CONSTANTS,
  type KeyCommand,
  type MenuMessage,
  type MeshBody,
  type Part,
  type ServerMessage,
  type Shape,
} from "./generated/viewer_protocol";

export * from "./generated/viewer_protocol";

/** What a `mesh` URL returns (GET /scene/mesh/...). */
export type MeshMessage = MeshBody;
export type ObjectShape = Shape;
export type MenuLabels = MenuMessage["labels"];

/** Soft keys KEY1..KEY4 as RoBIOS numbers them. */
export type KeyCode = KeyCommand["key"];
export const KEY_CODES: readonly KeyCode[] = [
  ROBIOS_CONSTANTS.KEY1,
  ROBIOS_CONSTANTS.KEY2,
  ROBIOS_CONSTANTS.KEY3,
  ROBIOS_CONSTANTS.KEY4,
];

const SIZE_LENGTH: Record<ObjectShape, number> = { box: 3, sphere: 1, cylinder: 2, capsule: 2 };

function checkSize(thing: { shape: ObjectShape; size: number[] }, what: string): void {
  if (thing.size.length !== SIZE_LENGTH[thing.shape]) {
    throw new MalformedMessage(`${what}.size must have ${SIZE_LENGTH[thing.shape]} numbers for a ${thing.shape}`);
  }
}

/** Drops list items whose fields disagree with each other, as the generated parsers drop malformed ones. */
function consistent<T>(items: T[], what: string, check: (item: T, what: string) => void): T[] {
  return items.filter((item, i) => {
    try {
      check(item, `${what}[${i}]`);
      return true;
    } catch (error) {
      if (!(error instanceof MalformedMessage)) throw error;
      console.warn(`EyeSim viewer: skipped ${what}[${i}]: ${error.message}`, item);
      return false;
    }
  });
}

function sameLength(a: number[], b: number[], what: string, factor = 1): void {
  if (b.length !== a.length * factor) throw new MalformedMessage(`${what}: lists of different lengths`);
}

function checkParts(parts: Part[], what: string): Part[] {
  return consistent(parts, what, checkSize);
}

/** The cross-field rules of a parsed message (recursively for a frame's messages). */
function checked(message: ServerMessage): ServerMessage {
  switch (message.type) {
    case "scene":
      message.objects = consistent(message.objects, "objects", (o, what) => {
        checkSize(o, what);
        o.parts = checkParts(o.parts, `${what}.parts`);
      });
      for (const body of message.bodies) body.parts = checkParts(body.parts, "bodies.parts");
      break;
    case "snapshot":
      if (message.rays) {
        message.rays = consistent(message.rays, "rays", (r, what) => {
          if (r.ends.length % 3 !== 0) throw new MalformedMessage(`${what}.ends must be x, y, z triples`);
        });
      }
      break;
    case "series":
      message.series = consistent(message.series, "series", (s, what) => sameLength(s.times, s.values, what));
      break;
    case "paths":
      message.robots = consistent(message.robots, "robots", (r, what) => sameLength(r.times, r.points, what, 2));
      break;
    case "frame":
      message.messages = message.messages.map((m) => checked(m) as typeof m);
      break;
  }
  return message;
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
    return checked(parseMessage(data, "message"));
  } catch (error) {
    if (!(error instanceof MalformedMessage)) throw error;
    console.warn(`EyeSim viewer: ignored a malformed message: ${error.message}`, data);
    return null;
  }
}
