// emit's MCAP recordings read back by the format's own reader, @mcap/core (CRCs checked), and
// every ROS 2 message decoded by @foxglove/rosmsg2-serialization from the schema the file carries;
// compared with what emit wrote beside them (the frames file, the contacts' JSON Lines). Then the
// same file cut short at many places: the reader must say it is incomplete, never misread it.
//
//   node read_back_test.mjs <emit> <work folder>
import { McapStreamReader } from "@mcap/core";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import { execFileSync, spawnSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, rmSync } from "node:fs";
import { join } from "node:path";
import { crc32 } from "node:zlib";

const [emit, work] = process.argv.slice(2);
rmSync(work, { recursive: true, force: true });
mkdirSync(work, { recursive: true });
const at = (name) => join(work, name);
const run = (...args) => execFileSync(emit, args, { stdio: ["ignore", "pipe", "pipe"] });
const cache = ["--cache", at("cache")];
let failures = 0;
const check = (ok, what) => {
  if (!ok) {
    failures++;
    console.error(`FAIL: ${what}`);
  }
};
const close = (a, b, rel) => Math.abs(a - b) <= rel * Math.max(Math.abs(a), Math.abs(b)) + 1e-12;

/** Every record of an MCAP file's bytes; `complete`: the reader reached the closing magic. */
function readRecords(bytes) {
  const reader = new McapStreamReader({ validateCrcs: true });
  reader.append(bytes);
  const records = [];
  let error = null;
  try {
    for (let record; (record = reader.nextRecord()); ) records.push(record);
  } catch (e) {
    error = e;
  }
  return { records, complete: reader.done() && error === null, error };
}

/** Every number of a decoded emit_msgs/TactileContact against its JSON Lines object (6 significant
 *  digits there; an absent key is 0), in SI units. */
function compareContact(c, j, what, rank = 0) {
  const pairs = [["x_mm", c.position.x, 1e-3], ["y_mm", c.position.y, 1e-3], ["area_mm2", c.area, 1e-6],
    ["pressure_N_per_mm2", c.pressure, 1e6], ["peak_pressure_N_per_mm2", c.peak_pressure, 1e6],
    ["force_N", -c.wrench.force.z, 1], ["x_std_mm", c.position_std_x, 1e-3], ["y_std_mm", c.position_std_y, 1e-3],
    ["pressure_std_N_per_mm2", c.pressure_std, 1e6], ["force_std_N", c.force_std, 1],
    ["semi_major_mm", c.semi_major_m, 1e-3], ["semi_minor_mm", c.semi_minor_m, 1e-3],
    ["orientation_deg", c.orientation_rad, Math.PI / 180], ["area_std_mm2", c.area_std_m2, 1e-6],
    ["orientation_std_deg", c.orientation_std_rad, Math.PI / 180], ["vx_mm_per_s", c.velocity.x, 1e-3],
    ["vy_mm_per_s", c.velocity.y, 1e-3]];
  // A tracked touch is named by its id (the same while it lasts), an untracked contact by its rank.
  check(c.name === (j.id !== undefined ? `touch_${j.id}` : `contact_${rank}`), `${what} name ${c.name}`);
  check(c.velocity.z === 0, `${what} velocity z`);
  for (const [key, value, scale] of pairs)
    check(close(value, scale * (j[key] ?? 0), 1e-5), `${what} ${key}: ${value} against ${scale * (j[key] ?? 0)}`);
  // The outline: a geometry_msgs/Polygon of float32 points [m], z = 0, as outline_mm's vertices.
  const outline = j.outline_mm ?? [];
  check(c.outline.points.length === outline.length,
        `${what} outline: ${c.outline.points.length} points against ${outline.length}`);
  c.outline.points.forEach((p, k) => {
    check(close(p.x, 1e-3 * outline[k][0], 1e-5) && close(p.y, 1e-3 * outline[k][1], 1e-5) && p.z === 0,
          `${what} outline point ${k}: ${p.x}, ${p.y} against ${outline[k]}`);
  });
}

