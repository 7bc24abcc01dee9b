// Real byte transports: the stand-in brick behind a TCP socket and behind a pty, the PC's
// session in a LinkRunner on the other side; a dropped connection is reconnected. Every wait
// ends: at its limit, or at once when the runner stops.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <pty.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <functional>
#include <mutex>
#include <thread>

#include "host/link/LinkRunner.hpp"
#include "host/link/SimBrick.hpp"
#include "host/sim/World.hpp"
#include "tests/link/LoopbackListener.hpp"

namespace nxtmap::link {
namespace {

sim::World smallRoom() {
  return sim::World::fromRows({"##########", "#........#", "#..#.....#", "#........#", "#....#...#", "##########"});
}

// Pumps bytes between a file descriptor and a stand-in brick on the wall clock.
std::mutex brickMutex;  // the brick is shared by the pump thread and the test's checks

void pumpBrick(int fd, SimBrick& brick, const std::atomic<bool>& stop, std::atomic<int>& closedCount) {
  const auto start = std::chrono::steady_clock::now();
  uint8_t buf[256];
  while (!stop) {
    const uint32_t now =
        static_cast<uint32_t>(
            std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count()) *
        10;  // ten times faster than real time
    std::vector<uint8_t> out;
    {
      std::lock_guard<std::mutex> lock(brickMutex);
      brick.step(now);
      out = brick.transmit(now, 512);
    }
    if (!out.empty()) {
      ssize_t n = ::send(fd, out.data(), out.size(), MSG_NOSIGNAL);
      if (n < 0 && errno == ENOTSOCK) n = ::write(fd, out.data(), out.size());
      if (n < 0) {
        ++closedCount;  // the PC closed its end
        break;
      }
    }
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 2) > 0) {
      const ssize_t n = ::read(fd, buf, sizeof(buf));
      if (n <= 0) {
        ++closedCount;
        break;
      }
      std::lock_guard<std::mutex> lock(brickMutex);
      brick.receive(buf, static_cast<size_t>(n));
    }
  }
}

