// LoopbackListener: a TCP listener on 127.0.0.1 that never answers, for the tests of bounded
// waits. NeverAccepts: its accept queue (backlog 0) is filled by connections of its own, so
// Linux drops every further connection request unanswered (the caller's connect never
// completes). AcceptsSilently: a thread accepts every connection and never sends or reads a byte.
#pragma once
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <thread>
#include <vector>

namespace nxtmap::link::test {

class LoopbackListener {
 public:
  enum class Mode { NeverAccepts, AcceptsSilently };

  explicit LoopbackListener(Mode mode) {
    server_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof(addr);
    if (server_ < 0 || ::bind(server_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0 ||
        ::listen(server_, mode == Mode::NeverAccepts ? 0 : 8) != 0 ||
        ::getsockname(server_, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
      return;
    }
    port_ = ntohs(addr.sin_port);
    if (mode == Mode::NeverAccepts) {
      ready_ = fillAcceptQueue(addr);
    } else {
      acceptor_ = std::thread([this] { acceptForever(); });
      ready_ = true;
    }
  }
  ~LoopbackListener() {
    stop_ = true;
    if (acceptor_.joinable()) acceptor_.join();
    for (const int fd : held_) ::close(fd);
    if (server_ >= 0) ::close(server_);
  }
  LoopbackListener(const LoopbackListener&) = delete;
  LoopbackListener& operator=(const LoopbackListener&) = delete;

  // Whether the listener was set up as asked (for NeverAccepts: its queue is full).
  bool ready() const { return ready_; }
  int port() const { return port_; }

 private:
  // Connects to itself until a connection request goes unanswered for 200 ms (at most 8 tries).
  bool fillAcceptQueue(const sockaddr_in& addr) {
    for (int i = 0; i < 8; ++i) {
      const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
      if (fd < 0) return false;
      held_.push_back(fd);
      if (::connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)) == 0) continue;
      pollfd p{fd, POLLOUT, 0};
      if (::poll(&p, 1, 200) == 0) return true;  // not answered: the queue is full
    }
    return false;
  }
  void acceptForever() {
    while (!stop_) {
      pollfd p{server_, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      const int fd = ::accept4(server_, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd >= 0) held_.push_back(fd);  // only this thread touches held_ until the join
    }
  }

  int server_ = -1;
  int port_ = 0;
  bool ready_ = false;
  std::atomic<bool> stop_{false};
  std::vector<int> held_;  // the fillers, or the accepted connections (never read)
  std::thread acceptor_;
};

}  // namespace nxtmap::link::test
