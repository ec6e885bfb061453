// Synthesizes a ROS 2-style bag (profile ros2, cdr messages, ros2msg schemas, zstd chunks) with
// @mcap/core, @foxglove/wasm-zstd, @foxglove/rosmsg and @foxglove/rosmsg2-serialization, the
// implementations Foxglove reads bags with, and prints each message as `kestrel mcap cat` must:
// one JSON line {"log_time", "topic", "message"}, in log-time order.
// Usage: node ros2_bag_write.mjs FILE
import { McapWriter } from "@mcap/core";
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";
import { createRequire } from "node:module";
import { open } from "node:fs/promises";
import { schemaText } from "./ros2_definitions.mjs";

const require = createRequire(import.meta.url);
const zstd = require("@foxglove/wasm-zstd");
await zstd.isLoaded;

const handle = await open(process.argv[2], "w");
let position = 0n;
const writable = {
  position: () => position,
  write: async (buffer) => {
    await handle.write(buffer);
    position += BigInt(buffer.byteLength);
  },
};
const writer = new McapWriter({
  writable,
  chunkSize: 4096,
  compressChunk: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 5) }),
});
await writer.start({ profile: "ros2", library: "rosbag2-style interop bag" });

const channels = {};
async function channel(topic, type) {
  const text = schemaText(type);
  const definitions = parse(text, { ros2: true });
  const schemaId = await writer.registerSchema({ name: type, encoding: "ros2msg", data: new TextEncoder().encode(text) });
  const id = await writer.registerChannel({ topic, schemaId, messageEncoding: "cdr", metadata: new Map() });
  channels[topic] = { id, writer: new MessageWriter(definitions), reader: new MessageReader(definitions) };
}
await channel("/chatter", "std_msgs/msg/String");
await channel("/camera/left/image_raw", "sensor_msgs/msg/Image");
await channel("/odom", "nav_msgs/msg/Odometry");
await channel("/tf", "tf2_msgs/msg/TFMessage");
await channel("/points", "sensor_msgs/msg/PointCloud2");

const header = (i, frame) => ({ stamp: { sec: i, nanosec: 1000 * i }, frame_id: frame });
const covariance = (i) => Array.from({ length: 36 }, (_, k) => (k % 7 === 0 ? 0.01 * (i + 1) : 0));
const lines = [];
let sequence = 0;
async function add(topic, logTime, message) {
  const c = channels[topic];
  const data = c.writer.writeMessage(message);
  await writer.addMessage({ channelId: c.id, sequence: sequence++, logTime, publishTime: logTime, data });
  // What Foxglove decodes from those bytes, in the JSON `kestrel mcap cat` prints.
  const decoded = c.reader.readMessage(data);
  lines.push({ log_time: logTime, topic, message: decoded });
}
for (let i = 0; i < 20; i++) {
  const t = BigInt(i) * 50_000_000n;
  await add("/chatter", t, { data: `hello ${i}` });
  await add("/odom", t + 1n, {
    header: header(i, "odom"),
    child_frame_id: "base_link",
    pose: { pose: { position: { x: i * 0.5, y: -i, z: 1e-9 * i }, orientation: { x: 0, y: 0, z: 0.1, w: 0.99 } }, covariance: covariance(i) },
    twist: { twist: { linear: { x: 1.25, y: 0, z: -0.5 }, angular: { x: 0, y: 0, z: i / 3 } }, covariance: covariance(i) },
  });
  if (i % 4 === 0) {
    await add("/camera/left/image_raw", t + 2n, {
      header: header(i, "camera_left"), height: 4, width: 3, encoding: "mono8", is_bigendian: 0, step: 3,
      data: Uint8Array.from({ length: 12 }, (_, k) => (k * 21 + i) % 256),
    });
    await add("/tf", t + 3n, {
      transforms: [
        { header: header(i, "world"), child_frame_id: "hunter", transform: { translation: { x: i, y: 2, z: 3 }, rotation: { x: 0, y: 0, z: 0, w: 1 } } },
        { header: header(i, "world"), child_frame_id: "intruder", transform: { translation: { x: -i, y: 0.5, z: 2.5 }, rotation: { x: 0.5, y: 0.5, z: 0.5, w: 0.5 } } },
      ],
    });
    const points = new Float32Array([i, 1.5, -2.25, 3, 4, 5]);
    await add("/points", t + 4n, {
      header: header(i, "camera"), height: 1, width: 2,
      fields: ["x", "y", "z"].map((name, k) => ({ name, offset: 4 * k, datatype: 7, count: 1 })),
      is_bigendian: false, point_step: 12, row_step: 24, data: new Uint8Array(points.buffer), is_dense: true,
    });
  }
}
await writer.end();
await handle.close();

// JSON as kestrel prints it: typed arrays as arrays, 64-bit integers as numbers, NaN as null.
const plain = (v) =>
  typeof v === "bigint" ? Number(v)
  : ArrayBuffer.isView(v) ? Array.from(v)
  : Array.isArray(v) ? v.map(plain)
  : v && typeof v === "object" ? Object.fromEntries(Object.entries(v).map(([k, x]) => [k, plain(x)]))
  : typeof v === "number" && !Number.isFinite(v) ? null
  : v;
lines.sort((a, b) => (a.log_time < b.log_time ? -1 : a.log_time > b.log_time ? 1 : 0));
for (const line of lines) console.log(JSON.stringify(plain(line)));
