// The simulator's HTTP routes with JSON bodies (docs/viewer-channel.md): one call per route, named
// by method and path as interface/viewer.schema.json names it. The request's type and the answer's
// checking parser are generated from the schema (./generated/viewer_protocol.ts, `make protocol`).

import {
  MalformedMessage,
  parseRouteError,
  ROUTE_ANSWERS,
  type Place,
  type RouteName,
  type Routes,
  type SceneDiagnostic,
} from "./generated/viewer_protocol";

/** A refused request: the simulator's own words on what was wrong, its status, and for the scene
 * routes the loader's diagnostics and the files a save would overwrite. */
export class RouteError extends Error {
  constructor(
    message: string,
    readonly status: number,
    readonly diagnostics: SceneDiagnostic[] = [],
    readonly exists: Place[] = [],
  ) {
    super(message);
  }
}

export type RequestOf<R extends RouteName> = Routes[R]["request"];
export type AnswerOf<R extends RouteName> = Routes[R]["response"];

/** A GET route takes an optional query string ("q=maze"), a POST route its request body. */
type Arguments<R extends RouteName> = RequestOf<R> extends undefined ? [query?: string] : [body: RequestOf<R>];

export async function call<R extends RouteName>(route: R, ...args: Arguments<R>): Promise<AnswerOf<R>> {
  const [method, path] = route.split(" ");
  const url = new URL(path, window.location.href);
  const init: RequestInit = { method, credentials: "same-origin" };
  if (method === "GET") {
    if (args[0]) url.search = args[0] as string;
  } else {
    init.headers = { "Content-Type": "application/json" };
    init.body = JSON.stringify(args[0]);
  }
  const response = await fetch(url, init);
  const text = await response.text();
  let body: unknown;
  try {
    body = JSON.parse(text);
  } catch {
    body = undefined; // the access checks answer 403 in plain text
  }
  if (!response.ok) throw refusal(body, text, response);
  try {
    return ROUTE_ANSWERS[route](body, route) as AnswerOf<R>;
  } catch (error) {
    if (!(error instanceof MalformedMessage)) throw error;
    throw new RouteError(`the simulator's answer is not what ${route} answers: ${error.message}`, response.status);
  }
}

function refusal(body: unknown, text: string, response: Response): RouteError {
  try {
    const refused = parseRouteError(body, "the refusal");
    return new RouteError(refused.error, response.status, refused.diagnostics ?? [], refused.exists ?? []);
  } catch {
    return new RouteError(text.trim() || `the simulator answered ${response.status} ${response.statusText}`,
      response.status);
  }
}

/** What went wrong, each diagnostic on its own line (file:line: ...). */
export function errorText(error: unknown): string {
  if (error instanceof RouteError) return [error.message, ...error.diagnostics.map((d) => d.text)].join("\n");
  return String(error);
}
