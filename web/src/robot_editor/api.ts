// The robot editor's requests to the simulator (eyesim/web/robot_editor.py).

import type { SceneMessage } from "../protocol";
import type { JsonObject, Schema } from "./schema_form";
import type { Sensors } from "./preview";

export const API = "/robot-editor/api";

export interface Problem {
  kind: "error" | "warning";
  /** JSON pointer of the field the loader's message is about; "" for the robot as a whole */
  pointer: string;
  message: string;
  code: string;
}

export interface Sources {
  builtins: string[];
  files: string[];
  drives: string[];
}

export interface Opened {
  robot: JsonObject;
  origin: string | null;
  builtin: string | null;
  problems: Problem[];
}

export interface Checked {
  problems: Problem[];
  preview: (Sensors & { scene: SceneMessage }) | null;
  robi?: string;
}

export interface Saved {
  path: string;
  problems: Problem[];
  loads: boolean;
}

export interface DriveState extends Sensors {
  time: number;
  readings: {
    psd: Record<string, number>;
    lidar?: number[];
    camera?: string;
    vw?: [number, number];
    servos: number[];
    motors: number[];
  };
}

/** A refusal from the server: its status and message. */
export class RequestError extends Error {
  constructor(
    readonly status: number,
    message: string,
  ) {
    super(message);
  }
}

async function answer<T>(response: Response): Promise<T> {
  const body = await response.json();
  if (!response.ok) throw new RequestError(response.status, body.error ?? response.statusText);
  return body as T;
}

export async function get<T>(path: string): Promise<T> {
  return answer<T>(await fetch(API + path));
}

export async function post<T>(path: string, body: unknown): Promise<T> {
  return answer<T>(
    await fetch(API + path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) }),
  );
}

export const fetchSchema = (): Promise<Schema> => get<Schema>("/schema");
