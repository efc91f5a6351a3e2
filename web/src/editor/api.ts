// The scene routes of the simulator (eyesim/web/scene_workspace.py): JSON in, JSON out.

/** A file under one of the scene roots. */
export interface Place {
  root: number;
  path: string;
}

export interface Diagnostic {
  kind: string;
  file: string;
  line: number;
  column: number;
  message: string;
  /** file:line: kind: message, as the simulator prints it */
  text: string;
}

export interface Root {
  index: number;
  name: string;
  path: string;
  writable: boolean;
}

export interface SceneFiles {
  roots: Root[];
  files: Place[];
  recent: Place[];
}

export interface Catalog {
  robots: string[];
  objects: string[];
  robot_files: Place[];
  object_files: Place[];
  programs: Place[];
}

export interface RobotItem {
  type: string;
  x: number;
  y: number;
  phi: number;
  program: string | null;
}

export interface ObjectItem {
  type: string;
  x: number;
  y: number;
  phi: number;
  /** one of the world file's own (a maze ball) */
  world: boolean;
}

export interface MarkerItem {
  x: number;
  y: number;
  color: number[];
}

export interface WallItem {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
}

/** The scene being edited, in mm and degrees, numbered as edits name the things. */
export interface EditorState {
  editing: boolean;
  browse_at_start: boolean;
  file: string;
  place: Place | null;
  can_undo: boolean;
  can_redo: boolean;
  items: {
    robots: RobotItem[];
    objects: ObjectItem[];
    markers: MarkerItem[];
    walls: WallItem[];
    floor: { width: number | null; height: number | null };
  };
  warnings?: Diagnostic[];
  saved?: Place[];
}

/** A refusal: the reason, the loader's diagnostics, and for a save the files that exist already. */
export class RouteError extends Error {
  constructor(
    message: string,
    readonly status: number,
    readonly diagnostics: Diagnostic[] = [],
    readonly exists: Place[] = [],
  ) {
    super(message);
  }
}

async function answer<T>(response: Response): Promise<T> {
  const text = await response.text();
  let body: unknown = null;
  try {
    body = JSON.parse(text);
  } catch {
    body = null;
  }
  if (!response.ok) {
    const fields = (body ?? {}) as { error?: string; diagnostics?: Diagnostic[]; exists?: Place[] };
    throw new RouteError(fields.error ?? (text.trim() || response.statusText), response.status,
      fields.diagnostics ?? [], fields.exists ?? []);
  }
  return body as T;
}

export async function getJson<T>(path: string): Promise<T> {
  return answer<T>(await fetch(path, { credentials: "same-origin" }));
}

export async function postJson<T>(path: string, body: unknown): Promise<T> {
  return answer<T>(
    await fetch(path, {
      method: "POST",
      credentials: "same-origin",
      headers: { "Content-Type": "application/json" },
      body: JSON.stringify(body),
    }),
  );
}

/** A place as the lists show it: "root name / path". */
export function placeText(place: Place, roots: Root[]): string {
  return `${roots[place.root]?.name ?? "?"} / ${place.path}`;
}

/** What went wrong, each diagnostic on its own line (file:line: ...). */
export function errorText(error: unknown): string {
  if (error instanceof RouteError) return [error.message, ...error.diagnostics.map((d) => d.text)].join("\n");
  return String(error);
}
