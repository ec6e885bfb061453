// kestrel on DDS over loopback, as two processes (docs/benchmarks.md, "DDS"): the latency from
// handing a message to dds_bridge's publication (encode, write) to its rebuilt kestrel message in
// another process's subscription (take, decode), p50 and p99, for a 640x480 grey stereo frame (two
// images, two camera infos and /tf: 0.62 MB) and a detections message, each at 30 Hz; then the
// throughput of frames written back to back. Both processes read one clock (CLOCK_MONOTONIC):
// each message's stamp is its publication time. Reliable, keep last 10, volatile (ROS 2's default).
//   kestrel_bench_dds [--count N] [--burst N]
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <kestrel/dds/participant.hpp>
#include <kestrel/dds/reader.hpp>
#include <kestrel/dds/writer.hpp>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/testing/dds_loopback.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <thread>
#include <vector>

#include "dds_publication.hpp"
#include "dds_subscription.hpp"

using namespace kestrel;
using namespace std::chrono_literals;

namespace {

enum Kind : std::int32_t { kFrame = 0, kDetections = 1, kBurst = 2 };
struct Result {
  std::int32_t kind;
  std::int64_t latency_ns;  // kBurst: arrival time
};

std::int64_t monotonic_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

template <class T>
Envelope envelope(std::shared_ptr<const T> message, std::string_view node, std::string_view port) {
  Envelope e;
  e.payload = std::move(message);
  e.type = MessageTraits<T>::name;
  e.source_node = node;
  e.source_port = port;
  return e;
}

std::shared_ptr<msg::StereoFrame> noisy_frame() {
  auto f = std::make_shared<msg::StereoFrame>();
  f->left = cv::Mat(480, 640, CV_8UC1);
  f->right = cv::Mat(480, 640, CV_8UC1);
  cv::randu(f->left, 0, 255);
  cv::randu(f->right, 0, 255);
  return f;
}

// The burst keeps every image until the reader has it (reliable, deep enough that nothing is
// replaced): its throughput is what the transport sustains, not what fits in 10.
const dds::Qos kBurstQos{dds::Reliability::reliable, 1000, dds::Durability::volatile_};

// The other process: rebuilds what arrives and reports, per message, now minus its stamp.
int subscriber(std::uint32_t domain, std::size_t expected, int out) {
  dds::Participant participant(domain);
  dds_bridge::DdsSubscription subscription(
      participant, dds::QosTable{},
      {{"frame", "kestrel.StereoFrame", "/bench/frame"}, {"detections", "kestrel.Detections", "/bench/detections"}});
  dds::Reader burst_reader(participant, "rt/burst/image", "sensor_msgs::msg::dds_::Image_", kBurstQos);
  Logger log("bench");
  std::vector<Result> results;
  auto last = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - last < 5s && results.size() < expected) {
    subscription.take(log, [&](std::size_t port, std::shared_ptr<const void> m, const dds::WriterMetadata&) {
      const std::int64_t now = monotonic_ns();
      last = std::chrono::steady_clock::now();
      if (port == 0) {
        const Time stamp = std::static_pointer_cast<const msg::StereoFrame>(m)->stamp;
        if (stamp != Time(0)) results.push_back({kFrame, now - stamp.count()});  // stamp 0: the warm-up
      }
      if (port == 1) {
        const Time stamp = std::static_pointer_cast<const msg::Detections>(m)->stamp;
        if (stamp != Time(0)) results.push_back({kDetections, now - stamp.count()});
      }
    });
    burst_reader.take([&](dds::ReceivedSample&&) {
      last = std::chrono::steady_clock::now();
      results.push_back({kBurst, monotonic_ns()});
    });
    std::this_thread::sleep_for(100us);
  }
  const auto bytes = static_cast<ssize_t>(results.size() * sizeof(Result));
  return ::write(out, results.data(), static_cast<std::size_t>(bytes)) == bytes ? 0 : 1;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(
      std::min<double>(static_cast<double>(v.size() - 1), p * static_cast<double>(v.size())))];
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t count = 300, burst = 200;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--count") == 0) count = std::stoul(argv[i + 1]);
    if (std::strcmp(argv[i], "--burst") == 0) burst = std::stoul(argv[i + 1]);
  }
  const std::uint32_t domain = testing::use_dds_loopback();
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return 1;
  // Fork before any participant exists: Cyclone's threads do not survive a fork.
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    try {
      ::_exit(subscriber(domain, 2 * count + burst, pipe_fds[1]));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "kestrel_bench_dds: the subscriber: %s\n", e.what());
      ::_exit(1);
    }
  }
  ::close(pipe_fds[1]);

  std::size_t frame_bytes = 0, sent_burst = 0;
  std::vector<std::uint8_t> image;
  std::int64_t burst_start_ns = 0;
  double burst_s = 0.0;
  {
    dds::Participant participant(domain);
    dds_bridge::DdsPublication publication(participant, dds::QosTable{}, "", true);
    auto frame = noisy_frame();
    auto detections = std::make_shared<msg::Detections>();
    detections->items.push_back({{0.1, -0.2, 5.0}, {0.4, 0.3, 0.2}, 57, 0.9});
    // The writers are made by their first message; the readers match them within a second.
    // The warm-up messages (stamp 0) are not measured.
    publication.publish(envelope<msg::StereoFrame>(frame, "bench", "frame"));
    publication.publish(envelope<msg::Detections>(detections, "bench", "detections"));
    std::this_thread::sleep_for(1500ms);
    for (std::size_t i = 0; i < count; ++i) {
      auto f = std::make_shared<msg::StereoFrame>(*frame);
      f->stamp = Time(monotonic_ns());
      publication.publish(envelope<msg::StereoFrame>(f, "bench", "frame"));
      auto d = std::make_shared<msg::Detections>(*detections);
      d->stamp = Time(monotonic_ns());
      publication.publish(envelope<msg::Detections>(d, "bench", "detections"));
      std::this_thread::sleep_for(33ms);
    }
    frame_bytes = 0;
    for (const auto& m : ros2::encode("kestrel.StereoFrame", frame.get(), "/bench/frame").messages)
      frame_bytes += m.cdr.size();
    // The burst: the left image's ROS 2 message, written back to back as fast as Cyclone takes it.
    image = ros2::encode("kestrel.StereoFrame", frame.get(), "/burst/frame").messages.at(0).cdr;
    dds::Writer writer(participant, "rt/burst/image", "sensor_msgs::msg::dds_::Image_", kBurstQos);
    writer.wait_for_readers(1, 10s);
    const auto start = std::chrono::steady_clock::now();
    burst_start_ns = monotonic_ns();
    for (sent_burst = 0; sent_burst < burst; ++sent_burst) writer.write(image);
    burst_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::this_thread::sleep_for(3s);  // reliable: repairs go on after the last write
  }
  std::vector<Result> results;
  Result r;
  while (::read(pipe_fds[0], &r, sizeof r) == static_cast<ssize_t>(sizeof r)) results.push_back(r);
  int status = 0;
  ::waitpid(child, &status, 0);

  std::vector<double> frame_ms, detections_us;
  std::vector<std::int64_t> burst_arrivals;
  for (const Result& x : results) {
    if (x.kind == kFrame) frame_ms.push_back(static_cast<double>(x.latency_ns) / 1e6);
    if (x.kind == kDetections) detections_us.push_back(static_cast<double>(x.latency_ns) / 1e3);
    if (x.kind == kBurst) burst_arrivals.push_back(x.latency_ns);
  }
  std::printf("DDS over loopback, two processes (Cyclone DDS, reliable, keep last 10, volatile)\n");
  std::printf("stereo frame 640x480 (%.2f MB in 5 samples): %zu of %zu at 30 Hz, latency p50 %.2f ms, p99 %.2f ms\n",
              static_cast<double>(frame_bytes) / 1e6, frame_ms.size(), count, percentile(frame_ms, 0.5),
              percentile(frame_ms, 0.99));
  std::printf("detections (1 item): %zu of %zu at 30 Hz, latency p50 %.0f us, p99 %.0f us\n", detections_us.size(),
              count, percentile(detections_us, 0.5), percentile(detections_us, 0.99));
  const std::size_t received = burst_arrivals.size();
  // From the first write to the last arrival: the reader takes in batches, so arrivals bunch.
  const double span_s = received > 0 ? static_cast<double>(burst_arrivals.back() - burst_start_ns) / 1e9 : 0.0;
  const double per_s = span_s > 0 ? static_cast<double>(received) / span_s : 0.0;
  std::printf(
      "burst of %zu images (%.2f MB each) written back to back in %.2f s (reliable, keep last 1000): %zu "
      "received, %.0f images/s, %.0f MB/s at the reader\n",
      sent_burst, static_cast<double>(image.size()) / 1e6, burst_s, received, per_s,
      per_s * static_cast<double>(image.size()) / 1e6);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1;
}
