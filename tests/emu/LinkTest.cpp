// The Bluetooth bridge over a real TCP socket: a PC client connects to 127.0.0.1:PORT, the firmware accepts,
// opens the stream and echoes; bytes pass through unchanged both ways.
#include "EmuTestSupport.hpp"
#include "host/emu/LinkServer.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <deque>
#include <string>
#include <vector>

namespace nxtmap::emu::test {
namespace {

TEST(TcpLink, PcClientTalksToTheFirmwareThroughTheBridge) {
  std::unique_ptr<TcpLink> link;
  int port = 0;
  for (int p = 42000 + getpid() % 2000; !link && p < 48000; p += 97) {
    try {
      link = std::make_unique<TcpLink>(p);
      port = p;
    } catch (const std::runtime_error&) {}
  }
  ASSERT_TRUE(link) << "no free port";
  const int pc = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(pc, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::send(pc, "wxyz", 4, 0), 4);
  ProbeRun r("bt", BrickConfig{}, 5.0, link.get());
  ASSERT_TRUE(r.ok) << r.fault();
  ASSERT_TRUE(r.port().exitCode.has_value());
  char buf[16] = {};
  pollfd p{pc, POLLIN, 0};
  ASSERT_GT(::poll(&p, 1, 2000), 0);
  const ssize_t n = ::recv(pc, buf, sizeof buf, 0);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<size_t>(n) : 0), "xyz{!");
  ::close(pc);
}

int dialLoopback(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(s);
    return -1;
  }
  return s;
}

// A PC that hangs up is seen to leave (connected() false once) before the next one, even when that one
// already waits in the backlog: the brick must see a new connection, not one stream going on.
TEST(TcpLink, APcLeavingIsSeenEvenWhenTheNextOneWaits) {
  const std::unique_ptr<TcpLink> link = listenOnFreePort(42050);
  ASSERT_TRUE(link) << "no free port";
  const int first = dialLoopback(link->port());
  ASSERT_GE(first, 0);
  ASSERT_TRUE(link->connected());
  const int second = dialLoopback(link->port());
  ASSERT_GE(second, 0);
  ::close(first);
  std::deque<uint8_t> in;
  bool left = false;
  for (int i = 0; i < 100 && !left; ++i) {
    left = !link->connected();
    link->receive(in, 64);  // reads the hang-up
    ::usleep(1000);
  }
  EXPECT_TRUE(left) << "the first PC's leaving was not seen";
  EXPECT_TRUE(link->connected()) << "the second PC";
  ASSERT_EQ(::send(second, "ab", 2, 0), 2);
  for (int i = 0; i < 100 && in.size() < 2; ++i) {
    link->receive(in, 64);
    ::usleep(1000);
  }
  EXPECT_EQ(std::string(in.begin(), in.end()), "ab");
  ::close(second);
}

// receive() takes at most what it is asked for; the rest stays in the socket.
TEST(TcpLink, ReceiveTakesAtMostWhatItIsAskedFor) {
  const std::unique_ptr<TcpLink> link = listenOnFreePort(42050);
  ASSERT_TRUE(link) << "no free port";
  const int pc = dialLoopback(link->port());
  ASSERT_GE(pc, 0);
  ASSERT_TRUE(link->connected());
  const std::string bytes(3000, 'x');
  ASSERT_EQ(::send(pc, bytes.data(), bytes.size(), 0), 3000);
  std::deque<uint8_t> in;
  size_t calls = 0;
  for (; calls < 1000 && in.size() < 3000; ++calls) {
    const size_t before = in.size();
    link->receive(in, 700);
    EXPECT_LE(in.size() - before, 700u);
    if (in.size() == before) ::usleep(1000);
  }
  EXPECT_EQ(in.size(), 3000u);
  EXPECT_GE(calls, 5u);
  ::close(pc);
}

TEST(TcpLink, RejectsAPortInUse) {
  const int s = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::listen(s, 1), 0);
  socklen_t len = sizeof a;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&a), &len);
  EXPECT_THROW(TcpLink(ntohs(a.sin_port)), std::runtime_error);
  ::close(s);
}

