// The live view's cost: one 30 Hz frame of the detection chain's messages (a 640x480 stereo frame
// with its camera infos, the depth cloud, detections, the hunter's odometry and /tf, and a Time
// frame) published to the Foxglove WebSocket server while three loopback clients subscribed to
// every channel read it all. The benchmark's CPU time is the graph thread's share (encoding each
// message and handing it to the server); the counters give the server's I/O thread, which frames and sends to
// every client, in ms per frame and as a share of one core at 30 frames a second.
#include <benchmark/benchmark.h>

// clang-format off
#include <utility>  // before Asio, whose awaitable.hpp uses std::exchange without including it
// clang-format on

#include <algorithm>
#include <atomic>
#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <functional>
#include <kestrel/messages/detections.hpp>
#include <kestrel/messages/point_cloud.hpp>
#include <kestrel/messages/stereo_frame.hpp>
#include <kestrel/messages/vehicle_state.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <random>
#include <thread>

#include "kestrel/ros2/definitions.hpp"
#include "kestrel/ros2_messages/message_mapping.hpp"
#include "live_server.hpp"

namespace {

using namespace kestrel;
namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

// A viewer that subscribes to every channel advertised and reads as fast as it can.
class GreedyClient {
 public:
  explicit GreedyClient(std::uint16_t port) {
    tcp::resolver resolver(io_);
    asio::connect(ws_.next_layer(), resolver.resolve("127.0.0.1", std::to_string(port)));
    ws_.set_option(websocket::stream_base::decorator([](websocket::request_type& r) {
      r.set(beast::http::field::sec_websocket_protocol, std::string(foxglove::kSubprotocol));
    }));
    ws_.handshake("127.0.0.1", "/");
    thread_ = std::thread([this] { run(); });
  }
  ~GreedyClient() {
    beast::error_code ignored;
    ws_.next_layer().shutdown(tcp::socket::shutdown_both, ignored);
    thread_.join();
  }
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t messages() const { return messages_; }
  std::size_t subscribed() const { return subscribed_; }

 private:
  void run() {
    beast::flat_buffer buffer;
    beast::error_code ec;
    std::uint32_t next_subscription = 0;
    for (;;) {
      ws_.read(buffer, ec);
      if (ec) return;  // closed by the server, or shut down by the destructor
      if (ws_.got_text()) {
        const auto j = nlohmann::json::parse(beast::buffers_to_string(buffer.data()));
        if (j["op"] == "advertise") {
          nlohmann::json subscribe = {{"op", "subscribe"}, {"subscriptions", nlohmann::json::array()}};
          for (const auto& c : j["channels"])
            subscribe["subscriptions"].push_back({{"id", next_subscription++}, {"channelId", c["id"]}});
          ws_.text(true);
          ws_.write(asio::buffer(subscribe.dump()), ec);
          subscribed_ += j["channels"].size();
        }
      } else {
        bytes_ += buffer.size();
        ++messages_;
      }
      buffer.clear();
    }
  }

