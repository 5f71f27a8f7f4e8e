// Wires the client together: the connection, the viewer, the camera controls, the convergence
// read-out and the side panel. The server owns the truth (scene, camera, accumulation); this
// page keeps only what the user asked for (`wanted`), so it can ask again when a reconnect
// starts a fresh session.
//
// URL parameters set the starting point, e.g. ?scene=torus-cornell&width=320&height=240&depth=3
// &exposure=1.5 (or exposure=auto),
// and ?token=... is the daemon's token when it has one (for the WebSocket and the jobs API).

import { Connection, defaultSocketUrl } from './connection.js';
import { Viewer } from './viewer.js';
import { Controls } from './controls.js';
import { Stats } from './stats.js';
import { JobsPanel } from './jobs.js';
import { ExposureControl } from './exposure.js';

const $ = (id) => document.getElementById(id);
const clamp = (v, lo, hi) => Math.min(hi, Math.max(lo, v));

const ui = {
  status: $('status'),
  title: $('scene-title'),
  canvas: $('view'),
  errors: $('errors'),
  picker: $('scene-picker'),
  generatorFile: $('generator-file'),
  width: $('width'),
  height: $('height'),
  depth: $('depth'),
  speed: $('speed'),
  jobButton: $('render-job'),
  jobStatus: $('job-status'),
  jobList: $('job-list'),
  jobSpp: $('job-spp'),
};

const MAX_ERRORS_SHOWN = 3;

// What the user asked for; null means "whatever the scene says".
const params = new URLSearchParams(location.search);
const intParam = (name) => {
  const v = Number.parseInt(params.get(name) ?? '', 10);
  return Number.isFinite(v) ? v : null;
};
function exposureParam(text) {
  if (text === 'auto') return 'auto';
  const v = Number.parseFloat(text ?? '');
  return Number.isFinite(v) ? clamp(v, -20, 20) : null;
}
const wanted = {
  scene: params.get('scene'),
  generators: null, // the text of a dropped .gen file, while its space is what we want
  width: intParam('width'),
  height: intParam('height'),
  max_depth: intParam('depth'),
  exposure: exposureParam(params.get('exposure')), // stops, 'auto', or null
};

let limits = null;        // the server's (`hello`): nothing is sent or clamped before it comes
let currentScene = null; // the last `scene` message
let lastFrame = null;    // the last `frame` message (its camera goes into render jobs)
let openPending = false; // an `open` sent and not yet answered by `scene` or `error`
let openGenerators = null; // the generator text of the scene rendering now, if it came from one
let sceneJustChanged = false; // a `scene` message came and no frame since

const viewer = new Viewer(ui.canvas);
const stats = new Stats(
  {
    rate: $('stat-rate'),
    spp: $('stat-spp'),
    elapsed: $('stat-elapsed'),
    error: $('stat-error'),
    nonFinite: $('stat-nonfinite'),
    truncated: $('stat-truncated'),
    mode: $('stat-mode'),
  },
  $('error-plot'),
);

// Browsers cannot set headers on a WebSocket: the token goes as a query parameter.
const token = params.get('token');
const socketUrl = defaultSocketUrl(location) + (token ? `?token=${encodeURIComponent(token)}` : '');
const connection = new Connection(socketUrl, {
  onStatus: showStatus,
  onMessage: handleMessage,
  onFrame: handleFrame,
});

const controls = new Controls(
  ui.canvas,
  (fields) => connection.send({ type: 'move', ...fields }),
  () => {
    const v = Number.parseFloat(ui.speed.value);
    return Number.isFinite(v) && v > 0 ? v : 1;
  },
);

// ---- status banner ------------------------------------------------------------------------

let countdown = null; // interval that counts down to the next reconnect attempt

function showStatus(status) {
  clearInterval(countdown);
  ui.status.dataset.state = status.state;
  document.body.dataset.connection = status.state; // style.css dims the stale image
  controls.enabled = status.state === 'open';
  switch (status.state) {
    case 'connecting':
      ui.status.textContent = 'connecting…';
      break;
    case 'open':
      ui.status.textContent = 'connected';
      break;
    case 'retrying': {
      const at = Date.now() + status.retryInMs;
      const show = () => {
        const seconds = Math.max(1, Math.ceil((at - Date.now()) / 1000));
        ui.status.textContent = `${status.reason} — retrying in ${seconds} s`;
      };
      show();
      countdown = setInterval(show, 250);
      break;
    }
    case 'stopped':
      ui.status.textContent = `${status.reason} — click to reconnect`;
      break;
    default:
      ui.status.textContent = status.state;
  }
}

