// A robot's LCD, drawn pixel for pixel, and its four soft keys (buttons and the LCD's menu bar);
// a click elsewhere on the LCD is a touch (KEYGetXY).

import { element } from "./dom";
import { KEY_CODES, type KeyCode, type MenuMessage } from "./protocol";

const LCD_WIDTH = 480;
const LCD_HEIGHT = 320;
/** RoBIOS draws the soft-key labels in a bar this many pixels high at the LCD's bottom. */
const MENU_BAR_HEIGHT = 38;

export class LcdView {
  readonly element = element("div", "lcd");
  private readonly image = element("img", "lcd-image");
  private readonly keys: HTMLButtonElement[];
  private readonly labels: HTMLElement[];
  private updates = 0;
  private enabled = true;
  private menuVisible = true;
  private rotated = false;

  constructor(
    private readonly pressKey: (key: KeyCode) => void,
    private readonly touch: (x: number, y: number) => void,
  ) {
    this.image.width = LCD_WIDTH;
    this.image.height = LCD_HEIGHT;
    this.image.alt = "robot LCD";
    this.image.draggable = false;
    this.image.addEventListener("load", () => this.updates++);
    this.image.addEventListener("error", () => {
      console.warn("EyeSim viewer: an LCD image could not be decoded");
    });
    this.image.addEventListener("click", (event) => this.clickImage(event));
    this.image.addEventListener("mousemove", (event) => {
      this.image.classList.toggle("over-menu", this.menuKeyAt(event) !== null);
    });

    const keyRow = element("div", "soft-keys");
    this.labels = KEY_CODES.map(() => element("span", "soft-key-label"));
    this.keys = KEY_CODES.map((key, i) => {
      const button = element("button", "soft-key");
      button.type = "button";
      button.dataset.key = String(key);
      button.append(element("span", "soft-key-name", `KEY${i + 1}`), this.labels[i]);
      button.addEventListener("click", () => this.pressKey(key));
      return button;
    });
    keyRow.append(...this.keys);
    const frame = element("div", "lcd-frame");
    frame.append(this.image);
    this.element.append(frame, keyRow);
  }

  showImage(png: string): void {
    this.image.src = `data:image/png;base64,${png}`;
  }

  /** A blank LCD with no menu labels (the timeline jumped back to before the program drew). */
  clear(): void {
    this.image.removeAttribute("src");
    this.showMenu({ labels: ["", "", "", ""], visible: true, rotated: false });
  }

  /** The LCD as a PNG data URL (what it shows), or null before the first image. */
  pngDataUrl(): string | null {
    return this.image.getAttribute("src");
  }

  showMenu({ labels, visible, rotated }: Pick<MenuMessage, "labels" | "visible" | "rotated">): void {
    this.menuVisible = visible;
    this.rotated = rotated;
    this.image.classList.toggle("rotated", rotated);
    labels.forEach((label, i) => {
      this.labels[i].textContent = label;
      this.keys[i].title = label ? `KEY${i + 1}: ${label}` : `KEY${i + 1}`;
    });
  }

  setEnabled(enabled: boolean): void {
    this.enabled = enabled;
    for (const key of this.keys) key.disabled = !enabled;
    this.element.classList.toggle("disabled", !enabled);
  }

  menuLabels(): string[] {
    return this.labels.map((label) => label.textContent ?? "");
  }

  /** How many LCD images have finished loading into the page. */
  imageUpdates(): number {
    return this.updates;
  }

  /** The LCD pixel under the pointer, in the program's coordinates (a rotated LCD shows turned). */
  private pixelAt(event: MouseEvent): { x: number; y: number } | null {
    const box = this.image.getBoundingClientRect();
    if (box.width === 0 || box.height === 0) return null;
    let x = Math.floor(((event.clientX - box.left) / box.width) * LCD_WIDTH);
    let y = Math.floor(((event.clientY - box.top) / box.height) * LCD_HEIGHT);
    if (x < 0 || x >= LCD_WIDTH || y < 0 || y >= LCD_HEIGHT) return null;
    if (this.rotated) [x, y] = [LCD_WIDTH - 1 - x, LCD_HEIGHT - 1 - y];
    return { x, y };
  }

  /** The soft key whose quarter of the shown menu bar is under the pointer, if any. */
  private menuKeyAt(event: MouseEvent): KeyCode | null {
    const pixel = this.pixelAt(event);
    if (!pixel || !this.menuVisible || pixel.y < LCD_HEIGHT - MENU_BAR_HEIGHT) return null;
    return KEY_CODES[Math.floor((pixel.x / LCD_WIDTH) * KEY_CODES.length)];
  }

  private clickImage(event: MouseEvent): void {
    if (!this.enabled) return;
    const key = this.menuKeyAt(event);
    const pixel = this.pixelAt(event);
    if (key !== null) this.pressKey(key);
    else if (pixel) this.touch(pixel.x, pixel.y);
  }
}