/** The messages of each topic, decoded from the schemas the file carries. */
function decode(records) {
  const schemas = new Map(), channels = new Map(), topics = {};
  for (const r of records) {
    if (r.type === "Schema") schemas.set(r.id, r);
    if (r.type === "Channel") {
      const schema = schemas.get(r.schemaId);
      const reader = new MessageReader(parse(new TextDecoder().decode(schema.data), { ros2: true }));
      channels.set(r.id, { topic: r.topic, reader, schema, channel: r });
      topics[r.topic] = [];
    }
    if (r.type === "Message") {
      const c = channels.get(r.channelId);
      topics[c.topic].push({ ...c.reader.readMessage(r.data), logTime: r.logTime, sequence: r.sequence });
    }
  }
  return { schemas, channels, topics };
}

// A recorded reconstruction: two fingers over six frames, contact fitting.
run("simulate", "--script", "none", "--frames", "10", "--out", at("ref.csv"));
run("simulate", "--script", "two-finger", "--frames", "6", "--out", at("two.csv"));
run("reconstruct", "--method", "fit", "--reference", at("ref.csv"), "--frames", at("two.csv"), "--contacts",
    at("contacts.jsonl"), "--mcap", at("run.mcap"), ...cache);
check(!existsSync(at("run.mcap.partial")), "the .partial file is renamed on close");
const bytes = new Uint8Array(readFileSync(at("run.mcap")));
const whole = readRecords(bytes);
check(whole.complete, `the file reads to its end, CRCs valid (${whole.error})`);
// The data section's CRC-32 (which the stream reader does not check): every byte before the Data
// End record (13 bytes, before the 29-byte footer and the 8-byte magic), as @mcap/core's writer counts.
const dataEnd = whole.records.find((r) => r.type === "DataEnd");
const dataEndAt = bytes.length - 8 - 29 - 13;
check(bytes[dataEndAt] === 0x0f && dataEnd.dataSectionCrc === crc32(bytes.subarray(0, dataEndAt)),
      `data section CRC ${dataEnd.dataSectionCrc} against ${crc32(bytes.subarray(0, dataEndAt))}`);
const header = whole.records.find((r) => r.type === "Header");
check(header && header.profile === "ros2" && header.library.startsWith("emit "), "profile ros2, library emit");
const { channels, topics } = decode(whole.records);
const names = [...channels.values()].map((c) => `${c.topic} ${c.schema.name} ${c.schema.encoding} ${c.channel.messageEncoding}`);
check(JSON.stringify(names.sort()) === JSON.stringify([
  "/emit/contacts emit_msgs/msg/TactileContacts ros2msg cdr", "/emit/frames emit_msgs/msg/TactileState ros2msg cdr",
  "/emit/mesh shape_msgs/msg/Mesh ros2msg cdr", "/emit/pressure emit_msgs/msg/PressureImage ros2msg cdr",
  "/emit/pressure_cloud sensor_msgs/msg/PointCloud2 ros2msg cdr"]),
  `topics and types: ${names}`);

// The mesh: the 60 x 60 mm sheet's triangles cover 3.6e-3 m^2.
const [mesh] = topics["/emit/mesh"];
let area = 0;
for (const t of mesh.triangles) {
  const [a, b, c] = [...t.vertex_indices].map((i) => mesh.vertices[i]);
  area += Math.abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2;
}
check(topics["/emit/mesh"].length === 1 && close(area, 3.6e-3, 1e-9), `mesh area ${area} m^2 (3.6e-3)`);

// Frames: the frames file's numbers exactly (the same text parsed to the same doubles).
const rows = readFileSync(at("two.csv"), "utf8").trim().split("\n").map((l) => l.split(",").map(Number));
const states = topics["/emit/frames"];
check(states.length === rows.length, `${states.length} frames of ${rows.length}`);
states.forEach((s, f) => {
  const values = [...s.sensors[0].values];
  check(s.sensors.length === 1 && s.sensors[0].name === "default 60 mm", `frame ${f}: the sensor's name`);
  check(values.length === 256 && values.every((v, i) => v === rows[f][i]), `frame ${f}: values as in two.csv`);
  check(s.header.frame_id === "emit_sheet", `frame ${f}: frame_id`);
  if (f > 0) {
    const dt = (s.header.stamp.sec - states[f - 1].header.stamp.sec) * 1e9 + s.header.stamp.nanosec - states[f - 1].header.stamp.nanosec;
    check(dt === 20e6 && s.logTime - states[f - 1].logTime === 20000000n, `frame ${f}: 20 ms after the last (${dt} ns)`);
  }
});