// After an idle timeout the page waits for the user: any click or key brings the session back.
function reconnectIfStopped() {
  if (ui.status.dataset.state === 'stopped') connection.reconnectNow();
}
ui.status.addEventListener('click', reconnectIfStopped);
window.addEventListener('pointerdown', reconnectIfStopped);
window.addEventListener('keydown', reconnectIfStopped);

// ---- server messages ----------------------------------------------------------------------

function handleMessage(msg) {
  switch (msg.type) {
    case 'hello':
      onHello(msg);
      break;
    case 'scene':
      onScene(msg);
      break;
    case 'error':
      showError(msg.field, msg.message);
      if (openPending) {
        // A failed `open` leaves the old scene in place: stop asking for the new one (a
        // reconnect would ask again) and put the picker back to match.
        openPending = false;
        wanted.scene = currentScene?.source === 'bundled' ? currentScene.name : null;
        wanted.generators = openGenerators;
        if (currentScene) {
          selectScene(currentScene);
          applyWantedSettings(currentScene); // skipped while the open was pending
        }
      }
      break;
    default:
      // Unknown types are ignored, so a newer server can add messages without breaking us.
      break;
  }
}

function onHello(msg) {
  connection.resetBackoff();
  ui.status.textContent = msg.session !== undefined ? `connected · session ${msg.session}` : 'connected';
  limits = msg.limits;
  for (const [input, max] of [[ui.width, limits.max_width], [ui.height, limits.max_height], [ui.depth, limits.max_depth]]) {
    input.max = String(max);
    input.disabled = false;
  }

  const scenes = Array.isArray(msg.scenes) ? msg.scenes : [];
  ui.picker.replaceChildren(...scenes.map((name) => new Option(name, name)));
  ui.picker.disabled = scenes.length === 0;
  viewer.reset(); // a new session numbers its frames afresh
  lastFrame = null;

  // The new session starts on the default scene: ask again for what the user had chosen.
  if (wanted.generators) openSpace(wanted.generators);
  else if (wanted.scene) openScene(wanted.scene);
}

function openScene(name) {
  wanted.scene = name;
  wanted.generators = null;
  openPending = connection.send({ type: 'open', scene: name });
}

// A space given by generators: the server builds its Dirichlet domain and a default scene in
// it, named by the text's first comment line (or `generators`).
function openSpace(text) {
  wanted.scene = null;
  wanted.generators = text;
  openPending = connection.send({ type: 'open', generators: text });
}

function onScene(msg) {
  currentScene = msg;
  sceneJustChanged = true;
  // The server says how the scene was given (`source`): bundled, a document, or generators.
  const fromGenerators = msg.source === 'generators';
  const isWanted = wanted.generators ? fromGenerators : msg.source === 'bundled' && msg.name === wanted.scene;
  if (isWanted) openPending = false;
  openGenerators = fromGenerators ? wanted.generators : null;
  stats.reset();
  clearErrors();
  selectScene(msg);
  const where = [msg.geometry, msg.manifold].filter((v) => v && v !== 'none').join(', ');
  ui.title.textContent = where ? `${msg.name} — ${where}` : msg.name;
  ui.title.title = msg.title; // the document's own description

  // A fresh session's default scene, with our own `open` already on its way: its settings would
  // be replaced at once, so don't send any.
  if (!(openPending && !isWanted)) applyWantedSettings(msg);
}

// Opening a scene brings that scene's own render settings; re-apply the user's, if any.
function applyWantedSettings(msg) {
  // URL parameters are unchecked until the server's limits are known.
  if (wanted.width !== null) wanted.width = clamp(wanted.width, 16, limits.max_width);
  if (wanted.height !== null) wanted.height = clamp(wanted.height, 16, limits.max_height);
  if (wanted.max_depth !== null) wanted.max_depth = clamp(wanted.max_depth, 0, limits.max_depth);
  const settings = {};
  if (wanted.width !== null && wanted.width !== msg.width) settings.width = wanted.width;
  if (wanted.height !== null && wanted.height !== msg.height) settings.height = wanted.height;
  if (wanted.max_depth !== null && wanted.max_depth !== msg.max_depth) settings.max_depth = wanted.max_depth;
  if (wanted.exposure !== null && wanted.exposure !== msg.exposure) settings.exposure = wanted.exposure;
  if (Object.keys(settings).length > 0) connection.send({ type: 'settings', ...settings });
  exposure.show(wanted.exposure ?? msg.exposure);

  ui.width.value = String(wanted.width ?? msg.width);
  ui.height.value = String(wanted.height ?? msg.height);
  ui.depth.value = String(wanted.max_depth ?? msg.max_depth);
}

