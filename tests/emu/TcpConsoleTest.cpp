// The real firmware image in the emulated brick behind `emulate --listen tcp:...` (a TcpLink), with PC
// consoles on real loopback sockets driven in step with the brick: console after console gets answers
// (each one quits while the brick is sending to it), and a flood of bytes is held back by the link
// (bounded input, back-pressure through the TCP window) while the brick keeps running and still
// answers the request sent after it.
#include "EmuTestSupport.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkServer.hpp"
#include "host/link/Session.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

// A connected, non-blocking loopback client socket (-1 on failure). sendBufferBytes > 0 fixes SO_SNDBUF.
int dial(int port, int sendBufferBytes = 0) {
  const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (s < 0) return -1;
  if (sendBufferBytes > 0) ::setsockopt(s, SOL_SOCKET, SO_SNDBUF, &sendBufferBytes, sizeof sendBufferBytes);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(s);
    return -1;
  }
  ::fcntl(s, F_SETFL, ::fcntl(s, F_GETFL) | O_NONBLOCK);
  return s;
}

// The PC console: a socket to the brick's link and the console's Session, stepped by the test.
class TcpConsole {
 public:
  TcpConsole(int socket, uint32_t sessionId) : fd_(socket), pc_(link::SessionConfig{sessionId, 250, 250}) {}
  ~TcpConsole() { quit(); }
  TcpConsole(const TcpConsole&) = delete;
  TcpConsole& operator=(const TcpConsole&) = delete;

  // Feeds the session what arrived; sends what it has, as far as the socket takes it now (never
  // blocks: the brick runs in this thread). Returns the number of bytes that arrived.
  size_t step(uint32_t nowMs) {
    if (fd_ < 0) return 0;
    size_t got = 0;
    uint8_t buf[512];
    for (ssize_t r; (r = ::recv(fd_, buf, sizeof buf, 0)) > 0;) {
      pc_.receive(buf, static_cast<size_t>(r), nowMs);
      got += static_cast<size_t>(r);
    }
    const std::vector<uint8_t> out = pc_.transmit(nowMs);
    unsent_.insert(unsent_.end(), out.begin(), out.end());
    while (!unsent_.empty()) {
      const ssize_t w = ::send(fd_, unsent_.data(), unsent_.size(), MSG_NOSIGNAL);
      if (w <= 0) break;
      unsent_.erase(unsent_.begin(), unsent_.begin() + w);
    }
    return got;
  }
  void quit() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool open() const { return fd_ >= 0; }
  link::Session& session() { return pc_; }

 private:
  int fd_;
  link::Session pc_;
  std::vector<uint8_t> unsent_;  // the session's bytes the socket did not take yet
};