// Contacts: as the JSON Lines say (6 significant digits there), in SI units.
const lines = readFileSync(at("contacts.jsonl"), "utf8").trim().split("\n").map((l) => JSON.parse(l));
const contacts = topics["/emit/contacts"];
check(contacts.length === lines.length, `${contacts.length} contact messages for ${lines.length} lines`);
let compared = 0;
contacts.forEach((m, f) => {
  check(Number(m.frame) === lines[f].frame, `contacts ${f}: frame number`);
  // A file of frames is put at the board's 50 frames/s: frame f at f / 50 s on its clock.
  check(close(m.board_time, 0.02 * f, 1e-12), `contacts ${f}: board time ${m.board_time}`);
  check(m.ended.length === (lines[f].ended ?? []).length, `contacts ${f}: ended touches`);
  m.ended.forEach((c, i) => compareContact(c, lines[f].ended[i], `ended ${f}.${i}`, i));
  check(m.contacts.length === lines[f].contacts.length, `contacts ${f}: count`);
  m.contacts.forEach((c, i) => {
    const j = lines[f].contacts[i];
    compareContact(c, j, `contacts ${f}.${i}`, i);
    check(c.normal.z === 1 && c.position.z === 0, `contacts ${f}.${i}: flat sheet`);
    compared++;
  });
});
check(compared >= 2 * lines.length - 1, `two contacts a frame (${compared} in ${lines.length} frames)`);

// A bar 24 x 4 mm at 30 degrees, `shapes`: its contact's outline (the ellipse of its second
// moments, and their 1 sigma) decoded as the JSON Lines say, in SI units; twice as long as wide,
// along the bar within the 10 degrees (the bar's own ellipse is 6 times).
run("simulate", "--press", "bar:30,30,24,4,30,10", "--out", at("bar.csv"));
run("reconstruct", "--method", "shapes", "--reference", at("ref.csv"), "--frames", at("bar.csv"), "--contacts",
    at("bar.jsonl"), "--mcap", at("bar.mcap"), ...cache);
const barLine = JSON.parse(readFileSync(at("bar.jsonl"), "utf8").trim());
const barRead = readRecords(new Uint8Array(readFileSync(at("bar.mcap"))));
const [barMessage] = decode(barRead.records).topics["/emit/contacts"];
check(barRead.complete && barMessage.contacts.length === barLine.contacts.length && barLine.contacts.length >= 1,
      `the bar's contacts: ${barMessage.contacts.length} against ${barLine.contacts.length}`);
const bar = barMessage.contacts[0];
compareContact(bar, barLine.contacts[0], "the bar's contact");
const offDeg = ((bar.orientation_rad * 180 / Math.PI - 30) % 180 + 270) % 180 - 90;
check(bar.semi_major_m >= 2 * bar.semi_minor_m && bar.semi_minor_m > 0 && Math.abs(offDeg) <= 10,
      `the bar's ellipse: ${bar.semi_major_m} by ${bar.semi_minor_m} m, ${offDeg} degrees off`);
check(bar.area_std_m2 > 0 && bar.orientation_std_rad > 0, "the bar's shape has its 1 sigma");
check(bar.outline.points.length >= 3, "the bar's contact has its outline's polygon");
console.log(`mcap: the bar's contact ${(1e3 * bar.semi_major_m).toFixed(2)} x ${(1e3 * bar.semi_minor_m).toFixed(2)} mm ` +
            `at ${(bar.orientation_rad * 180 / Math.PI).toFixed(1)} deg (area ${(1e6 * bar.area).toFixed(1)} mm^2)`);

