// Files under the scene roots as the scene browser and editor show them.

import type { Place, SceneRoot } from "../generated/viewer_protocol";

/** A place as the lists show it: "root name / path". */
export function placeText(place: Place, roots: SceneRoot[]): string {
  return `${roots[place.root]?.name ?? "?"} / ${place.path}`;
}