ElfImage firmware() {
  ElfLoad l = ElfImage::load(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf");
  if (!l.image) throw std::runtime_error(l.error);
  return std::move(*l.image);
}

EmulatedRunOptions linkedRun(LinkEndpoint& link, double seconds) {
  EmulatedRunOptions o;
  o.brick.startCol = 3;
  o.brick.startRow = 3;
  o.brick.link = &link;
  o.pressEnterAtS = -1;
  o.stopWhenExplored = false;
  o.maxSeconds = seconds;
  return o;
}

uint32_t msOf(uint64_t cycles) { return static_cast<uint32_t>(cycles / (kMckHz / 1000)); }

// Console after console: each connects, asks for the battery, and quits as soon as the brick's next
// bytes start arriving (the brick is mid-frame: the worst moment for the link to drop). The next one
// dials in after a gap (none, a few ms, a while) and must be answered too.
TEST(TcpConsoles, EachConsoleAfterTheLastQuitsGetsAnswers) {
  if (!std::filesystem::exists(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf")) GTEST_SKIP() << "no nxtmap.elf";
  const std::unique_ptr<TcpLink> link = listenOnFreePort(48000);
  ASSERT_TRUE(link) << "no free port";
  const ElfImage image = firmware();
  const sim::World world = smallRoom();
  const std::vector<uint32_t> gapMs{0, 0, 4, 300, 1};  // before consoles 2..6
  constexpr uint32_t kAnswerWithinMs = 10000;

  std::unique_ptr<TcpConsole> console;
  size_t index = 0, answered = 0;
  uint32_t openedAt = 0, nextAt = 500, lastMs = ~0u;
  bool quitting = false, late = false;
  EmulatedRunOptions o = linkedRun(*link, 120.0);
  o.onEvent = [&](uint64_t cycles) {
    const uint32_t ms = msOf(cycles);
    if (quitting) {  // every event: quit on the first byte of the brick's next frame
      if (console->step(ms) == 0) return false;
      console.reset();
      quitting = false;
      if (++index > gapMs.size()) return true;
      nextAt = ms + gapMs[index - 1];
    }
    if (!console && ms >= nextAt) {
      console = std::make_unique<TcpConsole>(dial(link->port()), 1000u + static_cast<uint32_t>(index));
      EXPECT_TRUE(console->open()) << "console " << index + 1 << " could not dial";
      console->session().requestBattery();
      openedAt = ms;
    }
    if (!console || ms == lastMs) return false;
    lastMs = ms;
    console->step(ms);
    const link::Session& pc = console->session();
    if (pc.connected() && pc.batteryMillivolts()) {
      ++answered;
      quitting = true;
    } else if (ms - openedAt > kAnswerWithinMs) {
      late = true;
      return true;
    }
    return false;
  };
  EmulatedRun run(image, world, o);
  const EmulatedRunReport r = run.run();
  EXPECT_FALSE(r.fault) << r.fault.describe();
  EXPECT_FALSE(late) << "console " << index + 1 << " got no answer within " << kAnswerWithinMs << " ms (emulated)";
  EXPECT_EQ(answered, gapMs.size() + 1) << "consoles answered";
}

// A 64 MiB flood (sent as fast as the socket takes it, for 2 emulated seconds): the brick's link input
// never holds more than its bound, the flooder is held back by the TCP window, the brick keeps running,
// and a console on the same connection is answered soon after the flood stops.
TEST(TcpConsoles, AFloodIsHeldBackAndTheBrickStillAnswers) {
  if (!std::filesystem::exists(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf")) GTEST_SKIP() << "no nxtmap.elf";
  const std::unique_ptr<TcpLink> link = listenOnFreePort(48000);
  ASSERT_TRUE(link) << "no free port";
  const ElfImage image = firmware();
  const sim::World world = smallRoom();
  constexpr size_t kFloodBytes = size_t{64} << 20;
  constexpr uint32_t kFloodUntilMs = 2000, kAnswerByMs = 15000;
  const int fd = dial(link->port(), 16 * 1024);
  ASSERT_GE(fd, 0);
  const std::vector<uint8_t> noise(64 * 1024, 0xFF);  // never a frame length the brick takes
  size_t flooded = 0, mostBuffered = 0;
  uint32_t lastMs = ~0u, answeredAt = 0;
  std::unique_ptr<TcpConsole> console;
  EmulatedRun* running = nullptr;
  EmulatedRunOptions o = linkedRun(*link, kAnswerByMs / 1000.0);
  o.onEvent = [&](uint64_t cycles) {
    mostBuffered = std::max(mostBuffered, running->brick().blueCore().pcBuffered());
    const uint32_t ms = msOf(cycles);
    if (ms == lastMs) return false;
    lastMs = ms;
    if (ms < kFloodUntilMs) {
      while (flooded < kFloodBytes) {
        const ssize_t w = ::send(fd, noise.data(), std::min(noise.size(), kFloodBytes - flooded), MSG_NOSIGNAL);
        if (w <= 0) break;  // the window is closed: the brick takes no more for now
        flooded += static_cast<size_t>(w);
      }
      uint8_t sink[4096];
      while (::recv(fd, sink, sizeof sink, 0) > 0) {}
      return false;
    }
    if (!console) {
      console = std::make_unique<TcpConsole>(fd, 77);
      console->session().requestBattery();
    }
    console->step(ms);
    if (console->session().connected() && console->session().batteryMillivolts()) {
      answeredAt = ms;
      return true;
    }
    return false;
  };
  EmulatedRun run(image, world, o);
  running = &run;
  const EmulatedRunReport r = run.run();
  EXPECT_FALSE(r.fault) << r.fault.describe();
  EXPECT_LE(mostBuffered, BlueCore::kPcInputBytes) << "bytes from the PC held by the emulator";
  EXPECT_LT(flooded, size_t{8} << 20) << "the flooder was not held back";
  EXPECT_GT(answeredAt, 0u) << "no answer by " << kAnswerByMs << " ms after " << flooded << " flood bytes";
  EXPECT_GT(r.btFromPc, 0u);
}

#endif

}  // namespace
}  // namespace nxtmap::emu::test
