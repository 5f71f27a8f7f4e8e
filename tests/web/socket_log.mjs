// The web walkthrough's record of the page's WebSocket messages (walkthrough.test.mjs): every
// JSON text message in order, and which scene each received frame belongs to.

// Keeps every JSON text message of the page's WebSockets (the JPEGs are binary and skipped).
export function recordSocket(p, log) {
  p.on('websocket', (ws) => {
    ws.on('framesent', (f) => push('sent', f.payload));
    ws.on('framereceived', (f) => push('received', f.payload));
  });
  function push(dir, payload) {
    if (typeof payload !== 'string') return;
    try {
      log.push({ dir, msg: JSON.parse(payload) });
    } catch {
      // not JSON: the test only reads JSON messages
    }
  }
}

// The scene each received frame belongs to (by frame number), from the log recordSocket keeps:
// frames follow their scene's `scene` message, but one frame of the old scene, already on its
// way, may come right after it (the page drops it); it continues the old accumulation rather
// than starting anew.
export function frameScenes(wsLog) {
  const byFrame = new Map();
  let scene = null;
  let next = null; // the scene named by a `scene` message, until its first frame
  let last = null;
  for (const { dir, msg } of wsLog) {
    if (dir !== 'received') continue;
    if (msg.type === 'scene') next = msg.name;
    if (msg.type !== 'frame') continue;
    const continues = last !== null && msg.spp > last.spp && msg.elapsed > last.elapsed;
    if (next !== null && !(continues && scene !== null)) {
      scene = next;
      next = null;
    }
    byFrame.set(msg.frame, { scene, spp: msg.spp, moving: msg.moving, width: msg.width, height: msg.height });
    last = msg;
  }
  return byFrame;
}
