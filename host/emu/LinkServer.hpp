// LinkServer: the PC ends of the emulated Bluetooth link. TcpLink listens on 127.0.0.1:PORT for one PC
// at a time (a connect = the PC dialling the brick; a hang-up = the link dropping). PtyLink opens a
// pseudo-terminal in raw mode whose slave name a serial tool (or the console) opens like /dev/rfcomm0;
// it counts as connected from the start. Both hand the brick at most what it asks for and leave the rest
// unread, so the kernel's flow control (the TCP window, the pty's buffer) holds the PC back.
#pragma once

#include "host/emu/LinkEndpoint.hpp"

#include <memory>
#include <string>

namespace nxtmap::emu {

class TcpLink : public LinkEndpoint {
 public:
  // Binds and listens; throws std::runtime_error with the reason when it cannot.
  explicit TcpLink(int port);
  ~TcpLink() override;
  bool connected() override;
  void send(const uint8_t* data, size_t n) override;
  void receive(std::deque<uint8_t>& out, size_t maxBytes) override;
  bool waitForActivity(int timeoutMs) override;
  int port() const { return port_; }

  // A PC that takes no byte for this long (wall time, ms) while the brick sends is dropped, so a client that
  // never reads cannot stall the emulated brick (a Bluetooth link's supervision timeout does the same).
  static constexpr int kStallLimitMs = 2000;

 private:
  void drop();
  int listen_ = -1, client_ = -1, port_ = 0;
  bool hungUp_ = false;  // a PC left and connected() has not said so yet
};

class PtyLink : public LinkEndpoint {
 public:
  PtyLink();  // throws std::runtime_error on failure
  ~PtyLink() override;
  const std::string& slaveName() const { return name_; }
  bool connected() override { return true; }
  void send(const uint8_t* data, size_t n) override;
  void receive(std::deque<uint8_t>& out, size_t maxBytes) override;
  bool waitForActivity(int timeoutMs) override;

 private:
  int master_ = -1, slave_ = -1;
  std::string name_;
};

// "tcp:127.0.0.1:PORT" or "pty"; throws std::invalid_argument naming the problem.
std::unique_ptr<LinkEndpoint> openLink(const std::string& spec, std::string& description);

}  // namespace nxtmap::emu
