// Links that cannot be had (defect 3 of issue 15: a brick that never answers must not hang the console) and
// hostile console lines against the stand-in brick: each refused with one line, the script's exit code 2.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "tests/adversarial/AdversarialCase.hpp"
#include "tests/adversarial/Fixtures.hpp"

namespace nxtmap::adversarial {
namespace {

AdversarialCase refused(const std::string& name, std::vector<std::string> args, const std::string& script = "") {
  AdversarialCase c;
  c.name = name;
  c.args = std::move(args);
  c.stdinText = script;
  return c;
}

// A loopback port with a listener that takes connections into its backlog and never says a word; it stays
// open for the rest of the test program. Returns "tcp:127.0.0.1:PORT".
std::string silentListener() {
  static std::string link;
  if (!link.empty()) return link;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof a;
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 8) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) != 0)
    throw std::runtime_error("silent listener");
  link = "tcp:127.0.0.1:" + std::to_string(ntohs(a.sin_port));
  return link;
}

}  // namespace

std::vector<AdversarialCase> linkCases() {
  std::vector<AdversarialCase> out;
  const std::string simLink = "sim:" + std::string(kGoodMap) + "@1,20";
  // A brick that never answers: refused within the timeout (the harness calls anything past 30 s a hang).
  AdversarialCase silent = refused("connect_silentBrick", {"connect", "", "--connect-timeout", "2"}, "status\nquit\n");
  silent.setup = [](const CaseDirs&) {};
  silent.args[1] = silentListener();
  silent.timeoutS = 15;
  out.push_back(silent);
  out.push_back(refused("connect_closedPort", {"connect", "tcp:127.0.0.1:1", "--connect-timeout", "2"}));
  out.push_back(refused("connect_portOutOfRange", {"connect", "tcp:127.0.0.1:99999"}));
  out.push_back(refused("connect_unknownScheme", {"connect", "usb:brick"}));
  out.push_back(refused("connect_badBtAddress", {"connect", "bt:00:16:53"}));
  out.push_back(refused("connect_serialMissing", {"connect", "serial:/dev/no-such-rfcomm", "--connect-timeout", "2"}));
  out.push_back(refused("connect_simMissingWorld", {"connect", "sim:/no/such.map@1,1"}));
  out.push_back(refused("connect_simDevZero", {"connect", "sim:{dir}/zero.map@1,1"}));
  out.back().setup = [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "zero.map"); };
  out.push_back(refused("connect_simStartInWall", {"connect", "sim:" + std::string(kGoodMap) + "@0,0"}));
  // Hostile console lines in a script: each refused, the run's exit code 2, no file written.
  const std::vector<std::pair<std::string, std::string>> lines = {
      {"GotoOutside", "goto 99999 99999"},
      {"GotoNan", "goto nan 1"},
      {"GotoNegative", "goto -1 -1"},
      {"GotoUnknownLabel", "goto near sofa"},
      {"LabelEscape", "label \x1b[2J 1 1"},
      {"RouteUnknownRoom", "route 99 1 1"},
      {"WaitNegative", "wait explored -1"},
      {"WaitHuge", "wait goal 1e300"},
      {"WaitNan", "wait goal nan"},
      {"SaveMissingParent", "save {dir}/no/such/house"},
      {"SaveYamlMissingParent", "save {dir}/no/such/room.yaml"},
      {"ExportDevFull", "export /dev/full"},
      {"ExportFolder", "export {dir}"},
      {"UnknownCommand", "fly 1 2"},
      {"Binary", std::string("\x01\x02\xff\xfe", 4)},
  };
  for (const auto& [tag, line] : lines) {
    AdversarialCase c = refused("console_" + tag, {"connect", simLink, "--no-live"}, line + "\nquit\n");
    c.timeoutS = 60;
    out.push_back(c);
  }
  return out;
}

}  // namespace nxtmap::adversarial
