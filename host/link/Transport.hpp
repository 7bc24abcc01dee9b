// Transport: a byte stream to a brick (Bluetooth RFCOMM, serial device or pty, TCP). Reads and
// writes wait with a limit; a broken connection, or a peer that takes no bytes within the limit,
// throws TransportClosed; the caller reconnects (see LinkRunner).
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "host/link/LinkSpec.hpp"

namespace nxtmap::link {

class TransportClosed : public std::runtime_error {
 public:
  explicit TransportClosed(const std::string& m) : std::runtime_error(m) {}
};

// How long one wait of a link may last (opening it, or one write): at most timeoutMs, and only
// while *keepGoing stays true (looked at every 20 ms; e.g. the runner's "running" flag, not owned).
struct WaitLimit {
  static constexpr int kMaxTimeoutMs = 3600 * 1000;  // an hour
  int timeoutMs = 5000;                              // 1 .. kMaxTimeoutMs
  const std::atomic<bool>* keepGoing = nullptr;      // none: only the timeout
};

class Transport {
 public:
  virtual ~Transport() = default;
  // Up to `capacity` bytes, waiting at most timeoutMs; 0 when nothing came.
  virtual size_t read(uint8_t* buffer, size_t capacity, int timeoutMs) = 0;
  virtual void write(const uint8_t* data, size_t size) = 0;
  virtual std::string describe() const = 0;
};

// A transport over a non-blocking file descriptor (owned; closed on destruction). A write that
// cannot hand over its bytes within `writeLimit` throws TransportClosed.
class FdTransport : public Transport {
 public:
  FdTransport(int fd, std::string description, const WaitLimit& writeLimit = {});
  ~FdTransport() override;
  FdTransport(const FdTransport&) = delete;
  FdTransport& operator=(const FdTransport&) = delete;
  size_t read(uint8_t* buffer, size_t capacity, int timeoutMs) override;
  void write(const uint8_t* data, size_t size) override;
  std::string describe() const override { return description_; }

 private:
  int fd_;
  std::string description_;
  WaitLimit writeLimit_;
};

// Opens bt:, serial: or tcp: links, waiting at most `limit` (a host or brick that never answers
// ends in a LinkError then). Throws LinkError with a clear reason when it cannot (no such device,
// connection refused, no answer, no Bluetooth adapter...). Writes on the link wait up to `limit` too.
std::unique_ptr<Transport> openTransport(const LinkSpec& spec, const WaitLimit& limit = {});

}  // namespace nxtmap::link
