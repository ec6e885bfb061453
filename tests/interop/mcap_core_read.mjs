// Reads an MCAP file with @mcap/core, the reference implementation, with every CRC checked:
// the indexed reader (summary CRC, chunk CRCs), the stream reader (chunk CRCs) and the data
// section CRC recomputed here. Prints what it read as JSON for the test to compare.
// Usage: node mcap_core_read.mjs FILE
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { crc32 } from "@foxglove/crc";
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
const hex = (data) => Buffer.from(data).toString("hex");
const describe = (m, channels) => ({
  topic: channels.get(m.channelId).topic,
  channel_id: m.channelId,
  sequence: m.sequence,
  log_time: m.logTime.toString(),
  publish_time: m.publishTime.toString(),
  data: hex(m.data),
});

// Indexed.
const readable = {
  size: async () => BigInt(bytes.length),
  read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
};
const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
if (reader.footer.summaryCrc === 0) throw new Error("the summary CRC is absent");
const indexed = [];
for await (const m of reader.readMessages({ validateCrcs: true })) indexed.push(describe(m, reader.channelsById));
if (!reader.dataSectionCrc) throw new Error("the data section CRC is absent");
const dataCrc = crc32(bytes.subarray(0, Number(reader.dataEndOffset)));
if (dataCrc !== reader.dataSectionCrc)
  throw new Error(`data section CRC ${reader.dataSectionCrc} in the file, ${dataCrc} computed`);
const metadata = [];
for await (const m of reader.readMetadata()) metadata.push({ name: m.name, metadata: Object.fromEntries(m.metadata) });
const attachments = [];
for await (const a of reader.readAttachments({ validateCrcs: true }))
  attachments.push({ name: a.name, media_type: a.mediaType, data: hex(a.data) });

// Streamed, record by record.
const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
stream.append(bytes);
const channels = new Map();
const streamed = [];
let footer = false;
for (let record; (record = stream.nextRecord()); ) {
  if (record.type === "Channel") channels.set(record.id, record);
  if (record.type === "Message") streamed.push(describe(record, channels));
  if (record.type === "Footer") footer = true;
}
if (!footer || !stream.done()) throw new Error("the stream reader did not reach the footer");

const schemas = [...reader.schemasById.values()].map((s) => ({
  id: s.id,
  name: s.name,
  encoding: s.encoding,
  data: Buffer.from(s.data).toString("utf8"),
}));
const s = reader.statistics;
console.log(
  JSON.stringify({
    profile: reader.header.profile,
    library: reader.header.library,
    statistics: {
      messages: Number(s.messageCount),
      channels: s.channelCount,
      schemas: s.schemaCount,
      chunks: s.chunkCount,
      attachments: s.attachmentCount,
      metadata: s.metadataCount,
      start_time_ns: s.messageStartTime.toString(),
      end_time_ns: s.messageEndTime.toString(),
    },
    channels: [...reader.channelsById.values()].map((c) => ({
      id: c.id,
      topic: c.topic,
      message_encoding: c.messageEncoding,
      schema_id: c.schemaId,
      metadata: Object.fromEntries(c.metadata),
    })),
    schemas,
    compression: [...new Set(reader.chunkIndexes.map((c) => c.compression))],
    indexed_messages: indexed,
    streamed_messages: streamed,
    metadata,
    attachments,
  }),
);
