// An eProsima Fast DDS 2.9 peer for the DDS interop tests: it reads what kestrel publishes through
// Cyclone DDS, the way a ROS 2 node on rmw_fastrtps would meet it on the wire.
//   fastdds_peer DOMAIN TIMEOUT_S TOPIC...
// Prints one JSON line per writer discovered in the domain and per sample received on the TOPICs
// asked for (DDS names, e.g. rt/tracker/tracks); exits 0 with {"ok": true} once every TOPIC gave a
// sample, 1 after TIMEOUT_S seconds without that, 2 on bad arguments.
#include <fastdds/rtps/common/Locator.h>
#include <fastdds/rtps/common/SerializedPayload.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/writer/WriterDiscoveryInfo.h>
#include <fastrtps/utils/IPLocator.h>

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fastdds/dds/core/policy/QosPolicies.hpp>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

// Fast DDS headers declare a global ::dds namespace, hence the prefixed aliases.
namespace fdds = eprosima::fastdds::dds;
namespace frtps = eprosima::fastrtps::rtps;
using eprosima::fastrtps::types::ReturnCode_t;

namespace {

// Participant indexes Cyclone may take with MaxAutoParticipantIndex 20, and so the ports its SPDP
// listens on: Fast DDS learns of Cyclone only if it sends there itself.
constexpr std::uint32_t kMaxPeerIndex = 20;

// The type's maximum serialized size. Not a limit on what the readers here receive: the type says
// it is unbounded and their payloads are allocated at each sample's size.
constexpr std::uint32_t kTypeSize = 4u << 20;

std::mutex out_mutex;  // JSON lines come from the discovery and reception threads
bool out_closed = false;

void print_locked(const std::string& line) {
  std::fputs(line.c_str(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);  // read line by line by the test scripts
}

void print_line(const std::string& line) {
  std::lock_guard lock(out_mutex);
  if (!out_closed) {
    print_locked(line);
  }
}

// Nothing is printed after this: the verdict stays the last line even if samples keep arriving
// while the participant is deleted.
void close_output(const std::string& last_line) {
  std::lock_guard lock(out_mutex);
  if (!last_line.empty()) {
    print_locked(last_line);
  }
  out_closed = true;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// A sample is the serialized payload as it came, encapsulation header included: the peer checks
// the wire, it does not need the message's fields.
using RawSample = std::vector<std::uint8_t>;

class RawType : public fdds::TopicDataType {
 public:
  explicit RawType(const std::string& name) {
    setName(name.c_str());
    m_typeSize = kTypeSize;
    m_isGetKeyDefined = false;  // ROS 2 topics are keyless
    // Cyclone's writers carry no XTypes type information; without ours either, matching falls
    // back to comparing type names.
    auto_fill_type_object(false);
    auto_fill_type_information(false);
  }

  bool serialize(void* data, frtps::SerializedPayload_t* payload) override {
    const auto& sample = *static_cast<RawSample*>(data);
    if (sample.size() > payload->max_size) {
      return false;
    }
    std::memcpy(payload->data, sample.data(), sample.size());
    payload->length = static_cast<std::uint32_t>(sample.size());
    return true;
  }

  bool deserialize(frtps::SerializedPayload_t* payload, void* data) override {
    auto& sample = *static_cast<RawSample*>(data);
    sample.assign(payload->data, payload->data + payload->length);
    return true;
  }

  std::function<std::uint32_t()> getSerializedSizeProvider(void* data) override {
    return [data] { return static_cast<std::uint32_t>(static_cast<RawSample*>(data)->size()); };
  }

  void* createData() override { return new RawSample(); }
  void deleteData(void* data) override { delete static_cast<RawSample*>(data); }

  bool getKey(void*, frtps::InstanceHandle_t*, bool) override { return false; }

  // Unbounded: a bounded type would get fixed payloads of m_typeSize, and larger samples dropped.
  bool is_bounded() const override { return false; }
  bool is_plain() const override { return false; }
};

struct State {
  std::mutex mutex;
  std::condition_variable changed;
  std::set<std::string> wanted;
  std::map<std::string, std::string> discovered;  // wanted topic -> type name of its first writer
  std::set<std::string> received;

  bool done() const { return received.size() == wanted.size(); }
};

class ParticipantListener : public fdds::DomainParticipantListener {
 public:
  explicit ParticipantListener(State& state) : state_(state) {}

  void on_publisher_discovery(fdds::DomainParticipant*, frtps::WriterDiscoveryInfo&& info) override {
    if (info.status != frtps::WriterDiscoveryInfo::DISCOVERED_WRITER) {
      return;
    }
    const std::string topic = info.info.topicName().to_string();
    const std::string type = info.info.typeName().to_string();
    print_line("{\"discovered\": " + json_string(topic) + ", \"type\": " + json_string(type) + "}");
    // Readers are made on the main thread: creating entities from inside discovery callbacks
    // risks Fast DDS's own locks.
    std::lock_guard lock(state_.mutex);
    if (state_.wanted.count(topic) != 0 && state_.discovered.count(topic) == 0) {
      state_.discovered.emplace(topic, type);
      state_.changed.notify_all();
    }
  }

 private:
  State& state_;
};

class ReaderListener : public fdds::DataReaderListener {
 public:
  ReaderListener(State& state, std::string topic, std::string type)
      : state_(state), topic_(std::move(topic)), type_(std::move(type)) {}

  void on_data_available(fdds::DataReader* reader) override {
    RawSample sample;
    fdds::SampleInfo info;
    while (reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data) {
        continue;
      }
      char encapsulation[9] = "";
      for (std::size_t i = 0; i < 4 && i < sample.size(); ++i) {
        std::snprintf(encapsulation + 2 * i, 3, "%02x", sample[i]);
      }
      print_line("{\"topic\": " + json_string(topic_) + ", \"type\": " + json_string(type_) +
                 ", \"bytes\": " + std::to_string(sample.size()) + ", \"encapsulation\": \"" + encapsulation + "\"}");
      std::lock_guard lock(state_.mutex);
      state_.received.insert(topic_);
      state_.changed.notify_all();
    }
  }

 private:
  State& state_;
  std::string topic_;
  std::string type_;
};

fdds::DomainParticipantQos loopback_participant_qos(std::uint32_t domain) {
  fdds::DomainParticipantQos qos;
  qos.name("kestrel_fastdds_peer");

  // Only UDP on loopback, no shared memory: the traffic must be what Cyclone sees.
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.emplace_back("127.0.0.1");
  qos.transport().use_builtin_transports = false;
  qos.transport().user_transports.push_back(udp);

  // Explicit unicast locators with port 0 (Fast DDS fills in the well-known ports of its
  // participant id) and no multicast ones: with both lists empty it would add 239.255.0.1.
  frtps::Locator_t local;
  local.kind = LOCATOR_KIND_UDPv4;
  frtps::IPLocator::setIPv4(local, 127, 0, 0, 1);
  local.port = 0;
  qos.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(local);
  qos.wire_protocol().default_unicast_locator_list.push_back(local);

  // SPDP to the metatraffic port of every participant index Cyclone may take; a peer of port 0
  // would only reach the transport's maxInitialPeersRange (4) indexes.
  for (std::uint32_t index = 0; index <= kMaxPeerIndex; ++index) {
    frtps::Locator_t peer = local;
    peer.port = qos.wire_protocol().port.getUnicastPort(domain, index);
    qos.wire_protocol().builtin.initialPeersList.push_back(peer);
  }
  return qos;
}

bool parse_uint(const char* text, unsigned long max, unsigned long& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtoul(text, &end, 10);
  return errno == 0 && end != text && *end == '\0' && text[0] != '-' && value <= max;
}

int usage() {
  std::fputs(
      "usage: fastdds_peer DOMAIN TIMEOUT_S TOPIC...\n"
      "  DOMAIN     DDS domain id (0..232)\n"
      "  TIMEOUT_S  seconds to wait for a sample of every TOPIC\n"
      "  TOPIC      DDS topic name, e.g. rt/tracker/tracks\n",
      stderr);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  unsigned long domain = 0;
  unsigned long timeout_s = 0;
  // Domains above 232 put the RTPS well-known ports past 65535.
  if (argc < 4 || !parse_uint(argv[1], 232, domain) || !parse_uint(argv[2], 86400, timeout_s)) {
    return usage();
  }

  State state;
  for (int i = 3; i < argc; ++i) {
    if (argv[i][0] == '\0') {
      return usage();
    }
    state.wanted.insert(argv[i]);
  }

  const auto qos = loopback_participant_qos(static_cast<std::uint32_t>(domain));
  ParticipantListener participant_listener(state);
  auto* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipant* participant = factory->create_participant(static_cast<fdds::DomainId_t>(domain), qos,
                                                                     &participant_listener, fdds::StatusMask::none());
  if (participant == nullptr) {
    std::fputs("fastdds_peer: cannot create the DomainParticipant\n", stderr);
    return 1;
  }
  fdds::Subscriber* subscriber = participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (subscriber == nullptr) {
    std::fputs("fastdds_peer: cannot create the Subscriber\n", stderr);
    factory->delete_participant(participant);
    return 1;
  }

  std::map<std::string, fdds::TypeSupport> types;  // registered type names
  std::vector<std::unique_ptr<ReaderListener>> reader_listeners;
  std::set<std::string> subscribed;
  bool failed = false;

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  std::unique_lock lock(state.mutex);
  while (!state.done() && !failed) {
    // Topics discovered since the last pass, subscribed to without holding the lock so that
    // the listeners are never blocked on it while Fast DDS holds its own.
    std::vector<std::pair<std::string, std::string>> fresh;
    for (const auto& [topic, type] : state.discovered) {
      if (subscribed.insert(topic).second) {
        fresh.emplace_back(topic, type);
      }
    }
    if (!fresh.empty()) {
      lock.unlock();
      for (const auto& [topic_name, type_name] : fresh) {
        if (types.count(type_name) == 0) {
          fdds::TypeSupport type(new RawType(type_name));
          if (participant->register_type(type) != ReturnCode_t::RETCODE_OK) {
            std::fprintf(stderr, "fastdds_peer: cannot register type %s\n", type_name.c_str());
            failed = true;
            break;
          }
          types.emplace(type_name, type);
        }
        fdds::Topic* topic = participant->create_topic(topic_name, type_name, fdds::TOPIC_QOS_DEFAULT);
        if (topic == nullptr) {
          std::fprintf(stderr, "fastdds_peer: cannot create topic %s\n", topic_name.c_str());
          failed = true;
          break;
        }
        fdds::DataReaderQos reader_qos = fdds::DATAREADER_QOS_DEFAULT;
        reader_qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
        reader_qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
        reader_qos.history().depth = 10;
        reader_qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
        reader_qos.type_consistency().representation.m_value = {fdds::XCDR_DATA_REPRESENTATION};
        reader_qos.data_sharing().off();
        // Payloads allocated at each sample's size and reused, rather than preallocated at
        // m_typeSize for every sample of the history.
        reader_qos.endpoint().history_memory_policy = frtps::DYNAMIC_REUSABLE_MEMORY_MODE;
        reader_listeners.push_back(std::make_unique<ReaderListener>(state, topic_name, type_name));
        if (subscriber->create_datareader(topic, reader_qos, reader_listeners.back().get()) == nullptr) {
          std::fprintf(stderr, "fastdds_peer: cannot create a reader of %s\n", topic_name.c_str());
          failed = true;
          break;
        }
      }
      lock.lock();
      continue;  // more may have come meanwhile
    }
    if (state.changed.wait_until(lock, deadline) == std::cv_status::timeout) {
      break;
    }
  }

  const bool ok = state.done() && !failed;
  close_output(ok ? "{\"ok\": true}" : "");
  if (!ok && !failed) {
    for (const auto& topic : state.wanted) {
      if (state.discovered.count(topic) == 0) {
        std::fprintf(stderr, "fastdds_peer: %s: no writer discovered\n", topic.c_str());
      } else if (state.received.count(topic) == 0) {
        std::fprintf(stderr, "fastdds_peer: %s: writer discovered (type %s), no sample received\n", topic.c_str(),
                     state.discovered[topic].c_str());
      }
    }
  }
  lock.unlock();

  participant->delete_contained_entities();
  factory->delete_participant(participant);
  return ok ? 0 : 1;
}
