// A walk through the web client in real headless Chromium (Debian's /usr/bin/chromium, driven
// by playwright-core) against a running `geodesic serve`: the page connects, frames appear and
// refine, W moves the camera, the picker switches scenes, a bad scene shows its error, a render
// job runs to its files and another is cancelled, and a dead server shows the "unreachable"
// banner.
//
// Run through tests/web/run.sh, which starts the daemon and sets:
//   GEODESIC_URL    the daemon's http://host:port (required)
//   GEODESIC_PID    its process id: the last test kills it to see the banner (skipped without)
//   GEODESIC_MAX_DEPTH  the daemon's --max-depth (required): the page must take it from `hello`
//   SCREENSHOT_DIR  where screenshots go (default build/web-screenshots/)
//   CHROMIUM        the browser (default /usr/bin/chromium)

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { canvasBlocks, canvasCodes, meanAbsDiff, toCode, toLinear } from './canvas.mjs';
import { frameScenes, recordSocket } from './socket_log.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const BASE = process.env.GEODESIC_URL;
const SCREENSHOT_DIR = process.env.SCREENSHOT_DIR || path.resolve(here, '../../build/web-screenshots');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
// Small frames keep lavapipe quick; the page's URL parameters set them before the first frame.
const START = '/?width=160&height=120&depth=2';
// Everything waits on a software renderer that may share two cores with other tests.
const FRAME_TIMEOUT = 60_000;

if (!BASE) throw new Error('GEODESIC_URL is not set: run tests/web/run.sh');
const MAX_DEPTH = Number(process.env.GEODESIC_MAX_DEPTH);
if (!Number.isInteger(MAX_DEPTH)) throw new Error('GEODESIC_MAX_DEPTH is not set: run tests/web/run.sh');

let userDataDir;
let context;
let page;
const wsLog = []; // { dir: 'sent' | 'received', msg } for every JSON message on the socket
const sentJobs = []; // the bodies the page POSTed to /api/jobs
const pageErrors = []; // uncaught exceptions in the page

before(async () => {
  fs.mkdirSync(SCREENSHOT_DIR, { recursive: true });
  userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'geodesic-chromium-'));
  // The flags keep Chromium off the network (this machine has none but loopback) and off the
  // sandbox (we run as root); a fresh profile so no state leaks between runs.
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1100, height: 700 },
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
    ],
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.on('console', (m) => {
    // The test's own pixel reads cause a getImageData performance hint: not the page's fault.
    if (m.text().includes('willReadFrequently')) return;
    if (m.type() === 'error' || m.type() === 'warning') console.log(`[page ${m.type()}] ${m.text()}`);
  });
  page.on('pageerror', (err) => {
    console.log(`[page exception] ${err.message}`);
    pageErrors.push(err.message);
  });
  recordSocket(page, wsLog);
  page.on('request', (r) => {
    if (r.method() === 'POST' && new URL(r.url()).pathname === '/api/jobs') sentJobs.push(JSON.parse(r.postData()));
  });
});

after(async () => {
  await context?.close();
  if (userDataDir) fs.rmSync(userDataDir, { recursive: true, force: true });
});

const sentOfType = (type) => wsLog.filter((e) => e.dir === 'sent' && e.msg.type === type).map((e) => e.msg);
const receivedOfType = (type) =>
  wsLog.filter((e) => e.dir === 'received' && e.msg.type === type).map((e) => e.msg);

const shownFrame = (p) => p.evaluate(() => Number(document.getElementById('view').dataset.frame ?? -1));

// Waits until the canvas shows a frame at least `minSpp` samples deep that satisfies `accept`
// (given the frame's { scene, spp, moving }): the frames on the canvas and on the socket are
// matched by their frame numbers.
// An `error` from the server meanwhile ends the wait at once, with its text; a timeout says
// what the page last sent and received.
async function waitForShownFrame(p, minSpp, accept = () => true, timeout = FRAME_TIMEOUT) {
  const deadline = Date.now() + timeout;
  const logStart = wsLog.length;
  for (;;) {
    const n = await shownFrame(p);
    const info = frameScenes(wsLog).get(n);
    if (info && !info.moving && info.spp >= minSpp && accept({ frame: n, ...info })) return { frame: n, ...info };
    const error = wsLog.slice(logStart).find((e) => e.dir === 'received' && e.msg.type === 'error');
    if (error) throw new Error(`the server answered an error while the test waited for a frame: ${JSON.stringify(error.msg)}`);
    if (Date.now() > deadline) {
      const seen = wsLog.slice(logStart).filter((e) => e.dir === 'sent' || e.msg.type !== 'frame');
      const last = seen.slice(-6).map((e) => `${e.dir} ${JSON.stringify(e.msg).slice(0, 120)}`);
      throw new Error(`no frame with spp >= ${minSpp} shown in ${timeout} ms (showing ${n}: ${JSON.stringify(info)}); ` +
                      `messages other than frames since the wait began: ${last.join(' | ') || 'none'}`);
    }
    await p.waitForTimeout(100);
  }
}

