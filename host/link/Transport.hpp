// Transport: a byte stream to a brick (Bluetooth RFCOMM, serial device or pty, TCP). Blocking
// writes, reads with a timeout. A broken connection throws TransportClosed; the caller
// reconnects (see LinkRunner).
#pragma once
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

class Transport {
 public:
  virtual ~Transport() = default;
  // Up to `capacity` bytes, waiting at most timeoutMs; 0 when nothing came.
  virtual size_t read(uint8_t* buffer, size_t capacity, int timeoutMs) = 0;
  virtual void write(const uint8_t* data, size_t size) = 0;
  virtual std::string describe() const = 0;
};

// A transport over a file descriptor (owned; closed on destruction).
class FdTransport : public Transport {
 public:
  FdTransport(int fd, std::string description);
  ~FdTransport() override;
  FdTransport(const FdTransport&) = delete;
  FdTransport& operator=(const FdTransport&) = delete;
  size_t read(uint8_t* buffer, size_t capacity, int timeoutMs) override;
  void write(const uint8_t* data, size_t size) override;
  std::string describe() const override { return description_; }

 private:
  int fd_;
  std::string description_;
};

// Opens bt:, serial: or tcp: links. Throws LinkError with a clear reason when it cannot
// (no such device, connection refused, no Bluetooth adapter...).
std::unique_ptr<Transport> openTransport(const LinkSpec& spec);

}  // namespace nxtmap::link