bool waitUntil(const std::function<bool()>& done, int seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (std::chrono::steady_clock::now() < end) {
    {
      std::lock_guard<std::mutex> lock(brickMutex);
      if (done()) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::lock_guard<std::mutex> lock(brickMutex);
  return done();
}

TEST(Transport, TcpLinkMapsTheRoomAndSurvivesADroppedConnection) {
  const sim::World world = smallRoom();
  SimBrickConfig config;
  config.run.startCol = 1;
  config.run.startRow = 1;
  SimBrick brick(world, config);

  const int server = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(server, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(server, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
  ASSERT_EQ(::listen(server, 2), 0);
  socklen_t len = sizeof(addr);
  ASSERT_EQ(::getsockname(server, reinterpret_cast<sockaddr*>(&addr), &len), 0);
  const int port = ntohs(addr.sin_port);

  std::atomic<bool> stop{false};
  std::atomic<int> closed{0};
  struct Joiner {
    std::atomic<bool>& stop;
    std::thread& t;
    ~Joiner() {
      stop = true;
      if (t.joinable()) t.join();
    }
  };
  std::thread brickSide;
  const Joiner joiner{stop, brickSide};
  brickSide = std::thread([&] {
    // One connection after another, as a brick accepting the PC again after a drop.
    while (!stop) {
      pollfd p{server, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      const int fd = ::accept(server, nullptr, nullptr);
      if (fd < 0) continue;
      pumpBrick(fd, brick, stop, closed);
      std::lock_guard<std::mutex> lock(brickMutex);
      brick.linkLost();
      ::close(fd);
    }
  });

  const LinkSpec spec = parseLinkSpec("tcp:127.0.0.1:" + std::to_string(port));
  LinkRunner runner([&] { return openTransport(spec); }, SessionConfig{}, 100);
  runner.start();  // stopped by its destructor, before the joiner ends the brick side
  ASSERT_TRUE(waitUntil([&] { return runner.with([](Session& s) { return s.connected(); }); }, 10));
  runner.with([](Session& s) { return s.explore(); });
  ASSERT_TRUE(waitUntil([&] { return brick.counters().cellsMoved >= 5; }, 20));
  runner.dropConnection();
  ASSERT_TRUE(waitUntil([&] { return closed.load() >= 1; }, 10));
  ASSERT_TRUE(waitUntil([&] { return brick.mode() == protocol::BrickMode::Done; }, 60));
  const bool same = waitUntil(
      [&] {
        return runner.with([&](Session& s) {
          if (s.counters().connects < 2 || brick.link().mapSync().pending() || brick.link().mapSync().inFlight() > 0)
            return false;
          const Bounds w = brick.grid().window();
          size_t known = 0;
          for (int y = w.minY; y <= w.maxY; ++y) {
            for (int x = w.minX; x <= w.maxX; ++x) {
              const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
              if (brick.grid().at(c) != s.map().at(c)) return false;
              known += brick.grid().at(c) != CellState::Unknown ? 1 : 0;
            }
          }
          return known == s.map().known() && known > 20;
        });
      },
      20);
  runner.stop();
  stop = true;
  brickSide.join();
  ::close(server);
  EXPECT_TRUE(same);
  EXPECT_EQ(brick.executed().size(), 1u);  // explore ran once, across the reconnect
}

TEST(Transport, PtyIsASerialLink) {
  int master = -1, slave = -1;
  char name[128] = {};
  ASSERT_EQ(::openpty(&master, &slave, name, nullptr, nullptr), 0);
  const sim::World world = smallRoom();
  SimBrickConfig config;
  config.run.startCol = 1;
  config.run.startRow = 1;
  SimBrick brick(world, config);
  std::atomic<bool> stop{false};
  std::atomic<int> closed{0};
  std::thread brickSide([&] { pumpBrick(master, brick, stop, closed); });

  const LinkSpec spec = parseLinkSpec(std::string("serial:") + name);
  LinkRunner runner([&] { return openTransport(spec); }, SessionConfig{}, 100);
  runner.start();
  const bool connected = waitUntil([&] { return runner.with([](Session& s) { return s.connected(); }); }, 10);
  if (connected) runner.with([](Session& s) { return s.explore(); });
  const bool mapped =
      connected && waitUntil([&] { return runner.with([](Session& s) { return s.map().known() > 10; }); }, 20);
  runner.stop();
  stop = true;
  brickSide.join();
  ::close(slave);
  ::close(master);
  EXPECT_TRUE(connected);
  EXPECT_TRUE(mapped);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(Transport, ConnectingToAHostThatNeverAcceptsGivesUpAtTheLimit) {
  const test::LoopbackListener host(test::LoopbackListener::Mode::NeverAccepts);
  ASSERT_TRUE(host.ready());
  const auto start = std::chrono::steady_clock::now();
  try {
    openTransport(parseLinkSpec("tcp:127.0.0.1:" + std::to_string(host.port())), WaitLimit{300, nullptr});
    FAIL() << "a host that never accepts cannot be connected";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("no answer within 0.3 s"), std::string::npos) << e.what();
  }
  EXPECT_GE(secondsSince(start), 0.29);
  EXPECT_LT(secondsSince(start), 1.5);
}

TEST(Transport, AStopEndsAConnectAttemptAtOnce) {
  const test::LoopbackListener host(test::LoopbackListener::Mode::NeverAccepts);
  ASSERT_TRUE(host.ready());
  std::atomic<bool> keepGoing{true};
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    keepGoing = false;
  });
  const auto start = std::chrono::steady_clock::now();
  try {
    openTransport(parseLinkSpec("tcp:127.0.0.1:" + std::to_string(host.port())), WaitLimit{60000, &keepGoing});
    ADD_FAILURE() << "a host that never accepts cannot be connected";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("stopped"), std::string::npos) << e.what();
  }
  stopper.join();
  EXPECT_LT(secondsSince(start), 1.0);
}

TEST(Transport, AWriteThePeerNeverTakesGivesUpAtTheLimit) {
  const test::LoopbackListener host(test::LoopbackListener::Mode::AcceptsSilently);
  ASSERT_TRUE(host.ready());
  const std::unique_ptr<Transport> t =
      openTransport(parseLinkSpec("tcp:127.0.0.1:" + std::to_string(host.port())), WaitLimit{300, nullptr});
  const std::vector<uint8_t> bytes(64u << 20, 0x55);  // far more than the socket buffers hold
  const auto start = std::chrono::steady_clock::now();
  try {
    t->write(bytes.data(), bytes.size());
    FAIL() << "64 MiB cannot fit into socket buffers nobody reads";
  } catch (const TransportClosed& e) {
    EXPECT_NE(std::string(e.what()).find("the other end took no bytes within 0.3 s"), std::string::npos) << e.what();
  }
  EXPECT_LT(secondsSince(start), 1.5);
}

TEST(Transport, StoppingTheRunnerEndsItsConnectAttemptAtOnce) {
  const test::LoopbackListener host(test::LoopbackListener::Mode::NeverAccepts);
  ASSERT_TRUE(host.ready());
  const LinkSpec spec = parseLinkSpec("tcp:127.0.0.1:" + std::to_string(host.port()));
  LinkRunner runner([&](const WaitLimit& limit) { return openTransport(spec, limit); }, SessionConfig{}, 100, 60000);
  runner.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // in the middle of the attempt
  const auto start = std::chrono::steady_clock::now();
  runner.stop();
  EXPECT_LT(secondsSince(start), 1.0);
  EXPECT_FALSE(runner.with([](Session& s) { return s.connected(); }));
}

TEST(Transport, OpeningWhatIsNotThereSaysWhy) {
  EXPECT_THROW(openTransport(parseLinkSpec("serial:/dev/nxtmap-no-such-device")), LinkError);
  EXPECT_THROW(openTransport(parseLinkSpec("tcp:127.0.0.1:1")), LinkError);
  try {
    openTransport(parseLinkSpec("bt:00:16:53:00:00:01"));
    FAIL() << "no NXT should answer here";
  } catch (const LinkError& e) {
    // Either no adapter here, or no NXT answering at that address: the message says which.
    const std::string what = e.what();
    EXPECT_TRUE(what.find("Bluetooth") != std::string::npos || what.find("00:16:53:00:00:01") != std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace nxtmap::link
