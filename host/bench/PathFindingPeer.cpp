#include "host/bench/PathFindingPeer.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace nxtmap::bench {
namespace {
namespace fs = std::filesystem;

fs::path sourceDir() { return fs::path(__FILE__).parent_path().parent_path().parent_path(); }

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream in(path);
  for (std::string dir; std::getline(in, dir, ':');) {
    std::error_code ec;
    if (!dir.empty() && fs::exists(fs::path(dir) / program, ec)) return true;
  }
  return false;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs a shell command, returns its stdout; exit status in `status`.
std::string capture(const std::string& command, int& status) {
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) {
    status = -1;
    return out;
  }
  char buf[4096];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  status = ::pclose(p);
  return out;
}

}  // namespace

std::string preparePeer(const fs::path& peerDir) {
  if (!onPath("node") || !onPath("npm")) {
    return "npm/node not available on PATH (install the Debian packages nodejs and npm: make deps)";
  }
  std::error_code ec;
  fs::create_directories(peerDir, ec);
  const fs::path script = sourceDir() / "scripts" / "peer";
  fs::copy_file(script / "package.json", peerDir / "package.json", fs::copy_options::overwrite_existing, ec);
  if (ec) return "cannot copy scripts/peer/package.json into " + peerDir.string() + " (" + ec.message() + ")";
  if (fs::exists(peerDir / "node_modules" / "pathfinding" / "package.json", ec)) return "";
  std::cerr << "[plan] npm install pathfinding into " << peerDir.string() << " ...\n";
  int status = 0;
  const std::string log =
      capture("cd " + quote(peerDir.string()) + " && npm install --no-audit --no-fund --loglevel=error 2>&1", status);
  if (status != 0 || !fs::exists(peerDir / "node_modules" / "pathfinding" / "package.json", ec)) {
    std::string firstLine = log.substr(0, log.find('\n'));
    return "npm install failed in " + peerDir.string() + (firstLine.empty() ? "" : ": " + firstLine);
  }
  return "";
}

PeerRun runPeer(const fs::path& peerDir, const fs::path& map, const std::vector<plan::ScenarioProblem>& problems,
                const std::vector<size_t>& sample) {
  PeerRun run;
  const fs::path list = peerDir / (map.stem().string() + ".problems.tsv");
  {
    std::ofstream out(list);
    for (size_t i : sample) {
      const plan::ScenarioProblem& p = problems[i];
      out << i << '\t' << p.start.col << '\t' << p.start.row << '\t' << p.goal.col << '\t' << p.goal.row << '\n';
    }
  }
  const fs::path script = sourceDir() / "scripts" / "peer" / "pathfinding-peer.js";
  int status = 0;
  const std::string out = capture("node " + quote(script.string()) + " --modules " + quote(peerDir.string()) + " " +
                                      quote(map.string()) + " " + quote(list.string()),
                                  status);
  std::istringstream in(out);
  std::map<size_t, std::pair<double, double>> byIndex;
  size_t index = 0;
  double length = 0, micros = 0;
  while (in >> index >> length >> micros) byIndex[index] = {length, micros};
  if (status != 0 || byIndex.size() != sample.size()) {
    run.error = "the peer failed on " + map.filename().string() + " (exit " + std::to_string(status) + ")";
    return run;
  }
  for (size_t i : sample) {
    run.lengths.push_back(byIndex[i].first);
    run.micros.push_back(byIndex[i].second);
  }
  return run;
}

}  // namespace nxtmap::bench
