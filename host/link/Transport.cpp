#include "host/link/Transport.hpp"

#include <bluetooth/bluetooth.h>
#include <bluetooth/rfcomm.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace nxtmap::link {
namespace {

std::string errnoText() { return std::strerror(errno); }

std::unique_ptr<Transport> openTcp(const LinkSpec& spec) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int rc = getaddrinfo(spec.address.c_str(), std::to_string(spec.port).c_str(), &hints, &found);
  if (rc != 0) throw LinkError("cannot resolve '" + spec.address + "': " + gai_strerror(rc));
  std::string lastError = "no address";
  for (addrinfo* a = found; a != nullptr; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) {
      lastError = errnoText();
      continue;
    }
    if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
      freeaddrinfo(found);
      return std::make_unique<FdTransport>(fd, spec.text);
    }
    lastError = errnoText();
    ::close(fd);
  }
  freeaddrinfo(found);
  throw LinkError("cannot connect to " + spec.address + ":" + std::to_string(spec.port) + ": " + lastError);
}

std::unique_ptr<Transport> openSerial(const LinkSpec& spec) {
  const int fd = ::open(spec.address.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw LinkError("cannot open " + spec.address + ": " + errnoText());
  termios tio{};
  if (::tcgetattr(fd, &tio) == 0) {
    // Raw bytes, 460800 baud (a pty ignores the rate), hardware handshake as the NXT's BC4 uses.
    ::cfmakeraw(&tio);
    ::cfsetispeed(&tio, B460800);
    ::cfsetospeed(&tio, B460800);
    tio.c_cflag |= CLOCAL | CREAD;
    tio.c_cc[VMIN] = 0;
    tio.c_cc[VTIME] = 0;
    if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
      const std::string why = errnoText();
      ::close(fd);
      throw LinkError("cannot set " + spec.address + " to raw 460800 baud: " + why);
    }
  } else if (errno != ENOTTY) {
    const std::string why = errnoText();
    ::close(fd);
    throw LinkError(spec.address + " is not a serial device: " + why);
  }
  return std::make_unique<FdTransport>(fd, spec.text);
}

std::unique_ptr<Transport> openBluetooth(const LinkSpec& spec) {
  const int fd = ::socket(AF_BLUETOOTH, SOCK_STREAM | SOCK_CLOEXEC, BTPROTO_RFCOMM);
  if (fd < 0) {
    throw LinkError("no Bluetooth here (" + errnoText() + "): is BlueZ running and an adapter present?");
  }
  sockaddr_rc addr{};
  addr.rc_family = AF_BLUETOOTH;
  addr.rc_channel = static_cast<uint8_t>(spec.port);
  if (str2ba(spec.address.c_str(), &addr.rc_bdaddr) != 0) {
    ::close(fd);
    throw LinkError("bad Bluetooth address " + spec.address);
  }
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0) {
    const std::string why = errnoText();
    ::close(fd);
    throw LinkError("cannot reach the NXT " + spec.address + " on RFCOMM channel " + std::to_string(spec.port) + ": " +
                    why + " (is it on, paired, and Bluetooth visible?)");
  }
  return std::make_unique<FdTransport>(fd, spec.text);
}

}  // namespace

FdTransport::FdTransport(int fd, std::string description) : fd_(fd), description_(std::move(description)) {}

FdTransport::~FdTransport() { ::close(fd_); }

size_t FdTransport::read(uint8_t* buffer, size_t capacity, int timeoutMs) {
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeoutMs);
  if (ready < 0) {
    if (errno == EINTR) return 0;
    throw TransportClosed(description_ + ": " + errnoText());
  }
  if (ready == 0) return 0;
  const ssize_t n = ::read(fd_, buffer, capacity);
  if (n > 0) return static_cast<size_t>(n);
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return 0;
  throw TransportClosed(description_ + (n == 0 ? ": connection closed" : ": " + errnoText()));
}

void FdTransport::write(const uint8_t* data, size_t size) {
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::send(fd_, data + done, size - done, MSG_NOSIGNAL);
    if (n < 0 && errno == ENOTSOCK) {
      const ssize_t m = ::write(fd_, data + done, size - done);
      if (m <= 0) throw TransportClosed(description_ + ": " + errnoText());
      done += static_cast<size_t>(m);
      continue;
    }
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      throw TransportClosed(description_ + ": " + errnoText());
    }
    done += static_cast<size_t>(n);
  }
}

std::unique_ptr<Transport> openTransport(const LinkSpec& spec) {
  switch (spec.kind) {
    case LinkSpec::Kind::Tcp:
      return openTcp(spec);
    case LinkSpec::Kind::Serial:
      return openSerial(spec);
    case LinkSpec::Kind::Bluetooth:
      return openBluetooth(spec);
    case LinkSpec::Kind::Sim:
      break;
  }
  throw LinkError("link " + spec.text + " is not a byte transport");
}

}  // namespace nxtmap::link
