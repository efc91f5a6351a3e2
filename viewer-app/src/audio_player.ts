// Plays what robots play: beeps synthesised with Web Audio, WAV/MP3 files from the bytes sent.

import type { AudioMessage } from "./protocol";

const MIME: Record<"wav" | "mp3", string> = { wav: "audio/wav", mp3: "audio/mpeg" };

export class AudioPlayer {
  private context: AudioContext | null = null;
  private readonly played = new Map<number, number>();

  play(message: AudioMessage): void {
    this.played.set(message.robot, (this.played.get(message.robot) ?? 0) + 1);
    // Browsers may refuse sound until the user has clicked the page: then it stays silent.
    if (message.sound === "beep") {
      this.beep(message.frequency ?? 1000, message.duration);
    } else if (message.data && message.format) {
      new Audio(`data:${MIME[message.format]};base64,${message.data}`).play().catch(() => {});
    }
  }

  /** How many sounds a robot has played since the page opened. */
  soundsPlayed(robot: number): number {
    return this.played.get(robot) ?? 0;
  }

  private beep(frequency: number, seconds: number): void {
    if (typeof AudioContext === "undefined") return;
    this.context ??= new AudioContext();
    const oscillator = this.context.createOscillator();
    const gain = this.context.createGain();
    oscillator.frequency.value = frequency;
    gain.gain.value = 0.1;
    oscillator.connect(gain).connect(this.context.destination);
    oscillator.start();
    oscillator.stop(this.context.currentTime + seconds);
  }
}
