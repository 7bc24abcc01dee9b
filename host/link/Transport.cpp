#include "host/link/Transport.hpp"

#include <bluetooth/bluetooth.h>
#include <bluetooth/rfcomm.h>
#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace nxtmap::link {
namespace {

using Clock = std::chrono::steady_clock;

std::string errnoText() { return std::strerror(errno); }

// "2 s", "0.5 s": a wait limit as the messages give it.
std::string durationText(int ms) {
  const std::string whole = std::to_string(ms / 1000);
  if (ms % 1000 == 0) return whole + " s";
  std::string frac = std::to_string(1000 + ms % 1000).substr(1);
  while (frac.back() == '0') frac.pop_back();
  return whole + "." + frac + " s";
}

Clock::time_point deadlineOf(const WaitLimit& limit) {
  return Clock::now() + std::chrono::milliseconds(std::clamp(limit.timeoutMs, 0, WaitLimit::kMaxTimeoutMs));
}

enum class Wait { Ready, TimedOut, Stopped };

// Waits until `fd` is ready for `events` (or has an error the next call will report), until
// `deadline` and while limit.keepGoing says so, in slices of at most 20 ms.
Wait waitReady(int fd, short events, const WaitLimit& limit, Clock::time_point deadline) {
  for (;;) {
    if (limit.keepGoing != nullptr && !limit.keepGoing->load()) return Wait::Stopped;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return Wait::TimedOut;
    pollfd p{fd, events, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<decltype(left)>(left, 20)));
    if (ready > 0 || (ready < 0 && errno != EINTR)) return Wait::Ready;
  }
}

// Connects the non-blocking socket `fd` within `limit`; false with the reason in `why` when it cannot.
bool connectWithin(int fd, const sockaddr* address, socklen_t size, const WaitLimit& limit, Clock::time_point deadline,
                   std::string& why) {
  if (::connect(fd, address, size) == 0) return true;
  if (errno != EINPROGRESS && errno != EINTR) {
    why = errnoText();
    return false;
  }
  switch (waitReady(fd, POLLOUT, limit, deadline)) {
    case Wait::TimedOut: why = "no answer within " + durationText(limit.timeoutMs); return false;
    case Wait::Stopped: why = "stopped"; return false;
    case Wait::Ready: break;
  }
  int error = 0;
  socklen_t length = sizeof(error);
  if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) != 0) error = errno;
  if (error == 0) return true;
  why = std::strerror(error);
  return false;
}

std::unique_ptr<Transport> openTcp(const LinkSpec& spec, const WaitLimit& limit) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int rc = getaddrinfo(spec.address.c_str(), std::to_string(spec.port).c_str(), &hints, &found);
  if (rc != 0) throw LinkError("cannot resolve '" + spec.address + "': " + gai_strerror(rc));
  const Clock::time_point deadline = deadlineOf(limit);  // for all the host's addresses together
  std::string lastError = "no address";
  for (addrinfo* a = found; a != nullptr; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, a->ai_protocol);
    if (fd < 0) {
      lastError = errnoText();
      continue;
    }
    if (connectWithin(fd, a->ai_addr, a->ai_addrlen, limit, deadline, lastError)) {
      freeaddrinfo(found);
      return std::make_unique<FdTransport>(fd, spec.text, limit);
    }
    ::close(fd);
  }
  freeaddrinfo(found);
  throw LinkError("cannot connect to " + spec.address + ":" + std::to_string(spec.port) + ": " + lastError);
}

std::unique_ptr<Transport> openSerial(const LinkSpec& spec, const WaitLimit& limit) {
  // Non-blocking: opening a tty without carrier would otherwise wait for one.
  const int fd = ::open(spec.address.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
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
  return std::make_unique<FdTransport>(fd, spec.text, limit);
}

std::unique_ptr<Transport> openBluetooth(const LinkSpec& spec, const WaitLimit& limit) {
  const int fd = ::socket(AF_BLUETOOTH, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, BTPROTO_RFCOMM);
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
  std::string why;
  if (!connectWithin(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr), limit, deadlineOf(limit), why)) {
    ::close(fd);
    throw LinkError("cannot reach the NXT " + spec.address + " on RFCOMM channel " + std::to_string(spec.port) + ": " +
                    why + " (is it on, paired, and Bluetooth visible?)");
  }
  return std::make_unique<FdTransport>(fd, spec.text, limit);
}

// One send (sockets) or write (serial devices, ptys): the bytes taken, or -1 with errno.
ssize_t sendSome(int fd, const uint8_t* data, size_t size) {
  const ssize_t n = ::send(fd, data, size, MSG_NOSIGNAL);
  if (n < 0 && errno == ENOTSOCK) return ::write(fd, data, size);
  return n;
}

}  // namespace

FdTransport::FdTransport(int fd, std::string description, const WaitLimit& writeLimit)
    : fd_(fd), description_(std::move(description)), writeLimit_(writeLimit) {}

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
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return 0;
  throw TransportClosed(description_ + (n == 0 ? ": connection closed" : ": " + errnoText()));
}

void FdTransport::write(const uint8_t* data, size_t size) {
  const Clock::time_point deadline = deadlineOf(writeLimit_);  // the whole buffer within the limit
  size_t done = 0;
  while (done < size) {
    const ssize_t n = sendSome(fd_, data + done, size - done);
    if (n > 0) {
      done += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) throw TransportClosed(description_ + ": the device took no bytes");
    if (errno != EAGAIN && errno != EWOULDBLOCK) throw TransportClosed(description_ + ": " + errnoText());
    switch (waitReady(fd_, POLLOUT, writeLimit_, deadline)) {
      case Wait::Ready: break;
      case Wait::TimedOut:
        throw TransportClosed(description_ + ": the other end took no bytes within " +
                              durationText(writeLimit_.timeoutMs));
      case Wait::Stopped: throw TransportClosed(description_ + ": stopped");
    }
  }
}

std::unique_ptr<Transport> openTransport(const LinkSpec& spec, const WaitLimit& limit) {
  switch (spec.kind) {
    case LinkSpec::Kind::Tcp: return openTcp(spec, limit);
    case LinkSpec::Kind::Serial: return openSerial(spec, limit);
    case LinkSpec::Kind::Bluetooth: return openBluetooth(spec, limit);
    case LinkSpec::Kind::Sim: break;
  }
  throw LinkError("link " + spec.text + " is not a byte transport");
}

}  // namespace nxtmap::link
