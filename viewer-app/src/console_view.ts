// A robot program's console output: follows new text, keeps only the most recent part.

import { element } from "./dom";

/** Enough for a long session's recent output without slowing the page down. */
const MAX_CHARACTERS = 50_000;

export class ConsoleView {
  readonly element = element("pre", "console");
  private length = 0;

  constructor() {
    this.element.setAttribute("role", "log");
    this.element.tabIndex = 0;
  }

  append(stream: "stdout" | "stderr", text: string): void {
    if (!text) return;
    const chunk = text.length > MAX_CHARACTERS ? text.slice(-MAX_CHARACTERS) : text;
    // Follow new output only if the reader has not scrolled up to read something.
    const box = this.element;
    const following = box.scrollHeight - box.scrollTop - box.clientHeight < 8;
    if (stream === "stderr") {
      box.append(element("span", "stderr", chunk));
    } else {
      box.append(chunk);
    }
    this.length += chunk.length;
    while (this.length > MAX_CHARACTERS && box.firstChild) {
      this.length -= box.firstChild.textContent?.length ?? 0;
      box.firstChild.remove();
    }
    if (following) box.scrollTop = box.scrollHeight;
  }

  /** Empties the console (the timeline jumped back). */
  clear(): void {
    this.element.replaceChildren();
    this.length = 0;
  }

  text(): string {
    return this.element.textContent ?? "";
  }
}
