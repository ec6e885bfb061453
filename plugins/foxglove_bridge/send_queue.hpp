#pragma once
// What waits to be sent to one client. Bounded in bytes: when a slow client lets it fill, the
// oldest droppable frames (message data, time) make room, so the graph never waits for a client.
// Control messages (serverInfo, advertise, status) are never dropped: without them a client could
// not decode what follows. Not thread-safe: the server's I/O thread alone uses it.
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace kestrel::foxglove {

struct Frame {
  bool text = false;                                      ///< a JSON text message, else binary
  bool droppable = false;                                 ///< message data and time; control messages are kept
  std::vector<std::uint8_t> head;                         ///< sent first (a Message Data header, or the whole frame)
  std::shared_ptr<const std::vector<std::uint8_t>> body;  ///< shared by every client it goes to; may be null
  std::size_t size() const { return head.size() + (body ? body->size() : 0); }
};

class SendQueue {
 public:
  explicit SendQueue(std::size_t max_bytes) : max_bytes_(max_bytes) {}

  /// Queues `frame`, first dropping the oldest droppable frames while it would not fit. A
  /// droppable frame larger than the whole queue is dropped itself.
  void push(Frame frame) {
    const std::size_t size = frame.size();
    if (frame.droppable && size > max_bytes_) {
      ++dropped_;
      return;
    }
    for (auto it = queue_.begin(); bytes_ + size > max_bytes_ && it != queue_.end();) {
      if (!it->droppable) {
        ++it;
        continue;
      }
      bytes_ -= it->size();
      it = queue_.erase(it);
      ++dropped_;
    }
    bytes_ += size;
    queue_.push_back(std::move(frame));
  }

  /// The frame to send next, taken out of the queue and kept until sent(); nullptr if the queue is
  /// empty or a frame is still being sent (a WebSocket sends one message at a time).
  const Frame* start_next() {
    if (in_flight_ || queue_.empty()) return nullptr;
    in_flight_ = std::make_unique<Frame>(std::move(queue_.front()));
    queue_.pop_front();
    bytes_ -= in_flight_->size();
    return in_flight_.get();
  }
  /// The frame start_next() gave has been sent (or failed to be).
  void sent() { in_flight_.reset(); }

  /// Bytes waiting, not counting the frame being sent.
  std::size_t bytes() const { return bytes_; }
  std::size_t size() const { return queue_.size(); }
  std::uint64_t dropped() const { return dropped_; }

 private:
  std::size_t max_bytes_;
  std::deque<Frame> queue_;
  std::unique_ptr<Frame> in_flight_;
  std::size_t bytes_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace kestrel::foxglove