function selectScene(scene) {
  // Only a bundled scene is one of the picker's; for a document or a space from generators the
  // picker shows no choice (and picking any scene then changes it).
  if (scene.source === 'bundled') ui.picker.value = scene.name;
  else ui.picker.selectedIndex = -1;
}

function handleFrame(meta, jpeg) {
  // One frame of the old scene may still arrive after the `scene` message (it was on its way
  // when the scene changed); it continues the old accumulation instead of starting anew. Drop
  // it rather than flash the old image and its numbers. At most one frame is in flight, so
  // at most one is dropped.
  if (sceneJustChanged) {
    sceneJustChanged = false;
    if (lastFrame && meta.spp > lastFrame.spp && meta.elapsed > lastFrame.elapsed) return;
  }
  lastFrame = meta;
  exposure.showFrame(meta.exposure);
  viewer.show(meta, jpeg);
  stats.update(meta);
}

// ---- errors -------------------------------------------------------------------------------

function showError(field, message) {
  const item = document.createElement('div');
  const dismiss = document.createElement('button');
  dismiss.type = 'button';
  dismiss.textContent = '×';
  dismiss.title = 'Dismiss';
  dismiss.addEventListener('click', () => {
    item.remove();
    ui.errors.hidden = ui.errors.childElementCount === 0;
  });
  item.append(dismiss);
  if (field) {
    const code = document.createElement('code');
    code.textContent = field;
    item.append(code, ': ');
  }
  item.append(message || 'unknown error');
  ui.errors.append(item);
  while (ui.errors.childElementCount > MAX_ERRORS_SHOWN) ui.errors.firstElementChild.remove();
  ui.errors.hidden = false;
}

function clearErrors() {
  ui.errors.replaceChildren();
  ui.errors.hidden = true;
}

// ---- panel --------------------------------------------------------------------------------

// A .gen file picked or dropped on the view opens its space.
function openGeneratorFile(file) {
  if (!file) return;
  file.text().then(openSpace, (e) => showError('generators', `${file.name}: ${e.message}`));
  ui.canvas.focus();
}
ui.generatorFile.addEventListener('change', () => openGeneratorFile(ui.generatorFile.files[0]));
ui.canvas.addEventListener('dragover', (e) => e.preventDefault());
ui.canvas.addEventListener('drop', (e) => {
  e.preventDefault();
  openGeneratorFile(e.dataTransfer.files[0]);
});

ui.picker.addEventListener('change', () => {
  openScene(ui.picker.value);
  // Hand the keyboard back to the view, so WASD moves the camera rather than the picker.
  ui.canvas.focus();
});

// Reads a number field, clamped to its range; writes the clamped value back so the field
// shows what was sent.
function readInt(input, min, max) {
  const v = Number.parseInt(input.value, 10);
  if (!Number.isFinite(v)) return null;
  const clamped = clamp(v, min, max);
  input.value = String(clamped);
  return clamped;
}

function sendSettings(field, value) {
  if (value === null) return;
  wanted[field] = value;
  connection.send({ type: 'settings', [field]: value });
}
// The fields are disabled until `hello` brings the server's limits.
ui.width.addEventListener('change', () => sendSettings('width', readInt(ui.width, 16, limits.max_width)));
ui.height.addEventListener('change', () => sendSettings('height', readInt(ui.height, 16, limits.max_height)));
ui.depth.addEventListener('change', () => sendSettings('max_depth', readInt(ui.depth, 0, limits.max_depth)));
const exposure = new ExposureControl(
  { slider: $('exposure'), value: $('exposure-value'), auto: $('exposure-auto') },
  (value) => sendSettings('exposure', value),
);

// Render jobs render the current view offline at full quality (web/js/jobs.js).
const jobs = new JobsPanel(
  { button: ui.jobButton, status: ui.jobStatus, list: ui.jobList, spp: ui.jobSpp },
  token,
);
ui.jobButton.addEventListener('click', () =>
  jobs.submit({
    // What is rendering now: a bundled scene, or the space of a dropped generator file.
    ...(openGenerators ? { generators: openGenerators } : { scene: currentScene?.name ?? wanted.scene ?? null }),
    camera: lastFrame?.camera ?? null,
    width: Number.parseInt(ui.width.value, 10),
    height: Number.parseInt(ui.height.value, 10),
    max_depth: Number.parseInt(ui.depth.value, 10),
    exposure: exposure.value,
  }),
);
jobs.start();

// For debugging from the console.
window.geodesic = { connection, viewer, stats, controls, wanted, jobs, exposure };

connection.connect();
