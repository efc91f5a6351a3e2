// "Open recording…" in a replay: sends an .mcap file from this computer to `eyesim replay`, which
// then shows it on every open page (a new scene, timeline and frame arrive over the WebSocket).

function find<T extends HTMLElement>(root: HTMLElement, selector: string): T {
  const found = root.querySelector<T>(selector);
  if (!found) throw new Error(`EyeSim viewer: the page has no ${selector}`);
  return found;
}

export class RecordingUpload {
  private readonly button: HTMLButtonElement;
  private readonly file: HTMLInputElement;
  private readonly message: HTMLElement;

  constructor(root: HTMLElement) {
    this.button = find(root, "#tl-open");
    this.file = find(root, "#tl-file");
    this.message = find(root, "#tl-message");
    this.button.addEventListener("click", () => this.file.click());
    this.file.addEventListener("change", () => {
      const chosen = this.file.files?.[0];
      if (chosen) void this.send(chosen);
      this.file.value = "";
    });
  }

  /** Only a replay can show another recording. */
  setAvailable(available: boolean): void {
    this.button.hidden = !available;
    if (!available) this.message.textContent = "";
  }

  /** What the last upload ended with: "" while none, the server's word otherwise. */
  get status(): string {
    return this.message.textContent ?? "";
  }

  private async send(file: File): Promise<void> {
    this.message.textContent = `opening ${file.name}…`;
    this.message.dataset.kind = "busy";
    try {
      const response = await fetch(new URL(`recording?name=${encodeURIComponent(file.name)}`, window.location.href), {
        method: "POST",
        body: file,
      });
      this.message.textContent = await response.text();
      this.message.dataset.kind = response.ok ? "ok" : "error";
    } catch (error) {
      this.message.textContent = `cannot send ${file.name}: ${String(error)}`;
      this.message.dataset.kind = "error";
    }
  }
}
