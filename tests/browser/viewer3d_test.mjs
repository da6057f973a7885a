// The live viewer's 3D view in a real browser: `emit live` on the dome (a spherical cap,
// examples/sensors/dome25.json) holds one simulated press at a known place; headless Chromium
// (Debian's, WebGL on SwiftShader, the CPU) loads the page, which draws the curved sheet with
// three.js. A screenshot shows the pressed colour at the press (window.emitViewer.toPixel3 projects
// it through the page's camera), the unpressed sheet's grey far from it and the view's background
// above the dome; a drag with the mouse orbits the camera, and the press's pixel moves with the
// pressed colour on it. With three.js unreachable the page draws the dome flat and says why.
// Usage: node viewer3d_test.mjs PATH/TO/emit SENSORS_DIR [SCREENSHOT.png]
// Exits 77 (skipped, CTest's SKIP_RETURN_CODE) when the page says its emit was built without three.js.
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { checkInstrument, decodePng, failer, launchChromium, startEmit, stoppedEmitSummary, waitForForceTrace } from "./browser_support.mjs";

const [emitPath, sensorsDir, screenshotPath = path.join(os.tmpdir(), "emit-viewer3d-test.png")] = process.argv.slice(2);
if (!emitPath || !sensorsDir) throw new Error("usage: node viewer3d_test.mjs PATH/TO/emit SENSORS_DIR [SCREENSHOT.png]");
// The dome: a sphere of radius 25 mm cut 20 mm from its axis, centred on x = y = 0, its rim at z = 0
// and its top at z = 10 mm; the point above (x, y) is at z = √(25² − x² − y²) − 15.
const onDome = (x_mm, y_mm) => ({ x_mm, y_mm, z_mm: Math.sqrt(25 ** 2 - x_mm ** 2 - y_mm ** 2) - 15 });
const press = onDome(5, -6);   // the held press, on the slope facing the camera
const far = onDome(-9, 11);    // 22 mm away, on the slope beyond the top: nothing pressed there
const outside = { x_mm: 0, y_mm: 0, z_mm: 20 };  // 10 mm above the top: the view's background
const startupSeconds = 300;    // meshing and the fit model, slow under sanitizers
const fail = failer("viewer3d_test");

// The map's upper half (orange rgb(245, 140, 60) at 0.35 through red to rgb(140, 0, 0) at its top), lit: clearly red.
const isPressed = (rgb) => rgb[0] > 120 && rgb[0] > 1.8 * rgb[1] && rgb[2] < 90;
const isSheet = (rgb) => Math.max(...rgb) - Math.min(...rgb) <= 6 && rgb[0] >= 120 && rgb[0] <= 236;  // grey, lit, not the page
const isBackground = (rgb) => rgb.every((v) => Math.abs(v - 250) <= 4);  // #fafafa

const emit = startEmit(emitPath, ["--sensor", path.join(sensorsDir, "dome25.json"), "--source",
                                  `sim:fixed:${press.x_mm},${press.y_mm}`], startupSeconds);