const statSpp = (p) => p.evaluate(() => Number(document.getElementById('stat-spp').textContent));

test('the page loads, connects and shows a frame', async () => {
  await page.goto(BASE + START);
  assert.equal(await page.title(), 'Geodesic');
  // The picker fills from the `hello` message's scenes.
  await page.waitForSelector('#scene-picker:not([disabled])', { timeout: FRAME_TIMEOUT });
  assert.equal(await page.getAttribute('#status', 'data-state'), 'open');
  const hello = receivedOfType('hello')[0];
  assert.ok(hello, 'no hello message');
  const options = await page.$$eval('#scene-picker option', (os) => os.map((o) => o.value));
  assert.deepEqual(options, hello.scenes);
  assert.ok(options.includes('cornell-box'));
  // The depth field's bound is the server's, from `hello`.
  assert.equal(await page.getAttribute('#depth', 'max'), String(hello.limits.max_depth));

  // The default scene's first frames may come at its own resolution, before our settings.
  const shown = await waitForShownFrame(page, 1, (f) => f.width === 160 && f.height === 120);
  const img = await canvasBlocks(page);
  assert.deepEqual([img.width, img.height], [160, 120], 'the URL parameters set 160x120');
  assert.ok(img.max > 20, `the canvas is blank (brightest pixel ${img.max})`);
  const spread = Math.max(...img.blocks) - Math.min(...img.blocks);
  assert.ok(spread > 5, `the canvas is flat (block spread ${spread})`);
  assert.equal(shown.scene, 'cornell-box', 'the default scene streams first');
  // The page asked for the small resolution itself.
  assert.ok(sentOfType('settings').some((m) => m.width === 160 && m.height === 120));
});

test('samples accumulate while the camera is still', async () => {
  const first = await statSpp(page);
  await page.waitForFunction((n) => Number(document.getElementById('stat-spp').textContent) > n, first, {
    timeout: FRAME_TIMEOUT,
  });
  // Two samples give an error estimate, and the log-log plot starts.
  await page.waitForFunction(() => document.getElementById('stat-error').textContent.includes('%'), null, {
    timeout: FRAME_TIMEOUT,
  });
  const rate = await page.textContent('#stat-rate');
  assert.match(rate, /samples\/s$/);
  // The dropped-sample and cut-off-geodesic counts are shown as the frames give them (the
  // Cornell box has no faces to cross: both are 0).
  const frames = receivedOfType('frame');
  assert.equal(frames.at(-1).non_finite_samples, 0);
  assert.equal(frames.at(-1).truncated_geodesics, 0);
  assert.equal(await page.textContent('#stat-nonfinite'), '0');
  assert.equal(await page.textContent('#stat-truncated'), '0');
});

test('the server says what the scene is and bounds depth; the page uses both', async () => {
  // hello carries the daemon's --max-depth, not the default 16.
  const hello = receivedOfType('hello')[0];
  assert.equal(hello.limits.max_depth, MAX_DEPTH);
  assert.notEqual(MAX_DEPTH, 16, 'run.sh starts the daemon with a non-default --max-depth');
  // The default scene is a bundled one, and says so; the picker shows it.
  const scene = receivedOfType('scene')[0];
  assert.equal(scene.source, 'bundled');
  assert.equal(scene.name, 'cornell-box');
  assert.match(scene.title, /^Cornell box/);
  assert.equal(await page.inputValue('#scene-picker'), 'cornell-box');
  assert.equal(await page.getAttribute('#scene-title', 'title'), scene.title);
  // A depth past the server's limit is clamped to it, and the clamped depth is what is sent.
  await page.fill('#depth', String(MAX_DEPTH + 20));
  await page.press('#depth', 'Enter');
  await waitFor(() => sentOfType('settings').some((m) => m.max_depth === MAX_DEPTH), `settings {max_depth: ${MAX_DEPTH}}`);
  assert.equal(await page.inputValue('#depth'), String(MAX_DEPTH));
  assert.ok(!sentOfType('settings').some((m) => m.max_depth > MAX_DEPTH), 'a depth over the limit was sent');
  assert.ok(!receivedOfType('error').some((m) => m.field === 'max_depth'), 'the server refused a depth');
});

