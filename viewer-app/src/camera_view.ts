// A robot's camera: the last image its program took with CAMGet, shown once the program takes one.

import { element } from "./dom";
import type { CameraMessage } from "./protocol";

export class CameraView {
  readonly element = element("figure", "camera-view");
  private readonly image = element("img", "camera-image");
  private readonly caption = element("figcaption", "camera-caption");
  private updates = 0;

  constructor() {
    this.image.alt = "robot camera";
    this.image.draggable = false;
    this.image.addEventListener("load", () => this.updates++);
    this.image.addEventListener("error", () => console.warn("EyeSim viewer: a camera image could not be decoded"));
    this.element.append(this.image, this.caption);
    this.element.hidden = true;
  }

  show(message: CameraMessage): void {
    this.element.hidden = false;
    this.image.src = `data:image/jpeg;base64,${message.jpeg}`;
    this.caption.textContent = `camera ${message.width} x ${message.height}`;
  }

  /** Hides the camera until the next image (the timeline jumped back). */
  clear(): void {
    this.element.hidden = true;
    this.image.removeAttribute("src");
  }

  /** Images decoded so far (for tests). */
  get imagesShown(): number {
    return this.updates;
  }
}
