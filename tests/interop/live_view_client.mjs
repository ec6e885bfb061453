// Watches a kestrel run served with --live as Foxglove does: @foxglove/ws-protocol's client on a
// `ws` WebSocket, every channel decoded from its advertised ros2msg schema by @foxglove/rosmsg and
// @foxglove/rosmsg2-serialization. Subscribes to every channel whose topic matches one of the
// patterns given, and exits once each has decoded a message and a Time frame has come. A pattern
// "tf:PARENT>CHILD" waits for that transform on /tf instead. Prints a JSON summary: {"serverInfo",
// "channels": [...], "received": {TOPIC: {count, schemaName, sample}}, "transforms": ["PARENT>CHILD"],
// "times", "firstTime", "lastTime"}.
// With WATCH_SECONDS set, it stays subscribed that long before it prints, as a viewer left open
// (docs/benchmarks.md measures the chain's cost so).
// Usage: [WATCH_SECONDS=S] node live_view_client.mjs ws://HOST:PORT PATTERN [PATTERN...]
import wsProtocol from "@foxglove/ws-protocol"; // CommonJS: no named exports under ESM

import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import WebSocket from "ws";

const { FoxgloveClient } = wsProtocol;
const [url, ...patterns] = process.argv.slice(2);
const wantedTransforms = new Set(patterns.filter((p) => p.startsWith("tf:")).map((p) => p.slice(3)));
const wanted = patterns.filter((p) => !p.startsWith("tf:")).map((p) => new RegExp(p));
if (wantedTransforms.size > 0) wanted.push(/^\/tf$/);
const client = new FoxgloveClient({ ws: new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]) });
const summary = { serverInfo: null, channels: [], received: {}, transforms: [], times: 0, firstTime: null,
                  lastTime: null };
const bySubscription = new Map();
const pending = new Set([...wanted.map(String), ...[...wantedTransforms].map((t) => `tf:${t}`)]);

const fail = (why) => {
  console.error(`live_view_client: ${why}`);
  console.error(`advertised: ${summary.channels.map((c) => c.topic).join(" ")}`);
  console.error(`received: ${Object.keys(summary.received).join(" ")}`);
  process.exit(1);
};
const bigintSafe = (_key, value) => (typeof value === "bigint" ? value.toString() : value);
const started = Date.now();
const watchMs = 1000 * Number(process.env.WATCH_SECONDS ?? 0);
const done = () => {
  if (pending.size > 0 || summary.times === 0 || Date.now() - started < watchMs) return;
  console.log(JSON.stringify(summary, bigintSafe));
  client.close();
  process.exit(0);
};

client.on("error", (e) => fail(`error: ${e?.message ?? e}`));
client.on("close", () => fail(`closed before every pattern got a message; still waiting for ${[...pending]}`));
client.on("serverInfo", (info) => (summary.serverInfo = info));
client.on("status", (s) => console.error(`status ${s.level}: ${s.message}`));
client.on("advertise", (channels) => {
  for (const c of channels) {
    summary.channels.push({ id: c.id, topic: c.topic, encoding: c.encoding, schemaName: c.schemaName,
                            schemaEncoding: c.schemaEncoding });
    const match = wanted.find((w) => w.test(c.topic));
    if (!match) continue;
    if (c.encoding !== "cdr" || c.schemaEncoding !== "ros2msg") fail(`${c.topic}: ${c.encoding}/${c.schemaEncoding}`);
    const reader = new MessageReader(parse(c.schema, { ros2: true }));
    bySubscription.set(client.subscribe(c.id), { channel: c, reader });
  }
});
client.on("time", ({ timestamp }) => {
  summary.times += 1;
  if (summary.firstTime === null) summary.firstTime = timestamp;
  summary.lastTime = timestamp;
  done();
});
client.on("message", ({ subscriptionId, timestamp, data }) => {
  const s = bySubscription.get(subscriptionId);
  if (!s) fail(`a message for subscription ${subscriptionId}, which was never made`);
  const bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  const message = s.reader.readMessage(bytes);
  const entry = (summary.received[s.channel.topic] ??= { count: 0, schemaName: s.channel.schemaName, sample: null });
  entry.count += 1;
  if (!entry.sample) {
    // Big arrays (image and cloud bytes) are summarised by their length.
    entry.sample = JSON.parse(JSON.stringify(message, (k, v) =>
      v instanceof Uint8Array || (Array.isArray(v) && v.length > 16) ? { length: v.length } : bigintSafe(k, v)));
    entry.sample.receive_time_ns = timestamp.toString();
  }
  for (const w of wanted) if (w.test(s.channel.topic)) pending.delete(String(w));  // every pattern it matches
  if (s.channel.schemaName === "tf2_msgs/msg/TFMessage")
    for (const t of message.transforms) {
      const pair = `${t.header.frame_id}>${t.child_frame_id}`;
      if (!summary.transforms.includes(pair)) summary.transforms.push(pair);
      pending.delete(`tf:${pair}`);
    }
  done();
});
setTimeout(() => fail(`timed out; still waiting for ${[...pending]}`), 120000 + watchMs);