// Pressure images: one float per triangle; their largest is the strongest contact's peak.
topics["/emit/pressure"].forEach((p, f) => {
  check(p.pressure.length === mesh.triangles.length, `pressure ${f}: one value per triangle`);
  const peak = Math.max(...p.pressure), expected = Math.max(...contacts[f].contacts.map((c) => c.peak_pressure));
  check(close(peak, expected, 1e-6), `pressure ${f}: peak ${peak} Pa against the contacts' ${expected}`);
});

// The pressure as RViz draws it: a PointCloud2 of a point per triangle, at its centroid [m], its
// pressure [Pa] the image's, bit for bit (float32 both).
const clouds = topics["/emit/pressure_cloud"];
check(clouds.length === topics["/emit/pressure"].length, `${clouds.length} pressure clouds for ${topics["/emit/pressure"].length} images`);
clouds.forEach((cloud, f) => {
  const image = topics["/emit/pressure"][f].pressure, n = mesh.triangles.length;
  check(cloud.height === 1 && cloud.width === n && cloud.point_step === 16 && cloud.row_step === 16 * n &&
        cloud.data.length === 16 * n && !cloud.is_bigendian && cloud.is_dense, `cloud ${f}: its layout`);
  check(JSON.stringify(cloud.fields.map((p) => [p.name, p.offset, p.datatype, p.count])) ===
        JSON.stringify([["x", 0, 7, 1], ["y", 4, 7, 1], ["z", 8, 7, 1], ["pressure", 12, 7, 1]]), `cloud ${f}: its fields`);
  const view = new DataView(cloud.data.buffer, cloud.data.byteOffset, cloud.data.byteLength);
  let same = 0, placed = 0;
  for (let t = 0; t < n; ++t) {
    same += view.getFloat32(16 * t + 12, true) === Math.fround(image[t]);
    const corners = Array.from(mesh.triangles[t].vertex_indices, (v) => mesh.vertices[v]);
    const centroid = ["x", "y", "z"].map((axis) => corners.reduce((sum, p) => sum + p[axis], 0) / 3);
    placed += centroid.every((v, axis) => Math.abs(view.getFloat32(16 * t + 4 * axis, true) - v) <= 1e-7);
  }
  check(same === n, `cloud ${f}: ${same} of ${n} pressures are the image's`);
  check(placed === n, `cloud ${f}: ${placed} of ${n} points at their triangles' centroids`);
});

// Cut short anywhere, the file is reported incomplete, and what was read is what was written.
const full = whole.records.filter((r) => r.type === "Message");
let cuts = 0;
for (let cut = 8; cut < bytes.length; cut += Math.max(1, Math.floor(bytes.length / 97))) {
  const part = readRecords(bytes.subarray(0, cut));
  check(!part.complete, `cut at ${cut} of ${bytes.length}: reported incomplete`);
  const messages = part.records.filter((r) => r.type === "Message");
  check(messages.every((m, i) => Buffer.compare(Buffer.from(m.data), Buffer.from(full[i].data)) === 0),
        `cut at ${cut}: the messages read are the file's`);
  cuts++;
}
check(!readRecords(bytes.subarray(0, bytes.length - 1)).complete, "one byte short: incomplete");

// A folder that does not exist: one line, exit non-zero, nothing written.
const missing = spawnSync(emit, ["reconstruct", "--method", "paper", "--reference", at("ref.csv"), "--frames",
  at("two.csv"), "--contacts", at("c2.jsonl"), "--mcap", at("no/such/run.mcap"), ...cache], { encoding: "utf8" });
check(missing.status !== 0 && /no\/such.*does not exist/.test(missing.stderr) && missing.stderr.trim().split("\n").length === 1,
      `missing folder: ${missing.stderr}`);
check(!existsSync(at("no")) && !existsSync(at("c2.jsonl")), "nothing written for a missing folder");

// Live: 20 reconstructed frames of the twin's held press, their source's numbers, the press found.
run("live", "--source", "sim:fixed:30,30,10", "--fps", "0", "--frames", "20", "--method", "paper", "--mcap", at("live.mcap"), ...cache);
const live = readRecords(new Uint8Array(readFileSync(at("live.mcap"))));
check(live.complete, "the live recording reads to its end");
const liveTopics = decode(live.records).topics;
const liveContacts = liveTopics["/emit/contacts"];
check(liveContacts.length === 20 && liveTopics["/emit/frames"].length === 20 && liveTopics["/emit/pressure"].length === 20,
      `20 live frames on each topic (${liveContacts.length})`);
