// Fuzz target: the MCAP reader. Any bytes must open and read (summary, messages, metadata,
// attachments, verification) or give a kestrel::mcap::FormatError; never a crash, undefined
// behaviour, a read out of bounds, an allocation beyond the reader's limit or another exception.
#include <cstdint>
#include <cstdlib>

#include "kestrel/mcap/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  kestrel::mcap::ReaderOptions options;
  options.max_record_bytes = 1 << 20;  // far below the fuzzer's memory limit
  try {
    kestrel::mcap::Reader reader(kestrel::mcap::Bytes(data, data + size), options);
    std::uint64_t messages = 0;
    reader.read_messages({}, [&](const kestrel::mcap::MessageView& m) {
      if (m.channel.id != m.message.channel_id) std::abort();
      ++messages;
    });
    kestrel::mcap::MessageFilter filter;
    filter.start = 1;
    filter.end = 1'000'000;
    filter.topics = {"/a"};
    reader.read_messages(filter, [&](const kestrel::mcap::MessageView& m) {
      if (m.message.log_time < 1 || m.message.log_time >= 1'000'000 || m.channel.topic != "/a") std::abort();
    });
    reader.metadata();
    reader.attachments();
    reader.verify();
  } catch (const kestrel::mcap::FormatError&) {
    // a malformed file: the message says what and at which byte
  }
  return 0;
}
