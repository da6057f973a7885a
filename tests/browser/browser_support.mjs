// What the browser tests of the live viewer share: emit live started and its viewer's address,
// headless Chromium (Debian's) launched, and a minimal PNG decoder for the screenshots' pixels.
import { spawn } from "node:child_process";
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
