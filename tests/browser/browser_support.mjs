// What the browser tests of the live viewer share: emit live started and its viewer's address,
// headless Chromium (Debian's) launched, and a minimal PNG decoder for the screenshots' pixels.
import { spawn } from "node:child_process";
import fs from "node:fs";
import zlib from "node:zlib";
import { chromium } from "playwright-core";

/// A failure function for the test `name`: prints, sets the exit code, throws.
export function failer(name) {
  return (message) => {
    console.error(`${name}: FAILED: ${message}`);
    process.exitCode = 1;
    throw new Error(message);
  };
}

/// `emit live ARGS… --serve 127.0.0.1:0`; `url` resolves to the viewer's address from emit's
/// output ("viewer: http://…/") within startupSeconds, `exited` to its exit code and output.
export function startEmit(emitPath, args, startupSeconds) {
  const child = spawn(emitPath, ["live", ...args, "--serve", "127.0.0.1:0"], { stdio: ["ignore", "pipe", "inherit"] });
  let output = "";
  const url = new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no viewer address after ${startupSeconds} s`)), startupSeconds * 1000);
    child.stdout.on("data", (chunk) => {
      output += chunk;
      const match = output.match(/viewer: (http:\/\/\S+)/);
      if (match) { clearTimeout(timer); resolve(match[1]); }
    });
    child.on("exit", (code) => reject(new Error(`emit live exited (${code}) before serving:\n${output}`)));
  });
  const exited = new Promise((resolve) => child.on("exit", (code, signal) => resolve({ code, signal, output: () => output })));
  return { child, url, exited };
}

/// After `emit live` was sent SIGINT (a user's Ctrl-C; the tests send it in `finally`, so it stops
/// whatever happened), checks it exits 0 with its summary line ("live: …"), which it returns.
/// `fail` is the test's failer.
export async function stoppedEmitSummary(emit, fail) {
  const { code, output } = await emit.exited;
  if (code !== 0) fail(`emit live exited with ${code} after SIGINT`);
  const summary = output().match(/live: .*/);
  if (!summary) fail("emit live printed no summary on SIGINT");
  return summary[0];
}

/// Debian's Chromium, headless, in a fresh profile, 1000 × 860 CSS pixels at one device pixel each.
export function launchChromium(profile, extraArgs = ["--disable-gpu"]) {
  return chromium.launchPersistentContext(profile, {
    executablePath: "/usr/bin/chromium",
    headless: true,
    args: ["--headless", "--no-sandbox", ...extraArgs, "--disable-quic", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync"],
    viewport: { width: 1000, height: 860 },
    deviceScaleFactor: 1,
  });
}

/// Minimal PNG decoder (8-bit RGB or RGBA, non-interlaced: what Chromium writes) → {width, height, rgb(x, y)}.
export function decodePng(buffer) {
  let at = 8, width = 0, height = 0, channels = 4;
  const idat = [];
  while (at < buffer.length) {
    const length = buffer.readUInt32BE(at), type = buffer.toString("ascii", at + 4, at + 8), data = buffer.subarray(at + 8, at + 8 + length);
    if (type === "IHDR") {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[12] !== 0) throw new Error("unexpected PNG format");
      channels = { 2: 3, 6: 4 }[data[9]];
    } else if (type === "IDAT") idat.push(data);
    at += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat)), stride = width * channels, pixels = Buffer.alloc(height * stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? pixels[y * stride + i - channels] : 0, b = y > 0 ? pixels[(y - 1) * stride + i] : 0;
      const c = i >= channels && y > 0 ? pixels[(y - 1) * stride + i - channels] : 0;
      const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
      const predictor = [0, a, b, (a + b) >> 1, pa <= pb && pa <= pc ? a : pb <= pc ? b : c][filter];
      pixels[y * stride + i] = (line[i] + predictor) & 255;
    }
  }
  return { width, height, rgb: (x, y) => [0, 1, 2].map((k) => pixels[Math.round(y) * stride + Math.round(x) * channels + k]) };
}

/// A copy of the recording `from` (docs/recording.md: a 32-byte header, then packets of
/// 20 + 2·N² bytes) as if its board had taken a frame every `interval_us`, and, given `swap`
/// [a, b], as if electrodes a and b had been wired in each other's places (their rows and
/// columns of each payload exchanged): each packet's timestamp rewritten and its CRC-32 (zlib's,
/// over everything after the sync) made again, so `emit live --source file:…` replays it so.
/// Returns the number of frames.
export function retimeRecording(from, to, interval_us, swap = null) {
  const bytes = Buffer.from(fs.readFileSync(from)), N = bytes.readUInt16LE(12), size = 20 + 2 * N * N;
  const wired = (k) => (swap && k === swap[0] ? swap[1] : swap && k === swap[1] ? swap[0] : k);
  let frames = 0;
  for (let at = 32; at + size <= bytes.length; at += size, ++frames) {
    bytes.writeUInt32LE((frames * interval_us) >>> 0, at + 12);
    if (swap) {
      const payload = Buffer.from(bytes.subarray(at + 16, at + 16 + 2 * N * N));
      for (let g = 0; g < N; ++g)
        for (let m = 0; m < N; ++m) bytes.writeUInt16LE(payload.readUInt16LE(2 * (wired(g) * N + wired(m))), at + 16 + 2 * (g * N + m));
    }
    bytes.writeUInt32LE(zlib.crc32(bytes.subarray(at + 2, at + size - 4)), at + size - 4);
  }
  fs.writeFileSync(to, bytes);
  return frames;
}

/// Pixels of `image` in the box {x, y, width, height} for which `test(rgb)` holds.
export function countPixels(image, box, test) {
  let count = 0;
  for (let y = Math.ceil(box.y); y < box.y + box.height; ++y)
    for (let x = Math.ceil(box.x); x < box.x + box.width; ++x) if (test(image.rgb(x, y))) ++count;
  return count;
}

/// Whether two colours are within `tolerance` in every channel.
export const near = (a, b, tolerance) => a.every((v, i) => Math.abs(v - b[i]) <= tolerance);

/// Waits for one contact with a force trace of three frames and a second (on the board's clock) at least.
export function waitForForceTrace(page, timeout_s) {
  return page.waitForFunction(() => {
    const v = window.emitViewer, c = v.last && v.last.contacts[0], track = c && v.tracks.get(c.id);
    return v.last.contacts.length === 1 && track && track.forces.length >= 3 &&
           track.forces[track.forces.length - 1].t - track.forces[0].t >= 1;
  }, null, { timeout: 1000 * timeout_s });
}

/// What makes the page an instrument, checked on a screenshot `image` of a page showing a held
/// press (both views): the colour bar's gradient (the page's own ramp at its top, middle and
/// bottom), its unit and tick labels written (dark pixels in each label's box), a contact's label
/// with its id and force, the force trace in the touch's colour at its force, the raw frame's cells
/// in the colours of their readings, the "uncalibrated" badge and the electrodes' health.
/// Returns a line to print. `fail` is the test's failer.
export async function checkInstrument(page, image, fail) {
  const state = await page.evaluate(() => {
    const v = window.emitViewer, g = v.geometry(), f = g.forces, frame = v.last;
    const c = frame.contacts[0];
    return {
      g, frame, range: v.range, readings: Array.from(v.readings),
      colours: { top: v.pressureColour(1), middle: v.pressureColour(0.5), bottom: v.pressureColour(0.02) },
      raw: Array.from({ length: 256 }, (_, i) => v.rawColour(i / 255)),
      badge: { text: document.getElementById("badge").textContent, box: document.getElementById("badge").getBoundingClientRect().toJSON() },
      health: document.getElementById("health").textContent,
      track: c && v.tracks.get(c.id) ? v.tracks.get(c.id).forces.slice(-6) : null,
      forceAt: f && c ? { x: f.right - (f.right - f.left) * 0.5 / f.span_s, y: f.bottom - (f.bottom - f.top) * c.force_N / f.fTop } : null,
    };
  });
  const dark = (rgb) => rgb.every((v) => v < 110);
  const { g, frame } = state, bar = g.colourBar;
  // The colour bar: its ramp, from the page's own colours.
  const cx = bar.x + bar.width / 2;
  for (const [name, y, want] of [["top", bar.y + 2, state.colours.top], ["middle", bar.y + bar.height / 2, state.colours.middle],
                                 ["bottom", bar.y + bar.height - 3, state.colours.bottom]])
    if (!near(image.rgb(cx, y), want, 14)) fail(`the colour bar's ${name} is rgb(${image.rgb(cx, y)}), not its ramp's rgb(${want})`);
  if (bar.ticks.length < 3) fail(`the colour bar has ${bar.ticks.length} ticks`);
  if (Math.abs(bar.ticks[bar.ticks.length - 1].value - state.range) > 1e-9 * state.range && bar.ticks[bar.ticks.length - 1].value > state.range)
    fail(`a tick above the range ${state.range}`);
  for (const tick of bar.ticks) {
    const inked = countPixels(image, { x: tick.x, y: tick.y - 6, width: 28, height: 12 }, dark);
    if (inked < 6) fail(`the colour bar's tick ${tick.text} has no label drawn (${inked} dark pixels)`);
  }
  const unitInk = countPixels(image, bar.units, dark);
  if (unitInk < 20) fail(`the colour bar's unit "N/mm²" is not drawn (${unitInk} dark pixels)`);
  // The contact's label: its id and force, drawn.
  const c = frame.contacts[0], label = g.labels[0];
  if (!label) fail("no contact label");
  const expected = (c.id >= 0 ? `#${c.id}` : "") + `${c.force_N.toFixed(1)} N`;
  if (label.text.replace(/\s+/g, "") !== expected.replace(/\s+/g, "")) fail(`the contact's label reads "${label.text}", not "${expected}"`);
  const labelInk = countPixels(image, label, dark);
  if (labelInk < 30) fail(`the contact's label "${label.text}" is not drawn (${labelInk} dark pixels)`);
  // The force trace: half a second ago, at the touch's force (within the line's 2 px and the force's
  // wobble: ±6 px), in the touch's colour (palette[id], the page's first: #1f5fbf for id 0).
  const palette = [[31, 95, 191], [42, 157, 58], [142, 68, 173], [0, 131, 143], [216, 27, 96], [109, 76, 65], [84, 110, 122], [158, 157, 36]];
  const want = palette[c.id % palette.length], at = state.forceAt;
  const traced = countPixels(image, { x: at.x - 2, y: at.y - 6, width: 4, height: 12 }, (rgb) => near(rgb, want, 40));
  if (traced < 2)
    fail(`no force trace in rgb(${want}) at (${at.x.toFixed(0)}, ${at.y.toFixed(0)}), ${c.force_N.toFixed(2)} N 0.5 s ago; ` +
         `the page's track: ${JSON.stringify(state.track)}`);
  // The raw frame: the cell of the largest reading and a diagonal one, in their readings' colours.
  const N = frame.electrode_count, raw = g.raw, readings = state.readings;
  let biggest = 0;
  for (let k = 0; k < N * N; ++k) if (readings[k] > readings[biggest]) biggest = k;
  for (const k of [biggest, 0, N + 1]) {
    const l = Math.floor(k / N), m = k % N, rgb = image.rgb(raw.x + (m + 0.5) * raw.cell, raw.y + (l + 0.5) * raw.cell);
    const wanted = state.raw[Math.max(0, Math.min(255, Math.round(255 * readings[k] / raw.full_V)))];
    if (!near(rgb, wanted, 3)) fail(`raw cell (ground ${l}, sense ${m}) ${readings[k].toFixed(3)} V is rgb(${rgb}), not rgb(${wanted})`);
  }
  // The badge and the health line.
  if (state.badge.text !== "uncalibrated") fail(`the badge reads "${state.badge.text}"`);
  const b = state.badge.box, badge = image.rgb(b.x + 3, b.y + b.height / 2);
  if (!near(badge, [245, 166, 35], 10)) fail(`the badge's colour is rgb(${badge}), not the uncalibrated amber`);
  if (!/^electrodes: none dead/.test(state.health)) fail(`the health line reads "${state.health}"`);
  return `colour bar 0 to ${+state.range.toPrecision(3)} N/mm² (${bar.ticks.map((t) => t.text).join(", ")}), label "${label.text}", ` +
         `force trace at ${c.force_N.toFixed(2)} N (${traced} px), raw cell max ${readings[biggest].toFixed(3)} V, badge, "${state.health}"`;
}