test('the depth control sends settings', async () => {
  const before = await waitForShownFrame(page, 24);
  await page.fill('#depth', '3');
  await page.press('#depth', 'Enter');
  await waitFor(() => sentOfType('settings').some((m) => m.max_depth === 3), 'settings {max_depth: 3}');
  // The server starts the accumulation again at the new depth. The next test compares two frames
  // of one accumulation: wait until the new one is on the canvas, not a frame from before.
  await waitForShownFrame(page, 1, (f) => f.frame > before.frame && f.spp < before.spp);
});

// Sets the slider as a user's drag ends on `stops`.
const setExposure = (p, stops) =>
  p.evaluate((v) => {
    const slider = document.getElementById('exposure');
    slider.value = String(v);
    slider.dispatchEvent(new Event('input', { bubbles: true }));
  }, stops);
const frameMessage = (n) => receivedOfType('frame').find((f) => f.frame === n);
test('the exposure slider brightens the view at once and auto follows the frames', async () => {
  const still = await waitForShownFrame(page, 16, (f) => frameMessage(f.frame)?.exposure === 0);
  const before = await canvasCodes(page);
  await setExposure(page, 2);
  assert.equal(await page.textContent('#exposure-value'), '+2.00');
  await waitFor(() => sentOfType('settings').some((m) => m.exposure === 2), 'settings {exposure: 2}');
  // The last frame comes again with the new exposure: the accumulation goes on, not over.
  const bright = await waitForShownFrame(page, still.spp, (f) => frameMessage(f.frame)?.exposure === 2);
  const after = await canvasCodes(page);
  // Each code is the old one's radiance times 4 through the sRGB curve, within the JPEG's
  // error; the same accumulation when no pass completed in between. Held the other way round,
  // each new code brought back by 1/4 against the old one: times 4 multiplies the old frame's
  // JPEG error by up to 4 in the dark codes, where the sRGB curve is linear (a mean code of 31
  // was off by 5.4 that way), and 1/4 divides the new frame's. Codes clipped at white measure
  // nothing and are left out.
  const predicted = before.map((c) => toCode(4 * toLinear(c)));
  const mean = (a) => a.reduce((s, v) => s + v, 0) / a.length;
  const measured = after.map((c, i) => [c, before[i]]).filter(([c]) => c < 255);
  const off = mean(measured.map(([c, b]) => Math.abs(toCode(toLinear(c) / 4) - b)));
  console.log(`# exposure +2: mean code ${mean(before).toFixed(1)} -> ${mean(after).toFixed(1)} (predicted ${mean(predicted).toFixed(1)}, off by ${off.toFixed(2)}), spp ${still.spp} -> ${bright.spp}`);
  assert.ok(mean(predicted) > 1.5 * mean(before), 'a view this bright cannot show +2 stops');
  assert.ok(off < (bright.spp === still.spp ? 3 : 8), `codes off the 4x prediction by ${off} on average`);
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-exposure.png') });

  await page.check('#exposure-auto');
  await waitFor(() => sentOfType('settings').some((m) => m.exposure === 'auto'), "settings {exposure: 'auto'}");
  assert.equal(await page.isDisabled('#exposure'), true, 'the slider is the automatic one now');
  const auto = await waitForShownFrame(page, 1, (f) => {
    const e = frameMessage(f.frame)?.exposure;
    return e !== undefined && e !== 2;
  });
  const stops = frameMessage(auto.frame).exposure;
  await page.waitForFunction((v) => Math.abs(Number(document.getElementById('exposure').value) - v) < 0.25, stops);

  // Back to the scene's own exposure for the tests that follow.
  await page.uncheck('#exposure-auto');
  await setExposure(page, 0);
  await waitForShownFrame(page, 1, (f) => frameMessage(f.frame)?.exposure === 0);
});