TEST(PtyLink, OpensARawPseudoTerminal) {
  PtyLink pty;
  EXPECT_EQ(pty.slaveName().rfind("/dev/pts/", 0), 0u);
  EXPECT_FALSE(pty.connected()) << "no PC has opened the slave yet";
  const uint8_t hello[] = {1, 2, 3};
  pty.send(hello, 3);  // nobody reads: must not block or fail
  const int pc = ::open(pty.slaveName().c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  ASSERT_GE(pc, 0);
  termios t{};
  ASSERT_EQ(::tcgetattr(pc, &t), 0);
  EXPECT_EQ(t.c_lflag & (ICANON | ECHO), 0u) << "raw mode for every opener";
  ::close(pc);
}

// The PC side of a pty: a tool that opens the slave connects, one that closes it leaves (reported once), and
// the next opener is a new session that never sees the bytes the first one left unread.
TEST(PtyLink, APcThatLeavesIsNoticedAndTheNextOneIsAccepted) {
  PtyLink pty;
  std::vector<std::string> lines;
  pty.setReporter([&](const std::string& l) { lines.push_back(l); });
  const int first = ::open(pty.slaveName().c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  ASSERT_GE(first, 0);
  EXPECT_TRUE(pty.connected());
  const uint8_t unread[] = {'o', 'l', 'd'};
  pty.send(unread, 3);
  ::close(first);
  EXPECT_FALSE(pty.connected()) << "the PC's leaving was not seen";
  EXPECT_FALSE(pty.connected());
  const int second = ::open(pty.slaveName().c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  ASSERT_GE(second, 0);
  EXPECT_TRUE(pty.connected());
  const uint8_t fresh[] = {'n', 'e', 'w'};
  pty.send(fresh, 3);
  char buf[16] = {};
  pollfd p{second, POLLIN, 0};
  ASSERT_GT(::poll(&p, 1, 1000), 0);
  const ssize_t n = ::read(second, buf, sizeof buf);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<size_t>(n) : 0), "new");
  EXPECT_EQ(pty.sessions(), 2);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_NE(lines[1].find("closed"), std::string::npos) << lines[1];
  ::close(second);
}

TEST(PtyLink, ReceiveTakesAtMostWhatItIsAskedFor) {
  PtyLink pty;
  const int pc = ::open(pty.slaveName().c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  ASSERT_GE(pc, 0);
  ASSERT_TRUE(pty.connected());
  const std::string bytes(1500, 'y');
  ASSERT_EQ(::write(pc, bytes.data(), bytes.size()), 1500);
  std::deque<uint8_t> in;
  for (int i = 0; i < 1000 && in.size() < 1500; ++i) {
    const size_t before = in.size();
    pty.receive(in, 400);
    EXPECT_LE(in.size() - before, 400u);
    if (in.size() == before) ::usleep(1000);
  }
  EXPECT_EQ(in.size(), 1500u);
  ::close(pc);
}

// A PC that connects and never reads: the brick's bytes fill the socket's buffers, and after kStallLimitMs with
// no byte taken the link is dropped, so the emulated brick goes on (before, send() waited for ever).
TEST(TcpLink, APcThatNeverReadsIsDroppedAndDoesNotStallTheBrick) {
  const std::unique_ptr<TcpLink> link = listenOnFreePort(42050);
  ASSERT_TRUE(link) << "no free port";
  const int pc = dialLoopback(link->port());
  ASSERT_GE(pc, 0);
  ASSERT_TRUE(link->connected());
  const std::string frame(4096, 'x');
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < 64 * 256 && link->connected(); ++i)  // up to 64 MiB, far past any socket buffer
    link->send(reinterpret_cast<const uint8_t*>(frame.data()), frame.size());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_FALSE(link->connected()) << "the silent PC is still attached";
  EXPECT_LT(seconds, 3.0 * TcpLink::kStallLimitMs / 1000.0);
  ::close(pc);
}

}  // namespace
}  // namespace nxtmap::emu::test
