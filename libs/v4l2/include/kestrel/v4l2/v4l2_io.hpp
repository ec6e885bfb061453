#pragma once
// The system calls a V4L2 capture makes, behind an interface one step above the kernel, so that
// the capture logic above it (V4l2Camera) runs against a fake device in tests: short, late,
// corrupt and vanishing buffers. The real one forwards to open(2), ioctl(2), mmap(2), poll(2).
#include <poll.h>
#include <sys/types.h>

#include <cstddef>

namespace kestrel::v4l2 {

class V4l2Io {
 public:
  virtual ~V4l2Io() = default;
  /// As open(2), ioctl(2), ...: -1 with errno set on failure.
  virtual int open(const char* path, int flags) = 0;
  virtual int close(int fd) = 0;
  virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
  virtual void* mmap(std::size_t length, int fd, off_t offset) = 0;  ///< MAP_FAILED on failure
  virtual int munmap(void* address, std::size_t length) = 0;
  virtual int poll(pollfd* fds, nfds_t n, int timeout_ms) = 0;
};

/// The kernel's.
V4l2Io& system_v4l2_io();

}  // namespace kestrel::v4l2
