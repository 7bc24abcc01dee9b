// LinkServer: the PC ends of the emulated Bluetooth link. TcpLink listens on 127.0.0.1:PORT for one PC
// at a time (a connect = the PC dialling the brick; a hang-up = the link dropping). PtyLink opens a
// pseudo-terminal in raw mode whose slave name a serial tool (or the console) opens like /dev/rfcomm0;
// a PC is connected while some process holds the slave open (the master reads POLLHUP once the last one
// closes it), so a tool that exits is a hang-up and the next one to open the slave a new connection;
// the bytes a leaving PC did not read are flushed, never handed to the next. Both hand the brick at most
// what it asks for and leave the rest unread, so the kernel's flow control (the TCP window, the pty's
// buffer) holds the PC back. Each send() is one write (the BlueCore's radio packet), never split by us.
// A reporter, when set, gets one line per PC arriving or leaving (openLink's prints them to stderr).
#pragma once

#include "host/emu/LinkEndpoint.hpp"

#include <functional>
#include <memory>
#include <string>

namespace nxtmap::emu {

using LinkReporter = std::function<void(const std::string& line)>;

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
  void setReporter(LinkReporter r) { report_ = std::move(r); }

  // A PC that takes no byte for this long (wall time, ms) while the brick sends is dropped, so a client that
  // never reads cannot stall the emulated brick (a Bluetooth link's supervision timeout does the same).
  static constexpr int kStallLimitMs = 2000;

 private:
  void drop();
  int listen_ = -1, client_ = -1, port_ = 0;
  bool hungUp_ = false;  // a PC left and connected() has not said so yet
  LinkReporter report_;
};

class PtyLink : public LinkEndpoint {
 public:
  PtyLink();  // throws std::runtime_error on failure
  ~PtyLink() override;
  const std::string& slaveName() const { return name_; }
  bool connected() override;  // some process holds the slave open
  void send(const uint8_t* data, size_t n) override;
  void receive(std::deque<uint8_t>& out, size_t maxBytes) override;
  bool waitForActivity(int timeoutMs) override;
  void setReporter(LinkReporter r) { report_ = std::move(r); }
  int sessions() const { return sessions_; }  // PCs that opened the slave so far

  // A PC that takes no byte for this long (wall time, ms) loses the rest of a send (a radio drops it too).
  static constexpr int kStallLimitMs = 2000;

 private:
  bool slaveOpen() const;    // POLLHUP on the master: no process holds the slave
  void flushUnread() const;  // drops what the slave's reader left unread
  int master_ = -1;
  std::string name_;
  bool open_ = false;  // a PC held the slave at the last connected()
  int sessions_ = 0;
  LinkReporter report_;
};

// "tcp:127.0.0.1:PORT" or "pty"; throws std::invalid_argument naming the problem.
std::unique_ptr<LinkEndpoint> openLink(const std::string& spec, std::string& description);

}  // namespace nxtmap::emu
