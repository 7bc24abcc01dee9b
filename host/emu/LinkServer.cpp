#include "host/emu/LinkServer.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>

namespace nxtmap::emu {

namespace {
const int kRadioWindowBytes = 4096;  // SO_RCVBUF asked for; Linux doubles it for its own bookkeeping
}  // namespace

TcpLink::TcpLink(int port) : port_(port) {
  listen_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (listen_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listen_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  // A PC's connection gets a receive window of about a radio's (accepted sockets inherit it), so a
  // PC that sends faster than the brick reads is held back within a few KiB.
  ::setsockopt(listen_, SOL_SOCKET, SO_RCVBUF, &kRadioWindowBytes, sizeof kRadioWindowBytes);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(listen_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(listen_, 1) != 0) {
    const std::string why = std::strerror(errno);
    ::close(listen_);
    throw std::runtime_error("cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + why);
  }
}

TcpLink::~TcpLink() {
  report_ = nullptr;  // closing is not a PC leaving
  drop();
  if (listen_ >= 0) ::close(listen_);
}

void TcpLink::drop() {
  if (client_ >= 0) {
    ::close(client_);
    hungUp_ = true;
    if (report_) report_("link: the PC on port " + std::to_string(port_) + " left; waiting for the next");
  }
  client_ = -1;
}

bool TcpLink::connected() {
  if (hungUp_) {  // the brick sees this PC leave before the next one, even one already waiting
    hungUp_ = false;
    return false;
  }
  if (client_ < 0) {
    client_ = ::accept4(listen_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (client_ >= 0 && report_) report_("link: a PC connected on port " + std::to_string(port_));
  }
  return client_ >= 0;
}

void TcpLink::send(const uint8_t* d, size_t n) {
  int stalledMs = 0;  // wall time the PC has taken no byte
  while (client_ >= 0 && n > 0) {
    const ssize_t w = ::send(client_, d, n, MSG_NOSIGNAL);
    if (w > 0) {
      d += w;
      n -= static_cast<size_t>(w);
      stalledMs = 0;
      continue;
    }
    if (w < 0 && (errno == EAGAIN || errno == EINTR) && stalledMs < kStallLimitMs) {
      pollfd p{client_, POLLOUT, 0};
      ::poll(&p, 1, 100);
      stalledMs += 100;
      continue;
    }
    drop();  // an error, or a PC that reads nothing: the link is lost, as a radio's would be
  }
}

void TcpLink::receive(std::deque<uint8_t>& out, size_t maxBytes) {
  uint8_t buf[512];
  while (client_ >= 0 && maxBytes > 0) {
    const ssize_t r = ::recv(client_, buf, std::min(sizeof buf, maxBytes), 0);
    if (r > 0) {
      out.insert(out.end(), buf, buf + r);
      maxBytes -= static_cast<size_t>(r);
      continue;
    }
    if (r == 0 || (errno != EAGAIN && errno != EINTR)) drop();  // the PC hung up
    break;
  }
}

bool TcpLink::waitForActivity(int ms) {
  pollfd p{client_ >= 0 ? client_ : listen_, POLLIN, 0};
  return ::poll(&p, 1, ms) > 0;
}

PtyLink::PtyLink() {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0)
    throw std::runtime_error(std::string("cannot open a pseudo-terminal: ") + std::strerror(errno));
  const char* n = ::ptsname(master_);
  if (!n) throw std::runtime_error("ptsname failed");
  name_ = n;
  // Raw mode through a short-lived slave descriptor: the terminal keeps it for every later opener.
  const int slave = ::open(n, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (slave < 0) throw std::runtime_error(name_ + ": " + std::strerror(errno));
  termios t{};
  if (::tcgetattr(slave, &t) == 0) {
    ::cfmakeraw(&t);
    ::tcsetattr(slave, TCSANOW, &t);
  }
  ::close(slave);
}

PtyLink::~PtyLink() {
  if (master_ >= 0) ::close(master_);
}

bool PtyLink::slaveOpen() const {
  pollfd p{master_, POLLIN, 0};
  return ::poll(&p, 1, 0) >= 0 && (p.revents & POLLHUP) == 0;
}

void PtyLink::flushUnread() const {
  const int slave = ::open(name_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (slave >= 0) {
    ::tcflush(slave, TCIOFLUSH);  // the brick's bytes the PC never read, and the PC's not yet taken
    ::close(slave);
  }
  uint8_t buf[512];
  while (::read(master_, buf, sizeof buf) > 0) {}
}

bool PtyLink::connected() {
  const bool open = slaveOpen();
  if (open && !open_) {
    ++sessions_;
    if (report_) report_("link: a PC opened " + name_ + " (session " + std::to_string(sessions_) + ")");
  }
  if (!open && open_) {
    flushUnread();
    if (report_) report_("link: the PC closed " + name_ + "; waiting for the next one to open it");
  }
  open_ = open;
  return open;
}

void PtyLink::send(const uint8_t* d, size_t n) {
  int stalledMs = 0;
  while (open_ && n > 0) {  // with no PC the bytes are lost with the link
    const ssize_t w = ::write(master_, d, n);
    if (w > 0) {
      d += w;
      n -= static_cast<size_t>(w);
      stalledMs = 0;
      continue;
    }
    if (w < 0 && (errno == EAGAIN || errno == EINTR) && stalledMs < kStallLimitMs) {
      pollfd p{master_, POLLOUT, 0};
      if (::poll(&p, 1, 100) > 0 && (p.revents & POLLHUP) != 0) return;  // the PC left
      stalledMs += 100;
      continue;
    }
    return;  // a PC that reads nothing: the rest is dropped, as a radio would
  }
}

void PtyLink::receive(std::deque<uint8_t>& out, size_t maxBytes) {
  uint8_t buf[512];
  while (maxBytes > 0) {
    const ssize_t r = ::read(master_, buf, std::min(sizeof buf, maxBytes));
    if (r <= 0) break;  // nothing yet, or EIO: no PC holds the slave
    out.insert(out.end(), buf, buf + r);
    maxBytes -= static_cast<size_t>(r);
  }
}

bool PtyLink::waitForActivity(int ms) {
  if (!slaveOpen()) {  // the master reads POLLHUP at once: wait a little for a PC to open the slave
    ::usleep(static_cast<useconds_t>(std::min(ms, 20)) * 1000u);
    return false;
  }
  pollfd p{master_, POLLIN, 0};
  return ::poll(&p, 1, ms) > 0;
}

std::unique_ptr<LinkEndpoint> openLink(const std::string& spec, std::string& description) {
  const LinkReporter toStderr = [](const std::string& line) { std::cerr << line << "\n" << std::flush; };
  if (spec == "pty") {
    auto l = std::make_unique<PtyLink>();
    l->setReporter(toStderr);
    description = "pty " + l->slaveName();
    return l;
  }
  const std::string prefix = "tcp:127.0.0.1:";
  if (spec.compare(0, prefix.size(), prefix) != 0)
    throw std::invalid_argument("--listen must be tcp:127.0.0.1:PORT or pty, not '" + spec + "'");
  const std::string p = spec.substr(prefix.size());
  char* end = nullptr;
  const long port = std::strtol(p.c_str(), &end, 10);
  if (p.empty() || *end != '\0' || port < 1 || port > 65535)
    throw std::invalid_argument("--listen: port must be 1..65535, not '" + p + "'");
  auto l = std::make_unique<TcpLink>(static_cast<int>(port));
  l->setReporter(toStderr);
  description = "tcp 127.0.0.1:" + std::to_string(port);
  return l;
}

}  // namespace nxtmap::emu
