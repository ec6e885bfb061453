// The recorder's cost per stereo frame at 640x480 on rendered frames: mapping a StereoFrame onto
// its ROS 2 messages, then writing them into an MCAP file (in /tmp: the disk is hardly
// measured, only the page cache) with no compression, zstd or lz4. Counters: input MB/s and the
// size written per frame.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <kestrel/messages/stereo_frame.hpp>

#include "kestrel/mcap/writer.hpp"
#include "kestrel/ros2/definitions.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"
#include "sensor_noise.hpp"
#include "stereo_renderer.hpp"
#include "trajectory.hpp"
#include "world_scene.hpp"

namespace {

using namespace kestrel;

// Ten rendered frames of the paper's scene (92.8 degrees, the intruder at 5 m), grey, with the
// camera's sensor noise (sim_stereo's default sigma of 1.5 grey levels): noise is what the
// compressors cannot take out.
const std::vector<msg::StereoFrame>& frames() {
  static const std::vector<msg::StereoFrame> f = [] {
    std::vector<msg::StereoFrame> out;
    msg::StereoCalibration calibration;
    calibration.fx = calibration.fy = sim::focal_from_hfov(640, 92.8);
    calibration.cx = 319.5;
    calibration.cy = 239.5;
    sim::SceneOptions options;
    options.clutter_count = 0;
    sim::WorldScene world(options);
    sim::StereoRenderer renderer(calibration);
    sim::SensorNoise noise(1.5, false);
    const auto camera = geometry::level_camera({0, 0, 2}, 0.0);
    const intruder::FigureEight path(camera, 5.0, 1.0, 0.5, 12.0);
    for (int i = 0; i < 10; ++i) {
      world.set_intruder(1, path.at(i * 0.4).position, 0.0);
      cv::Mat l, r;
      msg::StereoFrame frame;
      renderer.render(world.scene(), camera, l, r);
      frame.left = noise.apply(l, 2 * static_cast<std::uint64_t>(i));
      frame.right = noise.apply(r, 2 * static_cast<std::uint64_t>(i) + 1);
      frame.calibration = calibration;
      frame.frame_index = static_cast<std::uint64_t>(i);
      frame.stamp = Time(i * 33'333'333);
      out.push_back(frame);
    }
    return out;
  }();
  return f;
}

void BM_MapStereoFrame(benchmark::State& state) {
  const auto& f = frames();
  std::size_t i = 0, bytes = 0;
  for (auto _ : state) {
    auto encoded = ros2::encode("kestrel.StereoFrame", &f[i++ % f.size()], "/camera/frame");
    bytes += encoded.messages[0].cdr.size() + encoded.messages[1].cdr.size();
    benchmark::DoNotOptimize(encoded);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_MapStereoFrame)->Unit(benchmark::kMillisecond);

// state.range(0): 0 none, 1 zstd, 2 lz4.
void BM_RecordStereoFrame(benchmark::State& state) {
  const char* compression[] = {"", "zstd", "lz4"};
  const auto& f = frames();
  const std::string path = "/tmp/kestrel_bench_recording.mcap";
  mcap::Writer writer(path, mcap::WriterOptions{"ros2", "bench", compression[state.range(0)], 0, 1 << 20});
  const auto specs = ros2::channels_for("kestrel.StereoFrame", "/camera/frame");
  std::vector<std::uint16_t> channels;
  for (const auto& spec : specs) {
    const std::string& text = ros2::schema_text(spec.schema);
    const auto schema =
        writer.add_schema(spec.schema, "ros2msg", {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
    channels.push_back(writer.add_channel(schema, spec.topic, "cdr"));
  }
  std::size_t i = 0, bytes = 0;
  for (auto _ : state) {
    const auto& frame = f[i % f.size()];
    const auto encoded = ros2::encode("kestrel.StereoFrame", &frame, "/camera/frame");
    const auto t = static_cast<mcap::Timestamp>(i++) * 33'333'333u;
    for (const auto& m : encoded.messages) {
      writer.write_message(channels[m.channel], t, t, m.cdr, m.sequence);
      bytes += m.cdr.size();
    }
  }
  writer.finish();
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
  state.counters["written_kB_per_frame"] =
      static_cast<double>(std::filesystem::file_size(path)) / 1024.0 / static_cast<double>(std::max<std::size_t>(i, 1));
  std::filesystem::remove(path);
}
BENCHMARK(BM_RecordStereoFrame)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