test('W moves the camera forward and the image changes', async () => {
  // A reference image deep enough that its noise is small beside a change of view.
  const still = await waitForShownFrame(page, 8);
  const before = await canvasBlocks(page);
  // Noise floor: the same view a few samples later.
  await waitForShownFrame(page, still.spp + 4, (f) => f.scene === 'cornell-box');
  const noise = meanAbsDiff(before, await canvasBlocks(page));

  const movesBefore = sentOfType('move').length;
  await page.focus('#view');
  await page.keyboard.down('KeyW');
  await page.waitForTimeout(400);
  await page.keyboard.up('KeyW');
  const moves = sentOfType('move').slice(movesBefore);
  assert.ok(moves.length > 0, 'no move message sent');
  const forward = moves.reduce((s, m) => s + (m.forward ?? 0), 0);
  assert.ok(forward > 0.1, `moved forward by only ${forward}`);
  assert.ok(moves.every((m) => m.right === undefined && m.yaw === undefined), 'W moves straight ahead');

  // The server resets accumulation; wait for the new view to refine as far as the old one. The
  // frame already on its way when the last move went out (at most one is in flight) may still
  // show an older view, so only the frames after it count.
  const lastMove = wsLog.findLastIndex((e) => e.dir === 'sent' && e.msg.type === 'move');
  const after = await waitForShownFrame(page, 8, (f) => framesAfter(lastMove).slice(1).includes(f.frame));
  const changed = meanAbsDiff(before, await canvasBlocks(page));
  console.log(`# move: forward ${forward.toFixed(3)} in ${moves.length} messages, block diff ${changed.toFixed(2)} (noise ${noise.toFixed(2)}), frame ${after.frame}`);
  assert.ok(changed > Math.max(3 * noise, 2), `the image barely changed: ${changed} (noise ${noise})`);
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-moved.png') });
});

// Frame numbers received after wsLog index `index`.
function framesAfter(index) {
  return wsLog.slice(index + 1).filter((e) => e.dir === 'received' && e.msg.type === 'frame').map((e) => e.msg.frame);
}