  asio::io_context io_;
  websocket::stream<tcp::socket> ws_{io_};
  std::thread thread_;
  std::atomic<std::uint64_t> bytes_{0}, messages_{0};
  std::atomic<std::size_t> subscribed_{0};
};

// One output's channels on the server, and its message encoded as the bridge encodes it.
struct Served {
  std::vector<std::uint32_t> channel_ids;
  std::function<ros2::Encoded()> encode;
};

template <class T>
Served serve(foxglove::LiveServer& server, T message, const std::string& topic) {
  const std::string type(MessageTraits<T>::name);
  Served s;
  for (const auto& spec : ros2::channels_for(type, topic))
    s.channel_ids.push_back(server.add_channel(
        foxglove::Channel{0, spec.topic, "cdr", spec.schema, ros2::schema_text(spec.schema), "ros2msg"}));
  s.encode = [type, topic, m = std::move(message)] { return ros2::encode(type, &m, topic); };
  return s;
}

msg::StereoFrame noisy_frame() {
  msg::StereoFrame f;
  f.left = cv::Mat(480, 640, CV_8UC1);
  f.right = cv::Mat(480, 640, CV_8UC1);
  cv::randu(f.left, 0, 255);
  cv::randu(f.right, 0, 255);
  return f;
}

// A depth cloud of the size the paper's scene gives at full resolution.
msg::PointCloud depth_cloud(std::size_t points) {
  msg::PointCloud c;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  for (std::size_t i = 0; i < points; ++i) {
    const float x = u(rng), y = u(rng), z = u(rng);
    cloud->push_back({x, y, 10.0f + z});
  }
  c.points = cloud;
  return c;
}

void BM_LiveViewThreeClients(benchmark::State& state) {
  foxglove::LiveServerOptions options;
  options.address = "127.0.0.1";
  options.port = 0;
  foxglove::LiveServer server(options);
  std::vector<Served> frame;
  frame.push_back(serve(server, noisy_frame(), "/camera/frame"));
  frame.push_back(serve(server, depth_cloud(static_cast<std::size_t>(state.range(0))), "/depth/cloud"));
  msg::Detections detections;
  detections.items.push_back({{0.1, -0.2, 5.0}, {0.4, 0.3, 0.2}, 57, 0.9});
  frame.push_back(serve(server, detections, "/refine/detections"));
  frame.push_back(serve(server, msg::VehicleState{}, "/hunter/odometry"));
  std::size_t channels = 0;
  for (const auto& s : frame) channels += s.channel_ids.size();

  std::vector<std::unique_ptr<GreedyClient>> clients;
  for (int i = 0; i < 3; ++i) clients.push_back(std::make_unique<GreedyClient>(server.port()));
  for (int i = 0; i < 500; ++i) {  // each client has subscribed to everything it was advertised
    bool ready = true;
    for (const auto& c : clients) ready = ready && c->subscribed() >= channels;
    if (ready) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the subscriptions reach the server

  const double cpu_before = server.stats().io_cpu_s;
  const auto period = std::chrono::nanoseconds(33'333'333);
  auto next = std::chrono::steady_clock::now();
  std::uint64_t frames = 0, bytes = 0;
  for (auto _ : state) {
    const std::uint64_t t = frames * 33'333'333;
    for (const auto& s : frame)
      for (auto& m : s.encode().messages) {
        bytes += m.cdr.size();
        server.publish(s.channel_ids[m.channel], t,
                       std::make_shared<const std::vector<std::uint8_t>>(std::move(m.cdr)));
      }
    server.publish_time(t);
    ++frames;
    next += period;
    std::this_thread::sleep_until(next);  // the camera's pace: the sleep costs no CPU
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the last frames go out
  const auto stats = server.stats();
  const double io_ms = (stats.io_cpu_s - cpu_before) * 1e3 / static_cast<double>(frames);
  std::uint64_t received = 0;
  for (const auto& c : clients) received += c->bytes();
  state.counters["io_thread_ms_per_frame"] = io_ms;
  state.counters["io_thread_core_share_at_30hz"] = io_ms * 30.0 / 1000.0;
  state.counters["mb_per_frame_per_client"] = static_cast<double>(bytes) / static_cast<double>(frames) / 1e6;
  state.counters["received_share"] = static_cast<double>(received) / (3.0 * static_cast<double>(bytes));
  state.counters["dropped"] = static_cast<double>(stats.dropped);
  server.stop();
}
// The argument is the cloud's size in points. 90 frames: three seconds at 30 Hz.
BENCHMARK(BM_LiveViewThreeClients)->Arg(20000)->Iterations(90)->Unit(benchmark::kMillisecond);

// The latency of one message through the live view to one loopback client, for comparison with
// DDS (bench/dds_transport.cpp): from encoding to the client holding all of its ROS 2 messages,
// one at a time at 30 Hz. Argument 0: a 640x480 grey stereo frame (5 messages); 1: detections
// with their markers (2 messages). Client and server share this process, as DDS's two do not.
void BM_LiveViewLatency(benchmark::State& state) {
  foxglove::LiveServerOptions options;
  options.address = "127.0.0.1";
  options.port = 0;
  foxglove::LiveServer server(options);
  msg::Detections detections;
  detections.items.push_back({{0.1, -0.2, 5.0}, {0.4, 0.3, 0.2}, 57, 0.9});
  const Served served = state.range(0) == 0 ? serve(server, noisy_frame(), "/camera/frame")
                                            : serve(server, detections, "/refine/detections");
  GreedyClient client(server.port());
  for (int i = 0; i < 500 && client.subscribed() < served.channel_ids.size(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the subscriptions reach the server

  std::vector<double> latency_us;
  std::uint64_t t = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t before = client.messages();
    const auto encoded = served.encode();
    for (const auto& m : encoded.messages)
      server.publish(served.channel_ids[m.channel], t, std::make_shared<const std::vector<std::uint8_t>>(m.cdr));
    while (client.messages() < before + encoded.messages.size()) std::this_thread::yield();
    latency_us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    t += 33'333'333;
    std::this_thread::sleep_for(std::chrono::milliseconds(33));
  }
  std::sort(latency_us.begin(), latency_us.end());
  state.counters["p50_us"] = latency_us[latency_us.size() / 2];
  state.counters["p99_us"] = latency_us[std::min(latency_us.size() - 1, latency_us.size() * 99 / 100)];
  server.stop();
}
BENCHMARK(BM_LiveViewLatency)->Arg(0)->Arg(1)->Iterations(300)->UseRealTime()->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
