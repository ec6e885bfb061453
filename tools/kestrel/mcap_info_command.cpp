// kestrel mcap info FILE: what a recording holds (channels, schemas, message counts and rates,
// time range, chunk compression), as the MCAP tools print it, or as JSON with --json.
#include <fmt/format.h>

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "command_errors.hpp"
#include "commands.hpp"
#include "kestrel/mcap/reader.hpp"

namespace kestrel::cli {

namespace {

std::string human_bytes(std::uint64_t n) {
  if (n < 1024) return fmt::format("{} B", n);
  if (n < (1u << 20)) return fmt::format("{:.1f} KiB", static_cast<double>(n) / 1024);
  return fmt::format("{:.1f} MiB", static_cast<double>(n) / (1 << 20));
}

std::string seconds(mcap::Timestamp t) { return fmt::format("{}.{:09d}", t / 1'000'000'000u, t % 1'000'000'000u); }

nlohmann::json info_json(mcap::Reader& reader, const std::optional<mcap::Verification>& verified) {
  const mcap::Summary& s = reader.summary();
  nlohmann::json out;
  out["library"] = s.header.library;
  out["profile"] = s.header.profile;
  out["indexed"] = s.indexed;
  out["messages"] = s.statistics.message_count;
  out["chunks"] = s.statistics.chunk_count;
  out["start_time_ns"] = s.statistics.message_start_time;
  out["end_time_ns"] = s.statistics.message_end_time;
  nlohmann::json compression = nlohmann::json::object();
  for (const mcap::ChunkIndex& c : s.chunk_indexes) {
    auto& entry = compression[c.compression.empty() ? "none" : c.compression];
    if (entry.is_null()) entry = {{"chunks", 0}, {"compressed_bytes", 0}, {"uncompressed_bytes", 0}};
    entry["chunks"] = entry["chunks"].get<int>() + 1;
    entry["compressed_bytes"] = entry["compressed_bytes"].get<std::uint64_t>() + c.compressed_size;
    entry["uncompressed_bytes"] = entry["uncompressed_bytes"].get<std::uint64_t>() + c.uncompressed_size;
  }
  out["compression"] = compression;
  out["channels"] = nlohmann::json::array();
  for (const auto& [id, c] : s.channels) {
    const auto count = s.statistics.channel_message_counts.find(id);
    const auto schema = s.schemas.find(c.schema_id);
    out["channels"].push_back({{"id", id},
                               {"topic", c.topic},
                               {"message_encoding", c.message_encoding},
                               {"schema_name", schema == s.schemas.end() ? "" : schema->second.name},
                               {"schema_encoding", schema == s.schemas.end() ? "" : schema->second.encoding},
                               {"messages", count == s.statistics.channel_message_counts.end() ? 0 : count->second},
                               {"metadata", c.metadata}});
  }
  out["schemas"] = s.schemas.size();
  out["attachments"] = s.attachment_indexes.size();
  out["metadata"] = s.metadata_indexes.size();
  out["problems"] = reader.problems();
  if (verified)
    out["verified"] = {{"data_section_crc", verified->data_section_crc_present},
                       {"summary_crc", verified->summary_crc_present},
                       {"chunks_with_crc", verified->chunks_with_crc},
                       {"chunks", verified->chunks},
                       {"attachments_with_crc", verified->attachments_with_crc}};
  return out;
}

void print_text(const nlohmann::json& info) {
  const double duration_s =
      (info["end_time_ns"].get<std::uint64_t>() - info["start_time_ns"].get<std::uint64_t>()) * 1e-9;
  std::printf("library:     %s\n", info["library"].get<std::string>().c_str());
  std::printf("profile:     %s\n", info["profile"].get<std::string>().c_str());
  std::printf("messages:    %llu\n", static_cast<unsigned long long>(info["messages"].get<std::uint64_t>()));
  std::printf("duration:    %.9f s\n", duration_s);
  std::printf("start:       %s\n", seconds(info["start_time_ns"].get<std::uint64_t>()).c_str());
  std::printf("end:         %s\n", seconds(info["end_time_ns"].get<std::uint64_t>()).c_str());
  std::printf("indexed:     %s\n", info["indexed"].get<bool>() ? "yes" : "no (read by streaming)");
  std::printf("compression:\n");
  for (const auto& [name, c] : info["compression"].items()) {
    const auto compressed = c["compressed_bytes"].get<std::uint64_t>(),
               raw = c["uncompressed_bytes"].get<std::uint64_t>();
    std::printf("\t%s: %d chunks, %s of %s (%.1f%% smaller)\n", name.c_str(), c["chunks"].get<int>(),
                human_bytes(compressed).c_str(), human_bytes(raw).c_str(),
                raw > 0 ? 100.0 * (1.0 - static_cast<double>(compressed) / static_cast<double>(raw)) : 0.0);
  }
  std::size_t width = 0;
  for (const auto& c : info["channels"]) width = std::max(width, c["topic"].get<std::string>().size());
  std::printf("channels:\n");
  for (const auto& c : info["channels"]) {
    const auto n = c["messages"].get<std::uint64_t>();
    const std::string rate = duration_s > 0 ? fmt::format(" ({:.2f} Hz)", static_cast<double>(n) / duration_s) : "";
    std::printf("\t(%d) %-*s %llu msgs%s : %s [%s] %s\n", c["id"].get<int>(), static_cast<int>(width),
                c["topic"].get<std::string>().c_str(), static_cast<unsigned long long>(n), rate.c_str(),
                c["schema_name"].get<std::string>().c_str(), c["schema_encoding"].get<std::string>().c_str(),
                c["message_encoding"].get<std::string>().c_str());
  }
  std::printf("schemas:     %zu\n", info["schemas"].get<std::size_t>());
  std::printf("attachments: %zu\n", info["attachments"].get<std::size_t>());
  std::printf("metadata:    %zu\n", info["metadata"].get<std::size_t>());
  if (info.contains("verified")) {
    const auto& v = info["verified"];
    std::printf("verified:    data section CRC %s, summary CRC %s, %llu of %llu chunks with a CRC, all matching\n",
                v["data_section_crc"].get<bool>() ? "matches" : "absent",
                v["summary_crc"].get<bool>() ? "matches" : "absent",
                static_cast<unsigned long long>(v["chunks_with_crc"].get<std::uint64_t>()),
                static_cast<unsigned long long>(v["chunks"].get<std::uint64_t>()));
  }
  for (const auto& p : info["problems"]) std::printf("note:        %s\n", p.get<std::string>().c_str());
}

}  // namespace

int mcap_info_command(const McapInfoArgs& args) {
  return run_command_body("mcap info", [&] {
    mcap::Reader reader(args.file);
    std::optional<mcap::Verification> verified;
    if (args.verify) verified = reader.verify();
    const nlohmann::json info = info_json(reader, verified);
    if (args.json)
      std::printf("%s\n", info.dump(2).c_str());
    else
      print_text(info);
    return kOk;
  });
}

}  // namespace kestrel::cli
