// A video of the 3D view while it plays: the canvas captured with MediaRecorder into a WebM file.

/** The first WebM codec this browser can record. */
function webmType(): string | null {
  if (typeof MediaRecorder === "undefined") return null;
  return ["video/webm;codecs=vp9", "video/webm;codecs=vp8", "video/webm"].find((t) => MediaRecorder.isTypeSupported(t)) ?? null;
}

export const VIDEO_FPS = 30;

export class VideoExport {
  private recorder: MediaRecorder | null = null;
  private chunks: Blob[] = [];
  /** the last video made (for tests and for saving again) */
  last: Blob | null = null;

  constructor(private readonly done: (video: Blob) => void) {}

  get recording(): boolean {
    return this.recorder !== null;
  }

  static supported(): boolean {
    return webmType() !== null;
  }

  /** Starts capturing `canvas`; false when this browser cannot record video. */
  start(canvas: HTMLCanvasElement): boolean {
    const type = webmType();
    if (!type || this.recorder) return false;
    const recorder = new MediaRecorder(canvas.captureStream(VIDEO_FPS), { mimeType: type });
    this.chunks = [];
    recorder.addEventListener("dataavailable", (event) => {
      if (event.data.size > 0) this.chunks.push(event.data);
    });
    recorder.addEventListener("stop", () => {
      this.last = new Blob(this.chunks, { type: "video/webm" });
      this.chunks = [];
      this.done(this.last);
    });
    recorder.start();
    this.recorder = recorder;
    return true;
  }

  stop(): void {
    this.recorder?.stop();
    this.recorder = null;
  }
}
