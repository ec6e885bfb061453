#pragma once
// Two serial ports wired to each other, as a null-modem cable wires two UARTs: two pseudo-terminal
// pairs whose masters a thread joins, so that what one program writes to port `a` the other reads
// from port `b`, and back. Both ends open their pseudo-terminal's slave by its path.
#include <poll.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

namespace kestrel::testing {

class NullModem {
 public:
  NullModem() {
    for (End& e : ends_) {
      char name[256];
      termios raw{};
      ::cfmakeraw(&raw);
      if (::openpty(&e.master, &e.slave, name, &raw, nullptr) != 0) throw std::runtime_error("openpty failed");
      e.path = name;
    }
    relay_ = std::thread([this] { run(); });
  }
  ~NullModem() {
    stop_ = true;
    relay_.join();
    for (End& e : ends_) {
      ::close(e.master);
      ::close(e.slave);
    }
  }
  NullModem(const NullModem&) = delete;
  NullModem& operator=(const NullModem&) = delete;

  const std::string& a() const { return ends_[0].path; }
  const std::string& b() const { return ends_[1].path; }
  std::uint64_t bytes() const { return bytes_; }

 private:
  struct End {
    int master = -1, slave = -1;  // the slave stays open here too, so a port is never hung up between opens
    std::string path;
  };

  void run() {
    std::array<char, 4096> buffer{};
    while (!stop_) {
      pollfd p[2] = {{ends_[0].master, POLLIN, 0}, {ends_[1].master, POLLIN, 0}};
      if (::poll(p, 2, 10) <= 0) continue;
      for (int i = 0; i < 2; ++i) {
        if ((p[i].revents & POLLIN) == 0) continue;
        const ssize_t n = ::read(ends_[i].master, buffer.data(), buffer.size());
        if (n <= 0) continue;
        bytes_ += static_cast<std::uint64_t>(n);
        for (ssize_t done = 0; done < n;) {
          const ssize_t w = ::write(ends_[1 - i].master, buffer.data() + done, static_cast<std::size_t>(n - done));
          if (w <= 0) break;
          done += w;
        }
      }
    }
  }

  std::array<End, 2> ends_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> bytes_{0};
  std::thread relay_;
};

}  // namespace kestrel::testing
