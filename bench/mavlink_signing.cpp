// The cost of MAVLink 2 signing per frame (docs/field.md, "Security"): encoding a setpoint with and
// without its signature, and a receiver's check of a signed frame (SHA-256 over the frame and the
// key, the stream's timestamp), against parsing alone.
#include <benchmark/benchmark.h>

#include <memory>

#include "kestrel/mavlink/frame_parser.hpp"
#include "kestrel/mavlink/messages.hpp"
#include "kestrel/mavlink/signing.hpp"

using namespace kestrel::mavlink;

namespace {

SetPositionTargetLocalNed setpoint() {
  SetPositionTargetLocalNed sp;
  sp.time_boot_ms = 123456;
  sp.target_system = 1;
  sp.target_component = 1;
  sp.type_mask = 0x0DC0;
  sp.x = 1.5f;
  sp.y = -2.0f;
  sp.z = -3.0f;
  sp.vx = 0.5f;
  sp.yaw = 1.0f;
  return sp;
}

SigningKey key() {
  SigningKey k{};
  k.fill(0x5A);
  return k;
}

// Timestamps that keep rising, so that every check below is of a fresh frame.
struct RisingClock {
  SigningTimestamp now = 1'000'000'000;
  SigningTimestamp operator()() { return ++now; }
};

void BM_EncodeSetpoint(benchmark::State& state) {
  const SetPositionTargetLocalNed sp = setpoint();
  std::uint8_t sequence = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(encode_v2(SetPositionTargetLocalNed::definition(), &sp, {1, 191}, sequence++));
}
BENCHMARK(BM_EncodeSetpoint);

void BM_EncodeSignedSetpoint(benchmark::State& state) {
  const SetPositionTargetLocalNed sp = setpoint();
  Signing signing(SigningMode::require, key(), 0, RisingClock{});
  std::uint8_t sequence = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(signing.encode(SetPositionTargetLocalNed::definition(), &sp, {1, 191}, sequence++));
}
BENCHMARK(BM_EncodeSignedSetpoint);

void BM_ParseSetpoint(benchmark::State& state) {
  const SetPositionTargetLocalNed sp = setpoint();
  const auto bytes = encode_v2(SetPositionTargetLocalNed::definition(), &sp, {1, 191}, 0);
  FrameParser parser;
  for (auto _ : state) benchmark::DoNotOptimize(parser.feed(bytes));
}
BENCHMARK(BM_ParseSetpoint);

// Parse and check: each frame signed beforehand with a newer timestamp than the last.
void BM_ParseAndVerifySignedSetpoint(benchmark::State& state) {
  const SetPositionTargetLocalNed sp = setpoint();
  Signing sender(SigningMode::require, key(), 0, RisingClock{});
  std::vector<std::vector<std::uint8_t>> frames;
  for (int i = 0; i < 4096; ++i)
    frames.push_back(
        sender.encode(SetPositionTargetLocalNed::definition(), &sp, {1, 191}, static_cast<std::uint8_t>(i)));
  FrameParser parser;
  std::size_t i = 0;
  const auto new_receiver = [] {
    return std::make_unique<Signing>(SigningMode::require, key(), 0, [] { return SigningTimestamp{1'000'000'000}; });
  };
  auto receiver = new_receiver();
  for (auto _ : state) {
    if (i == frames.size()) {  // the frames again, to a receiver that has not seen them
      state.PauseTiming();
      receiver = new_receiver();
      i = 0;
      state.ResumeTiming();
    }
    for (const Frame& f : parser.feed(frames[i++]))
      if (!receiver->admit(f)) state.SkipWithError("a fresh signed frame was refused");
  }
}
BENCHMARK(BM_ParseAndVerifySignedSetpoint);

}  // namespace

BENCHMARK_MAIN();
