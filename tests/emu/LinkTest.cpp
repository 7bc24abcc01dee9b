// The Bluetooth bridge over a real TCP socket: a PC client connects to 127.0.0.1:PORT, the firmware accepts,
// opens the stream and echoes; bytes pass through unchanged both ways.
#include "EmuTestSupport.hpp"
#include "host/emu/LinkServer.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace nxtmap::emu::test {
namespace {

TEST(TcpLink, PcClientTalksToTheFirmwareThroughTheBridge) {
    std::unique_ptr<TcpLink> link;
    int port = 0;
    for (int p = 42000 + getpid() % 2000; !link && p < 48000; p += 97) {
        try {
            link = std::make_unique<TcpLink>(p);
            port = p;
        } catch (const std::runtime_error&) {
        }
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
    EXPECT_TRUE(pty.connected());
    const uint8_t hello[] = {1, 2, 3};
    pty.send(hello, 3);  // nobody reads: must not block or fail
}

}  // namespace
}  // namespace nxtmap::emu::test
