#pragma once
// Each MCAP record to and from its bytes. write_record appends the whole record (opcode, length,
// content); the parse_* functions read a record's content and ignore fields appended by later
// versions of the specification, as it requires.
#include "byte_io.hpp"
#include "kestrel/mcap/records.hpp"

namespace kestrel::mcap {

void write_record(ByteWriter& out, const Header& r);
void write_record(ByteWriter& out, const Footer& r);
void write_record(ByteWriter& out, const Schema& r);
void write_record(ByteWriter& out, const Channel& r);
void write_record(ByteWriter& out, const Message& r);
void write_record(ByteWriter& out, const Chunk& r);
void write_record(ByteWriter& out, const MessageIndex& r);
void write_record(ByteWriter& out, const ChunkIndex& r);
/// Computes the record's CRC over its fields when `with_crc`, else writes 0.
void write_record(ByteWriter& out, const Attachment& r, bool with_crc);
void write_record(ByteWriter& out, const AttachmentIndex& r);
void write_record(ByteWriter& out, const Statistics& r);
void write_record(ByteWriter& out, const Metadata& r);
void write_record(ByteWriter& out, const MetadataIndex& r);
void write_record(ByteWriter& out, const SummaryOffset& r);
void write_record(ByteWriter& out, const DataEnd& r);

Header parse_header(ByteReader& in);
Footer parse_footer(ByteReader& in);
Schema parse_schema(ByteReader& in);
Channel parse_channel(ByteReader& in);
Message parse_message(ByteReader& in);  ///< the data is the rest of the record
Chunk parse_chunk(ByteReader& in);
MessageIndex parse_message_index(ByteReader& in);
ChunkIndex parse_chunk_index(ByteReader& in);
/// Throws FormatError when the record's CRC is not 0 and does not match its fields.
Attachment parse_attachment(ByteReader& in);
AttachmentIndex parse_attachment_index(ByteReader& in);
Statistics parse_statistics(ByteReader& in);
Metadata parse_metadata(ByteReader& in);
MetadataIndex parse_metadata_index(ByteReader& in);
SummaryOffset parse_summary_offset(ByteReader& in);
DataEnd parse_data_end(ByteReader& in);

}  // namespace kestrel::mcap
