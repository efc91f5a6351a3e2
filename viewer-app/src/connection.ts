// The WebSocket to the simulator: connects, reconnects after it closes, sends commands.

import type { BrowserCommand } from "./protocol";

export type ConnectionState = "connecting" | "open" | "closed";

export interface ConnectionEvents {
  onMessage(frame: unknown): void;
  onState(state: ConnectionState): void;
}

const FIRST_RETRY_MS = 500;
const MAX_RETRY_MS = 5000;

/** The channel's address next to the page, so it works wherever the page is served from. */
function channelUrl(): string {
  const url = new URL("ws", window.location.href);
  url.protocol = url.protocol === "https:" ? "wss:" : "ws:";
  return url.href;
}

/** The simulator may restart at any time: keep trying, backing off to one attempt every 5 s. */
export class ViewerConnection {
  private socket: WebSocket | null = null;
  private retryMs = FIRST_RETRY_MS;
  private currentState: ConnectionState = "closed";
  private opened = 0;

  constructor(private readonly events: ConnectionEvents) {}

  get state(): ConnectionState {
    return this.currentState;
  }

  /** How many times a connection has been established (reconnects included). */
  get openings(): number {
    return this.opened;
  }

  connect(): void {
    this.setState("connecting");
    const socket = new WebSocket(channelUrl());
    this.socket = socket;
    socket.addEventListener("open", () => {
      this.retryMs = FIRST_RETRY_MS;
      this.opened++;
      this.setState("open");
    });
    socket.addEventListener("message", (event) => this.events.onMessage(event.data));
    // A failed attempt fires "error" then "close"; "close" alone drives the retry.
    socket.addEventListener("close", () => {
      this.socket = null;
      this.setState("closed");
      window.setTimeout(() => this.connect(), this.retryMs);
      this.retryMs = Math.min(MAX_RETRY_MS, this.retryMs * 2);
    });
  }

  /** Sends a command; returns false (and logs) if there is no open connection. */
  send(command: BrowserCommand): boolean {
    if (this.socket?.readyState !== WebSocket.OPEN) {
      console.warn("EyeSim viewer: not connected, command dropped:", command);
      return false;
    }
    this.socket.send(JSON.stringify(command));
    return true;
  }

  private setState(state: ConnectionState): void {
    this.currentState = state;
    this.events.onState(state);
  }
}