const profile = fs.mkdtempSync(path.join(os.tmpdir(), "emit-chromium-"));
let context, skipped = false;
try {
  const url = await emit.url;
  console.log(`viewer3d_test: emit serves ${url}`);
  // WebGL without a GPU: ANGLE on SwiftShader (Chromium asks for the flag to allow it).
  context = await launchChromium(profile, ["--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]);
  const page = context.pages()[0] || await context.newPage();
  page.on("console", (message) => console.log(`page: ${message.text()}`));
  page.on("pageerror", (error) => fail(`page error: ${error.message}`));
  await page.goto(url);
  await page.waitForFunction(() => window.emitViewer && window.emitViewer.mode, null, { timeout: 60000 });
  const mode = await page.evaluate(() => window.emitViewer.mode);
  if (mode !== "3d") {
    const note = await page.textContent("#note");
    if (/no 3D view in this build/.test(note)) {
      skipped = true;
      console.log(`viewer3d_test: skipped: ${note}`);
    } else fail(`the page draws the dome ${mode}, not in 3D: ${note}`);
  }
  if (!skipped) {
    await page.waitForFunction(() => window.emitViewer.frames > 10 && window.emitViewer.last &&
                                     !window.emitViewer.last.capturing_baseline && window.emitViewer.last.contacts.length > 0,
                               null, { timeout: 60000 });
    await waitForForceTrace(page, 60);
    // The page's own work a frame, once warm (shaders compiled, code optimised): over 3 s.
    const sample = () => page.evaluate(() => { const w = window.emitViewer.work; return { frames: w.frames, draws: w.draws, ms: w.total_ms }; });
    const warm = await sample();
    await page.waitForTimeout(3000);
    const now = await sample();
    const work = { ms: (now.ms - warm.ms) / (now.frames - warm.frames), frames: now.frames - warm.frames, draws: now.draws - warm.draws };
    const last = await page.evaluate(() => window.emitViewer.last);
    const c = last.contacts[0];
    console.log(`viewer3d_test: frame ${last.sequence}, ${last.frames_per_s.toFixed(1)} frames/s, contact at ` +
                `(${c.x_mm.toFixed(2)}, ${c.y_mm.toFixed(2)}, ${c.z_mm.toFixed(2)}) mm, normal (${c.normal.map((v) => v.toFixed(3))}), ` +
                `${c.force_N.toFixed(2)} N`);
    if (Math.hypot(c.x_mm - press.x_mm, c.y_mm - press.y_mm, c.z_mm - press.z_mm) > 3)
      fail(`the contact is not at the press (${press.x_mm}, ${press.y_mm}, ${press.z_mm.toFixed(2)}) mm`);

    const project = () => page.evaluate((points) => points.map((p) => window.emitViewer.toPixel3(p.x_mm, p.y_mm, p.z_mm)),
                                        [press, far, outside]);
    const look = async (file) => {
      const shot = await page.screenshot();
      fs.writeFileSync(file, shot);
      return decodePng(shot);
    };
    const describe = (name, at, rgb) => `${name} (${at.x.toFixed(0)}, ${at.y.toFixed(0)}) rgb(${rgb})`;

    const box = await page.locator("#view3d canvas").boundingBox();
    const inView = (p) => p.x > box.x + 1 && p.x < box.x + box.width - 1 && p.y > box.y + 1 && p.y < box.y + box.height - 1;
    await page.click("#pause");  // the picture and the page's numbers of one frame from here on
    let at = await project();
    if (!at.every(inView)) fail(`points off the 3D view ${JSON.stringify(box)}: ${JSON.stringify(at)}`);
    let image = await look(screenshotPath);
    const pressed = image.rgb(at[0].x, at[0].y), sheet = image.rgb(at[1].x, at[1].y), background = image.rgb(at[2].x, at[2].y);
    console.log(`viewer3d_test: ${describe("press", at[0], pressed)}, ${describe("far on the dome", at[1], sheet)}, ` +
                `${describe("above the dome", at[2], background)}; screenshot ${screenshotPath}`);
    if (!isPressed(pressed)) fail(`no pressed (red) colour at the press: rgb(${pressed})`);
    if (!isSheet(sheet)) fail(`not the unpressed sheet's grey far from the press: rgb(${sheet})`);
    if (!isBackground(background)) fail(`not the view's background above the dome: rgb(${background})`);
    console.log(`viewer3d_test: ${await checkInstrument(page, image, fail)}`);
    console.log(`viewer3d_test: the page's own work ${work.ms.toFixed(2)} ms a frame over 3 s (${work.frames} frames, ${work.draws} drawn; ` +
                "WebGL on SwiftShader: the CPU draws; the 2 ms target is the flat view's, viewer_test)");

    // Orbit: drag from the middle of the view 200 px to the right (the camera turns about the
    // sheet's axis); the press's pixel moves, and the pressed colour is at the new one.
    const from = { x: box.x + box.width / 2, y: box.y + box.height / 2 };
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(from.x + 200, from.y, { steps: 10 });
    await page.mouse.up();
    const before = at[0];
    at = await project();
    const moved = Math.hypot(at[0].x - before.x, at[0].y - before.y);
    image = await look(screenshotPath.replace(/\.png$/, "") + "-orbited.png");
    const pressedAfter = image.rgb(at[0].x, at[0].y), backgroundAfter = image.rgb(at[2].x, at[2].y);
    console.log(`viewer3d_test: after the drag, ${describe("press", at[0], pressedAfter)}, moved ${moved.toFixed(0)} px; ` +
                `${describe("above the dome", at[2], backgroundAfter)}`);
    if (moved < 40) fail(`the drag moved the press's pixel only ${moved.toFixed(1)} px`);
    if (!isPressed(pressedAfter)) fail(`no pressed (red) colour at the press after the drag: rgb(${pressedAfter})`);
    if (!isBackground(backgroundAfter)) fail(`not the view's background above the dome after the drag: rgb(${backgroundAfter})`);

    // Without three.js (as from a build that left it out: here its files answer 404), the page
    // draws the dome flat, seen from above, and says why; the press is still red at its (x, y).
    const flat = await context.newPage();
    flat.on("pageerror", (error) => fail(`page error (no three.js): ${error.message}`));
    await flat.route("**/three/**", (route) => route.fulfill({ status: 404, body: "not found" }));
    await flat.goto(url);
    await flat.waitForFunction(() => window.emitViewer && window.emitViewer.mode === "flat" && window.emitViewer.frames > 3 &&
                                     window.emitViewer.last && window.emitViewer.last.contacts.length > 0, null, { timeout: 60000 });
    const note = await flat.textContent("#note"), atFlat = await flat.evaluate((p) => window.emitViewer.toPixel(p.x_mm, p.y_mm), press);
    const pressedFlat = decodePng(await flat.screenshot()).rgb(atFlat.x, atFlat.y);
    console.log(`viewer3d_test: without three.js: "${note}"; press (${atFlat.x.toFixed(0)}, ${atFlat.y.toFixed(0)}) rgb(${pressedFlat})`);
    if (!/no 3D view in this build/.test(note)) fail(`the page does not say why it draws the dome flat: "${note}"`);
    if (!isPressed(pressedFlat)) fail(`no pressed (red) colour at the press, drawn flat: rgb(${pressedFlat})`);
    await flat.close();
  }
} finally {
  if (context) await context.close();
  fs.rmSync(profile, { recursive: true, force: true });
  emit.child.kill("SIGINT");
}
console.log(`viewer3d_test: ${await stoppedEmitSummary(emit, fail)}`);
if (skipped) process.exit(77);
console.log("viewer3d_test: passed");
