// The simulator's JSON routes under /api (program and settings controls), next to the page.

/** Thrown for a refused request: the simulator's own words on what was wrong. */
export class ApiError extends Error {}

async function answer<T>(response: Response): Promise<T> {
  let body: unknown = null;
  try {
    body = await response.json();
  } catch {
    throw new ApiError(`the simulator answered ${response.status} ${response.statusText}`);
  }
  if (!response.ok) {
    const message = (body as { error?: unknown } | null)?.error;
    throw new ApiError(typeof message === "string" ? message : `the simulator answered ${response.status}`);
  }
  return body as T;
}

/** The address of a route next to the page, so it works wherever the page is served from. */
function routeUrl(route: string): string {
  return new URL(route, window.location.href).href;
}

export async function getJson<T>(route: string): Promise<T> {
  return answer<T>(await fetch(routeUrl(route)));
}

export async function postJson<T>(route: string, body: object): Promise<T> {
  const response = await fetch(routeUrl(route), {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  });
  return answer<T>(response);
}
