// Writes MCAP files with @mcap/core's writer, the reference implementation: one per chunk
// compression (none, zstd, lz4), each with a schema, two channels, messages out of log-time order
// across chunks, metadata and an attachment. Prints, as JSON, what each file holds, for kestrel's
// reader to be checked against.
// Usage: node mcap_core_write.mjs OUTDIR
import { McapWriter } from "@mcap/core";
import { createRequire } from "node:module";
import { open } from "node:fs/promises";

const require = createRequire(import.meta.url);
const zstd = require("@foxglove/wasm-zstd");
await zstd.isLoaded;
// @foxglove/wasm-lz4 only decompresses; an LZ4 frame of stored (uncompressed) blocks is valid LZ4
// and exercises the reader's frame parsing all the same.
function lz4StoredFrame(data) {
  const header = Buffer.from([0x04, 0x22, 0x4d, 0x18, 0x60, 0x40, 0x82]);  // magic, FLG, BD 64 KiB, HC
  const blocks = [];
  for (let at = 0; at < data.length; at += 64 << 10) {
    const block = data.subarray(at, Math.min(data.length, at + (64 << 10)));
    const size = Buffer.alloc(4);
    size.writeUInt32LE((block.length | 0x80000000) >>> 0);  // high bit: stored, not compressed
    blocks.push(size, Buffer.from(block));
  }
  return Buffer.concat([header, ...blocks, Buffer.alloc(4)]);  // end mark
}
const compressors = {
  none: undefined,
  zstd: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }),
  lz4: (data) => ({ compression: "lz4", compressedData: lz4StoredFrame(data) }),
};

const outdir = process.argv[2];
const files = {};
for (const [name, compressChunk] of Object.entries(compressors)) {
  const path = `${outdir}/${name}.mcap`;
  const handle = await open(path, "w");
  let position = 0n;
  const writable = {
    position: () => position,
    write: async (buffer) => {
      await handle.write(buffer);
      position += BigInt(buffer.byteLength);
    },
  };
  const writer = new McapWriter({ writable, chunkSize: 300, compressChunk });
  await writer.start({ profile: "ros2", library: "@mcap/core interop" });
  const schemaId = await writer.registerSchema({
    name: "std_msgs/msg/String",
    encoding: "ros2msg",
    data: new TextEncoder().encode("string data\n"),
  });
  const text = await writer.registerChannel({ topic: "/text", schemaId, messageEncoding: "cdr", metadata: new Map([["node", "talker"]]) });
  const raw = await writer.registerChannel({ topic: "/raw", schemaId: 0, messageEncoding: "json", metadata: new Map() });
  const messages = [];
  for (let i = 0; i < 40; i++) {
    const channelId = i % 3 === 0 ? raw : text;
    const logTime = BigInt(1_000_000 * ((i * 7) % 40));
    const data = new TextEncoder().encode(i % 3 === 0 ? JSON.stringify({ i }) : `message ${i} `.repeat(1 + (i % 5)));
    await writer.addMessage({ channelId, sequence: i, logTime, publishTime: logTime + 5n, data });
    messages.push({ channel_id: channelId, sequence: i, log_time: logTime.toString(), data: Buffer.from(data).toString("hex") });
  }
  await writer.addMetadata({ name: "run", metadata: new Map([["seed", "7"]]) });
  await writer.addAttachment({ name: "notes.txt", mediaType: "text/plain", logTime: 3n, createTime: 2n, data: new TextEncoder().encode("hello") });
  await writer.end();
  await handle.close();
  files[name] = { path, messages };
}
console.log(JSON.stringify(files));
