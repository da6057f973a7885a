// The live viewer in a real browser: `emit live` holds one simulated press at a known place, a bar
// fitted with `--method shapes`; headless Chromium (Debian's) loads the page, frames arrive, and a
// screenshot shows the pressed colour at the press, the background far from it, and the contact's
// outline drawn as its ellipse, long along the bar; the re-capture button reaches the server's loop.
// Usage: node viewer_test.mjs PATH/TO/emit [SCREENSHOT.png]
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { decodePng, failer, launchChromium, startEmit, stoppedEmitSummary } from "./browser_support.mjs";

const [emitPath, screenshotPath = path.join(os.tmpdir(), "emit-viewer-test.png")] = process.argv.slice(2);
if (!emitPath) throw new Error("usage: node viewer_test.mjs PATH/TO/emit [SCREENSHOT.png]");
const press = { x_mm: 30, y_mm: 30, angle_deg: 30 };  // the held press: a bar 24 x 4 mm
const far = { x_mm: 45, y_mm: 15 };    // 20 mm from the bar: nothing pressed there
const startupSeconds = 300;            // meshing and the fit model, slow under sanitizers

const fail = failer("viewer_test");

const emit = startEmit(emitPath, ["--source", `sim:fixed:bar:${press.x_mm},${press.y_mm},24,4,${press.angle_deg},10`,
                                  "--method", "shapes"], startupSeconds);
const profile = fs.mkdtempSync(path.join(os.tmpdir(), "emit-chromium-"));
let context;
try {
  const url = await emit.url;
  console.log(`viewer_test: emit serves ${url}`);
  context = await launchChromium(profile);
  const page = context.pages()[0] || await context.newPage();
  page.on("console", (message) => console.log(`page: ${message.text()}`));
  page.on("pageerror", (error) => fail(`page error: ${error.message}`));
  await page.goto(url);
  await page.waitForFunction(() => window.emitViewer && window.emitViewer.frames > 3 && window.emitViewer.last &&
                                   !window.emitViewer.last.capturing_baseline && window.emitViewer.last.contacts.length > 0,
                             null, { timeout: 1000 * startupSeconds });
  const last = await page.evaluate(() => window.emitViewer.last);
  console.log(`viewer_test: frame ${last.sequence}, ${last.frames_per_s.toFixed(1)} frames/s, latency ${last.latency_ms.toFixed(2)} ms, ` +
              `contact at (${last.contacts[0].x_mm.toFixed(2)}, ${last.contacts[0].y_mm.toFixed(2)}) mm, ${last.contacts[0].force_N.toFixed(2)} N`);

  const shot = await page.screenshot();
  const after = await page.evaluate(() => window.emitViewer.last);  // the frame drawn: this one or `last`
  fs.writeFileSync(screenshotPath, shot);
  const image = decodePng(shot);
  const at = await page.evaluate(([a, b]) => [window.emitViewer.toPixel(a.x_mm, a.y_mm), window.emitViewer.toPixel(b.x_mm, b.y_mm)], [press, far]);
  const pressed = image.rgb(at[0].x, at[0].y), background = image.rgb(at[1].x, at[1].y);
  console.log(`viewer_test: pixel at the press (${at[0].x.toFixed(0)}, ${at[0].y.toFixed(0)}) rgb(${pressed}), ` +
              `far from it (${at[1].x.toFixed(0)}, ${at[1].y.toFixed(0)}) rgb(${background}); screenshot ${screenshotPath}`);
  // The page's top colour is rgb(200, 0, 0), its background rgb(246, 246, 246).
  if (!(pressed[0] > 150 && pressed[1] < 90 && pressed[2] < 90)) fail(`no pressed (red) colour at the press: rgb(${pressed})`);
  if (!background.every((v) => Math.abs(v - 246) <= 4)) fail(`not the background colour far from the press: rgb(${background})`);

  // The outline: from the contact's centre along its major axis and across it, the first dark
  // pixel (the outline's #111 stroke, 2 px) is at its semi-axes (within the stroke and a pixel);
  // its message's ellipse is the bar's, twice as long as wide at least (the bar's own is 6 times)
  // and along it within the 10 degrees.
  const c = last.contacts[0], c2 = after.contacts[0] ?? c;
  const offDeg = ((c.orientation_deg - press.angle_deg) % 180 + 270) % 180 - 90;
  if (!(c.semi_major_mm >= 2 * c.semi_minor_mm && c.semi_minor_mm > 0 && Math.abs(offDeg) <= 10))
    fail(`the contact is not the bar's ellipse: ${c.semi_major_mm} by ${c.semi_minor_mm} mm at ${c.orientation_deg} deg`);
  const reach = await page.evaluate((contact) => {
    const v = window.emitViewer, theta = contact.orientation_deg * Math.PI / 180, out = [];
    for (const [dx, dy] of [[Math.cos(theta), Math.sin(theta)], [-Math.sin(theta), Math.cos(theta)]]) {
      const points = [];
      for (let t = 0; t <= 20; t += 0.02) points.push(v.toPixel(contact.x_mm + t * dx, contact.y_mm + t * dy));
      out.push(points);
    }
    return { scale: v.toPixel(1, 0).x - v.toPixel(0, 0).x, walks: out };
  }, c);
  const firstDark = (walk) => walk.findIndex((p) => image.rgb(p.x, p.y).every((v) => v < 80)) * 0.02;
  const [along, across] = reach.walks.map(firstDark), slack_mm = 3 / reach.scale;
  console.log(`viewer_test: contact ellipse ${c.semi_major_mm.toFixed(2)} x ${c.semi_minor_mm.toFixed(2)} mm at ` +
              `${c.orientation_deg.toFixed(1)} deg; drawn: outline ${along.toFixed(2)} mm along, ${across.toFixed(2)} mm across`);
  const near = (drawn, a, b) => Math.abs(drawn - a) <= slack_mm || Math.abs(drawn - b) <= slack_mm;
  if (!near(along, c.semi_major_mm, c2.semi_major_mm)) fail(`the outline along the bar at ${along} mm, not ${c.semi_major_mm}`);
  if (!near(across, c.semi_minor_mm, c2.semi_minor_mm)) fail(`the outline across the bar at ${across} mm, not ${c.semi_minor_mm}`);

  const captures = last.baseline_captures;
  await page.click("#recapture");
  await page.waitForFunction((before) => window.emitViewer.last.commands >= 1 && window.emitViewer.last.baseline_captures > before,
                             captures, { timeout: 1000 * startupSeconds });
  const shown = await page.textContent("#commands");
  if (shown !== "1") fail(`the page shows ${shown} commands received, expected 1`);
  console.log(`viewer_test: re-capture reached the loop (baseline captures ${captures} -> ${await page.textContent("#captures")})`);
} finally {
  if (context) await context.close();
  fs.rmSync(profile, { recursive: true, force: true });
  emit.child.kill("SIGINT");
}
console.log(`viewer_test: ${await stoppedEmitSummary(emit, fail)}`);
console.log("viewer_test: passed");
