// Camera controls: WASD moves forward/back and strafes, Q/E moves down/up, the arrow keys turn
// (yaw/pitch), and dragging on the view looks around. Every motion is in the camera's own frame,
// as the `move` message wants, so the server can carry the camera across the manifold's faces.
//
// Input is gathered and sent at most once per animation frame: each `move` resets the server's
// accumulation, so one message per displayed frame is plenty and spares the socket.
//
// Sign conventions (docs/scene-format.md): positive yaw turns left, positive pitch looks up.

const MOVE_KEYS = {
  KeyW: ['forward', 1], KeyS: ['forward', -1],
  KeyD: ['right', 1], KeyA: ['right', -1],
  KeyE: ['up', 1], KeyQ: ['up', -1],
};
const TURN_KEYS = {
  ArrowLeft: ['yaw', 1], ArrowRight: ['yaw', -1],
  ArrowUp: ['pitch', 1], ArrowDown: ['pitch', -1],
};

const TURN_DEGREES_PER_SECOND = 60;
const DRAG_DEGREES_PER_PIXEL = 0.25;
const SHIFT_FACTOR = 4;
// A key pressed and released between two animation frames still moves, by this much time's
// worth: a quick tap is a small step, not nothing.
const TAP_SECONDS = 1 / 20;
// Longest step from one animation frame to the next: a tab in the background gets few frames,
// and a held key should not jump the camera when it comes back.
const MAX_STEP_SECONDS = 0.1;

export class Controls {
  // view: the element that takes mouse drags. sendMove(fields): sends one `move` message.
  // speed(): geodesic length per second.
  constructor(view, sendMove, speed) {
    this.view = view;
    this.sendMove = sendMove;
    this.speed = speed;
    this.held = new Map(); // code -> true once an animation frame has moved by it
    this.taps = [];        // codes released before any animation frame saw them
    this.shift = false;
    this.drag = null;      // last pointer position while dragging
    this.dragDx = 0;
    this.dragDy = 0;
    this.lastTime = null;
    this.enabled = true;

    window.addEventListener('keydown', (e) => this.onKeyDown(e));
    window.addEventListener('keyup', (e) => this.onKeyUp(e));
    // Keys released while the window has no focus never send keyup: forget them all.
    window.addEventListener('blur', () => this.held.clear());

    view.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      this.drag = { x: e.clientX, y: e.clientY };
      view.setPointerCapture(e.pointerId);
      view.classList.add('dragging');
      e.preventDefault();
    });
    view.addEventListener('pointermove', (e) => {
      if (!this.drag) return;
      this.dragDx += e.clientX - this.drag.x;
      this.dragDy += e.clientY - this.drag.y;
      this.drag = { x: e.clientX, y: e.clientY };
    });
    const endDrag = () => {
      this.drag = null;
      view.classList.remove('dragging');
    };
    view.addEventListener('pointerup', endDrag);
    view.addEventListener('pointercancel', endDrag);

    requestAnimationFrame((t) => this.tick(t));
  }

  // Keys typed into the scene picker or a number field are theirs, not the camera's.
  static isFormControl(target) {
    return target instanceof HTMLElement &&
      (target.isContentEditable || ['INPUT', 'SELECT', 'TEXTAREA'].includes(target.tagName));
  }

  onKeyDown(e) {
    this.shift = e.shiftKey;
    if (e.ctrlKey || e.metaKey || e.altKey || Controls.isFormControl(e.target)) return;
    if (!(e.code in MOVE_KEYS || e.code in TURN_KEYS)) return;
    e.preventDefault(); // arrows would scroll the page
    if (!this.held.has(e.code)) this.held.set(e.code, false);
  }

  onKeyUp(e) {
    this.shift = e.shiftKey;
    if (!this.held.has(e.code)) return;
    if (this.held.get(e.code) === false) this.taps.push(e.code);
    this.held.delete(e.code);
  }

  tick(time) {
    const dt = this.lastTime === null ? 0 : Math.min((time - this.lastTime) / 1000, MAX_STEP_SECONDS);
    this.lastTime = time;
    requestAnimationFrame((t) => this.tick(t));

    const move = { forward: 0, right: 0, up: 0, yaw: 0, pitch: 0 };
    const factor = this.shift ? SHIFT_FACTOR : 1;
    const apply = (code, seconds) => {
      if (code in MOVE_KEYS) {
        const [axis, sign] = MOVE_KEYS[code];
        move[axis] += sign * this.speed() * factor * seconds;
      } else {
        const [axis, sign] = TURN_KEYS[code];
        move[axis] += sign * TURN_DEGREES_PER_SECOND * factor * seconds;
      }
    };
    for (const [code, seen] of this.held) {
      apply(code, seen ? dt : Math.max(dt, TAP_SECONDS));
      this.held.set(code, true);
    }
    for (const code of this.taps) apply(code, TAP_SECONDS);
    this.taps = [];

    // Dragging moves the view with the pointer: drag right turns right, drag up looks up.
    move.yaw -= this.dragDx * DRAG_DEGREES_PER_PIXEL;
    move.pitch -= this.dragDy * DRAG_DEGREES_PER_PIXEL;
    this.dragDx = 0;
    this.dragDy = 0;

    if (!this.enabled) return;
    // Only the axes that changed: a smaller message, and the protocol allows any subset.
    const fields = {};
    for (const [axis, value] of Object.entries(move)) {
      if (value !== 0) fields[axis] = value;
    }
    if (Object.keys(fields).length > 0) this.sendMove(fields);
  }
}
