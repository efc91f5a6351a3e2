"""The browser viewer: HTTP + WebSocket server; built assets in static/."""
