// Reads a kestrel recording as Foxglove does: @mcap/core's indexed reader with every CRC checked
// (summary, chunks, and the data section recomputed here), each message decoded from its channel's
// ros2msg schema by @foxglove/rosmsg and @foxglove/rosmsg2-serialization. Prints one JSON line per
// message, {"log_time", "topic", "message"}, as `kestrel mcap cat` must; then a last line
// {"summary": {...}} with the header, channels and metadata.
// Usage: node ros2_recording_read.mjs FILE
import { McapIndexedReader } from "@mcap/core";
import { crc32 } from "@foxglove/crc";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import { createRequire } from "node:module";
import { readFileSync } from "node:fs";

const require = createRequire(import.meta.url);
const zstd = require("@foxglove/wasm-zstd");
const lz4 = require("@foxglove/wasm-lz4");
await zstd.isLoaded;
await lz4.isLoaded;
const decompressHandlers = {
  zstd: (data, size) => zstd.decompress(data, Number(size)),
  lz4: (data, size) => lz4(data, Number(size)),
};

const bytes = readFileSync(process.argv[2]);
const readable = {
  size: async () => BigInt(bytes.length),
  read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
};
const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
if (reader.footer.summaryCrc === 0) throw new Error("the summary CRC is absent");
if (!reader.dataSectionCrc) throw new Error("the data section CRC is absent");
const dataCrc = crc32(bytes.subarray(0, Number(reader.dataEndOffset)));
if (dataCrc !== reader.dataSectionCrc) throw new Error(`data section CRC ${reader.dataSectionCrc}, ${dataCrc} computed`);

const readers = new Map();
for (const c of reader.channelsById.values()) {
  const s = reader.schemasById.get(c.schemaId);
  if (c.messageEncoding !== "cdr" || s.encoding !== "ros2msg") throw new Error(`${c.topic}: not cdr with ros2msg`);
  readers.set(c.id, new MessageReader(parse(new TextDecoder().decode(s.data), { ros2: true })));
}
// JSON as kestrel prints it: typed arrays as arrays, 64-bit integers as numbers, NaN as null.
const plain = (v) =>
  typeof v === "bigint" ? Number(v)
  : ArrayBuffer.isView(v) ? Array.from(v)
  : Array.isArray(v) ? v.map(plain)
  : v && typeof v === "object" ? Object.fromEntries(Object.entries(v).map(([k, x]) => [k, plain(x)]))
  : typeof v === "number" && !Number.isFinite(v) ? null
  : v;
for await (const m of reader.readMessages({ validateCrcs: true })) {
  const topic = reader.channelsById.get(m.channelId).topic;
  console.log(JSON.stringify({ log_time: Number(m.logTime), topic, message: plain(readers.get(m.channelId).readMessage(m.data)) }));
}
const metadata = {};
for await (const m of reader.readMetadata()) metadata[m.name] = Object.fromEntries(m.metadata);
console.log(JSON.stringify({
  summary: {
    profile: reader.header.profile,
    messages: Number(reader.statistics.messageCount),
    channels: [...reader.channelsById.values()].map((c) => ({ topic: c.topic, schema: reader.schemasById.get(c.schemaId).name })),
    metadata,
  },
}));
