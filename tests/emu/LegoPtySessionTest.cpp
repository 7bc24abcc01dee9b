// A PC tool on the emulated brick's pseudo-terminal, as nxt-python's devfile backend uses it: it reads a
// reply's two length bytes, then its body with one read() (no loop), so the brick's bytes must reach it in the
// bursts the BlueCore sends, never byte by byte. Then it closes the device and a second tool opens it: the
// link server notices the first leave and the brick serves the next. Real threads on wall time: the emulated
// brick runs in the test's thread, the tool in another.
#include "EmuTestSupport.hpp"
#include "LegoBrickSession.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkServer.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <thread>

namespace nxtmap::emu::lego {
namespace {

struct ToolRun {
  int requests = 0, replies = 0, whole = 0;  // whole: body complete in the one read after the length
  std::string problem;
};

// Reads exactly n bytes within timeoutMs of wall time (the length prefix); false on time-out or error.
bool readExactly(int fd, uint8_t* p, size_t n, int timeoutMs) {
  while (n > 0) {
    pollfd w{fd, POLLIN, 0};
    if (::poll(&w, 1, timeoutMs) <= 0) return false;
    const ssize_t r = ::read(fd, p, n);
    if (r <= 0) return false;
    p += r;
    n -= static_cast<size_t>(r);
  }
  return true;
}

// One tool session: opens the slave, waits for the stream, asks n battery levels one at a time, closes.
ToolRun runTool(const std::string& slave, const std::atomic<bool>& streaming, int n) {
  ToolRun t;
  const int fd = ::open(slave.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    t.problem = "cannot open " + slave;
    return t;
  }
  for (int waited = 0; !streaming && waited < 20000; ++waited) ::usleep(1000);
  const Bytes request = framed(getBatteryLevel());
  for (int i = 0; i < n && t.problem.empty(); ++i) {
    ++t.requests;
    if (::write(fd, request.data(), request.size()) != static_cast<ssize_t>(request.size())) t.problem = "write";
    uint8_t length[2];
    if (!readExactly(fd, length, 2, 5000)) {
      t.problem = "no reply to request " + std::to_string(i);
      break;
    }
    const size_t size = length[0] | (static_cast<size_t>(length[1]) << 8);
    uint8_t body[256] = {};
    if (size == 0 || size > sizeof body) {
      t.problem = "length " + std::to_string(size);
      break;
    }
    const ssize_t got = ::read(fd, body, size);  // one read, as nxt-python's devfile recv does
    ++t.replies;
    if (got == static_cast<ssize_t>(size))
      ++t.whole;
    else if (got < 0 || !readExactly(fd, body + got, size - static_cast<size_t>(got), 5000))
      t.problem = "reply body cut";
  }
  ::close(fd);
  return t;
}

TEST(LegoPtySessionEndToEnd, ABodyReadInOneGoIsWholeAndTheNextToolIsServed) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the emulated brick at ASan speed: make test runs this from the Release build (EndToEnd)";
#endif
  const std::string elf = simFirmwarePath();
  if (elf.empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  ElfLoad load = ElfImage::load(elf);
  ASSERT_TRUE(load.image) << load.error;
  PtyLink pty;
  std::vector<std::string> lines;
  pty.setReporter([&](const std::string& l) { lines.push_back(l); });
  std::atomic<bool> streaming{false}, done{false};
  ToolRun first, second;
  std::thread tool([&] {
    first = runTool(pty.slaveName(), streaming, 100);
    for (int waited = 0; streaming && waited < 20000; ++waited) ::usleep(1000);  // the brick saw it leave
    second = runTool(pty.slaveName(), streaming, 20);
    done = true;
  });
  EmulatedRunOptions o;
  o.brick.startCol = 3;
  o.brick.startRow = 3;
  o.brick.link = &pty;
  o.pressEnterAtS = -1;
  o.stopWhenExplored = false;
  o.maxSeconds = 600;
  EmulatedRun* run = nullptr;
  o.onEvent = [&](uint64_t) {
    streaming = run->brick().blueCore().streaming();
    return done.load();
  };
  EmulatedRun e(*load.image, test::smallRoom(), o);
  run = &e;
  const EmulatedRunReport r = e.run();
  done = true;
  tool.join();
  EXPECT_FALSE(r.fault) << r.fault.describe();
  EXPECT_EQ(first.problem, "");
  EXPECT_EQ(first.replies, 100);
  EXPECT_EQ(first.whole, first.replies) << "replies whose body came in one read";
  EXPECT_EQ(second.problem, "") << "the second tool after the first closed the device";
  EXPECT_EQ(second.replies, 20);
  EXPECT_EQ(second.whole, second.replies);
  EXPECT_EQ(pty.sessions(), 2);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_NE(lines[1].find("closed"), std::string::npos) << lines[1];
}

}  // namespace
}  // namespace nxtmap::emu::lego
