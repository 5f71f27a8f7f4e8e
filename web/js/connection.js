// The WebSocket to the daemon (docs/protocol.md): JSON text messages both ways, and every `frame`
// message from the server immediately followed by one binary message, its JPEG. Reconnects with
// exponential backoff; the server gives each new socket a fresh session, so the app re-sends its
// scene and settings when `hello` arrives again.

const CLOSE_NAMES = {
  1000: 'closed',
  1001: 'server shutting down',
  1006: 'connection lost',
  1007: 'a message was not UTF-8',
  1008: 'refused by the server (policy)',
  1009: 'message too big',
  1011: 'internal server error',
  1013: 'server busy (too many sessions)',
  4000: 'disconnected after being idle',
};

// Reconnect delays: start fast (a daemon restart takes a moment), cap so a long outage doesn't
// flood the log, and add jitter so many tabs don't reconnect in lockstep.
const BACKOFF_FIRST_MS = 500;
const BACKOFF_MAX_MS = 10000;

export function closeReason(code) {
  return CLOSE_NAMES[code] || `connection lost (code ${code})`;
}

export class Connection {
  // url: ws:// or wss:// address of /ws. handlers: { onStatus(status), onMessage(msg),
  // onFrame(meta, jpegBlob) }. status is { state: 'connecting' | 'open' | 'retrying' | 'stopped',
  // code?, reason?, retryInMs? }.
  constructor(url, handlers) {
    this.url = url;
    this.handlers = handlers;
    this.ws = null;
    this.delay = BACKOFF_FIRST_MS;
    this.retryTimer = null;
    this.pendingFrame = null; // the last `frame` message, waiting for its JPEG
    this.stopped = false;
  }

  connect() {
    this.stopped = false;
    clearTimeout(this.retryTimer);
    this.retryTimer = null;
    this.handlers.onStatus({ state: 'connecting' });
    const ws = new WebSocket(this.url);
    ws.binaryType = 'blob'; // createImageBitmap takes a Blob directly
    this.ws = ws;
    this.pendingFrame = null;
    let opened = false;

    ws.onopen = () => {
      opened = true;
      this.handlers.onStatus({ state: 'open' });
    };
    ws.onmessage = (event) => this.receive(event.data);
    // onerror is always followed by onclose, which does the work.
    ws.onclose = (event) => {
      if (this.ws !== ws) return; // an old socket replaced by reconnectNow()
      this.ws = null;
      this.pendingFrame = null;
      if (this.stopped) return;
      const code = opened ? event.code : 0;
      if (code === 4000) {
        // Idle timeout: the server freed our session on purpose; reconnecting at once would
        // defeat that, so wait for the user to come back (app calls reconnectNow()).
        this.stopped = true;
        this.handlers.onStatus({ state: 'stopped', code, reason: closeReason(code) });
        return;
      }
      this.scheduleRetry(code);
    };
  }

  scheduleRetry(code) {
    const wait = Math.round(this.delay * (0.8 + 0.4 * Math.random()));
    this.delay = Math.min(this.delay * 2, BACKOFF_MAX_MS);
    const reason = code === 0 ? 'server unreachable' : closeReason(code);
    this.handlers.onStatus({ state: 'retrying', code, reason, retryInMs: wait });
    this.retryTimer = setTimeout(() => this.connect(), wait);
  }

  // Called after a successful handshake (`hello`): the next outage starts with short delays again.
  resetBackoff() {
    this.delay = BACKOFF_FIRST_MS;
  }

  reconnectNow() {
    if (this.ws && this.ws.readyState <= WebSocket.OPEN) return;
    this.resetBackoff();
    this.connect();
  }

  get isOpen() {
    return this.ws !== null && this.ws.readyState === WebSocket.OPEN;
  }

  // Returns false when not connected: messages are not queued, since a move or a setting meant
  // for a session that is gone means nothing to the next one.
  send(message) {
    if (!this.isOpen) return false;
    this.ws.send(JSON.stringify(message));
    return true;
  }

  receive(data) {
    if (typeof data !== 'string') {
      // The JPEG of the preceding `frame` message. A JPEG with no frame before it (should not
      // happen) is dropped rather than shown with the wrong numbers.
      const meta = this.pendingFrame;
      this.pendingFrame = null;
      if (meta) this.handlers.onFrame(meta, data);
      return;
    }
    let msg;
    try {
      msg = JSON.parse(data);
    } catch {
      console.warn('geodesic: ignoring a text message that is not JSON');
      return;
    }
    if (msg === null || typeof msg !== 'object') return;
    if (msg.type === 'frame') {
      this.pendingFrame = msg; // a newer frame message replaces one whose JPEG never came
      return;
    }
    this.handlers.onMessage(msg);
  }
}

// The /ws address on the server that served this page (http -> ws, https -> wss).
export function defaultSocketUrl(location) {
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/ws`;
}
