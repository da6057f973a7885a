// An MCAP recording checked as it streams (a FIFO `emit live --mcap` writes into, or a file), by
// the format's own reader, @mcap/core, with CRCs checked, keeping only counts: however long the
// run, memory stays flat. It prints one line,
//
//   mcap: complete; /emit/contacts 812 (sequence 0..811), /emit/frames 812 (…), /emit/mesh 1 (…), …
//
// and exits 0 when the stream ends with its footer and closing magic and each channel's message
// sequence numbers run on by one from 0; 1 otherwise, saying why.
//
//   node stream_check.mjs <path>
import { McapStreamReader } from "@mcap/core";
import { createReadStream } from "node:fs";

const [path] = process.argv.slice(2);
const reader = new McapStreamReader({ validateCrcs: true });
const channels = new Map();  // id -> { topic, count, first, last, gaps }
let error = null;

function drain() {
  for (let record; (record = reader.nextRecord()); ) {
    if (record.type === "Channel") channels.set(record.id, { topic: record.topic, count: 0, first: -1, last: -1, gaps: 0 });
    if (record.type !== "Message") continue;
    const c = channels.get(record.channelId);
    if (c.count === 0) c.first = record.sequence;
    else if (record.sequence !== c.last + 1) c.gaps++;
    c.last = record.sequence;
    c.count++;
  }
}

const stream = createReadStream(path, { highWaterMark: 1 << 20 });
stream.on("data", (chunk) => {
  if (error) return;
  try {
    reader.append(chunk);
    drain();
  } catch (e) {
    error = e;
  }
});
stream.on("error", (e) => {
  console.log(`mcap: FAIL: cannot read ${path}: ${e.message}`);
  process.exit(1);
});
stream.on("end", () => {
  const topics = [...channels.values()]
    .sort((a, b) => a.topic.localeCompare(b.topic))
    .map((c) => `${c.topic} ${c.count} (sequence ${c.first}..${c.last}${c.gaps ? `, ${c.gaps} gaps` : ""})`)
    .join(", ");
  const gaps = [...channels.values()].some((c) => c.gaps > 0 || (c.count > 0 && c.first !== 0));
  if (error) console.log(`mcap: FAIL: ${error.message}; ${topics}`);
  else if (!reader.done()) console.log(`mcap: FAIL: incomplete (no footer); ${topics}`);
  else if (gaps) console.log(`mcap: FAIL: message sequence numbers do not run on by one; ${topics}`);
  else console.log(`mcap: complete; ${topics}`);
  process.exit(error || !reader.done() || gaps ? 1 : 0);
});