check(liveContacts.every((m, i) => Number(m.frame) === 10 + i), "live frames numbered 10..29 (after the baseline's 10)");
// Times: the board's clock goes forward; the header stamps (when each frame reached the host, Unix
// time) too, and are the MCAP log times, taken within this test's run.
const stampNs = (m) => BigInt(m.header.stamp.sec) * 1000000000n + BigInt(m.header.stamp.nanosec);
check(liveContacts.every((m, i) => i === 0 || (m.board_time > liveContacts[i - 1].board_time &&
      stampNs(m) >= stampNs(liveContacts[i - 1]))), "live board times and stamps go forward");
check(liveContacts.every((m) => m.logTime === stampNs(m) &&
      Math.abs(Number(stampNs(m) / 1000000n) - Date.now()) < 600e3), "live stamps: the host's receive time, now");
// The twin's first 15 frames are untouched; the press is found within the README's p95, 8.05 mm.
const pressed = liveContacts.filter((m) => Number(m.frame) >= 15);
check(pressed.length === 15 && pressed.every((m) => m.contacts.length >= 1 &&
      Math.hypot(m.contacts[0].position.x - 0.03, m.contacts[0].position.y - 0.03) < 8.05e-3), "live press found at (30, 30) mm");

// Export: a live run's recording (10 reference frames, then 20) exported as MCAP: every frame of the
// recording on each topic, numbered by its index in it, the board's times going forward, stamped
// with the recording's start plus the board's time (so within this test's run), the press found.
run("live", "--source", "sim:fixed:30,30,10", "--fps", "0", "--frames", "20", "--method", "paper", "--record",
    at("live.emitrec"), ...cache);
run("export", at("live.emitrec"), "--method", "paper", "--mcap", at("export.mcap"), "--contacts", at("export.jsonl"),
    ...cache);
const exported = readRecords(new Uint8Array(readFileSync(at("export.mcap"))));
check(exported.complete, "the exported recording reads to its end");
const exportTopics = decode(exported.records).topics;
const exportContacts = exportTopics["/emit/contacts"];
check(exportContacts.length === 30 && exportTopics["/emit/frames"].length === 30 &&
      exportTopics["/emit/pressure"].length === 30, `30 exported frames on each topic (${exportContacts.length})`);
check(exportContacts.every((m, i) => Number(m.frame) === i), "exported frames numbered 0..29 (the recording's)");
check(exportContacts.every((m, i) => m.logTime === stampNs(m) && (i === 0 ||
      (m.board_time > exportContacts[i - 1].board_time && stampNs(m) >= stampNs(exportContacts[i - 1])))),
      "exported board times and stamps go forward");
check(exportContacts.every((m) => Math.abs(Number(stampNs(m) / 1000000n) - Date.now()) < 600e3),
      "exported stamps: the recording's start and the board's time, within this run");
const exportLines = readFileSync(at("export.jsonl"), "utf8").trim().split("\n").map((line) => JSON.parse(line));
check(exportLines.length === 30 && exportLines.every((line, i) => close(line.board_time_s, exportContacts[i].board_time, 1e-5)),
      "the exported contacts' board times are the MCAP's");
const exportPressed = exportContacts.filter((m) => Number(m.frame) >= 15);
check(exportPressed.length === 15 && exportPressed.every((m) => m.contacts.length >= 1 &&
      Math.hypot(m.contacts[0].position.x - 0.03, m.contacts[0].position.y - 0.03) < 8.05e-3),
      "exported press found at (30, 30) mm");

console.log(`mcap: ${whole.records.length} records, ${full.length} messages read back and compared; ${cuts} cuts ` +
            `reported incomplete; live ${liveContacts.length} frames; ${failures} failures`);
process.exit(failures === 0 ? 0 : 1);