async function waitFor(predicate, what, timeout = 10_000) {
  const deadline = Date.now() + timeout;
  while (!predicate()) {
    if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

test('dragging the view turns the camera', async () => {
  const box = await page.locator('#view').boundingBox();
  const movesBefore = sentOfType('move').length;
  const x = box.x + box.width / 2;
  const y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 1; i <= 5; i++) {
    await page.mouse.move(x + 8 * i, y - 2 * i);
    await page.waitForTimeout(20);
  }
  await page.mouse.up();
  await waitFor(() => sentOfType('move').length > movesBefore, 'a move from the drag');
  await page.waitForTimeout(100); // the last animation frame's batch
  const moves = sentOfType('move').slice(movesBefore);
  const yaw = moves.reduce((s, m) => s + (m.yaw ?? 0), 0);
  const pitch = moves.reduce((s, m) => s + (m.pitch ?? 0), 0);
  // Drag right turns right (negative yaw), drag up looks up (positive pitch); no translation.
  assert.ok(yaw < -5 && pitch > 1, `drag gave yaw ${yaw}, pitch ${pitch}`);
  assert.ok(moves.every((m) => m.forward === undefined && m.right === undefined && m.up === undefined));
});

test('the scene picker switches scenes and the image changes', async () => {
  const before = await canvasBlocks(page);
  const options = await page.$$eval('#scene-picker option', (os) => os.map((o) => o.value));
  // A scene that looks nothing like the Cornell box.
  const target = ['poincare-sphere', 'hyperbolic-spheres', 'mirrored-dodecahedron', 'torus-cornell']
    .find((s) => options.includes(s)) ?? options.find((s) => s !== 'cornell-box');
  assert.ok(target, 'only one scene to pick');

  await page.selectOption('#scene-picker', target);
  await waitFor(() => sentOfType('open').some((m) => m.scene === target), `open ${target}`);
  const shown = await waitForShownFrame(page, 4, (f) => f.scene === target);
  const scene = receivedOfType('scene').at(-1);
  assert.equal(scene.name, target);
  assert.equal(await page.inputValue('#scene-picker'), target);
  assert.match(await page.textContent('#scene-title'), new RegExp(target));
  // The cut-off count on the page is one a frame of this scene gave (a quotient may cut some).
  const truncated = Number(await page.textContent('#stat-truncated'));
  const counts = receivedOfType('frame').map((f) => f.truncated_geodesics);
  assert.ok(counts.includes(truncated), `page shows ${truncated}, frames gave ${counts.slice(-5)}`);

  const img = await canvasBlocks(page);
  assert.deepEqual([img.width, img.height], [160, 120], 'the page re-applies its resolution to the new scene');
  const changed = meanAbsDiff(before, img);
  console.log(`# scene ${target}: block diff ${changed.toFixed(2)}, frame ${shown.frame} at ${shown.spp} spp`);
  assert.ok(changed > 2, `the image did not change with the scene: ${changed}`);
  // Let the error plot gather a few points for the screenshot.
  await waitForShownFrame(page, 8, (f) => f.scene === target, 15_000).catch(() => {});
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough.png') });
});

// Submits the current view as a render job from the panel; its id.
async function submitJob(spp) {
  await page.fill('#job-spp', String(spp));
  await page.click('#render-job');
  await page.waitForFunction(
    () => !['', 'submitting…'].includes(document.getElementById('job-status').textContent),
    null,
    { timeout: 10_000 },
  );
  const text = await page.textContent('#job-status');
  const match = /^render job (\d+) queued$/.exec(text);
  assert.ok(match, `the job was not queued: "${text}"`);
  return match[1];
}

test('a render job runs to its files, another is cancelled', async () => {
  // Two samples: the scene the walk switched to (a quotient manifold) is slow on lavapipe, and
  // the job shares the device with the session.
  const done = await submitJob(2);
  // The list shows it with its progress, then links its results.
  const item = `#job-list li[data-id="${done}"]`;
  await page.waitForSelector(`${item}[data-state="done"] a:text("png")`, { timeout: 120_000 });
  assert.match(await page.textContent(`${item} .job-state`), /^done · 2 spp/);
  const href = await page.getAttribute(`${item} a:text("png")`, 'href');
  const png = await page.request.get(`${BASE}${href}`);
  assert.equal(png.status(), 200);
  assert.equal(png.headers()['content-type'], 'image/png');
  const bytes = await png.body();
  assert.deepEqual([...bytes.subarray(1, 4)], [0x50, 0x4e, 0x47], 'not a PNG');
  assert.equal(bytes.readUInt32BE(16), 160, 'PNG width'); // IHDR: the view's resolution
  assert.equal(bytes.readUInt32BE(20), 120, 'PNG height');

  const long = await submitJob(1_000_000);
  const running = `#job-list li[data-id="${long}"]`;
  await page.waitForSelector(`${running}[data-state="running"] .job-cancel`, { timeout: 120_000 });
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-jobs.png') });
  await page.click(`${running} .job-cancel`);
  await page.waitForSelector(`${running}[data-state="cancelled"]`, { timeout: 30_000 });
  assert.equal(await page.$(`${running} .job-cancel`), null, 'a cancelled job keeps its cancel button');
});

test('a .gen file picked on the page opens its space, W walks through it, and a job renders it', async () => {
  // A mirrored lens: its domain is charted in pieces, and two of its faces are mirrors.
  const gen = path.resolve(here, '../../catalogue/mirrored-lens-6.gen');
  await page.setInputFiles('#generator-file', gen);
  await waitFor(() => sentOfType('open').some((m) => typeof m.generators === 'string' &&
                                                     m.generators.includes('Mirrored lens')), 'open {generators}');
  // Named by the file's first comment line, and rendered at the size the page asks for.
  const title = 'Mirrored lens, dihedral angle 2 pi / 6 (orbifold)';
  const width = Number(await page.inputValue('#width'));
  const height = Number(await page.inputValue('#height'));
  await waitForShownFrame(page, 2, (f) => f.scene === title && f.width === width && f.height === height);
  const scene = receivedOfType('scene').at(-1);
  assert.equal(scene.name, title);
  assert.equal(scene.source, 'generators', 'the server says the scene came from generators');
  assert.equal(scene.geometry, 'spherical');
  assert.match(await page.textContent('#scene-title'), /Mirrored lens.* — spherical, generators/);
  assert.equal(await page.inputValue('#scene-picker'), '', 'the picker names no bundled scene');

  const before = await canvasBlocks(page);
  const movesBefore = sentOfType('move').length;
  await page.focus('#view');
  await page.keyboard.down('w');
  await page.waitForTimeout(400);
  await page.keyboard.up('w');
  await waitFor(() => sentOfType('move').length > movesBefore, 'a move inside the lens space');
  const after = await waitForShownFrame(page, 2, (f) => f.scene === title);
  const changed = meanAbsDiff(before, await canvasBlocks(page));
  console.log(`# lens space walk: block diff ${changed.toFixed(2)}, frame ${after.frame}`);
  assert.ok(changed > 1, `walking did not change the view: ${changed}`);

  // A render job of what is on screen: the space itself goes with it, as generator text.
  const id = await submitJob(2);
  const posted = sentJobs.at(-1);
  assert.equal(typeof posted.generators, 'string');
  assert.equal(posted.scene, undefined);
  const item = `#job-list li[data-id="${id}"]`;
  await page.waitForSelector(`${item}[data-state="done"] a:text("png")`, { timeout: 120_000 });
  assert.match(await page.textContent(`${item} .job-title`), /Mirrored lens/);
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-generators.png') });
});

test('a cusped space opens from SnapPy\'s Moebius matrices, and the picker lists the knot complements', async () => {
  // The figure-eight knot complement as SnapPy prints G.SL2C(g) for its two generators.
  const file = path.join(os.tmpdir(), `geodesic-m004-${process.pid}.txt`);
  fs.writeFileSync(file, '# Figure-eight knot complement, from SnapPy\n[1  1]\n[0  1]\n\n' +
                         '[1  0]\n[0.5 - 0.86602540378443865*I  1]\n');
  const title = 'Figure-eight knot complement, from SnapPy';
  const asked = Date.now();
  // Chromium reads a picked file when the page asks for its text, after setInputFiles has
  // returned: the file stays until the page has sent it.
  try {
    await page.setInputFiles('#generator-file', file);
    await waitFor(() => sentOfType('open').some((m) => m.generators?.includes(title)), 'the open of the file');
  } finally {
    fs.rmSync(file, { force: true });
  }
  const shown = await waitForShownFrame(page, 2, (f) => f.scene === title);
  console.log(`# cusped space: frame ${shown.frame} at ${shown.spp} spp, ${Date.now() - asked} ms after the file was picked`);
  const scene = receivedOfType('scene').at(-1);
  assert.equal(scene.name, title);
  assert.equal(scene.source, 'generators');
  assert.equal(scene.geometry, 'hyperbolic');
  // Not black: the camera sees the cusps' glowing horospheres and the spheres' copies.
  const { blocks } = await canvasBlocks(page);
  const mean = blocks.reduce((a, b) => a + b, 0) / blocks.length;
  assert.ok(mean > 20, `the cusped view is dark: mean block value ${mean}`);
  const options = await page.$$eval('#scene-picker option', (list) => list.map((o) => o.value));
  for (const name of ['figure-eight-knot', 'whitehead-link'])
    assert.ok(options.includes(name), `the picker lists ${name}`);
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-cusped.png') });
});

test('a bad scene shows its error and the session goes on', async () => {
  const p = await context.newPage();
  const log = [];
  recordSocket(p, log);
  try {
    await p.goto(`${BASE}/?scene=no-such-scene&width=160&height=120&depth=1`);
    await p.waitForSelector('#errors:not([hidden])', { timeout: FRAME_TIMEOUT });
    const error = log.find((e) => e.dir === 'received' && e.msg.type === 'error')?.msg;
    assert.ok(error, 'no error message from the server');
    const shown = await p.textContent('#errors');
    assert.ok(shown.includes(error.message), `"${shown}" lacks the server's message "${error.message}"`);
    if (error.field) assert.ok(shown.includes(error.field), `"${shown}" lacks the field "${error.field}"`);
    // The old (default) scene stays and keeps streaming, at the resolution the page asked for
    // once its `open` had failed.
    await p.waitForFunction(() => document.getElementById('view').width === 160, null, { timeout: FRAME_TIMEOUT });
    assert.equal(await p.inputValue('#scene-picker'), 'cornell-box');
    assert.ok(
      log.some((e) => e.dir === 'sent' && e.msg.type === 'settings' && e.msg.width === 160 && e.msg.max_depth === 1),
      'no settings sent after the failed open',
    );
    await p.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-error.png') });
  } finally {
    await p.close();
  }
});

test('the page threw no exceptions', () => {
  assert.deepEqual(pageErrors, []);
});

test('a dead server shows the unreachable banner', { skip: !process.env.GEODESIC_PID && 'GEODESIC_PID not set' }, async () => {
  process.kill(Number(process.env.GEODESIC_PID), 'SIGTERM');
  await page.waitForFunction(
    () => document.getElementById('status').textContent.includes('server unreachable — retrying'),
    null,
    { timeout: 30_000 },
  );
  await page.screenshot({ path: path.join(SCREENSHOT_DIR, 'walkthrough-unreachable.png') });
});
