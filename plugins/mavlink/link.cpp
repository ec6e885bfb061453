#include "link.hpp"

#include <kestrel/error.hpp>
#include <map>

namespace kestrel::mavlink {

namespace {

// Kept bounded: a node that never asks must not let the link grow without end.
constexpr std::size_t kKeptAcks = 64, kKeptTexts = 64;

bool same_signing(const std::shared_ptr<Signing>& a, const std::shared_ptr<Signing>& b) {
  if (!a || !b) return !a && !b;
  return a->mode() == b->mode() && a->link_id() == b->link_id() && a->key() == b->key();
}

bool same_options(const LinkOptions& a, const LinkOptions& b) {
  return a.autopilot_system_id == b.autopilot_system_id && a.pin_peer == b.pin_peer &&
         a.heartbeat_timeout_s == b.heartbeat_timeout_s && same_signing(a.signing, b.signing);
}

}  // namespace

std::shared_ptr<Link> Link::open(const std::string& url, const LinkOptions& options) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<Link>> links;
  std::lock_guard lock(mutex);
  if (auto existing = links[url].lock()) {
    if (!same_options(existing->options_, options))
      throw Error(url +
                  ": this link is open already with other options (autopilot_system_id, pin_peer, "
                  "heartbeat_timeout_s, signing, signing_key_file, signing_link_id): every node of one link must "
                  "give the same");
    return existing;
  }
  auto link = std::make_shared<Link>(open_transport(parse_connection_url(url)), options);
  links[url] = link;
  return link;
}

Link::Link(std::unique_ptr<Transport> transport, const LinkOptions& options)
    : transport_(std::move(transport)),
      options_(options),
      writer_({options.autopilot_system_id, mav::comp_onboard_computer}, options.signing) {
  view_.signing = options_.signing ? options_.signing->mode() : SigningMode::off;
  transport_->set_pinning(options_.pin_peer);
  // A signing link judges what an address it does not answer sends too, for its counters: the
  // report then says what an intruder on the network tried (unsigned, badly signed, replayed).
  transport_->set_foreign_delivery(options_.signing != nullptr);
  reader_ = std::thread([this] { read_loop(); });
}

Link::~Link() {
  stop_ = true;
  if (reader_.joinable()) reader_.join();
}

void Link::read_loop() {
  FrameParser parser, foreign_parser;  // apart: a foreign sender's bytes never join the peer's stream
  std::vector<std::uint8_t> buffer(4096);
  while (!stop_) {
    std::size_t n = 0;
    try {
      n = transport_->receive(buffer, std::chrono::milliseconds(50));
    } catch (const std::exception& e) {
      std::lock_guard lock(mutex_);
      failure_ = e.what();
      failed_ = true;
      return;
    }
    if (n > 0 && options_.signing && transport_->last_was_foreign()) {
      for (const Frame& f : foreign_parser.feed(std::span(buffer.data(), n))) options_.signing->admit(f);
      std::lock_guard lock(mutex_);
      view_.signatures = options_.signing->counts();
      autopilot_heard_ = false;
      keep_the_peer(LinkClock::now());  // a flood from elsewhere must not stop a silent peer being let go
      continue;
    }
    const auto frames = parser.feed(std::span(buffer.data(), n));
    std::lock_guard lock(mutex_);
    autopilot_heard_ = false;
    for (const Frame& f : frames)
      if (!options_.signing || options_.signing->admit(f)) take(f);  // dropped frames pin nobody
    view_.parser = parser.counts();
    if (options_.signing) view_.signatures = options_.signing->counts();
    keep_the_peer(LinkClock::now());
  }
}

// The peer is pinned by the autopilot's heartbeat, and let go when it has been silent longer
// than the timeout: a rebooted autopilot on a new port is found again, an impostor never
// displaces it while it speaks.
void Link::keep_the_peer(LinkClock::time_point now) {
  if (!options_.pin_peer) return;
  if (view_.peer_pinned && view_.heartbeat_at &&
      std::chrono::duration<double>(now - *view_.heartbeat_at).count() > options_.heartbeat_timeout_s) {
    transport_->unpin();
    view_.peer_pinned = false;
  }
  if (autopilot_heard_ && !view_.peer_pinned) {
    transport_->pin_sender();
    view_.peer_pinned = true;
    ++view_.pins;
  }
  view_.foreign_datagrams = transport_->foreign_datagrams();
}

void Link::take(const Frame& f) {
  const auto now = LinkClock::now();
  if (f.system_id != options_.autopilot_system_id) {
    ++view_.other_system_frames;  // another vehicle, or a ground station: not ours to follow
    return;
  }
  if (f.is<Heartbeat>()) {
    const auto hb = f.as<Heartbeat>();
    if (hb.autopilot == mav::autopilot_invalid) return;  // a ground station or another companion
    autopilot_heard_ = true;
    view_.heartbeat = hb;
    view_.heartbeat_at = now;
    ++view_.heartbeat_count;
    view_.system_id = f.system_id;
    view_.component_id = f.component_id;
  } else if (f.is<LocalPositionNed>()) {
    view_.position = f.as<LocalPositionNed>();
    view_.position_at = now;
    ++view_.position_count;
  } else if (f.is<AttitudeQuaternion>()) {
    view_.attitude = f.as<AttitudeQuaternion>();
    view_.attitude_at = now;
    ++view_.attitude_count;
  } else if (f.is<Odometry>()) {
    view_.odometry = f.as<Odometry>();
    view_.odometry_at = now;
    ++view_.odometry_count;
  } else if (f.is<ExtendedSysState>()) {
    view_.extended = f.as<ExtendedSysState>();
  } else if (f.is<CommandAck>()) {
    acks_.push_back(f.as<CommandAck>());
    if (acks_.size() > kKeptAcks) acks_.pop_front();
  } else if (f.is<StatusText>()) {
    texts_.push_back(f.as<StatusText>());
    if (texts_.size() > kKeptTexts) texts_.pop_front();
  }
}

VehicleView Link::view() const {
  std::lock_guard lock(mutex_);
  return view_;
}

std::vector<CommandAck> Link::take_acks() {
  std::lock_guard lock(mutex_);
  std::vector<CommandAck> out(acks_.begin(), acks_.end());
  acks_.clear();
  return out;
}

std::vector<StatusText> Link::take_texts() {
  std::lock_guard lock(mutex_);
  std::vector<StatusText> out(texts_.begin(), texts_.end());
  texts_.clear();
  return out;
}

bool Link::send_frame(const std::vector<std::uint8_t>& frame) {
  if (failed_) return false;
  try {
    return transport_->send(frame);
  } catch (const std::exception& e) {
    std::lock_guard lock(mutex_);
    failure_ = e.what();
    failed_ = true;
    return false;
  }
}

std::string Link::describe() const { return transport_->describe(); }

std::optional<std::string> Link::failure() const {
  std::lock_guard lock(mutex_);
  return failure_;
}

}  // namespace kestrel::mavlink
